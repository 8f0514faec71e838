//! The texture-optimisation session (Kwatra et al. 2005, Algorithm 1 with sections 3.1 and 3.2):
//! a state machine whose `step()` runs one EM iteration of the planned schedule.

use super::e_step::{Matches, e_step, edge, robust_weight};
use super::features::{feature_map, gather};
use super::m_step::Matcher;
use super::options::Options;
use super::schedule::{Level, grid_axis, nearest_corner, plan};
use crate::core::pyramid::gaussian_pyramid;
use crate::core::sample::resize_bilinear;
use crate::core::{Edge, Image, Result, Rng};
use crate::solvers::nn::Pos;
use crate::solvers::nn::patches::gaussian_falloff;
use crate::solvers::nn::patchmatch::QueryGrid;

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
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
    pub kind: EventKind,
    /// Index of the synthesis level in the schedule, 0-based.
    pub level: usize,
    pub level_count: usize,
    /// Resolution index: 0 is full resolution, k is down-sampled k times (1/2^k).
    pub octave: usize,
    pub size: usize,
    /// Iteration within the level, 1-based.
    pub iteration: usize,
    /// Texture energy sum_p ||x_p - z_p||^r, normalised by the number of neighbourhoods and the
    /// pixels in each (so levels compare, as in the paper's Fig. 3).
    pub energy: f64,
    /// Matches z_p that changed in this iteration's M-step.
    pub changed: usize,
    /// Total EM iterations so far.
    pub total_iterations: usize,
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
    state: Option<LevelState>,
    history: Vec<EnergyPoint>,
    last: Option<Event>,
}

/// What a level needs between iterations.
struct LevelState {
    matcher: Matcher,
    cols: Vec<usize>,
    rows: Vec<usize>,
    matches: Vec<Pos>,
    distances: Vec<f32>,
    falloff: Vec<f32>,
    queries: Vec<f32>,
    /// True until the first M-step of the level ran on the up-sampled output.
    fresh: bool,
}

impl Session {
    /// Validates the options against the exemplar and plans the schedule.
    pub fn new(exemplar: &Image, options: Options) -> Result<Session> {
        options.validate(exemplar.width(), exemplar.height())?;
        let levels = plan(exemplar.width(), exemplar.height(), &options)?;
        let octaves = levels.iter().map(|l| l.octave).max().unwrap_or(0) + 1;
        let exemplars = gaussian_pyramid(exemplar, octaves, Edge::Clamp)?;
        Ok(Session {
            rng: Rng::new(options.seed),
            options,
            levels,
            exemplars,
            level: 0,
            iteration: 0,
            output: None,
            state: None,
            history: Vec::new(),
            last: None,
        })
    }

    #[must_use]
    pub fn options(&self) -> &Options {
        &self.options
    }

    #[must_use]
    pub fn schedule(&self) -> &[Level] {
        &self.levels
    }

    #[must_use]
    pub fn is_done(&self) -> bool {
        self.level >= self.levels.len()
    }

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
        self.state
            .as_ref()
            .map(|s| (s.cols.as_slice(), s.rows.as_slice(), s.matches.as_slice()))
    }

    /// The current output up-sampled to the full output size (coarse levels look blocky-smooth).
    pub fn output_full_size(&self) -> Result<Image> {
        let (w, h) = (self.options.output_width, self.options.output_height);
        match &self.output {
            Some(out) if out.width() == w && out.height() == h => Ok(out.clone()),
            Some(out) => resize_bilinear(out, w, h, edge(self.options.tileable)),
            None => Image::new(w, h, self.exemplars[0].channels()),
        }
    }

    /// Runs one EM iteration and reports it.
    pub fn step(&mut self) -> Result<Event> {
        if self.is_done() {
            let mut last = self.last.expect("a finished session has stepped");
            last.kind = EventKind::Done;
            return Ok(last);
        }
        let kind = if self.iteration == 0 {
            self.enter_level()?;
            EventKind::Level
        } else {
            EventKind::Iteration
        };
        let changed = self.iterate()?;
        self.iteration += 1;
        let energy = self.energy();
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
            changed,
            total_iterations: self.history.len(),
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

    /// Sets up the level `self.level`: its exemplar neighbourhoods and search structure, its grid,
    /// the output at its resolution, and matches carried over from the previous level.
    fn enter_level(&mut self) -> Result<()> {
        let lv = self.levels[self.level];
        let wrap = self.options.tileable;
        let exemplar = &self.exemplars[lv.octave];
        let matcher = Matcher::new(
            feature_map(exemplar, self.options.mu, Edge::Clamp),
            lv.size,
            self.options.search,
            &mut self.rng,
        );
        let cols = grid_axis(lv.output_width, lv.size, lv.spacing, wrap);
        let rows = grid_axis(lv.output_height, lv.size, lv.spacing, wrap);
        let (ex_nx, ex_ny) = matcher.space().extent();
        let previous = self.level.checked_sub(1).map(|i| self.levels[i]);
        let matches: Vec<Pos> = match (&self.state, previous) {
            (Some(old), Some(prev)) => {
                // Carry each node's match over: find the old node nearest to the new node's
                // centre, follow its match, and rescale to this level's exemplar.
                let sx = lv.exemplar_width as f64 / prev.exemplar_width as f64;
                let sy = lv.exemplar_height as f64 / prev.exemplar_height as f64;
                let ox = prev.output_width as f64 / lv.output_width as f64;
                let oy = prev.output_height as f64 / lv.output_height as f64;
                let half_old = prev.size as f64 / 2.0;
                let half_new = lv.size as f64 / 2.0;
                let old_nx = old.cols.len();
                let mut carried = Vec::with_capacity(cols.len() * rows.len());
                for &y in &rows {
                    for &x in &cols {
                        let (cx, cy) = ((x as f64 + half_new) * ox, (y as f64 + half_new) * oy);
                        let i = nearest_corner(&old.cols, cx - half_old);
                        let j = nearest_corner(&old.rows, cy - half_old);
                        let z = old.matches[j * old_nx + i];
                        let zx = (f64::from(z.x) + cx - old.cols[i] as f64) * sx - half_new;
                        let zy = (f64::from(z.y) + cy - old.rows[j] as f64) * sy - half_new;
                        carried.push(matcher.space().clamp(zx.round() as i64, zy.round() as i64));
                    }
                }
                carried
            }
            // Bootstrap: a random neighbourhood for every node.
            _ => (0..cols.len() * rows.len())
                .map(|_| Pos::new(self.rng.index(ex_nx), self.rng.index(ex_ny)))
                .collect(),
        };
        if let Some(out) = &self.output {
            if out.width() != lv.output_width || out.height() != lv.output_height {
                self.output = Some(resize_bilinear(
                    out,
                    lv.output_width,
                    lv.output_height,
                    edge(wrap),
                )?);
            }
        }
        let nodes = matches.len();
        let len = matcher.space().vector_len();
        self.state = Some(LevelState {
            falloff: gaussian_falloff(lv.size, 1),
            queries: vec![0.0; nodes * len],
            distances: vec![f32::INFINITY; nodes],
            matcher,
            cols,
            rows,
            matches,
            fresh: self.output.is_some(),
        });
        Ok(())
    }

    /// One EM iteration: (on a fresh level, an M-step on the up-sampled output first), E-step
    /// with IRLS weights, M-step. Returns how many matches changed in the final M-step.
    fn iterate(&mut self) -> Result<usize> {
        let lv = self.levels[self.level];
        let (r, mu, wrap) = (self.options.r, self.options.mu, self.options.tileable);
        let exemplar = &self.exemplars[lv.octave];
        let state = self.state.as_mut().expect("level entered");
        if state.fresh {
            let out = self.output.as_ref().expect("fresh levels have an output");
            m_step(state, out, mu, wrap, &mut self.rng);
            state.fresh = false;
        }
        let output = match &mut self.output {
            Some(out) => out,
            none => none.insert(Image::new(
                lv.output_width,
                lv.output_height,
                exemplar.channels(),
            )?),
        };
        // IRLS: weights from the current distances (all 1 on the bootstrap iteration).
        let weights: Vec<f32> = state
            .distances
            .iter()
            .map(|&d| {
                if d.is_finite() {
                    robust_weight(d, r)
                } else {
                    1.0
                }
            })
            .collect();
        let m = Matches {
            exemplar,
            cols: &state.cols,
            rows: &state.rows,
            matches: &state.matches,
            node_weights: &weights,
            falloff: &state.falloff,
            size: lv.size,
            wrap,
            mu,
        };
        e_step(&m, output);
        Ok(m_step(state, output, mu, wrap, &mut self.rng))
    }

    /// sum_p d_p^(r/2) / (nodes * w^2), from the distances of the last M-step.
    fn energy(&self) -> f64 {
        let state = self.state.as_ref().expect("level entered");
        let half_r = f64::from(self.options.r) / 2.0;
        let total: f64 = state
            .distances
            .iter()
            .map(|&d| f64::from(d).powf(half_r))
            .sum();
        let size = self.levels[self.level.min(self.levels.len() - 1)].size;
        total / (state.distances.len() * size * size) as f64
    }
}

/// Gathers the output neighbourhoods and runs the matcher on them.
fn m_step(state: &mut LevelState, output: &Image, mu: f32, wrap: bool, rng: &mut Rng) -> usize {
    let map = feature_map(output, mu, edge(wrap));
    let size = state.matcher.space().size();
    let len = state.matcher.space().vector_len();
    let nx = state.cols.len();
    for (n, query) in state.queries.chunks_exact_mut(len).enumerate() {
        gather(
            &map,
            state.cols[n % nx],
            state.rows[n / nx],
            size,
            wrap,
            query,
        );
    }
    let grid = QueryGrid {
        cols: &state.cols,
        rows: &state.rows,
    };
    state.matcher.m_step(
        &state.queries,
        grid,
        &mut state.matches,
        &mut state.distances,
        rng,
    )
}
