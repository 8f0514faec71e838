//! A procedural test clip for benchmarks and tests: travelling waves over a static grain, so
//! that no frame repeats exactly and every region moves (water-like, spatio-temporally
//! stationary).

use super::volume::Volume;
use crate::core::{Result, Rng};

/// `width` x `height` x `frames` of waves; the same seed gives the same clip.
pub fn waves(width: usize, height: usize, frames: usize, seed: u64) -> Result<Volume> {
    let mut rng = Rng::new(seed);
    let grain: Vec<f32> = (0..width * height).map(|_| rng.next_f32() * 0.1).collect();
    Volume::from_fn(width, height, frames, |x, y, t| {
        let g = grain[y * width + x];
        let (x, y, t) = (x as f32, y as f32, t as f32);
        let a = crate::core::math::sinf(0.45 * x + 0.2 * y - 0.55 * t);
        let b = crate::core::math::sinf(0.17 * x - 0.38 * y + 0.31 * t + 1.0);
        [
            0.5 + 0.3 * a + g,
            0.5 + 0.2 * b + 0.1 * a,
            0.4 + 0.2 * (a * b) + g,
        ]
    })
}
