//! The video session: `step()` places one spatio-temporal patch (or, for a loop, one of the two
//! translated copies whose seam surface makes the transition) and reports it, like
//! `graphcut::Session` for images.
//!
//! Phases, in order:
//! - `loop` (7.A): copy A (the frames around the transition's end i), then copy B (the same
//!   frames around its start j, i.e. A translated by the loop length) along the optimal seam;
//! - `offsets` (7.B) and `extend` (7.C, 7.E): with k > 0 the constrained frames of 7.D first
//!   (the input's first k frames, at t = 0 and, identically, at t = T - k), then patches until
//!   every voxel is covered, then refinement patches over the worst seams; the first k frames
//!   are removed from what the caller sees.

use std::collections::HashSet;

use super::anatomy::{CostSlice, cost_slice};
use super::budget::WorkingSet;
use super::canvas::{Canvas, Patch, UNCOVERED};
use super::loop_band::{COPY_A, EXACT_PIXELS, place_second_copy};
use super::options::{Blend, Mode, Options, Placement};
use super::placement::{Allowed, Region, draw_offset, largest_search, region_around};
use super::seam::Placed;
use super::source::Source;
use super::synthesis::GraphSlice;
use super::synthesis::Synthesis;
use super::transition::{Transition, good_transitions, half_window};
use super::volume::Volume;
use crate::core::{Result, Rng};
use crate::methods::graphcut::cost::value_sigma;
use crate::solvers::fft_ssd::volume_search_bytes;

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// True once the session has nothing left to do (this step may still have placed a patch).
    pub done: bool,
    /// Number of the patch placed by this step (0-based), or None.
    pub patch: Option<usize>,
    /// Patches placed so far.
    pub patches: usize,
    /// The patch's offset in the output (output frames, after the removal of 7.D's first k).
    pub offset: (i32, i32, i32),
    /// Output voxels (pixels of all frames) the new patch took; 0 when none was placed.
    pub voxels_taken: usize,
    /// Cost of this placement's min cut (0 when no patch was placed).
    pub cut_cost: f64,
    /// Every output voxel covered.
    pub covered: bool,
    /// Fraction of the output covered, 0..1.
    pub coverage: f64,
    /// The output frame around which the loop closes: the centre of 7.A's seam window, the last
    /// frame for a 7.D loop (it is followed by frame 0); None while unknown or when not a loop.
    pub loop_frame: Option<usize>,
    /// 7.A: the transition this step seamed (the one kept, once done): its number among the
    /// good transitions (0 is the best by frame SSD), how many there are, and its loop length.
    pub transition: Option<(usize, usize, usize)>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    LoopA,
    LoopB,
    Constraint,
    Cover,
    Refine,
    Done,
}

/// A running video synthesis.
pub struct Session {
    options: Options,
    clip: Volume,
    synthesis: Synthesis,
    rng: Rng,
    sigma: f32,
    used: HashSet<Patch>,
    phase: Phase,
    transition: Option<Transition>,
    /// k of 7.D in effect (0 for loops and when off).
    fixed: usize,
    refinements: usize,
    last: Option<Event>,
    /// The last placement's cost slice, while the anatomy is recorded.
    last_costs: Option<CostSlice>,
    /// What the constructor checked against the memory budget.
    working_set: WorkingSet,
    /// 7.A: the transitions to seam, best first; `candidate` is the one being seamed.
    candidates: Vec<Transition>,
    candidate: usize,
    /// 7.A: the cheapest seam so far, with its canvas, its transition and that transition's
    /// number.
    best: Option<(Placed, Synthesis, Transition, usize)>,
    /// The canvas feathered across its seams, once done (with `blend: Feather`).
    feathered: Option<Volume>,
}

impl Session {
    /// Checks the options and the memory budget, finds the transition for a loop, and sets up
    /// the canvas. Fails with a named error on bad options or a video too large for the budget.
    pub fn new(clip: Volume, options: Options) -> Result<Session> {
        let input = (clip.width(), clip.height(), clip.frames());
        let size = options.output_size(input)?;
        // A feathered canvas (colours only: a quarter of a canvas voxel's bytes) is kept beside
        // the canvas.
        let feathered = |voxels: usize| match options.blend {
            Blend::Feather => voxels + voxels / 4,
            _ => voxels,
        };
        let plane = |w: usize, h: usize| w * h;
        let sigma = value_sigma(clip.data());
        let rng = Rng::new(options.seed);
        match options.mode {
            Mode::Loop => {
                let h = half_window(input.2, options.transition_window);
                let window = 2 * h + 1;
                // With several transitions the cheapest seam so far is kept beside the current.
                let copies = if options.transitions > 1 { 2 } else { 1 };
                let working_set = WorkingSet {
                    input_voxels: plane(input.0, input.1) * (input.2 + 2 * (window + 1) * copies),
                    output_voxels: feathered(
                        plane(input.0, input.1) * ((window + 1) * copies + input.2 / 4),
                    ),
                    patch_voxels: plane(input.0, input.1) * window,
                    search_bytes: 0,
                };
                working_set.check(input, input, options.memory_budget_mib)?;
                let candidates =
                    good_transitions(&clip, options.transition_window, options.transitions)?;
                let tr = candidates[0];
                let synthesis = loop_synthesis(&clip, tr, options.gradient_cost)?;
                Ok(Session {
                    candidates,
                    candidate: 0,
                    best: None,
                    feathered: None,
                    options,
                    clip,
                    synthesis,
                    rng,
                    sigma,
                    used: HashSet::new(),
                    phase: Phase::LoopA,
                    transition: Some(tr),
                    fixed: 0,
                    refinements: 0,
                    last: None,
                    last_costs: None,
                    working_set,
                })
            }
            Mode::Offsets | Mode::Extend => {
                let k = options.fixed();
                let total = size.2 + k;
                let search_bytes = if options.placement.is_matching() {
                    let side = region_side(input, (size.0, size.1, total), options.mode);
                    let whole = options.placement == Placement::EntirePatch;
                    let spatial = options.mode == Mode::Extend;
                    let (nx, ny, nz) = largest_search(whole, spatial, side, input);
                    volume_search_bytes(nx * ny * nz)
                } else {
                    0
                };
                let working_set = WorkingSet {
                    input_voxels: plane(input.0, input.1) * (input.2 + k),
                    output_voxels: feathered(plane(size.0, size.1) * total),
                    patch_voxels: plane(input.0, input.1) * input.2,
                    search_bytes,
                };
                working_set.check(input, size, options.memory_budget_mib)?;
                let mut sources = vec![Source::new(clip.clone())];
                if k > 0 {
                    sources.push(Source::new(clip.frames_range(0, k)?));
                }
                let canvas = Canvas::new(size.0, size.1, total)?;
                let synthesis = Synthesis::new(sources, canvas, options.gradient_cost);
                Ok(Session {
                    candidates: Vec::new(),
                    candidate: 0,
                    best: None,
                    feathered: None,
                    options,
                    clip,
                    synthesis,
                    rng,
                    sigma,
                    used: HashSet::new(),
                    phase: if k > 0 {
                        Phase::Constraint
                    } else {
                        Phase::Cover
                    },
                    transition: None,
                    fixed: k,
                    refinements: 0,
                    last: None,
                    last_costs: None,
                    working_set,
                })
            }
        }
    }

    /// The sources and the canvas (voxels, labels, seams) so far, in canvas frames (see
    /// [`Session::frame_origin`]).
    #[must_use]
    pub fn synthesis(&self) -> &Synthesis {
        &self.synthesis
    }

    /// The estimated working set the constructor checked against the memory budget.
    #[must_use]
    pub fn working_set(&self) -> WorkingSet {
        self.working_set
    }

    /// The options the session was built with.
    #[must_use]
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The input clip.
    #[must_use]
    pub fn clip(&self) -> &Volume {
        &self.clip
    }

    /// Whether the session has nothing left to do.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.phase == Phase::Done
    }

    /// The transition of a loop (7.A).
    #[must_use]
    pub fn transition(&self) -> Option<Transition> {
        self.transition
    }

    /// k of 7.D in effect.
    #[must_use]
    pub fn fixed_frames(&self) -> usize {
        self.fixed
    }

    /// The output size the caller sees (a loop's length for 7.A; without 7.D's first k frames).
    #[must_use]
    pub fn size(&self) -> (usize, usize, usize) {
        let (w, h, d) = self.synthesis.canvas.size();
        match self.transition {
            Some(tr) => (w, h, tr.period()),
            None => (w, h, d - self.fixed),
        }
    }

    /// Where output frame `t` comes from: a canvas frame, or (beyond a loop's seam window) a frame
    /// of the clip that copy B shows there.
    #[must_use]
    pub fn frame_origin(&self, t: usize) -> FrameOrigin {
        match self.transition {
            Some(tr) => {
                let window = 2 * tr.half_window + 1;
                if t < window {
                    FrameOrigin::Canvas(t + 1)
                } else {
                    FrameOrigin::Clip(tr.to - tr.half_window + t)
                }
            }
            None => FrameOrigin::Canvas(t + self.fixed),
        }
    }

    fn loop_frame(&self) -> Option<usize> {
        match self.transition {
            Some(tr) => Some(tr.half_window),
            None => (self.fixed > 0 && self.is_done()).then(|| self.size().2 - 1),
        }
    }

    /// Records (or stops recording) each placement's cost slice and graph slice for the page's
    /// placement anatomy (see `super::anatomy`); off by default.
    pub fn set_anatomy(&mut self, on: bool) {
        self.synthesis.record_anatomy = on;
        if !on {
            self.last_costs = None;
            self.synthesis.last_graph = None;
        }
    }

    /// The last placement's cost slice: recorded while the anatomy is on, for placements drawn
    /// by matching (7.C) over a region with covered voxels; random ones have no costs.
    #[must_use]
    pub fn placement_costs(&self) -> Option<&CostSlice> {
        self.last_costs.as_ref()
    }

    /// The last placement's graph slice (recorded while the anatomy is on).
    #[must_use]
    pub fn placement_graph(&self) -> Option<&GraphSlice> {
        self.synthesis.last_graph.as_ref()
    }

    /// The output frame (as events number them) of canvas frame `t`: a loop's canvas starts one
    /// frame early, 7.D's first k canvas frames are removed (negative: one of them).
    #[must_use]
    pub fn output_frame(&self, t: i64) -> i64 {
        if self.transition.is_some() {
            t - 1
        } else {
            t - self.fixed as i64
        }
    }

    /// Places one patch.
    pub fn step(&mut self) -> Result<Event> {
        if self.phase == Phase::Done {
            return Ok(self.last.expect("a finished session has stepped"));
        }
        // Each placement records its own anatomy (a random one has no cost surface).
        self.last_costs = None;
        self.synthesis.last_graph = None;
        // 7.A: the transition a second copy was just seamed for (the session moves on to the
        // next one in the same step).
        let mut seamed = None;
        let placed = match self.phase {
            Phase::LoopA => {
                let placed = self.synthesis.place(COPY_A, &[])?;
                self.phase = Phase::LoopB;
                Some(placed)
            }
            Phase::LoopB => {
                // Copy B: the clip translated by the loop length; its first frame is forced to
                // keep A (it borders A's first frame), its last one to take B (the clip goes on
                // from it after the window), so the seam surface runs through the window in
                // between. A reaches that last frame too, so a cut there costs both copies'
                // differences, as a cut anywhere else does, and the seam does not drift to it.
                let placed = place_second_copy(&mut self.synthesis, EXACT_PIXELS)?;
                seamed = self.transition_step();
                Some(self.next_transition(placed)?)
            }
            Phase::Constraint => self.step_constraint()?,
            Phase::Cover | Phase::Refine => self.step_patch()?,
            Phase::Done => unreachable!("handled above"),
        };
        if self.phase == Phase::Done && self.options.blend == Blend::Feather {
            self.feathered = Some(self.synthesis.feathered());
        }
        let canvas = &self.synthesis.canvas;
        let mut event = Event {
            done: self.phase == Phase::Done,
            patch: placed.map(|p| p.index),
            patches: canvas.patches.len(),
            offset: (0, 0, 0),
            voxels_taken: 0,
            cut_cost: 0.0,
            covered: canvas.is_covered(),
            coverage: canvas.covered as f64 / canvas.voxel_count() as f64,
            loop_frame: None,
            transition: None,
        };
        if let Some(p) = placed {
            let tt = self.output_frame(i64::from(p.patch.tt)) as i32;
            event.offset = (p.patch.tx, p.patch.ty, tt);
            event.voxels_taken = p.voxels_taken;
            event.cut_cost = p.cut_cost;
        }
        event.loop_frame = self.loop_frame();
        event.transition = seamed
            .filter(|_| !event.done)
            .or_else(|| self.transition_step());
        self.last = Some(event);
        Ok(event)
    }

    /// 7.A: the transition being seamed (the one kept, once done), as [`Event::transition`].
    fn transition_step(&self) -> Option<(usize, usize, usize)> {
        self.transition
            .map(|tr| (self.candidate, self.candidates.len(), tr.period()))
    }

    /// After a transition's seam (`placed`): keeps it if it is the cheapest so far and sets up
    /// the next transition's canvas, or, after the last, restores the cheapest and finishes.
    /// Returns the placement the step reports: this one, or the kept one once done.
    fn next_transition(&mut self, placed: Placed) -> Result<Placed> {
        let better = self
            .best
            .as_ref()
            .is_none_or(|(least, ..)| placed.cut_cost < least.cut_cost);
        let current = self.transition.expect("a loop has a transition");
        let watched = self.synthesis.record_anatomy;
        if let Some(&next) = self.candidates.get(self.candidate + 1) {
            let mut fresh = loop_synthesis(&self.clip, next, self.options.gradient_cost)?;
            fresh.record_anatomy = watched;
            let seamed = std::mem::replace(&mut self.synthesis, fresh);
            if better {
                self.best = Some((placed, seamed, current, self.candidate));
            }
            self.candidate += 1;
            self.transition = Some(next);
            self.phase = Phase::LoopA;
        } else {
            self.phase = Phase::Done;
            if let Some((kept_placed, kept, tr, number)) = self.best.take().filter(|_| !better) {
                self.synthesis = kept;
                self.synthesis.record_anatomy = watched;
                self.transition = Some(tr);
                self.candidate = number;
                return Ok(kept_placed);
            }
        }
        Ok(placed)
    }

    /// One patch of 7.D's constrained frames: the input's first k frames at t = 0 (anywhere in x
    /// and y when the frames are larger than the input's), and the identical cut repeated at
    /// t = T - k, so the last k frames equal the first k.
    fn step_constraint(&mut self) -> Result<Option<super::seam::Placed>> {
        let k = self.fixed;
        let s = &mut self.synthesis;
        let (w, h, total) = s.canvas.size();
        let first = s
            .first_uncovered()
            .expect("constraint frames are not covered yet");
        let spatial = self.options.mode == Mode::Extend;
        let side = if spatial {
            (
                self.clip.width().div_ceil(3),
                self.clip.height().div_ceil(3),
                k,
            )
        } else {
            (w, h, k)
        };
        let region = region_around(s.canvas.coords(first), side, (w, h, k));
        let allowed = Allowed {
            source: 1,
            spatial,
            tt: Some(0),
        };
        // The first one at the origin: the output starts with the input's own first k frames,
        // as the paper fixes them; larger frames are completed around them.
        let origin = Patch {
            source: 1,
            tx: 0,
            ty: 0,
            tt: 0,
        };
        let chosen = if s.canvas.patches.is_empty() {
            Some(origin)
        } else if self.options.placement.is_matching() {
            // Around the first patch the constrained frames are matched like any other patch
            // (7.C over the k frames).
            let k_sigma = (self.options.k, self.sigma);
            let search = (region, allowed, self.options.placement);
            let (chosen, costs) = matched_offset(s, search, &self.used, k_sigma, &mut self.rng)?;
            self.last_costs = costs;
            chosen
        } else {
            s.random_offset(region, allowed, &self.used, &mut self.rng)
        };
        let Some(patch) = chosen else {
            self.phase = Phase::Done;
            return Ok(None);
        };
        self.used.insert(patch);
        let placed = s.place(patch, &[])?;
        let shift = (total - k) * w * h;
        let mirror = Patch {
            tt: (total - k) as i32,
            ..patch
        };
        let taken: Vec<usize> = (0..k * w * h)
            .filter(|&i| s.canvas.label[i] == placed.index as u32)
            .map(|i| i + shift)
            .collect();
        let index = s.canvas.patches.len();
        s.canvas.patches.push(mirror);
        s.take(index, mirror, &taken);
        if s.first_uncovered().is_none_or(|i| i >= k * w * h) {
            for t in (0..k).chain(total - k..total) {
                s.canvas.fixed[t * w * h..(t + 1) * w * h].fill(true);
            }
            self.phase = if s.canvas.is_covered() {
                Phase::Refine
            } else {
                Phase::Cover
            };
        }
        Ok(Some(placed))
    }

    /// One patch while covering, or one refinement over the worst seams (section 3.2).
    fn step_patch(&mut self) -> Result<Option<super::seam::Placed>> {
        let input = (self.clip.width(), self.clip.height(), self.clip.frames());
        let s = &mut self.synthesis;
        let size = s.canvas.size();
        let side = region_side(input, size, self.options.mode);
        let (region, force): (Region, Vec<usize>) = match s.first_uncovered() {
            Some(first) => (
                region_around(s.canvas.coords(first), side, size),
                Vec::new(),
            ),
            None => {
                if self.refinements >= self.options.refinement_patches {
                    self.phase = Phase::Done;
                    return Ok(None);
                }
                let region = s.worst_region(side);
                let (x, y, t) = region.centre();
                let centre = (t * size.1 + y) * size.0 + x;
                let force = if s.canvas.fixed[centre] {
                    vec![]
                } else {
                    vec![centre]
                };
                (region, force)
            }
        };
        let allowed = Allowed {
            source: 0,
            spatial: self.options.mode == Mode::Extend,
            tt: None,
        };
        let chosen = match self.options.placement {
            Placement::Random if force.is_empty() && !s.canvas.is_covered() => {
                s.covering_offset(region, allowed, &self.used, &mut self.rng, COVERING_DRAWS)
            }
            Placement::Random => s.random_offset(region, allowed, &self.used, &mut self.rng),
            Placement::EntirePatch | Placement::SubPatch => {
                let k_sigma = (self.options.k, self.sigma);
                let search = (region, allowed, self.options.placement);
                let (chosen, costs) = matched_offset(s, search, &self.used, k_sigma, &mut self.rng)?;
                self.last_costs = costs;
                chosen
            }
        };
        let Some(patch) = chosen else {
            self.phase = Phase::Done;
            return Ok(None);
        };
        let refining = force.len() == 1 || s.canvas.is_covered();
        self.used.insert(patch);
        let placed = s.place(patch, &force)?;
        if refining {
            self.refinements += 1;
        }
        if s.canvas.is_covered() {
            self.phase = if self.refinements >= self.options.refinement_patches {
                Phase::Done
            } else {
                Phase::Refine
            };
        }
        Ok(Some(placed))
    }

    /// The colours of output frame `t` (RGB f32), feathered across seams once done when the
    /// options ask for it.
    #[must_use]
    pub fn frame(&self, t: usize) -> &[f32] {
        match self.frame_origin(t) {
            FrameOrigin::Canvas(f) => self
                .feathered
                .as_ref()
                .unwrap_or(&self.synthesis.canvas.pixels)
                .frame(f),
            FrameOrigin::Clip(f) => self.clip.frame(f),
        }
    }

    /// The patch label of every voxel of output frame `t` (`UNCOVERED` where none); beyond a
    /// loop's seam window every voxel shows copy B (label 1).
    #[must_use]
    pub fn frame_labels(&self, t: usize) -> Vec<u32> {
        let (w, h, _) = self.synthesis.canvas.size();
        match self.frame_origin(t) {
            FrameOrigin::Canvas(f) => {
                self.synthesis.canvas.label[f * w * h..(f + 1) * w * h].to_vec()
            }
            FrameOrigin::Clip(_) => {
                let label = if self.is_done() { 1 } else { UNCOVERED };
                vec![label; w * h]
            }
        }
    }
}

/// Random offsets drawn per covering step, of which the one bringing the most new voxels is
/// placed (see `Synthesis::covering_offset`).
const COVERING_DRAWS: usize = 8;

/// Where an output frame's colours live.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrameOrigin {
    Canvas(usize),
    Clip(usize),
}

/// The error region's size: a third of the input along each axis (the image version's default),
/// whole frames for temporal offsets (7.B), clamped to the output.
fn region_side(
    input: (usize, usize, usize),
    output: (usize, usize, usize),
    mode: Mode,
) -> (usize, usize, usize) {
    let third = |n: usize| n.div_ceil(3).max(1);
    let (x, y) = if mode == Mode::Extend {
        (third(input.0), third(input.1))
    } else {
        (input.0, input.1)
    };
    (
        x.min(output.0),
        y.min(output.1),
        third(input.2).min(output.2),
    )
}

/// A placement by matching (eq. 2 or 7.C's eq. 4, as `placement` says): every unused offset
/// allowed over `region` scored by its SSD with what is laid, one drawn by eq. 3 with `k_sigma`;
/// with the cost slice of the draw when `s` records its anatomy.
fn matched_offset(
    s: &Synthesis,
    (region, allowed, placement): (Region, Allowed, Placement),
    used: &HashSet<Patch>,
    k_sigma: (f32, f32),
    rng: &mut Rng,
) -> Result<(Option<Patch>, Option<CostSlice>)> {
    let whole = placement == Placement::EntirePatch;
    let scored = s.score_offsets(region, allowed, used, whole)?;
    let chosen = draw_offset(&scored, k_sigma, rng);
    let costs = s.record_anatomy.then(|| {
        let temperature = f64::from(k_sigma.0) * f64::from(k_sigma.1).powi(2);
        chosen.and_then(|p| cost_slice(&scored, p, allowed.spatial, temperature))
    });
    Ok((chosen, costs.flatten()))
}

/// 7.A's canvas and copies for transition `tr` of `clip`: copy A holds the clip's frames
/// i - h - 1 to i + h, copy B frames j - h to j + h (placed one frame later).
fn loop_synthesis(clip: &Volume, tr: Transition, gradient_cost: bool) -> Result<Synthesis> {
    let h = tr.half_window;
    let a = clip.frames_range(tr.from - h - 1, 2 * h + 2)?;
    let b = clip.frames_range(tr.to - h, 2 * h + 1)?;
    let canvas = Canvas::new(clip.width(), clip.height(), 2 * h + 2)?;
    Ok(Synthesis::new(
        vec![Source::new(a), Source::new(b)],
        canvas,
        gradient_cost,
    ))
}
