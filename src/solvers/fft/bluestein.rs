//! Bluestein's chirp-z algorithm: a transform of any length `n` as a circular convolution of
//! smooth length `m >= 2n - 1`, which the Stockham passes compute.
//!
//! With `jk = (j^2 + k^2 - (k - j)^2) / 2`, the forward transform is
//! `X[k] = c_k sum_j (x_j c_j) conj(c_{k-j})`, `c_j = e^{-pi i j^2 / n}`: a product by the chirp,
//! a convolution with its conjugate, and a product by the chirp again. The inverse conjugates the
//! chirp.

use super::Complex;
use super::smooth::smooth_size;
use super::stockham::Stockham;
use super::twiddle::Direction;

type C = Complex<f64>;

#[derive(Debug, Clone)]
pub(super) struct Bluestein {
    len: usize,
    /// `c_j` for `j < n`.
    chirp: Vec<C>,
    /// The spectrum of the convolution kernel `conj(c)` wrapped onto `m`, divided by `m` so that
    /// the unnormalised inverse gives the convolution itself.
    kernel: Vec<C>,
    /// Transforms of the smooth length `m`.
    forward: Stockham,
    inverse: Stockham,
}

impl Bluestein {
    pub(super) fn new(len: usize, direction: Direction) -> Self {
        let m = smooth_size(2 * len - 1);
        let sign = match direction {
            Direction::Forward => -1.0,
            Direction::Inverse => 1.0,
        };
        // j^2 mod 2n keeps the angle small, so it stays exact for long transforms.
        let chirp: Vec<C> = (0..len as u64)
            .map(|j| {
                let phase = (j * j) % (2 * len as u64);
                let angle = sign * std::f64::consts::PI * phase as f64 / len as f64;
                C::new(crate::core::math::cos(angle), crate::core::math::sin(angle))
            })
            .collect();
        let plan = |d| Stockham::new(m, d).expect("smooth_size gives a smooth length");
        let (forward, inverse) = (plan(Direction::Forward), plan(Direction::Inverse));
        let mut kernel = vec![C::default(); m];
        kernel[0] = chirp[0].conj();
        for j in 1..len {
            kernel[j] = chirp[j].conj();
            kernel[m - j] = chirp[j].conj();
        }
        let mut scratch = vec![C::default(); m];
        forward.process(&mut kernel, &mut scratch, 1);
        let scale = 1.0 / m as f64;
        for value in &mut kernel {
            *value *= scale;
        }
        Bluestein {
            len,
            chirp,
            kernel,
            forward,
            inverse,
        }
    }

    pub(super) fn scratch_len(&self) -> usize {
        let m = self.kernel.len();
        2 * m
    }

    /// Transforms the `batch` interleaved sequences of `data` one after the other.
    pub(super) fn process(&self, data: &mut [C], scratch: &mut [C], batch: usize) {
        let (buffer, rest) = scratch.split_at_mut(self.kernel.len());
        for lane in 0..batch {
            for ((b, &x), &c) in buffer
                .iter_mut()
                .zip(data.iter().skip(lane).step_by(batch))
                .zip(&self.chirp)
            {
                *b = x * c;
            }
            buffer[self.len..].fill(C::default());
            self.forward.process(buffer, &mut rest[..buffer.len()], 1);
            for (b, &k) in buffer.iter_mut().zip(&self.kernel) {
                *b *= k;
            }
            self.inverse.process(buffer, &mut rest[..buffer.len()], 1);
            for ((x, &b), &c) in data
                .iter_mut()
                .skip(lane)
                .step_by(batch)
                .zip(buffer.iter())
                .zip(&self.chirp)
            {
                *x = b * c;
            }
        }
    }
}
