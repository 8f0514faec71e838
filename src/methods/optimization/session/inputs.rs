//! What a caller gives a session besides the exemplar and the options, before its first step:
//! a start, exemplar pixels to leave out, and the histogram's reference. Inpainting uses all
//! three.

use super::Session;
use crate::core::{Error, Image, Result};
use crate::methods::optimization::exclusion::exclusion_table;

impl Session {
    /// Starts the coarsest level from `image` (the output's size and the exemplar's channels,
    /// shrunk to the level by area averaging) instead of the options' start. Only before the
    /// first step.
    pub fn start_from(&mut self, image: Image) -> Result<()> {
        let (w, h) = (self.options.output_width, self.options.output_height);
        if (image.width(), image.height()) != (w, h) {
            return Err(Error::InvalidSize {
                what: "start",
                width: image.width(),
                height: image.height(),
                reason: format!("must match the output size {w}x{h}"),
            });
        }
        if image.channels() != self.exemplar_channels() {
            return Err(Error::UnsupportedChannels(image.channels()));
        }
        if self.entered.is_some() {
            return Err(Error::InvalidParameter {
                name: "start",
                reason: "can only be given before the first step".into(),
            });
        }
        self.given_start = Some(image);
        self.start_set = None;
        Ok(())
    }

    /// Forbids every exemplar neighbourhood that holds a pixel where `mask` (one entry per
    /// exemplar pixel, true = excluded) is set, at every level (see `super::exclusion`). Only
    /// before the first step; fails when a level would have no neighbourhood left.
    pub fn exclude_exemplar(&mut self, mask: Vec<bool>) -> Result<()> {
        let e = &self.exemplars[0];
        if mask.len() != e.width() * e.height() {
            return Err(Error::LengthMismatch {
                what: "exemplar exclusion mask",
                expected: e.width() * e.height(),
                actual: mask.len(),
            });
        }
        if self.entered.is_some() {
            return Err(Error::InvalidParameter {
                name: "exclude",
                reason: "can only be given before the first step".into(),
            });
        }
        let size = (e.width(), e.height());
        for lv in &self.levels {
            if !exclusion_table(&mask, size, lv.octave, lv.size).contains(&0.0) {
                return Err(Error::InvalidParameter {
                    name: "neighbourhoodSizes",
                    reason: format!(
                        "no {0}x{0} neighbourhood of the exemplar at 1/{1} resolution lies \
                         outside the excluded pixels",
                        lv.size,
                        1 << lv.octave
                    ),
                });
            }
        }
        self.excluded = mask.contains(&true).then_some(mask);
        Ok(())
    }

    /// Makes histogram matching move the free pixels towards the colours of the constraint's
    /// fully held pixels at each level (mask 1) instead of the exemplar's. Inpainting holds the
    /// known pixels so: the hole takes the statistics of its surroundings, not of the whole
    /// image, whose other objects (a wall's windows) would otherwise be pressed into it.
    pub fn match_histogram_to_constraint(&mut self, on: bool) {
        self.histogram_to_constraint = on;
    }

}
