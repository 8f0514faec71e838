//! Sub-pixel matches, for flow frames.
//!
//! A match z_p is a whole exemplar pixel, so the E-step can only lay exemplar content on the
//! output's pixel grid. Content carried a fraction of a pixel along a flow snaps back to a whole
//! pixel at every frame: where the flow is slower than half a pixel per frame the texture does
//! not move at all (tiles_128 translated by 0.3 px per frame: frame 60 lies exactly where
//! frame 1 did; the page's vortex: its centre, 32 px across, never turns), and elsewhere it jerks.
//!
//! With sub-pixel matches (the flow option `sub_pixel`), flow frames match against the exemplar
//! moved by 0 or 1/2 pixel along each axis: four copies, stacked into one neighbourhood space
//! ([`Neighbourhoods::stacked`](crate::solvers::nn::Neighbourhoods::stacked)), so every search,
//! the E-step and the energy run unchanged. A match's copy is its phase. Carrying matches along
//! the flow rounds to the nearest half pixel and keeps what rounding left over, so that it does
//! not add up over the frames. A node changes phase only through propagation from a neighbour
//! (regions share one, and their averages stay sharp), never by a random jump: letting the
//! search try the other phases at each node stalled slow flows again, since a warped (slightly
//! blurred) frame lies as close to the softer half-pixel copies as to the carried match.

use super::features::feature_map;
use crate::core::sample::shift;
use crate::core::{Edge, Image};
use crate::solvers::nn::FeatureMap;

/// Phase steps per pixel along each axis. Rounding to half a pixel leaves at most a quarter
/// pixel of snapping (a quarter of the whole-pixel rounding's mean squared error), for four
/// copies of the exemplar.
pub const STEPS: usize = 2;
/// Number of phases (copies), the whole-pixel one (copy 0) included.
pub const COUNT: usize = STEPS * STEPS;

/// The offset (phi_x, phi_y), each in [0, 1), of phase `phase`.
#[must_use]
pub fn offset(phase: usize) -> (f64, f64) {
    (
        (phase % STEPS) as f64 / STEPS as f64,
        (phase / STEPS) as f64 / STEPS as f64,
    )
}

/// Splits a continuous coordinate into a whole pixel and a phase step, rounding to the nearest
/// 1/[`STEPS`] of a pixel.
#[must_use]
pub fn split(s: f64) -> (i64, usize) {
    let steps = (s * STEPS as f64).round() as i64;
    (
        steps.div_euclid(STEPS as i64),
        steps.rem_euclid(STEPS as i64) as usize,
    )
}

/// The phase of the steps along x and y.
#[must_use]
pub fn phase(step_x: usize, step_y: usize) -> usize {
    step_x + STEPS * step_y
}

/// The exemplar moved by every phase (copy 0: the exemplar itself), and the copies stacked
/// into one image, as the E-step reads them.
#[must_use]
pub fn stacked_exemplar(exemplar: &Image) -> (Vec<Image>, Image) {
    let copies: Vec<Image> = (0..COUNT)
        .map(|p| {
            let (dx, dy) = offset(p);
            shift(exemplar, dx as f32, dy as f32, Edge::Clamp)
        })
        .collect();
    let data = copies
        .iter()
        .flat_map(|c| c.data().iter().copied())
        .collect();
    let stacked = Image::from_vec(
        exemplar.width(),
        exemplar.height() * COUNT,
        exemplar.channels(),
        data,
    )
    .expect("four copies of a valid exemplar");
    (copies, stacked)
}

/// The feature maps of the moved copies (each its own, so no feature reads across copies).
#[must_use]
pub fn copy_maps(copies: &[Image], mu: f32) -> Vec<FeatureMap> {
    copies
        .iter()
        .map(|c| feature_map(c, mu, Edge::Clamp))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_split_into_whole_pixels_and_half_pixel_steps() {
        assert_eq!(split(3.2), (3, 0));
        assert_eq!(split(3.3), (3, 1));
        assert_eq!(split(3.74), (3, 1));
        assert_eq!(split(3.8), (4, 0));
        assert_eq!(split(-0.4), (-1, 1));
        assert_eq!(offset(phase(1, 0)), (0.5, 0.0));
        assert_eq!(offset(phase(1, 1)), (0.5, 0.5));
    }

    #[test]
    fn the_copies_are_the_exemplar_moved_by_each_phase() {
        let img = crate::core::testing::noise(6, 5, 3, 4);
        let (copies, stacked) = stacked_exemplar(&img);
        assert_eq!(copies[0], img);
        assert_eq!((stacked.width(), stacked.height()), (6, 20));
        let moved = shift(&img, 0.5, 0.5, Edge::Clamp);
        assert_eq!(copies[3], moved);
        assert_eq!(stacked.pixel(2, 3 * 5 + 1), moved.pixel(2, 1));
    }
}
