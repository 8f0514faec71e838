//! Orthonormal discrete wavelet transforms of square power-of-two blocks (the neighbourhoods of
//! texture optimisation, 8x8 to 32x32): Haar and Daubechies D4 (4 taps), separable 2-D in
//! Mallat's layout, periodic extension at the block border, forward and inverse. Written by
//! hand (no crate needed for four taps); the caller owns every buffer, so the hot path
//! allocates nothing.
//!
//! Layout after `levels` levels of an `n` x `n` block (row-major, one plane): the top-left
//! `n >> levels` square is the approximation; the detail bands of level `j` (0 = finest) are the
//! three quadrants of the `n >> j` square outside the `n >> (j + 1)` square.
//!
//! Both filters are orthonormal, so the transform preserves the sum of squares (Parseval).

use std::f64::consts::SQRT_2;

/// Which wavelet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wavelet {
    /// Haar: low-pass (1, 1)/sqrt(2), high-pass (1, -1)/sqrt(2).
    Haar,
    /// Daubechies D4: low-pass (1+sqrt3, 3+sqrt3, 3-sqrt3, 1-sqrt3)/(4 sqrt2), two vanishing
    /// moments (the detail of a linear signal is zero away from the periodic wrap).
    Daubechies4,
}

const HAAR: [f32; 2] = [
    std::f32::consts::FRAC_1_SQRT_2,
    std::f32::consts::FRAC_1_SQRT_2,
];

fn d4() -> [f32; 4] {
    let s3 = 3f64.sqrt();
    let k = 4.0 * SQRT_2;
    [
        ((1.0 + s3) / k) as f32,
        ((3.0 + s3) / k) as f32,
        ((3.0 - s3) / k) as f32,
        ((1.0 - s3) / k) as f32,
    ]
}

impl Wavelet {
    /// The low-pass filter h; the high-pass is g_k = (-1)^k h_(L-1-k).
    #[must_use]
    pub fn low_pass(self) -> Vec<f32> {
        match self {
            Wavelet::Haar => HAAR.to_vec(),
            Wavelet::Daubechies4 => d4().to_vec(),
        }
    }
}

/// The filter pair of a wavelet, held on the stack for the loops.
#[derive(Clone, Copy)]
struct Filters {
    h: [f32; 4],
    g: [f32; 4],
    taps: usize,
}

impl Filters {
    fn of(wavelet: Wavelet) -> Filters {
        let (h, taps) = match wavelet {
            Wavelet::Haar => ([HAAR[0], HAAR[1], 0.0, 0.0], 2),
            Wavelet::Daubechies4 => (d4(), 4),
        };
        let mut g = [0.0; 4];
        for k in 0..taps {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            g[k] = sign * h[taps - 1 - k];
        }
        Filters { h, g, taps }
    }
}

/// The most levels a block of side `size` takes (down to a 1x1 approximation).
#[must_use]
pub fn max_levels(size: usize) -> usize {
    if size.is_power_of_two() {
        size.trailing_zeros() as usize
    } else {
        0
    }
}

/// The detail level (0 = finest) of coefficient (x, y) of a `size` block after `levels`
/// levels, or None for the approximation band.
#[must_use]
pub fn band_level(x: usize, y: usize, size: usize, levels: usize) -> Option<usize> {
    let m = x.max(y);
    (0..levels).find(|&j| m >= size >> (j + 1))
}

/// One level of the 1-D transform of `n` samples `data[base + i * stride]`, periodic: the first
/// n/2 outputs are the approximation, the next n/2 the detail. `scratch` holds at least `n`.
fn forward_1d(
    f: Filters,
    data: &mut [f32],
    base: usize,
    stride: usize,
    n: usize,
    scratch: &mut [f32],
) {
    let (half, mask) = (n / 2, n - 1); // n is a power of two: `& mask` is the periodic wrap
    for i in 0..half {
        let (mut a, mut d) = (0.0, 0.0);
        for k in 0..f.taps {
            let v = data[base + ((2 * i + k) & mask) * stride];
            a += f.h[k] * v;
            d += f.g[k] * v;
        }
        scratch[i] = a;
        scratch[half + i] = d;
    }
    for (i, &v) in scratch[..n].iter().enumerate() {
        data[base + i * stride] = v;
    }
}

/// The inverse of [`forward_1d`] (the transpose of an orthonormal map).
fn inverse_1d(
    f: Filters,
    data: &mut [f32],
    base: usize,
    stride: usize,
    n: usize,
    scratch: &mut [f32],
) {
    let (half, mask) = (n / 2, n - 1);
    scratch[..n].fill(0.0);
    for i in 0..half {
        let a = data[base + i * stride];
        let d = data[base + (half + i) * stride];
        for k in 0..f.taps {
            scratch[(2 * i + k) & mask] += f.h[k] * a + f.g[k] * d;
        }
    }
    for (i, &v) in scratch[..n].iter().enumerate() {
        data[base + i * stride] = v;
    }
}

/// Forward 2-D transform of the `size` x `size` row-major `block`, in place, `levels` levels
/// (at most [`max_levels`]). `scratch` holds at least `size` values. `size` must be a power of
/// two.
pub fn forward_2d(
    wavelet: Wavelet,
    block: &mut [f32],
    size: usize,
    levels: usize,
    scratch: &mut [f32],
) {
    debug_assert!(size.is_power_of_two() && levels <= max_levels(size));
    debug_assert!(block.len() >= size * size && scratch.len() >= size);
    let f = Filters::of(wavelet);
    for level in 0..levels {
        let n = size >> level;
        for y in 0..n {
            forward_1d(f, block, y * size, 1, n, scratch);
        }
        for x in 0..n {
            forward_1d(f, block, x, size, n, scratch);
        }
    }
}

/// Inverse of [`forward_2d`] with the same `levels`.
pub fn inverse_2d(
    wavelet: Wavelet,
    block: &mut [f32],
    size: usize,
    levels: usize,
    scratch: &mut [f32],
) {
    debug_assert!(size.is_power_of_two() && levels <= max_levels(size));
    debug_assert!(block.len() >= size * size && scratch.len() >= size);
    let f = Filters::of(wavelet);
    for level in (0..levels).rev() {
        let n = size >> level;
        for x in 0..n {
            inverse_1d(f, block, x, size, n, scratch);
        }
        for y in 0..n {
            inverse_1d(f, block, y * size, 1, n, scratch);
        }
    }
}

/// Forward 1-D transform of `signal` (power-of-two length), in place, `levels` levels, for
/// tests and teaching.
pub fn forward_1d_levels(wavelet: Wavelet, signal: &mut [f32], levels: usize, scratch: &mut [f32]) {
    let f = Filters::of(wavelet);
    for level in 0..levels {
        forward_1d(f, signal, 0, 1, signal.len() >> level, scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    const BOTH: [Wavelet; 2] = [Wavelet::Haar, Wavelet::Daubechies4];

    fn random_block(size: usize, seed: u64) -> Vec<f32> {
        let mut rng = Rng::new(seed);
        (0..size * size)
            .map(|_| rng.next_f32() * 2.0 - 1.0)
            .collect()
    }

    #[test]
    fn filters_are_orthonormal() {
        for w in BOTH {
            let f = Filters::of(w);
            let hh: f32 = f.h.iter().map(|v| v * v).sum();
            let gg: f32 = f.g.iter().map(|v| v * v).sum();
            let hg: f32 = f.h.iter().zip(&f.g).map(|(a, b)| a * b).sum();
            assert!((hh - 1.0).abs() < 1e-6 && (gg - 1.0).abs() < 1e-6 && hg.abs() < 1e-6);
            // Sums: the low-pass passes a constant (sqrt 2), the high-pass removes it.
            assert!((f.h.iter().sum::<f32>() - SQRT_2 as f32).abs() < 1e-6);
            assert!(f.g.iter().sum::<f32>().abs() < 1e-6);
        }
    }

    #[test]
    fn forward_then_inverse_is_the_identity() {
        let mut scratch = [0.0; 64];
        for w in BOTH {
            for size in [2, 4, 8, 16, 32, 64] {
                for levels in 0..=max_levels(size).min(4) {
                    let original = random_block(size, size as u64 * 10 + levels as u64);
                    let mut block = original.clone();
                    forward_2d(w, &mut block, size, levels, &mut scratch);
                    if levels > 0 {
                        assert_ne!(block, original);
                    }
                    inverse_2d(w, &mut block, size, levels, &mut scratch);
                    for (a, b) in block.iter().zip(&original) {
                        assert!((a - b).abs() < 1e-5, "{w:?} {size} {levels}: {a} vs {b}");
                    }
                }
            }
        }
    }

    #[test]
    fn haar_2x2_by_hand() {
        // [a b; c d] -> [(a+b+c+d)/2, (a-b+c-d)/2; (a+b-c-d)/2, (a-b-c+d)/2]
        let mut block = [1.0, 2.0, 3.0, 4.0];
        forward_2d(Wavelet::Haar, &mut block, 2, 1, &mut [0.0; 2]);
        let expected = [5.0, -1.0, -2.0, 0.0];
        for (a, b) in block.iter().zip(&expected) {
            assert!((a - b).abs() < 1e-6, "{block:?}");
        }
    }

    #[test]
    fn haar_4x4_by_hand() {
        // A constant block: everything goes to the approximation, which after two levels is
        // the sum / 4 (the scale of an orthonormal 4x4 average: 16 values of 1 -> 4).
        let mut block = [1.0; 16];
        forward_2d(Wavelet::Haar, &mut block, 4, 2, &mut [0.0; 4]);
        assert!((block[0] - 4.0).abs() < 1e-6);
        assert!(block[1..].iter().all(|v| v.abs() < 1e-6));
        // A vertical edge between columns 1 and 2: rows are (0, 0, 1, 1). One level: each 2x2
        // cell is flat, so the level-0 details vanish; the 2x2 approximation is
        // [0 2; 0 2] (cell sums / 2). Second level: approximation (0 + 2 + 0 + 2) / 2 = 2, the
        // horizontal detail (0 - 2 + 0 - 2) / 2 = -2, the others 0.
        let mut edge: Vec<f32> = (0..16)
            .map(|i| if i % 4 >= 2 { 1.0 } else { 0.0 })
            .collect();
        forward_2d(Wavelet::Haar, &mut edge, 4, 2, &mut [0.0; 4]);
        let mut expected = [0.0; 16];
        expected[0] = 2.0;
        expected[1] = -2.0;
        for (i, (a, b)) in edge.iter().zip(&expected).enumerate() {
            assert!((a - b).abs() < 1e-6, "coefficient {i}: {a} vs {b}");
        }
    }

    #[test]
    fn d4_kills_the_detail_of_a_ramp_away_from_the_wrap_and_of_a_constant() {
        let mut scratch = [0.0; 16];
        let mut ramp: Vec<f32> = (0..16).map(|i| i as f32).collect();
        forward_1d_levels(Wavelet::Daubechies4, &mut ramp, 1, &mut scratch);
        // Details 8..16: d_i uses samples 2i..2i+3; only the last one wraps.
        for (i, d) in ramp.iter().enumerate().take(15).skip(8) {
            assert!(d.abs() < 1e-4, "detail {i} = {d}");
        }
        assert!(
            ramp[15].abs() > 1.0,
            "the wrapped detail sees the jump 15 -> 0"
        );
        // Approximations of a ramp: sum_k h_k (2i + k) = sqrt2 * 2i + sum_k k h_k.
        let f = d4();
        let offset: f32 = f.iter().enumerate().map(|(k, h)| k as f32 * h).sum();
        for (i, a) in ramp.iter().enumerate().take(7) {
            let expected = SQRT_2 as f32 * 2.0 * i as f32 + offset;
            assert!((a - expected).abs() < 1e-4, "approximation {i}");
        }
        let mut constant = [3.0f32; 8];
        forward_1d_levels(Wavelet::Daubechies4, &mut constant, 2, &mut scratch);
        assert!((constant[0] - 6.0).abs() < 1e-5); // 3 * sqrt2 * sqrt2
        assert!((constant[1] - 6.0).abs() < 1e-5);
        assert!(constant[2..].iter().all(|v| v.abs() < 1e-5), "{constant:?}");
    }

    #[test]
    fn parseval_energy_is_preserved() {
        // Property: for random blocks of every size and level count, sum of squares in equals
        // sum of squares out, and the transform is linear (W(a - b) = Wa - Wb).
        let mut scratch = [0.0; 32];
        for w in BOTH {
            for seed in 0..20u64 {
                let size = [4, 8, 16, 32][seed as usize % 4];
                let levels = 1 + seed as usize % max_levels(size);
                let a = random_block(size, seed);
                let b = random_block(size, seed + 100);
                let energy: f64 = a.iter().map(|&v| f64::from(v * v)).sum();
                let mut ca = a.clone();
                forward_2d(w, &mut ca, size, levels, &mut scratch);
                let coeff_energy: f64 = ca.iter().map(|&v| f64::from(v * v)).sum();
                assert!(
                    (energy - coeff_energy).abs() < 1e-4 * energy,
                    "{w:?} {size} {levels}"
                );
                let mut cb = b.clone();
                forward_2d(w, &mut cb, size, levels, &mut scratch);
                let mut diff: Vec<f32> = a.iter().zip(&b).map(|(x, y)| x - y).collect();
                forward_2d(w, &mut diff, size, levels, &mut scratch);
                for ((d, x), y) in diff.iter().zip(&ca).zip(&cb) {
                    assert!((d - (x - y)).abs() < 1e-4);
                }
            }
        }
    }

    #[test]
    fn bands_partition_the_block() {
        let (size, levels) = (8, 2);
        assert_eq!(band_level(0, 0, size, levels), None);
        assert_eq!(band_level(1, 1, size, levels), None);
        assert_eq!(band_level(2, 0, size, levels), Some(1));
        assert_eq!(band_level(3, 3, size, levels), Some(1));
        assert_eq!(band_level(4, 0, size, levels), Some(0));
        assert_eq!(band_level(0, 7, size, levels), Some(0));
        assert_eq!(max_levels(32), 5);
        assert_eq!(max_levels(12), 0);
    }
}
