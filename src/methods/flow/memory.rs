//! The working set of a flow animation (see [`crate::core::budget`]): the larger of frame 0's
//! texture optimisation ([`crate::methods::optimization::memory`]) and what the later frames
//! hold, counted from the session (`N` pixels a frame, `c` channels):
//!
//! - the current, previous and naive frames, and a full-size copy for reading one back,
//!   `4 * 4c N`;
//! - the previous frame warped along the flow as a soft constraint (colours and mask,
//!   `(4c + 4) N`), while the warp of the naive frame is made (`(4c + 4) N` more);
//! - the flow field of the frame, `8 N`, and every field the caller gave, `8 N` each;
//! - one level per frame neighbourhood size, each with its histogram-matching scratch (`16 N`)
//!   and its grid of matches (32 bytes per node);
//! - an iteration's M-step feature map (`4c N`), the constrained queries read in place from it
//!   (values and weight gains, `8c N`), and the E-step accumulators (`4(1 + c) N`).

use super::options::FlowOptions;
use crate::core::budget::{WorkingSet, image_bytes};

/// What the session is called in messages.
pub const METHOD: &str = "flow animation";

/// The working set of the frames after frame 0 (frame 0's synthesis is estimated by
/// [`crate::methods::optimization::memory::working_set`]); `fields`: flow fields the caller gave.
#[must_use]
pub fn frames_working_set(
    options: &FlowOptions,
    channels: usize,
    fields: usize,
    exemplar_pixels: usize,
) -> WorkingSet {
    let (w, h) = (options.output_width, options.output_height);
    let n = w as u64 * h as u64;
    let c = channels as u64;
    let frame = image_bytes(w, h, channels);
    let nodes: u64 = options
        .frame_sizes
        .iter()
        .map(|&s| {
            let spacing = (s / 4).max(1);
            (w.div_ceil(spacing) + 1) as u64 * (h.div_ceil(spacing) + 1) as u64
        })
        .sum();
    let mut set = WorkingSet::new()
        .with("frames", 4 * frame)
        .with("warped constraint", 2 * (frame + n * 4))
        .with("flow field", n * 8 * (1 + fields as u64))
        .with("grid nodes", nodes * 32)
        .with("M-step feature map", frame)
        .with("M-step constrained queries", 2 * frame)
        .with("E-step accumulators", n * (1 + c) * 4);
    if options.sub_pixel {
        // Per frame size: the exemplar's four half-pixel copies, stacked as an image for the
        // E-step and as a feature map for the searches.
        set.add(
            "sub-pixel exemplar copies",
            2 * 4 * exemplar_pixels as u64 * c * 4 * options.frame_sizes.len() as u64,
        );
    }
    if options.histogram_matching > 0.0 {
        set.add(
            "histogram matching",
            n * 16 * options.frame_sizes.len() as u64,
        );
    }
    set
}

#[cfg(test)]
mod tests {
    use super::super::{FlowOptions, FlowSession, FlowSource};
    use crate::core::testing::noise;
    use crate::methods::flow::generators::{Component, FlowKind, FlowSpec};

    fn session(side: usize, budget: usize) -> crate::core::Result<FlowSession> {
        let flow = FlowSource::Generator(
            FlowSpec::new(vec![Component::new(FlowKind::Vortex, 1.0)]).unwrap(),
        );
        let options = FlowOptions {
            output_width: side,
            output_height: side,
            memory_budget_mib: budget,
            ..FlowOptions::default()
        };
        FlowSession::new(&noise(64, 64, 3, 1), flow, options)
    }

    #[test]
    fn estimate_grows_with_the_output_and_huge_outputs_are_refused_by_the_constructor() {
        let bytes = |side| session(side, 3584).unwrap().working_set().bytes();
        let (small, large) = (bytes(256), bytes(1024));
        assert!(large > 8 * small, "{small} -> {large}");
        assert!(session(2048, 1024).is_ok());
        let e = session(4096, 256).err().unwrap().to_string();
        assert!(
            e.starts_with("frames 4096x4096: flow animation needs about")
                && e.contains("memory budget of 256 MiB"),
            "{e}"
        );
    }

    #[test]
    fn sub_pixel_copies_of_a_large_exemplar_count_against_the_budget() {
        let flow = || {
            FlowSource::Generator(
                FlowSpec::new(vec![Component::new(FlowKind::Vortex, 1.0)]).unwrap(),
            )
        };
        let exemplar = noise(1024, 1024, 3, 2);
        let make = |sub_pixel| {
            let options = FlowOptions {
                output_width: 128,
                output_height: 128,
                memory_budget_mib: 256,
                sub_pixel,
                ..FlowOptions::default()
            };
            FlowSession::new(&exemplar, flow(), options)
        };
        // Whole-pixel frames fit; four copies of a million-pixel exemplar per frame size
        // (as image and as feature map: 3 x 96 MiB) do not.
        assert!(make(false).is_ok());
        let e = make(true).err().unwrap().to_string();
        assert!(e.contains("memory budget of 256 MiB"), "{e}");
    }
}
