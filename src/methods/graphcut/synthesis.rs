//! The state of a graph-cut synthesis: the sources, the canvas with its seam memory, and the
//! offsets already used. Placement (`placement.rs`) and seam finding (`seam.rs`) extend it.

use rustc_hash::FxHashSet;

use super::canvas::{Canvas, Patch};
use super::cost::{Sample, colour_distance, match_cost, value_sigma};
use super::options::Options;
use super::source::{Source, build_sources};
use super::source_window::{MAX_SOURCE_SIDE, draw_origin, window_extent};
use crate::core::{Image, Result, Rng};
use crate::solvers::fft_ssd::SsdSearch;

/// Sources, canvas and history of one synthesis.
pub struct Synthesis {
    pub options: Options,
    pub sources: Vec<Source>,
    pub canvas: Canvas,
    pub rng: Rng,
    /// Offsets already placed (section 4: only unused offsets are considered).
    pub used: FxHashSet<Patch>,
    /// Standard deviation of the exemplar's values (sigma of eq. 3).
    pub sigma: f32,
    /// The FFT SSD search, kept between placements for its plans and buffers.
    pub ssd: SsdSearch,
    /// Optional feature masks of the sources (one per source, row-major; empty: none), and the
    /// cost a seam pays per pixel where the two patches disagree on a feature (feature-guided
    /// placement: a cut through a curve that does not go on in the other patch breaks it).
    pub seam_features: Vec<Vec<bool>>,
    pub seam_feature_weight: f32,
    /// The largest side of the part of a source one placement uses ([`MAX_SOURCE_SIDE`]; see
    /// `source_window.rs`). `usize::MAX` uses every source whole, as the paper does.
    pub max_source_side: usize,
    /// The window origin of every source for the current placement (drawn by
    /// [`Synthesis::draw_windows`]; (0, 0) for a source within the bound).
    pub windows: Vec<(u32, u32)>,
    /// Whether placements keep their graph for the page's placement anatomy, and the last one.
    pub record_anatomy: bool,
    pub last_graph: Option<super::anatomy::GraphView>,
    /// The max-flow graph, reset at every placement: its buffers (arcs, nodes, queues) keep
    /// their memory between placements instead of being allocated and cleared anew each time.
    pub graph: crate::solvers::maxflow::Graph,
}

impl Synthesis {
    /// A synthesis of `exemplar` (and its transformed versions, as the options say).
    pub fn new(exemplar: &Image, options: Options) -> Result<Synthesis> {
        Self::with_exemplars(std::slice::from_ref(exemplar), options)
    }

    /// A synthesis whose patches come from any of `exemplars` (each with its transformed
    /// versions): the placement's candidates range over all of them, and each patch knows its
    /// source and so its exemplar ([`Source::exemplar`]). Exemplars with fewer channels are
    /// widened to the most any has (grey to RGB, an alpha of 1 added).
    pub fn with_exemplars(exemplars: &[Image], options: Options) -> Result<Synthesis> {
        let Some(first) = exemplars.first() else {
            return Err(crate::core::Error::InvalidParameter {
                name: "exemplars",
                reason: "give at least one exemplar".into(),
            });
        };
        let channels = exemplars.iter().map(Image::channels).max().unwrap_or(1);
        let mut sources = Vec::new();
        let mut values = Vec::new();
        for (k, exemplar) in exemplars.iter().enumerate() {
            let exemplar = exemplar.with_channels(channels)?;
            options.validate(exemplar.width(), exemplar.height())?;
            for mut source in build_sources(&exemplar, &options.transforms)? {
                source.exemplar = k as u32;
                if exemplars.len() > 1 {
                    source.name = format!("exemplar {} {}", k + 1, source.name)
                        .replace(" exemplar", "");
                }
                sources.push(source);
            }
            values.extend_from_slice(exemplar.data());
        }
        let exemplar = first.with_channels(channels)?;
        // The budget is checked before the canvas, the largest buffer, is allocated.
        let (w, h) = (options.output_width, options.output_height);
        working_set(&options, &sources, exemplar.channels()).check(
            &format!("output {w}x{h}"),
            super::memory::METHOD,
            options.memory_budget_mib,
        )?;
        let canvas = Canvas::new(
            options.output_width,
            options.output_height,
            exemplar.channels(),
            options.tileable,
        )?;
        let synthesis = Synthesis {
            rng: Rng::new(options.seed),
            sigma: value_sigma(&values),
            options,
            sources,
            canvas,
            used: FxHashSet::default(),
            ssd: SsdSearch::new(),
            seam_features: Vec::new(),
            seam_feature_weight: 0.0,
            max_source_side: MAX_SOURCE_SIDE,
            windows: Vec::new(),
            record_anatomy: false,
            last_graph: None,
            graph: crate::solvers::maxflow::Graph::default(),
        };
        synthesis.check_search_size()?;
        Ok(synthesis)
    }

    /// The estimated working set of the synthesis (see [`super::memory`]).
    #[must_use]
    pub fn working_set(&self) -> crate::core::budget::WorkingSet {
        working_set(&self.options, &self.sources, self.canvas.pixels.channels())
    }

    /// What patch `patch` shows at output pixel `i`, with its gradient across a horizontal edge
    /// (`horizontal`) or a vertical one; `None` where the patch does not reach.
    #[inline]
    #[must_use]
    pub fn sample(&self, patch: Patch, i: usize, horizontal: bool) -> Option<Sample<'_>> {
        let (x, y) = (i % self.canvas.width, i / self.canvas.width);
        let source = &self.sources[patch.source as usize];
        let (sx, sy) = self.source_coords(patch, x, y)?;
        let k = sy * source.width() + sx;
        Some(Sample {
            colour: source.image.pixel(sx, sy),
            gradient: if horizontal {
                source.grad_x[k]
            } else {
                source.grad_y[k]
            },
        })
    }

    /// The seam cost M(s, t, A, B) for neighbouring output pixels `s`, `t` (t right of or below
    /// s) when s shows patch `a` and t shows patch `b`. Zero when they are the same patch. A pixel
    /// one of the patches does not reach adds nothing (see [`match_cost`]): the cost never
    /// depends on what the canvas shows, so the cut that places a patch and the seam it leaves
    /// behind are costed alike, covered or not.
    #[must_use]
    pub fn seam_cost(&self, s: usize, t: usize, horizontal: bool, a: Patch, b: Patch) -> f32 {
        if a == b {
            return 0.0;
        }
        let gradient = self.options.gradient_cost;
        let m = match_cost(
            self.sample(a, s, horizontal),
            self.sample(b, s, horizontal),
            self.sample(a, t, horizontal),
            self.sample(b, t, horizontal),
            gradient,
        );
        if self.seam_feature_term() {
            let mismatch = |i: usize| match (self.feature_at(a, i), self.feature_at(b, i)) {
                (Some(fa), Some(fb)) => f32::from(u8::from(fa != fb)),
                _ => 0.0,
            };
            m + self.seam_feature_weight * (mismatch(s) + mismatch(t))
        } else {
            m
        }
    }

    /// Pixel `i`'s term `||A(i) - B(i)||` of M when it shows patch `a` and `b` is the other patch:
    /// [`Synthesis::seam_cost`] is the sum of its two pixels' terms, computed the same way, when
    /// the cost is plain M (no gradient scaling, no feature mismatch); `None` otherwise.
    #[must_use]
    pub fn cell_term(&self, i: usize, a: Patch, b: Patch) -> Option<f32> {
        let plain = !self.options.gradient_cost && !self.seam_feature_term();
        plain.then(
            || match (self.sample(a, i, true), self.sample(b, i, true)) {
                (Some(a), Some(b)) => colour_distance(a.colour, b.colour),
                _ => 0.0,
            },
        )
    }

    /// Whether M has the feature-mismatch term (feature-guided synthesis's seams).
    fn seam_feature_term(&self) -> bool {
        self.seam_feature_weight > 0.0 && !self.seam_features.is_empty()
    }

    /// Whether `patch` shows a feature pixel at output pixel `i` (None where it does not reach
    /// or its source has no feature mask).
    #[inline]
    #[must_use]
    pub fn feature_at(&self, patch: Patch, i: usize) -> Option<bool> {
        let (x, y) = (i % self.canvas.width, i / self.canvas.width);
        let source = &self.sources[patch.source as usize];
        let mask = self.seam_features.get(patch.source as usize)?;
        let (sx, sy) = self.source_coords(patch, x, y)?;
        mask.get(sy * source.width() + sx).copied()
    }

    /// The source coordinates `patch` copies to output pixel (x, y), if it covers it.
    #[inline]
    #[must_use]
    pub fn source_coords(&self, patch: Patch, x: usize, y: usize) -> Option<(usize, usize)> {
        self.canvas
            .source_coords(patch, self.patch_extent(patch.source as usize), x, y)
    }

    /// The size of the window of source `s` one placement uses: the source itself when within
    /// `max_source_side` (see `source_window.rs`).
    #[must_use]
    pub fn window_extent(&self, s: usize) -> (usize, usize) {
        let source = &self.sources[s];
        window_extent(source.width(), source.height(), self.max_source_side)
    }

    /// The part of source `s` a patch uses: its window, or at most the output size when
    /// wrapping (a larger patch would overlap itself).
    #[must_use]
    pub fn patch_extent(&self, s: usize) -> (usize, usize) {
        let (ww, wh) = self.window_extent(s);
        if self.canvas.wrap {
            (ww.min(self.canvas.width), wh.min(self.canvas.height))
        } else {
            (ww, wh)
        }
    }

    /// Draws the window of every source larger than `max_source_side` for the next placement
    /// (uniformly where it fits, from the seeded generator); a source within the bound keeps
    /// (0, 0) and draws nothing, so its results are those of the unbounded method.
    pub fn draw_windows(&mut self) {
        self.windows = (0..self.sources.len())
            .map(|s| {
                let source = &self.sources[s];
                let (size, extent) = ((source.width(), source.height()), self.patch_extent(s));
                draw_origin(&mut self.rng, size, extent, self.max_source_side)
            })
            .collect();
    }

    /// The window origin of source `s` for the current placement.
    #[must_use]
    pub fn window(&self, s: usize) -> (u32, u32) {
        self.windows.get(s).copied().unwrap_or((0, 0))
    }

    /// The patch of a labelled pixel.
    #[inline]
    #[must_use]
    pub fn patch_of(&self, i: usize) -> Option<Patch> {
        let label = self.canvas.label[i];
        (label != super::canvas::UNCOVERED).then(|| self.canvas.patches[label as usize])
    }

    /// The footprint of `patch` in the output: the output pixels it covers, in source scan order.
    #[must_use]
    pub fn footprint(&self, patch: Patch) -> Vec<usize> {
        let (w, h) = (self.canvas.width as i64, self.canvas.height as i64);
        let (sw, sh) = self.patch_extent(patch.source as usize);
        let mut pixels = Vec::with_capacity(sw * sh);
        for v in 0..sh as i64 {
            let mut y = i64::from(patch.ty) + v;
            if self.canvas.wrap {
                y = y.rem_euclid(h);
            } else if !(0..h).contains(&y) {
                continue;
            }
            for u in 0..sw as i64 {
                let mut x = i64::from(patch.tx) + u;
                if self.canvas.wrap {
                    x = x.rem_euclid(w);
                } else if !(0..w).contains(&x) {
                    continue;
                }
                pixels.push((y * w + x) as usize);
            }
        }
        pixels
    }
}

/// The working set of a synthesis with `options` over `sources` (see [`super::memory`]).
fn working_set(
    options: &Options,
    sources: &[Source],
    channels: usize,
) -> crate::core::budget::WorkingSet {
    let canvas = (
        options.output_width,
        options.output_height,
        options.tileable,
    );
    let patch = sources
        .iter()
        .map(|s| {
            let (w, h) = super::region::patch_extent(s, canvas);
            w * h
        })
        .max()
        .unwrap_or(0);
    let search = super::region::largest_search(options, sources, canvas)
        .map_or(0, |(_, nx, ny)| nx.saturating_mul(ny));
    let dims: Vec<(usize, usize)> = sources.iter().map(|s| (s.width(), s.height())).collect();
    super::memory::working_set(
        (options.output_width, options.output_height, channels),
        &dims,
        patch,
        search,
        options.blend,
    )
}

/// The working set a synthesis of `exemplar` with `options` would have, without allocating
/// anything of the output's size (the sources are built: they are the exemplar's size).
pub fn estimate(exemplar: &Image, options: &Options) -> Result<crate::core::budget::WorkingSet> {
    let sources = build_sources(exemplar, &options.transforms)?;
    Ok(working_set(options, &sources, exemplar.channels()))
}
