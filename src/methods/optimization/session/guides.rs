//! Guided synthesis: source and target guide images (Hertzmann et al. 2001's image analogies;
//! Embark's guide maps). The M-step's distance adds `weight ||g_source - g_target||^2` over the
//! neighbourhood, so a match must look like the exemplar and have the guide value the target
//! asks for there. Style transfer is one use: the exemplar's luminance as the source guide, a
//! photo's as the target's.

use super::Session;
use crate::core::pyramid::gaussian_pyramid;
use crate::core::{Edge, Error, Image, Result};
use crate::methods::optimization::exemplars::stack;
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
    /// with the pixel energy and one exemplar (with several, [`Session::set_exemplar_guides`]).
    pub fn set_guides(&mut self, source: &Image, target: &Image, weight: f32) -> Result<()> {
        if self.several.is_some() {
            return refuse(
                "guides",
                "this session has several exemplars: give each its source guide \
                 (set_exemplar_guides; in JS, setGuides before addGuidedExemplar)"
                    .into(),
            );
        }
        let e = &self.exemplars[0];
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
        self.install_guides(source, target, weight)
    }

    /// [`Session::set_guides`] for a session over several exemplars: `sources[k]` is exemplar
    /// `k`'s source guide (its size; all with the target's channels). Each match then compares
    /// the guide of the exemplar it lies in. With one exemplar, [`Session::set_guides`].
    pub fn set_exemplar_guides(
        &mut self,
        sources: &[Image],
        target: &Image,
        weight: f32,
    ) -> Result<()> {
        let Some(several) = &self.several else {
            return match sources {
                [one] => self.set_guides(one, target, weight),
                _ => refuse(
                    "sourceGuide",
                    format!("give 1 source guide, one per exemplar; got {}", sources.len()),
                ),
            };
        };
        let count = several.pyramids.len();
        if sources.len() != count {
            return refuse(
                "sourceGuide",
                format!(
                    "give one source guide per exemplar ({count}), got {}",
                    sources.len()
                ),
            );
        }
        for (k, (source, &(_, w, h))) in sources.iter().zip(&several.stack.bands).enumerate() {
            if (source.width(), source.height()) != (w, h) {
                return refuse(
                    "sourceGuide",
                    format!(
                        "guide {} is {}x{}, its exemplar {w}x{h}",
                        k + 1,
                        source.width(),
                        source.height()
                    ),
                );
            }
            if source.channels() != target.channels() {
                return refuse(
                    "sourceGuide",
                    format!(
                        "guide {} has {} channels, the target guide {}",
                        k + 1,
                        source.channels(),
                        target.channels()
                    ),
                );
            }
        }
        // Stacked as the exemplars are, so each guide lies beside its exemplar.
        let stacked = stack(sources)?.image;
        self.install_guides(&stacked, target, weight)
    }

    /// Checks the target, the channels, the weight and the session, and keeps the guides'
    /// pyramids; `source` is the size of the session's (stacked) exemplar.
    fn install_guides(&mut self, source: &Image, target: &Image, weight: f32) -> Result<()> {
        let (w, h) = (self.options.output_width, self.options.output_height);
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

fn refuse(name: &'static str, reason: String) -> Result<()> {
    Err(Error::InvalidParameter { name, reason })
}
