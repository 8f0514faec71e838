//! The first pass of inpainting: the hole filled by graph-cut patches (Kwatra et al. 2003),
//! placed from the outside in.
//!
//! Each placement takes the unfilled pixel on the hole's front whose patch-sized window holds
//! the most filled pixels (so the fill grows inwards from where most is known), finds the source
//! window that best matches the filled pixels of that window (area-normalised SSD by the FFT
//! search, drawn with probability exp(-C / (k sigma^2)), eq. 3), and lays it down along the
//! minimum cut of the shared seam graph. The known pixels are held by constraint arcs (section 3:
//! they keep the old side), unfilled pixels must take the patch, and earlier patches may be cut
//! into along a cheaper seam, with their seams remembered (section 3.1).

use crate::core::{Image, Result, Rng};
use crate::methods::graphcut::cost::{colour_distance, value_sigma};
use crate::methods::graphcut::seam_graph::{Footprint, SeamGraph, SeamGrid};
use crate::solvers::box_sum::box_sums;
use crate::solvers::fft_ssd::{OffsetRange, SsdSearch};
use crate::solvers::maxflow::Graph;

/// The label of a known pixel of the image.
const KNOWN: u32 = u32::MAX - 1;
/// The label of a pixel not filled yet.
const UNFILLED: u32 = u32::MAX;

/// The smallest patch side the fill shrinks to when the source has no larger window outside
/// the hole.
pub const MIN_SIDE: usize = 4;

/// A source searched whole when both its sides are at most this; a larger one is searched in a
/// window of this side around the place being filled (or drawn at random for a separate
/// exemplar), so that a placement's transform stays near 600x600 values.
pub const SEARCH_SIDE: usize = 576;

/// Where the fill's patches come from: an image and the pixels of it that may not be copied.
pub struct FillSource {
    /// The source's pixels.
    pub image: Image,
    /// True where the source pixel is unknown (the hole, when the image is its own source).
    pub unknown: Option<Vec<bool>>,
    /// Source coordinates of the region's pixel (0, 0), when the source is the image itself:
    /// search windows are then centred on the place being filled.
    pub region_origin: Option<(usize, usize)>,
}

/// What one placement did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Left column of the patch in the region.
    pub x: usize,
    /// Top row of the patch in the region.
    pub y: usize,
    /// Left column of the source window it copies.
    pub source_x: usize,
    /// Top row of the source window it copies.
    pub source_y: usize,
    /// Region pixels that took the patch.
    pub pixels_taken: usize,
    /// Hole pixels filled for the first time.
    pub pixels_filled: usize,
    /// Cost of the minimum cut.
    pub cut_cost: f64,
}

/// A graph-cut fill of the unknown pixels of a region under way.
pub struct Fill {
    width: usize,
    height: usize,
    pixels: Image,
    known: Vec<bool>,
    label: Vec<u32>,
    /// Per patch: source pixel = region pixel + offset.
    offsets: Vec<(i64, i64)>,
    h_seam: Vec<f32>,
    v_seam: Vec<f32>,
    source: FillSource,
    /// Per source pixel, whether the `side` x `side` window whose top-left corner it is lies in
    /// the source and holds no unknown pixel.
    usable: Vec<bool>,
    side: usize,
    k: f32,
    sigma: f32,
    rng: Rng,
    ssd: SsdSearch,
    graph: Graph,
    unfilled: usize,
}

impl Fill {
    /// A fill of the pixels of `region` where `known` is false, from `source`, with patches of
    /// `side` (at most the region's shorter side and the source's, halved while the source has
    /// no window of that side outside its unknown pixels). Fails when no window of
    /// [`MIN_SIDE`] is usable.
    pub fn new(
        region: Image,
        known: Vec<bool>,
        source: FillSource,
        side: usize,
        k: f32,
        seed: u64,
    ) -> Result<Fill> {
        let (w, h) = (region.width(), region.height());
        let (sw, sh) = (source.image.width(), source.image.height());
        let unknown: Vec<f32> = match &source.unknown {
            Some(u) => u.iter().map(|&u| f32::from(u8::from(u))).collect(),
            None => vec![0.0; sw * sh],
        };
        // The patch side asked for, halved while no window of the source avoids the hole (a
        // small image around a large hole), down to MIN_SIDE.
        let mut side = side.min(w).min(h).min(sw).min(sh).max(1);
        let usable = loop {
            let sums = box_sums(&unknown, sw, sh, side, false);
            let usable: Vec<bool> = sums.iter().map(|&s| s == 0.0).collect();
            if usable.contains(&true) {
                break usable;
            }
            if side / 2 < MIN_SIDE {
                return Err(crate::core::Error::InvalidParameter {
                    name: "mask",
                    reason: format!(
                        "leaves no {side}x{side} window of the image outside the hole to fill \
                         from; give a separate exemplar"
                    ),
                });
            }
            side /= 2;
        };
        let label: Vec<u32> = known.iter().map(|&k| if k { KNOWN } else { UNFILLED }).collect();
        let unfilled = known.iter().filter(|&&k| !k).count();
        Ok(Fill {
            sigma: value_sigma(source.image.data()),
            width: w,
            height: h,
            pixels: region,
            known,
            label,
            offsets: Vec::new(),
            h_seam: vec![0.0; w * h],
            v_seam: vec![0.0; w * h],
            source,
            usable,
            side,
            k,
            rng: Rng::new(seed),
            ssd: SsdSearch::new(),
            graph: Graph::default(),
            unfilled,
        })
    }

    /// Whether every pixel is filled.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.unfilled == 0
    }

    /// Pixels still unfilled.
    #[must_use]
    pub fn unfilled(&self) -> usize {
        self.unfilled
    }

    /// Patches placed so far.
    #[must_use]
    pub fn patches(&self) -> usize {
        self.offsets.len()
    }

    /// The side of the patches.
    #[must_use]
    pub fn side(&self) -> usize {
        self.side
    }

    /// The region as filled so far (unfilled pixels hold what the region held).
    #[must_use]
    pub fn pixels(&self) -> &Image {
        &self.pixels
    }

    /// Whether each pixel is filled (known, or taken by a patch).
    #[must_use]
    pub fn filled(&self) -> Vec<bool> {
        self.label.iter().map(|&l| l != UNFILLED).collect()
    }

    /// Per pixel: 0 unfilled, 1 known, 2 + the patch index for a placed patch.
    #[must_use]
    pub fn labels(&self) -> Vec<u32> {
        self.label
            .iter()
            .map(|&l| match l {
                UNFILLED => 0,
                KNOWN => 1,
                p => 2 + p,
            })
            .collect()
    }

    /// The source coordinates each pixel shows: `None` for known and unfilled pixels.
    #[must_use]
    pub fn source_coords(&self, i: usize) -> Option<(usize, usize)> {
        let l = self.label[i];
        if l == KNOWN || l == UNFILLED {
            return None;
        }
        let (ox, oy) = self.offsets[l as usize];
        let (x, y) = ((i % self.width) as i64 + ox, (i / self.width) as i64 + oy);
        Some((x as usize, y as usize))
    }

    /// Places the next patch. Call only while not done.
    pub fn place(&mut self) -> Result<Placement> {
        let target = self.next_target();
        let (w, h, p) = (self.width, self.height, self.side);
        let corner = |c: usize, len: usize| c.saturating_sub(p / 2).min(len - p);
        let (x0, y0) = (corner(target % w, w), corner(target / w, h));
        let (sx, sy) = self.best_source(x0, y0)?;
        let index = self.offsets.len() as u32;
        self.offsets
            .push((sx as i64 - x0 as i64, sy as i64 - y0 as i64));
        let cells: Vec<usize> = (y0..y0 + p)
            .flat_map(|y| (y * w + x0)..(y * w + x0 + p))
            .collect();
        let local = |j: usize| {
            let (x, y) = (j % w, j / w);
            (x >= x0 && x < x0 + p && y >= y0 && y < y0 + p).then(|| (y - y0) * p + (x - x0))
        };
        let graph = SeamGraph::new(
            self,
            &Footprint {
                cells: &cells,
                local: &local,
                box_len: p * p,
            },
            index,
            &[],
            |i| self.known[i],
        );
        let (cut_cost, taken) = graph.solve_with(&mut self.graph)?;
        let mut filled = 0;
        for &i in &taken {
            let (u, v) = self.source_coords_of(index, i).expect("inside the patch");
            let colour = self.source.image.pixel(u, v).to_vec();
            self.pixels.pixel_mut(i % w, i / w).copy_from_slice(&colour);
            if self.label[i] == UNFILLED {
                filled += 1;
            }
            self.label[i] = index;
        }
        self.unfilled -= filled;
        self.update_seams(&taken);
        Ok(Placement {
            x: x0,
            y: y0,
            source_x: sx,
            source_y: sy,
            pixels_taken: taken.len(),
            pixels_filled: filled,
            cut_cost,
        })
    }

    /// The unfilled pixel next to a filled one whose window holds the most filled pixels (the
    /// first in scan order among equals).
    fn next_target(&self) -> usize {
        let (w, h, p) = (self.width, self.height, self.side);
        let filled: Vec<f32> = self
            .label
            .iter()
            .map(|&l| f32::from(u8::from(l != UNFILLED)))
            .collect();
        let sums = box_sums(&filled, w, h, p, false);
        let corner = |c: usize, len: usize| c.saturating_sub(p / 2).min(len - p);
        let is_filled = |i: usize| self.label[i] != UNFILLED;
        let mut best: Option<(f32, usize)> = None;
        for i in (0..w * h).filter(|&i| !is_filled(i)) {
            let (x, y) = (i % w, i / w);
            let front = (x > 0 && is_filled(i - 1))
                || (x + 1 < w && is_filled(i + 1))
                || (y > 0 && is_filled(i - w))
                || (y + 1 < h && is_filled(i + w));
            if !front {
                continue;
            }
            let score = sums[corner(y, h) * w + corner(x, w)];
            if best.is_none_or(|(b, _)| score > b) {
                best = Some((score, i));
            }
        }
        // A region with nothing filled has no front: start at its first pixel.
        best.map_or_else(
            || (0..w * h).find(|&i| !is_filled(i)).expect("not done"),
            |(_, i)| i,
        )
    }

    /// The source window for the patch at (x0, y0): among the usable windows of the searched
    /// part of the source, drawn by eq. 3 from their SSD against the window's filled pixels.
    fn best_source(&mut self, x0: usize, y0: usize) -> Result<(usize, usize)> {
        let (w, p) = (self.width, self.side);
        let (sw, sh) = (self.source.image.width(), self.source.image.height());
        let mut target = Image::new(p, p, self.pixels.channels())?;
        let mut weights = vec![0.0f32; p * p];
        for v in 0..p {
            for u in 0..p {
                let i = (y0 + v) * w + x0 + u;
                if self.label[i] != UNFILLED {
                    target
                        .pixel_mut(u, v)
                        .copy_from_slice(self.pixels.pixel(x0 + u, y0 + v));
                    weights[v * p + u] = 1.0;
                }
            }
        }
        // The part of the source searched: all of it, or a window around the place.
        let whole = sw <= SEARCH_SIDE && sh <= SEARCH_SIDE;
        let (ax, ay, aw, ah) = if whole {
            (0, 0, sw, sh)
        } else {
            let (aw, ah) = (sw.min(SEARCH_SIDE), sh.min(SEARCH_SIDE));
            let (cx, cy) = match self.source.region_origin {
                Some((ox, oy)) => (ox + x0 + p / 2, oy + y0 + p / 2),
                None => (
                    aw / 2 + self.rng.index(sw - aw + 1),
                    ah / 2 + self.rng.index(sh - ah + 1),
                ),
            };
            let at = |c: usize, len: usize, a: usize| c.saturating_sub(a / 2).min(len - a);
            (at(cx, sw, aw), at(cy, sh, ah), aw, ah)
        };
        let area = if whole {
            None
        } else {
            Some(self.source.image.crop(ax, ay, aw, ah)?)
        };
        let searched = area.as_ref().unwrap_or(&self.source.image);
        // Source pixel u of the searched part lies on target pixel t + u: the window at (a, b)
        // of the part is translation (-a, -b).
        let range = OffsetRange {
            first: (-((aw - p) as isize), -((ah - p) as isize)),
            count: (aw - p + 1, ah - p + 1),
        };
        let key = whole.then_some(1);
        let map = self
            .ssd
            .search_range((&target, Some(&weights)), (searched, None), range, key)?;
        let mut candidates: Vec<((usize, usize), f32)> = Vec::new();
        for b in 0..=ah - p {
            for a in 0..=aw - p {
                let (sx, sy) = (ax + a, ay + b);
                if !self.usable[sy * sw + sx] {
                    continue;
                }
                let Some((cost, area)) = map.get(-(a as isize), -(b as isize)) else {
                    continue;
                };
                candidates.push(((sx, sy), cost / area.max(1.0)));
            }
        }
        if candidates.is_empty() {
            // The window around the place holds no usable window: any usable one will do.
            let i = self.usable.iter().position(|&u| u).expect("checked at the start");
            return Ok((i % sw, i / sw));
        }
        let best = candidates.iter().map(|c| c.1).fold(f32::INFINITY, f32::min);
        let scale = f64::from(self.k) * f64::from(self.sigma).powi(2);
        let weights: Vec<f64> = candidates
            .iter()
            .map(|c| crate::core::math::exp(-(f64::from(c.1) - f64::from(best)) / scale))
            .collect();
        let total: f64 = weights.iter().sum();
        let mut pick = self.rng.next_f64() * total;
        for (c, weight) in candidates.iter().zip(&weights) {
            if pick < *weight {
                return Ok(c.0);
            }
            pick -= weight;
        }
        Ok(candidates
            .iter()
            .zip(&weights)
            .rev()
            .find(|(_, w)| **w > 0.0)
            .map_or(candidates[0].0, |(c, _)| c.0))
    }

    /// The source pixel patch `label` shows at region pixel `i`, if the patch has one there.
    fn source_coords_of(&self, label: u32, i: usize) -> Option<(usize, usize)> {
        let (ox, oy) = self.offsets[label as usize];
        let (x, y) = ((i % self.width) as i64 + ox, (i / self.width) as i64 + oy);
        let (sw, sh) = (self.source.image.width(), self.source.image.height());
        if x < 0 || y < 0 || x >= sw as i64 || y >= sh as i64 {
            return None;
        }
        let (x, y) = (x as usize, y as usize);
        match &self.source.unknown {
            Some(u) if u[y * sw + x] => None,
            _ => Some((x, y)),
        }
    }

    /// What pixel `i` shows under `label`: the known pixel, or the patch's source pixel.
    fn value(&self, i: usize, label: u32) -> Option<&[f32]> {
        if label == KNOWN {
            return self
                .known[i]
                .then(|| self.pixels.pixel(i % self.width, i / self.width));
        }
        let (x, y) = self.source_coords_of(label, i)?;
        Some(self.source.image.pixel(x, y))
    }

    /// Recomputes the remembered seam cost of every edge touching `pixels`.
    fn update_seams(&mut self, pixels: &[usize]) {
        let w = self.width;
        for &i in pixels {
            let (x, y) = (i % w, i / w);
            let mut edges = vec![];
            if x + 1 < w {
                edges.push((i, 0));
            }
            if x > 0 {
                edges.push((i - 1, 0));
            }
            if y + 1 < self.height {
                edges.push((i, 1));
            }
            if y > 0 {
                edges.push((i - w, 1));
            }
            for (s, axis) in edges {
                let t = if axis == 0 { s + 1 } else { s + w };
                let (a, b) = (self.label[s], self.label[t]);
                let cost = if a == UNFILLED || b == UNFILLED {
                    0.0
                } else {
                    SeamGrid::seam_cost(self, s, t, axis, a, b)
                };
                if axis == 0 {
                    self.h_seam[s] = cost;
                } else {
                    self.v_seam[s] = cost;
                }
            }
        }
    }
}

/// The region's pixels as the seam graph's grid (4-connected, not wrapping).
impl SeamGrid for Fill {
    type Label = u32;
    const AXES: usize = 2;

    fn next(&self, i: usize, axis: usize) -> Option<usize> {
        let w = self.width;
        match axis {
            0 => (i % w + 1 < w).then_some(i + 1),
            _ => (i / w + 1 < self.height).then_some(i + w),
        }
    }

    fn prev(&self, i: usize, axis: usize) -> Option<usize> {
        let w = self.width;
        match axis {
            0 => (!i.is_multiple_of(w)).then(|| i - 1),
            _ => (i >= w).then(|| i - w),
        }
    }

    fn label_of(&self, i: usize) -> Option<u32> {
        let l = self.label[i];
        (l != UNFILLED).then_some(l)
    }

    fn old_seam(&self, s: usize, axis: usize) -> f32 {
        if axis == 0 {
            self.h_seam[s]
        } else {
            self.v_seam[s]
        }
    }

    fn seam_cost(&self, s: usize, t: usize, _axis: usize, a: u32, b: u32) -> f32 {
        if a == b {
            return 0.0;
        }
        self.cell_term(s, a, b).unwrap_or(0.0) + self.cell_term(t, a, b).unwrap_or(0.0)
    }

    fn cell_term(&self, i: usize, a: u32, b: u32) -> Option<f32> {
        Some(match (self.value(i, a), self.value(i, b)) {
            (Some(a), Some(b)) => colour_distance(a, b),
            _ => 0.0,
        })
    }
}
