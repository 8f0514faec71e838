//! Flow-guided texture animation (Kwatra et al. 2005, section 4.1): the first frame by plain
//! texture optimisation, then frame by frame: warp the previous frame along the flow, use it both
//! as the start and as the soft-constraint target of eq. 3, and synthesise at one resolution with
//! Algorithm 2, the matches moved along the flow from the previous frame's.

use super::field::FlowField;
use super::memory::{METHOD, frames_working_set};
use super::options::{FlowOptions, FlowSource};
use super::setup::FrameSetup;
use crate::core::{Error, Image, Result, Rng};
use crate::methods::optimization::channel_weights::ChannelWeights;
use crate::methods::optimization::constraints::Constraint;
use crate::methods::optimization::iteration::{Iteration, Phase, StepBudget, Work};
use crate::methods::optimization::level::{LevelSetup, LevelSolver};
use crate::methods::optimization::schedule::Level;
use crate::methods::optimization::teaching::{self, Field};
use crate::methods::optimization::{self, EventKind};

/// PatchMatch sweeps per M-step within a frame: the matches arrive carried along the flow, so
/// two sweeps reach what three do (measured: gravel_128, 128x128 vortex, coherence and flow
/// energy within 2%), for less search time. Only the first sweep searches at random, so a third
/// sweep would only propagate.
const FRAME_PATCHMATCH_PASSES: usize = 2;

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlowEventKind {
    /// Part of an iteration: on large frames an iteration is split over several steps (see
    /// `SPLIT_PIXELS`), and setting up a frame (the
    /// warp, the matches moved along the flow) is a step of its own; the event names the phase
    /// and the share of the iteration done.
    Part,
    /// An EM iteration within a frame.
    Iteration,
    /// The iteration that finished a frame: render it now to keep it.
    Frame,
    /// The last frame is finished.
    Done,
}

/// The report of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowEvent {
    /// What the step did; [`FlowEventKind::Done`] on the last step and any after it.
    pub kind: FlowEventKind,
    /// The frame worked on, 0-based.
    pub frame: usize,
    /// Iteration within the frame, 1-based.
    pub iteration: usize,
    /// Neighbourhood width of this iteration.
    pub size: usize,
    /// Texture energy of this iteration (normalised as in the optimisation session).
    pub texture_energy: f64,
    /// Flow energy: mean squared difference per value between the frame and the previous frame
    /// carried along the flow, over the pixels whose source lies inside (0 for the first frame).
    pub flow_energy: f64,
    /// Matches that changed in this iteration's M-step.
    pub changed: usize,
    /// Whole iterations so far over all frames, frame 0's levels included (parts not counted).
    pub total_iterations: usize,
    /// With [`FlowEventKind::Part`]: the phase the step stopped in and the share (0 to 1) of
    /// the iteration's work done; a whole iteration reports its last phase and 1.
    pub phase: Phase,
    /// Share of the iteration's work done, 0 to 1 (1 for a whole iteration).
    pub progress: f64,
}

/// The energies a finished frame ended with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameEnergy {
    pub texture: f64,
    pub flow: f64,
}

/// A running flow animation.
pub struct FlowSession {
    options: FlowOptions,
    flow: FlowSource,
    exemplar: Image,
    /// The synthesis of frame 0, while it runs.
    first: Option<optimization::Session>,
    /// One level per frame neighbourhood size, largest first; they live across frames so that
    /// matches carry along the flow.
    solvers: Vec<LevelSolver>,
    rng: Rng,
    frame: usize,
    size_index: usize,
    iteration: usize,
    /// Whether the current frame's warp and constraint are set up.
    begun: bool,
    /// The current frame's set-up while it runs over several steps.
    setup: Option<FrameSetup>,
    /// True until the first M-step of a (frame, size) ran on the warped start.
    fresh: bool,
    /// The iteration under way, and how long a step works.
    run: Iteration,
    budget: StepBudget,
    /// The frame being made (or the last one made).
    current: Option<Image>,
    /// The last finished frame.
    previous: Option<Image>,
    /// The previous frame warped along the flow, with its mask: eq. 3 as a soft constraint.
    constraint: Option<Constraint>,
    /// The naive baseline of Fig. 7: frame 0 warped along the flow, frame after frame.
    naive: Option<Image>,
    /// The index in `solvers` of the level solver the last frame step iterated (None before a
    /// frame after the first has iterated): whose grid and matches the step anatomy shows.
    iterated: Option<usize>,
    field: Option<FlowField>,
    history: Vec<FrameEnergy>,
    total_iterations: usize,
    last: Option<FlowEvent>,
}

impl FlowSession {
    /// Validates the options, the exemplar and the flow fields' sizes.
    pub fn new(exemplar: &Image, flow: FlowSource, options: FlowOptions) -> Result<Self> {
        options.validate(exemplar.width(), exemplar.height())?;
        if let FlowSource::Fields(fields) = &flow {
            if fields.is_empty() {
                return Err(Error::InvalidParameter {
                    name: "flow",
                    reason: "needs at least one field".into(),
                });
            }
            let (w, h) = (options.output_width, options.output_height);
            if let Some(f) = fields.iter().find(|f| (f.width(), f.height()) != (w, h)) {
                return Err(Error::InvalidSize {
                    what: "flow field",
                    width: f.width(),
                    height: f.height(),
                    reason: format!("must match the frame size {w}x{h}"),
                });
            }
        }
        // The budget is checked before anything of the output's size is allocated: frame 0's
        // synthesis checks its own, the later frames' is checked here.
        let fields = match &flow {
            FlowSource::Fields(f) => f.len(),
            FlowSource::Generator(_) => 0,
        };
        let (w, h) = (options.output_width, options.output_height);
        frames_working_set(
            &options,
            exemplar.channels(),
            fields,
            exemplar.pixel_count(),
        )
        .check(
            &format!("frames {w}x{h}"),
            METHOD,
            options.memory_budget_mib,
        )?;
        let first = optimization::Session::new(exemplar, options.first_frame())?;
        let sizes = options.fitting_frame_sizes(exemplar.width(), exemplar.height());
        let mut rng = Rng::new(options.seed ^ 0x5eed_f10e);
        let solvers = sizes
            .iter()
            .map(|&size| {
                let setup = LevelSetup {
                    output_width: options.output_width,
                    output_height: options.output_height,
                    size,
                    spacing: (size / 4).max(1),
                    search: options.search,
                    r: options.r,
                    mu: 0.0,
                    search_mu: 0.0,
                    wrap: options.tileable,
                    passes: FRAME_PATCHMATCH_PASSES,
                    completeness: 0.0,
                    histogram_matching: options.histogram_matching,
                    match_constrained: true,
                    energy: crate::methods::optimization::Energy::Pixels,
                    wavelet_detail_weight: 0.0,
                    channel_weights: ChannelWeights::default(),
                };
                if options.sub_pixel {
                    LevelSolver::with_sub_pixel_matches(exemplar, setup, &mut rng)
                } else {
                    LevelSolver::new(exemplar, setup, &mut rng)
                }
            })
            .collect();
        let budget = StepBudget::for_pixels(options.output_width * options.output_height);
        Ok(FlowSession {
            exemplar: exemplar.clone(),
            first: Some(first),
            solvers,
            rng,
            flow,
            options,
            frame: 0,
            size_index: 0,
            iteration: 0,
            begun: false,
            setup: None,
            fresh: false,
            run: Iteration::default(),
            budget,
            current: None,
            previous: None,
            constraint: None,
            naive: None,
            iterated: None,
            field: None,
            history: Vec::new(),
            total_iterations: 0,
            last: None,
        })
    }

    /// The estimated working set: the larger of frame 0's synthesis and the later frames'
    /// (see `super::memory`).
    #[must_use]
    pub fn working_set(&self) -> crate::core::budget::WorkingSet {
        let fields = match &self.flow {
            FlowSource::Fields(f) => f.len(),
            FlowSource::Generator(_) => 0,
        };
        let frames = frames_working_set(
            &self.options,
            self.exemplar.channels(),
            fields,
            self.exemplar.pixel_count(),
        );
        let e = &self.exemplar;
        let opts = self.options.first_frame();
        let first = optimization::schedule::plan(e.width(), e.height(), &opts).map(|levels| {
            optimization::memory::working_set(
                &opts,
                &levels,
                (e.width(), e.height(), e.channels()),
                false,
            )
        });
        match first {
            Ok(first) if first.bytes() > frames.bytes() => first,
            _ => frames,
        }
    }

    /// The options the animation was built with.
    #[must_use]
    pub fn options(&self) -> &FlowOptions {
        &self.options
    }

    /// Whether every frame is finished.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.frame >= self.options.frames
    }

    /// The frame being made, at full size (before the first frame is finished, the first
    /// synthesis's current state up-sampled).
    pub fn frame_image(&self) -> Result<Image> {
        match (&self.current, &self.first) {
            (Some(img), _) => Ok(img.clone()),
            (None, Some(first)) => first.output_full_size(),
            (None, None) => unreachable!("the first synthesis runs until a frame exists"),
        }
    }

    /// The naive warp of frame 0 to the current frame (frame 0 itself until it is finished).
    pub fn naive_image(&self) -> Result<Image> {
        match &self.naive {
            Some(img) => Ok(img.clone()),
            None => self.frame_image(),
        }
    }

    /// The field that carried the previous frame into the current one (None for frame 0).
    #[must_use]
    pub fn current_field(&self) -> Option<&FlowField> {
        self.field.as_ref()
    }

    /// The field f_t of this animation's flow.
    pub fn field_at(&self, t: usize) -> Result<FlowField> {
        self.flow
            .field(self.options.output_width, self.options.output_height, t)
    }

    /// The energies of the finished frames, in order.
    #[must_use]
    pub fn history(&self) -> &[FrameEnergy] {
        &self.history
    }

    /// Index of the frame being made (the number of finished frames).
    #[must_use]
    pub fn frame(&self) -> usize {
        self.frame
    }

    /// Sets whether iterations split over steps and how long such a step works (None: whole
    /// iterations; the default splits frames larger than
    /// `SPLIT_PIXELS`), and the work between looks at
    /// the clock, for frame 0's synthesis too. Where iterations split changes no output.
    pub fn set_step_budget(&mut self, milliseconds: Option<f64>, chunk_work: usize) {
        // The step anatomy's halves are a separate switch: a new budget keeps it.
        self.budget = StepBudget {
            halves: self.budget.halves,
            ..StepBudget::new(milliseconds, chunk_work)
        };
        if let Some(first) = &mut self.first {
            first.set_step_budget(milliseconds, chunk_work);
        }
    }

    /// Makes every step end after one half of an EM iteration (the page's step anatomy, as
    /// [`optimization::Session::set_half_steps`]): frame 0's synthesis and every later frame
    /// stop after the first M-step on the warped start, after each E-step and after each M-step.
    /// No output changes.
    pub fn set_half_steps(&mut self, on: bool) {
        self.budget.halves = on;
        if let Some(first) = &mut self.first {
            first.set_half_steps(on);
        }
    }

    /// The neighbourhood grid X-dagger and matches z_p of the level solver the last step
    /// iterated, with that solver (for its distances): frame 0's current level while it runs,
    /// then the frame level last iterated. None before the first step, and from the step that
    /// finishes frame 0 until frame 1 iterates (frame 0's levels are gone, the frame levels not
    /// yet matched).
    #[must_use]
    pub fn anatomy_field(&self) -> Option<(Field<'_>, &LevelSolver)> {
        if let Some(first) = &self.first {
            return Some((teaching::field(first)?, first.level_solver()?));
        }
        let solver = &self.solvers[self.iterated?];
        let setup = solver.setup();
        let (columns, rows) = solver.grid();
        let level = Level {
            octave: 0,
            output_width: setup.output_width,
            output_height: setup.output_height,
            exemplar_width: self.exemplar.width(),
            exemplar_height: self.exemplar.height(),
            size: setup.size,
            spacing: setup.spacing,
        };
        let field = Field {
            level,
            columns,
            rows,
            matches: solver.matches(),
        };
        Some((field, solver))
    }

    /// The previous frame carried along the flow: the target of eq. 3's soft constraint and the
    /// start of the current frame's synthesis, with its mask (1 where the warp's source lies
    /// inside the frame). None during frame 0, which has no previous frame.
    #[must_use]
    pub fn warped_previous(&self) -> Option<&Constraint> {
        self.constraint.as_ref()
    }

    /// Runs one EM iteration and reports it; on a large frame, part of one (the event's kind
    /// is then [`FlowEventKind::Part`]).
    pub fn step(&mut self) -> Result<FlowEvent> {
        if self.is_done() {
            let mut last = self.last.expect("a finished animation has stepped");
            last.kind = FlowEventKind::Done;
            return Ok(last);
        }
        let event = if self.first.is_some() {
            self.step_first()?
        } else {
            self.step_frame()?
        };
        if event.kind != FlowEventKind::Part {
            self.total_iterations += 1;
        }
        let event = FlowEvent {
            total_iterations: self.total_iterations,
            kind: if event.kind == FlowEventKind::Frame && self.is_done() {
                FlowEventKind::Done
            } else {
                event.kind
            },
            ..event
        };
        self.last = Some(event);
        Ok(event)
    }

    /// One iteration (or part of one) of frame 0's multi-level synthesis.
    fn step_first(&mut self) -> Result<FlowEvent> {
        let first = self.first.as_mut().expect("frame 0 is running");
        let e = first.step()?;
        let mut event = FlowEvent {
            kind: if e.kind == EventKind::Part {
                FlowEventKind::Part
            } else {
                FlowEventKind::Iteration
            },
            frame: 0,
            iteration: e.total_iterations,
            size: e.size,
            texture_energy: e.energy,
            flow_energy: 0.0,
            changed: e.changed,
            total_iterations: 0,
            phase: e.phase,
            progress: e.progress,
        };
        if e.kind == EventKind::Done {
            let frame = first.output_full_size()?;
            // The frame levels start from the finest level's matches.
            if let Some(last) = first.level_solver() {
                for solver in &mut self.solvers {
                    solver.carry_from(last, |x, y| (x, y), (1.0, 1.0));
                }
            }
            self.first = None;
            self.finish_frame(frame, e.energy, 0.0);
            event.kind = FlowEventKind::Frame;
        }
        Ok(event)
    }

    /// Stores a finished frame and moves on to the next.
    fn finish_frame(&mut self, frame: Image, texture: f64, flow: f64) {
        if self.naive.is_none() {
            self.naive = Some(frame.clone());
        }
        self.history.push(FrameEnergy { texture, flow });
        self.current = Some(frame.clone());
        self.previous = Some(frame);
        self.frame += 1;
        self.size_index = 0;
        self.iteration = 0;
        self.begun = false;
    }

    /// Sets the current frame up, or part of it on a large frame: warps the previous frame
    /// (and the naive baseline) along f_{t-1} and moves every level's matches along it; once
    /// done, sets the constraint. Returns whether it is done.
    fn begin_frame(&mut self) -> Result<bool> {
        let started = crate::core::clock::now_ms();
        let previous = self.previous.as_ref().expect("a frame is finished");
        let naive = self.naive.as_ref().expect("frame 0 is the naive start");
        let setup = match &mut self.setup {
            Some(setup) => setup,
            None => {
                let field = self.field_at(self.frame - 1)?;
                let setup = FrameSetup::new(field, previous, naive, self.options.tileable)?;
                self.setup.insert(setup)
            }
        };
        // The field and the set-up's buffers count against the step's time too.
        let left = self
            .budget
            .split
            .map(|ms| (ms - (crate::core::clock::now_ms() - started)).max(0.0));
        if !setup.advance(previous, naive, &mut self.solvers, left) {
            return Ok(false);
        }
        let start = self.setup.take().expect("set up above").finish();
        self.naive = Some(start.naive);
        self.current = Some(start.previous.image.clone());
        self.constraint = Some(Constraint {
            target: start.previous.image,
            mask: start.previous.inside,
            lambda: self.options.lambda,
        });
        self.field = Some(start.field);
        self.begun = true;
        self.fresh = true;
        Ok(true)
    }

    /// One iteration of Algorithm 2 on the current frame at the current neighbourhood size, or
    /// part of one on a large frame (where setting the frame up is a step of its own).
    fn step_frame(&mut self) -> Result<FlowEvent> {
        if !self.begun {
            // On a large frame the set-up takes a step or more of its own.
            if !self.begin_frame()? || self.budget.split.is_some() {
                return Ok(self.part_event());
            }
        }
        self.iterated = Some(self.size_index);
        let solver = &mut self.solvers[self.size_index];
        let output = self.current.as_mut().expect("frame begun");
        if self.run.idle() {
            // The last iteration at a size ends with the E-step's frame: its M-step would only
            // find matches for the next frame, whose first M-step searches anyway after moving
            // them along the flow, so it measures them instead (a search costs several
            // distances a node, a measure one).
            let last = self.iteration + 1 >= self.options.frame_iterations;
            self.run
                .begin(solver, output, std::mem::take(&mut self.fresh), last);
        }
        let work = Work {
            solver,
            exemplar: &self.exemplar,
            output,
            constraint: self.constraint.as_ref(),
            rng: &mut self.rng,
        };
        let Some(changed) = self.run.advance(work, self.budget) else {
            return Ok(self.part_event());
        };
        self.iteration += 1;
        let solver = &self.solvers[self.size_index];
        let texture_energy = solver.energy();
        let output = self.current.as_ref().expect("frame begun");
        let flow_energy = self.constraint.as_ref().map_or(0.0, |c| c.energy(output));
        let mut event = FlowEvent {
            kind: FlowEventKind::Iteration,
            frame: self.frame,
            iteration: self.size_index * self.options.frame_iterations + self.iteration,
            size: solver.setup().size,
            texture_energy,
            flow_energy,
            changed,
            total_iterations: 0,
            // A measuring iteration ended with its E-step (its M-step searched nothing).
            phase: if self.run.measure_only {
                Phase::EStep
            } else {
                Phase::MStep
            },
            progress: 1.0,
        };
        if changed == 0 || self.iteration >= self.options.frame_iterations {
            self.size_index += 1;
            self.iteration = 0;
            self.fresh = true;
            if self.size_index == self.solvers.len() {
                let frame = self.current.clone().expect("frame made");
                self.finish_frame(frame, texture_energy, flow_energy);
                event.kind = FlowEventKind::Frame;
            }
        }
        Ok(event)
    }

    /// The report of a step that stopped inside an iteration of a frame after the first: the
    /// last figures, the phase and the share of the iteration done.
    fn part_event(&self) -> FlowEvent {
        let solver = &self.solvers[self.size_index];
        let pixels = self.options.output_width * self.options.output_height;
        // A step that completed a half (step anatomy) reports that half whole, with the shares
        // the optimisation session gives it.
        let (phase, progress) = match self.run.completed {
            Some(Phase::FirstMatch) => (Phase::FirstMatch, 0.2),
            Some(Phase::EStep) => (Phase::EStep, 0.4),
            _ => self.run.progress(solver, pixels),
        };
        let last = self.last.expect("frame 0 stepped before");
        FlowEvent {
            kind: FlowEventKind::Part,
            frame: self.frame,
            iteration: self.size_index * self.options.frame_iterations + self.iteration + 1,
            size: solver.setup().size,
            changed: 0,
            phase,
            progress,
            ..last
        }
    }
}
