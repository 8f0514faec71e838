//! The M-step's queries x_p, gathered from the output's feature map one grid node at a time (a
//! stored copy of every neighbourhood would take 16 times the output's memory at spacing w/4),
//! transformed when the energy is a wavelet one, and pulled towards the soft constraints'
//! colours with the constraint's weights when one is given (Algorithm 2).

use super::constraints::QueryTerms;
use super::features::gather;
use super::wavelet_energy::WaveletEnergy;
use crate::solvers::nn::{FeatureMap, Queries, Query};

/// The queries of one M-step over a level's grid.
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

    fn in_place(&self, n: usize) -> Option<(&[f32], usize)> {
        if self.wavelet.is_some() || self.constraint.is_some() {
            return None;
        }
        let nx = self.cols.len();
        let (x, y) = (self.cols[n % nx], self.rows[n / nx]);
        let map = self.map;
        if x + self.size > map.width || y + self.size > map.height {
            return None; // wraps
        }
        let start = (y * map.width + x) * map.dims;
        Some((&map.data[start..], map.width * map.dims))
    }
}
