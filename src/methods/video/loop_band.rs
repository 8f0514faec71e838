//! 7.A's seam surface, coarse to fine. The loop's graph is held to copy A on the window's first
//! frame and forced to copy B on its last, with no terminal arc in between: the max-flow solver's
//! trees grow from two opposite faces through the whole window. On a clip of smooth, even motion
//! the solver's time then grows far faster than the voxel count (`procedural::waves` at 128x128
//! with a 19-frame window: over 40 s natively; 64x64: about 1 s). So frames of more than
//! [`EXACT_PIXELS`] pixels are first cut at half the size (recursively), and each pixel's cut is
//! then confined to a band around the coarse cuts of its neighbourhood: frames before the band are
//! held to A and frames after it forced to B, so every voxel outside the band has a terminal arc
//! and the solver stays fast. The cut found is the least within the bands, not always the least
//! overall.

use super::canvas::{Canvas, Patch};
use super::seam::Placed;
use super::source::Source;
use super::synthesis::Synthesis;
use super::volume::Volume;
use crate::core::Result;

/// Frames of at most this many pixels are cut exactly, over the whole window.
pub const EXACT_PIXELS: usize = 64 * 64;
/// The band reaches this many frames beyond the coarse cuts around a pixel.
pub const BAND_MARGIN: usize = 2;

/// The copies of a loop: A at the canvas's origin, B one frame later.
pub const COPY_A: Patch = Patch {
    source: 0,
    tx: 0,
    ty: 0,
    tt: 0,
};
pub const COPY_B: Patch = Patch {
    source: 1,
    tx: 0,
    ty: 0,
    tt: 1,
};

/// Places 7.A's second copy on `s`, whose sources are the two copies and whose canvas holds the
/// first: the cut runs between canvas frame 1 (held to A as the copy's border) and the last
/// (forced to B), within each pixel's band when the frames have more than `exact_pixels` pixels.
pub fn place_second_copy(s: &mut Synthesis, exact_pixels: usize) -> Result<Placed> {
    let (keep, take) = seam_band(s, exact_pixels)?;
    for &i in &keep {
        s.canvas.fixed[i] = true;
    }
    let placed = s.place(COPY_B, &take);
    s.canvas.fixed.fill(false);
    placed
}

/// The voxels that must keep copy A (before each pixel's band) and those that must take copy B
/// (after it, and the canvas's last frame in any case); no band on frames of at most
/// `exact_pixels` pixels.
fn seam_band(s: &Synthesis, exact_pixels: usize) -> Result<(Vec<usize>, Vec<usize>)> {
    let (w, h, d) = s.canvas.size();
    let plane = w * h;
    let last = (d - 1) * plane..d * plane;
    if plane <= exact_pixels || w < 2 || h < 2 {
        return Ok((Vec::new(), last.collect()));
    }
    let (cw, ch) = (w / 2, h / 2);
    let half = |v: &Volume| half_size(v, (cw, ch));
    let mut coarse = Synthesis::new(
        vec![
            Source::new(half(&s.sources[0].volume)?),
            Source::new(half(&s.sources[1].volume)?),
        ],
        Canvas::new(cw, ch, d)?,
        s.gradient_cost,
    );
    coarse.place(COPY_A, &[])?;
    place_second_copy(&mut coarse, exact_pixels)?;
    // Each coarse pixel's cut: the last canvas frame that keeps A.
    let cuts: Vec<usize> = (0..cw * ch)
        .map(|p| {
            (0..d)
                .filter(|&t| coarse.canvas.label[t * cw * ch + p] == 0)
                .count()
                .saturating_sub(1)
        })
        .collect();
    let (mut keep, mut take) = (Vec::new(), Vec::new());
    for y in 0..h {
        for x in 0..w {
            let (lo, hi) = around(&cuts, (cw, ch), ((x / 2).min(cw - 1), (y / 2).min(ch - 1)));
            let from = lo.saturating_sub(BAND_MARGIN).max(1);
            let to = (hi + BAND_MARGIN).min(d - 2);
            let p = y * w + x;
            keep.extend((1..=from).map(|t| t * plane + p));
            take.extend((to + 1..d).map(|t| t * plane + p));
        }
    }
    Ok((keep, take))
}

/// The least and greatest cut of the 3x3 coarse pixels around `(x, y)`.
fn around(cuts: &[usize], (w, h): (usize, usize), (x, y): (usize, usize)) -> (usize, usize) {
    let (mut lo, mut hi) = (usize::MAX, 0);
    for v in y.saturating_sub(1)..(y + 2).min(h) {
        for u in x.saturating_sub(1)..(x + 2).min(w) {
            lo = lo.min(cuts[v * w + u]);
            hi = hi.max(cuts[v * w + u]);
        }
    }
    (lo, hi)
}

/// `v` at `w` x `h` (half its size or less), each pixel the mean of the 2x2 block it covers.
fn half_size(v: &Volume, (w, h): (usize, usize)) -> Result<Volume> {
    Volume::from_fn(w, h, v.frames(), |x, y, t| {
        let mut sum = [0.0f32; 3];
        for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let i = v.index(2 * x + dx, 2 * y + dy, t);
            for (s, c) in sum.iter_mut().zip(v.voxel(i)) {
                *s += c;
            }
        }
        sum.map(|s| s / 4.0)
    })
}
