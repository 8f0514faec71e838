//! The working set of a feature-guided synthesis (see [`crate::core::budget`]), counted from the
//! session (`N` output pixels, `c` channels):
//!
//! - its own output buffers: colours `4c N`, the made and feature masks `2 N`, tangents `4 N`,
//!   and the scan origins (16 bytes each);
//! - with graph-cut placement, the graph-cut synthesis underneath
//!   ([`crate::methods::graphcut::memory`]) and each placement's whole-output scratch: the
//!   synthesised feature map (mask and tangent, `5 N`) and the band around the made part
//!   (`3 N`);
//! - with scan placement, the max-flow graph of one patch and the FFT search of one patch over
//!   an input;
//! - every input (the exemplar and its deformed copies): its feature map (mask, tangent,
//!   response: `9` bytes a pixel), one feature index
//!   ([`super::matching::INDEX_BYTES_PER_PIXEL`], 43 bytes a pixel with the scratch of its
//!   construction), and its image: the scan placement's own copy (`4c`); under graph-cut
//!   placement the images are graph cut's sources, the exemplar counted with them and the
//!   deformed copies here (`4c + 8`).

use super::matching::INDEX_BYTES_PER_PIXEL;
use super::options::{FeatureOptions, FeaturePlacement};
use crate::core::budget::{WorkingSet, image_bytes};
use crate::methods::graphcut::memory::{GRAPH_BYTES_PER_PATCH_PIXEL, search_bytes};
use crate::solvers::fft_ssd::{Boundary, transform_size};

/// What the session is called in messages.
pub const METHOD: &str = "feature-guided synthesis";

/// The working set of the session's own buffers and inputs; `inputs`: the exemplar and its
/// deformed copies, `(width, height)` each. With graph-cut placement, the graph-cut
/// synthesis's working set is added by the caller.
#[must_use]
pub fn working_set(
    options: &FeatureOptions,
    inputs: &[(usize, usize)],
    channels: usize,
    graphcut: Option<&WorkingSet>,
) -> WorkingSet {
    let (w, h) = (options.output_width, options.output_height);
    let n = w as u64 * h as u64;
    let c = channels as u64;
    let step = options.patch().saturating_sub(options.zone()).max(1);
    let origins = (w.div_ceil(step) + 1) as u64 * (h.div_ceil(step) + 1) as u64;
    let pixels = |inputs: &[(usize, usize)]| -> u64 {
        inputs.iter().map(|&(w, h)| w as u64 * h as u64).sum()
    };
    let input_pixels = pixels(inputs);
    // Each input's feature map and index, and its image: the scan placement's own copy, while
    // under graph-cut placement the images are the synthesis's sources (the exemplar counted
    // with it, the deformed copies here, with their gradients as graph cut counts them).
    let images = match options.placement {
        FeaturePlacement::Scan => input_pixels * 4 * c,
        FeaturePlacement::Graphcut => pixels(inputs.get(1..).unwrap_or_default()) * (4 * c + 8),
    };
    let mut set = WorkingSet::new()
        .with("output", image_bytes(w, h, channels) + n * 6 + origins * 16)
        .with(
            "inputs",
            input_pixels * (9 + INDEX_BYTES_PER_PIXEL) + images,
        );
    match options.placement {
        FeaturePlacement::Graphcut => set.add("feature scratch", n * 8),
        FeaturePlacement::Scan => {
            let p = options.patch();
            set.add("seam graph", (p * p) as u64 * GRAPH_BYTES_PER_PATCH_PIXEL);
            let search = inputs
                .iter()
                .map(|&(iw, ih)| {
                    let (nx, ny) = transform_size((iw, ih), (p, p), Boundary::Open);
                    nx * ny
                })
                .max()
                .unwrap_or(0);
            set.add("FFT search", search_bytes(search, channels));
        }
    }
    // With graph-cut placement, the graph-cut synthesis underneath holds its own.
    for (what, bytes) in graphcut.map_or(&[][..], WorkingSet::parts) {
        set.add(what, *bytes);
    }
    set
}

#[cfg(test)]
mod tests {
    use super::super::options::{FeatureOptions, FeaturePlacement};
    use super::super::session::FeatureSynthesis;
    use crate::core::testing::noise;

    fn options(side: usize, budget: usize, placement: FeaturePlacement) -> FeatureOptions {
        FeatureOptions {
            output_width: side,
            output_height: side,
            placement,
            memory_budget_mib: budget,
            ..FeatureOptions::default()
        }
    }

    #[test]
    fn estimate_grows_with_the_output_and_huge_outputs_are_refused_by_the_constructor() {
        let exemplar = noise(64, 64, 3, 1);
        for placement in [FeaturePlacement::Graphcut, FeaturePlacement::Scan] {
            let make = |side, budget| {
                FeatureSynthesis::new(&exemplar, None, options(side, budget, placement))
            };
            let bytes = |side| make(side, 3584).unwrap().working_set().bytes();
            let (small, large) = (bytes(256), bytes(1024));
            // The inputs and the search are the exemplar's size at any output size.
            assert!(large > 4 * small, "{placement:?}: {small} -> {large}");
            assert!(make(2048, 1024).is_ok());
            let e = make(4096, 256).err().unwrap().to_string();
            assert!(
                e.starts_with("output 4096x4096: feature-guided synthesis needs about")
                    && e.contains("memory budget of 256 MiB"),
                "{e}"
            );
        }
    }
}
