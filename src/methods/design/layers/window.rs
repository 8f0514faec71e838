//! Search windows: bounding what one patch's search reads of a large layer.
//!
//! Patch-based sampling (Liang et al. 2001), which Shen et al. 2009 use for layer-based design,
//! chooses each new patch by the SSD of its boundary zone against every position of the layer
//! texture; the quadtree pyramid only shortens the descent. Its top level cannot be made coarse
//! enough to help with a photo: the query's pyramid stops while the boundary zone is still two
//! coarse pixels wide (with the default patch of 32 and zone of 5 that is one halving), so the
//! exhaustive top level of a 4000x3000 layer has about 3 million positions, searched for every
//! one of the 361 patches of a 512x512 output (over 5 minutes), and the pyramid of the whole
//! photo is built and held besides.
//!
//! So a layer larger than [`MAX_LAYER_SIDE`] on a side is searched, for each patch, within a
//! *search window*: a `MAX_LAYER_SIDE`-sided rectangle of it drawn uniformly at random, from a
//! seeded generator of the design's own (the logistic map and the placement generator are not
//! touched), afresh for every patch, as graph cut draws its source windows
//! ([`crate::methods::graphcut::source_window`], whose bound and drawing this reuses). Within
//! the patch's search the window is the paper's input texture: its pyramid is built, QTP (or the
//! exhaustive search) runs over it, the acceptable candidates are its positions, and the chosen
//! one is offset back into the layer. A patch then costs what it costs with a 512x512 layer,
//! whatever the photo's size, while over the patches every part of the photo can be used. A layer
//! within the bound is searched whole through the pyramid built once, no window is drawn for it,
//! and the outputs are exactly those of the unbounded method.

use crate::core::{Image, Result, Rng};
use crate::methods::graphcut::source_window::{MAX_SOURCE_SIDE, draw_origin, window_extent};

/// The largest side of the part of a layer one patch's search reads (graph cut's bound).
pub const MAX_LAYER_SIDE: usize = MAX_SOURCE_SIDE;

/// Whether a `width` x `height` layer is searched through windows when at most `max_side`
/// pixels a side are searched at once.
#[must_use]
pub fn is_windowed(width: usize, height: usize, max_side: usize) -> bool {
    width > max_side || height > max_side
}

/// A search window of `texture` for one patch: its origin in the layer and its pixels.
pub fn draw_window(
    rng: &mut Rng,
    texture: &Image,
    max_side: usize,
) -> Result<((usize, usize), Image)> {
    let (w, h) = (texture.width(), texture.height());
    let extent = window_extent(w, h, max_side);
    let (x, y) = draw_origin(rng, (w, h), extent, max_side);
    let (x, y) = (x as usize, y as usize);
    Ok(((x, y), texture.crop(x, y, extent.0, extent.1)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_are_bounded_inside_the_layer_and_repeatable() {
        let tex = Image::from_fn(1200, 300, 1, |x, y, _| (x + 7 * y) as f32).unwrap();
        assert!(is_windowed(1200, 300, MAX_LAYER_SIDE));
        assert!(!is_windowed(512, 512, MAX_LAYER_SIDE));
        let (mut a, mut b) = (Rng::new(5), Rng::new(5));
        for _ in 0..50 {
            let ((x, y), win) = draw_window(&mut a, &tex, MAX_LAYER_SIDE).unwrap();
            assert_eq!((win.width(), win.height()), (512, 300));
            assert!(x + 512 <= 1200 && y == 0);
            assert_eq!(win.pixel(3, 4)[0], tex.pixel(x + 3, 4)[0]);
            assert_eq!(draw_window(&mut b, &tex, MAX_LAYER_SIDE).unwrap().0, (x, y));
        }
    }
}
