//! The options of texture optimisation. The defaults of `levels`, `neighbourhood_sizes`,
//! `iterations` and `r` are the paper's; those of `mu`, `m_step_mu`, `search`, `start`,
//! `completeness` and `histogram_matching` differ from it, for the reasons the method page
//! (`docs/methods/optimization.md`) gives.

use crate::core::budget::{DEFAULT_MEMORY_BUDGET_MIB, validate_budget};
use crate::core::{Error, Result, error::check_size};
use crate::solvers::nn::Search;

pub use super::initial::Start;
pub use super::wavelet_energy::{DEFAULT_DETAIL_WEIGHT, Energy};

/// Everything a texture-optimisation run can be told. Validate with [`Options::validate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Output width in pixels. Default: 256.
    pub output_width: usize,
    /// Output height in pixels. Default: 256.
    pub output_height: usize,
    /// Seed of every random choice (bootstrap, PatchMatch, k-means). Default: 1.
    pub seed: u64,
    /// Resolution levels, coarse to fine, each twice the previous. Default: 3 (section 3.2).
    pub levels: usize,
    /// Neighbourhood widths tried at every level, largest first; those that do not fit the
    /// level's exemplar are skipped. Default: [32, 16, 8] (section 3.2).
    pub neighbourhood_sizes: Vec<usize>,
    /// Cap on EM iterations per (resolution, neighbourhood size) level; a level also ends when
    /// no match changes. Default: 5 (the paper: 3 to 5).
    pub iterations: usize,
    /// Exponent of the robust energy ||x_p - z_p||^r, solved by IRLS; 2 is the plain quadratic
    /// energy. Default: 0.8 (section 3.1).
    pub r: f32,
    /// Weight of the gradient energy mu ||Dx_p - Dz_p||^2; 0 turns it off. Default: 0 (the paper
    /// uses 10 when it is on).
    pub mu: f32,
    /// Weight of the gradient term in the M-step's distance alone (not in the paper, whose EM
    /// minimises one energy in both steps: `Some(mu)` is that). Default `None`: `mu` up to 1,
    /// `DEFAULT_M_STEP_MU` above. At the paper's mu = 10 a search with the same weight
    /// matches by gradient almost alone (each of a pixel's six gradient values weighs ten times
    /// each of its three colour values), so neighbouring matches agree on edges and not on
    /// colour, and the output drifts into colour blotches (carpet_64) or crack-free washes
    /// (paving_128, flat fraction 0.224 for seed 2). At 1 the search compares the plain feature
    /// vector, colour and forward differences alike, while the E-step keeps the paper's
    /// gradient energy (see the README).
    pub m_step_mu: Option<f32>,
    /// Nearest-neighbourhood search of the M-step. Default: PatchMatch, the fastest of the three
    /// and within 2% of the exact search's final energy on the samples (see the benchmark).
    pub search: Search,
    /// Periodic output: neighbourhoods wrap around the borders, so the result tiles. Default: false.
    pub tileable: bool,
    /// Weight of the occurrence penalty that makes the output use all of the exemplar (see
    /// `super::occurrence`; not in the paper); 0 is the paper's M-step. Default: 1.
    pub completeness: f32,
    /// How far each E-step's output is moved to the exemplar's colour histogram, per channel
    /// (see `super::histogram`; not in the paper): 0 is the paper's E-step, 1 matches the
    /// histograms exactly. Without it, averaging neighbourhoods that do not line up washes
    /// out contrast, and EM settles on the exemplar's smooth areas (flat fraction up to 0.95
    /// on paving_128, 0.08-0.17 with it). Default: 1.
    pub histogram_matching: f32,
    /// What the M-step's distance is made of: `pixels` (Kwatra et al. 2005), or the
    /// wavelet-based energy of Shen et al. 2009 (eq. 4) with `haar` or `daubechies` (D4)
    /// coefficients of each neighbourhood (see `super::wavelet_energy`). The wavelet energies
    /// need power-of-two neighbourhood sizes of at least 4, and do not take soft constraints.
    /// Default: pixels.
    pub energy: Energy,
    /// Weight w of the wavelet detail bands in eq. 4 (the approximation band has 1). Both
    /// transforms are orthonormal, so w = 1 is eq. 4 taken literally, which only doubles the
    /// pixel distance (Parseval) and changes no match; w > 1 stresses multi-scale edges over
    /// mean colour. Ignored with the pixel energy. Default: `DEFAULT_DETAIL_WEIGHT`.
    pub wavelet_detail_weight: f32,
    /// How the coarsest level starts (see `super::initial`; the paper starts at random): a
    /// graph-cut synthesis, which keeps lattices and large elements whole, or random exemplar
    /// patches. Default: graph cut.
    pub start: Start,
    /// The memory budget in MiB (see `crate::core::budget`): the constructor refuses an
    /// output whose working set would exceed it. Default: 1024.
    pub memory_budget_mib: usize,
    /// The weight of each exemplar channel in the M-step's distance (see
    /// `super::channel_weights`), one per channel; empty weighs every channel 1. A channel of
    /// weight 0 follows the matches without steering them. Pixel energy only. Default: empty.
    pub channel_weights: Vec<f32>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            output_width: 256,
            output_height: 256,
            seed: 1,
            levels: 3,
            neighbourhood_sizes: vec![32, 16, 8],
            iterations: 5,
            r: 0.8,
            mu: 0.0,
            m_step_mu: None,
            search: Search::PatchMatch,
            tileable: false,
            completeness: DEFAULT_COMPLETENESS,
            histogram_matching: 1.0,
            energy: Energy::Pixels,
            wavelet_detail_weight: DEFAULT_DETAIL_WEIGHT,
            start: Start::Graphcut,
            memory_budget_mib: DEFAULT_MEMORY_BUDGET_MIB,
            channel_weights: Vec::new(),
        }
    }
}

/// The default occurrence-penalty weight. Measured on six samples (128 and 64 -> 256, quality
/// metrics of the README): alpha = 1 cuts the completeness distance by 2x to 9x and the histogram
/// distance by 1.5x to 5x while coherence stays within 5% (better on some), for 10-20% more time;
/// alpha = 0.5 does about half as much, alpha = 2 starts to cost coherence.
pub const DEFAULT_COMPLETENESS: f32 = 1.0;

/// The M-step's gradient weight when `m_step_mu` is not set and `mu` is larger: the weight at
/// which a gradient value counts as much as a colour value in the search.
pub const DEFAULT_M_STEP_MU: f32 = 1.0;

/// The smallest exemplar side accepted.
pub const MIN_EXEMPLAR_SIDE: usize = 16;
/// Iteration caps above this are refused: a level converges long before.
pub const MAX_ITERATIONS: usize = 100;

impl Options {
    /// The gradient weight of the M-step's distance: `m_step_mu` where set, else `mu` up to
    /// `DEFAULT_M_STEP_MU`.
    #[must_use]
    pub fn search_mu(&self) -> f32 {
        self.m_step_mu.unwrap_or(self.mu.min(DEFAULT_M_STEP_MU))
    }

    /// Checks every option on its own and against the exemplar size; the error names the option.
    pub fn validate(&self, exemplar_width: usize, exemplar_height: usize) -> Result<()> {
        let invalid =
            |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        check_size("output", self.output_width, self.output_height)?;
        validate_budget(self.memory_budget_mib)?;
        if exemplar_width < MIN_EXEMPLAR_SIDE || exemplar_height < MIN_EXEMPLAR_SIDE {
            return Err(Error::InvalidSize {
                what: "exemplar",
                width: exemplar_width,
                height: exemplar_height,
                reason: format!(
                    "texture optimization needs at least {MIN_EXEMPLAR_SIDE}x{MIN_EXEMPLAR_SIDE}"
                ),
            });
        }
        if !(1..=8).contains(&self.levels) {
            return invalid(
                "levels",
                format!("must be between 1 and 8, got {}", self.levels),
            );
        }
        if self.neighbourhood_sizes.is_empty() {
            return invalid("neighbourhoodSizes", "must name at least one size".into());
        }
        if let Some(&bad) = self
            .neighbourhood_sizes
            .iter()
            .find(|&&s| !(2..=128).contains(&s))
        {
            return invalid(
                "neighbourhoodSizes",
                format!("each size must be between 2 and 128, got {bad}"),
            );
        }
        if !(1..=MAX_ITERATIONS).contains(&self.iterations) {
            return invalid(
                "iterations",
                format!(
                    "must be between 1 and {MAX_ITERATIONS}, got {}",
                    self.iterations
                ),
            );
        }
        if !self.r.is_finite() || self.r <= 0.0 || self.r > 2.0 {
            return invalid("r", format!("must be in (0, 2], got {}", self.r));
        }
        if !self.completeness.is_finite() || !(0.0..=100.0).contains(&self.completeness) {
            return invalid(
                "completeness",
                format!("must be between 0 and 100, got {}", self.completeness),
            );
        }
        if !(0.0..=1.0).contains(&self.histogram_matching) {
            return invalid(
                "histogramMatching",
                format!("must be between 0 and 1, got {}", self.histogram_matching),
            );
        }
        if !self.mu.is_finite() || self.mu < 0.0 || self.mu > 1000.0 {
            return invalid("mu", format!("must be between 0 and 1000, got {}", self.mu));
        }
        if let Some(m) = self.m_step_mu
            && (!m.is_finite() || !(0.0..=1000.0).contains(&m))
        {
            return invalid("mStepMu", format!("must be between 0 and 1000, got {m}"));
        }
        let w = self.wavelet_detail_weight;
        if !w.is_finite() || !(0.0..=1000.0).contains(&w) {
            return invalid(
                "waveletDetailWeight",
                format!("must be between 0 and 1000, got {w}"),
            );
        }
        if self.energy != Energy::Pixels && !self.channel_weights.is_empty() {
            return invalid(
                "channelWeights",
                format!(
                    "weigh the pixel energy's channels; energy '{}' compares wavelet \
                     coefficients",
                    self.energy.name()
                ),
            );
        }
        if self.energy != Energy::Pixels
            && let Some(&bad) = self
                .neighbourhood_sizes
                .iter()
                .find(|&&s| s < 4 || !s.is_power_of_two())
        {
            return invalid(
                "neighbourhoodSizes",
                format!(
                    "energy '{}' needs powers of two from 4 (the wavelet blocks), got {bad}",
                    self.energy.name()
                ),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(options: Options) -> String {
        options.validate(64, 64).unwrap_err().to_string()
    }

    #[test]
    fn defaults_are_valid_and_every_bad_option_is_named() {
        assert!(Options::default().validate(64, 64).is_ok());
        let d = Options::default;
        assert!(
            message(Options {
                output_width: 0,
                ..d()
            })
            .contains("output size 0x256")
        );
        assert!(message(Options { levels: 0, ..d() }).contains("levels"));
        assert!(
            message(Options {
                neighbourhood_sizes: vec![],
                ..d()
            })
            .contains("neighbourhoodSizes")
        );
        assert!(
            message(Options {
                neighbourhood_sizes: vec![8, 1],
                ..d()
            })
            .contains("got 1")
        );
        assert!(
            message(Options {
                iterations: 0,
                ..d()
            })
            .contains("iterations")
        );
        assert!(message(Options { r: f32::NAN, ..d() }).contains("invalid r"));
        assert!(message(Options { r: 3.0, ..d() }).contains("invalid r"));
        assert!(message(Options { mu: -1.0, ..d() }).contains("invalid mu"));
        for bad in [-1.0, f32::NAN, 1e4] {
            let m = message(Options {
                m_step_mu: Some(bad),
                ..d()
            });
            assert!(m.contains("mStepMu"), "{m}");
        }
        assert!(
            message(Options {
                histogram_matching: f32::NAN,
                ..d()
            })
            .contains("invalid histogramMatching")
        );
        assert!(
            message(Options {
                mu: f32::INFINITY,
                ..d()
            })
            .contains("invalid mu")
        );
        for w in [f32::NAN, -1.0, f32::INFINITY] {
            assert!(
                message(Options {
                    wavelet_detail_weight: w,
                    ..d()
                })
                .contains("invalid waveletDetailWeight"),
                "{w}"
            );
        }
        let odd = message(Options {
            energy: Energy::Haar,
            neighbourhood_sizes: vec![16, 12],
            ..d()
        });
        assert!(
            odd.contains("neighbourhoodSizes") && odd.contains("haar"),
            "{odd}"
        );
        assert!(
            Options {
                energy: Energy::Daubechies,
                ..d()
            }
            .validate(64, 64)
            .is_ok()
        );
        let small = Options::default().validate(15, 40).unwrap_err().to_string();
        assert!(small.contains("exemplar size 15x40"), "{small}");
    }
}
