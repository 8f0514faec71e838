//! A 2-D real FFT: real transforms along the rows, then complex transforms along the columns.

use crate::solvers::fft::{Complex, Direction, Fft, RealFft};

/// Rows and columns are transformed this many at a time, interleaved: long, contiguous inner
/// loops in the passes, and a block that stays in cache (`n * 16 * 16` bytes).
const BLOCK: usize = 8;

/// The spectrum is row-major, `spectrum[y * (nx / 2 + 1) + kx]`; products of spectra do not care
/// about the layout.
pub(super) struct Transform2d {
    pub(super) nx: usize,
    pub(super) ny: usize,
    rows: RealFft,
    columns_forward: Fft,
    columns_inverse: Fft,
    block: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Transform2d {
    pub(super) fn new(nx: usize, ny: usize) -> Self {
        let rows = RealFft::new(nx);
        let columns_forward = Fft::new(ny, Direction::Forward);
        let columns_inverse = Fft::new(ny, Direction::Inverse);
        let scratch_len = rows
            .batch_scratch_len(BLOCK)
            .max(columns_forward.batch_scratch_len(BLOCK))
            .max(columns_inverse.batch_scratch_len(BLOCK));
        Transform2d {
            nx,
            ny,
            rows,
            columns_forward,
            columns_inverse,
            block: vec![Complex::default(); ny * BLOCK],
            scratch: vec![Complex::default(); scratch_len],
        }
    }

    /// `field` (row-major, `nx * ny`) to its unnormalised spectrum.
    pub(super) fn forward(&mut self, field: &[f64], spectrum: &mut [Complex<f64>]) {
        let width = self.rows.spectrum_len();
        for (rows, out) in field
            .chunks(self.nx * BLOCK)
            .zip(spectrum.chunks_mut(width * BLOCK))
        {
            self.rows.forward_batch(rows, out, &mut self.scratch);
        }
        self.columns(spectrum, Direction::Forward);
    }

    /// The spectrum (overwritten) back to `field`, scaled by `nx * ny`.
    pub(super) fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        self.columns(spectrum, Direction::Inverse);
        let width = self.rows.spectrum_len();
        for (rows, out) in spectrum
            .chunks(width * BLOCK)
            .zip(field.chunks_mut(self.nx * BLOCK))
        {
            self.rows.inverse_batch(rows, out, &mut self.scratch);
        }
    }

    /// Transforms every column of the row-major spectrum, a block of columns at a time.
    fn columns(&mut self, spectrum: &mut [Complex<f64>], direction: Direction) {
        let width = self.rows.spectrum_len();
        let plan = match direction {
            Direction::Forward => &self.columns_forward,
            Direction::Inverse => &self.columns_inverse,
        };
        for first in (0..width).step_by(BLOCK) {
            let count = BLOCK.min(width - first);
            let block = &mut self.block[..self.ny * count];
            for (to, row) in block
                .chunks_exact_mut(count)
                .zip(spectrum.chunks_exact(width))
            {
                to.copy_from_slice(&row[first..first + count]);
            }
            plan.process_batch(block, &mut self.scratch, count);
            for (from, row) in block
                .chunks_exact(count)
                .zip(spectrum.chunks_exact_mut(width))
            {
                row[first..first + count].copy_from_slice(from);
            }
        }
    }
}
