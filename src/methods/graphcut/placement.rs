//! Choosing where the next patch goes (section 4): an error region first, then an unused offset
//! whose patch covers it, at random or by matching (entire patch, eq. 2; sub-patch, eq. 4), drawn
//! with probability exp(-C / (k sigma^2)) (eq. 3). Costs come from the FFT SSD search (section 5).

use super::canvas::Patch;
use super::options::Placement;
use super::region::{Candidate, Region, SearchWindow};
use super::source_window::search_key;
use super::synthesis::Synthesis;
use crate::core::{Error, Result};
use crate::solvers::fft_ssd::{Boundary, MAX_TRANSFORM_VALUES, OffsetRange, transform_size};

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
