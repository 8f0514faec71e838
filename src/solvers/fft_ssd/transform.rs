//! A 2-D real FFT on grids whose sides have only small prime factors.

use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

/// The smallest size `>= n` whose only prime factors are 2, 3 and 5, where FFTs are fastest.
pub(super) fn smooth_size(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| {
            let mut rest = m;
            for p in [2, 3, 5] {
                while rest.is_multiple_of(p) {
                    rest /= p;
                }
            }
            rest == 1
        })
        .expect("smooth numbers are unbounded")
}

/// A 2-D real FFT: real transforms along the rows, then complex transforms along the columns.
/// The spectrum is stored transposed (`spectrum[kx * ny + y]`), so that each column transform
/// reads contiguous memory; products of spectra do not care about the layout.
pub(super) struct Transform2d {
    pub(super) nx: usize,
    pub(super) ny: usize,
    rows_forward: Arc<dyn RealToComplex<f64>>,
    rows_inverse: Arc<dyn ComplexToReal<f64>>,
    columns_forward: Arc<dyn Fft<f64>>,
    columns_inverse: Arc<dyn Fft<f64>>,
    row: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Transform2d {
    pub(super) fn new(
        nx: usize,
        ny: usize,
        real_planner: &mut RealFftPlanner<f64>,
        complex_planner: &mut FftPlanner<f64>,
    ) -> Self {
        let rows_forward = real_planner.plan_fft_forward(nx);
        let rows_inverse = real_planner.plan_fft_inverse(nx);
        let columns_forward = complex_planner.plan_fft_forward(ny);
        let columns_inverse = complex_planner.plan_fft_inverse(ny);
        let scratch_len = rows_forward
            .get_scratch_len()
            .max(rows_inverse.get_scratch_len())
            .max(columns_forward.get_inplace_scratch_len())
            .max(columns_inverse.get_inplace_scratch_len());
        Transform2d {
            nx,
            ny,
            rows_forward,
            rows_inverse,
            columns_forward,
            columns_inverse,
            row: vec![Complex::default(); nx / 2 + 1],
            scratch: vec![Complex::default(); scratch_len],
        }
    }

    /// `field` (row-major, `nx * ny`, overwritten) to its unnormalised spectrum.
    pub(super) fn forward(&mut self, field: &mut [f64], spectrum: &mut [Complex<f64>]) {
        let ny = self.ny;
        for (y, row) in field.chunks_exact_mut(self.nx).enumerate() {
            self.rows_forward
                .process_with_scratch(row, &mut self.row, &mut self.scratch)
                .expect("buffer lengths match the plan");
            for (k, &value) in self.row.iter().enumerate() {
                spectrum[k * ny + y] = value;
            }
        }
        self.columns_forward
            .process_with_scratch(spectrum, &mut self.scratch);
    }

    /// The spectrum (overwritten) back to `field`, scaled by `nx * ny`.
    pub(super) fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        let ny = self.ny;
        self.columns_inverse
            .process_with_scratch(spectrum, &mut self.scratch);
        let last = self.row.len() - 1;
        for (y, row) in field.chunks_exact_mut(self.nx).enumerate() {
            for (k, value) in self.row.iter_mut().enumerate() {
                *value = spectrum[k * ny + y];
            }
            // The spectrum of a real row has real DC and Nyquist terms; what rounding leaves in
            // their imaginary parts is noise, which the real inverse refuses.
            self.row[0].im = 0.0;
            if self.nx.is_multiple_of(2) {
                self.row[last].im = 0.0;
            }
            self.rows_inverse
                .process_with_scratch(&mut self.row, row, &mut self.scratch)
                .expect("buffer lengths match the plan");
        }
    }
}
