//! The wavelet-based texture energy of Shen et al. 2009 (section 3.3, eq. 4, Table 1): the M-step
//! compares neighbourhoods by ||x_p - z_p||^2 + sum_i w_i ||c^i_(x_p) - c^i_(z_p)||^2, where c^i
//! are the wavelet coefficients (Haar or Daubechies D4) of the neighbourhood.
//!
//! **Parseval.** Both transforms are orthonormal, so with every w_i = 1 the wavelet term *equals*
//! the pixel term and eq. 4 taken literally only doubles every distance: no match changes. What
//! the paper intends (multi-scale edge information that keeps texture elements aligned) needs the
//! detail bands weighted differently from the approximation. Here the approximation keeps
//! w = 1 and every detail band gets `waveletDetailWeight` (see
//! [`DEFAULT_DETAIL_WEIGHT`]); the per-coefficient weight of the total distance is 1 + w_i.
//!
//! **Implementation.** The pixel term of this project is fall-off weighted (sum g_k d_k^2, see
//! [`gaussian_falloff`]), so the coefficients are those of the *windowed* neighbourhood,
//! c = W(sqrt(g) x): then by Parseval ||c_x - c_z||^2 is exactly the fall-off weighted pixel
//! term, and the whole distance is one weighted sum over coefficients,
//! sum_k (1 + w_k) (c_x,k - c_z,k)^2 — the distance ||W(x - z)||^2 of a fixed linear map. So every
//! exemplar neighbourhood is transformed once per level, every output neighbourhood once per
//! M-step, and the searches (exact, k-means tree, PatchMatch) run unchanged on the transformed
//! vectors ([`Neighbourhoods::transformed`](crate::solvers::nn::Neighbourhoods::transformed)).
//! The reported energy stays the pixel term (the unweighted coefficient distance), comparable
//! across energies.
//!
//! With the gradient energy on (mu > 0) the gradient features are transformed too but keep
//! weight 1: their term stays mu ||Dx_p - Dz_p||^2 (fall-off weighted), and the wavelet term is
//! about colour only.

use crate::solvers::nn::patches::gaussian_falloff;
use crate::solvers::wavelet::{Wavelet, band_level, forward_2d, max_levels};

/// What the M-step's distance is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Energy {
    /// ||x_p - z_p||^2 (Kwatra et al. 2005).
    #[default]
    Pixels,
    /// Plus the weighted Haar coefficient term (Shen et al. 2009, eq. 4).
    Haar,
    /// Plus the weighted Daubechies D4 coefficient term (the paper's choice).
    Daubechies,
}

impl Energy {
    /// The names used in options (JS `energy`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Energy::Pixels => "pixels",
            Energy::Haar => "haar",
            Energy::Daubechies => "daubechies",
        }
    }

    /// The energy of that name (see [`Energy::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Energy> {
        [Energy::Pixels, Energy::Haar, Energy::Daubechies]
            .into_iter()
            .find(|e| e.name() == name)
    }

    /// The wavelet of the energy, None for the pixel energy.
    #[must_use]
    pub fn wavelet(self) -> Option<Wavelet> {
        match self {
            Energy::Pixels => None,
            Energy::Haar => Some(Wavelet::Haar),
            Energy::Daubechies => Some(Wavelet::Daubechies4),
        }
    }
}

/// Default weight w of the detail bands (the approximation has 1). Measured with
/// `examples/wavelet_sweep.rs` (see the README's wavelet section for the table).
pub const DEFAULT_DETAIL_WEIGHT: f32 = 4.0;

/// Transform levels for a neighbourhood of side `size`: three, or fewer so that the
/// approximation keeps at least 2x2 coefficients (8x8 -> 2 levels, 16 and 32 -> 3).
#[must_use]
pub fn levels_for(size: usize) -> usize {
    max_levels(size).saturating_sub(1).min(3)
}

/// The transform of one neighbourhood size and its coefficient weights.
#[derive(Debug, Clone)]
pub struct WaveletEnergy {
    wavelet: Wavelet,
    size: usize,
    dims: usize,
    levels: usize,
    /// sqrt of the Gaussian fall-off, one per pixel.
    window: Vec<f32>,
    /// 1 + w_i per coefficient, plane by plane (`dims` planes of `size * size`).
    weights: Vec<f32>,
}

impl WaveletEnergy {
    /// For neighbourhoods of `size` (a power of two, checked by the options) over a feature map
    /// of `dims` values per pixel whose first `colour` are colour channels.
    #[must_use]
    pub fn new(
        wavelet: Wavelet,
        size: usize,
        dims: usize,
        colour: usize,
        detail_weight: f32,
    ) -> Self {
        let levels = levels_for(size);
        let window = gaussian_falloff(size, 1).iter().map(|g| g.sqrt()).collect();
        let mut weights = Vec::with_capacity(size * size * dims);
        for c in 0..dims {
            for y in 0..size {
                for x in 0..size {
                    let w = match (c < colour, band_level(x, y, size, levels)) {
                        (false, _) => 0.0,
                        (true, None) => 1.0,
                        (true, Some(_)) => detail_weight,
                    };
                    weights.push(1.0 + w);
                }
            }
        }
        WaveletEnergy {
            wavelet,
            size,
            dims,
            levels,
            window,
            weights,
        }
    }

    /// Weights of the transformed vectors (1 + w_i).
    #[must_use]
    pub fn weights(&self) -> &[f32] {
        &self.weights
    }

    #[must_use]
    pub fn levels(&self) -> usize {
        self.levels
    }

    /// The coefficients of the windowed neighbourhood `pixels` (interleaved, `size * size *
    /// dims`) into `out` (same length, plane by plane). `scratch` holds at least `size` values.
    pub fn transform(&self, pixels: &[f32], out: &mut [f32], scratch: &mut [f32]) {
        let area = self.size * self.size;
        for (c, plane) in out.chunks_exact_mut(area).enumerate() {
            for (p, (v, &g)) in plane.iter_mut().zip(&self.window).enumerate() {
                *v = g * pixels[p * self.dims + c];
            }
            forward_2d(self.wavelet, plane, self.size, self.levels, scratch);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// The distance of eq. 4 computed the slow, obvious way: fall-off weighted pixel SSD plus
    /// the sum over coefficients of w_i times the squared difference, each neighbourhood
    /// windowed and transformed on its own, coefficient by coefficient, in f64.
    fn naive(wavelet: Wavelet, x: &[f32], z: &[f32], size: usize, dims: usize, w: f32) -> f64 {
        let g = gaussian_falloff(size, 1);
        let levels = levels_for(size);
        let mut pixel = 0.0;
        for p in 0..size * size {
            for c in 0..dims {
                let d = f64::from(x[p * dims + c] - z[p * dims + c]);
                pixel += f64::from(g[p]) * d * d;
            }
        }
        let mut term = 0.0;
        for c in 0..dims {
            let plane = |v: &[f32]| -> Vec<f32> {
                let mut out: Vec<f32> = (0..size * size)
                    .map(|p| g[p].sqrt() * v[p * dims + c])
                    .collect();
                forward_2d(wavelet, &mut out, size, levels, &mut vec![0.0; size]);
                out
            };
            let (cx, cz) = (plane(x), plane(z));
            for y in 0..size {
                for xx in 0..size {
                    let i = y * size + xx;
                    let wi = if band_level(xx, y, size, levels).is_some() {
                        w
                    } else {
                        1.0
                    };
                    let d = f64::from(cx[i] - cz[i]);
                    term += f64::from(wi) * d * d;
                }
            }
        }
        pixel + term
    }

    #[test]
    fn transformed_distance_is_the_weighted_sum_of_pixel_and_coefficient_differences() {
        let mut rng = Rng::new(4);
        for wavelet in [Wavelet::Haar, Wavelet::Daubechies4] {
            for (size, dims) in [(8, 3), (16, 1), (32, 3)] {
                for w in [0.0, 1.0, 4.0] {
                    let e = WaveletEnergy::new(wavelet, size, dims, dims, w);
                    let len = size * size * dims;
                    let x: Vec<f32> = (0..len).map(|_| rng.next_f32()).collect();
                    let z: Vec<f32> = (0..len).map(|_| rng.next_f32()).collect();
                    let (mut cx, mut cz) = (vec![0.0; len], vec![0.0; len]);
                    let mut scratch = vec![0.0; size];
                    e.transform(&x, &mut cx, &mut scratch);
                    e.transform(&z, &mut cz, &mut scratch);
                    let fast = crate::solvers::nn::patches::weighted_ssd(&cx, &cz, e.weights());
                    let slow = naive(wavelet, &x, &z, size, dims, w);
                    assert!(
                        (f64::from(fast) - slow).abs() < 1e-4 * slow,
                        "{wavelet:?} {size} {dims} w {w}: {fast} vs {slow}"
                    );
                }
            }
        }
    }

    #[test]
    fn gradient_features_keep_weight_one_and_names_round_trip() {
        let e = WaveletEnergy::new(Wavelet::Haar, 8, 9, 3, 5.0);
        let area = 64;
        assert_eq!(e.weights()[0], 2.0); // colour approximation: 1 + 1
        assert_eq!(e.weights()[area - 1], 6.0); // colour finest detail: 1 + 5
        assert!(e.weights()[3 * area..].iter().all(|&w| w == 1.0));
        assert_eq!(e.levels(), 2);
        for energy in [Energy::Pixels, Energy::Haar, Energy::Daubechies] {
            assert_eq!(Energy::from_name(energy.name()), Some(energy));
        }
        assert_eq!(Energy::from_name("db4"), None);
    }
}
