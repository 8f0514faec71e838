//! Choosing where the next patch goes (section 4): an error region first, then an unused offset
//! whose patch covers it, at random or by matching (entire patch, eq. 2; sub-patch, eq. 4), drawn
//! with probability exp(-C / (k sigma^2)) (eq. 3). Costs come from the FFT SSD search (section 5).

use super::canvas::{Patch, UNCOVERED};
use super::options::{Options, Placement};
use super::source::Source;
use super::source_window::{MAX_SOURCE_SIDE, search_key, window_extent};
use super::synthesis::Synthesis;
use crate::core::{Error, Image, Result};
use crate::solvers::fft_ssd::{Boundary, MAX_TRANSFORM_VALUES, OffsetRange, transform_size};

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

impl Synthesis {
    /// The region the next patch must cover. While the output is not covered: a square around
    /// the first uncovered pixel in scan order, so it holds both covered and uncovered pixels
    /// and the texture grows consistently with what is there (its size and place:
    /// [`Options::fill_region`]). Once covered: the square with the largest total seam error.
    #[must_use]
    pub fn error_region(&self) -> Region {
        let (ew, eh) = self.window_extent(0);
        let side = self.options.error_region_side(ew, eh);
        let (w, h) = (self.canvas.width, self.canvas.height);
        if !self.canvas.is_covered() {
            let smallest = (0..self.sources.len())
                .map(|s| {
                    let (pw, ph) = self.patch_extent(s);
                    pw.min(ph)
                })
                .min()
                .unwrap_or(side);
            let (side, before) = self.options.fill_region(ew, eh, smallest);
            let lead = (side as f32 * before) as usize;
            let clamp = |c: usize, len: usize| c.saturating_sub(lead).min(len - side);
            let first = self.canvas.first_uncovered().expect("not covered");
            let (x, y) = (first % w, first / w);
            return Region {
                x: clamp(x, w),
                y: clamp(y, h),
                width: side,
                height: side,
            };
        }
        let (x, y) = self.canvas.largest_error_window(side);
        Region {
            x,
            y,
            width: side,
            height: side,
        }
    }

    /// The output window the FFT search of a placement over `region` reads, for a patch of
    /// `extent` (see [`SearchWindow::of`]).
    #[must_use]
    pub fn search_window(&self, region: Region, extent: (usize, usize)) -> SearchWindow {
        let (w, h) = (self.canvas.width, self.canvas.height);
        SearchWindow::of(
            self.options.placement,
            region,
            extent,
            (w, h),
            self.canvas.wrap,
        )
    }

    /// Refuses, before any step, an exemplar whose search window would need a transform larger
    /// than the FFT search allows. With the sources bounded to windows of at most
    /// [`super::source_window::MAX_SOURCE_SIDE`] a side this never happens (the transform is at
    /// most 1536 values a side); it guards a synthesis that uses its sources whole
    /// (`max_source_side = usize::MAX`).
    pub fn check_search_size(&self) -> Result<()> {
        if self.options.placement == Placement::Random {
            return Ok(());
        }
        let (ew, eh) = self.window_extent(0);
        let side = self.options.error_region_side(ew, eh);
        let (w, h) = (self.canvas.width, self.canvas.height);
        // The window is largest where the border does not clip it: the region in the middle.
        let region = Region {
            x: w.saturating_sub(side) / 2,
            y: h.saturating_sub(side) / 2,
            width: side,
            height: side,
        };
        for s in 0..self.sources.len() {
            let (pw, ph) = self.patch_extent(s);
            let window = self.search_window(region, (pw, ph));
            let (nx, ny) = transform_size((window.width, window.height), (pw, ph), window.boundary);
            if nx.saturating_mul(ny) > MAX_TRANSFORM_VALUES {
                let source = &self.sources[s];
                return Err(Error::InvalidSize {
                    what: "exemplar",
                    width: source.width(),
                    height: source.height(),
                    reason: format!(
                        "graph-cut matching with patches of {pw}x{ph} would search a {nx}x{ny} \
                         transform, more than the {MAX_TRANSFORM_VALUES} values allowed; bound \
                         the source windows (max_source_side), shrink it first (e.g. \
                         exemplar.resized(512)) or use placement 'random'"
                    ),
                });
            }
        }
        Ok(())
    }

    /// Every unused offset of every allowed source whose patch covers `region` entirely. The
    /// patch is the source's current window (see `source_window.rs`; [`Synthesis::draw_windows`]
    /// draws it before each placement): the whole source when within the bound.
    #[must_use]
    pub fn candidates(&self, region: Region) -> Vec<Patch> {
        let mut out = Vec::new();
        for s in 0..self.sources.len() {
            if !self.source_allowed(s, region) {
                continue;
            }
            let (sw, sh) = self.patch_extent(s);
            if sw < region.width || sh < region.height {
                continue;
            }
            let window = self.window(s);
            let (x0, y0) = (region.x as i64, region.y as i64);
            let (x1, y1) = (x0 + region.width as i64, y0 + region.height as i64);
            for ty in (y1 - sh as i64)..=y0 {
                for tx in (x1 - sw as i64)..=x0 {
                    let (tx, ty) = if self.canvas.wrap {
                        (
                            tx.rem_euclid(self.canvas.width as i64),
                            ty.rem_euclid(self.canvas.height as i64),
                        )
                    } else {
                        (tx, ty)
                    };
                    let patch = Patch {
                        source: s as u32,
                        tx: tx as i32,
                        ty: ty as i32,
                        window,
                    };
                    if !self.used.contains(&patch) {
                        out.push(patch);
                    }
                }
            }
        }
        out
    }

    /// With perspective on, each band of output rows takes only the source whose scale belongs
    /// there: scales rise monotonically from the top row (smallest) to the bottom (largest).
    fn source_allowed(&self, s: usize, region: Region) -> bool {
        if !self.options.transforms.perspective {
            return true;
        }
        let mut scales: Vec<f32> = self.sources.iter().map(|src| src.scale).collect();
        scales.sort_by(f32::total_cmp);
        scales.dedup();
        let centre = (region.y + region.height / 2) as f32 / self.canvas.height as f32;
        let band = ((centre * scales.len() as f32) as usize).min(scales.len() - 1);
        self.sources[s].scale == scales[band]
    }

    /// The matching cost of every candidate (empty costs for random placement).
    pub fn score(&mut self, region: Region, candidates: &[Patch]) -> Result<Vec<Candidate>> {
        if self.options.placement == Placement::Random || self.canvas.covered == 0 {
            return Ok(candidates
                .iter()
                .map(|&patch| Candidate { patch, cost: 0.0 })
                .collect());
        }
        let (w, h) = (self.canvas.width, self.canvas.height);
        let mut scored = Vec::with_capacity(candidates.len());
        for s in 0..self.sources.len() {
            let of_source: Vec<Patch> = candidates
                .iter()
                .copied()
                .filter(|p| p.source as usize == s)
                .collect();
            if of_source.is_empty() {
                continue;
            }
            let (pw, ph) = self.patch_extent(s);
            let (wx, wy) = self.window(s);
            let patch_image = self.sources[s]
                .image
                .crop(wx as usize, wy as usize, pw, ph)?;
            // Weights on the output: covered pixels (eq. 2), and only inside the error region
            // (the output sub-patch of eq. 4) for sub-patch matching, whose window is the region.
            let window = self.search_window(region, (pw, ph));
            let (pixels, weights) = window.gather(&self.canvas, |_, _| true)?;
            // Keyed by source and window: a source within the bound is transformed once per
            // synthesis, not per placement (the window's size depends on the patch and the region
            // only, so it never changes); a larger one each time its window moves.
            let key = Some(search_key(s, (wx, wy)));
            let map = match window.boundary {
                // The map is needed only at the candidates' offsets: a transform the size of
                // their span plus the patch (about 180 a side for a 128 patch while covering,
                // instead of 300), not the window plus the patch.
                Boundary::Open => {
                    let offsets: Vec<(isize, isize)> = of_source
                        .iter()
                        .map(|&p| window.offset(p, (w, h)))
                        .collect();
                    let min = |f: fn(&(isize, isize)) -> isize| offsets.iter().map(f).min();
                    let max = |f: fn(&(isize, isize)) -> isize| offsets.iter().map(f).max();
                    let (x0, x1) = (min(|o| o.0).unwrap_or(0), max(|o| o.0).unwrap_or(0));
                    let (y0, y1) = (min(|o| o.1).unwrap_or(0), max(|o| o.1).unwrap_or(0));
                    let range = OffsetRange {
                        first: (x0, y0),
                        count: ((x1 - x0 + 1) as usize, (y1 - y0 + 1) as usize),
                    };
                    self.ssd.search_range(
                        (&pixels, Some(&weights)),
                        (&patch_image, None),
                        range,
                        key,
                    )?
                }
                Boundary::Periodic => self.ssd.search_keyed(
                    &pixels,
                    Some(&weights),
                    &patch_image,
                    None,
                    window.boundary,
                    key,
                )?,
            };
            for patch in of_source {
                let (ox, oy) = window.offset(patch, (w, h));
                let (cost, area) = map.get(ox, oy).unwrap_or((0.0, 0.0));
                // Area-normalised (eq. 2); for sub-patches too, so that k means the same thing.
                let cost = if area > 0.5 {
                    cost / area
                } else {
                    f32::INFINITY
                };
                scored.push(Candidate { patch, cost });
            }
        }
        Ok(scored)
    }

    /// Draws a candidate with probability proportional to exp(-C / (k sigma^2)) (eq. 3).
    pub fn choose(&mut self, scored: &[Candidate]) -> Option<Patch> {
        if scored.is_empty() {
            return None;
        }
        let best = scored.iter().map(|c| c.cost).fold(f32::INFINITY, f32::min);
        if !best.is_finite() {
            return Some(scored[self.rng.index(scored.len())].patch);
        }
        let scale = f64::from(self.options.k) * f64::from(self.sigma).powi(2);
        // Relative to the best cost, so the largest weight is 1 and nothing underflows to 0 everywhere.
        let weights: Vec<f64> = scored
            .iter()
            .map(|c| crate::core::math::exp(-(f64::from(c.cost) - f64::from(best)) / scale))
            .collect();
        let total: f64 = weights.iter().sum();
        let mut pick = self.rng.next_f64() * total;
        for (candidate, weight) in scored.iter().zip(&weights) {
            if pick < *weight {
                return Some(candidate.patch);
            }
            pick -= weight;
        }
        scored
            .iter()
            .zip(&weights)
            .rev()
            .find(|(_, w)| **w > 0.0)
            .map(|(c, _)| c.patch)
    }
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
/// whole output makes a placement cost the same at 256x256 and 4096x4096 (issue 17). A wrapping
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

/// Sum of `values` over every `side` x `side` window, indexed by the window's top-left corner.
/// Windows that would cross the border get -inf (or wrap around when `wrap`). Running sums along
/// rows then columns: O(w h) whatever the side.
#[must_use]
pub fn box_sums(values: &[f32], w: usize, h: usize, side: usize, wrap: bool) -> Vec<f32> {
    let rows = sliding_row_sums(values, w, h, side, wrap);
    sliding_column_sums(&rows, w, h, side, wrap)
}

/// Slides a window of `side` values along positions `0..len`: `read(k)` is the value at position
/// `k` (asked for `k < len + side`), and `write(k, total)` receives the total of positions
/// `k..k + side`. The total is kept in f64 so that it does not drift, and updated as "plus the
/// entering value, minus the leaving one" in that order. Every row and single-column window sum
/// of the refinement goes through here, whole-output and kept alike (`error_regions.rs`), so
/// windows started at the same place add to the same bits.
#[inline]
pub(super) fn slide_window(
    len: usize,
    side: usize,
    read: impl Fn(usize) -> f32,
    mut write: impl FnMut(usize, f32),
) {
    let mut sum: f64 = (0..side).map(|k| f64::from(read(k))).sum();
    for k in 0..len {
        write(k, sum as f32);
        sum += f64::from(read(k + side)) - f64::from(read(k));
    }
}

/// Window sums of length `side` along each row (see [`slide_window`]).
pub(super) fn sliding_row_sums(
    values: &[f32],
    w: usize,
    h: usize,
    side: usize,
    wrap: bool,
) -> Vec<f32> {
    let mut out = vec![f32::NEG_INFINITY; w * h];
    for (row, out) in values.chunks_exact(w).zip(out.chunks_exact_mut(w)).take(h) {
        slide_window(
            w,
            side,
            |k| row[k % w],
            |start, total| {
                if wrap || start + side <= w {
                    out[start] = total;
                }
            },
        );
    }
    out
}

/// The same down the columns, all columns at once row by row (a column at a time strides through
/// memory a row apart: 11% of a 1024x1024 synthesis went there).
pub(super) fn sliding_column_sums(
    values: &[f32],
    w: usize,
    h: usize,
    side: usize,
    wrap: bool,
) -> Vec<f32> {
    let mut out = vec![f32::NEG_INFINITY; w * h];
    // Columns whose windows already cross the right border stay -inf.
    let live: Vec<bool> = values[..w]
        .iter()
        .map(|&v| v != f32::NEG_INFINITY)
        .collect();
    let mut sums = vec![0.0f64; w];
    for k in 0..side {
        let row = &values[(k % h) * w..][..w];
        for ((sum, &v), &on) in sums.iter_mut().zip(row).zip(&live) {
            if on {
                *sum += f64::from(v);
            }
        }
    }
    for start in 0..h {
        let (entering, leaving) = (((start + side) % h) * w, start * w);
        let out_row = &mut out[start * w..][..w];
        let write = wrap || start + side <= h;
        for x in 0..w {
            if !live[x] {
                continue;
            }
            if write {
                out_row[x] = sums[x] as f32;
            }
            sums[x] += f64::from(values[entering + x]) - f64::from(values[leaving + x]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_sums_match_a_direct_sum() {
        let values: Vec<f32> = (0..30).map(|i| (i * 7 % 5) as f32).collect();
        let sums = box_sums(&values, 6, 5, 2, false);
        assert_eq!(sums[0], values[0] + values[1] + values[6] + values[7]);
        assert_eq!(sums[5], f32::NEG_INFINITY);
        assert!(sums.iter().all(|v| !v.is_nan()));
        for y in 0..4 {
            for x in 0..5 {
                let direct: f32 = (0..2)
                    .flat_map(|dy| (0..2).map(move |dx| (dx, dy)))
                    .map(|(dx, dy)| values[(y + dy) * 6 + x + dx])
                    .sum();
                assert!((sums[y * 6 + x] - direct).abs() < 1e-4);
            }
        }
        let wrapped = box_sums(&values, 6, 5, 2, true);
        assert_eq!(wrapped[29], values[29] + values[24] + values[5] + values[0]);
    }

    /// Box sums on random values, every size and side, wrapping or not, against a direct sum.
    #[test]
    fn box_sums_match_a_direct_sum_on_random_values() {
        let mut rng = crate::core::Rng::new(5);
        for (w, h, side) in [(7, 5, 2), (13, 9, 4), (5, 12, 5), (16, 16, 16), (9, 4, 1)] {
            let values: Vec<f32> = (0..w * h).map(|_| rng.next_f32() * 3.0).collect();
            for wrap in [false, true] {
                let sums = box_sums(&values, w, h, side, wrap);
                for y in 0..h {
                    for x in 0..w {
                        let fits = x + side <= w && y + side <= h;
                        if !wrap && !fits {
                            assert_eq!(sums[y * w + x], f32::NEG_INFINITY);
                            continue;
                        }
                        let direct: f64 = (0..side * side)
                            .map(|k| values[((y + k / side) % h) * w + (x + k % side) % w])
                            .map(f64::from)
                            .sum();
                        let got = f64::from(sums[y * w + x]);
                        assert!(
                            (got - direct).abs() < 1e-4,
                            "{w}x{h} side {side} wrap {wrap}"
                        );
                    }
                }
            }
        }
    }

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
