//! Stage 4 of Shen et al. 2009: fast layer-based texture design. The paper says little beyond
//! "completion-based synthesis \[29\] with the quadtree pyramid \[14\] and a chaotic map"; here is how
//! it is made concrete:
//!
//! - **Layers and layout.** Each layer is a designed texture (the sample, a deformed one, a
//!   locally deformed one) with its own global deformations applied. A layout gives every output
//!   pixel a layer; a patch is taken from the layer under its centre, so regions of the output
//!   show different designed textures and the graph cut joins them.
//! - **Completion.** The output is filled patch by patch in scanline order (patch-based sampling,
//!   Liang et al. 2001): each new `patch_size` square overlaps what is made by a boundary zone of
//!   `overlap` pixels, and is chosen from its layer by the SSD over that zone (the "known" part of
//!   an image-completion step).
//! - **Search.** Exhaustive (every position, as \[29\]) or by the quadtree pyramid (`qtp`). A layer
//!   larger than 512 on a side (a photo) is searched, for each patch, within a 512-sided window
//!   of it drawn at random (`window`), so a patch costs what it costs with a 512x512 layer.
//! - **Choice.** Every candidate within `(1 + tolerance)` of the best is acceptable; one is
//!   picked by the logistic map (the paper's chaotic variation), by the seeded random generator,
//!   or the best is taken.
//! - **Stitching.** The new patch meets the old pixels along a minimum-cut seam through the zone
//!   (the project's max-flow solver with the seam cost of graph-cut textures).

pub mod logistic;
pub mod qtp;
mod session;
pub mod window;

pub use session::{
    Layer, LayerDesign, LayerEvent, LayerOptions, LayerPlacement, LayerSearch, MAX_LAYERS,
};
