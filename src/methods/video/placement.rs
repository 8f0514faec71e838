//! Choosing where the next spatio-temporal patch goes (section 4 in 3-D): an error region first
//! (a box around the first uncovered voxel, or the box of largest seam error once covered), then
//! an unused offset whose patch covers it, drawn at random (7.B, 7.E) or by entire-patch (eq. 2)
//! or sub-patch matching (7.C, eq. 4) with the 3-D FFT SSD, drawn by eq. 3.

use std::collections::HashSet;

use super::canvas::{Patch, UNCOVERED};
use super::synthesis::Synthesis;
use super::volume::CHANNELS;
use crate::core::{Result, Rng};
use crate::solvers::fft::smooth_size;
use crate::solvers::fft_ssd::{VolumeRange, VolumeView, volume_ssd_map_range};

/// A box of the output: origin and size along x, y, t.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Region {
    pub origin: (usize, usize, usize),
    pub size: (usize, usize, usize),
}

impl Region {
    #[must_use]
    pub fn centre(&self) -> (usize, usize, usize) {
        (
            self.origin.0 + self.size.0 / 2,
            self.origin.1 + self.size.1 / 2,
            self.origin.2 + self.size.2 / 2,
        )
    }
}

/// Which offsets a phase allows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Allowed {
    pub source: u32,
    /// Spatial offsets may move (7.C, 7.E); otherwise tx = ty = 0 (temporal offsets only, 7.B).
    pub spatial: bool,
    /// The one temporal offset allowed (the constrained frames of 7.D sit at t = 0), or any.
    pub tt: Option<i32>,
}

/// A box of `side` around voxel (x, y, t), clamped into an output of `size`.
#[must_use]
pub fn region_around(
    (x, y, t): (usize, usize, usize),
    side: (usize, usize, usize),
    size: (usize, usize, usize),
) -> Region {
    let clamp = |c: usize, s: usize, len: usize| c.saturating_sub(s / 2).min(len - s);
    let side = (side.0.min(size.0), side.1.min(size.1), side.2.min(size.2));
    Region {
        origin: (
            clamp(x, side.0, size.0),
            clamp(y, side.1, size.1),
            clamp(t, side.2, size.2),
        ),
        size: side,
    }
}

impl Synthesis {
    /// The region of largest total seam error (fixed voxels count nothing: they cannot change),
    /// by a summed-volume table.
    #[must_use]
    pub fn worst_region(&self, side: (usize, usize, usize)) -> Region {
        let (w, h, d) = self.canvas.size();
        let side = (side.0.min(w), side.1.min(h), side.2.min(d));
        let mut error = self.canvas.seam_error();
        for (e, &fixed) in error.iter_mut().zip(&self.canvas.fixed) {
            if fixed {
                *e = 0.0;
            }
        }
        let (sw, sh) = (w + 1, h + 1);
        let mut table = vec![0.0f64; sw * sh * (d + 1)];
        let at = |x: usize, y: usize, t: usize| (t * sh + y) * sw + x;
        for t in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let v = f64::from(error[(t * h + y) * w + x]);
                    table[at(x + 1, y + 1, t + 1)] = v
                        + table[at(x, y + 1, t + 1)]
                        + table[at(x + 1, y, t + 1)]
                        + table[at(x + 1, y + 1, t)]
                        - table[at(x, y, t + 1)]
                        - table[at(x, y + 1, t)]
                        - table[at(x + 1, y, t)]
                        + table[at(x, y, t)];
                }
            }
        }
        let mut best = (f64::NEG_INFINITY, (0, 0, 0));
        for t in 0..=d - side.2 {
            for y in 0..=h - side.1 {
                for x in 0..=w - side.0 {
                    let (x1, y1, t1) = (x + side.0, y + side.1, t + side.2);
                    let sum = table[at(x1, y1, t1)]
                        - table[at(x, y1, t1)]
                        - table[at(x1, y, t1)]
                        - table[at(x1, y1, t)]
                        + table[at(x, y, t1)]
                        + table[at(x, y1, t)]
                        + table[at(x1, y, t)]
                        - table[at(x, y, t)];
                    if sum > best.0 {
                        best = (sum, (x, y, t));
                    }
                }
            }
        }
        Region {
            origin: best.1,
            size: side,
        }
    }

    /// The first uncovered voxel in scan order (x, then y, then t), if any.
    #[must_use]
    pub fn first_uncovered(&self) -> Option<usize> {
        self.canvas.label.iter().position(|&l| l == UNCOVERED)
    }

    /// The ranges of offsets along x, y, t whose patch covers `region`.
    fn offset_ranges(&self, region: Region, allowed: Allowed) -> [(i64, i64); 3] {
        let v = &self.sources[allowed.source as usize].volume;
        let span = |origin: usize, size: usize, len: usize| {
            (origin as i64 + size as i64 - len as i64, origin as i64)
        };
        let mut ranges = [
            span(region.origin.0, region.size.0, v.width()),
            span(region.origin.1, region.size.1, v.height()),
            span(region.origin.2, region.size.2, v.frames()),
        ];
        if !allowed.spatial {
            ranges[0] = (0, 0);
            ranges[1] = (0, 0);
        }
        if let Some(tt) = allowed.tt {
            ranges[2] = (i64::from(tt), i64::from(tt));
        }
        ranges
    }

    /// A uniformly drawn unused offset covering `region` (7.B's random temporal offsets, and
    /// random spatio-temporal placement), or `None` when every one is used.
    pub fn random_offset(
        &self,
        region: Region,
        allowed: Allowed,
        used: &HashSet<Patch>,
        rng: &mut Rng,
    ) -> Option<Patch> {
        let r = self.offset_ranges(region, allowed);
        if r.iter().any(|(lo, hi)| lo > hi) {
            return None;
        }
        let patch = |tx: i64, ty: i64, tt: i64| Patch {
            source: allowed.source,
            tx: tx as i32,
            ty: ty as i32,
            tt: tt as i32,
        };
        let draw =
            |rng: &mut Rng, (lo, hi): (i64, i64)| lo + rng.index((hi - lo + 1) as usize) as i64;
        for _ in 0..64 {
            let p = patch(draw(rng, r[0]), draw(rng, r[1]), draw(rng, r[2]));
            if !used.contains(&p) {
                return Some(p);
            }
        }
        let all = self.candidates(region, allowed, used);
        (!all.is_empty()).then(|| all[rng.index(all.len())])
    }

    /// While covering: of `draws` random unused offsets, the one whose patch brings the most
    /// uncovered voxels. Deviation from a uniform draw, measured: extending 96x96x30 to
    /// 192x192x60 takes 91 patches and 42 s uniformly, 63 patches and 16 s with 8 draws (native,
    /// seed 1); with the region centred on the first uncovered voxel, half of every uniform patch
    /// lands on covered video.
    pub fn covering_offset(
        &self,
        region: Region,
        allowed: Allowed,
        used: &HashSet<Patch>,
        rng: &mut Rng,
        draws: usize,
    ) -> Option<Patch> {
        let mut best: Option<(usize, Patch)> = None;
        let mut seen = used.clone();
        for _ in 0..draws {
            let Some(p) = self.random_offset(region, allowed, &seen, rng) else {
                break;
            };
            seen.insert(p);
            let new = self
                .footprint(p)
                .iter()
                .filter(|&&i| self.canvas.label[i] == UNCOVERED)
                .count();
            if best.is_none_or(|(n, _)| new > n) {
                best = Some((new, p));
            }
        }
        best.map(|(_, p)| p)
    }

    /// Every unused offset covering `region`.
    #[must_use]
    pub fn candidates(
        &self,
        region: Region,
        allowed: Allowed,
        used: &HashSet<Patch>,
    ) -> Vec<Patch> {
        let r = self.offset_ranges(region, allowed);
        let mut out = Vec::new();
        for tt in r[2].0..=r[2].1 {
            for ty in r[1].0..=r[1].1 {
                for tx in r[0].0..=r[0].1 {
                    let p = Patch {
                        source: allowed.source,
                        tx: tx as i32,
                        ty: ty as i32,
                        tt: tt as i32,
                    };
                    if !used.contains(&p) {
                        out.push(p);
                    }
                }
            }
        }
        out
    }

    /// The output box a matching placement compares with the input, and the range of offsets
    /// (relative to the box) its candidates take: the error region for sub-patch matching (eq.
    /// 4), the union of the candidates' footprints, clamped to the output, for entire-patch
    /// matching (eq. 2).
    fn search_box(&self, region: Region, allowed: Allowed, whole: bool) -> (Region, VolumeRange) {
        let r = self.offset_ranges(region, allowed);
        let v = &self.sources[allowed.source as usize].volume;
        let (w, h, d) = self.canvas.size();
        let lens = [v.width(), v.height(), v.frames()];
        let (out, origin, size) = ([w, h, d], region.origin, region.size);
        let (origin, size) = if whole {
            let axis = |a: usize| {
                let lo = r[a].0.max(0) as usize;
                let hi = ((r[a].1 + lens[a] as i64) as usize).min(out[a]);
                (lo, hi - lo)
            };
            let (x, y, t) = (axis(0), axis(1), axis(2));
            ((x.0, y.0, t.0), (x.1, y.1, t.1))
        } else {
            (origin, size)
        };
        let o = [origin.0 as i64, origin.1 as i64, origin.2 as i64];
        let first = |a: usize| (r[a].0 - o[a]) as isize;
        let count = |a: usize| (r[a].1 - r[a].0 + 1) as usize;
        (
            Region { origin, size },
            VolumeRange {
                first: (first(0), first(1), first(2)),
                count: (count(0), count(1), count(2)),
            },
        )
    }

    /// Every unused offset covering `region` with its cost C(t) / A(t) (eq. 2 over the whole
    /// overlap when `whole`, eq. 4 over the region otherwise; infinite where nothing overlaps);
    /// the costs are None while nothing the search reads is covered (nothing to match: the draw
    /// is uniform).
    pub fn score_offsets(
        &self,
        region: Region,
        allowed: Allowed,
        used: &HashSet<Patch>,
        whole: bool,
    ) -> Result<Scored> {
        let candidates = self.candidates(region, allowed, used);
        if candidates.is_empty() {
            return Ok(Scored {
                candidates,
                costs: None,
            });
        }
        let (w, h, _) = self.canvas.size();
        let (window, range) = self.search_box(region, allowed, whole);
        let (rw, rh, rd) = window.size;
        let (ox, oy, ot) = window.origin;
        let mut data = Vec::with_capacity(rw * rh * rd * CHANNELS);
        let mut weights = Vec::with_capacity(rw * rh * rd);
        for t in ot..ot + rd {
            for y in oy..oy + rh {
                for x in ox..ox + rw {
                    let i = (t * h + y) * w + x;
                    data.extend_from_slice(self.canvas.pixels.voxel(i));
                    weights.push(if self.canvas.label[i] == UNCOVERED {
                        0.0
                    } else {
                        1.0
                    });
                }
            }
        }
        if weights.iter().all(|&w| w == 0.0) {
            return Ok(Scored {
                candidates,
                costs: None,
            });
        }
        let source = &self.sources[allowed.source as usize].volume;
        let map = volume_ssd_map_range(
            VolumeView {
                data: &data,
                width: rw,
                height: rh,
                depth: rd,
                channels: CHANNELS,
                weights: Some(&weights),
            },
            VolumeView {
                data: source.data(),
                width: source.width(),
                height: source.height(),
                depth: source.frames(),
                channels: CHANNELS,
                weights: None,
            },
            range,
        )?;
        let costs: Vec<f64> = candidates
            .iter()
            .map(|p| {
                let t = (
                    i64::from(p.tx) - ox as i64,
                    i64::from(p.ty) - oy as i64,
                    i64::from(p.tt) - ot as i64,
                );
                match map.get(t.0 as isize, t.1 as isize, t.2 as isize) {
                    Some((c, a)) if a > 0.5 => f64::from(c) / f64::from(a),
                    _ => f64::INFINITY,
                }
            })
            .collect();
        Ok(Scored {
            candidates,
            costs: Some(costs),
        })
    }
}

/// The largest 3-D transform a matching placement with error regions of `side` searches, for
/// an `input` clip: along each axis the input's length for sub-patch matching, and the span of
/// the candidates' footprints (twice the input less the region) for entire-patch matching, along
/// the axes offsets move on (`spatial`: x and y too).
#[must_use]
pub fn largest_search(
    whole: bool,
    spatial: bool,
    side: (usize, usize, usize),
    input: (usize, usize, usize),
) -> (usize, usize, usize) {
    let span = |moves: bool, r: usize, len: usize| {
        if whole && moves {
            (2 * len).saturating_sub(r).max(len)
        } else {
            len
        }
    };
    (
        2 * smooth_size(span(spatial, side.0, input.0).div_ceil(2)),
        smooth_size(span(spatial, side.1, input.1)),
        smooth_size(span(true, side.2, input.2)),
    )
}

/// The unused offsets a matching placement considered, with their costs (None: uniform).
#[derive(Debug, Clone, PartialEq)]
pub struct Scored {
    pub candidates: Vec<Patch>,
    pub costs: Option<Vec<f64>>,
}

/// Draws an offset of `scored` with probability exp(-(C - C_min) / (k sigma^2)) (eq. 3),
/// uniformly where no cost is known or finite; None when there is no candidate.
pub fn draw_offset(scored: &Scored, (k, sigma): (f32, f32), rng: &mut Rng) -> Option<Patch> {
    let candidates = &scored.candidates;
    if candidates.is_empty() {
        return None;
    }
    let best = scored.costs.as_ref().map_or(f64::INFINITY, |c| {
        c.iter().copied().fold(f64::INFINITY, f64::min)
    });
    let (Some(costs), true) = (&scored.costs, best.is_finite()) else {
        return Some(candidates[rng.index(candidates.len())]);
    };
    let scale = f64::from(k) * f64::from(sigma).powi(2);
    let weights: Vec<f64> = costs
        .iter()
        .map(|c| crate::core::math::exp(-(c - best) / scale))
        .collect();
    let mut pick = rng.next_f64() * weights.iter().sum::<f64>();
    for (p, w) in candidates.iter().zip(&weights) {
        if pick < *w {
            return Some(*p);
        }
        pick -= w;
    }
    candidates
        .iter()
        .zip(&weights)
        .rev()
        .find(|(_, w)| **w > 0.0)
        .map(|(p, _)| *p)
}
