//! Where a placement looks (section 4): the error region the next patch must cover, the
//! candidates with their costs, and the window of the output an FFT search of a patch covers.
//! Plain data and free functions, used by the placement itself (`placement.rs`), its memory
//! estimate and its anatomy.

use super::canvas::{Patch, UNCOVERED};
use super::options::{Options, Placement};
use super::source::Source;
use super::source_window::{MAX_SOURCE_SIDE, window_extent};
use crate::core::{Image, Result};
use crate::solvers::fft_ssd::{Boundary, transform_size};

/// A rectangle of the output (it may run past the right or bottom border when wrapping).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Region {
    pub x: usize,
    pub y: usize,
    pub width: usize,
    pub height: usize,
}

/// An offset to try and its matching cost (0 for random placement).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Candidate {
    pub patch: Patch,
    pub cost: f32,
}

/// The part of `source` a patch uses on a `(width, height, wrap)` canvas: its window (at most
/// [`MAX_SOURCE_SIDE`] a side, see `source_window.rs`), or at most the output size when wrapping
/// (a larger patch would overlap itself). For estimates made before a synthesis exists.
#[must_use]
pub fn patch_extent(source: &Source, (w, h, wrap): (usize, usize, bool)) -> (usize, usize) {
    let (ww, wh) = window_extent(source.width(), source.height(), MAX_SOURCE_SIDE);
    if wrap {
        (ww.min(w), wh.min(h))
    } else {
        (ww, wh)
    }
}

/// The largest FFT search a placement on a `(width, height, wrap)` canvas makes: (source,
/// transform width, height), or `None` for random placement, which searches nothing.
#[must_use]
pub fn largest_search(
    options: &Options,
    sources: &[Source],
    (w, h, wrap): (usize, usize, bool),
) -> Option<(usize, usize, usize)> {
    if options.placement == Placement::Random {
        return None;
    }
    let (ew, eh) = window_extent(sources[0].width(), sources[0].height(), MAX_SOURCE_SIDE);
    let side = options.error_region_side(ew, eh);
    // The window is largest where the border does not clip it: the region in the middle.
    let region = Region {
        x: w.saturating_sub(side) / 2,
        y: h.saturating_sub(side) / 2,
        width: side,
        height: side,
    };
    (0..sources.len())
        .map(|s| {
            let (pw, ph) = patch_extent(&sources[s], (w, h, wrap));
            let window = SearchWindow::of(options.placement, region, (pw, ph), (w, h), wrap);
            let (nx, ny) = transform_size((window.width, window.height), (pw, ph), window.boundary);
            (s, nx, ny)
        })
        .max_by_key(|&(_, nx, ny)| nx.saturating_mul(ny))
}

/// Whether output pixel (x, y) lies in `region`.
#[must_use]
pub fn region_contains(region: Region, x: usize, y: usize, w: usize, h: usize, wrap: bool) -> bool {
    let inside = |p: usize, start: usize, len: usize, size: usize| {
        if wrap {
            (p + size - start) % size < len
        } else {
            p >= start && p < start + len
        }
    };
    inside(x, region.x, region.width, w) && inside(y, region.y, region.height, h)
}

/// The part of the output a placement's search looks at: every offset whose patch covers the
/// error region lies in `[x1 - pw, x0]` along x (likewise y), so its patches span a window of
/// `2 pw - region width` by `2 ph - region height` pixels. Searching that window instead of the
/// whole output makes a placement cost the same at 256x256 and 4096x4096. A wrapping
/// output whose window would be wider than the output itself is searched whole, as a torus.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SearchWindow {
    /// Top-left corner in output coordinates (negative or past the border where the patches
    /// reach outside the output).
    pub x: i64,
    pub y: i64,
    pub width: usize,
    pub height: usize,
    pub boundary: Boundary,
    /// Whether the output wraps (its offsets are reduced modulo its size).
    pub wrap: bool,
    /// The smallest offset a candidate can have in the window, along x and y: a wrapped offset
    /// is reduced into the output's size from there.
    pub lowest: (i64, i64),
}

impl SearchWindow {
    #[must_use]
    pub fn around(
        region: Region,
        (pw, ph): (usize, usize),
        (w, h): (usize, usize),
        wrap: bool,
    ) -> SearchWindow {
        let width = (2 * pw).saturating_sub(region.width).max(1);
        let height = (2 * ph).saturating_sub(region.height).max(1);
        if wrap && (width > w || height > h) {
            return SearchWindow {
                x: 0,
                y: 0,
                width: w,
                height: h,
                boundary: Boundary::Periodic,
                wrap,
                lowest: (0, 0),
            };
        }
        let (x, y) = (
            (region.x + region.width) as i64 - pw as i64,
            (region.y + region.height) as i64 - ph as i64,
        );
        if wrap {
            return SearchWindow {
                x,
                y,
                width,
                height,
                boundary: Boundary::Open,
                wrap,
                lowest: (0, 0),
            };
        }
        // Outside a bounded output the patch's pixels count for nothing, so the window stops at
        // the border: a patch (exemplar) much larger than the output searches no more than the
        // output itself.
        let clip = |start: i64, len: usize, size: usize| {
            let first = start.max(0);
            let last = (start + len as i64).min(size as i64).max(first + 1);
            (first, (last - first) as usize)
        };
        let ((x, width), (y, height)) = (clip(x, width, w), clip(y, height, h));
        SearchWindow {
            x,
            y,
            width,
            height,
            boundary: Boundary::Open,
            wrap,
            lowest: (0, 0),
        }
    }

    /// The window a placement searches: [`SearchWindow::over_region`] for sub-patch matching,
    /// [`SearchWindow::around`] otherwise.
    #[must_use]
    pub fn of(
        placement: Placement,
        region: Region,
        extent: (usize, usize),
        output: (usize, usize),
        wrap: bool,
    ) -> SearchWindow {
        if placement == Placement::SubPatch {
            SearchWindow::over_region(region, extent, wrap)
        } else {
            SearchWindow::around(region, extent, output, wrap)
        }
    }

    /// The window of sub-patch matching (eq. 4): the error region itself, the only output
    /// pixels its cost reads, with the candidates at offsets from `region - patch` to 0. The
    /// FFT search then correlates the region with the patch over the patch's size (a 128 patch
    /// over a 42 region: 128x128 transforms), not over the candidates' span plus the patch
    /// (216x216), which is what [`SearchWindow::around`] costs: a third of the work.
    #[must_use]
    pub fn over_region(region: Region, (pw, ph): (usize, usize), wrap: bool) -> SearchWindow {
        SearchWindow {
            x: region.x as i64,
            y: region.y as i64,
            width: region.width,
            height: region.height,
            boundary: Boundary::Open,
            wrap,
            lowest: (
                region.width as i64 - pw as i64,
                region.height as i64 - ph as i64,
            ),
        }
    }

    /// The window's pixels and weights: 1 on covered pixels where `keep(x, y)` (output
    /// coordinates), 0 elsewhere and outside a non-wrapping output.
    pub fn gather(
        &self,
        canvas: &super::canvas::Canvas,
        keep: impl Fn(usize, usize) -> bool,
    ) -> Result<(Image, Vec<f32>)> {
        let channels = canvas.pixels.channels();
        let mut data = vec![0.0f32; self.width * self.height * channels];
        let mut weights = vec![0.0f32; self.width * self.height];
        let (w, h) = (canvas.width as i64, canvas.height as i64);
        let source = canvas.pixels.data();
        for j in 0..self.height {
            let y = self.y + j as i64;
            let y = if canvas.wrap { y.rem_euclid(h) } else { y };
            if !(0..h).contains(&y) {
                continue;
            }
            for i in 0..self.width {
                let x = self.x + i as i64;
                let x = if canvas.wrap { x.rem_euclid(w) } else { x };
                if !(0..w).contains(&x) {
                    continue;
                }
                let (x, y) = (x as usize, y as usize);
                let at = y * canvas.width + x;
                if canvas.label[at] == UNCOVERED || !keep(x, y) {
                    continue;
                }
                let k = j * self.width + i;
                weights[k] = 1.0;
                data[k * channels..(k + 1) * channels]
                    .copy_from_slice(&source[at * channels..(at + 1) * channels]);
            }
        }
        Ok((
            Image::from_vec(self.width, self.height, channels, data)?,
            weights,
        ))
    }

    /// Where `patch` sits in the search map of this window.
    #[must_use]
    pub fn offset(&self, patch: Patch, (w, h): (usize, usize)) -> (isize, isize) {
        let (tx, ty) = (i64::from(patch.tx), i64::from(patch.ty));
        match self.boundary {
            Boundary::Periodic => (tx as isize, ty as isize),
            // A wrapped offset was reduced modulo the output size; inside the window it is the
            // distance from the window's corner, between `lowest` and `lowest` plus the output
            // size (0 up for a window around the candidates, negative for the region's).
            Boundary::Open if self.wrap => {
                let (lx, ly) = self.lowest;
                (
                    ((tx - self.x - lx).rem_euclid(w as i64) + lx) as isize,
                    ((ty - self.y - ly).rem_euclid(h as i64) + ly) as isize,
                )
            }
            // Bounded: the window may start after the patch does (negative offsets are in the
            // map, down to 1 - patch size).
            Boundary::Open => ((tx - self.x) as isize, (ty - self.y) as isize),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_wrap() {
        let r = Region {
            x: 4,
            y: 0,
            width: 3,
            height: 2,
        };
        assert!(region_contains(r, 0, 1, 6, 5, true));
        assert!(!region_contains(r, 0, 1, 6, 5, false));
        assert!(region_contains(r, 5, 0, 6, 5, false));
    }
}
