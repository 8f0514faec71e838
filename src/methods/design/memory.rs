//! The working sets of the texture-design sessions (see [`crate::core::budget`]), counted from
//! what they allocate (`N` pixels of the output or image, `c` channels).
//!
//! - Layer-based design: the output (`4c N`), its made mask and the layout (the caller's copy
//!   and the design's, `3 N`); each layer's texture, deformed, and its QTP search pyramids
//!   (about `3 * 4c` per texture pixel); the max-flow graph of one patch.
//! - Making an image tileable: at the second stitch the input, the first stitch's result, its
//!   transpose, the rearranged halves, the stitched transpose and the result are live at once
//!   (`6 * 4c N`), with the seam mask (`N`) and the graph over the overlap strip.
//! - The texture brush: the base and the copy a stroke keeps for undo (`2 * 4c N`), the undo
//!   history (at most [`UNDO_BUDGET_BYTES`] or one image), and a stroke's
//!   labelling graph and Poisson solve over at most the base (about 240 bytes a pixel).

use crate::core::budget::{WorkingSet, image_bytes};
use crate::methods::graphcut::memory::GRAPH_BYTES_PER_PATCH_PIXEL;

/// Most bytes of earlier bases the brush keeps for undo (64 MiB: 85 strokes on a 256x256 RGB
/// base).
pub const UNDO_BUDGET_BYTES: usize = 64 << 20;

/// What the sessions are called in messages.
pub const LAYERS: &str = "layer-based texture design";
pub const TILEABLE: &str = "making a texture tileable";
pub const BRUSH: &str = "the texture brush";

/// Layer-based design of a `width` x `height` output with `patch` patches over layer textures
/// of `(width, height)` each (after their deformations).
#[must_use]
pub fn layers_working_set(
    (width, height, channels): (usize, usize, usize),
    patch: usize,
    textures: &[(usize, usize)],
) -> WorkingSet {
    let n = width as u64 * height as u64;
    let texture_pixels: u64 = textures.iter().map(|&(w, h)| w as u64 * h as u64).sum();
    WorkingSet::new()
        .with("output", image_bytes(width, height, channels) + 3 * n)
        .with("layer textures", texture_pixels * 12 * channels as u64)
        .with(
            "seam graph",
            (patch * patch) as u64 * GRAPH_BYTES_PER_PATCH_PIXEL,
        )
}

/// Making a `width` x `height` image tileable with overlaps `(m_h, m_v)`.
#[must_use]
pub fn tileable_working_set(
    (width, height, channels): (usize, usize, usize),
    (m_h, m_v): (usize, usize),
) -> WorkingSet {
    let n = width as u64 * height as u64;
    let strip = (m_h as u64 * height as u64).max(m_v as u64 * width as u64);
    WorkingSet::new()
        .with("images", 6 * image_bytes(width, height, channels) + n)
        .with("seam graph", strip * GRAPH_BYTES_PER_PATCH_PIXEL)
}

/// The brush over a `width` x `height` base.
#[must_use]
pub fn brush_working_set((width, height, channels): (usize, usize, usize)) -> WorkingSet {
    let n = width as u64 * height as u64;
    let image = image_bytes(width, height, channels);
    WorkingSet::new()
        .with("base and undo copy", 2 * image)
        .with("undo history", image.max(UNDO_BUDGET_BYTES as u64))
        .with("stroke", n * 240)
}

#[cfg(test)]
mod tests {
    use crate::core::testing::noise;
    use crate::methods::design::layers::{Layer, LayerDesign, LayerOptions};
    use crate::methods::design::local::{BrushOptions, LocalDeformation};
    use crate::methods::design::tileable::{TileableOptions, TileableSession};

    #[test]
    fn layer_design_estimate_grows_and_huge_outputs_are_refused_by_the_constructor() {
        let texture = noise(64, 64, 3, 1);
        let make = |side: usize, budget| {
            let options = LayerOptions {
                output_width: side,
                output_height: side,
                memory_budget_mib: budget,
                ..LayerOptions::default()
            };
            options.validate()?;
            let layer = Layer {
                texture: texture.clone(),
                deformations: vec![],
            };
            LayerDesign::new(&[layer], &vec![0; side * side], options)
        };
        let small = super::layers_working_set((256, 256, 3), 32, &[(64, 64)]).bytes();
        let large = super::layers_working_set((1024, 1024, 3), 32, &[(64, 64)]).bytes();
        assert!(large > 8 * small, "{small} -> {large}");
        assert!(make(1024, 1024).is_ok());
        let e = make(4096, 64).err().unwrap().to_string();
        assert!(
            e.starts_with("output 4096x4096: layer-based texture design needs about")
                && e.contains("memory budget of 64 MiB"),
            "{e}"
        );
    }

    #[test]
    fn tileable_and_brush_estimates_grow_and_huge_images_are_refused_by_the_constructor() {
        let tileable = |side: usize, budget| {
            TileableSession::new(
                &noise(side, side, 3, 1),
                TileableOptions {
                    memory_budget_mib: Some(budget),
                    ..TileableOptions::default()
                },
            )
        };
        let bytes = |side| tileable(side, 3584).unwrap().working_set().bytes();
        assert!(bytes(1024) > 8 * bytes(256));
        assert!(tileable(512, 1024).is_ok());
        let e = tileable(1024, 16).err().unwrap().to_string();
        assert!(
            e.starts_with("image 1024x1024: making a texture tileable needs about")
                && e.contains("memory budget of 16 MiB"),
            "{e}"
        );
        let brush = |side: usize, budget| {
            LocalDeformation::new(
                &noise(side, side, 3, 1),
                BrushOptions {
                    memory_budget_mib: budget,
                    ..BrushOptions::default()
                },
            )
        };
        let bytes = |side| brush(side, 3584).unwrap().working_set().bytes();
        // The undo history's 64 MiB is there at any size.
        assert!(bytes(1024) > 2 * bytes(256));
        assert!(brush(256, 1024).is_ok());
        let e = brush(1024, 64).err().unwrap().to_string();
        assert!(
            e.starts_with("base 1024x1024: the texture brush needs about")
                && e.contains("memory budget of 64 MiB"),
            "{e}"
        );
    }
}
