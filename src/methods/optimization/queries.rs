//! The M-step's queries x_p, gathered from the output's feature map one grid node at a time (a
//! stored copy of every neighbourhood would take 16 times the output's memory at spacing w/4),
//! transformed when the energy is a wavelet one, and pulled towards the soft constraints'
//! colours with the constraint's weights when one is given (Algorithm 2).

use super::constraints::QueryTerms;
use super::features::gather;
use super::wavelet_energy::WaveletEnergy;
use crate::solvers::nn::{FeatureMap, InPlace, Queries, Query};

/// The queries of one M-step over a level's grid (cloned per band of a parallel sweep: the
/// scratch is each band's own).
#[derive(Clone)]
pub struct GridQueries<'a> {
    pub map: &'a FeatureMap,
    pub cols: &'a [usize],
    pub rows: &'a [usize],
    pub size: usize,
    pub wrap: bool,
    /// Transform gathered neighbourhoods (the wavelet energies) before comparing.
    pub wavelet: Option<&'a WaveletEnergy>,
    /// Soft constraints' query terms, with the space's fall-off that their weights scale.
    pub constraint: Option<(&'a QueryTerms, &'a [f32])>,
    /// The same queries made once for the whole map ([`QueryTerms::in_place_map`]), to read
    /// them in place.
    pub constrained_map: Option<(&'a FeatureMap, &'a [f32])>,
    /// Scratch: one gathered neighbourhood and one block side, for the wavelet transform.
    gathered: Vec<f32>,
    scratch: Vec<f32>,
}

impl<'a> GridQueries<'a> {
    #[must_use]
    pub fn new(
        map: &'a FeatureMap,
        (cols, rows): (&'a [usize], &'a [usize]),
        size: usize,
        wrap: bool,
    ) -> Self {
        GridQueries {
            map,
            cols,
            rows,
            size,
            wrap,
            wavelet: None,
            constraint: None,
            constrained_map: None,
            gathered: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// Compares wavelet coefficients instead of pixels.
    #[must_use]
    pub fn transformed(mut self, wavelet: Option<&'a WaveletEnergy>) -> Self {
        self.wavelet = wavelet;
        self
    }

    /// Reads constrained queries in place from `map` (values and gains, as made by
    /// [`QueryTerms::in_place_map`] for this M-step's map and constraint).
    #[must_use]
    pub fn constrained_in_place(mut self, map: Option<(&'a FeatureMap, &'a [f32])>) -> Self {
        self.constrained_map = map;
        self
    }

    /// Applies soft constraints, scaling the space's `weights`.
    #[must_use]
    pub fn constrained(mut self, constraint: Option<&'a QueryTerms>, weights: &'a [f32]) -> Self {
        self.constraint = constraint.map(|c| (c, weights));
        self
    }
}

impl Queries for GridQueries<'_> {
    fn count(&self) -> usize {
        self.cols.len() * self.rows.len()
    }

    fn fill(&mut self, n: usize, query: &mut Query) {
        let nx = self.cols.len();
        let (x, y) = (self.cols[n % nx], self.rows[n / nx]);
        let len = self.size * self.size * self.map.dims;
        query.values.resize(len, 0.0);
        match self.wavelet {
            None => gather(self.map, x, y, self.size, self.wrap, &mut query.values),
            Some(e) => {
                self.gathered.resize(len, 0.0);
                self.scratch.resize(self.size, 0.0);
                gather(self.map, x, y, self.size, self.wrap, &mut self.gathered);
                e.transform(&self.gathered, &mut query.values, &mut self.scratch);
            }
        }
        query.own_weights = false;
        if let Some((constraint, weights)) = self.constraint {
            query.weights.clear();
            query.weights.extend_from_slice(weights);
            query.own_weights = true;
            constraint.apply(
                x,
                y,
                self.size,
                self.map.dims,
                self.wrap,
                &mut query.values,
                &mut query.weights,
            );
        }
    }

    fn in_place(&self, n: usize) -> Option<InPlace<'_>> {
        if self.wavelet.is_some() {
            return None;
        }
        let (map, gains) = match self.constraint {
            None => (self.map, None),
            Some(_) => {
                let (map, gains) = self.constrained_map?;
                (map, Some(gains))
            }
        };
        let nx = self.cols.len();
        let (x, y) = (self.cols[n % nx], self.rows[n / nx]);
        if x + self.size > map.width || y + self.size > map.height {
            return None; // wraps
        }
        let start = (y * map.width + x) * map.dims;
        Some(InPlace {
            values: &map.data[start..],
            gains: gains.map(|g| &g[start..]),
            stride: map.width * map.dims,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Edge;
    use crate::core::testing::noise;
    use crate::methods::optimization::constraints::Constraint;
    use crate::methods::optimization::features::feature_map;
    use crate::solvers::nn::{Neighbourhoods, Pos};

    /// Every query read in place (plain, and under a soft constraint with a mask that varies
    /// pixel by pixel, with and without gradient features) gives the same distances, to the
    /// bit, as the query copied and constrained node by node; wrapping nodes are not read in
    /// place.
    #[test]
    fn queries_read_in_place_equal_the_copied_ones() {
        let (w, h, size) = (40, 36, 8);
        let output = noise(w, h, 3, 1);
        let exemplar = noise(32, 32, 3, 2);
        let mask: Vec<f32> = (0..w * h)
            .map(|i| [0.0, 1.0, 0.25, 1.0, 0.6][i % 5])
            .collect();
        let constraint = Constraint {
            target: noise(w, h, 3, 3),
            mask,
            lambda: 0.7,
        };
        for mu in [0.0, 4.0] {
            let map = feature_map(&output, mu, Edge::Wrap);
            let space = Neighbourhoods::new(feature_map(&exemplar, mu, Edge::Clamp), size);
            let terms = constraint.query_terms();
            let (constrained_map, gains) = terms.in_place_map(&map);
            let cols: Vec<usize> = (0..w).step_by(2).collect();
            let rows: Vec<usize> = (0..h).step_by(2).collect();
            for constrained in [false, true] {
                let mut queries = GridQueries::new(&map, (&cols, &rows), size, true);
                if constrained {
                    queries = queries
                        .constrained(Some(&terms), space.weights())
                        .constrained_in_place(Some((&constrained_map, &gains)));
                }
                let mut query = Query::default();
                let mut read = 0;
                for n in 0..queries.count() {
                    let (x, y) = (cols[n % cols.len()], rows[n / cols.len()]);
                    let wraps = x + size > w || y + size > h;
                    queries.fill(n, &mut query);
                    let Some(in_place) = queries.in_place(n) else {
                        assert!(wraps, "node {n} at ({x}, {y}) is read in place");
                        continue;
                    };
                    assert!(!wraps);
                    assert_eq!(in_place.gains.is_some(), constrained);
                    read += 1;
                    for pos in [Pos::new(0, 0), Pos::new(5, 17), Pos::new(24, 24)] {
                        let copied = query.distance(&space, pos, f32::INFINITY);
                        let direct =
                            space.distance_in_place(in_place, space.weights(), pos, f32::INFINITY);
                        assert_eq!(copied.to_bits(), direct.to_bits(), "mu {mu}, node {n}");
                    }
                }
                assert!(read > queries.count() / 2);
            }
        }
    }
}
