//! The two-label graph cut of stage 2 (Shen et al. 2009, section 3.2, eqs. 1-3): which pixels of
//! a window on the base texture take the clipped reference I_s, and which keep the base.
//!
//! E(L) = sum_p E_d(p, L(p)) + sum_(p,q) E_s(p, q, L(p), L(q)), with
//! - E_d = nu where the stroke lies and the label is not I_s (eq. 2), 0 elsewhere. Eq. 2 reads as
//!   if it held at every pixel, but then every pixel would take I_s whatever the seam; like the
//!   photomontage it builds on, it constrains the brushed pixels only.
//! - E_s = k1 S_x + k2 S_y across a seam (eq. 3): S_x sums the colour differences of the two
//!   labels' images at p and at q, S_y the differences of their 6-component colour gradients.
//! - The window's own border keeps the base (a hard constraint where the window lies inside the
//!   base), so that the pasted region is enclosed by base texture, as in Fig. 3(d).
//!
//! The minimum is found exactly by the project's max-flow solver: the source side is I_s, the
//! sink side the base.

use crate::core::{Error, Result};
use crate::methods::graphcut::cost::colour_distance;
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

/// The weights of eqs. 2 and 3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LabellingWeights {
    /// Cost of a brushed pixel that does not take I_s (eq. 2). Default: 1000, far above any seam
    /// (colour differences are at most sqrt(3) per pixel), so the stroke is always taken; lower
    /// it to let a costly seam trim the stroke's rough edge.
    pub nu: f32,
    /// Weight of the colour term S_x (eq. 3). Default: 0.5, the paper's.
    pub k1: f32,
    /// Weight of the gradient term S_y (eq. 3). Default: 0.5, the paper's.
    pub k2: f32,
}

impl Default for LabellingWeights {
    fn default() -> Self {
        LabellingWeights {
            nu: 1000.0,
            k1: 0.5,
            k2: 0.5,
        }
    }
}

impl LabellingWeights {
    pub fn validate(&self) -> Result<()> {
        for (name, v) in [("nu", self.nu), ("k1", self.k1), ("k2", self.k2)] {
            if !v.is_finite() || v < 0.0 {
                return Err(Error::InvalidParameter {
                    name,
                    reason: format!("must be a finite number >= 0, got {v}"),
                });
            }
        }
        if self.nu > 1.0e9 {
            return Err(Error::InvalidParameter {
                name: "nu",
                reason: format!(
                    "must be at most 1e9 (the solver's finite range), got {}",
                    self.nu
                ),
            });
        }
        Ok(())
    }
}

/// One label's view of the window: its colour and its 6-component gradient (d/dx then d/dy per
/// channel) at every window pixel, `channels` and `2 * channels` values per pixel.
pub struct LabelImage {
    pub colour: Vec<f32>,
    pub gradient: Vec<f32>,
}

/// What pins a window pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pin {
    Free,
    /// Under the stroke: costs nu unless it takes I_s.
    Stroke,
    /// On the window's border inside the base: must keep the base.
    Base,
}

/// The labelling problem on a `width` x `height` window.
pub struct Problem<'a> {
    pub width: usize,
    pub height: usize,
    pub channels: usize,
    pub source: &'a LabelImage,
    pub base: &'a LabelImage,
    pub pins: &'a [Pin],
    pub weights: LabellingWeights,
}

impl Problem<'_> {
    /// E_s of the edge p-q when their labels differ (eq. 3).
    #[must_use]
    pub fn seam_cost(&self, p: usize, q: usize) -> f32 {
        let (c, g) = (self.channels, 2 * self.channels);
        let (s, b) = (self.source, self.base);
        let colour = |i: usize| {
            colour_distance(&s.colour[i * c..(i + 1) * c], &b.colour[i * c..(i + 1) * c])
        };
        let grad = |i: usize| {
            colour_distance(
                &s.gradient[i * g..(i + 1) * g],
                &b.gradient[i * g..(i + 1) * g],
            )
        };
        let s_x = colour(p) + colour(q);
        let s_y = grad(p) + grad(q);
        self.weights.k1 * s_x + self.weights.k2 * s_y
    }

    /// E(L) for a labelling (`true` = I_s), infinite if it breaks a hard pin.
    #[must_use]
    pub fn energy(&self, labels: &[bool]) -> f64 {
        let (w, h) = (self.width, self.height);
        let mut e = 0.0f64;
        for (i, (&pin, &l)) in self.pins.iter().zip(labels).enumerate() {
            match (pin, l) {
                (Pin::Stroke, false) => e += f64::from(self.weights.nu),
                (Pin::Base, true) => return f64::INFINITY,
                _ => {}
            }
            let (x, y) = (i % w, i / w);
            if x + 1 < w && labels[i + 1] != l {
                e += f64::from(self.seam_cost(i, i + 1));
            }
            if y + 1 < h && labels[i + w] != l {
                e += f64::from(self.seam_cost(i, i + w));
            }
        }
        e
    }

    /// The labelling of least energy (`true` = I_s) and its energy.
    pub fn solve(&self, graph: &mut Graph) -> Result<(Vec<bool>, f64)> {
        let (w, h) = (self.width, self.height);
        let n = w * h;
        if self.pins.len() != n {
            return Err(Error::LengthMismatch {
                what: "labelling pins",
                expected: n,
                actual: self.pins.len(),
            });
        }
        graph.reset(n)?;
        for (i, &pin) in self.pins.iter().enumerate() {
            match pin {
                Pin::Stroke => graph.add_terminal(i, self.weights.nu, 0.0)?,
                Pin::Base => graph.add_terminal(i, 0.0, HARD_CONSTRAINT)?,
                Pin::Free => {}
            }
            let (x, y) = (i % w, i / w);
            if x + 1 < w {
                let cost = self.seam_cost(i, i + 1);
                graph.add_edge(i, i + 1, cost, cost)?;
            }
            if y + 1 < h {
                let cost = self.seam_cost(i, i + w);
                graph.add_edge(i, i + w, cost, cost)?;
            }
        }
        let flow = graph.maxflow();
        let labels: Vec<bool> = (0..n).map(|i| graph.is_source_side(i)).collect();
        Ok((labels, flow))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    fn random_label_image(n: usize, rng: &mut Rng) -> LabelImage {
        LabelImage {
            colour: (0..n * 3).map(|_| rng.next_f32()).collect(),
            gradient: (0..n * 6).map(|_| rng.next_f32() - 0.5).collect(),
        }
    }

    /// A 6x5 window: its 18 border pixels keep the base, 1-2 stroke pixels inside, 12 free
    /// interior pixels, so all 4096 labellings of the interior can be tried.
    #[test]
    fn the_cut_is_the_true_minimum_and_honours_the_stroke() {
        let (w, h) = (6, 5);
        let n = w * h;
        for seed in 0..12u64 {
            let mut rng = Rng::new(seed);
            let (source, base) = (
                random_label_image(n, &mut rng),
                random_label_image(n, &mut rng),
            );
            let mut pins: Vec<Pin> = (0..n)
                .map(|i| {
                    let (x, y) = (i % w, i / w);
                    if x == 0 || y == 0 || x == w - 1 || y == h - 1 {
                        Pin::Base
                    } else {
                        Pin::Free
                    }
                })
                .collect();
            pins[2 * w + 2] = Pin::Stroke;
            if seed % 2 == 0 {
                pins[2 * w + 3] = Pin::Stroke;
            }
            let nu = if seed < 6 {
                1000.0
            } else {
                0.5 + seed as f32 * 0.2
            };
            let problem = Problem {
                width: w,
                height: h,
                channels: 3,
                source: &source,
                base: &base,
                pins: &pins,
                weights: LabellingWeights {
                    nu,
                    ..LabellingWeights::default()
                },
            };
            let (labels, flow) = problem.solve(&mut Graph::new(1).unwrap()).unwrap();
            let interior: Vec<usize> = (0..n).filter(|&i| pins[i] != Pin::Base).collect();
            let mut best = f64::INFINITY;
            for mask in 0u32..1 << interior.len() {
                let mut l = vec![false; n];
                for (k, &i) in interior.iter().enumerate() {
                    l[i] = mask >> k & 1 == 1;
                }
                best = best.min(problem.energy(&l));
            }
            let found = problem.energy(&labels);
            assert!(
                (found - best).abs() < 1e-4,
                "seed {seed}: {found} vs {best}"
            );
            assert!(
                (flow - best).abs() < 1e-3,
                "seed {seed}: flow {flow} vs {best}"
            );
            if nu >= 1000.0 {
                assert!(labels[2 * w + 2], "the stroke takes I_s");
            }
            assert!(
                (0..n).all(|i| pins[i] != Pin::Base || !labels[i]),
                "the border keeps the base"
            );
        }
    }

    #[test]
    fn bad_weights_are_named() {
        let bad = LabellingWeights {
            k1: f32::NAN,
            ..LabellingWeights::default()
        };
        assert!(bad.validate().unwrap_err().to_string().contains("k1"));
        let bad = LabellingWeights {
            nu: -1.0,
            ..LabellingWeights::default()
        };
        assert!(bad.validate().unwrap_err().to_string().contains("nu"));
    }
}
