//! One EM iteration of a level (Algorithm 1's loop body: E-step with the IRLS weights, then
//! M-step; on a fresh level an M-step on the up-sampled output comes first), resumable: on a
//! large output it runs over several steps, each stopping after about [`STEP_MILLISECONDS`], so
//! that no step blocks a page for long. Texture optimisation and the frames of a flow animation
//! both run their iterations through it. Where an iteration stops changes no output.

use super::constraints::Constraint;
use super::level::LevelSolver;
use crate::core::{Image, Rng};

/// Outputs with more pixels than this (larger than 256x512) split their iterations over
/// several steps (one iteration at neighbourhood size 8 takes about 0.5 s at 1024x1024).
/// Smaller ones step whole iterations, as the paper's Fig. 3 counts them.
pub const SPLIT_PIXELS: usize = 1 << 17;

/// The time a step of a split iteration works before it stops. It looks at the clock between
/// chunks of about [`CHUNK_WORK`] (a few milliseconds); the E-step's last part (the average,
/// histogram matching, the M-step's feature map) cannot be cut and starts only in the first
/// third of a step.
pub const STEP_MILLISECONDS: f64 = 60.0;

/// Work between two looks at the clock, in vector values: an M-step's node visit counts as the
/// vector length plus [`VISIT_OVERHEAD`], adding a node to the E-step's sums as one such visit.
pub const CHUNK_WORK: usize = 1 << 21;

/// The fixed cost of visiting a node (making its query, proposing candidates), in vector
/// values: measured at 1024x1024, a visit takes 0.7 us at size 8 (192 values) and 6.4 us at
/// size 32 (3072 values), 2 ns per value plus 0.3 us.
pub const VISIT_OVERHEAD: usize = 160;

/// How long a step may work.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepBudget {
    /// Milliseconds per step when iterations are split, None to run whole iterations.
    pub split: Option<f64>,
    /// Work between two looks at the clock (see [`CHUNK_WORK`]).
    pub chunk_work: usize,
    /// Stop after each half of an iteration (the page's step anatomy): a level's first M-step,
    /// the E-step (with its average and histogram matching) and the M-step each end a step.
    pub halves: bool,
}

impl StepBudget {
    /// A budget of `milliseconds` per step (None: whole iterations) and `chunk_work` between
    /// looks at the clock, clamped to sensible values (no negative time, at least 1 of work).
    #[must_use]
    pub fn new(milliseconds: Option<f64>, chunk_work: usize) -> StepBudget {
        StepBudget {
            split: milliseconds.map(|ms| ms.max(0.0)),
            chunk_work: chunk_work.max(1),
            halves: false,
        }
    }

    /// The default for an output of `pixels`: split above [`SPLIT_PIXELS`].
    #[must_use]
    pub fn for_pixels(pixels: usize) -> StepBudget {
        StepBudget {
            split: (pixels > SPLIT_PIXELS).then_some(STEP_MILLISECONDS),
            chunk_work: CHUNK_WORK,
            halves: false,
        }
    }
}

/// Where the current EM iteration is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Nothing done yet.
    Start,
    /// The M-step on a level's up-sampled output, before its first E-step.
    FirstMatch,
    /// The E-step's sums are next (or under way).
    EStep,
    /// The E-step's average is next.
    Average,
    /// Histogram matching of the E-step's output is next, then the M-step begins.
    Histogram,
    /// The M-step after the E-step is running.
    MStep,
}

/// The half of an EM iteration a step stopped in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Making the coarsest level's start (a graph cut, see [`super::initial`]), before any EM.
    Start,
    /// The M-step that starts a level (on its up-sampled output).
    FirstMatch,
    EStep,
    MStep,
}

/// What a level's EM iteration needs, borrowed for one step.
pub struct Work<'a> {
    pub solver: &'a mut LevelSolver,
    pub exemplar: &'a Image,
    pub output: &'a mut Image,
    pub constraint: Option<&'a Constraint>,
    pub rng: &'a mut Rng,
}

/// A resumable EM iteration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Iteration {
    pub stage: Stage,
    /// The half of the iteration the last step completed, if it completed one (the first
    /// M-step or the E-step; a completed M-step ends the iteration).
    pub completed: Option<Phase>,
    /// Conjugate-gradient iterations of the last E-step's gradient-energy solve.
    pub solver_iterations: usize,
    /// Whether this iteration's M-step only measures the kept matches
    /// ([`LevelSolver::measure`]) instead of searching.
    pub measure_only: bool,
}

impl Default for Iteration {
    fn default() -> Self {
        Iteration {
            stage: Stage::Start,
            completed: None,
            solver_iterations: 0,
            measure_only: false,
        }
    }
}

impl Iteration {
    /// Whether no iteration is under way.
    #[must_use]
    pub fn idle(&self) -> bool {
        self.stage == Stage::Start
    }

    /// Begins an iteration on `output`; `fresh`: the output is new to the solver (a level's
    /// up-sampled output, a flow frame's warped start), so it is matched before the E-step.
    /// `measure_only`: the iteration's M-step measures the kept matches without searching
    /// (it then reports 0 changed).
    pub fn begin(
        &mut self,
        solver: &mut LevelSolver,
        output: &Image,
        fresh: bool,
        measure_only: bool,
    ) {
        debug_assert!(self.idle(), "an iteration is under way");
        self.measure_only = measure_only;
        self.stage = if fresh {
            solver.begin_m_step(output);
            Stage::FirstMatch
        } else {
            Stage::EStep
        };
    }

    /// Advances the begun iteration until it ends or the budget's time is up (between chunks;
    /// it always does some work). Returns how many matches changed in its final M-step once the
    /// iteration is done, else None (the next call resumes it).
    pub fn advance(&mut self, w: Work<'_>, budget: StepBudget) -> Option<usize> {
        let Work {
            solver,
            exemplar,
            output,
            constraint,
            rng,
        } = w;
        let len = solver.vector_len() + VISIT_OVERHEAD;
        let chunk = match budget.split {
            Some(_) => (budget.chunk_work / len).max(1),
            None => usize::MAX,
        };
        let started = crate::core::clock::now_ms();
        let time_up = |share: f64| {
            budget
                .split
                .is_some_and(|ms| crate::core::clock::now_ms() - started >= share * ms)
        };
        // Whether this step did any work yet (it always does some before it stops).
        let mut worked = false;
        self.completed = None;
        loop {
            match self.stage {
                Stage::Start => unreachable!("an iteration is begun before it advances"),
                Stage::FirstMatch | Stage::MStep => {
                    let mut visits = chunk;
                    match (
                        self.stage,
                        solver.resume_m_step(constraint, rng, &mut visits),
                    ) {
                        (_, None) => {}
                        (Stage::FirstMatch, Some(_)) => {
                            self.stage = Stage::EStep;
                            if budget.halves {
                                self.completed = Some(Phase::FirstMatch);
                                return None;
                            }
                        }
                        (_, Some(changed)) => {
                            self.stage = Stage::Start;
                            return Some(changed);
                        }
                    }
                }
                Stage::EStep => {
                    if !solver.e_step_running() {
                        solver.begin_e_step(output);
                    }
                    let mut nodes = chunk;
                    if solver.resume_e_step(exemplar, &mut nodes) {
                        self.stage = Stage::Average;
                    }
                }
                // The E-step's average cannot be cut: it starts only early in a step.
                Stage::Average if worked && time_up(1.0 / 3.0) => return None,
                Stage::Average => {
                    self.solver_iterations = solver.average(exemplar, output, constraint);
                    solver.begin_histogram();
                    self.stage = Stage::Histogram;
                }
                Stage::Histogram => {
                    // A pixel visit of histogram matching costs about as much as 8 values of
                    // a neighbourhood comparison.
                    let mut pixels = chunk.saturating_mul(len) / 8;
                    if solver.resume_histogram(output, constraint, &mut pixels) {
                        if self.measure_only {
                            solver.measure(output);
                            self.stage = Stage::Start;
                            return Some(0);
                        }
                        solver.begin_m_step(output);
                        self.stage = Stage::MStep;
                        if budget.halves {
                            self.completed = Some(Phase::EStep);
                            return None;
                        }
                    }
                }
            }
            worked = true;
            if time_up(1.0) {
                return None;
            }
        }
    }

    /// The phase of the iteration under way and the share (0 to 1) of its work done, for an
    /// output of `pixels`: the first M-step of a level, the E-step and the M-step weigh
    /// 1 : 1 : 3 per node visit, roughly their costs.
    #[must_use]
    pub fn progress(&self, solver: &LevelSolver, pixels: usize) -> (Phase, f64) {
        let fraction = solver.m_step_fraction().unwrap_or(0.0);
        match self.stage {
            Stage::FirstMatch => (Phase::FirstMatch, 0.2 * fraction),
            Stage::Start | Stage::EStep => (
                Phase::EStep,
                0.2 + 0.15 * solver.e_step_fraction().unwrap_or(0.0),
            ),
            Stage::Average => (Phase::EStep, 0.35),
            Stage::Histogram => (
                Phase::EStep,
                0.35 + 0.05 * solver.histogram_fraction(pixels),
            ),
            Stage::MStep => (Phase::MStep, 0.4 + 0.6 * fraction),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::{noise, sample};
    use crate::methods::optimization::level::LevelSetup;

    fn solver(exemplar: &Image, constrained: bool) -> LevelSolver {
        let setup = LevelSetup {
            match_constrained: constrained,
            ..LevelSetup::plain(64, 64, 8)
        };
        LevelSolver::new(exemplar, setup, &mut Rng::new(3))
    }

    /// One whole iteration on `output`, begun fresh; returns what it reports changed.
    fn iterate(
        solver: &mut LevelSolver,
        exemplar: &Image,
        output: &mut Image,
        constraint: Option<&Constraint>,
        measure_only: bool,
    ) -> usize {
        let mut run = Iteration::default();
        run.begin(solver, output, true, measure_only);
        let work = Work {
            solver,
            exemplar,
            output,
            constraint,
            rng: &mut Rng::new(5),
        };
        run.advance(work, StepBudget::new(None, CHUNK_WORK))
            .expect("a whole iteration")
    }

    /// The iteration that measures instead of searching leaves the same output (its E-step is
    /// the same), keeps the matches its first M-step found, and reports their distances to the
    /// new output as an M-step reports its own.
    #[test]
    fn a_measuring_iteration_makes_the_same_output_and_keeps_its_matches() {
        let exemplar = sample("tiles_64");
        let start = noise(64, 64, 3, 9);
        let constraint = Constraint {
            target: noise(64, 64, 3, 11),
            mask: vec![1.0; 64 * 64],
            lambda: 0.2,
        };
        for constraint in [None, Some(&constraint)] {
            let constrained = constraint.is_some();
            let (mut searched, mut measured) = (start.clone(), start.clone());
            let mut searching = solver(&exemplar, constrained);
            let changed = iterate(&mut searching, &exemplar, &mut searched, constraint, false);
            assert!(changed > 0, "a search from noise changes matches");
            let mut measuring = solver(&exemplar, constrained);
            let changed = iterate(&mut measuring, &exemplar, &mut measured, constraint, true);
            assert_eq!(changed, 0, "a measure changes no match");
            assert_eq!(searched, measured, "the E-step's output is the same");

            // The matches the first M-step found, searched again on its own.
            let mut first = solver(&exemplar, constrained);
            first.m_step(&start, constraint, &mut Rng::new(5));
            assert_eq!(measuring.matches(), first.matches());
            assert_ne!(searching.matches(), first.matches());

            // Measured distances equal what an M-step that keeps them reports: a search on the
            // measured output from these matches reports its distances; measuring its matches
            // again gives them back.
            let mut again = solver(&exemplar, constrained);
            again.m_step(&measured, None, &mut Rng::new(7));
            let found = again.distances().to_vec();
            let energy = again.energy();
            again.measure(&measured);
            for (&m, &f) in again.distances().iter().zip(&found) {
                assert!((m - f).abs() <= 1e-5 * f.max(1e-3), "{m} vs {f}");
            }
            assert!((again.energy() - energy).abs() <= 1e-6 * energy);
        }
    }
}
