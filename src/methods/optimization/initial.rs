//! The starting output of the coarsest level: random exemplar patches laid edge to edge.
//!
//! Algorithm 1 only asks for a random start. Starting from random *matches* (the E-step average
//! of randomly chosen, heavily overlapping neighbourhoods) gives the exemplar's mean colour with
//! almost no contrast, and for exemplars with smooth areas (paving, stone, dirt) the first M-step
//! then finds those smooth areas to be the nearest neighbourhoods everywhere: a flat output is a
//! fixed point of EM, so it never leaves. Whole patches keep the exemplar's local contrast from
//! the start, so the first M-step sees texture and matches texture.

use crate::core::{Image, Result, Rng};

/// A `width` x `height` image tiled with `block` x `block` copies of random exemplar windows
/// (clipped at the right and bottom borders).
pub fn random_patches(
    exemplar: &Image,
    width: usize,
    height: usize,
    block: usize,
    rng: &mut Rng,
) -> Result<Image> {
    let (ew, eh, c) = (exemplar.width(), exemplar.height(), exemplar.channels());
    let block = block.clamp(1, ew.min(eh));
    let mut out = Image::new(width, height, c)?;
    for by in (0..height).step_by(block) {
        for bx in (0..width).step_by(block) {
            let (sx, sy) = (rng.index(ew - block + 1), rng.index(eh - block + 1));
            let (bw, bh) = (block.min(width - bx), block.min(height - by));
            for dy in 0..bh {
                let src =
                    &exemplar.data()[((sy + dy) * ew + sx) * c..((sy + dy) * ew + sx + bw) * c];
                let start = ((by + dy) * width + bx) * c;
                out.data_mut()[start..start + bw * c].copy_from_slice(src);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_block_is_a_window_of_the_exemplar() {
        let ex =
            Image::from_fn(20, 16, 2, |x, y, k| (100 * y + x) as f32 + 0.5 * k as f32).unwrap();
        let out = random_patches(&ex, 23, 13, 6, &mut Rng::new(3)).unwrap();
        for by in (0..13).step_by(6) {
            for bx in (0..23).step_by(6) {
                // The block's top-left pixel says where it came from; the rest must follow.
                let origin = out.pixel(bx, by)[0] as usize;
                let (sx, sy) = (origin % 100, origin / 100);
                for y in by..(by + 6).min(13) {
                    for x in bx..(bx + 6).min(23) {
                        assert_eq!(out.pixel(x, y), ex.pixel(sx + x - bx, sy + y - by));
                    }
                }
            }
        }
    }
}
