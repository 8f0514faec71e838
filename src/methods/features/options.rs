//! The options of feature-guided synthesis: how patches are laid down (graph-cut placement or the
//! paper's scan order), the weights and counts of the matching, and their validation.

use super::detect::DetectOptions;
use crate::core::error::check_size;
use crate::core::{Error, Result};
use crate::methods::design::deform::Deformation;
use crate::methods::graphcut::overlap::check_scan_geometry;

/// How the patches are laid down.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FeaturePlacement {
    /// Graph-cut textures' placement (whole exemplar, error region, seam memory, refinement
    /// patches) with the offset chosen by colour SSD plus the feature cost of eq. 2 over the band
    /// where the patch meets the made output, and a seam that also pays for cutting through
    /// curves the two patches do not share (`hybrid`). No warp.
    #[default]
    Graphcut,
    /// The paper's: `patch_size` patches in scan order over an L-shaped context, warped.
    Scan,
}

impl FeaturePlacement {
    /// The name used in options ("graphcut", "scan").
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            FeaturePlacement::Graphcut => "graphcut",
            FeaturePlacement::Scan => "scan",
        }
    }

    /// The placement of that name (see [`FeaturePlacement::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<FeaturePlacement> {
        [FeaturePlacement::Graphcut, FeaturePlacement::Scan]
            .into_iter()
            .find(|p| p.name() == name)
    }
}

/// Options of feature-guided synthesis.
#[derive(Debug, Clone, PartialEq)]
pub struct FeatureOptions {
    /// Output size. Default: 256x256.
    pub output_width: usize,
    /// Output height in pixels. Default: 256.
    pub output_height: usize,
    /// How patches are laid down. Default: graph-cut placement.
    pub placement: FeaturePlacement,
    /// Graph-cut placement: the seam cost per pixel where the two patches disagree on a feature,
    /// in units of the exemplar's feature contrast (the mean colour step across its feature
    /// curves, see `hybrid::feature_step`): 1 prices a broken feature like a visible cut across
    /// one. Default: 1.
    pub seam_feature_weight: f32,
    /// Patch side (scan placement; graph-cut placement uses the whole exemplar, and the
    /// feature-cost band is as wide as the scan overlap). Default (`None`): `DEFAULT_PATCH`,
    /// or the exemplar's shorter side when that is smaller, so that an exemplar of 16 to 63
    /// pixels works without options, as it does in graph cut; see [`FeatureOptions::fitted`].
    pub patch_size: Option<usize>,
    /// Width of the context region. Default (None): a quarter of the patch, so the context
    /// holds enough feature pixels to match.
    pub overlap: Option<usize>,
    /// Weight of the feature cost against the colour SSD. Default: 0.5 (the paper's).
    pub feature_weight: f32,
    /// Bend each patch onto the context's features (section 2.2). Default: true. Only the scan
    /// placement warps: graph-cut placement's events report
    /// [`crate::features::WarpKind::Unavailable`].
    pub warp: bool,
    /// Candidates within (1 + tolerance) of the best total cost are drawn at random. Default: 0.1.
    pub tolerance: f32,
    /// Candidates, the best by colour SSD, whose feature cost is computed (the colour SSD of every
    /// translation comes from one FFT; the feature cost is per candidate). Default (`None`): 64
    /// for graph-cut placement, whose 2 s budget also pays for graph cut's own search and
    /// min-cut (64 and 256 give the same coherence and broken-feature counts over three seeds),
    /// and 256 for scan placement.
    pub feature_candidates: Option<usize>,
    /// Extra inputs: deformed copies of the exemplar (the paper adds rotated and reflected ones
    /// for some textures). Default: none.
    pub extra_inputs: Vec<Deformation>,
    /// How the feature maps of the exemplar and the extra inputs are detected (kind, threshold
    /// percentile, alpha). Default: ridges, 0.9, 0.3.
    pub detect: DetectOptions,
    /// Seed of every random choice (the candidate drawn, graph-cut placement's offsets).
    /// Default: 1.
    pub seed: u64,
    /// The memory budget in MiB (see `crate::core::budget`): the constructor refuses an
    /// output whose working set would exceed it. Default: 1024.
    pub memory_budget_mib: usize,
}

/// The default patch side: the top of the paper's 32 to 64. On the six structured samples
/// (128x128 to 256x256) it broke the fewest features (fewer than plain graph cut on 5 of 6,
/// against 4 of 6 at 32 and 3 of 6 at 48).
pub const DEFAULT_PATCH: usize = 64;

/// The smallest patch side, and so the smallest exemplar side.
pub const MIN_PATCH: usize = 16;

impl FeatureOptions {
    /// The patch side: the option, or `DEFAULT_PATCH` before [`FeatureOptions::fitted`].
    #[must_use]
    pub fn patch(&self) -> usize {
        self.patch_size.unwrap_or(DEFAULT_PATCH)
    }

    /// These options with the default patch side fitted to a `ew` x `ew` exemplar: the
    /// exemplar's shorter side when it is under `DEFAULT_PATCH`. A patch side the caller chose
    /// is kept (and `FeatureOptions::validate` refuses it if it does not fit).
    #[must_use]
    pub fn fitted(mut self, ew: usize, eh: usize) -> Self {
        if self.patch_size.is_none() {
            self.patch_size = Some(DEFAULT_PATCH.min(ew.min(eh)));
        }
        self
    }

    /// How many candidates get the feature cost: the option, or its default for the placement.
    #[must_use]
    pub fn candidates(&self) -> usize {
        self.feature_candidates.unwrap_or(match self.placement {
            FeaturePlacement::Graphcut => 64,
            FeaturePlacement::Scan => 256,
        })
    }
}

impl Default for FeatureOptions {
    fn default() -> Self {
        FeatureOptions {
            output_width: 256,
            output_height: 256,
            placement: FeaturePlacement::Graphcut,
            seam_feature_weight: 1.0,
            patch_size: None,
            overlap: None,
            feature_weight: 0.5,
            warp: true,
            tolerance: 0.1,
            feature_candidates: None,
            extra_inputs: Vec::new(),
            detect: DetectOptions::default(),
            seed: 1,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

impl FeatureOptions {
    /// The context-region width (scan), or the feature-cost band's (graph cut): the option, or
    /// a quarter of the patch side, at least 2.
    #[must_use]
    pub fn zone(&self) -> usize {
        self.overlap.unwrap_or((self.patch() / 4).max(2))
    }

    /// Checks the options against a `ew` x `eh` exemplar (after [`FeatureOptions::fitted`]).
    pub(super) fn validate(&self, ew: usize, eh: usize) -> Result<()> {
        check_size("output", self.output_width, self.output_height)?;
        crate::core::budget::validate_budget(self.memory_budget_mib)?;
        if ew.min(eh) < MIN_PATCH {
            return Err(Error::InvalidSize {
                what: "exemplar",
                width: ew,
                height: eh,
                reason: format!(
                    "feature-guided synthesis needs at least {MIN_PATCH}x{MIN_PATCH} (its smallest patch)"
                ),
            });
        }
        let patch = self.patch();
        if !(MIN_PATCH..=128).contains(&patch) {
            return Err(Error::InvalidParameter {
                name: "patchSize",
                reason: format!("must be between {MIN_PATCH} and 128, got {patch}"),
            });
        }
        if patch > ew.min(eh) {
            return Err(Error::InvalidParameter {
                name: "patchSize",
                reason: format!("{patch} is larger than the {ew}x{eh} exemplar"),
            });
        }
        if self.placement == FeaturePlacement::Scan {
            check_scan_geometry(self.output_width, self.output_height, patch, self.zone(), 2)?;
        } else if 2 * self.zone() >= patch || self.zone() < 2 {
            return Err(Error::InvalidParameter {
                name: "overlap",
                reason: format!(
                    "must be between 2 and {} for patches of {patch}, got {}",
                    (patch - 1) / 2,
                    self.zone()
                ),
            });
        }
        for (name, v, hi) in [
            ("featureWeight", self.feature_weight, 1.0),
            ("tolerance", self.tolerance, 10.0),
            ("seamFeatureWeight", self.seam_feature_weight, 100.0),
        ] {
            if !v.is_finite() || !(0.0..=hi).contains(&v) {
                return Err(Error::InvalidParameter {
                    name,
                    reason: format!("must be between 0 and {hi}, got {v}"),
                });
            }
        }
        if let Some(n) = self.feature_candidates
            && !(1..=100_000).contains(&n)
        {
            return Err(Error::InvalidParameter {
                name: "featureCandidates",
                reason: format!("must be between 1 and 100000, got {n}"),
            });
        }
        if self.extra_inputs.len() > 8 {
            return Err(Error::InvalidParameter {
                name: "extraInputs",
                reason: format!("at most 8, got {}", self.extra_inputs.len()),
            });
        }
        self.detect.validate()
    }
}
