//! Transforms of real sequences, which have conjugate-symmetric spectra: only the `n / 2 + 1`
//! values `X[0 ..= n/2]` are stored.
//!
//! An even length packs the samples as `z_k = x_{2k} + i x_{2k+1}` and transforms that at half
//! the length, then separates the spectra of the even and odd samples (`E`, `O`) by symmetry:
//! `X[k] = E[k] + e^{-2 pi i k / n} O[k]`. That halves the work of a complex transform. An odd
//! length (only periodic searches over odd widths ask for one) transforms the samples as complex
//! values.

use super::lane::Lane;
use super::twiddle::{Direction, twiddle};
use super::{Complex, Fft};

type C = Complex<f64>;

/// A planned real-to-spectrum and spectrum-to-real transform pair of one length.
#[derive(Debug, Clone)]
pub struct RealFft {
    len: usize,
    forward: Fft,
    inverse: Fft,
    /// Even lengths: `e^{-2 pi i k / n}` for `k < n / 2`.
    twiddles: Vec<C>,
}

impl RealFft {
    /// Plans both directions for `len` real values (`len >= 1`).
    #[must_use]
    pub fn new(len: usize) -> Self {
        let inner = if len.is_multiple_of(2) { len / 2 } else { len };
        let twiddles = if len.is_multiple_of(2) {
            (0..len / 2)
                .map(|k| twiddle(k, len, Direction::Forward))
                .collect()
        } else {
            Vec::new()
        };
        RealFft {
            len,
            forward: Fft::new(inner, Direction::Forward),
            inverse: Fft::new(inner, Direction::Inverse),
            twiddles,
        }
    }

    /// The number of real values.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Always false: a transform has at least one value.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The number of spectrum values, `n / 2 + 1`.
    #[must_use]
    pub fn spectrum_len(&self) -> usize {
        self.len / 2 + 1
    }

    /// How many values [`RealFft::forward`] and [`RealFft::inverse`] need as scratch.
    #[must_use]
    pub fn scratch_len(&self) -> usize {
        self.batch_scratch_len(1)
    }

    /// How many values the batch transforms need as scratch for `batch` rows.
    #[must_use]
    pub fn batch_scratch_len(&self, batch: usize) -> usize {
        let inner = self.forward.len() * batch;
        inner
            + self
                .forward
                .batch_scratch_len(batch)
                .max(self.inverse.batch_scratch_len(batch))
    }

    /// The spectrum `X[0 ..= n/2]` of `input` (`n` values) into `spectrum`.
    ///
    /// # Panics
    /// On buffer lengths other than the plan's (a programming error of the caller).
    pub fn forward(&self, input: &[f64], spectrum: &mut [C], scratch: &mut [C]) {
        self.forward_batch(input, spectrum, scratch);
    }

    /// `n` times the real sequence whose spectrum is `spectrum` (`n / 2 + 1` values; the imaginary
    /// parts that a real sequence cannot have, at 0 and at `n / 2`, are ignored) into `output`.
    ///
    /// # Panics
    /// On buffer lengths other than the plan's (a programming error of the caller).
    pub fn inverse(&self, spectrum: &[C], output: &mut [f64], scratch: &mut [C]) {
        self.inverse_batch(spectrum, output, scratch);
    }

    /// [`RealFft::forward`] of several rows at once: `input` holds `batch` rows of `n` values,
    /// `spectrum` their `batch` spectra of `n / 2 + 1`. The rows are transformed interleaved, so
    /// the passes run long inner loops.
    ///
    /// # Panics
    /// When the lengths are not whole rows of the plan, or differ in row count.
    pub fn forward_batch(&self, input: &[f64], spectrum: &mut [C], scratch: &mut [C]) {
        let batch = self.rows(input.len(), spectrum.len());
        let inner = self.forward.len();
        let (z, rest) = scratch.split_at_mut(inner * batch);
        let width = self.spectrum_len();
        if self.twiddles.is_empty() {
            for (r, row) in input.chunks_exact(self.len).enumerate() {
                for (k, &x) in row.iter().enumerate() {
                    z[k * batch + r] = C::new(x, 0.0);
                }
            }
            self.forward.process_batch(z, rest, batch);
            for (r, out) in spectrum.chunks_exact_mut(width).enumerate() {
                for (k, value) in out.iter_mut().enumerate() {
                    *value = z[k * batch + r];
                }
            }
            return;
        }
        for (r, row) in input.chunks_exact(self.len).enumerate() {
            for (k, pair) in row.chunks_exact(2).enumerate() {
                z[k * batch + r] = C::new(pair[0], pair[1]);
            }
        }
        self.forward.process_batch(z, rest, batch);
        let half = inner;
        for (r, out) in spectrum.chunks_exact_mut(width).enumerate() {
            for (k, value) in out.iter_mut().enumerate() {
                let zk = Lane::load(z[(k % half) * batch + r]);
                let zc = Lane::load(z[((half - k) % half) * batch + r].conj());
                // E = (zk + zc) / 2, O = (zk - zc) / 2i, X = E + w^k O.
                let even = zk.add(zc).scale(0.5);
                let odd = zk.sub(zc).rotate::<false>().scale(0.5);
                let w = if k < half {
                    self.twiddles[k]
                } else {
                    C::new(-1.0, 0.0)
                };
                *value = even.add(odd.mul(Lane::load(w))).get();
            }
        }
    }

    /// [`RealFft::inverse`] of several rows at once (see [`RealFft::forward_batch`]).
    ///
    /// # Panics
    /// When the lengths are not whole rows of the plan, or differ in row count.
    pub fn inverse_batch(&self, spectrum: &[C], output: &mut [f64], scratch: &mut [C]) {
        let batch = self.rows(output.len(), spectrum.len());
        let inner = self.inverse.len();
        let (z, rest) = scratch.split_at_mut(inner * batch);
        let n = self.len;
        let width = self.spectrum_len();
        if self.twiddles.is_empty() {
            for (r, row) in spectrum.chunks_exact(width).enumerate() {
                z[r] = C::new(row[0].re, 0.0);
                for k in 1..width {
                    z[k * batch + r] = row[k];
                    z[(n - k) * batch + r] = row[k].conj();
                }
            }
            self.inverse.process_batch(z, rest, batch);
            for (r, out) in output.chunks_exact_mut(n).enumerate() {
                for (k, value) in out.iter_mut().enumerate() {
                    *value = z[k * batch + r].re;
                }
            }
            return;
        }
        let half = inner;
        for (r, row) in spectrum.chunks_exact(width).enumerate() {
            for k in 0..half {
                let (mut xk, mut xc) = (row[k], row[half - k].conj());
                if k == 0 {
                    // DC and Nyquist are real.
                    xk.im = 0.0;
                    xc.im = 0.0;
                }
                let (xk, xc) = (Lane::load(xk), Lane::load(xc));
                // Z = (xk + xc) + i e^{+2 pi i k / n} (xk - xc), which is 2 (E + i O).
                let d = xk
                    .sub(xc)
                    .mul(Lane::load(self.twiddles[k].conj()))
                    .rotate::<true>();
                z[k * batch + r] = xk.add(xc).add(d).get();
            }
        }
        self.inverse.process_batch(z, rest, batch);
        for (r, out) in output.chunks_exact_mut(n).enumerate() {
            for (pair, k) in out.chunks_exact_mut(2).zip(0..) {
                let v = z[k * batch + r];
                pair[0] = v.re;
                pair[1] = v.im;
            }
        }
    }

    /// The number of rows in a batch call, checked against both buffers.
    fn rows(&self, values: usize, spectrum: usize) -> usize {
        let width = self.spectrum_len();
        assert!(
            values.is_multiple_of(self.len) && spectrum.is_multiple_of(width),
            "real FFT buffers of whole rows"
        );
        let batch = values / self.len;
        assert_eq!(batch, spectrum / width, "real FFT row counts");
        batch
    }
}
