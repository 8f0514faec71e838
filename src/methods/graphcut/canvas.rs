//! The output being synthesised: its pixels, which patch every pixel came from (the label map),
//! and the cost of the seam on every edge between neighbouring pixels, remembered so that later
//! patches can overwrite bad old seams (section 3.1).

use super::error_regions::{ErrorRegions, SeamErrors};
use crate::core::{Image, Result};

/// Label of a pixel no patch has covered yet.
pub const UNCOVERED: u32 = u32::MAX;

/// A placed patch: the window of `source` whose top-left corner is `window` (the whole source
/// when it is within the bound of `source_window.rs`: window (0, 0)), translated by (tx, ty):
/// output pixel p copies window pixel p - t, i.e. source pixel p - t + window (p - t modulo the
/// output size when wrapping).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Patch {
    pub source: u32,
    pub tx: i32,
    pub ty: i32,
    pub window: (u32, u32),
}

impl Patch {
    /// The whole of a source within the bound (window at the origin), translated by (tx, ty).
    #[must_use]
    pub const fn new(source: u32, tx: i32, ty: i32) -> Patch {
        Patch {
            source,
            tx,
            ty,
            window: (0, 0),
        }
    }
}

/// The output and its seam memory.
#[derive(Debug, Clone)]
pub struct Canvas {
    pub width: usize,
    pub height: usize,
    pub wrap: bool,
    pub pixels: Image,
    /// Patch index of every pixel, or [`UNCOVERED`].
    pub label: Vec<u32>,
    pub patches: Vec<Patch>,
    /// Seam cost of the edge between (x, y) and its right neighbour, at `y * width + x`; zero
    /// where both pixels come from the same patch.
    pub h_seam: Vec<f32>,
    /// Seam cost of the edge between (x, y) and the pixel below.
    pub v_seam: Vec<f32>,
    pub covered: usize,
    /// No pixel before this index is uncovered: labels only ever go from uncovered to covered,
    /// so the scan for the first uncovered pixel resumes here instead of at 0 (a scan from 0 at
    /// every placement made covering a 4096x4096 output quadratic).
    first_uncovered_from: std::cell::Cell<usize>,
    /// The sum of `h_seam` and `v_seam`, kept by [`Canvas::set_seam`] so that each step's event
    /// does not add up the whole output again.
    seam_total: f64,
    /// The refinement's window totals of seam error, kept where [`Canvas::set_seam`] changes
    /// seams (interior mutability: finding the region is a question, not a change).
    regions: std::cell::RefCell<ErrorRegions>,
}

impl Canvas {
    pub fn new(width: usize, height: usize, channels: usize, wrap: bool) -> Result<Canvas> {
        Ok(Canvas {
            width,
            height,
            wrap,
            pixels: Image::new(width, height, channels)?,
            label: vec![UNCOVERED; width * height],
            patches: Vec::new(),
            h_seam: vec![0.0; width * height],
            v_seam: vec![0.0; width * height],
            covered: 0,
            first_uncovered_from: std::cell::Cell::new(0),
            seam_total: 0.0,
            regions: std::cell::RefCell::default(),
        })
    }

    /// The first uncovered pixel in scan order.
    #[must_use]
    pub fn first_uncovered(&self) -> Option<usize> {
        let from = self.first_uncovered_from.get().min(self.label.len());
        let found = self.label[from..]
            .iter()
            .position(|&l| l == UNCOVERED)
            .map(|k| from + k);
        self.first_uncovered_from
            .set(found.unwrap_or(self.label.len()));
        found
    }

    #[must_use]
    pub fn is_covered(&self) -> bool {
        self.covered == self.width * self.height
    }

    /// The right neighbour of pixel `i`, wrapping or not.
    #[inline]
    #[must_use]
    pub fn right(&self, i: usize) -> Option<usize> {
        let x = i % self.width;
        if x + 1 < self.width {
            Some(i + 1)
        } else if self.wrap && self.width > 1 {
            Some(i + 1 - self.width)
        } else {
            None
        }
    }

    /// The neighbour below pixel `i`.
    #[inline]
    #[must_use]
    pub fn down(&self, i: usize) -> Option<usize> {
        if i + self.width < self.width * self.height {
            Some(i + self.width)
        } else if self.wrap && self.height > 1 {
            Some(i + self.width - self.width * self.height)
        } else {
            None
        }
    }

    /// The source coordinates patch `patch`, `extent` pixels wide and high (see
    /// `Synthesis::patch_extent`), would copy to output pixel (x, y), if it covers it.
    #[inline]
    #[must_use]
    pub fn source_coords(
        &self,
        patch: Patch,
        (pw, ph): (usize, usize),
        x: usize,
        y: usize,
    ) -> Option<(usize, usize)> {
        let (mut sx, mut sy) = (
            x as i64 - i64::from(patch.tx),
            y as i64 - i64::from(patch.ty),
        );
        if self.wrap {
            sx = sx.rem_euclid(self.width as i64);
            sy = sy.rem_euclid(self.height as i64);
        }
        ((0..pw as i64).contains(&sx) && (0..ph as i64).contains(&sy)).then(|| {
            (
                sx as usize + patch.window.0 as usize,
                sy as usize + patch.window.1 as usize,
            )
        })
    }

    /// Per-pixel seam error: the sum of the seam costs on the pixel's edges (the error map that
    /// drives placement once the output is covered).
    #[must_use]
    pub fn seam_error(&self) -> Vec<f32> {
        let mut error = vec![0.0f32; self.width * self.height];
        for i in 0..error.len() {
            if let Some(j) = self.right(i) {
                error[i] += self.h_seam[i];
                error[j] += self.h_seam[i];
            }
            if let Some(j) = self.down(i) {
                error[i] += self.v_seam[i];
                error[j] += self.v_seam[i];
            }
        }
        error
    }

    /// Sum of every seam cost in the output.
    #[must_use]
    pub fn total_seam_cost(&self) -> f64 {
        self.seam_total
    }

    /// Remembers the seam cost of the edge from pixel `s` to its right (`horizontal`) or lower
    /// neighbour.
    pub fn set_seam(&mut self, s: usize, horizontal: bool, cost: f32) {
        let other = if horizontal {
            self.right(s)
        } else {
            self.down(s)
        };
        let seams = if horizontal {
            &mut self.h_seam
        } else {
            &mut self.v_seam
        };
        let old = std::mem::replace(&mut seams[s], cost);
        self.seam_total += f64::from(cost) - f64::from(old);
        if old != cost {
            // Both ends' seam error changed.
            let regions = self.regions.get_mut();
            for p in std::iter::once(s).chain(other) {
                regions.mark(p % self.width, p / self.width);
            }
        }
    }

    /// The top-left corner of the `side` x `side` window with the largest total seam error
    /// (see `error_regions.rs`).
    #[must_use]
    pub fn largest_error_window(&self, side: usize) -> (usize, usize) {
        self.regions.borrow_mut().largest(self, side)
    }

    /// 1 where a pixel's right or lower neighbour comes from a different patch (the seam map).
    #[must_use]
    pub fn seam_map(&self) -> Vec<u8> {
        let mut map = vec![0u8; self.width * self.height];
        for i in 0..map.len() {
            for j in [self.right(i), self.down(i)].into_iter().flatten() {
                if self.label[i] != self.label[j]
                    && self.label[i] != UNCOVERED
                    && self.label[j] != UNCOVERED
                {
                    map[i] = 1;
                    map[j] = 1;
                }
            }
        }
        map
    }
}

impl SeamErrors for Canvas {
    fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    fn wraps(&self) -> bool {
        self.wrap
    }

    fn seam_error(&self) -> Vec<f32> {
        Canvas::seam_error(self)
    }

    /// Pixel `p`'s seam error, its edges' costs added in the order [`Canvas::seam_error`] adds them
    /// (by the index of the edge's first pixel), so the value is the same to the bit.
    fn pixel_error(&self, p: usize) -> f32 {
        let canvas = self;
        let (w, n) = (canvas.width, canvas.width * canvas.height);
        let mut terms: [(usize, f32); 4] = [(usize::MAX, 0.0); 4];
        let mut count = 0;
        let left = if p.is_multiple_of(w) {
            None
        } else {
            Some(p - 1)
        }
        .or_else(|| (canvas.wrap && w > 1).then(|| p + w - 1));
        let up = if p >= w { Some(p - w) } else { None }
            .or_else(|| (canvas.wrap && n > w).then(|| p + n - w));
        if let Some(i) = up.filter(|&i| canvas.down(i) == Some(p)) {
            terms[count] = (i, canvas.v_seam[i]);
            count += 1;
        }
        if let Some(i) = left.filter(|&i| canvas.right(i) == Some(p)) {
            terms[count] = (i, canvas.h_seam[i]);
            count += 1;
        }
        if canvas.right(p).is_some() {
            terms[count] = (p, canvas.h_seam[p]);
            count += 1;
        }
        if canvas.down(p).is_some() {
            terms[count] = (p, canvas.v_seam[p]);
            count += 1;
        }
        // Stable: p's own two edges keep their order (right, then down).
        terms[..count].sort_by_key(|t| t.0);
        terms[..count].iter().fold(0.0, |e, t| e + t.1)
    }
}
