//! Gradient-domain pasting of the labelled region (Shen et al. 2009, section 3.2, after the
//! photomontage's gradient-domain fusion): inside the region the result takes the gradients of
//! I_s, on the base around it the base's colours, so the pasted elements keep their texture
//! while their colour shifts smoothly to meet the base and no seam shows.
//!
//! It is the screened Poisson system of the project's solver (`solvers::poisson`) with the
//! base pixels of the window pinned by a data weight far above the gradient weights (1e4: they
//! move by less than 1e-4 of a difference, and only the region's pixels are written back) and
//! no data term inside the region. Every edge that touches the region is guided by I_s's
//! difference, so if I_s and the base agree on the pixels around the region the solution is I_s
//! itself.

use crate::solvers::poisson::ScreenedPoisson;

/// Data weight of a pinned (base) pixel against gradient weights of 1.
const PIN: f32 = 1.0e4;
/// Conjugate-gradient stopping rule: residual below this fraction of the right-hand side.
pub const TOLERANCE: f32 = 1.0e-5;
/// Iteration cap: a 128x128 region converges in a few hundred.
pub const MAX_ITERATIONS: usize = 2000;

/// Pastes `source` into `base` where `region` is true, in the gradient domain. Both are
/// `width` x `height` windows with `channels` interleaved values; `base` is overwritten in the
/// region only. Returns the conjugate-gradient iterations of the slowest channel.
pub fn paste(
    width: usize,
    height: usize,
    channels: usize,
    source: &[f32],
    region: &[bool],
    base: &mut [f32],
) -> usize {
    let n = width * height;
    debug_assert!(source.len() == n * channels && base.len() == n * channels && region.len() == n);
    if !region.iter().any(|&r| r) {
        return 0;
    }
    let data_weight: Vec<f32> = region.iter().map(|&r| if r { 0.0 } else { PIN }).collect();
    // Only edges with a region pixel at one end matter; the others join two pinned pixels.
    let mut h_weight = vec![0.0f32; n];
    let mut v_weight = vec![0.0f32; n];
    for y in 0..height {
        for x in 0..width {
            let i = y * width + x;
            if x + 1 < width && (region[i] || region[i + 1]) {
                h_weight[i] = 1.0;
            }
            if y + 1 < height && (region[i] || region[i + width]) {
                v_weight[i] = 1.0;
            }
        }
    }
    let system = ScreenedPoisson {
        width,
        height,
        wrap: false,
        mu: 1.0,
        data_weight: &data_weight,
        h_weight: &h_weight,
        v_weight: &v_weight,
    };
    let (mut ax, mut d) = (vec![0.0f32; n], vec![0.0f32; n]);
    let (mut dt, mut h_diff, mut v_diff, mut b, mut x) = (
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
        vec![0.0f32; n],
    );
    let mut iterations = 0;
    for c in 0..channels {
        for i in 0..n {
            dt[i] = data_weight[i] * base[i * channels + c];
            // Warm start: the plain cut-and-paste.
            x[i] = if region[i] {
                source[i * channels + c]
            } else {
                base[i * channels + c]
            };
            let s = |j: usize| source[j * channels + c];
            h_diff[i] = if h_weight[i] > 0.0 {
                s(i + 1) - s(i)
            } else {
                0.0
            };
            v_diff[i] = if v_weight[i] > 0.0 {
                s(i + width) - s(i)
            } else {
                0.0
            };
        }
        system.right_hand_side(&dt, &h_diff, &v_diff, &mut b);
        // Solve for the correction to the cut-and-paste, A d = b - A x0, from d = 0: the
        // solver's tolerance is relative to the right-hand side, and b itself is dominated by
        // the pinned pixels' 1e4 weights, which would make the region's error 1e4 times looser.
        system.apply(&x, &mut ax);
        for i in 0..n {
            b[i] -= ax[i];
            d[i] = 0.0;
        }
        iterations = iterations.max(system.solve(&b, &mut d, MAX_ITERATIONS, TOLERANCE));
        for i in 0..n {
            if region[i] {
                base[i * channels + c] = x[i] + d[i];
            }
        }
    }
    iterations
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    fn disc(w: usize, h: usize) -> Vec<bool> {
        (0..w * h)
            .map(|i| {
                let (x, y) = ((i % w) as f32 - 7.0, (i / w) as f32 - 6.0);
                x * x + y * y < 16.0
            })
            .collect()
    }

    #[test]
    fn agreeing_borders_reproduce_the_source_and_the_base_is_untouched() {
        let (w, h, c) = (15, 13, 3);
        let mut rng = Rng::new(3);
        let source: Vec<f32> = (0..w * h * c).map(|_| rng.next_f32()).collect();
        let region = disc(w, h);
        // The base equals the source outside the region and is garbage inside.
        let mut base: Vec<f32> = source
            .iter()
            .enumerate()
            .map(|(k, &v)| if region[k / c] { 0.9 - v * 0.3 } else { v })
            .collect();
        let before = base.clone();
        paste(w, h, c, &source, &region, &mut base);
        for (k, (&got, &want)) in base.iter().zip(&source).enumerate() {
            if region[k / c] {
                assert!(
                    (got - want).abs() < 1e-3,
                    "pixel {}: {got} vs {want}",
                    k / c
                );
            } else {
                assert_eq!(got, before[k], "outside the region nothing moves");
            }
        }
    }

    #[test]
    fn a_brighter_source_keeps_its_gradients_and_meets_the_base() {
        let (w, h, c) = (15, 13, 1);
        let region = disc(w, h);
        // Source: a ramp plus 0.5; base: the same ramp. The paste removes the offset.
        let ramp: Vec<f32> = (0..w * h).map(|i| (i % w) as f32 * 0.02).collect();
        let source: Vec<f32> = ramp.iter().map(|v| v + 0.5).collect();
        let mut base = ramp.clone();
        paste(w, h, c, &source, &region, &mut base);
        for i in 0..w * h {
            assert!(
                (base[i] - ramp[i]).abs() < 1e-3,
                "{i}: {} vs {}",
                base[i],
                ramp[i]
            );
        }
    }
}
