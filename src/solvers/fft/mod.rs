//! Fast Fourier transforms of any length, in `f64`, for the FFT-accelerated SSD search.
//!
//! Written for this project rather than taken from a general FFT crate: the searches need only
//! complex transforms of lengths with small prime factors (2, 3, 5: the search pads to them) and
//! real transforms built on them, and the general planner of `rustfft` (every butterfly for every
//! length, per SIMD flavour) would be about a fifth of the compressed `.wasm`. Lengths with other
//! factors (a periodic search over an output of prime width) go through Bluestein's chirp-z
//! algorithm on a smooth length, so every length works.
//!
//! Conventions, as in the usual FFT libraries: the forward transform is
//! `X[k] = sum_j x[j] e^{-2 pi i j k / n}`, the inverse uses `e^{+...}`, neither normalises, so an
//! inverse after a forward multiplies by `n`.

mod bluestein;
mod lane;
mod real;
mod smooth;
mod stockham;
#[cfg(test)]
mod tests;
mod twiddle;

pub use num_complex::Complex;
pub use real::RealFft;

pub use smooth::{is_smooth, smooth_size};
pub use twiddle::Direction;

use bluestein::Bluestein;
use lane::Lane;
use stockham::Stockham;

/// A planned complex transform of one length and direction: twiddle factors precomputed, no
/// allocation when it runs.
#[derive(Debug, Clone)]
pub struct Fft {
    len: usize,
    algorithm: Algorithm,
}

#[derive(Debug, Clone)]
enum Algorithm {
    /// Lengths `2^a 3^b 5^c`: mixed-radix Stockham passes.
    Stockham(Stockham),
    /// Any other length: a convolution of smooth length.
    Bluestein(Box<Bluestein>),
}

impl Fft {
    /// Plans a transform of `len` values (`len >= 1`).
    #[must_use]
    pub fn new(len: usize, direction: Direction) -> Self {
        let algorithm = match Stockham::new(len, direction) {
            Some(plan) => Algorithm::Stockham(plan),
            None => Algorithm::Bluestein(Box::new(Bluestein::new(len, direction))),
        };
        Fft { len, algorithm }
    }

    /// The number of values transformed.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Always false: a transform has at least one value.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// How many values [`Fft::process`] needs as scratch.
    #[must_use]
    pub fn scratch_len(&self) -> usize {
        self.batch_scratch_len(1)
    }

    /// How many values [`Fft::process_batch`] needs as scratch for `batch` sequences.
    #[must_use]
    pub fn batch_scratch_len(&self, batch: usize) -> usize {
        match &self.algorithm {
            Algorithm::Stockham(_) => self.len * batch,
            Algorithm::Bluestein(plan) => plan.scratch_len(),
        }
    }

    /// Transforms `data` (exactly [`Fft::len`] values) in place.
    ///
    /// # Panics
    /// When `data` has the wrong length or `scratch` is shorter than [`Fft::scratch_len`]:
    /// both are programming errors of the caller, which sizes them from the plan.
    pub fn process(&self, data: &mut [Complex<f64>], scratch: &mut [Complex<f64>]) {
        self.process_batch(data, scratch, 1);
    }

    /// Transforms `batch` interleaved sequences in place: value `j` of sequence `b` is
    /// `data[j * batch + b]`, so the columns of a row-major grid `batch` wide are one call.
    ///
    /// # Panics
    /// When `data` is not `len * batch` long or `scratch` is shorter than
    /// [`Fft::batch_scratch_len`].
    pub fn process_batch(
        &self,
        data: &mut [Complex<f64>],
        scratch: &mut [Complex<f64>],
        batch: usize,
    ) {
        assert_eq!(data.len(), self.len * batch, "FFT data length");
        assert!(
            scratch.len() >= self.batch_scratch_len(batch),
            "FFT scratch length"
        );
        match &self.algorithm {
            Algorithm::Stockham(plan) => {
                plan.process(data, &mut scratch[..self.len * batch], batch);
            }
            Algorithm::Bluestein(plan) => plan.process(data, scratch, batch),
        }
    }
}

/// `out[i] = (out[i] if accumulate, else 0) + factor * a[i] * conj(b[i])`: the product of spectra
/// that makes a cross-correlation.
///
/// # Panics
/// When the three lengths differ.
pub fn correlate_spectra(
    out: &mut [Complex<f64>],
    a: &[Complex<f64>],
    b: &[Complex<f64>],
    factor: f64,
    accumulate: bool,
) {
    assert!(
        out.len() == a.len() && a.len() == b.len(),
        "spectrum lengths"
    );
    for ((o, &x), &y) in out.iter_mut().zip(a).zip(b) {
        let product = Lane::load(x).mul_conj(Lane::load(y)).scale(factor);
        *o = if accumulate {
            Lane::load(*o).add(product).get()
        } else {
            product.get()
        };
    }
}
