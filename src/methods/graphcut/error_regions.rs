//! The refinement's error region (section 3.1 of the paper: once the output is covered, the next
//! patch goes where the seams cost most): the `side` x `side` window of the output with the
//! largest total per-pixel seam error. A placement changes seams only under its patch, so the
//! per-pixel error, the window sums and each row's best window are kept between placements and
//! recomputed only where seams changed ([`ErrorRegions::mark`]). Recomputing them over the whole
//! output at every refinement step would make one placement's cost grow with the output (0.5-1 s
//! a step at 4096x4096 for that alone).
//!
//! The first look at a covered output computes everything with the whole-output functions
//! ([`SeamErrors::seam_error`] and the two passes of `box_sum::box_sums`), so it gives the same
//! region as they do. Later updates
//! slide the same running sums over the changed part only, starting where that part starts: a
//! window's sum can differ from a whole-row slide in its last bit, so two windows whose totals
//! agree to about 1e-7 may trade places.

use crate::solvers::box_sum::{slide_window, sliding_column_sums, sliding_row_sums};

/// What the error regions read of a canvas (`canvas.rs` implements it): its size, whether it
/// wraps, and the per-pixel seam error, whole or one pixel at a time.
pub trait SeamErrors {
    /// Width and height.
    fn size(&self) -> (usize, usize);
    /// Whether the canvas wraps around (tileable output).
    fn wraps(&self) -> bool;
    /// The per-pixel seam error over the whole canvas.
    fn seam_error(&self) -> Vec<f32>;
    /// Pixel `p`'s seam error, added in the same order as [`SeamErrors::seam_error`] adds it, so
    /// the value is the same to the bit.
    fn pixel_error(&self, p: usize) -> f32;
}

/// Pixels whose seam error changed since the sums were brought up to date, as a box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Dirty {
    x0: usize,
    y0: usize,
    x1: usize,
    y1: usize,
}

/// The kept state (see the module's documentation).
#[derive(Debug, Clone, Default)]
pub struct ErrorRegions {
    /// Window side the sums are for; 0 before the first computation.
    side: usize,
    /// Per-pixel seam error (what [`SeamErrors::seam_error`] returns).
    error: Vec<f32>,
    /// Sums of `side` errors along each row from each pixel (-inf where the window would cross
    /// the border of a non-wrapping output).
    rows: Vec<f32>,
    /// Sums of `side` row sums down each column: the window totals, by top-left corner.
    sums: Vec<f32>,
    /// Per output row, the first column of its largest window total.
    best: Vec<usize>,
    dirty: Option<Dirty>,
}

impl ErrorRegions {
    /// Records that the seam error of pixel (x, y) changed.
    pub fn mark(&mut self, x: usize, y: usize) {
        if self.side == 0 {
            return; // nothing computed yet: the first look computes everything
        }
        self.dirty = Some(match self.dirty {
            None => Dirty {
                x0: x,
                y0: y,
                x1: x,
                y1: y,
            },
            Some(d) => Dirty {
                x0: d.x0.min(x),
                y0: d.y0.min(y),
                x1: d.x1.max(x),
                y1: d.y1.max(y),
            },
        });
    }

    /// The top-left corner of the `side` x `side` window of `canvas` with the largest total seam
    /// error (the first in scan order among equal ones).
    pub fn largest(&mut self, canvas: &impl SeamErrors, side: usize) -> (usize, usize) {
        let (w, h) = (canvas.size().0, canvas.size().1);
        if self.side != side || self.error.len() != w * h {
            self.rebuild(canvas, side);
        } else if let Some(d) = self.dirty.take() {
            // A change over most of the output is cheaper redone whole.
            if (d.x1 - d.x0 + side) * (d.y1 - d.y0 + side) * 2 > w * h {
                self.rebuild(canvas, side);
            } else {
                self.update(canvas, d);
            }
        }
        let mut top = 0;
        for y in 1..h {
            if self.sums[y * w + self.best[y]] > self.sums[top * w + self.best[top]] {
                top = y;
            }
        }
        (self.best[top], top)
    }

    fn rebuild(&mut self, canvas: &impl SeamErrors, side: usize) {
        let (w, h) = (canvas.size().0, canvas.size().1);
        self.side = side;
        self.dirty = None;
        self.error = canvas.seam_error();
        // The two passes of `box_sums`, keeping the row sums the updates slide from.
        self.rows = sliding_row_sums(&self.error, w, h, side, canvas.wraps());
        self.sums = sliding_column_sums(&self.rows, w, h, side, canvas.wraps());
        self.best = (0..h).map(|y| self.best_in_row(w, y)).collect();
    }

    /// Brings the error, the row sums, the window totals and the rows' best up to date over the
    /// windows that overlap `d`.
    fn update(&mut self, canvas: &impl SeamErrors, d: Dirty) {
        let (w, h, side, wrap) = (canvas.size().0, canvas.size().1, self.side, canvas.wraps());
        for y in d.y0..=d.y1 {
            for x in d.x0..=d.x1 {
                self.error[y * w + x] = canvas.pixel_error(y * w + x);
            }
        }
        let columns = Span::reaching(d.x0, d.x1, side, w, wrap);
        for y in d.y0..=d.y1 {
            self.slide_row(canvas, y, columns);
        }
        let rows = Span::reaching(d.y0, d.y1, side, h, wrap);
        for k in 0..columns.len {
            let x = columns.at(k, w);
            self.slide_column(canvas, x, rows);
        }
        for k in 0..rows.len {
            let y = rows.at(k, h);
            self.best[y] = self.best_in_row(w, y);
        }
    }

    /// Row sums of row `y` for the windows starting at `columns`: a running f64 sum, as
    /// `box_sums` keeps one along the whole row.
    fn slide_row(&mut self, canvas: &impl SeamErrors, y: usize, columns: Span) {
        let (w, side) = (canvas.size().0, self.side);
        let row = &self.error[y * w..(y + 1) * w];
        let out = &mut self.rows[y * w..(y + 1) * w];
        slide_window(
            columns.len,
            side,
            |k| row[columns.at(k, w)],
            |k, total| {
                let x = columns.at(k, w);
                if canvas.wraps() || x + side <= w {
                    out[x] = total;
                }
            },
        );
    }

    /// Window totals of column `x` for the windows starting at `rows`.
    fn slide_column(&mut self, canvas: &impl SeamErrors, x: usize, rows: Span) {
        let (w, h, side) = (canvas.size().0, canvas.size().1, self.side);
        if !canvas.wraps() && x + side > w {
            return; // no window starts here: its totals stay -inf
        }
        let (row_sums, sums) = (&self.rows, &mut self.sums);
        slide_window(
            rows.len,
            side,
            |k| row_sums[rows.at(k, h) * w + x],
            |k, total| {
                let y = rows.at(k, h);
                if canvas.wraps() || y + side <= h {
                    sums[y * w + x] = total;
                }
            },
        );
    }

    fn best_in_row(&self, w: usize, y: usize) -> usize {
        let row = &self.sums[y * w..(y + 1) * w];
        (1..w).fold(0, |best, x| if row[x] > row[best] { x } else { best })
    }
}

/// Consecutive window starts along one axis, from `start` (wrapping round a torus).
#[derive(Debug, Clone, Copy)]
struct Span {
    start: usize,
    len: usize,
}

impl Span {
    fn whole(n: usize) -> Span {
        Span { start: 0, len: n }
    }

    /// The starts of the windows of `side` that overlap `lo..=hi` on an axis of `n`.
    fn reaching(lo: usize, hi: usize, side: usize, n: usize, wrap: bool) -> Span {
        if wrap {
            let len = hi - lo + side;
            if len >= n {
                return Span::whole(n);
            }
            Span {
                start: (lo + n - (side - 1) % n) % n,
                len,
            }
        } else {
            let start = lo.saturating_sub(side - 1);
            // Starts past n - side have no window (their sums stay -inf); they are slid over
            // all the same, since the running sum must pass them to stay in step.
            Span {
                start,
                len: hi.min(n - 1) + 1 - start,
            }
        }
    }

    /// The `k`-th position (reading past the end wraps, as the running sums' look-ahead does).
    fn at(self, k: usize, n: usize) -> usize {
        (self.start + k) % n
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;
    use crate::methods::graphcut::canvas::Canvas;
    use crate::solvers::box_sum::box_sums;

    /// The region found over the whole output from scratch, without the kept sums.
    fn whole(canvas: &Canvas, side: usize) -> (usize, usize, f32) {
        let (w, h) = (canvas.width, canvas.height);
        let sums = box_sums(&canvas.seam_error(), w, h, side, canvas.wrap);
        let best = (0..sums.len()).fold(0, |b, i| if sums[i] > sums[b] { i } else { b });
        (best % w, best / w, sums[best])
    }

    #[test]
    fn kept_sums_find_the_region_a_whole_output_search_finds() {
        let mut rng = Rng::new(3);
        for (w, h, side, wrap) in [
            (23, 17, 5, false),
            (23, 17, 5, true),
            (16, 16, 16, false),
            (9, 31, 4, true),
            (40, 12, 1, false),
        ] {
            let mut canvas = Canvas::new(w, h, 3, wrap).unwrap();
            let mut regions = ErrorRegions::default();
            for step in 0..60 {
                // A "placement": new seam costs over a random rectangle (wrapping past the
                // border on a torus), sometimes most of the output; sometimes nothing changes.
                let (rw, rh) = (1 + rng.index(w), 1 + rng.index(h.min(8)));
                let (x0, y0) = (rng.index(w), rng.index(h));
                let changes = if step % 7 == 3 { 0 } else { rw * rh };
                for k in 0..changes {
                    let (x, y) = ((x0 + k % rw) % w, (y0 + k / rw) % h);
                    let cost = rng.next_f32() * 4.0;
                    canvas.set_seam(y * w + x, rng.index(2) == 0, cost);
                    // Mirror the canvas's own marks into this test's copy of the state.
                    regions.mark(x, y);
                    regions.mark((x + 1) % w, y);
                    regions.mark(x, (y + 1) % h);
                }
                let (x, y, total) = whole(&canvas, side);
                assert_eq!(
                    canvas.largest_error_window(side),
                    (x, y),
                    "{w}x{h} side {side} wrap {wrap}, step {step}: total {total}"
                );
                assert_eq!(regions.largest(&canvas, side), (x, y));
                assert_eq!(
                    regions.error,
                    canvas.seam_error(),
                    "per-pixel error to the bit"
                );
            }
        }
    }

    #[test]
    fn pixel_error_adds_in_the_whole_output_order() {
        // Costs of very different sizes, so that a different order of addition shows.
        for wrap in [false, true] {
            let mut canvas = Canvas::new(5, 4, 3, wrap).unwrap();
            let mut rng = Rng::new(9);
            for i in 0..20 {
                let scale = [1e-8f32, 1.0, 1e8][i % 3];
                canvas.set_seam(i, true, rng.next_f32() * scale);
                canvas.set_seam(i, false, rng.next_f32() * scale);
            }
            let whole = canvas.seam_error();
            for (p, &e) in whole.iter().enumerate() {
                assert_eq!(canvas.pixel_error(p).to_bits(), e.to_bits(), "pixel {p}");
            }
        }
    }
}
