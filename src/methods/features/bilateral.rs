//! The bilateral filter (Tomasi & Manduchi 1998) that Wu & Yu 2004 (section 2.3) run before
//! edge and ridge detection: it smooths texture noise but keeps edges sharp. Closeness
//! sigma_d = 2 pixels, similarity sigma_r = 10/256 of the grey range.

/// Filters a `width` x `height` grey image (values in 0..1). The window reaches 2 sigma_d; the
/// spatial weights are tabulated once, and so is the range weight's exponential ([`NegExp`]).
#[must_use]
pub fn bilateral(
    grey: &[f32],
    width: usize,
    height: usize,
    sigma_d: f32,
    sigma_r: f32,
) -> Vec<f32> {
    let radius = (2.0 * sigma_d).ceil() as isize;
    let side = (2 * radius + 1) as usize;
    let mut spatial = vec![0.0f32; side * side];
    for dy in -radius..=radius {
        for dx in -radius..=radius {
            let d2 = (dx * dx + dy * dy) as f32;
            spatial[((dy + radius) as usize) * side + (dx + radius) as usize] =
                crate::core::math::expf(-d2 / (2.0 * sigma_d * sigma_d));
        }
    }
    let range_scale = 1.0 / (2.0 * sigma_r * sigma_r);
    let neg_exp = NegExp::new();
    let mut out = vec![0.0f32; grey.len()];
    let r = radius as usize;
    for y in 0..height {
        // The window clipped to the image once per pixel, then walked as zipped row slices (the
        // same pairs in the same order as a bounds check per pair, without the checks).
        let (y0, y1) = (y.saturating_sub(r), (y + r).min(height - 1));
        for x in 0..width {
            let centre = grey[y * width + x];
            let (x0, x1) = (x.saturating_sub(r), (x + r).min(width - 1));
            let (mut sum, mut norm) = (0.0f32, 0.0f32);
            for yy in y0..=y1 {
                let weights = &spatial[(yy + r - y) * side + (x0 + r - x)..];
                let values = &grey[yy * width + x0..=yy * width + x1];
                for (&v, &g) in values.iter().zip(weights) {
                    let d = v - centre;
                    let w = g * neg_exp.at(d * d * range_scale);
                    sum += w * v;
                    norm += w;
                }
            }
            out[y * width + x] = sum / norm;
        }
    }
    out
}

/// `exp(-t)` for `t >= 0`, tabulated and read linearly between entries (at most 1e-6 off);
/// 0 past [`NegExp::CUTOFF`], where it is below 3e-9. The range weight of every pair in the
/// window was a library call: over a 12-megapixel photo that was a quarter of the feature-guided
/// session's set-up (15 s of 53 natively).
struct NegExp {
    table: Vec<f32>,
}

impl NegExp {
    const CUTOFF: f32 = 20.0;
    const STEPS: usize = 8192;

    fn new() -> Self {
        let step = Self::CUTOFF / Self::STEPS as f32;
        let table = (0..=Self::STEPS + 1)
            .map(|i| crate::core::math::expf(-(i as f32) * step))
            .collect();
        NegExp { table }
    }

    #[inline]
    fn at(&self, t: f32) -> f32 {
        let u = t * (Self::STEPS as f32 / Self::CUTOFF);
        // Past the cutoff, and for a NaN (no pair of finite values gives one), nothing.
        if u.is_nan() || u >= Self::STEPS as f32 {
            return 0.0;
        }
        let i = u as usize;
        let (a, b) = (self.table[i], self.table[i + 1]);
        a + (u - i as f32) * (b - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// The filter written straight from its definition, in f64, over the whole image.
    fn direct(grey: &[f32], w: usize, h: usize, sd: f64, sr: f64) -> Vec<f64> {
        let r = (2.0 * sd).ceil() as i64;
        (0..w * h)
            .map(|i| {
                let (x, y) = ((i % w) as i64, (i / w) as i64);
                let c = f64::from(grey[i]);
                let (mut s, mut n) = (0.0, 0.0);
                for yy in 0..h as i64 {
                    for xx in 0..w as i64 {
                        if (xx - x).abs() > r || (yy - y).abs() > r {
                            continue;
                        }
                        let v = f64::from(grey[(yy as usize) * w + xx as usize]);
                        let d2 = ((xx - x).pow(2) + (yy - y).pow(2)) as f64;
                        let wgt = crate::core::math::exp(-d2 / (2.0 * sd * sd))
                            * crate::core::math::exp(-(v - c).powi(2) / (2.0 * sr * sr));
                        s += wgt * v;
                        n += wgt;
                    }
                }
                s / n
            })
            .collect()
    }

    #[test]
    fn the_tabulated_exponential_is_within_a_millionth_and_zero_past_its_cutoff() {
        let e = NegExp::new();
        let mut worst = 0.0f64;
        for k in 0..200_000 {
            let t = k as f32 * 1e-4;
            let err = (f64::from(e.at(t)) - (-f64::from(t)).exp()).abs();
            worst = worst.max(err);
        }
        assert!(worst < 1e-6, "worst error {worst}");
        for t in [20.0f32, 21.0, 1e9, f32::INFINITY] {
            assert_eq!(e.at(t), 0.0, "exp(-{t})");
        }
        assert_eq!(e.at(0.0), 1.0);
    }

    #[test]
    fn it_matches_the_direct_definition_and_keeps_a_step_edge() {
        let (w, h) = (17, 13);
        let mut rng = Rng::new(5);
        let grey: Vec<f32> = (0..w * h)
            .map(|i| if i % w < 8 { 0.2 } else { 0.8 } + 0.02 * rng.next_f32())
            .collect();
        let fast = bilateral(&grey, w, h, 2.0, 10.0 / 256.0);
        let slow = direct(&grey, w, h, 2.0, 10.0 / 256.0);
        for (a, b) in fast.iter().zip(&slow) {
            assert!((f64::from(*a) - b).abs() < 1e-5, "{a} vs {b}");
        }
        // The step survives: the columns either side of it stay 0.6 apart.
        assert!(fast[6 * w + 8] - fast[6 * w + 7] > 0.55);
    }
}
