//! The texture-optimisation session (Kwatra et al. 2005, Algorithm 1 with sections 3.1 and 3.2):
//! a state machine whose `step()` runs one EM iteration of the planned schedule.

mod guides;
mod inputs;
mod maps;
mod several;

use super::channel_weights::ChannelWeights;
use super::constraints::{Constraint, SoftConstraints};

use super::e_step::edge;
use super::exemplars::Several;
use super::guides::Guides;
use super::exclusion::exclusion_table;
use super::histogram::SortedChannels;
use super::initial::{Start, graphcut_start_options, random_patches};
pub use super::iteration::Phase;
use super::iteration::{Iteration, StepBudget, Work};
use super::level::{LevelSetup, LevelSolver, fit_output};
use super::m_step::PATCHMATCH_PASSES;
use super::memory::{METHOD, working_set};
use super::options::{Energy, Options};
use super::schedule::{Level, plan};
use crate::core::budget::WorkingSet;
use crate::core::pyramid::gaussian_pyramid;
use crate::core::sample::{resize_bilinear, shrink_area};
use crate::core::{Edge, Error, Image, Result, Rng};
use crate::methods::graphcut;
use crate::solvers::nn::Pos;

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// Part of an iteration: on large outputs an iteration is split over several steps (see
    /// `SPLIT_PIXELS`); the event names the phase and the share of the iteration done.
    Part,
    /// The first iteration of a new level (resolution or neighbourhood size changed).
    Level,
    /// Another iteration within the level.
    Iteration,
    /// The schedule is finished (this step ran its last iteration, or nothing is left).
    Done,
}

/// The report of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// What the step did; [`EventKind::Done`] on the last step and any after it.
    pub kind: EventKind,
    /// Index of the synthesis level in the schedule, 0-based.
    pub level: usize,
    /// Levels in the schedule.
    pub level_count: usize,
    /// Resolution index: 0 is full resolution, k is down-sampled k times (1/2^k).
    pub octave: usize,
    /// Neighbourhood width w of the level, in pixels.
    pub size: usize,
    /// Iteration within the level, 1-based.
    pub iteration: usize,
    /// Texture energy sum_p ||x_p - z_p||^r, normalised by the number of neighbourhoods and the
    /// pixels in each (so levels compare, as in the paper's Fig. 3). Always the pixel term, with
    /// a wavelet energy too, so that runs with different energies compare on one plot.
    pub energy: f64,
    /// The energy the M-step minimised, normalised the same way: with a wavelet energy the pixel
    /// term plus the weighted wavelet term (eq. 4 of Shen et al. 2009), else equal to `energy`.
    pub match_energy: f64,
    /// Matches z_p that changed in this iteration's M-step.
    pub changed: usize,
    /// Total EM iterations so far.
    pub total_iterations: usize,
    /// Conjugate-gradient iterations of this step's gradient-energy solve (0 when mu = 0); it
    /// stops at a relative residual of `CG_TOLERANCE`.
    pub solver_iterations: usize,
    /// With [`EventKind::Part`]: the phase the step stopped in and the share (0 to 1) of the
    /// iteration's work done; a whole iteration reports its last phase and 1.
    pub phase: Phase,
    /// Share of the iteration's work done, 0 to 1 (1 for a whole iteration).
    pub progress: f64,
}

/// One point of the energy history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyPoint {
    pub level: usize,
    pub energy: f64,
}

/// A running texture optimisation.
pub struct Session {
    options: Options,
    levels: Vec<Level>,
    /// Exemplar Gaussian pyramid, index = octave.
    exemplars: Vec<Image>,
    rng: Rng,
    level: usize,
    iteration: usize,
    output: Option<Image>,
    /// The level being worked on, once entered.
    solver: Option<LevelSolver>,
    /// Which level `solver` is for.
    entered: Option<usize>,
    /// True until the first M-step of a level ran on the up-sampled output.
    fresh: bool,
    /// Soft constraints at full resolution, and their copy at the current level's size.
    constraints: Option<SoftConstraints>,
    constraint: Option<Constraint>,
    history: Vec<EnergyPoint>,
    last: Option<Event>,
    /// The iteration under way.
    run: Iteration,
    /// The iteration under way is its level's first since the level was entered.
    new_level: bool,
    /// How long a step works (see [`StepBudget`]).
    budget: StepBudget,
    /// The graph-cut start of the coarsest level while it is being made (see
    /// [`super::initial`]); a large one takes several steps.
    start: Option<graphcut::Session>,
    /// The graph-cut start's working set, when the options ask for one: it is live before any
    /// level's buffers are, so the session's peak is the larger of the two.
    start_set: Option<WorkingSet>,
    /// A start the caller gave at the output's size ([`Session::start_from`]), used instead of
    /// the options' start.
    given_start: Option<Image>,
    /// Exemplar pixels no match may use ([`Session::exclude_exemplar`]), full resolution.
    excluded: Option<Vec<bool>>,
    /// Whether histogram matching takes the constraint's fully held pixels as its reference
    /// ([`Session::match_histogram_to_constraint`]).
    histogram_to_constraint: bool,
    /// With several exemplars ([`Session::with_exemplars`]): the stack and each one's pyramid.
    several: Option<Several>,
    /// Source and target guides ([`Session::set_guides`]).
    guides: Option<Guides>,
    /// The options' channel weights, checked against the exemplar's channels.
    channel_weights: ChannelWeights,
}

impl Session {
    /// Validates the options against the exemplar and plans the schedule.
    pub fn new(exemplar: &Image, options: Options) -> Result<Session> {
        options.validate(exemplar.width(), exemplar.height())?;
        let levels = plan(exemplar.width(), exemplar.height(), &options)?;
        Self::build(exemplar, options, levels)
    }

    /// A session over `exemplar` with the schedule `levels`, the options checked.
    fn build(exemplar: &Image, options: Options, levels: Vec<Level>) -> Result<Session> {
        let dims = (exemplar.width(), exemplar.height(), exemplar.channels());
        let (w, h) = (options.output_width, options.output_height);
        working_set(&options, &levels, dims, false).check(
            &format!("output {w}x{h}"),
            METHOD,
            options.memory_budget_mib,
        )?;
        let octaves = levels.iter().map(|l| l.octave).max().unwrap_or(0) + 1;
        let exemplars = gaussian_pyramid(exemplar, octaves, Edge::Clamp)?;
        let start_set = match options.start {
            Start::Patches => None,
            Start::Graphcut => {
                let first = levels[0];
                let start = graphcut_start_options(
                    first.output_width,
                    first.output_height,
                    options.tileable,
                    options.memory_budget_mib,
                    &mut Rng::new(0),
                );
                let set = graphcut::synthesis::estimate(&exemplars[first.octave], &start)?;
                set.check(
                    &format!("output {w}x{h} (its graph-cut start)"),
                    METHOD,
                    options.memory_budget_mib,
                )?;
                Some(set)
            }
        };
        Ok(Session {
            channel_weights: ChannelWeights::new(&options.channel_weights, exemplar.channels())?,
            start: None,
            start_set,
            given_start: None,
            excluded: None,
            histogram_to_constraint: false,
            several: None,
            guides: None,
            run: Iteration::default(),
            new_level: false,
            budget: StepBudget::for_pixels(options.output_width * options.output_height),
            rng: Rng::new(options.seed),
            options,
            levels,
            exemplars,
            level: 0,
            iteration: 0,
            output: None,
            solver: None,
            entered: None,
            fresh: false,
            constraints: None,
            constraint: None,
            history: Vec::new(),
            last: None,
        })
    }

    /// Sets (or with `None` removes) the soft constraints of Algorithm 2. The target must have
    /// the output's size and the exemplar's channel count. They apply from the next step; a
    /// finished session reopens its finest level for another round of iterations, so that
    /// painting on a finished output makes the synthesis follow.
    pub fn set_constraints(&mut self, constraints: Option<SoftConstraints>) -> Result<()> {
        if constraints.is_some() && self.options.energy != Energy::Pixels {
            // The constraint weighs output pixels one by one; a wavelet coefficient mixes a
            // whole block of them, so the weights have no counterpart in the wavelet term.
            return Err(Error::InvalidParameter {
                name: "energy",
                reason: format!(
                    "soft constraints need energy 'pixels', not '{}'",
                    self.options.energy.name()
                ),
            });
        }
        if let Some(c) = &constraints {
            let (w, h) = (self.options.output_width, self.options.output_height);
            if (c.target.width(), c.target.height()) != (w, h) {
                return Err(Error::InvalidSize {
                    what: "constraint target",
                    width: c.target.width(),
                    height: c.target.height(),
                    reason: format!("must match the output size {w}x{h}"),
                });
            }
            if c.target.channels() != self.exemplars[0].channels() {
                return Err(Error::InvalidParameter {
                    name: "target",
                    reason: format!(
                        "has {} channels, the exemplar {}",
                        c.target.channels(),
                        self.exemplars[0].channels()
                    ),
                });
            }
        }
        if constraints.is_some() {
            let (w, h) = (self.options.output_width, self.options.output_height);
            self.working_set(true).check(
                &format!("output {w}x{h} with soft constraints"),
                METHOD,
                self.options.memory_budget_mib,
            )?;
        }
        self.constraints = constraints;
        self.constraint = self.level_constraint();
        if self.is_done() && self.entered.is_some() {
            self.level = self.levels.len() - 1;
            self.iteration = 0;
        }
        Ok(())
    }

    /// Sets whether iterations split over steps and how long such a step works (None: whole
    /// iterations; see `SPLIT_PIXELS` for the default), and the work between looks at the
    /// clock (see `CHUNK_WORK`). Where iterations split
    /// changes no output.
    pub fn set_step_budget(&mut self, milliseconds: Option<f64>, chunk_work: usize) {
        self.budget = StepBudget {
            halves: self.budget.halves,
            ..StepBudget::new(milliseconds, chunk_work)
        };
    }

    /// The estimated working set (see `super::memory`), with or without soft constraints.
    #[must_use]
    pub fn working_set(&self, constraints: bool) -> crate::core::budget::WorkingSet {
        let e = &self.exemplars[0];
        let levels = working_set(
            &self.options,
            &self.levels,
            (e.width(), e.height(), e.channels()),
            constraints,
        );
        match &self.start_set {
            Some(start) if start.bytes() > levels.bytes() => start.clone(),
            _ => levels,
        }
    }

    /// Channels of the exemplar (and of the output and of constraint targets).
    #[must_use]
    pub fn exemplar_channels(&self) -> usize {
        self.exemplars[0].channels()
    }

    /// The soft constraints at full output resolution, as given (None when there are none).
    #[must_use]
    pub fn constraints(&self) -> Option<&SoftConstraints> {
        self.constraints.as_ref()
    }

    /// The constraint at the entered level's resolution.
    fn level_constraint(&self) -> Option<Constraint> {
        let lv = self.levels[self.entered?];
        let c = self.constraints.as_ref()?;
        Some(c.at_size(lv.output_width, lv.output_height))
    }

    /// The options the session was built with.
    #[must_use]
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The levels of the schedule, coarsest first.
    #[must_use]
    pub fn schedule(&self) -> &[Level] {
        &self.levels
    }

    /// Whether every level of the schedule is finished.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.level >= self.levels.len()
    }

    /// The texture energy of every whole iteration so far, with its level, in order.
    #[must_use]
    pub fn history(&self) -> &[EnergyPoint] {
        &self.history
    }

    /// The current output at the current level's resolution (None before the first step).
    #[must_use]
    pub fn output(&self) -> Option<&Image> {
        self.output.as_ref()
    }

    /// The level being (or last) worked on.
    #[must_use]
    pub fn current_level(&self) -> &Level {
        &self.levels[self.level.min(self.levels.len() - 1)]
    }

    /// The neighbourhood grid and its matches: (column corners, row corners, z_p per node).
    #[must_use]
    pub fn matches(&self) -> Option<(&[usize], &[usize], &[Pos])> {
        self.solver.as_ref().map(|s| {
            let (cols, rows) = s.grid();
            (cols, rows, s.matches())
        })
    }

    /// The index of the level whose solver is current (the last one entered).
    #[must_use]
    pub fn solver_level(&self) -> Option<usize> {
        self.entered
    }

    /// The level's solver (grid, matches, search), once a level is entered.
    #[must_use]
    pub fn level_solver(&self) -> Option<&LevelSolver> {
        self.solver.as_ref()
    }

    /// The current output up-sampled to the full output size (coarse levels look blocky-smooth).
    pub fn output_full_size(&self) -> Result<Image> {
        let (w, h) = (self.options.output_width, self.options.output_height);
        match &self.output {
            Some(out) if out.width() == w && out.height() == h => Ok(out.clone()),
            Some(out) => resize_bilinear(out, w, h, edge(self.options.tileable)),
            // A large start takes several steps: its canvas so far (black where uncovered).
            None => match &self.start {
                Some(cut) => resize_bilinear(&cut.output()?, w, h, edge(self.options.tileable)),
                None => Image::new(w, h, self.exemplars[0].channels()),
            },
        }
    }

    /// Makes every step end after one half of an EM iteration (the page's step anatomy: the
    /// output after the E-step, then the matches after the M-step), or whole iterations again.
    /// A part event then names the half it completed; no output changes.
    pub fn set_half_steps(&mut self, on: bool) {
        self.budget.halves = on;
    }

    /// Runs one EM iteration and reports it; on a large output, part of one (see
    /// `SPLIT_PIXELS`; the event's kind is then [`EventKind::Part`]).
    pub fn step(&mut self) -> Result<Event> {
        if self.is_done() {
            let mut last = self.last.expect("a finished session has stepped");
            last.kind = EventKind::Done;
            return Ok(last);
        }
        let entering = self.entered != Some(self.level);
        if entering {
            self.enter_level()?;
        }
        let Some(changed) = self.advance(entering)? else {
            return Ok(self.part_event());
        };
        let kind = if std::mem::take(&mut self.new_level) {
            EventKind::Level
        } else {
            EventKind::Iteration
        };
        self.iteration += 1;
        let solver = self.solver.as_ref().expect("level entered");
        // Without a wavelet energy the two are one sum (a power per node), so it is taken once.
        let (energy, match_energy) = if solver.has_wavelet() {
            (solver.energy(), solver.match_energy())
        } else {
            let energy = solver.energy();
            (energy, energy)
        };
        let level = self.level;
        self.history.push(EnergyPoint { level, energy });
        let lv = self.levels[level];
        let mut event = Event {
            kind,
            level,
            level_count: self.levels.len(),
            octave: lv.octave,
            size: lv.size,
            iteration: self.iteration,
            energy,
            match_energy,
            changed,
            total_iterations: self.history.len(),
            solver_iterations: self.run.solver_iterations,
            phase: Phase::MStep,
            progress: 1.0,
        };
        // Converged: no match changed (Algorithm 1's test), or the cap is reached.
        if changed == 0 || self.iteration >= self.options.iterations {
            self.level += 1;
            self.iteration = 0;
            if self.is_done() {
                event.kind = EventKind::Done;
            }
        }
        self.last = Some(event);
        Ok(event)
    }

    /// The report of a step that stopped inside an iteration: the level's figures so far,
    /// the phase and the share of the iteration done (the first M-step of a level, the E-step
    /// and the M-step weigh 1 : 1 : 3 per node visit, roughly their costs).
    fn part_event(&self) -> Event {
        let lv = self.levels[self.level];
        let solver = self.solver.as_ref().expect("level entered");
        // A step that completed a half (step anatomy) reports that half, whole.
        let (phase, progress) = match self.run.completed {
            _ if self.start.is_some() => (Phase::Start, 0.0),
            Some(Phase::FirstMatch) => (Phase::FirstMatch, 0.2),
            Some(Phase::EStep) => (Phase::EStep, 0.4),
            _ => self
                .run
                .progress(solver, lv.output_width * lv.output_height),
        };
        let (energy, match_energy, total) = match self.last {
            Some(e) => (e.energy, e.match_energy, e.total_iterations),
            None => (f64::NAN, f64::NAN, 0),
        };
        Event {
            kind: EventKind::Part,
            level: self.level,
            level_count: self.levels.len(),
            octave: lv.octave,
            size: lv.size,
            iteration: self.iteration + 1,
            energy: if solver.m_step_fraction().is_some() || self.iteration > 0 {
                energy
            } else {
                f64::NAN
            },
            match_energy,
            changed: 0,
            total_iterations: total,
            solver_iterations: self.run.solver_iterations,
            phase,
            progress,
        }
    }

    /// Sets up the level `self.level`: its exemplar neighbourhoods and search structure, its grid,
    /// the output at its resolution, and matches carried over from the previous level.
    fn enter_level(&mut self) -> Result<()> {
        let lv = self.levels[self.level];
        let setup = LevelSetup {
            output_width: lv.output_width,
            output_height: lv.output_height,
            size: lv.size,
            spacing: lv.spacing,
            search: self.options.search,
            r: self.options.r,
            mu: self.options.mu,
            search_mu: self.options.search_mu(),
            wrap: self.options.tileable,
            passes: PATCHMATCH_PASSES,
            completeness: self.options.completeness,
            histogram_matching: self.options.histogram_matching,
            match_constrained: false,
            energy: self.options.energy,
            wavelet_detail_weight: self.options.wavelet_detail_weight,
            channel_weights: self.channel_weights,
        };
        let exemplar = &self.exemplars[lv.octave];
        let mut solver = match &self.guides {
            None => LevelSolver::new(exemplar, setup, &mut self.rng),
            Some(g) => g.level_solver(exemplar, setup, lv.octave, &mut self.rng),
        };
        let previous = self.level.checked_sub(1).map(|i| self.levels[i]);
        if let (Some(old), Some(prev)) = (&self.solver, previous) {
            // Old node centres are in the previous level's output coordinates.
            let ox = prev.output_width as f64 / lv.output_width as f64;
            let oy = prev.output_height as f64 / lv.output_height as f64;
            let scale = (
                lv.exemplar_width as f64 / prev.exemplar_width as f64,
                lv.exemplar_height as f64 / prev.exemplar_height as f64,
            );
            solver.carry_from(old, |cx, cy| (cx * ox, cy * oy), scale);
        }
        if let Some(mask) = &self.excluded {
            let e = &self.exemplars[0];
            let table = exclusion_table(mask, (e.width(), e.height()), lv.octave, lv.size);
            solver.exclude(table, &mut self.rng)?;
        }
        if let Some(out) = self.output.take() {
            self.output = Some(fit_output(out, &setup)?);
        }
        self.fresh = self.output.is_some();
        self.new_level = true;
        self.run = Iteration::default();
        self.entered = Some(self.level);
        self.constraint = self.level_constraint();
        if let Some(several) = &self.several {
            let keep = several.kept_at(lv.octave);
            let reference = SortedChannels::of_pixels(&self.exemplars[lv.octave], Some(&keep));
            solver.set_histogram_reference(reference);
        }
        if let Some(c) = self.constraint.as_ref().filter(|_| self.histogram_to_constraint) {
            let held: Vec<bool> = c.mask.iter().map(|&m| m >= 1.0).collect();
            if held.contains(&true) {
                solver.set_histogram_reference(SortedChannels::of_pixels(&c.target, Some(&held)));
            }
        }
        self.solver = Some(solver);
        Ok(())
    }

    /// Advances the current EM iteration: (on a fresh level, an M-step on the up-sampled output
    /// first), E-step with IRLS weights, M-step. With split iterations (see [`SPLIT_PIXELS`](super::iteration::SPLIT_PIXELS))
    /// it stops once the step's time is up, between chunks. Returns how many matches changed in
    /// the final M-step once the iteration is done, else None (the next step resumes it).
    fn advance(&mut self, entering: bool) -> Result<Option<usize>> {
        let lv = self.levels[self.level];
        let exemplar = &self.exemplars[lv.octave];
        let solver = self.solver.as_mut().expect("level entered");
        if self.run.idle() {
            if self.output.is_none() {
                // The coarsest level's start (see [`super::initial`]), or the caller's.
                let given = self.given_start.as_ref();
                let start = match self.options.start {
                    _ if given.is_some() => {
                        let given = given.expect("matched");
                        if (given.width(), given.height()) == (lv.output_width, lv.output_height) {
                            given.clone()
                        } else {
                            shrink_area(given, lv.output_width, lv.output_height)?
                        }
                    }
                    Start::Patches => random_patches(
                        self.several.as_ref().map_or(exemplar, |s| &s.pyramids[0][lv.octave]),
                        lv.output_width,
                        lv.output_height,
                        lv.size,
                        &mut self.rng,
                    )?,
                    Start::Graphcut => {
                        let started = crate::core::clock::now_ms();
                        let cut = match &mut self.start {
                            Some(cut) => cut,
                            None => {
                                let options = graphcut_start_options(
                                    lv.output_width,
                                    lv.output_height,
                                    self.options.tileable,
                                    self.options.memory_budget_mib,
                                    &mut self.rng,
                                );
                                let cut = match &self.several {
                                    None => graphcut::Session::new(exemplar, options)?,
                                    Some(s) => graphcut::Session::with_exemplars(
                                        &s.at_octave(lv.octave),
                                        options,
                                    )?,
                                };
                                self.start.insert(cut)
                            }
                        };
                        // Whole graph-cut steps, so that where a large start splits changes
                        // nothing.
                        while !cut.step()?.done {
                            if let Some(ms) = self.budget.split
                                && crate::core::clock::now_ms() - started >= ms
                            {
                                return Ok(None);
                            }
                        }
                        let made = cut.output()?;
                        self.start = None;
                        made
                    }
                };
                self.output = Some(start);
                self.fresh = true;
            }
            let output = self.output.as_ref().expect("made above");
            self.run
                .begin(solver, output, std::mem::take(&mut self.fresh), false);
            if entering && self.budget.split.is_some() {
                // Entering a level (its exemplar neighbourhoods, the up-sampled output, carried
                // matches, the first M-step's feature map) is a step of its own on a large
                // output.
                return Ok(None);
            }
        }
        let work = Work {
            solver,
            exemplar,
            output: self.output.as_mut().expect("made at the start"),
            constraint: self.constraint.as_ref(),
            rng: &mut self.rng,
        };
        Ok(self.run.advance(work, self.budget))
    }

    /// The soft-constraint energy of the current output (0 without constraints): the mean
    /// squared difference to the constraint colours over the constrained pixels.
    #[must_use]
    pub fn constraint_energy(&self) -> f64 {
        match (&self.constraint, &self.output) {
            (Some(c), Some(out)) if c.target.width() == out.width() => c.energy(out),
            _ => 0.0,
        }
    }
}
