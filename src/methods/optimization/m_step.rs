//! The M-step: for every output neighbourhood x_p, the nearest exemplar neighbourhood z_p, by the
//! chosen search. Every search starts from the current match and only accepts a closer one, so
//! the quadratic energy never rises in an M-step whichever search is used.

use crate::core::Rng;
use crate::solvers::nn::kmeans_tree::KMeansTree;
use crate::solvers::nn::patchmatch::{self, QueryGrid};
use crate::solvers::nn::{FeatureMap, Neighbourhoods, Pos, Search, exact};

/// PatchMatch sweeps per M-step (forward, backward, forward). The EM loop calls it again every
/// iteration, warm-started. Measured on the samples (128 -> 256, `cargo run --release --example
/// bench`): 2 sweeps end 2% above the exact search's energy on gravel_128, 3 sweeps end below it
/// for 10-40% more time, 4 sweeps gain nothing more.
pub const PATCHMATCH_PASSES: usize = 3;

/// The exemplar's neighbourhoods at one level, with the search structure built over them.
pub struct Matcher {
    space: Neighbourhoods,
    search: Search,
    tree: Option<KMeansTree>,
    passes: usize,
}

impl Matcher {
    /// Builds the search structure (the k-means tree, when that search is chosen).
    #[must_use]
    pub fn new(exemplar: FeatureMap, size: usize, search: Search, rng: &mut Rng) -> Self {
        let space = Neighbourhoods::new(exemplar, size);
        let tree = (search == Search::KMeansTree).then(|| KMeansTree::build(&space, rng));
        Matcher {
            space,
            search,
            tree,
            passes: PATCHMATCH_PASSES,
        }
    }

    /// Sets the PatchMatch sweeps per M-step (animation frames start from matches carried along
    /// the flow and need fewer than a synthesis from scratch).
    #[must_use]
    pub fn with_passes(mut self, passes: usize) -> Self {
        self.passes = passes.max(1);
        self
    }

    #[must_use]
    pub fn space(&self) -> &Neighbourhoods {
        &self.space
    }

    /// Recomputes `distances` for the current `matches` (the queries changed in the E-step), then
    /// improves the matches. `weights`, when given, are per-value weights for every query (soft
    /// constraints) in place of the Gaussian fall-off. Returns how many matches changed.
    pub fn m_step(
        &self,
        queries: &[f32],
        weights: Option<&[f32]>,
        grid: QueryGrid<'_>,
        matches: &mut [Pos],
        distances: &mut [f32],
        rng: &mut Rng,
    ) -> usize {
        let len = self.space.vector_len();
        let weights_of =
            |n: usize| weights.map_or(self.space.weights(), |w| &w[n * len..(n + 1) * len]);
        for (n, (m, d)) in matches.iter().zip(distances.iter_mut()).enumerate() {
            *d = self.space.distance_with(
                &queries[n * len..(n + 1) * len],
                weights_of(n),
                *m,
                f32::INFINITY,
            );
        }
        match self.search {
            Search::PatchMatch => patchmatch::improve(
                &self.space,
                queries,
                weights,
                grid,
                matches,
                distances,
                self.passes,
                rng,
            ),
            Search::Exact | Search::KMeansTree => {
                let mut changed = 0;
                for (n, (m, d)) in matches.iter_mut().zip(distances.iter_mut()).enumerate() {
                    let query = &queries[n * len..(n + 1) * len];
                    let (pos, dist) = match &self.tree {
                        // The tree is built for the fall-off weights: it proposes a candidate
                        // for the (constrained) query, which is then scored under the query's
                        // own weights, so a match still only changes to a better one.
                        Some(tree) => {
                            let pos = tree.nearest(&self.space, query).0;
                            let d = self.space.distance_with(query, weights_of(n), pos, *d);
                            (pos, d)
                        }
                        None => exact::nearest_with(&self.space, query, weights_of(n)),
                    };
                    if dist < *d {
                        changed += usize::from(pos != *m);
                        *m = pos;
                        *d = dist;
                    }
                }
                changed
            }
        }
    }
}
