//! Options of graph-cut texture synthesis. Only `k` defaults to a value of the paper; the other
//! defaults are the library's (docs/methods/graphcut.md gives each one's reason).

use crate::core::{Error, Result, error::check_size};

/// How the next patch offset is chosen (Kwatra et al. 2003, section 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Placement {
    /// A random unused offset whose patch covers the error region. Fastest; good for random
    /// textures.
    Random,
    /// Area-normalised SSD of the whole patch against the covered output (eq. 2), offset drawn
    /// with probability exp(-C / (k sigma^2)) (eq. 3). Best for structured textures.
    #[default]
    EntirePatch,
    /// SSD of the input against the output sub-patch around the error region only (eq. 4).
    SubPatch,
}

impl Placement {
    /// The name used in options ("random", "entire-patch", "sub-patch").
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Placement::Random => "random",
            Placement::EntirePatch => "entire-patch",
            Placement::SubPatch => "sub-patch",
        }
    }

    /// The placement of that name (see [`Placement::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Placement> {
        [
            Placement::Random,
            Placement::EntirePatch,
            Placement::SubPatch,
        ]
        .into_iter()
        .find(|p| p.name() == name)
    }
}

/// How the final image is smoothed across seams (section 5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Blend {
    /// Pixels exactly as cut.
    #[default]
    None,
    /// Gaussian-weighted mix of the patches that meet near a seam.
    Feather,
    /// Burt-Adelson multi-resolution splining of the patches along their cut masks.
    Spline,
}

impl Blend {
    /// The name used in options ("none", "feather", "spline").
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Blend::None => "none",
            Blend::Feather => "feather",
            Blend::Spline => "spline",
        }
    }

    /// The blending of that name (see [`Blend::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Blend> {
        [Blend::None, Blend::Feather, Blend::Spline]
            .into_iter()
            .find(|b| b.name() == name)
    }
}

/// Extra versions of the exemplar patches may come from (section 6.A).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Transforms {
    /// The exemplar rotated by 90, 180 and 270 degrees.
    pub rotate: bool,
    /// The exemplar mirrored left-right and top-bottom.
    pub mirror: bool,
    /// The exemplar scaled by these factors (besides 1), e.g. [0.5, 0.75].
    pub scales: [Option<f32>; 4],
    /// Perspective: the scale of the source used varies monotonically from the top row of the
    /// output (smallest scale) to the bottom row (scale 1). Needs `scales`.
    pub perspective: bool,
}

/// Everything a graph-cut synthesis can be told. Validate with [`Options::validate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Output width in pixels. Default: 256.
    pub output_width: usize,
    /// Output height in pixels. Default: 256.
    pub output_height: usize,
    /// Seed of every random choice. Default: 1.
    pub seed: u64,
    /// How offsets are chosen. Default: entire-patch matching.
    pub placement: Placement,
    /// Randomness of the offset choice, k in exp(-C / (k sigma^2)); the paper varies it between
    /// 0.001 and 1. Default: 0.01.
    pub k: f32,
    /// Side of the error region (and of the output sub-patch for sub-patch matching), in pixels;
    /// 0 picks a third of the exemplar's shorter side. Default: 0.
    pub error_region: usize,
    /// Patches placed after the output is fully covered, to overwrite the worst seams. Default: 24.
    pub refinement_patches: usize,
    /// Use the gradient-scaled matching cost M' (eq. 5). Default: false.
    pub gradient_cost: bool,
    /// Smoothing of the final image across seams. Default: none.
    pub blend: Blend,
    /// Rotated / mirrored / scaled exemplars as extra sources. Default: none.
    pub transforms: Transforms,
    /// Periodic output: costs and overlaps wrap around, so the result tiles. Default: false.
    pub tileable: bool,
    /// The memory budget in MiB (see `crate::core::budget`): the constructor refuses an
    /// output whose working set would exceed it. Default: 1024.
    pub memory_budget_mib: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            output_width: 256,
            output_height: 256,
            seed: 1,
            placement: Placement::EntirePatch,
            k: 0.01,
            error_region: 0,
            refinement_patches: 24,
            gradient_cost: false,
            blend: Blend::None,
            transforms: Transforms::default(),
            tileable: false,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

/// The smallest exemplar side accepted.
pub const MIN_EXEMPLAR_SIDE: usize = 8;

impl Options {
    /// Checks every option on its own and against the exemplar size; the error names the option.
    pub fn validate(&self, exemplar_width: usize, exemplar_height: usize) -> Result<()> {
        let invalid =
            |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        check_size("output", self.output_width, self.output_height)?;
        crate::core::budget::validate_budget(self.memory_budget_mib)?;
        if exemplar_width < MIN_EXEMPLAR_SIDE || exemplar_height < MIN_EXEMPLAR_SIDE {
            return Err(Error::InvalidSize {
                what: "exemplar",
                width: exemplar_width,
                height: exemplar_height,
                reason: format!(
                    "graph-cut synthesis needs at least {MIN_EXEMPLAR_SIDE}x{MIN_EXEMPLAR_SIDE}"
                ),
            });
        }
        if !self.k.is_finite() || self.k <= 0.0 || self.k > 100.0 {
            return invalid("k", format!("must be in (0, 100], got {}", self.k));
        }
        let shorter = exemplar_width.min(exemplar_height);
        if self.error_region > shorter {
            return invalid(
                "errorRegion",
                format!(
                    "must be at most the exemplar's shorter side ({shorter}), got {}",
                    self.error_region
                ),
            );
        }
        if self.refinement_patches > 10_000 {
            return invalid(
                "refinementPatches",
                format!("must be at most 10000, got {}", self.refinement_patches),
            );
        }
        for scale in self.transforms.scales.iter().flatten() {
            if !scale.is_finite() || *scale < 0.25 || *scale > 4.0 {
                return invalid(
                    "scales",
                    format!("each scale must be between 0.25 and 4, got {scale}"),
                );
            }
            let (w, h) = (
                (exemplar_width as f32 * scale) as usize,
                (exemplar_height as f32 * scale) as usize,
            );
            if w < MIN_EXEMPLAR_SIDE || h < MIN_EXEMPLAR_SIDE {
                return invalid(
                    "scales",
                    format!(
                        "scale {scale} makes the exemplar smaller than {MIN_EXEMPLAR_SIDE} pixels"
                    ),
                );
            }
        }
        if self.transforms.perspective && self.transforms.scales.iter().all(Option::is_none) {
            return invalid("perspective", "needs at least one entry in scales".into());
        }
        Ok(())
    }

    /// The side of the region a patch must cover while the output is being covered, and where
    /// that region sits: the fraction of its side that lies before the first uncovered pixel.
    ///
    /// Entire-patch matching (eq. 2) only uses the region to say where the patch goes, so a
    /// region two thirds of the patch wide, with the first uncovered pixel a quarter of the way
    /// in, makes every patch reach well past the growth front: it overlaps what is made by a
    /// band of 1/6 to 1/2 of its side (all of 1/3 to 5/6 before). Each placement then extends the
    /// texture by about twice as much: on 16 samples at 256x256, seeds 1-2, 15% fewer patches,
    /// 13% lower total seam cost, coherence 2.5% and completeness 10% better, and at 1024x1024
    /// 178 placements instead of 328, each with a smaller graph.
    ///
    /// Sub-patch matching (eq. 4) matches the region itself against the exemplar, so the region
    /// keeps its side (widening it too made completeness 17% worse), but it too has the first
    /// uncovered pixel a quarter of the way in rather than at its centre: a quarter of the
    /// region is made texture to match, and the patch around it reaches further past the front.
    /// On the 32 samples at 256x256, seeds 1-3 (geometric means of after / before): 8% fewer
    /// patches, 7% lower total seam cost, completeness 13% and histogram 10% better, coherence
    /// and flat fraction the same; at 1024x1024 from tiles_128 238 placements instead of 308.
    ///
    /// An error region the caller sets keeps the centred square of the paper.
    ///
    /// `smallest_patch` is the shorter side of the smallest source's patch (transforms add
    /// smaller sources): every source allowed there must be able to cover the region.
    #[must_use]
    pub fn fill_region(
        &self,
        exemplar_width: usize,
        exemplar_height: usize,
        smallest_patch: usize,
    ) -> (usize, f32) {
        let side = self.error_region_side(exemplar_width, exemplar_height);
        match (self.placement, self.error_region) {
            (Placement::EntirePatch, 0) => {
                let front = (2 * smallest_patch / 3)
                    .max(side)
                    .min(self.output_width)
                    .min(self.output_height);
                (front, 0.25)
            }
            (Placement::SubPatch, 0) => (side, 0.25),
            _ => (side, 0.5),
        }
    }

    /// The error-region side actually used.
    #[must_use]
    pub fn error_region_side(&self, exemplar_width: usize, exemplar_height: usize) -> usize {
        let shorter = exemplar_width.min(exemplar_height);
        let side = if self.error_region == 0 {
            (shorter / 3).max(4)
        } else {
            self.error_region
        };
        side.min(self.output_width)
            .min(self.output_height)
            .min(shorter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_bad_options_are_named() {
        assert!(Options::default().validate(64, 64).is_ok());
        let msg = |o: Options| o.validate(64, 64).unwrap_err().to_string();
        let d = Options::default;
        assert!(msg(Options { k: 0.0, ..d() }).contains("invalid k"));
        assert!(msg(Options { k: f32::NAN, ..d() }).contains("invalid k"));
        assert!(
            msg(Options {
                error_region: 65,
                ..d()
            })
            .contains("errorRegion")
        );
        assert!(
            msg(Options {
                output_height: 0,
                ..d()
            })
            .contains("output size")
        );
        let scales = Transforms {
            scales: [Some(0.1), None, None, None],
            ..Transforms::default()
        };
        assert!(
            msg(Options {
                transforms: scales,
                ..d()
            })
            .contains("scales")
        );
        let persp = Transforms {
            perspective: true,
            ..Transforms::default()
        };
        assert!(
            msg(Options {
                transforms: persp,
                ..d()
            })
            .contains("perspective")
        );
        assert!(
            Options::default()
                .validate(4, 64)
                .unwrap_err()
                .to_string()
                .contains("exemplar size 4x64")
        );
        assert_eq!(Options::default().error_region_side(128, 96), 32);
    }
}
