//! The options of inpainting (and uncrop): the graph-cut fill's patches, then the texture
//! optimisation's levels. Defaults are the library's (see `docs/methods/inpainting.md`).

use crate::core::budget::{DEFAULT_MEMORY_BUDGET_MIB, validate_budget};
use crate::core::{Error, Result};
use crate::methods::optimization;
use crate::solvers::nn::Search;

/// Everything an inpainting can be told. Validate with [`Options::validate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Seed of every random choice. Default: 1.
    pub seed: u64,
    /// Side of the graph-cut fill's patches, in pixels (at most the image's shorter side is
    /// used). Default: 32.
    pub patch_size: usize,
    /// Randomness k of the fill's source choice, probability exp(-C / (k sigma^2)) (Kwatra et
    /// al. 2003, eq. 3). Default: 0.01, graph cut's.
    pub k: f32,
    /// Resolution levels of the texture optimisation that follows. Default: 1 (with two
    /// neighbourhood sizes): the fill has laid the structure, and coarser levels break it up
    /// again (a wall's window continued by the fill came out as scattered frame pieces).
    pub levels: usize,
    /// Its neighbourhood widths, largest first. Default: [16, 8].
    pub neighbourhood_sizes: Vec<usize>,
    /// Its cap on EM iterations per level. Default: 5.
    pub iterations: usize,
    /// Its robust exponent r. Default: 2, least squares: the robust weights of r < 2 weigh
    /// down the neighbourhoods that straddle the hole's boundary (they fit worst), so the pixels
    /// next to the known ones follow the hole's inside and a seam shows (seam score, 12 samples
    /// with 25% holes: mean |ln| 0.54 at r = 0.8, 0.37 at r = 2).
    pub r: f32,
    /// Its nearest-neighbourhood search. Default: PatchMatch.
    pub search: Search,
    /// How far each E-step moves the filled pixels to the colour histogram of the known pixels
    /// around the hole (0 to 1; the known pixels are not moved). Without it EM averages the
    /// hole's neighbourhoods into the exemplar's smooth areas (a 40% hole in paving_128 turns
    /// flat); against the whole image's histogram, a wall's windows are pressed into the hole
    /// as bright fragments. Default: 1.
    pub histogram_matching: f32,
    /// Weight of the occurrence penalty that spreads the hole's matches over the exemplar (see
    /// texture optimisation's `completeness`). Default: 1.
    pub completeness: f32,
    /// Whether the texture optimisation runs at all; without it the fill is the result.
    /// Default: true.
    pub optimize: bool,
    /// The memory budget in MiB. Default: 1024.
    pub memory_budget_mib: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            seed: 1,
            patch_size: 32,
            k: 0.01,
            levels: 1,
            neighbourhood_sizes: vec![16, 8],
            iterations: 5,
            r: 2.0,
            search: Search::PatchMatch,
            histogram_matching: 1.0,
            completeness: optimization::options::DEFAULT_COMPLETENESS,
            optimize: true,
            memory_budget_mib: DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

impl Options {
    /// Checks the fill's options (the optimisation's are checked by its own options); the
    /// error names the option.
    pub fn validate(&self) -> Result<()> {
        let invalid =
            |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        validate_budget(self.memory_budget_mib)?;
        if !(4..=256).contains(&self.patch_size) {
            return invalid(
                "patchSize",
                format!("must be between 4 and 256, got {}", self.patch_size),
            );
        }
        if !self.k.is_finite() || self.k <= 0.0 || self.k > 1000.0 {
            return invalid("k", format!("must be in (0, 1000], got {}", self.k));
        }
        Ok(())
    }

    /// The largest neighbourhood width: the margin of known pixels the optimisation works on.
    #[must_use]
    pub fn margin(&self) -> usize {
        self.neighbourhood_sizes.iter().copied().max().unwrap_or(8)
    }
}
