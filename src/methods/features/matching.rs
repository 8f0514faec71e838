//! Curvilinear feature matching (Wu & Yu 2004, section 2.1): the cost of placing a patch so that
//! the features of its L-shaped context region (already in the output) meet the exemplar's.
//!
//! Each exemplar feature pixel falls in one of four orientation buckets, and each bucket has an
//! exact Euclidean distance transform with nearest-pixel pointers (`solvers::distance`). A context
//! feature f_out of bucket l is matched to the nearest exemplar feature of bucket l - 1, l or l + 1
//! that minimises gdist (eq. 1) = |f_out - f_in| + tau |v_out - v_in|; the cost of a translation is
//! eq. 2, the mean gdist plus beta times the bijectivity term (1/n) sum_j |B(f_in_j) - 1| over the
//! n exemplar features of the overlapping region. Evaluating one translation is linear in the
//! number of context features: three pointer lookups each, and counters per exemplar feature.

use super::detect::{BUCKETS, FeatureMap, bucket, tangent_difference};
use crate::solvers::distance::DistanceMap;

/// tau of eq. 1 for matching.
pub const TAU_MATCH: f32 = 0.1;
/// tau of eq. 1 for the alignment's correspondences (section 2.2).
pub const TAU_ALIGN: f32 = 10.0;
/// beta of eq. 2, with distances in pixels.
pub const BETA: f32 = 0.3;

/// A feature of a context region, relative to the patch's top-left corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContextFeature {
    pub x: usize,
    pub y: usize,
    pub angle: f32,
}

/// The context region's shape: the made rows at the top of the patch (`top`) and the made
/// columns at its left below them (`left`), as scan-order filling leaves it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Region {
    pub size: usize,
    pub top: usize,
    pub left: usize,
}

impl Region {
    #[must_use]
    pub fn contains(&self, x: usize, y: usize) -> bool {
        x < self.size && y < self.size && (y < self.top || x < self.left)
    }
}

/// The exemplar's features ready for matching.
pub struct FeatureIndex {
    width: usize,
    height: usize,
    angle: Vec<f32>,
    /// Per orientation bucket, the nearest feature pixel of that bucket to every pixel
    /// ([`DistanceMap::NONE`] for none); the distance itself is recomputed from the two
    /// positions, which is what the transform's squared distance is, so it is not kept.
    nearest: Vec<Vec<u32>>,
    /// Summed-area table of the feature mask, (w + 1) x (h + 1).
    sat: Vec<u32>,
    features: usize,
    /// Per exemplar pixel: how many context features map to it (reset after each evaluation).
    counts: Vec<u16>,
    touched: Vec<usize>,
}

/// One context feature's correspondence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Correspondence {
    /// Index into the context features.
    pub context: usize,
    /// The exemplar pixel it maps to (y * width + x).
    pub target: usize,
    pub gdist: f32,
}

/// Bytes per pixel of an index (for the memory estimate): per orientation bucket the nearest
/// pixels (`u32`), the tangents (`f32`), the mask's summed-area table (`u32`) and the match
/// counts (`u16`); and, while one bucket's transform is being built, its seeds (`bool`) and its
/// four `f32`/`u32` buffers.
pub const INDEX_BYTES_PER_PIXEL: u64 = (BUCKETS * 4 + 4 + 4 + 2 + (1 + 4 * 4)) as u64;

impl FeatureIndex {
    /// The bytes the index holds (its buffers' lengths), for checking the estimate.
    #[must_use]
    pub fn held_bytes(&self) -> u64 {
        let maps: usize = self.nearest.iter().map(|m| m.len() * 4).sum();
        (maps + self.angle.len() * 4 + self.sat.len() * 4 + self.counts.len() * 2) as u64
    }

    #[must_use]
    pub fn new(map: &FeatureMap) -> FeatureIndex {
        let (w, h) = (map.width, map.height);
        let nearest = (0..BUCKETS)
            .map(|b| {
                let seeds: Vec<bool> = (0..w * h)
                    .map(|i| map.mask[i] && bucket(map.angle[i]) == b)
                    .collect();
                DistanceMap::new(w, h, &seeds).nearest
            })
            .collect();
        let mut sat = vec![0u32; (w + 1) * (h + 1)];
        for y in 0..h {
            let mut row = 0u32;
            for x in 0..w {
                row += u32::from(map.mask[y * w + x]);
                sat[(y + 1) * (w + 1) + x + 1] = sat[y * (w + 1) + x + 1] + row;
            }
        }
        FeatureIndex {
            width: w,
            height: h,
            angle: map.angle.clone(),
            nearest,
            sat,
            features: map.count(),
            counts: vec![0; w * h],
            touched: Vec::new(),
        }
    }

    /// Feature pixels of the exemplar.
    #[must_use]
    pub fn features(&self) -> usize {
        self.features
    }

    /// Exemplar features in the rectangle [x0, x1) x [y0, y1).
    fn count_in(&self, x0: usize, y0: usize, x1: usize, y1: usize) -> u32 {
        if x1 <= x0 || y1 <= y0 {
            return 0;
        }
        let s = |x: usize, y: usize| self.sat[y * (self.width + 1) + x];
        s(x1, y1) + s(x0, y0) - s(x0, y1) - s(x1, y0)
    }

    /// The nearest exemplar feature to (x, y) in the buckets next to `angle`'s, by gdist.
    fn nearest(&self, x: usize, y: usize, angle: f32, tau: f32) -> Option<(usize, f32)> {
        let p = y * self.width + x;
        let l = bucket(angle);
        let mut best: Option<(usize, f32)> = None;
        for k in [(l + BUCKETS - 1) % BUCKETS, l, (l + 1) % BUCKETS] {
            let j = self.nearest[k][p];
            if j == DistanceMap::NONE {
                continue;
            }
            let j = j as usize;
            let (dx, dy) = (
                (j % self.width) as f32 - x as f32,
                (j / self.width) as f32 - y as f32,
            );
            let g = (dx * dx + dy * dy).sqrt() + tau * tangent_difference(angle, self.angle[j]);
            if best.is_none_or(|(_, b)| g < b) {
                best = Some((j, g));
            }
        }
        best
    }

    /// Eq. 2 for the context placed with the patch's top-left at (tx, ty) of the exemplar.
    /// `miss` is the gdist charged to a context feature with no candidate at all.
    pub fn cost(
        &mut self,
        context: &[ContextFeature],
        region: Region,
        tx: usize,
        ty: usize,
        tau: f32,
        miss: f32,
    ) -> f32 {
        let s = region.size;
        let n = self.count_in(tx, ty, tx + s, ty + region.top)
            + self.count_in(tx, ty + region.top, tx + region.left, ty + s);
        let width = self.width;
        self.eq2(
            context.iter().map(|f| (tx + f.x, ty + f.y, f.angle)),
            context.len(),
            n,
            |j| {
                let (jx, jy) = (j % width, j / width);
                jx >= tx && jy >= ty && region.contains(jx - tx, jy - ty)
            },
            tau,
            miss,
        )
    }

    /// Eq. 2 for a context given in exemplar coordinates: `context` holds, for every feature of
    /// the output under the patch, the exemplar pixel the patch would show there and the output
    /// feature's tangent. `overlap` is the number of exemplar features under the made part of the
    /// patch, and `inside(j)` tells whether exemplar pixel `j` (y * width + x) lies there. For
    /// whole-exemplar placements (graph-cut textures), whose made overlap has any shape.
    pub fn cost_in_exemplar(
        &mut self,
        context: &[(usize, usize, f32)],
        overlap: u32,
        inside: impl Fn(usize) -> bool,
        tau: f32,
        miss: f32,
    ) -> f32 {
        self.eq2(
            context.iter().copied(),
            context.len(),
            overlap,
            inside,
            tau,
            miss,
        )
    }

    /// The mean gdist of the context features (exemplar position and tangent) to their nearest
    /// exemplar features, plus beta times the bijectivity term over the `n` exemplar features of
    /// the overlap (`inside`).
    fn eq2(
        &mut self,
        context: impl Iterator<Item = (usize, usize, f32)>,
        len: usize,
        n: u32,
        inside: impl Fn(usize) -> bool,
        tau: f32,
        miss: f32,
    ) -> f32 {
        if len == 0 {
            // Every exemplar feature of the region is unmatched: |0 - 1| each.
            return if n > 0 { BETA } else { 0.0 };
        }
        let mut sum = 0.0f32;
        for (x, y, angle) in context {
            match self.nearest(x, y, angle, tau) {
                Some((j, g)) => {
                    sum += g;
                    if self.counts[j] == 0 {
                        self.touched.push(j);
                    }
                    self.counts[j] = self.counts[j].saturating_add(1);
                }
                None => sum += miss,
            }
        }
        // sum_j |B_j - 1| over the region's features: the many-to-one excess of the matched ones
        // plus the region's features nobody matched.
        let mut excess = 0u32;
        let mut matched_inside = 0u32;
        for &j in &self.touched {
            excess += u32::from(self.counts[j]) - 1;
            if inside(j) {
                matched_inside += 1;
            }
            self.counts[j] = 0;
        }
        self.touched.clear();
        let unmatched = n.saturating_sub(matched_inside);
        let bijectivity = (excess + unmatched) as f32 / n.max(1) as f32;
        sum / len as f32 + BETA * bijectivity
    }

    /// The correspondences of the context at (tx, ty), one-to-one: where several context features
    /// map to one exemplar feature only the closest keeps it ("we enforce a one-to-one mapping by
    /// removing extraneous corresponding features"), and none farther than `max_gdist`.
    #[must_use]
    pub fn correspondences(
        &self,
        context: &[ContextFeature],
        tx: usize,
        ty: usize,
        tau: f32,
        max_gdist: f32,
    ) -> Vec<Correspondence> {
        let mut all: Vec<Correspondence> = context
            .iter()
            .enumerate()
            .filter_map(|(i, f)| {
                self.nearest(tx + f.x, ty + f.y, f.angle, tau)
                    .filter(|&(_, g)| g <= max_gdist)
                    .map(|(target, gdist)| Correspondence {
                        context: i,
                        target,
                        gdist,
                    })
            })
            .collect();
        all.sort_by(|a, b| a.target.cmp(&b.target).then(a.gdist.total_cmp(&b.gdist)));
        all.dedup_by_key(|c| c.target);
        all.sort_by_key(|c| c.context);
        all
    }

    #[must_use]
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::FRAC_PI_2;

    /// A feature map from drawn curves: `(x, y, angle)` pixels.
    fn map(w: usize, h: usize, pixels: &[(usize, usize, f32)]) -> FeatureMap {
        let mut m = FeatureMap {
            width: w,
            height: h,
            mask: vec![false; w * h],
            angle: vec![0.0; w * h],
            response: vec![0.0; w * h],
            threshold: 1.0,
        };
        for &(x, y, a) in pixels {
            m.mask[y * w + x] = true;
            m.angle[y * w + x] = a;
        }
        m
    }

    #[test]
    fn the_bytes_per_pixel_estimate_covers_what_an_index_holds() {
        for (w, h) in [(50, 40), (128, 96), (7, 300)] {
            let index = FeatureIndex::new(&map(w, h, &grid(w, h)));
            let estimate = INDEX_BYTES_PER_PIXEL * (w * h) as u64;
            let held = index.held_bytes();
            // The estimate also counts one bucket's construction scratch, 17 bytes a pixel.
            let scratch = 17 * (w * h) as u64;
            assert!(
                held <= estimate,
                "{w}x{h}: holds {held}, estimated {estimate}"
            );
            assert!(
                estimate <= held + scratch,
                "{w}x{h}: estimate {estimate} far above {held}"
            );
        }
    }

    fn grid(w: usize, h: usize) -> Vec<(usize, usize, f32)> {
        // Horizontal lines every 10 rows, vertical ones every 12 columns.
        let mut px = Vec::new();
        for y in 0..h {
            for x in 0..w {
                if y % 10 == 3 {
                    px.push((x, y, 0.0));
                } else if x % 12 == 5 {
                    px.push((x, y, FRAC_PI_2));
                }
            }
        }
        px
    }

    fn context_from(m: &FeatureMap, tx: usize, ty: usize, region: Region) -> Vec<ContextFeature> {
        let mut out = Vec::new();
        for y in 0..region.size {
            for x in 0..region.size {
                if region.contains(x, y) && m.mask[(ty + y) * m.width + tx + x] {
                    out.push(ContextFeature {
                        x,
                        y,
                        angle: m.angle[(ty + y) * m.width + tx + x],
                    });
                }
            }
        }
        out
    }

    #[test]
    fn a_context_costs_nothing_against_itself_and_ranks_shifts() {
        let m = map(80, 70, &grid(80, 70));
        let mut index = FeatureIndex::new(&m);
        let region = Region {
            size: 24,
            top: 6,
            left: 6,
        };
        let ctx = context_from(&m, 20, 15, region);
        assert!(ctx.len() > 20);
        assert_eq!(index.cost(&ctx, region, 20, 15, TAU_MATCH, 24.0), 0.0);
        // The grid repeats every 60 columns and 10 rows: (20 + 60 would not fit) a period down.
        assert_eq!(index.cost(&ctx, region, 20, 25, TAU_MATCH, 24.0), 0.0);
        let one = index.cost(&ctx, region, 21, 15, TAU_MATCH, 24.0);
        let three = index.cost(&ctx, region, 23, 15, TAU_MATCH, 24.0);
        assert!(0.0 < one && one < three, "{one} {three}");
        // Counters are reset between evaluations.
        assert_eq!(index.cost(&ctx, region, 20, 15, TAU_MATCH, 24.0), 0.0);
    }

    /// Fig. 3: a context edge is matched to a farther exemplar edge of its own orientation, not
    /// to a closer one that crosses it.
    #[test]
    fn orientation_rejects_a_closer_feature_of_the_wrong_direction() {
        // Exemplar: a vertical line at x = 10 (tangent pi/2) and a horizontal one at y = 14.
        let mut px = Vec::new();
        for y in 0..30 {
            px.push((10, y, FRAC_PI_2));
        }
        for x in 0..30 {
            px.push((x, 14, 0.0));
        }
        let index = FeatureIndex::new(&map(30, 30, &px));
        // A context pixel at (13, 13), horizontal tangent: the vertical line is 3 away, the
        // horizontal one 1 away; its own orientation wins even though both lie in reach.
        let ctx = [ContextFeature {
            x: 13,
            y: 13,
            angle: 0.0,
        }];
        let c = index.correspondences(&ctx, 0, 0, TAU_MATCH, 100.0);
        assert_eq!(c[0].target, 14 * 30 + 13);
        // A vertical context pixel next to the horizontal line matches the vertical line.
        let ctx = [ContextFeature {
            x: 12,
            y: 15,
            angle: FRAC_PI_2,
        }];
        let c = index.correspondences(&ctx, 0, 0, TAU_MATCH, 100.0);
        assert_eq!(
            c[0].target % 30,
            10,
            "the vertical line, 2 away, not the horizontal, 1 away"
        );
    }

    #[test]
    fn correspondences_are_one_to_one() {
        // Three context pixels all nearest to one lone exemplar feature: only the closest keeps it.
        let index = FeatureIndex::new(&map(20, 20, &[(10, 10, 0.0)]));
        let ctx = [
            ContextFeature {
                x: 8,
                y: 10,
                angle: 0.0,
            },
            ContextFeature {
                x: 10,
                y: 11,
                angle: 0.0,
            },
            ContextFeature {
                x: 13,
                y: 10,
                angle: 0.0,
            },
        ];
        let c = index.correspondences(&ctx, 0, 0, TAU_ALIGN, 100.0);
        assert_eq!(c.len(), 1);
        assert_eq!(c[0].context, 1);
        assert!(
            index.correspondences(&ctx, 0, 0, TAU_ALIGN, 0.5).is_empty(),
            "too far"
        );
    }
}
