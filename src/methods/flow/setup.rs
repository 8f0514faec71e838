//! Setting up a frame after the first: the previous frame and the naive baseline warped along
//! the field f_(t-1), and every level's matches moved along it. On a large frame this is split
//! over steps as an iteration is (rows of the warps between looks at the clock): at 2048x2048
//! it takes 1.3 s in wasm, too long for one step.

use super::field::FlowField;
use super::warp::{Warped, Warping};
use crate::core::clock::now_ms;
use crate::core::{Edge, Image, Result};
use crate::methods::optimization::level::LevelSolver;

/// Pixels warped between two looks at the clock (a few milliseconds of bicubic sampling).
const ROW_CHUNK_PIXELS: usize = 1 << 15;

/// A frame's set-up under way.
pub struct FrameSetup {
    field: FlowField,
    edge: Edge,
    previous: Warping,
    naive: Warping,
    /// The level solvers whose matches have moved.
    moved: usize,
}

/// What a finished set-up made.
pub struct FrameStart {
    pub field: FlowField,
    pub previous: Warped,
    pub naive: Image,
}

impl FrameSetup {
    /// Starts the set-up of the frame after `previous` along `field` (its size).
    pub fn new(field: FlowField, previous: &Image, naive: &Image, wrap: bool) -> Result<Self> {
        Ok(FrameSetup {
            previous: Warping::new(previous, &field)?,
            naive: Warping::new(naive, &field)?,
            field,
            edge: if wrap { Edge::Wrap } else { Edge::Clamp },
            moved: 0,
        })
    }

    /// Works on the set-up until it is done (true) or, with `split` milliseconds, until that
    /// time is up (false; it always does some work). `previous` and `naive` are the frames it
    /// was started with.
    pub fn advance(
        &mut self,
        previous: &Image,
        naive: &Image,
        solvers: &mut [LevelSolver],
        split: Option<f64>,
    ) -> bool {
        let started = now_ms();
        let time_up = || split.is_some_and(|ms| now_ms() - started >= ms);
        let rows = (ROW_CHUNK_PIXELS / previous.width().max(1)).max(1);
        let count = if split.is_some() { rows } else { usize::MAX };
        loop {
            if !self.previous.done() {
                self.previous.rows(previous, &self.field, self.edge, count);
            } else if !self.naive.done() {
                self.naive.rows(naive, &self.field, self.edge, count);
            } else if let Some(solver) = solvers.get_mut(self.moved) {
                move_matches(solver, &self.field, self.edge == Edge::Wrap);
                self.moved += 1;
            } else {
                return true;
            }
            if time_up() {
                return false;
            }
        }
    }

    /// The warped frames and the field, once [`FrameSetup::advance`] returned true.
    #[must_use]
    pub fn finish(self) -> FrameStart {
        debug_assert!(self.previous.done() && self.naive.done());
        FrameStart {
            field: self.field,
            previous: self.previous.finish(),
            naive: self.naive.finish().image,
        }
    }
}

/// Moves a level's matches along the flow: a node's content came from its centre moved back
/// along the field.
fn move_matches(solver: &mut LevelSolver, field: &FlowField, wrap: bool) {
    let (w, h) = (field.width() as f64, field.height() as f64);
    solver.move_along(|cx, cy| {
        let (vx, vy) = field.near(cx - 0.5, cy - 0.5);
        let (x, y) = (cx - f64::from(vx), cy - f64::from(vy));
        if wrap {
            (x.rem_euclid(w), y.rem_euclid(h))
        } else {
            (x, y)
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::noise;
    use crate::methods::flow::warp::warp;

    /// Split into steps of one band each, the set-up makes the same warps as one whole warp.
    #[test]
    fn a_set_up_split_over_steps_warps_as_the_whole_warp_does() {
        let (previous, naive) = (noise(300, 200, 3, 5), noise(300, 200, 3, 6));
        let field = FlowField::from_fn(300, 200, |x, y| (0.01 * y - 1.0, 0.5 - 0.02 * x)).unwrap();
        let mut setup = FrameSetup::new(field.clone(), &previous, &naive, false).unwrap();
        let mut steps = 1;
        while !setup.advance(&previous, &naive, &mut [], Some(0.0)) {
            steps += 1;
        }
        // 109 rows of 300 pixels a band: two bands for each warp, a step each.
        assert!(steps >= 4, "{steps} steps");
        let start = setup.finish();
        let whole = warp(&previous, &field, Edge::Clamp).unwrap();
        assert_eq!(start.previous.image, whole.image);
        assert_eq!(start.previous.inside, whole.inside);
        assert!(whole.inside.contains(&0.0), "some sources lie outside");
        assert_eq!(
            start.naive,
            warp(&naive, &field, Edge::Clamp).unwrap().image
        );
        // Unsplit, one call does it all.
        let mut setup = FrameSetup::new(field, &previous, &naive, false).unwrap();
        assert!(setup.advance(&previous, &naive, &mut [], None));
    }
}
