//! The minimum-cut seam between what a window of the output already shows and a new patch laid
//! over it (Kwatra et al. 2003, section 3, eq. 1 without old-seam memory): for syntheses that fill
//! the output in scan order, where each patch overlaps only pixels made before it (layer-based
//! design, feature-guided synthesis).

use super::cost::colour_distance;
use crate::core::{Error, Result};
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

/// A `width` x `height` window: the old colours, the new patch's, which pixels are already made,
/// and which made pixels touch made pixels outside the window (those must stay old, or the seam
/// would run along the window's edge into the old texture).
pub struct Overlap<'a> {
    pub width: usize,
    pub height: usize,
    pub channels: usize,
    pub old: &'a [f32],
    pub new: &'a [f32],
    pub made: &'a [bool],
    pub pinned_old: &'a [bool],
}

/// Per window pixel: true where the old pixel stays, false where the new patch shows. Unmade
/// pixels always take the new patch, and so do made pixels next to them (the patch must reach
/// what it fills without a gap).
pub fn keep_old(graph: &mut Graph, o: &Overlap<'_>) -> Result<Vec<bool>> {
    let (w, h, c) = (o.width, o.height, o.channels);
    let n = w * h;
    let mut node = vec![usize::MAX; n];
    let mut count = 0;
    for (slot, &made) in node.iter_mut().zip(o.made) {
        if made {
            *slot = count;
            count += 1;
        }
    }
    let mut keep = vec![false; n];
    if count == 0 {
        return Ok(keep);
    }
    graph.reset(count)?;
    fn colour(buf: &[f32], i: usize, c: usize) -> &[f32] {
        &buf[i * c..(i + 1) * c]
    }
    for i in 0..n {
        let a = node[i];
        if a == usize::MAX {
            continue;
        }
        let (x, y) = (i % w, i / w);
        let next_to_new = [
            (x > 0, i.wrapping_sub(1)),
            (x + 1 < w, i + 1),
            (y > 0, i.wrapping_sub(w)),
            (y + 1 < h, i + w),
        ]
        .iter()
        .any(|&(ok, j)| ok && node[j] == usize::MAX);
        if next_to_new {
            graph.add_terminal(a, 0.0, HARD_CONSTRAINT)?;
        } else if o.pinned_old[i] {
            graph.add_terminal(a, HARD_CONSTRAINT, 0.0)?;
        }
        for (ok, j) in [(x + 1 < w, i + 1), (y + 1 < h, i + w)] {
            if ok && node[j] != usize::MAX {
                let cost = colour_distance(colour(o.old, i, c), colour(o.new, i, c))
                    + colour_distance(colour(o.old, j, c), colour(o.new, j, c));
                graph.add_edge(a, node[j], cost, cost)?;
            }
        }
    }
    graph.maxflow();
    for i in 0..n {
        if node[i] != usize::MAX {
            keep[i] = graph.is_source_side(node[i]);
        }
    }
    Ok(keep)
}

/// The pins for a window at (x0, y0) of a `width` x `height` output whose made pixels are
/// `filled` (output-sized): window pixels on the window's edge next to a made pixel outside it.
#[must_use]
pub fn pins_from_outside(
    filled: &[bool],
    width: usize,
    height: usize,
    x0: usize,
    y0: usize,
    w: usize,
    h: usize,
) -> Vec<bool> {
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let (gx, gy) = (x0 + x, y0 + y);
            let at = |xx: usize, yy: usize| filled[yy * width + xx];
            (x == 0 && gx > 0 && at(gx - 1, gy))
                || (x + 1 == w && gx + 1 < width && at(gx + 1, gy))
                || (y == 0 && gy > 0 && at(gx, gy - 1))
                || (y + 1 == h && gy + 1 < height && at(gx, gy + 1))
        })
        .collect()
}

/// A square window at (x, y) of a scan-order fill's output, whose made pixels are `filled`
/// (output-sized).
pub struct ScanWindow<'a> {
    pub filled: &'a [bool],
    pub output_width: usize,
    pub output_height: usize,
    pub x: usize,
    pub y: usize,
    pub size: usize,
}

impl ScanWindow<'_> {
    /// Which window pixels are made.
    #[must_use]
    pub fn made(&self) -> Vec<bool> {
        let (w, p) = (self.output_width, self.size);
        (0..p * p)
            .map(|i| self.filled[(self.y + i / p) * w + self.x + i % p])
            .collect()
    }

    /// [`keep_old`] for this window, with its made pixels and pins derived from `filled`.
    pub fn keep_old(
        &self,
        graph: &mut Graph,
        channels: usize,
        old: &[f32],
        new: &[f32],
    ) -> Result<Vec<bool>> {
        let made = self.made();
        let pinned = pins_from_outside(
            self.filled,
            self.output_width,
            self.output_height,
            self.x,
            self.y,
            self.size,
            self.size,
        );
        keep_old(
            graph,
            &Overlap {
                width: self.size,
                height: self.size,
                channels,
                old,
                new,
                made: &made,
                pinned_old: &pinned,
            },
        )
    }
}

/// Patch origins along one side of a scan-order fill: every `step` pixels, the last one flush
/// with the end. A side shorter than the patch gets the one origin 0: the scan fills check that
/// the output holds a patch, but feature synthesis with graph-cut placement builds these origins
/// without using them, for outputs of any size (fuzz target `session_steps`: `len - patch`
/// overflowed there, a panic natively).
#[must_use]
pub fn scan_origins(len: usize, patch: usize, step: usize) -> Vec<usize> {
    let mut out: Vec<usize> = (0..)
        .map(|i| i * step)
        .take_while(|&o| o + patch < len)
        .collect();
    out.push(len.saturating_sub(patch));
    out.dedup();
    out
}

/// The geometry every scan-order fill needs: an output at least one patch wide and high, and an
/// overlap `zone` of at least `min_zone` and under half the patch (so each step advances).
pub fn check_scan_geometry(
    output_width: usize,
    output_height: usize,
    patch: usize,
    zone: usize,
    min_zone: usize,
) -> Result<()> {
    if output_width < patch || output_height < patch {
        return Err(Error::InvalidSize {
            what: "output",
            width: output_width,
            height: output_height,
            reason: format!("must be at least the patch size {patch}"),
        });
    }
    if zone < min_zone || 2 * zone >= patch {
        return Err(Error::InvalidParameter {
            name: "overlap",
            reason: format!(
                "must be between {min_zone} and {} for patches of {patch}, got {zone}",
                (patch - 1) / 2
            ),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    #[test]
    fn scan_origins_cover_the_side_and_end_flush() {
        assert_eq!(scan_origins(100, 32, 27), vec![0, 27, 54, 68]);
        assert_eq!(scan_origins(32, 32, 27), vec![0]);
        assert_eq!(
            scan_origins(8, 16, 12),
            vec![0],
            "a side shorter than the patch"
        );
        assert!(
            check_scan_geometry(20, 40, 32, 5, 2)
                .unwrap_err()
                .to_string()
                .contains("20x40")
        );
        assert!(
            check_scan_geometry(40, 40, 32, 16, 2)
                .unwrap_err()
                .to_string()
                .contains("overlap")
        );
    }

    /// The seam's cost equals the brute-force minimum over all labellings of the free pixels.
    #[test]
    fn the_cut_is_the_cheapest_seam() {
        let (w, h, c) = (6, 4, 1);
        for seed in 0..8u64 {
            let mut rng = Rng::new(seed);
            let old: Vec<f32> = (0..w * h).map(|_| rng.next_f32()).collect();
            let new: Vec<f32> = (0..w * h).map(|_| rng.next_f32()).collect();
            // The left 4 columns are made (an overlap of 4), the right 2 are not.
            let made: Vec<bool> = (0..w * h).map(|i| i % w < 4).collect();
            let pinned: Vec<bool> = (0..w * h).map(|i| i % w == 0).collect();
            let o = Overlap {
                width: w,
                height: h,
                channels: c,
                old: &old,
                new: &new,
                made: &made,
                pinned_old: &pinned,
            };
            let keep = keep_old(&mut Graph::new(1).unwrap(), &o).unwrap();
            let cost = |keep: &[bool]| -> f32 {
                let mut s = 0.0;
                for i in 0..w * h {
                    let (x, y) = (i % w, i / w);
                    for (ok, j) in [(x + 1 < w, i + 1), (y + 1 < h, i + w)] {
                        if ok && keep[i] != keep[j] {
                            s += (old[i] - new[i]).abs() + (old[j] - new[j]).abs();
                        }
                    }
                }
                s
            };
            // Free pixels: columns 1 and 2 (column 0 pinned old, column 3 next to unmade).
            let free: Vec<usize> = (0..w * h).filter(|&i| matches!(i % w, 1 | 2)).collect();
            let mut best = f32::INFINITY;
            for mask in 0u32..1 << free.len() {
                let mut k: Vec<bool> = (0..w * h).map(|i| i % w == 0).collect();
                for (b, &i) in free.iter().enumerate() {
                    k[i] = mask >> b & 1 == 1;
                }
                best = best.min(cost(&k));
            }
            assert!((cost(&keep) - best).abs() < 1e-4, "seed {seed}");
            assert!(
                (0..w * h).all(|i| i % w != 0 || keep[i])
                    && (0..w * h).all(|i| i % w < 3 || !keep[i])
            );
        }
    }
}
