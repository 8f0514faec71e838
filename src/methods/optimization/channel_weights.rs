//! Per-channel weights of the M-step's distance: a channel of weight 0 is carried along by the
//! matches without steering them (a height or roughness channel stacked with the colours),
//! and a larger weight makes the matches follow that channel more closely (a guide channel
//! stacked with the colours). The E-step and histogram matching treat every channel alike, as
//! without weights.

use crate::core::{Error, Result};

/// The weight of each channel (at most four), 1 where not given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChannelWeights([f32; 4]);

impl Default for ChannelWeights {
    fn default() -> Self {
        ChannelWeights([1.0; 4])
    }
}

impl ChannelWeights {
    /// The weights of `weights` for an exemplar of `channels` channels: empty gives every
    /// channel 1; otherwise one finite, non-negative weight per channel, not all 0.
    pub fn new(weights: &[f32], channels: usize) -> Result<ChannelWeights> {
        let invalid = |reason: String| {
            Err(Error::InvalidParameter {
                name: "channelWeights",
                reason,
            })
        };
        if weights.is_empty() {
            return Ok(ChannelWeights::default());
        }
        if weights.len() != channels {
            return invalid(format!(
                "give one weight per channel of the exemplar ({channels}), got {}",
                weights.len()
            ));
        }
        if let Some(bad) = weights.iter().find(|w| !w.is_finite() || **w < 0.0) {
            return invalid(format!("weights must be finite and at least 0, got {bad}"));
        }
        if weights.iter().all(|&w| w == 0.0) {
            return invalid("at least one weight must be above 0".into());
        }
        let mut out = [1.0; 4];
        out[..channels].copy_from_slice(weights);
        Ok(ChannelWeights(out))
    }

    /// Whether every channel weighs 1 (the distance is the unweighted one).
    #[must_use]
    pub fn is_uniform(&self) -> bool {
        self.0.iter().all(|&w| w == 1.0)
    }

    /// The weight of each of a feature map's `dims` values per pixel whose first
    /// `colour_dims` are the colour channels and their differences, channel by channel in
    /// groups of `channels` (see `features::feature_map`); values past them (guides) weigh 1.
    #[must_use]
    pub fn per_dim(&self, channels: usize, colour_dims: usize, dims: usize) -> Vec<f32> {
        (0..dims)
            .map(|d| {
                if d < colour_dims {
                    self.0[d % channels]
                } else {
                    1.0
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_weights_are_named_errors() {
        for (weights, says) in [
            (&[1.0, 1.0][..], "one weight per channel"),
            (&[1.0, -1.0, 1.0][..], "at least 0"),
            (&[1.0, f32::NAN, 1.0][..], "finite"),
            (&[0.0, 0.0, 0.0][..], "above 0"),
        ] {
            let message = ChannelWeights::new(weights, 3).unwrap_err().to_string();
            assert!(
                message.contains("channelWeights") && message.contains(says),
                "{message}"
            );
        }
        assert!(ChannelWeights::new(&[], 3).unwrap().is_uniform());
        assert!(!ChannelWeights::new(&[1.0, 1.0, 0.5], 3).unwrap().is_uniform());
    }

    #[test]
    fn differences_take_their_channels_weight_and_guides_weigh_one() {
        let w = ChannelWeights::new(&[2.0, 0.0], 2).unwrap();
        assert_eq!(
            w.per_dim(2, 6, 7),
            vec![2.0, 0.0, 2.0, 0.0, 2.0, 0.0, 1.0]
        );
    }
}
