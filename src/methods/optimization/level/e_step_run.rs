//! The E-step of a level, resumable: begun with the IRLS weights of the last M-step, summed
//! band by band of output rows over as many steps as the budget asks, then averaged and matched
//! to the histogram.

use super::{EStepRun, LevelSolver};
use crate::core::{Image, parallel};
use crate::methods::optimization::constraints::Constraint;
use crate::methods::optimization::e_step::{Matches, Sums};

impl LevelSolver {
    /// Whether an E-step is begun and not finished.
    #[must_use]
    pub fn e_step_running(&self) -> bool {
        self.summing.is_some()
    }

    /// The share of the running E-step's bands of output rows summed (None when none runs).
    #[must_use]
    pub fn e_step_fraction(&self) -> Option<f64> {
        self.summing
            .as_ref()
            .map(|r| r.next as f64 / r.sums.bands().len().max(1) as f64)
    }

    /// The E-step: replaces `output` (this level's size) by the minimiser of the IRLS-weighted
    /// texture energy for the current matches, plus the constraint's term when given, then
    /// matches its histogram to the exemplar's when the setup asks for it. Returns the
    /// conjugate-gradient iterations of the gradient solve (0 without the gradient energy).
    pub fn e_step(
        &mut self,
        exemplar: &Image,
        output: &mut Image,
        constraint: Option<&Constraint>,
    ) -> usize {
        self.begin_e_step(output);
        let mut unlimited = usize::MAX;
        self.resume_e_step(exemplar, &mut unlimited);
        self.finish_e_step(exemplar, output, constraint)
    }

    /// Starts an E-step on an output like `output`: the IRLS weights are fixed now, from the
    /// last distances (all 1 before the first M-step).
    pub fn begin_e_step(&mut self, output: &Image) {
        // With a wavelet energy the E-step stays this pixel average (the matches, chosen under
        // eq. 4, carry the wavelet term): the exact minimiser of eq. 4 over x with weighted
        // coefficients is a linear solve with W^T D W, which is not diagonal (a block-coupled
        // system per neighbourhood), and with all weights 1 it is the pixel average anyway
        // (Parseval). The IRLS weights come from the full eq. 4 distances.
        self.summing = Some(EStepRun {
            weights: self.robust.clone(),
            sums: Sums::new(output, self.setup.mu > 0.0),
            next: 0,
        });
    }

    fn matches_for<'a>(&'a self, exemplar: &'a Image, weights: &'a [f32]) -> Matches<'a> {
        Matches {
            exemplar: self.stacked.as_ref().unwrap_or(exemplar),
            cols: &self.cols,
            rows: &self.rows,
            matches: &self.matches,
            node_weights: weights,
            falloff: &self.falloff,
            size: self.setup.size,
            wrap: self.setup.wrap,
            mu: self.setup.mu,
        }
    }

    /// Sums about `budget` more node visits of the begun E-step, taking them off it: whole
    /// bands of output rows, each over every node that reaches it, in whole rounds of the
    /// threads and at least [`parallel::MIN_ROUNDS`] of them, so the bands of one call keep
    /// every thread busy (where the calls stop changes no sum). A band costs the nodes' visits
    /// spread evenly over the bands. Returns true when every band is summed.
    pub fn resume_e_step(&mut self, exemplar: &Image, budget: &mut usize) -> bool {
        let mut run = self.summing.take().expect("an E-step is begun");
        let nodes = self.matches.len();
        let bands = run.sums.bands().len();
        let per_band = nodes.div_ceil(bands.max(1)).max(1);
        let threads = parallel::threads();
        let count = budget
            .div_ceil(per_band)
            .div_ceil(threads)
            .max(parallel::MIN_ROUNDS)
            .saturating_mul(threads);
        let end = run.next.saturating_add(count).min(bands);
        let m = self.matches_for(exemplar, &run.weights);
        run.sums.add(&m, 0..nodes, run.next..end);
        *budget = budget.saturating_sub((end - run.next) * per_band);
        run.next = end;
        let done = end == bands;
        self.summing = Some(run);
        done
    }

    /// The IRLS weights of the begun E-step.
    #[cfg(test)]
    pub fn e_step_weights(&self) -> Option<&[f32]> {
        self.summing.as_ref().map(|run| &run.weights[..])
    }

    /// Ends the begun E-step (every node added): writes the output and matches its histogram.
    pub fn finish_e_step(
        &mut self,
        exemplar: &Image,
        output: &mut Image,
        constraint: Option<&Constraint>,
    ) -> usize {
        let iterations = self.average(exemplar, output, constraint);
        self.begin_histogram();
        let mut unlimited = usize::MAX;
        self.resume_histogram(output, constraint, &mut unlimited);
        iterations
    }

    /// The first half of [`LevelSolver::finish_e_step`]: the output from the sums. Returns the
    /// conjugate-gradient iterations (0 without the gradient energy).
    pub fn average(
        &mut self,
        exemplar: &Image,
        output: &mut Image,
        constraint: Option<&Constraint>,
    ) -> usize {
        let run = self.summing.take().expect("an E-step is begun");
        debug_assert_eq!(run.next, run.sums.bands().end, "every band is summed");
        let m = self.matches_for(exemplar, &run.weights);
        run.sums.finish(&m, output, constraint)
    }

    /// Starts the second half of [`LevelSolver::finish_e_step`]: histogram matching.
    pub fn begin_histogram(&mut self) {
        self.order.restart();
    }

    /// Runs the begun histogram matching (when the setup asks for one) for at most `budget`
    /// more pixel visits, taken off it. Returns true when done.
    pub fn resume_histogram(
        &mut self,
        output: &mut Image,
        constraint: Option<&Constraint>,
        budget: &mut usize,
    ) -> bool {
        let strength = self.setup.histogram_matching;
        if strength <= 0.0 {
            return true;
        }
        let fixed = constraint
            .filter(|_| !self.setup.match_constrained)
            .map(|c| c.mask.as_slice());
        self.histogram
            .resume(output, strength, fixed, &mut self.order, budget)
    }

    /// The share of the begun histogram matching done, over an output of `pixels` pixels.
    #[must_use]
    pub fn histogram_fraction(&self, pixels: usize) -> f64 {
        self.order.fraction(pixels)
    }
}
