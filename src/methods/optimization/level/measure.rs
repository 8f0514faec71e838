//! Measuring kept matches without searching: the distances, IRLS weights and texture energy an
//! M-step's end sets, for one distance per node. The constrained M-step measures its matches
//! without the constraint this way, and a flow frame's last iteration at a size measures instead
//! of searching.

use super::{LevelSetup, LevelSolver};
use crate::core::{Image, parallel};

/// Nodes in a piece of the measure that runs on one thread.
const MEASURE_NODES: usize = 4096;
use crate::methods::optimization::e_step::edge;
use crate::methods::optimization::features::feature_map;
use crate::methods::optimization::queries::GridQueries;
use crate::solvers::nn::{FeatureMap, Queries, Query};

impl LevelSolver {
    /// Measures the kept matches against `output` without searching: their distances, IRLS
    /// weights and texture energy, as the end of an M-step sets them, for one distance per node
    /// (a search costs several). A flow frame's last iteration at a size ends with this: its
    /// matches only carry into the next frame, whose first M-step searches from them anyway.
    pub fn measure(&mut self, output: &Image) {
        let LevelSetup {
            search_mu, wrap, ..
        } = self.setup;
        // A measure replaces an M-step.
        self.abandon_m_step();
        let map = self.query_map(feature_map(output, search_mu, edge(wrap)));
        self.measure_distances(&map, true);
        self.settle();
    }

    /// The distances of the kept matches to the neighbourhoods of `map` (the pixel term; with
    /// `texture` false only the wavelet energy's pixel distances, the others being set).
    pub(super) fn measure_distances(&mut self, map: &FeatureMap, texture: bool) {
        let LevelSetup { wrap, size, .. } = self.setup;
        let space = self.matcher.space();
        let plain = || {
            GridQueries::new(map, (&self.cols, &self.rows), size, wrap)
                .transformed(self.wavelet.as_ref())
        };
        let matches = &self.matches[..];
        // One distance per node, so in parallel pieces of nodes.
        if texture {
            parallel::for_each_piece_mut(&mut self.distances, MEASURE_NODES, |p, piece| {
                let mut queries = plain();
                let mut query = Query::new(space.vector_len());
                for (k, d) in piece.iter_mut().enumerate() {
                    let n = p * MEASURE_NODES + k;
                    let m = matches[n];
                    *d = match queries.in_place(n) {
                        Some(rows) => {
                            space.distance_in_place(rows, space.weights(), m, f32::INFINITY)
                        }
                        None => {
                            queries.fill(n, &mut query);
                            query.distance(space, m, f32::INFINITY)
                        }
                    };
                }
            });
        }
        if self.wavelet.is_some() {
            // Parseval: the unweighted distance of transformed (windowed) vectors is the
            // fall-off weighted pixel distance.
            let unit = &self.unit_weights[..];
            parallel::for_each_piece_mut(&mut self.pixel_distances, MEASURE_NODES, |p, piece| {
                let mut queries = plain();
                let mut query = Query::new(space.vector_len());
                for (k, d) in piece.iter_mut().enumerate() {
                    let n = p * MEASURE_NODES + k;
                    queries.fill(n, &mut query);
                    *d = space.distance_with(&query.values, unit, matches[n], f32::INFINITY);
                }
            });
        }
    }
}
