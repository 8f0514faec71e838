//! The bilateral filter (Tomasi & Manduchi 1998) that Wu & Yu 2004 (section 2.3) run before
//! edge and ridge detection: it smooths texture noise but keeps edges sharp. Closeness
//! sigma_d = 2 pixels, similarity sigma_r = 10/256 of the grey range.

/// Filters a `width` x `height` grey image (values in 0..1). The window reaches 2 sigma_d; the
/// spatial weights are tabulated once, the range weight is `neg_exp`.
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
    let mut out = vec![0.0f32; grey.len()];
    let r = radius as usize;
    for y in 0..height {
        // The window clipped to the image once per pixel, then walked as zipped row slices (the
        // same pairs in the same order as a bounds check per pair, without the checks).
        let (y0, y1) = (y.saturating_sub(r), (y + r).min(height - 1));
        let mut x = 0;
        while x < width {
            if x >= r && x + LANES + r <= width {
                // LANES pixels at once, whose windows lie whole in the row: each pixel's sums
                // in the same order as below, in lanes the compiler vectorises.
                let at = y * width + x;
                let centre: [f32; LANES] = std::array::from_fn(|j| grey[at + j]);
                let (mut sum, mut norm) = ([0.0f32; LANES], [0.0f32; LANES]);
                for yy in y0..=y1 {
                    let weights = &spatial[(yy + r - y) * side..(yy + r - y + 1) * side];
                    let row = &grey[yy * width + x - r..yy * width + x + LANES + r];
                    for (dx, &g) in weights.iter().enumerate() {
                        let values = &row[dx..dx + LANES];
                        for j in 0..LANES {
                            let (v, d) = (values[j], values[j] - centre[j]);
                            let w = g * neg_exp(d * d * range_scale);
                            sum[j] += w * v;
                            norm[j] += w;
                        }
                    }
                }
                for j in 0..LANES {
                    out[at + j] = sum[j] / norm[j];
                }
                x += LANES;
                continue;
            }
            let centre = grey[y * width + x];
            let (x0, x1) = (x.saturating_sub(r), (x + r).min(width - 1));
            let (mut sum, mut norm) = (0.0f32, 0.0f32);
            for yy in y0..=y1 {
                let weights = &spatial[(yy + r - y) * side + (x0 + r - x)..];
                let values = &grey[yy * width + x0..=yy * width + x1];
                for (&v, &g) in values.iter().zip(weights) {
                    let d = v - centre;
                    let w = g * neg_exp(d * d * range_scale);
                    sum += w * v;
                    norm += w;
                }
            }
            out[y * width + x] = sum / norm;
            x += 1;
        }
    }
    out
}

/// Output pixels filtered together away from the image's sides.
const LANES: usize = 8;

/// `exp(-t)` for `t >= 0` (relative error under 3e-6, under 1e-6 for the weights above e^-8
/// that make a pixel's value; 0 from `t` = 80 on), in plain
/// arithmetic that the compiler vectorises: `2^-x` with `x = t log2(e)` split into a whole power
/// `k` (written into the exponent bits) and a remainder `f` in [-1/2, 1/2] (a Taylor polynomial
/// of `e^(-f ln 2)`, degree 6). It gives the range weight of every pair in the window: as a
/// library call, over a 12-megapixel photo, that takes a quarter of the feature-guided session's
/// set-up.
#[inline(always)]
fn neg_exp(t: f32) -> f32 {
    let x = (t * std::f32::consts::LOG2_E).min(126.0);
    let k = (x + 0.5) as i32;
    let u = (x - k as f32) * -std::f32::consts::LN_2;
    let p = 1.0
        + u * (1.0
            + u * (1.0 / 2.0
                + u * (1.0 / 6.0 + u * (1.0 / 24.0 + u * (1.0 / 120.0 + u * (1.0 / 720.0))))));
    let scale = f32::from_bits(((127 - k) as u32) << 23);
    if x >= 115.0 { 0.0 } else { p * scale }
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
    fn the_exponential_is_within_a_few_millionths_and_zero_far_out() {
        let (mut worst, mut worst_near) = (0.0f64, 0.0f64);
        for k in 0..400_000 {
            let t = k as f32 * 1e-4;
            let want = (-f64::from(t)).exp();
            let err = (f64::from(neg_exp(t)) - want).abs() / want;
            worst = worst.max(err);
            if t <= 8.0 {
                worst_near = worst_near.max(err);
            }
        }
        assert!(
            worst_near < 1e-6,
            "worst relative error up to t = 8: {worst_near}"
        );
        // Up to t = 40 (weights of 4e-18): the f32 rounding of t log2(e) is most of it there.
        assert!(worst < 3e-6, "worst relative error {worst}");
        assert_eq!(neg_exp(0.0), 1.0);
        for t in [80.0f32, 1e9, f32::INFINITY] {
            assert_eq!(neg_exp(t), 0.0, "exp(-{t})");
        }
    }

    #[test]
    fn the_lanes_and_the_sides_give_the_same_sums() {
        // A wide image: every row has pixels filtered in lanes and pixels filtered one by one;
        // the same image shifted by one column swaps which is which for most pixels.
        let (w, h) = (41, 9);
        let mut rng = Rng::new(3);
        let grey: Vec<f32> = (0..w * h).map(|_| rng.next_f32()).collect();
        let out = bilateral(&grey, w, h, 2.0, 10.0 / 256.0);
        let shifted: Vec<f32> = (0..h)
            .flat_map(|y| std::iter::once(0.5).chain(grey[y * w..(y + 1) * w].iter().copied()))
            .collect();
        let out2 = bilateral(&shifted, w + 1, h, 2.0, 10.0 / 256.0);
        for y in 0..h {
            for x in 5..w - 4 {
                assert_eq!(
                    out[y * w + x].to_bits(),
                    out2[y * (w + 1) + x + 1].to_bits(),
                    "({x}, {y})"
                );
            }
        }
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
