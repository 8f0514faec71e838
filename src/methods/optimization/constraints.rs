//! Soft constraints (Kwatra et al. 2005, section 4, eq. 2 and Algorithm 2): desired colours at
//! some output pixels, pulled on with weight lambda.
//!
//! The paper leaves the scale of lambda open. Here it is relative to the texture term at each
//! pixel, in both steps:
//! - E-step: the pixel becomes `(texture average + lambda m c) / (1 + lambda m)`, so lambda = 1
//!   lands half way between what the texture neighbourhoods say and the constraint colour c, and
//!   a large lambda makes the constraint hard. (The energy minimised is eq. 2 with a per-pixel
//!   weight lambda m_k W_k, W_k the texture weight the pixel already has.)
//! - M-step: z_p minimises `sum g (x - v)^2 + lambda m g (v - c)^2` over the neighbourhood, the
//!   paper's `||x_p - z_p||^2 + lambda E_c(y)`; completing the square turns it into a weighted
//!   nearest-neighbour search for the query `(x + lambda m c) / (1 + lambda m)` with weights
//!   `g (1 + lambda m)`.
//!
//! `m` is the mask (0 = free, 1 = fully constrained; fractions soften stroke edges).
//!
//! Hard constraints ([`SoftConstraints::hard`], lambda infinite) are the limit of a large
//! lambda taken exactly in the E-step: it sets a pixel to `(1 - m) * texture average + m c` (c
//! itself where m = 1). The M-step searches as under a soft constraint of lambda
//! [`HARD_MATCH_LAMBDA`]: the query's values are the output's (the E-step already put c there)
//! and a constrained pixel weighs `1 + HARD_MATCH_LAMBDA m` times as much as a free one, so a
//! neighbourhood across the constraint's edge matches one that continues the constrained
//! pixels. Inpainting holds the known pixels of an image so.

use crate::core::{Error, Image, Result, parallel};

/// Pixels in a piece of [`Constraint::add_to_e_step`] that runs on one thread.
const E_STEP_PIXELS: usize = 1 << 14;
use crate::solvers::nn::FeatureMap;

/// Soft constraints at full output resolution, as the caller gave them.
#[derive(Debug, Clone, PartialEq)]
pub struct SoftConstraints {
    /// Desired colours, output size, the exemplar's channel count.
    pub target: Image,
    /// Per-pixel mask m in [0, 1], `width * height` long.
    pub mask: Vec<f32>,
    /// Weight lambda >= 0 of the constraint term.
    pub lambda: f32,
}

/// The largest lambda accepted: beyond it the constraint is hard for all practical purposes.
pub const MAX_LAMBDA: f32 = 1e6;

/// The lambda a hard constraint's M-step searches with (see the module's notes), chosen on
/// inpainting's sheets (`./scripts/compare.sh --task inpaint`): at 0 the known pixels weigh
/// as much as the filled ones, and the filled side meets them with a step (the boundary's
/// mean colour step 1.4 to 1.9 times the texture's on granular textures); at 4 the steps are
/// near the texture's own; at 16 the filled side blurs (brick's mortar lines fade).
pub const HARD_MATCH_LAMBDA: f32 = 4.0;

impl SoftConstraints {
    /// Checks the mask length, the mask and target values and lambda; the error names the problem.
    pub fn new(target: Image, mask: Vec<f32>, lambda: f32) -> Result<Self> {
        let pixels = target.width() * target.height();
        if mask.len() != pixels {
            return Err(Error::LengthMismatch {
                what: "constraint mask",
                expected: pixels,
                actual: mask.len(),
            });
        }
        if let Some(bad) = mask.iter().find(|m| !(0.0..=1.0).contains(*m)) {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: format!("every value must be between 0 and 1, got {bad}"),
            });
        }
        if target.data().iter().any(|v| !v.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "target",
                reason: "every colour must be finite".into(),
            });
        }
        if !lambda.is_finite() || !(0.0..=MAX_LAMBDA).contains(&lambda) {
            return Err(Error::InvalidParameter {
                name: "lambda",
                reason: format!("must be between 0 and {MAX_LAMBDA}, got {lambda}"),
            });
        }
        Ok(SoftConstraints {
            target,
            mask,
            lambda,
        })
    }

    /// Hard constraints: the pixels where `mask` is 1 take the target's colour exactly after
    /// every E-step, fractions blend the texture average with it (see the module's notes).
    pub fn hard(target: Image, mask: Vec<f32>) -> Result<Self> {
        let mut constraints = SoftConstraints::new(target, mask, 0.0)?;
        constraints.lambda = f32::INFINITY;
        Ok(constraints)
    }

    /// Whether the constraints are hard (see [`SoftConstraints::hard`]).
    #[must_use]
    pub fn is_hard(&self) -> bool {
        self.lambda == f32::INFINITY
    }

    /// The constraint at a level of `width` x `height` (the output, or a coarser level of it).
    /// Shrinking is a box filter of the mask and of the mask-weighted colours, so a thin stroke
    /// survives as a fainter one instead of being skipped.
    #[must_use]
    pub fn at_size(&self, width: usize, height: usize) -> Constraint {
        let (sw, sh, c) = (
            self.target.width(),
            self.target.height(),
            self.target.channels(),
        );
        if (sw, sh) == (width, height) {
            return Constraint {
                target: self.target.clone(),
                mask: self.mask.clone(),
                lambda: self.lambda,
            };
        }
        let mut mass = vec![0.0f32; width * height];
        let mut count = vec![0.0f32; width * height];
        let mut colour = vec![0.0f32; width * height * c];
        let src = self.target.data();
        for y in 0..sh {
            let ty = (y * height / sh).min(height - 1);
            for x in 0..sw {
                let tx = (x * width / sw).min(width - 1);
                let (s, t) = (y * sw + x, ty * width + tx);
                let m = self.mask[s];
                mass[t] += m;
                count[t] += 1.0;
                for k in 0..c {
                    colour[t * c + k] += m * src[s * c + k];
                }
            }
        }
        for t in 0..width * height {
            if mass[t] > 0.0 {
                for k in 0..c {
                    colour[t * c + k] /= mass[t];
                }
            }
        }
        Constraint {
            target: Image::from_vec(width, height, c, colour).expect("sizes agree"),
            mask: mass
                .iter()
                .zip(&count)
                .map(|(&m, &n)| m / n.max(1.0))
                .collect(),
            lambda: self.lambda,
        }
    }
}

/// A constraint's M-step query terms per pixel: `lm c` (the pull towards the target colour,
/// per channel), `1 + lm` (the weight's gain) and its inverse, so that constraining a query is
/// a multiply-add per value (a division per value would make it a third of a flow frame's time).
#[derive(Debug, Clone, PartialEq)]
pub struct QueryTerms {
    width: usize,
    height: usize,
    channels: usize,
    pull: Vec<f32>,
    gain: Vec<f32>,
    inverse: Vec<f32>,
}

impl QueryTerms {
    /// Every query's values and gains at once, as maps like `map` (the output's feature map):
    /// values `(x + lm c) / (1 + lm)` in the colour channels, and per value the factor its
    /// fall-off weight takes, `1 + lm` for colours and 1 otherwise. A query read from them in
    /// place equals one made by [`QueryTerms::apply`], to the bit, without a copy per node.
    #[must_use]
    pub fn in_place_map(&self, map: &FeatureMap) -> (FeatureMap, Vec<f32>) {
        let (dims, c) = (map.dims, self.channels);
        let mut values = map.clone();
        let mut gains = vec![1.0f32; map.data.len()];
        let pixels = values
            .data
            .chunks_exact_mut(dims)
            .zip(gains.chunks_exact_mut(dims))
            .zip(&self.gain)
            .zip(&self.inverse)
            .zip(self.pull.chunks_exact(c));
        for ((((q, wt), &gain), &inverse), pull) in pixels {
            for ((q, wt), &pull) in q.iter_mut().zip(wt.iter_mut()).zip(pull) {
                *q = (*q + pull) * inverse;
                *wt = gain;
            }
        }
        (values, gains)
    }

    /// Turns the gathered query of the neighbourhood at `(x0, y0)` (`size` wide, `dims` values
    /// per pixel of which the first `channels` are colour) and its weights into the constrained
    /// search: query `(x + lm c) / (1 + lm)`, weights `g (1 + lm)` (completing the square of
    /// `g (x - v)^2 + lm g (v - c)^2`).
    #[allow(clippy::too_many_arguments)]
    pub fn apply(
        &self,
        x0: usize,
        y0: usize,
        size: usize,
        dims: usize,
        wrap: bool,
        query: &mut [f32],
        weights: &mut [f32],
    ) {
        let (w, h, c) = (self.width, self.height, self.channels);
        for dy in 0..size {
            let y = if wrap { (y0 + dy) % h } else { y0 + dy };
            let first = if wrap { size.min(w - x0) } else { size };
            for (x, dx0, len) in [(x0, 0, first), (0, first, size - first)] {
                let row = y * w + x;
                let base = (dy * size + dx0) * dims;
                // Zipped slices, no index arithmetic per value: this runs at every node visit.
                let pixels = self.gain[row..row + len]
                    .iter()
                    .zip(&self.inverse[row..row + len])
                    .zip(self.pull[row * c..(row + len) * c].chunks_exact(c))
                    .zip(query[base..base + len * dims].chunks_exact_mut(dims))
                    .zip(weights[base..base + len * dims].chunks_exact_mut(dims));
                for ((((&gain, &inverse), pull), q), wt) in pixels {
                    for ((q, wt), &pull) in q.iter_mut().zip(wt.iter_mut()).zip(pull) {
                        *q = (*q + pull) * inverse;
                        *wt *= gain;
                    }
                }
            }
        }
    }
}

/// A constraint at one level's resolution: target colours, mask m per pixel, and lambda.
#[derive(Debug, Clone, PartialEq)]
pub struct Constraint {
    pub target: Image,
    pub mask: Vec<f32>,
    pub lambda: f32,
}

impl Constraint {
    /// Adds the constraint to the E-step's per-pixel sums (`colour` = sum of weighted matched
    /// colours, `weight` = W, the sum of their weights): afterwards `colour / weight` is the
    /// constrained minimiser, and the same arrays feed the screened Poisson solve.
    pub fn add_to_e_step(&self, colour: &mut [f32], weight: &mut [f32]) {
        let c = self.target.channels();
        let (target, mask, lambda) = (self.target.data(), &self.mask[..], self.lambda);
        // Per pixel, so in parallel pieces of pixels.
        let mut pieces: Vec<(&mut [f32], &mut [f32])> = colour
            .chunks_mut(E_STEP_PIXELS * c)
            .zip(weight.chunks_mut(E_STEP_PIXELS))
            .collect();
        parallel::for_each_piece_mut(&mut pieces, 1, |p, piece| {
            let (colour, weight) = &mut piece[0];
            let first = p * E_STEP_PIXELS;
            let mask = &mask[first..first + weight.len()];
            let target = &target[first * c..(first + weight.len()) * c];
            if lambda == f32::INFINITY {
                // Hard: colour / weight becomes (1 - m) * average + m * c, the weight unchanged.
                for (i, (&m, &w)) in mask.iter().zip(weight.iter()).enumerate() {
                    if m > 0.0 {
                        for k in 0..c {
                            let v = &mut colour[i * c + k];
                            *v = (1.0 - m) * *v + m * w * target[i * c + k];
                        }
                    }
                }
                return;
            }
            for (i, (&m, w)) in mask.iter().zip(weight.iter_mut()).enumerate() {
                let lm = lambda * m;
                if lm > 0.0 {
                    let extra = lm * *w;
                    for k in 0..c {
                        colour[i * c + k] += extra * target[i * c + k];
                    }
                    *w += extra;
                }
            }
        });
    }

    /// The terms that turn a gathered neighbourhood query and its weights into the M-step's
    /// constrained search (see [`QueryTerms::apply`]), computed once for an M-step whose queries
    /// are made at every node visit.
    #[must_use]
    pub fn query_terms(&self) -> QueryTerms {
        let c = self.target.channels();
        let target = self.target.data();
        let mut pull = vec![0.0f32; target.len()];
        let mut gain = vec![1.0f32; self.mask.len()];
        let mut inverse = vec![1.0f32; self.mask.len()];
        // Hard constraints match as a soft constraint of lambda HARD_MATCH_LAMBDA: the query's
        // values stay what the E-step put there (the target), and the constrained pixels weigh
        // more.
        let lambda = if self.lambda.is_finite() {
            self.lambda
        } else {
            HARD_MATCH_LAMBDA
        };
        for (p, &m) in self.mask.iter().enumerate() {
            let lm = lambda * m;
            if lm > 0.0 {
                gain[p] = 1.0 + lm;
                inverse[p] = 1.0 / (1.0 + lm);
                for k in 0..c {
                    pull[p * c + k] = lm * target[p * c + k];
                }
            }
        }
        QueryTerms {
            width: self.target.width(),
            height: self.target.height(),
            channels: c,
            pull,
            gain,
            inverse,
        }
    }

    /// Mean squared difference per value between `output` and the target over the masked
    /// pixels, each weighted by its mask value (the control energy E_c normalised, lambda left
    /// out so that runs with different lambdas compare). Zero when nothing is masked.
    #[must_use]
    pub fn energy(&self, output: &Image) -> f64 {
        let c = self.target.channels();
        let (x, t) = (output.data(), self.target.data());
        let (mut sum, mut mass) = (0.0f64, 0.0f64);
        for (i, &m) in self.mask.iter().enumerate() {
            if m > 0.0 {
                let m = f64::from(m);
                for k in 0..c {
                    sum += m * f64::from(x[i * c + k] - t[i * c + k]).powi(2);
                }
                mass += m * c as f64;
            }
        }
        if mass > 0.0 { sum / mass } else { 0.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_names_the_problem() {
        let target = Image::new(4, 4, 3).unwrap();
        let msg = |r: Result<SoftConstraints>| r.unwrap_err().to_string();
        assert!(msg(SoftConstraints::new(target.clone(), vec![0.0; 15], 1.0)).contains("mask"));
        assert!(msg(SoftConstraints::new(target.clone(), vec![2.0; 16], 1.0)).contains("mask"));
        assert!(
            msg(SoftConstraints::new(
                target.clone(),
                vec![1.0; 16],
                f32::NAN
            ))
            .contains("lambda")
        );
        let mut bad = target.clone();
        bad.data_mut()[3] = f32::INFINITY;
        assert!(msg(SoftConstraints::new(bad, vec![1.0; 16], 1.0)).contains("target"));
    }

    #[test]
    fn shrinking_keeps_the_mask_share_and_the_stroke_colour() {
        // A one-pixel red line at x = 1 of an 8x8 image, shrunk to 2x2 (blocks of 4x4).
        let target = Image::from_fn(8, 8, 3, |_, _, k| if k == 0 { 1.0 } else { 0.0 }).unwrap();
        let mask: Vec<f32> = (0..64)
            .map(|i| if i % 8 == 1 { 1.0 } else { 0.0 })
            .collect();
        let soft = SoftConstraints::new(target, mask, 2.0).unwrap();
        let small = soft.at_size(2, 2);
        assert_eq!(small.mask, vec![0.25, 0.0, 0.25, 0.0]); // 4 of 16 pixels
        assert_eq!(small.lambda, 2.0);
        assert_eq!(small.target.pixel(0, 1), &[1.0, 0.0, 0.0]);
    }

    #[test]
    fn the_e_step_average_lands_between_texture_and_target() {
        let target = Image::from_fn(2, 1, 1, |_, _, _| 1.0).unwrap();
        let constraint = SoftConstraints::new(target, vec![1.0, 0.0], 1.0)
            .unwrap()
            .at_size(2, 1);
        // Texture average 0.2 from weight 4 at both pixels.
        let (mut colour, mut weight) = (vec![0.8, 0.8], vec![4.0, 4.0]);
        constraint.add_to_e_step(&mut colour, &mut weight);
        assert!((colour[0] / weight[0] - 0.6).abs() < 1e-6); // (0.2 + 1 * 1.0) / 2
        assert!((colour[1] / weight[1] - 0.2).abs() < 1e-6); // free pixel unchanged
    }

    #[test]
    fn the_m_step_query_completes_the_square() {
        // sum g (x - v)^2 + lm g (v - c)^2 = g (1 + lm) (v - q)^2 + const for every v.
        let target = Image::from_fn(1, 1, 1, |_, _, _| 0.9).unwrap();
        let constraint = SoftConstraints::new(target, vec![1.0], 3.0)
            .unwrap()
            .at_size(1, 1);
        let (x, g) = (0.1f32, 0.7f32);
        let (mut query, mut weights) = (vec![x], vec![g]);
        constraint
            .query_terms()
            .apply(0, 0, 1, 1, false, &mut query, &mut weights);
        let direct = |v: f32| g * (x - v).powi(2) + 3.0 * g * (v - 0.9).powi(2);
        let squared = |v: f32| weights[0] * (v - query[0]).powi(2);
        let offset = direct(0.0) - squared(0.0);
        for v in [0.2, 0.5, 1.0] {
            assert!((direct(v) - squared(v) - offset).abs() < 1e-5);
        }
    }

    #[test]
    fn queries_are_constrained_pixel_by_pixel_also_across_the_wrap() {
        // Against a direct per-pixel loop (wrapped coordinates by modulo), on a 7x5 target
        // with a partial mask, neighbourhoods of 3 with 2 values per pixel (colour + one more).
        let (w, h, size, dims) = (7usize, 5usize, 3usize, 2usize);
        let target = Image::from_fn(w, h, 1, |x, y, _| (x * 5 + y) as f32 / 40.0).unwrap();
        let mask: Vec<f32> = (0..w * h).map(|i| [0.0, 0.5, 1.0][i % 3]).collect();
        let lambda = 2.0;
        let constraint = SoftConstraints::new(target.clone(), mask.clone(), lambda)
            .unwrap()
            .at_size(w, h);
        for (x0, y0, wrap) in [(0, 0, false), (4, 2, false), (6, 4, true), (5, 3, true)] {
            let base: Vec<f32> = (0..size * size * dims).map(|i| i as f32 * 0.01).collect();
            let (mut query, mut weights) = (base.clone(), vec![0.5; base.len()]);
            constraint
                .query_terms()
                .apply(x0, y0, size, dims, wrap, &mut query, &mut weights);
            for dy in 0..size {
                for dx in 0..size {
                    let (x, y) = ((x0 + dx) % w, (y0 + dy) % h);
                    let lm = lambda * mask[y * w + x];
                    let i = (dy * size + dx) * dims;
                    let want = (base[i] + lm * target.pixel(x, y)[0]) / (1.0 + lm);
                    assert!(
                        (query[i] - want).abs() < 1e-6,
                        "({x0}, {y0}) at ({dx}, {dy})"
                    );
                    assert!((weights[i] - 0.5 * (1.0 + lm)).abs() < 1e-6);
                    // Values past the colour are left alone.
                    assert_eq!((query[i + 1], weights[i + 1]), (base[i + 1], 0.5));
                }
            }
        }
    }
}
