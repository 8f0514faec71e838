//! Guided synthesis: source and target guide images (Hertzmann et al. 2001's image analogies;
//! Embark's guide maps). The M-step's distance adds `weight ||g_source - g_target||^2` over the
//! neighbourhood, so a match must look like the exemplar and have the guide value the target
//! asks for there. Style transfer is one use: the exemplar's luminance as the source guide, a
//! photo's as the target's.

use super::Session;
use crate::core::pyramid::gaussian_pyramid;
use crate::core::{Edge, Error, Image, Result};
use crate::methods::optimization::guides::Guides;
use crate::methods::optimization::options::Energy;

/// The largest guide weight accepted.
pub const MAX_GUIDE_WEIGHT: f32 = 1e4;

impl Session {
    /// Whether the session has guides ([`Session::set_guides`]).
    #[must_use]
    pub fn has_guides(&self) -> bool {
        self.guides.is_some()
    }

    /// Guides the synthesis: `source` (the exemplar's size) and `target` (the output's size),
    /// with the same channel count, and the weight of their term in the M-step's distance (a
    /// weight of 1 counts a guide value as much as a colour value). Only before the first step,
    /// with the pixel energy and one exemplar.
    pub fn set_guides(&mut self, source: &Image, target: &Image, weight: f32) -> Result<()> {
        let e = &self.exemplars[0];
        let (w, h) = (self.options.output_width, self.options.output_height);
        let refuse = |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        if (source.width(), source.height()) != (e.width(), e.height()) {
            return refuse(
                "sourceGuide",
                format!(
                    "is {}x{}, the exemplar {}x{}",
                    source.width(),
                    source.height(),
                    e.width(),
                    e.height()
                ),
            );
        }
        if (target.width(), target.height()) != (w, h) {
            return refuse(
                "targetGuide",
                format!("is {}x{}, the output {w}x{h}", target.width(), target.height()),
            );
        }
        if source.channels() != target.channels() {
            return refuse(
                "targetGuide",
                format!(
                    "has {} channels, the source guide {}",
                    target.channels(),
                    source.channels()
                ),
            );
        }
        if !weight.is_finite() || !(0.0..=MAX_GUIDE_WEIGHT).contains(&weight) {
            return refuse(
                "guideWeight",
                format!("must be between 0 and {MAX_GUIDE_WEIGHT}, got {weight}"),
            );
        }
        if self.options.energy != Energy::Pixels {
            return refuse(
                "energy",
                format!(
                    "guides need energy 'pixels', not '{}'",
                    self.options.energy.name()
                ),
            );
        }
        if self.several.is_some() {
            return refuse("guides", "need a session of one exemplar".into());
        }
        if self.entered.is_some() {
            return refuse("guides", "can only be given before the first step".into());
        }
        let octaves = self.exemplars.len();
        self.guides = Some(Guides {
            source: gaussian_pyramid(source, octaves, Edge::Clamp)?,
            target: gaussian_pyramid(target, octaves, Edge::Clamp)?,
            weight,
        });
        Ok(())
    }
}
