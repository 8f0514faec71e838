//! One synthesis level at work: the grid X† of output neighbourhoods, their matches z_p, the
//! search structure over the exemplar's neighbourhoods, and the E- and M-steps that alternate
//! on them (Algorithm 1, or Algorithm 2 with a [`Constraint`]). The multi-level session and the
//! flow-guided animation both drive it.

use super::constraints::{Constraint, QueryTerms};
use super::channel_weights::ChannelWeights;
use super::e_step::{Sums, robust_weights};
use super::features::{append_guide, feature_map};
use super::histogram::{Scratch, SortedChannels};
use super::m_step::Matcher;
use super::occurrence::{Occurrence, strength};
use super::phases;
use super::queries::GridQueries;
use super::schedule::grid_axis;
use super::wavelet_energy::{Energy, WaveletEnergy};
use crate::core::sample::resize_bilinear;
use crate::core::{Edge, Image, Result, Rng};
use crate::methods::optimization::e_step::edge;
use crate::solvers::nn::patches::gaussian_falloff;
use crate::solvers::nn::patchmatch::QueryGrid;
use crate::solvers::nn::{
    FeatureMap, Neighbourhoods, Objective, Penalties, Pos, Progress, Search,
};

mod carry;
mod e_step_run;
mod limits;
mod measure;

/// The fixed settings of a level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelSetup {
    pub output_width: usize,
    pub output_height: usize,
    /// Neighbourhood width w.
    pub size: usize,
    /// Spacing of the grid X†.
    pub spacing: usize,
    pub search: Search,
    /// Robust exponent r of the energy (IRLS).
    pub r: f32,
    /// Weight of the gradient energy.
    pub mu: f32,
    /// Weight of the gradient term in the M-step's distance (`mu` unless the options say
    /// otherwise).
    pub search_mu: f32,
    /// Neighbourhoods wrap around the output's borders.
    pub wrap: bool,
    /// PatchMatch sweeps per M-step.
    pub passes: usize,
    /// Weight alpha of the occurrence penalty (see [`super::occurrence`]); 0 is off.
    pub completeness: f32,
    /// Strength of the histogram matching after each E-step (see [`super::histogram`]); 0 is
    /// off.
    pub histogram_matching: f32,
    /// Whether histogram matching also moves constrained pixels: yes for flow frames, whose
    /// constraint is the texture itself carried along the flow; no for a user's paint, whose
    /// colours need not be the exemplar's.
    pub match_constrained: bool,
    /// The M-step's distance: pixels, or pixels plus a weighted wavelet term (Shen et al.
    /// 2009); the wavelet energies take no constraint.
    pub energy: Energy,
    /// Weight of the wavelet detail bands (see [`super::wavelet_energy`]).
    pub wavelet_detail_weight: f32,
    /// Weight of each colour channel in the M-step's distance (pixel energies).
    pub channel_weights: ChannelWeights,
}

#[cfg(test)]
impl LevelSetup {
    /// A level of tests: pixel energy, r = 0.8, PatchMatch with three sweeps, spacing a quarter
    /// of `size` (at least 1: the node grid steps by it), nothing else on.
    #[must_use]
    pub fn plain(output_width: usize, output_height: usize, size: usize) -> Self {
        LevelSetup {
            output_width,
            output_height,
            size,
            spacing: (size / 4).max(1),
            search: Search::PatchMatch,
            r: 0.8,
            mu: 0.0,
            search_mu: 0.0,
            wrap: false,
            passes: 3,
            completeness: 0.0,
            histogram_matching: 0.0,
            match_constrained: false,
            energy: Energy::Pixels,
            wavelet_detail_weight: 1.0,
            channel_weights: ChannelWeights::default(),
        }
    }
}

/// An M-step under way: the output's feature map it compares with, its occurrence penalty,
/// and where the search stopped.
struct MStepRun {
    map: FeatureMap,
    occurrence: Option<Occurrence>,
    progress: Progress,
    /// The constraint's query terms, made at the first part that has a constraint, and every
    /// query under them made at once (values and gains, to read queries in place).
    terms: Option<QueryTerms>,
    constrained: Option<(FeatureMap, Vec<f32>)>,
}

/// An E-step under way: its IRLS weights, its sums, and the next band of output rows to sum.
struct EStepRun {
    weights: Vec<f32>,
    sums: Sums,
    next: usize,
}

/// The state of one level between iterations.
pub struct LevelSolver {
    setup: LevelSetup,
    matcher: Matcher,
    cols: Vec<usize>,
    rows: Vec<usize>,
    matches: Vec<Pos>,
    /// With sub-pixel matches ([`LevelSolver::with_sub_pixel_matches`]): the exemplar's moved copies
    /// stacked (the E-step reads them), each node's content position beyond its match and
    /// phase (carried on exactly, so that rounding does not add up over frames), and the
    /// matches as positions in the exemplar (the teaching views show them).
    stacked: Option<Image>,
    offsets: Vec<(f64, f64)>,
    local_matches: Vec<Pos>,
    /// Texture distances after the last M-step (infinite before the first): ||x_p - z_p||^2
    /// (fall-off weighted), plus the weighted wavelet term with a wavelet energy. The IRLS
    /// weights and the occurrence penalty's scale come from them.
    distances: Vec<f32>,
    /// The IRLS weight of each distance and the sum of d^(r/2) over them, made once per
    /// M-step ([`LevelSolver::settle`]).
    robust: Vec<f32>,
    texture_sum: f64,
    /// The pixel term alone with a wavelet energy (empty otherwise): the reported energy, so
    /// that energies compare.
    pixel_distances: Vec<f32>,
    /// The wavelet transform of the neighbourhoods with a wavelet energy, and unit weights
    /// (the pixel term of transformed vectors, by Parseval).
    wavelet: Option<WaveletEnergy>,
    unit_weights: Vec<f32>,
    /// The M-step's own objective per node (equal to `distances` without constraints).
    objective: Vec<f32>,
    falloff: Vec<f32>,
    /// The last occurrence penalty (None before the first): the next remembers its coverage
    /// and reuses its buffers.
    occurrence_kept: Option<Occurrence>,
    /// This level's exemplar values sorted, for histogram matching, and its scratch space.
    histogram: SortedChannels,
    order: Scratch,
    /// Exemplar neighbourhoods no match may take (non-zero per top-left corner, `extent().0`
    /// per row; empty: none), see [`LevelSolver::exclude`].
    excluded: Vec<f32>,
    /// The target guide at this level's output size and its scale (sqrt of the guide weight),
    /// appended to every query (see [`LevelSolver::guided`]).
    target_guide: Option<(Image, f32)>,
    /// The M-step under way, between steps of a session that splits iterations.
    running: Option<MStepRun>,
    /// The E-step under way.
    summing: Option<EStepRun>,
}

impl LevelSolver {
    /// A level over `exemplar` (this level's resolution of it) with a random match per node.
    pub fn new(exemplar: &Image, setup: LevelSetup, rng: &mut Rng) -> Self {
        Self::build(exemplar, setup, false, None, rng)
    }

    /// A level whose distance adds `weight` times the squared difference of guide values:
    /// `source_guide` (the exemplar's size at this level) is appended to every exemplar
    /// neighbourhood, `target_guide` (the output's) to every query. Pixel energy only.
    pub fn guided(
        exemplar: &Image,
        setup: LevelSetup,
        (source_guide, target_guide): (&Image, Image),
        weight: f32,
        rng: &mut Rng,
    ) -> Self {
        let scale = weight.sqrt();
        let mut solver = Self::build(exemplar, setup, false, Some((source_guide, scale)), rng);
        solver.target_guide = Some((target_guide, scale));
        solver
    }

    /// A level whose matches have half-pixel precision (see [`phases`]): the searches run over
    /// the exemplar moved by each phase, and carrying matches along a flow keeps their
    /// fractions. For flow frames (pixel energies only).
    pub fn with_sub_pixel_matches(exemplar: &Image, setup: LevelSetup, rng: &mut Rng) -> Self {
        debug_assert!(
            setup.energy.wavelet().is_none(),
            "flow frames compare pixels"
        );
        Self::build(exemplar, setup, true, None, rng)
    }

    fn build(
        exemplar: &Image,
        setup: LevelSetup,
        sub_pixel: bool,
        guide: Option<(&Image, f32)>,
        rng: &mut Rng,
    ) -> Self {
        let map = feature_map(exemplar, setup.search_mu, Edge::Clamp);
        let map = match guide {
            Some((guide, scale)) => append_guide(map, guide, scale),
            None => map,
        };
        let wavelet = setup.energy.wavelet().map(|w| {
            WaveletEnergy::new(
                w,
                setup.size,
                map.dims,
                exemplar.channels(),
                setup.wavelet_detail_weight,
            )
        });
        let mut wavelet_scratch = vec![0.0; setup.size];
        // With a wavelet energy every exemplar neighbourhood is transformed once here, and the
        // searches compare transformed vectors (one code path for all three searches).
        let mut stacked = None;
        let space = match &wavelet {
            None if sub_pixel => {
                let (copies, image) = phases::stacked_exemplar(exemplar);
                stacked = Some(image);
                Neighbourhoods::stacked(&phases::copy_maps(&copies, setup.search_mu), setup.size)
            }
            None => Neighbourhoods::new(map, setup.size),
            Some(e) => {
                Neighbourhoods::transformed(map, setup.size, e.weights().to_vec(), |v, out| {
                    e.transform(v, out, &mut wavelet_scratch);
                })
            }
        };
        let mut space = space;
        if wavelet.is_none() && !setup.channel_weights.is_uniform() {
            let colour_dims = if setup.search_mu > 0.0 { 3 } else { 1 } * exemplar.channels();
            let dims = space.exemplar().dims;
            space.weigh_dims(&setup.channel_weights.per_dim(exemplar.channels(), colour_dims, dims));
        }
        let matcher = Matcher::over(space, setup.search, rng).with_passes(setup.passes);
        let cols = grid_axis(setup.output_width, setup.size, setup.spacing, setup.wrap);
        let rows = grid_axis(setup.output_height, setup.size, setup.spacing, setup.wrap);
        let (ex_nx, ex_ny) = matcher.space().extent();
        let nodes = cols.len() * rows.len();
        let matches = (0..nodes)
            .map(|_| Pos::new(rng.index(ex_nx), rng.index(ex_ny)))
            .collect();
        let len = matcher.space().vector_len();
        let mut solver = LevelSolver {
            falloff: gaussian_falloff(setup.size, 1),
            distances: vec![f32::INFINITY; nodes],
            robust: vec![1.0; nodes],
            texture_sum: f64::INFINITY,
            pixel_distances: if wavelet.is_some() {
                vec![f32::INFINITY; nodes]
            } else {
                Vec::new()
            },
            unit_weights: if wavelet.is_some() {
                vec![1.0; len]
            } else {
                Vec::new()
            },
            wavelet,
            objective: vec![f32::INFINITY; nodes],
            occurrence_kept: None,
            histogram: SortedChannels::new(exemplar),
            order: Scratch::default(),
            running: None,
            summing: None,
            excluded: Vec::new(),
            target_guide: None,
            setup,
            matcher,
            cols,
            rows,
            matches,
            stacked,
            offsets: Vec::new(),
            local_matches: Vec::new(),
        };
        solver.refresh_local();
        solver
    }

    /// The exemplar position of every match (its copy taken off).
    fn refresh_local(&mut self) {
        if self.stacked.is_some() {
            let space = self.matcher.space();
            self.local_matches = self.matches.iter().map(|&z| space.copy_of(z).1).collect();
        }
    }

    #[must_use]
    pub fn setup(&self) -> &LevelSetup {
        &self.setup
    }

    /// Column and row corners of the grid X†.
    #[must_use]
    pub fn grid(&self) -> (&[usize], &[usize]) {
        (&self.cols, &self.rows)
    }

    /// Nodes of the grid X†.
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.matches.len()
    }

    /// PatchMatch sweeps per M-step (1 for the other searches).
    #[must_use]
    pub fn passes(&self) -> usize {
        self.matcher.progress(1).passes
    }

    /// Values per neighbourhood vector.
    #[must_use]
    pub fn vector_len(&self) -> usize {
        self.matcher.space().vector_len()
    }

    /// The texture distance ||x_p - z_p||^2 of every node after the last M-step (infinite
    /// before the first), row by row: the IRLS weights of the next E-step come from them.
    #[must_use]
    pub fn distances(&self) -> &[f32] {
        &self.distances
    }

    /// z_p of every node, row by row (with sub-pixel matches: rounded down to whole pixels).
    #[must_use]
    pub fn matches(&self) -> &[Pos] {
        if self.stacked.is_some() {
            &self.local_matches
        } else {
            &self.matches
        }
    }

    /// The M-step: gathers every x_p from `output` and improves its match, under the
    /// constraint's search (Algorithm 2) when given. Returns how many matches changed.
    pub fn m_step(
        &mut self,
        output: &Image,
        constraint: Option<&Constraint>,
        rng: &mut Rng,
    ) -> usize {
        self.begin_m_step(output);
        let mut unlimited = usize::MAX;
        self.resume_m_step(constraint, rng, &mut unlimited)
            .expect("an unlimited M-step finishes")
    }

    /// Starts an M-step on `output` (its feature map and occurrence penalty are fixed now);
    /// [`LevelSolver::resume_m_step`] runs it.
    pub fn begin_m_step(&mut self, output: &Image) {
        let LevelSetup {
            search_mu, wrap, ..
        } = self.setup;
        self.abandon_m_step();
        let occurrence = self.occurrence();
        let map = self.query_map(feature_map(output, search_mu, edge(wrap)));
        self.running = Some(MStepRun {
            map,
            occurrence,
            progress: self.matcher.progress(self.matches.len()),
            terms: None,
            constrained: None,
        });
    }

    /// The output's feature map with the target guide appended, when the level has one.
    pub(super) fn query_map(&self, map: FeatureMap) -> FeatureMap {
        match &self.target_guide {
            Some((guide, scale)) => append_guide(map, guide, *scale),
            None => map,
        }
    }

    /// Drops an M-step begun and not finished; its occurrence penalty is kept for the next.
    fn abandon_m_step(&mut self) {
        if let Some(o) = self.running.take().and_then(|run| run.occurrence) {
            self.occurrence_kept = Some(o);
        }
    }

    /// Whether an M-step is begun and not finished.
    #[must_use]
    pub fn m_step_running(&self) -> bool {
        self.running.is_some()
    }

    /// The share of the running M-step's node visits done (None when none runs).
    #[must_use]
    pub fn m_step_fraction(&self) -> Option<f64> {
        self.running.as_ref().map(|r| r.progress.fraction())
    }

    /// Runs the begun M-step for at most `budget` more node visits, taking the visits made
    /// off it (the result does not depend on where it stops). Returns how many matches
    /// changed once it is done, else None.
    pub fn resume_m_step(
        &mut self,
        constraint: Option<&Constraint>,
        rng: &mut Rng,
        budget: &mut usize,
    ) -> Option<usize> {
        let LevelSetup { wrap, size, .. } = self.setup;
        let mut run = self.running.take().expect("an M-step is begun");
        let space = self.matcher.space();
        let grid = QueryGrid {
            cols: &self.cols,
            rows: &self.rows,
        };
        let occurrence = run.occurrence.as_ref();
        let objective = Objective {
            penalty: occurrence.map(Occurrence::penalties),
            excluded: (!self.excluded.is_empty()).then(|| Penalties {
                values: &self.excluded,
                columns: space.extent().0,
            }),
        };
        debug_assert!(
            constraint.is_none() || self.wavelet.is_none(),
            "the session refuses constraints with a wavelet energy"
        );
        let constraint = constraint.filter(|_| self.wavelet.is_none());
        if let (Some(c), None) = (constraint, &run.terms) {
            let terms = c.query_terms();
            run.constrained = Some(terms.in_place_map(&run.map));
            run.terms = Some(terms);
        }
        let map = &run.map;
        let terms = run.terms.as_ref().filter(|_| constraint.is_some());
        let constrained = run
            .constrained
            .as_ref()
            .filter(|_| terms.is_some())
            .map(|(map, gains)| (map, &gains[..]));
        let plain = || {
            GridQueries::new(map, (&self.cols, &self.rows), size, wrap)
                .transformed(self.wavelet.as_ref())
        };
        let before = run.progress.visits();
        let done = self.matcher.resume(
            &mut plain()
                .constrained(terms, space.weights())
                .constrained_in_place(constrained),
            &objective,
            grid,
            (&mut self.matches, &mut self.objective),
            rng,
            &mut run.progress,
            *budget,
        );
        *budget = budget.saturating_sub(run.progress.visits() - before);
        if !done {
            self.running = Some(run);
            return None;
        }
        if constraint.is_none() {
            // Costs are distance + penalty of the match (accepted candidates have full sums).
            for ((d, &cost), &m) in self
                .distances
                .iter_mut()
                .zip(&self.objective)
                .zip(&self.matches)
            {
                *d = cost - occurrence.map_or(0.0, |o| o.penalty(m));
            }
        }
        // Under a constraint the IRLS weights and the reported energy are about the texture
        // term alone, so the distances are measured again without it.
        self.measure_distances(map, constraint.is_some());
        if run.occurrence.is_some() {
            self.occurrence_kept = run.occurrence.take();
        }
        self.refresh_local();
        self.settle();
        Some(run.progress.changed())
    }

    /// The IRLS weights of the distances just found and their texture energy
    /// ([`robust_weights`]), once per M-step.
    pub(super) fn settle(&mut self) {
        self.texture_sum = robust_weights(&self.distances, self.setup.r, &mut self.robust);
    }

    /// The occurrence penalty for this M-step (None when it is off, or before the level's first
    /// M-step, when there are no distances to scale it by).
    fn occurrence(&mut self) -> Option<Occurrence> {
        let alpha = self.setup.completeness;
        if alpha <= 0.0 || self.distances.iter().any(|d| !d.is_finite()) {
            return None;
        }
        let mean = self.distances.iter().map(|&d| f64::from(d)).sum::<f64>()
            / self.distances.len().max(1) as f64;
        let ex = self.matcher.space().exemplar();
        let share = strength(
            ex.width * ex.height,
            self.setup.output_width * self.setup.output_height,
        );
        // Every node sees the same coverage in an M-step, so the nodes on an over-used part
        // of the exemplar all leave it at once for the same under-used part, which is then
        // over-used: matches and energy see-saw from one iteration to the next. Averaging the
        // coverage with the last M-step's damps the swing (paving_128: 3430 -> 1746 matches
        // changed in the last iteration, and the energy falls at every iteration).
        let extent = (ex.width, ex.height);
        let remember = self.occurrence_kept.is_some();
        let mut occurrence = self.occurrence_kept.take().unwrap_or_default();
        occurrence.rebuild(
            &self.matches,
            (self.setup.size, self.setup.spacing),
            extent,
            alpha * share * mean as f32,
            remember,
        );
        Some(occurrence)
    }

    /// The texture energy sum_p d_p^(r/2) of the pixel term ||x_p - z_p||^2 (also with a
    /// wavelet energy, so that the energies compare on one plot), normalised by the number of
    /// neighbourhoods and the pixels in each (so that levels compare, as in the paper's Fig. 3).
    #[must_use]
    pub fn energy(&self) -> f64 {
        if self.wavelet.is_some() {
            self.normalised(&self.pixel_distances)
        } else {
            self.match_energy()
        }
    }

    /// Whether the matches minimise a wavelet energy (then [`LevelSolver::match_energy`]
    /// differs from [`LevelSolver::energy`]).
    #[must_use]
    pub fn has_wavelet(&self) -> bool {
        self.wavelet.is_some()
    }

    /// The energy the M-step minimised, normalised like [`LevelSolver::energy`]: with a wavelet
    /// energy, the pixel term plus the weighted wavelet term (eq. 4); otherwise the same as
    /// [`LevelSolver::energy`].
    #[must_use]
    pub fn match_energy(&self) -> f64 {
        self.texture_sum / (self.distances.len() * self.setup.size * self.setup.size) as f64
    }

    fn normalised(&self, distances: &[f32]) -> f64 {
        let half_r = f64::from(self.setup.r) / 2.0;
        let total: f64 = distances
            .iter()
            .map(|&d| crate::core::math::pow(f64::from(d), half_r))
            .sum();
        total / (distances.len() * self.setup.size * self.setup.size) as f64
    }
}

/// `output` resized to the level's size when it is not already (coarse to fine up-sampling).
pub fn fit_output(output: Image, setup: &LevelSetup) -> Result<Image> {
    if output.width() == setup.output_width && output.height() == setup.output_height {
        Ok(output)
    } else {
        resize_bilinear(
            &output,
            setup.output_width,
            setup.output_height,
            edge(setup.wrap),
        )
    }
}
