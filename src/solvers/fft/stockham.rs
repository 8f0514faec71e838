//! Mixed-radix Stockham passes (radices 8, 4, 2, 3 and 5) for lengths `2^a 3^b 5^c`.
//!
//! The self-sorting (Stockham) decimation in frequency: each pass reads one buffer and writes the
//! other, so the result comes out in natural order with no bit-reversal step. A pass of radix `p`
//! over sub-transforms of length `L` (`m = L / p` of them per stride `s`, `s` = the product of the
//! radices already done) computes, for every `j < m` and `q < s`,
//!
//! ```text
//! a_r = x[q + s (j + r m)]            r = 0 .. p-1
//! y[q + s (p j + k)] = w_L^{j k} sum_r a_r w_p^{r k}
//! ```
//!
//! with `w_L = e^{-2 pi i / L}`. After the last pass (`L = 1`) the buffer holds the transform.

use super::Complex;
use super::lane::Lane;
use super::smooth::is_smooth;
use super::twiddle::{Direction, twiddle};

type C = Complex<f64>;

/// One pass: its radix, the sub-transform length `L` it splits and where its twiddles start.
#[derive(Debug, Clone)]
struct Pass {
    radix: usize,
    length: usize,
    twiddles: usize,
}

/// A planned Stockham transform.
#[derive(Debug, Clone)]
pub(super) struct Stockham {
    len: usize,
    inverse: bool,
    passes: Vec<Pass>,
    /// Per pass, `w_L^{j k}` for `j < m`, `k = 1 .. p-1`, row by row.
    twiddles: Vec<C>,
}

impl Stockham {
    /// `None` when `len` has a prime factor other than 2, 3 and 5.
    pub(super) fn new(len: usize, direction: Direction) -> Option<Self> {
        if !is_smooth(len) {
            return None;
        }
        // Radix 8 and 4 where possible (each pass reads and writes the whole buffer, so fewer
        // passes is most of the speed), one radix 2 for what is left of the power of two, then
        // the 3s and 5s.
        let mut radices = Vec::new();
        let mut rest = len;
        while rest.is_multiple_of(8) {
            radices.push(8);
            rest /= 8;
        }
        while rest.is_multiple_of(4) {
            radices.push(4);
            rest /= 4;
        }
        for p in [2, 3, 5] {
            while rest.is_multiple_of(p) {
                radices.push(p);
                rest /= p;
            }
        }
        let mut passes = Vec::with_capacity(radices.len());
        let mut twiddles = Vec::new();
        let mut length = len;
        for radix in radices {
            let m = length / radix;
            passes.push(Pass {
                radix,
                length,
                twiddles: twiddles.len(),
            });
            for j in 0..m {
                for k in 1..radix {
                    twiddles.push(twiddle(j * k, length, direction));
                }
            }
            length = m;
        }
        Some(Stockham {
            len,
            inverse: direction == Direction::Inverse,
            passes,
            twiddles,
        })
    }

    /// Transforms the `batch` interleaved sequences of `data` in place (value `j` of sequence
    /// `b` at `j * batch + b`); `scratch` has the same length. Interleaving is the stride the
    /// passes have anyway, so a batch makes every inner loop `batch` times longer and contiguous.
    pub(super) fn process(&self, data: &mut [C], scratch: &mut [C], batch: usize) {
        let mut stride = batch;
        let mut in_data = true;
        for pass in &self.passes {
            let (x, y): (&[C], &mut [C]) = if in_data {
                (data, scratch)
            } else {
                (scratch, data)
            };
            let m = pass.length / pass.radix;
            let twiddles = &self.twiddles[pass.twiddles..pass.twiddles + m * (pass.radix - 1)];
            match (pass.radix, self.inverse) {
                (8, false) => radix8::<false>(x, y, m, stride, twiddles),
                (8, true) => radix8::<true>(x, y, m, stride, twiddles),
                (4, false) => radix4::<false>(x, y, m, stride, twiddles),
                (4, true) => radix4::<true>(x, y, m, stride, twiddles),
                (2, _) => radix2(x, y, m, stride, twiddles),
                (3, false) => radix3::<false>(x, y, m, stride, twiddles),
                (3, true) => radix3::<true>(x, y, m, stride, twiddles),
                (5, false) => radix5::<false>(x, y, m, stride, twiddles),
                (5, true) => radix5::<true>(x, y, m, stride, twiddles),
                _ => unreachable!("only radices 2, 3, 4, 5 and 8 are planned"),
            }
            stride *= pass.radix;
            in_data = !in_data;
        }
        if !in_data {
            data.copy_from_slice(scratch);
        }
        debug_assert_eq!(stride, self.len * batch);
    }
}

fn radix2(x: &[C], y: &mut [C], m: usize, s: usize, twiddles: &[C]) {
    let (x0, x1) = x.split_at(s * m);
    for (j, &w) in twiddles.iter().enumerate() {
        let w = Lane::load(w);
        let (y0, y1) = y[s * 2 * j..s * (2 * j + 2)].split_at_mut(s);
        let a0 = &x0[s * j..s * j + s];
        let a1 = &x1[s * j..s * j + s];
        for q in 0..s {
            let (a, b) = (Lane::load(a0[q]), Lane::load(a1[q]));
            y0[q] = a.add(b).get();
            y1[q] = a.sub(b).mul(w).get();
        }
    }
}

fn radix4<const INVERSE: bool>(x: &[C], y: &mut [C], m: usize, s: usize, twiddles: &[C]) {
    let quarter = s * m;
    for j in 0..m {
        let w = &twiddles[3 * j..3 * j + 3];
        let (w1, w2, w3) = (Lane::load(w[0]), Lane::load(w[1]), Lane::load(w[2]));
        let out = &mut y[s * 4 * j..s * (4 * j + 4)];
        let (y0, out) = out.split_at_mut(s);
        let (y1, out) = out.split_at_mut(s);
        let (y2, y3) = out.split_at_mut(s);
        let base = s * j;
        let a0 = &x[base..base + s];
        let a1 = &x[base + quarter..base + quarter + s];
        let a2 = &x[base + 2 * quarter..base + 2 * quarter + s];
        let a3 = &x[base + 3 * quarter..base + 3 * quarter + s];
        for q in 0..s {
            let (b0, b1, b2, b3) = (
                Lane::load(a0[q]),
                Lane::load(a1[q]),
                Lane::load(a2[q]),
                Lane::load(a3[q]),
            );
            let [c0, c1, c2, c3] = dft4::<INVERSE>(b0, b1, b2, b3);
            y0[q] = c0.get();
            y1[q] = c1.mul(w1).get();
            y2[q] = c2.mul(w2).get();
            y3[q] = c3.mul(w3).get();
        }
    }
}

fn radix3<const INVERSE: bool>(x: &[C], y: &mut [C], m: usize, s: usize, twiddles: &[C]) {
    // w_3 = -1/2 -+ i sqrt(3)/2.
    const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;
    let third = s * m;
    for j in 0..m {
        let (w1, w2) = (Lane::load(twiddles[2 * j]), Lane::load(twiddles[2 * j + 1]));
        let out = &mut y[s * 3 * j..s * (3 * j + 3)];
        let (y0, out) = out.split_at_mut(s);
        let (y1, y2) = out.split_at_mut(s);
        let base = s * j;
        let a0 = &x[base..base + s];
        let a1 = &x[base + third..base + third + s];
        let a2 = &x[base + 2 * third..base + 2 * third + s];
        for q in 0..s {
            let (b0, b1, b2) = (Lane::load(a0[q]), Lane::load(a1[q]), Lane::load(a2[q]));
            let sum = b1.add(b2);
            let centre = b0.sub(sum.scale(0.5));
            let turn = b1.sub(b2).rotate::<INVERSE>().scale(HALF_SQRT3);
            y0[q] = b0.add(sum).get();
            y1[q] = centre.add(turn).mul(w1).get();
            y2[q] = centre.sub(turn).mul(w2).get();
        }
    }
}

fn radix5<const INVERSE: bool>(x: &[C], y: &mut [C], m: usize, s: usize, twiddles: &[C]) {
    // cos and sin of 2 pi / 5 and 4 pi / 5.
    const C1: f64 = 0.309_016_994_374_947_45;
    const C2: f64 = -0.809_016_994_374_947_5;
    const S1: f64 = 0.951_056_516_295_153_5;
    const S2: f64 = 0.587_785_252_292_473_1;
    let fifth = s * m;
    for j in 0..m {
        let w = &twiddles[4 * j..4 * j + 4];
        let (w1, w2, w3, w4) = (
            Lane::load(w[0]),
            Lane::load(w[1]),
            Lane::load(w[2]),
            Lane::load(w[3]),
        );
        let out = &mut y[s * 5 * j..s * (5 * j + 5)];
        let (y0, out) = out.split_at_mut(s);
        let (y1, out) = out.split_at_mut(s);
        let (y2, out) = out.split_at_mut(s);
        let (y3, y4) = out.split_at_mut(s);
        let base = s * j;
        let a = |r: usize| &x[base + r * fifth..base + r * fifth + s];
        let (a0, a1, a2, a3, a4) = (a(0), a(1), a(2), a(3), a(4));
        for q in 0..s {
            let b0 = Lane::load(a0[q]);
            let (b1, b2, b3, b4) = (
                Lane::load(a1[q]),
                Lane::load(a2[q]),
                Lane::load(a3[q]),
                Lane::load(a4[q]),
            );
            let s1 = b1.add(b4);
            let d1 = b1.sub(b4);
            let s2 = b2.add(b3);
            let d2 = b2.sub(b3);
            let e1 = b0.add(s1.scale(C1)).add(s2.scale(C2));
            let e2 = b0.add(s1.scale(C2)).add(s2.scale(C1));
            // b_1 = e1 -+ i (S1 d1 + S2 d2), b_2 = e2 -+ i (S2 d1 - S1 d2); b_4, b_3 their mirrors.
            let o1 = d1.scale(S1).add(d2.scale(S2)).rotate::<INVERSE>();
            let o2 = d1.scale(S2).sub(d2.scale(S1)).rotate::<INVERSE>();
            y0[q] = b0.add(s1).add(s2).get();
            y1[q] = e1.add(o1).mul(w1).get();
            y2[q] = e2.add(o2).mul(w2).get();
            y3[q] = e2.sub(o2).mul(w3).get();
            y4[q] = e1.sub(o1).mul(w4).get();
        }
    }
}

/// The 4-point DFT of `(a0, a1, a2, a3)`.
#[inline(always)]
fn dft4<const INVERSE: bool>(a0: Lane, a1: Lane, a2: Lane, a3: Lane) -> [Lane; 4] {
    let t0 = a0.add(a2);
    let t1 = a0.sub(a2);
    let t2 = a1.add(a3);
    let t3 = a1.sub(a3).rotate::<INVERSE>();
    [t0.add(t2), t1.add(t3), t0.sub(t2), t1.sub(t3)]
}

fn radix8<const INVERSE: bool>(x: &[C], y: &mut [C], m: usize, s: usize, twiddles: &[C]) {
    const SQRT_HALF: f64 = std::f64::consts::FRAC_1_SQRT_2;
    let eighth = s * m;
    for j in 0..m {
        let w: [Lane; 7] = std::array::from_fn(|k| Lane::load(twiddles[7 * j + k]));
        let out = &mut y[s * 8 * j..s * (8 * j + 8)];
        let base = s * j;
        let inputs: [&[C]; 8] = std::array::from_fn(|r| &x[base + r * eighth..][..s]);
        for q in 0..s {
            let a: [Lane; 8] = std::array::from_fn(|r| Lane::load(inputs[r][q]));
            // Even and odd samples, then b_k = E_k + w_8^k O_k and b_{k+4} = E_k - w_8^k O_k,
            // with w_8 = (1 -+ i) / sqrt 2 and w_8^2 = -+i, w_8^3 = -+i w_8.
            let e = dft4::<INVERSE>(a[0], a[2], a[4], a[6]);
            let o = dft4::<INVERSE>(a[1], a[3], a[5], a[7]);
            let o1 = o[1].add(o[1].rotate::<INVERSE>()).scale(SQRT_HALF);
            let o2 = o[2].rotate::<INVERSE>();
            let o3 = o[3]
                .add(o[3].rotate::<INVERSE>())
                .scale(SQRT_HALF)
                .rotate::<INVERSE>();
            out[q] = e[0].add(o[0]).get();
            out[s + q] = e[1].add(o1).mul(w[0]).get();
            out[2 * s + q] = e[2].add(o2).mul(w[1]).get();
            out[3 * s + q] = e[3].add(o3).mul(w[2]).get();
            out[4 * s + q] = e[0].sub(o[0]).mul(w[3]).get();
            out[5 * s + q] = e[1].sub(o1).mul(w[4]).get();
            out[6 * s + q] = e[2].sub(o2).mul(w[5]).get();
            out[7 * s + q] = e[3].sub(o3).mul(w[6]).get();
        }
    }
}
