//! Texture optimisation over several exemplars (see `crate::methods::optimization::exemplars`):
//! the session runs on their stack, with the padding excluded from the searches and left out of
//! the histograms, and starts from a graph cut over the exemplars themselves.

use super::Session;
use crate::core::pyramid::{gaussian_pyramid, half_size};
use crate::core::{Edge, Error, Image, Result};
use crate::methods::optimization::exemplars::{Several, stack};
use crate::methods::optimization::options::Options;
use crate::methods::optimization::schedule::plan;

impl Session {
    /// A texture optimisation whose matches range over all of `exemplars`: each match lies
    /// inside one exemplar ([`Session::exemplar_map`] says which), the histograms are the
    /// exemplars' together, and the graph-cut start takes patches from any of them (the
    /// patch start from the first). The schedule is planned for the smallest exemplar.
    /// Exemplars with fewer channels are widened to the most any has.
    pub fn with_exemplars(exemplars: &[Image], options: Options) -> Result<Session> {
        match exemplars {
            [] => {
                return Err(Error::InvalidParameter {
                    name: "exemplars",
                    reason: "give at least one exemplar".into(),
                });
            }
            [one] => return Session::new(one, options),
            _ => {}
        }
        let channels = exemplars.iter().map(Image::channels).max().unwrap_or(1);
        let widened = exemplars
            .iter()
            .map(|e| e.with_channels(channels))
            .collect::<Result<Vec<Image>>>()?;
        for e in &widened {
            options.validate(e.width(), e.height())?;
        }
        let smallest = |side: fn(&Image) -> usize| widened.iter().map(side).min().unwrap_or(1);
        let mut levels = plan(smallest(Image::width), smallest(Image::height), &options)?;
        let stack = stack(&widened)?;
        for lv in &mut levels {
            let (mut w, mut h) = (stack.image.width(), stack.image.height());
            for _ in 0..lv.octave {
                (w, h) = (half_size(w), half_size(h));
            }
            (lv.exemplar_width, lv.exemplar_height) = (w, h);
        }
        let octaves = levels.iter().map(|l| l.octave).max().unwrap_or(0) + 1;
        let pyramids = widened
            .iter()
            .map(|e| gaussian_pyramid(e, octaves, Edge::Clamp))
            .collect::<Result<Vec<_>>>()?;
        let mut session = Session::build(&stack.image, options, levels)?;
        session.exclude_exemplar(stack.padding.clone())?;
        session.several = Some(Several { stack, pyramids });
        Ok(session)
    }

    /// The number of exemplars (1 unless [`Session::with_exemplars`] was given several).
    #[must_use]
    pub fn exemplar_count(&self) -> usize {
        self.several.as_ref().map_or(1, |s| s.pyramids.len())
    }
}
