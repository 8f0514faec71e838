//! The working set of a graph-cut synthesis (see [`crate::core::budget`]), counted from what the
//! session allocates (`N` output pixels, `c` channels):
//!
//! - the canvas: colours `4c N`, the patch label of every pixel `4 N`, seam costs on two edges
//!   `8 N`, and the teaching views' seam map `N`;
//! - a placement's whole-output scratch: the error map, the covered weights and the box maxima
//!   of the error region, `12 N`;
//! - the sources (the exemplar and its transformed copies) with their gradients, `(4c + 8)` per
//!   source pixel;
//! - the max-flow graph of one placement, over the patch: [`GRAPH_BYTES_PER_PATCH_PIXEL`];
//! - the FFT search of one placement ([`search_bytes`]), whose size depends on the patch and the
//!   error region only, not on the output;
//! - the blended result, when blending: a copy of the output (feather) or Laplacian and Gaussian
//!   pyramids of it and of each patch (spline, about `7` outputs' worth).

use super::options::Blend;
use crate::core::budget::{WorkingSet, image_bytes};

/// Bytes of the max-flow graph per pixel under the patch: the node map (4), two 4-connected
/// edges each of two residual arcs (2 * 2 * 12), the node's state and terminal arcs (about 48),
/// and room for the old-seam nodes, rounded up.
pub const GRAPH_BYTES_PER_PATCH_PIXEL: u64 = 192;

/// What the session is called in messages.
pub const METHOD: &str = "graph-cut synthesis";

/// Bytes an FFT SSD search of `values` transform values holds: the real field (8 bytes a
/// value), three half spectra (16-byte complex), the patch's cached spectra (2 + `c` of them),
/// the gathered window with its weights and the cost and area map.
#[must_use]
pub fn search_bytes(values: usize, channels: usize) -> u64 {
    let v = values as u64;
    let half = v / 2 + v / 64 + 1;
    v * 8 + 3 * half * 16 + (2 + channels as u64) * half * 16 + v * (4 * channels as u64 + 12)
}

/// The working set of a `width` x `height` output of `channels` channels, over `sources` (each
/// `(width, height)`), whose largest patch covers `patch_pixels` and whose largest search has
/// `search_values` transform values.
#[must_use]
pub fn working_set(
    (width, height, channels): (usize, usize, usize),
    sources: &[(usize, usize)],
    patch_pixels: usize,
    search_values: usize,
    blend: Blend,
) -> WorkingSet {
    let n = width as u64 * height as u64;
    let c = channels as u64;
    let source_pixels: u64 = sources.iter().map(|&(w, h)| w as u64 * h as u64).sum();
    let mut set = WorkingSet::new()
        .with("canvas", n * (4 * c + 13))
        .with("placement scratch", n * 12)
        .with("sources", source_pixels * (4 * c + 8))
        .with(
            "seam graph",
            patch_pixels as u64 * GRAPH_BYTES_PER_PATCH_PIXEL,
        )
        .with("FFT search", search_bytes(search_values, channels));
    match blend {
        Blend::None => {}
        Blend::Feather => set.add("blend", image_bytes(width, height, channels) + n * 4),
        Blend::Spline => set.add("blend", 7 * image_bytes(width, height, channels) + n * 8),
    }
    set
}

#[cfg(test)]
mod tests {
    use super::super::{Options, Session};
    use crate::core::testing::noise;

    fn options(side: usize, budget: usize) -> Options {
        Options {
            output_width: side,
            output_height: side,
            memory_budget_mib: budget,
            ..Options::default()
        }
    }

    #[test]
    fn estimate_grows_with_the_output_and_huge_outputs_are_refused_by_the_constructor() {
        let exemplar = noise(64, 64, 3, 1);
        let bytes = |side| {
            Session::new(&exemplar, options(side, 3584))
                .unwrap()
                .synthesis()
                .working_set()
                .bytes()
        };
        let (small, large) = (bytes(256), bytes(2048));
        assert!(large > 16 * small, "{small} -> {large}");
        assert!(Session::new(&exemplar, options(2048, 1024)).is_ok());
        let e = Session::new(&exemplar, options(4096, 256))
            .err()
            .unwrap()
            .to_string();
        assert!(
            e.starts_with("output 4096x4096: graph-cut synthesis needs about")
                && e.contains("memory budget of 256 MiB"),
            "{e}"
        );
    }
}
