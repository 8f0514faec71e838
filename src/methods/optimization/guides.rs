//! The guides of guided synthesis at every level (see `session/guides.rs`, which sets them):
//! each level's solver appends them to the exemplar's neighbourhoods and to the queries.

use super::level::{LevelSetup, LevelSolver};
use crate::core::{Image, Rng};

/// The guides at every octave, and the weight of their term.
pub struct Guides {
    /// The source guide's Gaussian pyramid, index = octave.
    pub source: Vec<Image>,
    /// The target guide's.
    pub target: Vec<Image>,
    /// The weight of the guide term.
    pub weight: f32,
}

impl Guides {
    /// A level solver over `exemplar` at `octave` with the guides' term.
    pub fn level_solver(
        &self,
        exemplar: &Image,
        setup: LevelSetup,
        octave: usize,
        rng: &mut Rng,
    ) -> LevelSolver {
        let guides = (&self.source[octave], self.target[octave].clone());
        LevelSolver::guided(exemplar, setup, guides, self.weight, rng)
    }
}

