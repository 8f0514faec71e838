//! The starting output of the coarsest level: a graph-cut synthesis at that level's size (the
//! default), or random exemplar patches laid edge to edge.
//!
//! Algorithm 1 only asks for a random start. Starting from random *matches* (the E-step average
//! of randomly chosen, heavily overlapping neighbourhoods) gives the exemplar's mean colour with
//! almost no contrast, and for exemplars with smooth areas (paving, stone, dirt) the first M-step
//! then finds those smooth areas to be the nearest neighbourhoods everywhere: a flat output is a
//! fixed point of EM, so it never leaves. Whole patches keep the exemplar's local contrast from
//! the start, so the first M-step sees texture and matches texture.
//!
//! Random patches, though, start every regular texture with its lattice broken (each patch at its
//! own phase) and every large element in pieces, and EM only moves what it finds nearby: the
//! paper names the result, "misalignment of texture elements" (section 6). The outputs showed it:
//! tiles and squares in misaligned runs, roof's windows as scattered corners, carpet's border
//! stripes chopped. A graph cut at the coarsest level (graph-cut textures' sub-patch placement,
//! Kwatra et al. 2003) lays whole exemplar pieces whose offsets continue what is already there,
//! so the lattice is whole and elements are whole before EM starts; EM then refines it as
//! before. On the 32 samples (128 and 64 -> 256, seed 1) it lowered coherence on every one
//! (geometric mean 0.66x; tiles, squares and roof 0.4-0.6x) at a geometric mean completeness of
//! 0.77x (worst 1.9x, planks_64) and about 10% more time; the whole-exemplar placement scored a
//! better coherence (0.62x) but a worse completeness (up to 2.6x on potatoes_128, one plant
//! everywhere).

use crate::core::{Image, Result, Rng};
use crate::methods::graphcut::{self, Placement};

/// How the coarsest level's output starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Start {
    /// A graph-cut synthesis (sub-patch placement) at the coarsest level's size.
    #[default]
    Graphcut,
    /// Random exemplar windows laid edge to edge, a neighbourhood wide (`random_patches`).
    Patches,
}

impl Start {
    /// The names used in options (JS `start`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Start::Graphcut => "graphcut",
            Start::Patches => "patches",
        }
    }

    /// The start of that name (see [`Start::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Start> {
        [Start::Graphcut, Start::Patches]
            .into_iter()
            .find(|s| s.name() == name)
    }
}

/// The options of the graph-cut start of a `width` x `height` coarsest level: sub-patch
/// placement, a seed drawn from the synthesis's own generator, periodic when the output is.
#[must_use]
pub fn graphcut_start_options(
    width: usize,
    height: usize,
    tileable: bool,
    memory_budget_mib: usize,
    rng: &mut Rng,
) -> graphcut::Options {
    graphcut::Options {
        output_width: width,
        output_height: height,
        seed: rng.index(1 << 30) as u64,
        placement: Placement::SubPatch,
        tileable,
        memory_budget_mib,
        ..graphcut::Options::default()
    }
}

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
