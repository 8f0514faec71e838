//! The options of flow-guided texture animation.

use super::field::FlowField;
use super::generators::FlowSpec;
use crate::core::{Error, Result};
use crate::methods::optimization;
use crate::methods::optimization::schedule::{FIT_RATIO, fallback_size};
use crate::solvers::nn::Search;

/// Where the flow fields come from.
#[derive(Debug, Clone, PartialEq)]
pub enum FlowSource {
    /// A built-in generator (possibly time-varying), evaluated at every frame.
    Generator(FlowSpec),
    /// Fields given by the caller: f_1, f_2, ...; a single field is a stationary flow, and a
    /// shorter list than the animation repeats (so a cycle of fields loops).
    Fields(Vec<FlowField>),
}

impl FlowSource {
    /// The field f_t between frame t and t + 1, for frames of `width` x `height`.
    pub fn field(&self, width: usize, height: usize, t: usize) -> Result<FlowField> {
        match self {
            FlowSource::Generator(spec) => spec.field(width, height, t),
            FlowSource::Fields(fields) => Ok(fields[t % fields.len()].clone()),
        }
    }
}

/// Everything a flow animation can be told. Validate with [`FlowOptions::validate`].
#[derive(Debug, Clone, PartialEq)]
pub struct FlowOptions {
    /// Frame width and height. Default: 128x128.
    pub output_width: usize,
    /// Frame height in pixels. Default: 128.
    pub output_height: usize,
    /// Frames to make, the first included. Default: 60.
    pub frames: usize,
    /// Weight of the flow term (eq. 3 as a soft constraint, relative to the texture term at each
    /// pixel; see `optimization::constraints`). Default: 0.2, chosen on the samples (vortex,
    /// 50 frames): it keeps the frames' coherence within about 1.3x of the first frame's while
    /// cutting the flow energy by a third from lambda = 0; lambda = 0.5 follows the flow more
    /// closely (flow energy halved again) but the constraint's blur lifts coherence to ~1.8x.
    pub lambda: f32,
    /// Neighbourhood widths of the per-frame synthesis (one resolution; sizes that do not fit
    /// the exemplar, as in texture optimisation, or are wider than the frame are skipped). Default: [32, 16, 8], the first frame's ladder.
    /// Structures wider than the smallest size (paving's cells, the tiles' grid) are broken a
    /// little by every warp, and only a neighbourhood as wide as they are repairs them: with
    /// [16, 8] the flat fraction of frames 30-60 rises to 1.3-1.7x frame 1's and cracks and grid
    /// lines come apart; with 32 added it stays at 0.9-1.3x, for about 40% more time per frame
    /// (see the README's flow section for the flow energy this costs).
    pub frame_sizes: Vec<usize>,
    /// Cap on EM iterations per neighbourhood size per frame; the last one's M-step only
    /// measures the kept matches (see `FlowSession::step_frame`). Default: 3.
    pub frame_iterations: usize,
    /// Seed, search, robust exponent r and wrap-around, shared with the first frame.
    pub seed: u64,
    /// Nearest-neighbourhood search of every frame's M-step. Default: PatchMatch.
    pub search: Search,
    /// Exponent of the robust energy, in (0, 2] (2 is the plain quadratic). Default: 0.8.
    pub r: f32,
    /// Periodic frames: neighbourhoods and the flow's warp wrap around the borders, so every
    /// frame tiles. Default: false.
    pub tileable: bool,
    /// Histogram matching after every E-step, of the first frame and of every later frame
    /// (see `optimization::histogram`); 0 turns it off. In frames after the first it applies to
    /// every pixel: the flow constraint's colours are the texture's own, carried along the
    /// flow. Without it each frame averages the bilinearly warped previous frame with the
    /// texture, and contrast drains away frame after frame (tiles_128, vortex, 256x256: the
    /// flat fraction of frames 30-60 reaches 3.8x frame 1's). Default: 1.
    pub histogram_matching: f32,
    /// The memory budget in MiB (see `crate::core::budget`): the constructor refuses a frame
    /// size whose working set would exceed it. Default: 1024.
    pub memory_budget_mib: usize,
    /// Matches at half-pixel precision (see `optimization::phases`): content carried along the
    /// flow keeps its fraction of a pixel. With whole-pixel matches a flow slower than half a
    /// pixel per frame does not move the texture at all: the page's vortex never turns its
    /// centre (64 px across), and tiles_128 translated by 0.3 px per frame has frame 60 where
    /// frame 1 was. Sub-pixel matches follow the flow (flow energy of frames 30-60 on the
    /// vortex 15-34% lower) but content between pixels is a little softer, and under fast
    /// turns some frames lose more detail (frames 30-60 flat against frame 1: paving_128
    /// 1.50x against 1.32x, tiles_128 1.09x against 0.91x, gravel_128 1.19x against 1.28x),
    /// so it is off by default. Default: false.
    pub sub_pixel: bool,
}

impl Default for FlowOptions {
    fn default() -> Self {
        FlowOptions {
            output_width: 128,
            output_height: 128,
            frames: 60,
            lambda: 0.2,
            frame_sizes: vec![32, 16, 8],
            frame_iterations: 3,
            seed: 1,
            search: Search::PatchMatch,
            r: 0.8,
            tileable: false,
            histogram_matching: 1.0,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
            sub_pixel: false,
        }
    }
}

/// The longest animation accepted (about an hour at 25 frames per second).
pub const MAX_FRAMES: usize = 100_000;

impl FlowOptions {
    /// The options of the first frame, made by plain multi-level texture optimisation.
    #[must_use]
    pub fn first_frame(&self) -> optimization::Options {
        optimization::Options {
            output_width: self.output_width,
            output_height: self.output_height,
            seed: self.seed,
            search: self.search,
            r: self.r,
            tileable: self.tileable,
            histogram_matching: self.histogram_matching,
            memory_budget_mib: self.memory_budget_mib,
            // Random patches, not texture optimisation's graph-cut start: the frames' drift is
            // measured against frame 1, and a graph-cut frame 1 lies closer to the exemplar than
            // any turned frame can stay (seed 1, frames 30-60: tiles_128 at 256 coherence
            // 0.00050 against frame 1's 0.00019, 2.7x; with this start 0.00054 against 0.00037,
            // 1.5x; the later frames alike either way).
            start: optimization::Start::Patches,
            ..optimization::Options::default()
        }
    }

    /// The frame sizes the frames use, largest first: those that fit the exemplar by texture
    /// optimisation's rule (its shorter side at least `FIT_RATIO` widths, so the defaults are the
    /// first frame's full-resolution sizes) and are no wider than the frame; the others are
    /// skipped. Where none fits, texture optimisation's fallback (`schedule::fallback_size`):
    /// the smallest size at most half the exemplar.
    #[must_use]
    pub fn fitting_frame_sizes(&self, exemplar_width: usize, exemplar_height: usize) -> Vec<usize> {
        let exemplar_side = exemplar_width.min(exemplar_height);
        let frame_side = self.output_width.min(self.output_height);
        let mut sizes: Vec<usize> = self
            .frame_sizes
            .iter()
            .copied()
            .filter(|&s| s * FIT_RATIO <= exemplar_side && s <= frame_side)
            .collect();
        sizes.sort_unstable_by(|a, b| b.cmp(a));
        sizes.dedup();
        if sizes.is_empty() {
            sizes.extend(fallback_size(&self.frame_sizes, exemplar_side, frame_side));
        }
        sizes
    }

    /// Checks every option, the first frame's too; the error names the option.
    pub fn validate(&self, exemplar_width: usize, exemplar_height: usize) -> Result<()> {
        let invalid =
            |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        self.first_frame()
            .validate(exemplar_width, exemplar_height)?;
        if !(1..=MAX_FRAMES).contains(&self.frames) {
            return invalid(
                "frames",
                format!("must be between 1 and {MAX_FRAMES}, got {}", self.frames),
            );
        }
        if !self.lambda.is_finite()
            || !(0.0..=optimization::constraints::MAX_LAMBDA).contains(&self.lambda)
        {
            return invalid(
                "lambda",
                format!(
                    "must be between 0 and {}, got {}",
                    optimization::constraints::MAX_LAMBDA,
                    self.lambda
                ),
            );
        }
        if self.frame_sizes.is_empty() {
            return invalid("frameSizes", "must name at least one size".into());
        }
        if let Some(&bad) = self.frame_sizes.iter().find(|s| !(2..=128).contains(*s)) {
            return invalid(
                "frameSizes",
                format!("each size must be between 2 and 128, got {bad}"),
            );
        }
        if self
            .fitting_frame_sizes(exemplar_width, exemplar_height)
            .is_empty()
        {
            return invalid(
                "frameSizes",
                format!(
                    "none of {:?} fits both the exemplar ({exemplar_width}x{exemplar_height}; a size needs {FIT_RATIO} times its width, or twice where none does) and the frame ({}x{})",
                    self.frame_sizes, self.output_width, self.output_height
                ),
            );
        }
        if !(1..=optimization::options::MAX_ITERATIONS).contains(&self.frame_iterations) {
            return invalid(
                "frameIterations",
                format!(
                    "must be between 1 and {}, got {}",
                    optimization::options::MAX_ITERATIONS,
                    self.frame_iterations
                ),
            );
        }
        Ok(())
    }
}
