//! Source windows: bounding what one placement reads of a large exemplar.
//!
//! In Kwatra et al. (2003, section 4) the patch is the entire input texture: random placement
//! translates "the entire input image", entire-patch matching scores every translation of it
//! (eq. 2), and sub-patch matching looks for the sub-patch of the input that best matches the
//! output-sub-patch (eq. 4), i.e. over every translation of the input that covers it. With a
//! 128x128 exemplar that is what makes the method good; with a 4000x3000 photo it makes every
//! placement cost grow with the exemplar's area: the FFT search over the translations needs a
//! transform larger than the photo (and past 2048x2048 cannot run at all), random placement
//! lists ~12 million offsets, and the min-cut graph has a node per pixel the patch covers.
//!
//! So a source larger than [`MAX_SOURCE_SIDE`] on a side takes part in each placement through a
//! *source window*: a `MAX_SOURCE_SIDE`-sided rectangle of it, drawn uniformly at random (with
//! the synthesis's seeded generator) afresh for every placement. Within the placement the window
//! is the input texture of the paper: the patch for random placement and entire-patch matching,
//! the input searched for the output-sub-patch in sub-patch matching. A placement then costs what
//! it costs with a `MAX_SOURCE_SIDE`-sided exemplar, whatever the photo's size, while over the
//! placements every part of the photo can be used. A source within the bound is its own window
//! (origin (0, 0)), no random number is drawn for it, and results are exactly those of the
//! unbounded method.
//!
//! Why 512: the search window over the output is at most `2 * 512` pixels wide, so the FFT
//! transform stays at most 1536 values on a side (2.4 million, below the 4.2 million allowed);
//! a 512x512 patch is also large enough to carry the large-scale structure entire-patch matching
//! is for (a third of its side, 170 pixels, is the default error region), and 512 is the
//! page's largest default working size for an exemplar.

use crate::core::Rng;

/// The largest side of the part of a source one placement uses.
pub const MAX_SOURCE_SIDE: usize = 512;

/// The size of the window of a `width` x `height` source when at most `max_side` pixels a side
/// are used: the source itself when it fits.
#[must_use]
pub fn window_extent(width: usize, height: usize, max_side: usize) -> (usize, usize) {
    (width.min(max_side.max(1)), height.min(max_side.max(1)))
}

/// A window origin for a `width` x `height` source with windows of `extent`, uniform over every
/// position where the window fits, along each side longer than `max_side`. A source within the
/// bound draws nothing from `rng` and gets (0, 0).
pub fn draw_origin(
    rng: &mut Rng,
    (width, height): (usize, usize),
    extent: (usize, usize),
    max_side: usize,
) -> (u32, u32) {
    let mut along = |len: usize, ext: usize| {
        if len > max_side && len > ext {
            rng.index(len - ext + 1) as u32
        } else {
            0
        }
    };
    let x = along(width, extent.0);
    let y = along(height, extent.1);
    (x, y)
}

/// The key naming a source's window in the FFT search's patch cache: the source index alone for
/// a window at the origin (as before windows existed), and distinct for every other origin.
#[must_use]
pub fn search_key(source: usize, (x, y): (u32, u32)) -> u64 {
    source as u64 | (u64::from(x) << 16) | (u64::from(y) << 40)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_sources_are_their_own_window_and_draw_nothing() {
        assert_eq!(window_extent(128, 96, MAX_SOURCE_SIDE), (128, 96));
        assert_eq!(window_extent(4000, 300, MAX_SOURCE_SIDE), (512, 300));
        let mut a = Rng::new(3);
        let mut b = Rng::new(3);
        assert_eq!(
            draw_origin(&mut a, (128, 96), (96, 96), MAX_SOURCE_SIDE),
            (0, 0)
        );
        assert_eq!(a.next_f64(), b.next_f64());
        let mut seen = (u32::MAX, 0u32);
        for _ in 0..2000 {
            let (x, y) = draw_origin(&mut a, (4000, 300), (512, 300), MAX_SOURCE_SIDE);
            assert!(x as usize + 512 <= 4000 && y == 0);
            seen = (seen.0.min(x), seen.1.max(x));
        }
        assert!(seen.0 < 50 && seen.1 > 3400, "{seen:?}");
        assert_eq!(search_key(2, (0, 0)), 2);
        assert_ne!(search_key(2, (1, 0)), search_key(2, (0, 1)));
    }
}
