//! Options of a video synthesis. `fixed_frames` and `transition_window` default to the paper's
//! values; the other defaults are the library's (docs/methods/video.md gives the reasons).

use crate::core::{Error, Result};
pub use crate::methods::graphcut::Blend;

/// Which of the paper's video syntheses to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// 7.A: the best transition (i -> j) by frame-pair SSD, then the optimal seam surface in a
    /// window around it; the output is a loop of i - j frames.
    #[default]
    Loop,
    /// 7.B: copies of the whole input at random (or matching) temporal offsets; frame size of the
    /// input; looped by the temporal constraints of 7.D when `fixed_frames > 0`.
    Offsets,
    /// 7.C / 7.E: spatio-temporal patches placed in x, y and t; frames may be larger than the
    /// input's; looped by 7.D when `fixed_frames > 0`.
    Extend,
}

impl Mode {
    /// The mode of a name used in options ("loop", "offsets", "extend"); `None` for another.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Mode> {
        match name {
            "loop" => Some(Mode::Loop),
            "offsets" => Some(Mode::Offsets),
            "extend" => Some(Mode::Extend),
            _ => None,
        }
    }
}

/// How offsets are chosen (section 4), with the image version's names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Placement {
    /// Any unused offset that covers the error region, uniformly (7.B's random offsets).
    #[default]
    Random,
    /// Entire-patch matching in 3-D (eq. 2): the SSD between the whole input clip at each
    /// translation that covers the error region and every covered voxel it overlaps, divided by
    /// the overlap, by 3-D FFT, drawn by eq. 3.
    EntirePatch,
    /// Sub-patch matching in 3-D (7.C, eq. 4): the SSD of the error region against every
    /// translation of the input that covers it, by 3-D FFT, drawn by eq. 3.
    SubPatch,
}

impl Placement {
    /// The placement of a name used in options ("random", "entire-patch", "sub-patch", and
    /// "matching" for "sub-patch"); `None` for another.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Placement> {
        match name {
            "random" => Some(Placement::Random),
            "entire-patch" => Some(Placement::EntirePatch),
            "sub-patch" | "matching" => Some(Placement::SubPatch),
            _ => None,
        }
    }

    /// Whether offsets are drawn from their matching costs (eq. 3).
    #[must_use]
    pub fn is_matching(self) -> bool {
        self != Placement::Random
    }
}

/// Every option; `None` sizes mean "the input's" (frames: twice the input's for `Offsets`,
/// the input's for `Extend`; `Loop` chooses its own length).
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Which synthesis to run. Default: [`Mode::Loop`].
    pub mode: Mode,
    /// Frame width in pixels; only [`Mode::Extend`] may differ from the input's.
    pub output_width: Option<usize>,
    /// Frame height in pixels; only [`Mode::Extend`] may differ from the input's.
    pub output_height: Option<usize>,
    /// Output frames, without 7.D's removed first k; refused for [`Mode::Loop`], which chooses
    /// its own length.
    pub output_frames: Option<usize>,
    /// k of 7.D for [`Mode::Offsets`] and [`Mode::Extend`]: the first and last k frames fixed
    /// while synthesising, then the first k removed, so that the output loops. Default (None):
    /// 10 ("k = 10 in our implementation"). `Some(0)` turns the constraint off (no loop).
    /// Refused for [`Mode::Loop`], whose loop is 7.A's transition.
    pub fixed_frames: Option<usize>,
    /// The most frames of the seam window around the transition of 7.A. Default: 60 (the
    /// paper's "60-frame spatio-temporal window"); shorter clips get a shorter window.
    pub transition_window: usize,
    /// [`Mode::Loop`]: how many good transitions get a seam surface (the best by frame SSD, and
    /// the next best of other loop lengths within the window around it); the one whose seam costs
    /// least is kept. Default: 3; 1 seams the best transition only.
    pub transitions: usize,
    /// How offsets are chosen in [`Mode::Offsets`] and [`Mode::Extend`]. Default: random.
    pub placement: Placement,
    /// Seed of every random choice (offsets, eq. 3's draws). Default: 1.
    pub seed: u64,
    /// k of eq. 3 for matching placement. Default: 0.01, as in the image version.
    pub k: f32,
    /// Patches placed over the worst seams once the output is covered (section 3.2). Default: 2;
    /// every one is a graph the size of a whole input clip.
    pub refinement_patches: usize,
    /// M' (eq. 5) instead of M. Default: false.
    pub gradient_cost: bool,
    /// How the output is smoothed across seams (section 5): [`Blend::None`] or
    /// [`Blend::Feather`], over x, y and time; [`Blend::Spline`] is for images only. Default:
    /// none.
    pub blend: Blend,
    /// The memory budget in MiB (see `crate::core::budget`): the constructor refuses a video
    /// whose working set would exceed it. Default: 1024.
    pub memory_budget_mib: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            mode: Mode::Loop,
            output_width: None,
            output_height: None,
            output_frames: None,
            fixed_frames: None,
            transition_window: 60,
            transitions: DEFAULT_TRANSITIONS,
            placement: Placement::Random,
            seed: 1,
            k: 0.01,
            refinement_patches: 2,
            gradient_cost: false,
            blend: Blend::None,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

/// Transitions a loop seams by default (the paper's "limited number").
pub const DEFAULT_TRANSITIONS: usize = 3;

/// The most transitions a loop may seam: each is a max-flow over the whole window.
pub const MAX_TRANSITIONS: usize = 16;

/// k of 7.D when `fixed_frames` is not given: "k = 10 in our implementation".
pub const DEFAULT_FIXED_FRAMES: usize = 10;

fn invalid(name: &'static str, reason: String) -> Error {
    Error::InvalidParameter { name, reason }
}

impl Options {
    /// k of 7.D for this mode: 0 for [`Mode::Loop`], else `fixed_frames` or its default.
    #[must_use]
    pub fn fixed(&self) -> usize {
        match self.mode {
            Mode::Loop => 0,
            Mode::Offsets | Mode::Extend => self.fixed_frames.unwrap_or(DEFAULT_FIXED_FRAMES),
        }
    }

    /// The output size (width, height, frames as the user sees them) for an input of this size,
    /// or an error naming the option that does not fit the mode.
    pub fn output_size(&self, input: (usize, usize, usize)) -> Result<(usize, usize, usize)> {
        crate::core::budget::validate_budget(self.memory_budget_mib)?;
        let width = self.output_width.unwrap_or(input.0);
        let height = self.output_height.unwrap_or(input.1);
        if self.mode != Mode::Extend && (width, height) != (input.0, input.1) {
            return Err(invalid(
                "outputWidth/outputHeight",
                format!(
                    "only mode 'extend' changes the frame size; the clip is {}x{}, asked for {width}x{height}",
                    input.0, input.1
                ),
            ));
        }
        if self.blend == Blend::Spline {
            return Err(invalid(
                "blend",
                "'spline' blends images only; video offers 'none' and 'feather'".into(),
            ));
        }
        if !(self.k.is_finite() && self.k > 0.0) {
            return Err(invalid(
                "k",
                format!("must be a positive number, got {}", self.k),
            ));
        }
        match self.mode {
            Mode::Loop => {
                if let Some(k) = self.fixed_frames {
                    return Err(invalid(
                        "fixedFrames",
                        format!(
                            "mode 'loop' loops through 7.A's transition; the fixed frames of 7.D (k = {k}) are for 'offsets' and 'extend'; leave it out"
                        ),
                    ));
                }
                if self.output_frames.is_some() {
                    return Err(invalid(
                        "outputFrames",
                        "mode 'loop' chooses the loop length from the best transition; leave it out".into(),
                    ));
                }
                if !(1..=MAX_TRANSITIONS).contains(&self.transitions) {
                    return Err(invalid(
                        "transitions",
                        format!(
                            "must be between 1 and {MAX_TRANSITIONS}, got {}",
                            self.transitions
                        ),
                    ));
                }
                if self.transition_window < 3 {
                    return Err(invalid(
                        "transitionWindow",
                        format!("must be at least 3 frames, got {}", self.transition_window),
                    ));
                }
                Ok((width, height, input.2))
            }
            Mode::Offsets | Mode::Extend => {
                let frames = self.output_frames.unwrap_or(if self.mode == Mode::Offsets {
                    2 * input.2
                } else {
                    input.2
                });
                if frames == 0 || width == 0 || height == 0 {
                    return Err(invalid(
                        "output size",
                        format!("{width}x{height}x{frames} is empty"),
                    ));
                }
                let k = self.fixed();
                if k > 0 && k > input.2 {
                    return Err(invalid(
                        "fixedFrames",
                        format!(
                            "{k} fixed frames need a clip of at least {k} frames; it has {} (use a smaller fixedFrames, or 0)",
                            input.2
                        ),
                    ));
                }
                if k > 0 && frames < k + 1 {
                    return Err(invalid(
                        "fixedFrames",
                        format!(
                            "{k} fixed frames need more than {k} output frames, got outputFrames {frames}"
                        ),
                    ));
                }
                // Bounded before the working set multiplies the sizes in usize: 'extend' to
                // 65536^3 would overflow the estimate (a panic natively; in wasm32 it would wrap
                // round and accept the session). Beyond 2^32 voxels no budget could hold it;
                // below, the budget check names the sizes and the limit. (Saturating: three
                // sizes near 2^32 overflow even u64.)
                let voxels = (width as u64)
                    .saturating_mul(height as u64)
                    .saturating_mul(frames as u64 + k as u64);
                if voxels > u64::from(u32::MAX) {
                    return Err(invalid(
                        "output size",
                        format!(
                            "{width}x{height}x{frames} is {voxels} voxels, far beyond any memory budget"
                        ),
                    ));
                }
                Ok((width, height, frames))
            }
        }
    }
}
