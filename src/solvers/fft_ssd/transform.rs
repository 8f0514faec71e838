//! A 2-D or 3-D real FFT: real transforms along the rows, then complex transforms along the
//! columns, then (for a volume, `nz > 1`) complex transforms along the third axis, the time of a
//! video. An image is the depth-1 case: the third pass is skipped and nothing else changes.

use crate::core::parallel;
use crate::solvers::fft::{Complex, Direction, Fft, RealFft};

/// Rows and columns are transformed this many at a time, interleaved: long, contiguous inner
/// loops in the passes, and a block that stays in cache (`n * 16 * 16` bytes).
const BLOCK: usize = 8;

/// Blocks per piece of parallel work: the pieces, and so the results, do not depend on the
/// thread count.
const PIECE: usize = 8;

/// Transforms of fewer values than this run on the calling thread: graph cut's windows (about
/// 200 a side) are transformed hundreds of times, and handing their few pieces to other threads
/// costs more than it saves. The split does not change a bit of the result.
const PARALLEL_VALUES: usize = 1 << 19;

/// The spectrum is row-major, `spectrum[(z * ny + y) * (nx / 2 + 1) + kx]`; products of spectra
/// do not care about the layout.
pub(super) struct Transform {
    pub(super) nx: usize,
    pub(super) ny: usize,
    /// Depth (frames); 1 for an image.
    pub(super) nz: usize,
    rows: RealFft,
    columns_forward: Fft,
    columns_inverse: Fft,
    /// Plans along the third axis (`None` for an image).
    depth: Option<(Fft, Fft)>,
    block: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Transform {
    /// A transform of an `nx` x `ny` image.
    pub(super) fn new(nx: usize, ny: usize) -> Self {
        Self::new_volume(nx, ny, 1)
    }

    /// A transform of an `nx` x `ny` x `nz` volume (`nz` frames of `nx` x `ny`).
    pub(super) fn new_volume(nx: usize, ny: usize, nz: usize) -> Self {
        let rows = RealFft::new(nx);
        let columns_forward = Fft::new(ny, Direction::Forward);
        let columns_inverse = Fft::new(ny, Direction::Inverse);
        let depth = (nz > 1).then(|| {
            (
                Fft::new(nz, Direction::Forward),
                Fft::new(nz, Direction::Inverse),
            )
        });
        let mut scratch_len = rows
            .batch_scratch_len(BLOCK)
            .max(columns_forward.batch_scratch_len(BLOCK))
            .max(columns_inverse.batch_scratch_len(BLOCK));
        if let Some((f, i)) = &depth {
            scratch_len = scratch_len
                .max(f.batch_scratch_len(BLOCK))
                .max(i.batch_scratch_len(BLOCK));
        }
        Transform {
            nx,
            ny,
            nz,
            rows,
            columns_forward,
            columns_inverse,
            depth,
            block: vec![Complex::default(); ny.max(nz) * BLOCK],
            scratch: vec![Complex::default(); scratch_len],
        }
    }

    /// `field` (row-major, `nx * ny`) to its unnormalised spectrum.
    pub(super) fn forward(&mut self, field: &[f64], spectrum: &mut [Complex<f64>]) {
        let width = self.rows.spectrum_len();
        if !self.parallel() {
            for (rows_in, out) in field.chunks(self.nx * BLOCK).zip(spectrum.chunks_mut(width * BLOCK)) {
                self.rows.forward_batch(rows_in, out, &mut self.scratch);
            }
        } else {
        let (nx, rows, scratch_len) = (self.nx, &self.rows, self.scratch.len());
        parallel::for_each_piece_mut(spectrum, width * BLOCK * PIECE, |piece, out| {
            let mut scratch = vec![Complex::default(); scratch_len];
            let field = &field[piece * nx * BLOCK * PIECE..];
            for (rows_in, out) in field.chunks(nx * BLOCK).zip(out.chunks_mut(width * BLOCK)) {
                rows.forward_batch(rows_in, out, &mut scratch);
            }
        });
        }
        let slice = width * self.ny;
        for frame in spectrum.chunks_exact_mut(slice) {
            self.columns(frame, Direction::Forward);
        }
        self.depth(spectrum, Direction::Forward);
    }

    /// The spectrum (overwritten) back to `field`, scaled by `nx * ny`.
    pub(super) fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        self.depth(spectrum, Direction::Inverse);
        let width = self.rows.spectrum_len();
        for frame in spectrum.chunks_exact_mut(width * self.ny) {
            self.columns(frame, Direction::Inverse);
        }
        if !self.parallel() {
            for (rows_in, out) in spectrum.chunks(width * BLOCK).zip(field.chunks_mut(self.nx * BLOCK)) {
                self.rows.inverse_batch(rows_in, out, &mut self.scratch);
            }
            return;
        }
        let spectrum = &*spectrum;
        let (nx, rows, scratch_len) = (self.nx, &self.rows, self.scratch.len());
        parallel::for_each_piece_mut(field, nx * BLOCK * PIECE, |piece, out| {
            let mut scratch = vec![Complex::default(); scratch_len];
            let spectrum = &spectrum[piece * width * BLOCK * PIECE..];
            for (rows_in, out) in spectrum.chunks(width * BLOCK).zip(out.chunks_mut(nx * BLOCK)) {
                rows.inverse_batch(rows_in, out, &mut scratch);
            }
        });
    }

    /// Whether the passes hand their pieces to other threads.
    fn parallel(&self) -> bool {
        self.nx * self.ny * self.nz >= PARALLEL_VALUES
    }

    /// Transforms along the third axis: the same (y, kx) of every frame is one sequence. Frames are
    /// `slice` values apart, so a block of neighbouring sequences is gathered, transformed as one
    /// batch, and scattered back, as for the columns.
    fn depth(&mut self, spectrum: &mut [Complex<f64>], direction: Direction) {
        let Some((forward, inverse)) = &self.depth else {
            return;
        };
        let plan = match direction {
            Direction::Forward => forward,
            Direction::Inverse => inverse,
        };
        let slice = self.rows.spectrum_len() * self.ny;
        for first in (0..slice).step_by(BLOCK) {
            let count = BLOCK.min(slice - first);
            let block = &mut self.block[..self.nz * count];
            for (to, frame) in block
                .chunks_exact_mut(count)
                .zip(spectrum.chunks_exact(slice))
            {
                to.copy_from_slice(&frame[first..first + count]);
            }
            plan.process_batch(block, &mut self.scratch, count);
            for (from, frame) in block
                .chunks_exact(count)
                .zip(spectrum.chunks_exact_mut(slice))
            {
                frame[first..first + count].copy_from_slice(from);
            }
        }
    }

    /// Transforms every column of one row-major frame of the spectrum, a block of columns at a
    /// time.
    fn columns(&mut self, spectrum: &mut [Complex<f64>], direction: Direction) {
        let width = self.rows.spectrum_len();
        let plan = match direction {
            Direction::Forward => &self.columns_forward,
            Direction::Inverse => &self.columns_inverse,
        };
        let (ny, scratch_len) = (self.ny, self.scratch.len());
        if !self.parallel() {
            for first in (0..width).step_by(BLOCK) {
                let count = BLOCK.min(width - first);
                let block = &mut self.block[..ny * count];
                for (to, row) in block.chunks_exact_mut(count).zip(spectrum.chunks_exact(width)) {
                    to.copy_from_slice(&row[first..first + count]);
                }
                plan.process_batch(block, &mut self.scratch, count);
                for (from, row) in block.chunks_exact(count).zip(spectrum.chunks_exact_mut(width)) {
                    row[first..first + count].copy_from_slice(from);
                }
            }
            return;
        }
        let firsts: Vec<usize> = (0..width).step_by(BLOCK).collect();
        for group in firsts.chunks(PIECE) {
            // Each block of columns is gathered and transformed on its own; the blocks are then
            // scattered back in order.
            let spectrum_in = &*spectrum;
            let blocks = parallel::map(group.len(), |b| {
                let first = group[b];
                let count = BLOCK.min(width - first);
                let mut block = vec![Complex::default(); ny * count];
                let mut scratch = vec![Complex::default(); scratch_len];
                for (to, row) in block
                    .chunks_exact_mut(count)
                    .zip(spectrum_in.chunks_exact(width))
                {
                    to.copy_from_slice(&row[first..first + count]);
                }
                plan.process_batch(&mut block, &mut scratch, count);
                block
            });
            for (&first, block) in group.iter().zip(&blocks) {
                let count = BLOCK.min(width - first);
                for (from, row) in block
                    .chunks_exact(count)
                    .zip(spectrum.chunks_exact_mut(width))
                {
                    row[first..first + count].copy_from_slice(from);
                }
            }
        }
    }
}
