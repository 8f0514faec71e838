//! Exact nearest patch by sum of squared differences, fast enough to score whole images.
//!
//! Each patch is summarised by the per-channel means of its four quadrants, each scaled by the
//! square root of the quadrant's pixel count: the squared distance between two summaries is a
//! lower bound of the SSD between the patches (Cauchy-Schwarz on each quadrant). The candidates'
//! summaries go into a k-d tree whose nodes keep their bounding boxes; a query descends the
//! nearer child first and skips every node whose box lies as far from its own summary as the
//! best distance found, and every candidate whose summary does. A candidate is compared in full
//! (stopping early) only when its summary is near enough.
//!
//! The search ends sooner the smaller the best distance found so far, so a caller scoring a
//! whole image passes hints: the matches of the query's neighbours, moved by the step between
//! the queries. In a synthesised texture a patch's neighbour often continues the same exemplar
//! region, so a hint is often the nearest patch or close to it.

/// Values per pixel.
const C: usize = 3;
/// Values of a summary.
const D: usize = 12;
/// A patch's summary (see the module's comment), quadrant-major: `[q * 3 + c]`.
type Summary = [f32; D];
/// Candidates per leaf of the tree.
const LEAF: usize = 32;

/// Bytes the index holds per candidate patch, at most: its summary and corner (56), the slots of
/// the table that finds identical patches while it is built (at most 4 per candidate, 4 bytes
/// each), and its share of the tree's nodes (leaves hold at least `LEAF / 2` candidates, so
/// there are at most `4 / LEAF` nodes per candidate, of 112 bytes each).
pub const BYTES_PER_PATCH: u64 = (std::mem::size_of::<(Summary, (u32, u32))>()
    + 4 * std::mem::size_of::<u32>()
    + 4 * std::mem::size_of::<Node>() / LEAF) as u64;

/// A node of the k-d tree: the candidates `start..end` (in tree order) and their bounding box;
/// an inner node's children hold the two halves of its range.
struct Node {
    lo: Summary,
    hi: Summary,
    start: u32,
    end: u32,
    /// Indices of the children in `nodes`, 0 for a leaf (the root is never a child).
    left: u32,
    right: u32,
}

/// All `size` x `size` patches of an image (RGB, 3 values per pixel), indexed by summary.
pub struct PatchIndex<'a> {
    data: &'a [f32],
    width: usize,
    size: usize,
    /// The largest top-left corner coordinates.
    max_x: usize,
    max_y: usize,
    /// The candidates in tree order: summaries and top-left corners.
    candidates: Vec<(Summary, (u32, u32))>,
    /// The k-d tree, root first.
    nodes: Vec<Node>,
}

/// The summary of the patch at (x, y): quadrants split rows and columns at `(size + 1) / 2`.
fn summary(data: &[f32], width: usize, size: usize, x: usize, y: usize) -> Summary {
    let half = size.div_ceil(2);
    let mut sums = [0.0f32; D];
    for dy in 0..size {
        let row = &data[((y + dy) * width + x) * C..((y + dy) * width + x + size) * C];
        let band = if dy < half { 0 } else { 2 };
        for (dx, px) in row.chunks_exact(C).enumerate() {
            let q = band + usize::from(dx >= half);
            for c in 0..C {
                sums[q * C + c] += px[c];
            }
        }
    }
    let (a, b) = (half as f32, (size - half) as f32);
    let pixels = [a * a, a * b, b * a, b * b];
    // The mean times the square root of the pixel count.
    std::array::from_fn(|i| sums[i] / pixels[i / C].sqrt())
}

fn squared_distance(a: &Summary, b: &Summary) -> f32 {
    a.iter().zip(b).map(|(p, q)| (p - q) * (p - q)).sum()
}

/// Squared distance from `s` to the box `lo..hi` (0 inside it).
fn box_distance(s: &Summary, lo: &Summary, hi: &Summary) -> f32 {
    (0..D)
        .map(|k| {
            let d = (lo[k] - s[k]).max(s[k] - hi[k]).max(0.0);
            d * d
        })
        .sum()
}

/// Builds the node over `items[start..end]` (and below it), reordering the items; returns its index.
fn build(
    items: &mut [(Summary, (u32, u32))],
    start: usize,
    end: usize,
    nodes: &mut Vec<Node>,
) -> u32 {
    let mut lo = [f32::INFINITY; D];
    let mut hi = [f32::NEG_INFINITY; D];
    for (s, _) in &items[start..end] {
        for k in 0..D {
            lo[k] = lo[k].min(s[k]);
            hi[k] = hi[k].max(s[k]);
        }
    }
    let index = nodes.len() as u32;
    nodes.push(Node {
        lo,
        hi,
        start: start as u32,
        end: end as u32,
        left: 0,
        right: 0,
    });
    if end - start > LEAF {
        // Split the widest dimension at its median.
        let k = (0..D)
            .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
            .unwrap_or(0);
        let mid = start + (end - start) / 2;
        items[start..end].select_nth_unstable_by(mid - start, |a, b| a.0[k].total_cmp(&b.0[k]));
        let left = build(items, start, mid, nodes);
        let right = build(items, mid, end, nodes);
        let node = &mut nodes[index as usize];
        (node.left, node.right) = (left, right);
    }
    index
}

/// Keeps one of each set of identical patches. Bounds cannot prune a copy of the nearest patch
/// (its bound is below the best distance, which it equals), so every copy would be compared in
/// full: a flat output has as many copies of one patch as it has patches, and a graph-cut
/// output holds each exemplar region several times. Identical patches have bit-identical
/// summaries, so a hash table of summaries finds the candidates to compare. (A table rather
/// than a sort: a second sort's code would add 6 KB of compressed wasm.)
fn dedup(items: &mut Vec<(Summary, (u32, u32))>, data: &[f32], width: usize, size: usize) {
    let hash = |s: &Summary| {
        s.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, v| {
            (h ^ u64::from(v.to_bits())).wrapping_mul(0x0100_0000_01b3)
        })
    };
    let same_pixels = |a: (u32, u32), b: (u32, u32)| {
        (0..size).all(|dy| {
            let row = |(x, y): (u32, u32)| {
                let start = ((y as usize + dy) * width + x as usize) * C;
                &data[start..start + size * C]
            };
            row(a) == row(b)
        })
    };
    let slots = (2 * items.len()).next_power_of_two().max(2);
    // Positions in the kept prefix of `items`; u32::MAX is empty.
    let mut table = vec![u32::MAX; slots];
    let mut kept = 0;
    for i in 0..items.len() {
        let item = items[i];
        let bits = item.0.map(f32::to_bits);
        let mut slot = hash(&item.0) as usize & (slots - 1);
        let duplicate = loop {
            let k = table[slot];
            if k == u32::MAX {
                table[slot] = kept as u32;
                break false;
            }
            let other = items[k as usize];
            if other.0.map(f32::to_bits) == bits && same_pixels(other.1, item.1) {
                break true;
            }
            slot = (slot + 1) & (slots - 1);
        };
        if !duplicate {
            items[kept] = item;
            kept += 1;
        }
    }
    items.truncate(kept);
}

impl<'a> PatchIndex<'a> {
    /// Indexes every patch of a `width` x `height` RGB image (`data`, interleaved).
    #[must_use]
    pub fn new(data: &'a [f32], width: usize, height: usize, size: usize) -> Self {
        let mut items: Vec<(Summary, (u32, u32))> = (0..=height - size)
            .flat_map(|y| (0..=width - size).map(move |x| (x, y)))
            .map(|(x, y)| (summary(data, width, size, x, y), (x as u32, y as u32)))
            .collect();
        dedup(&mut items, data, width, size);
        // At most 4 / LEAF nodes per candidate (see BYTES_PER_PATCH): no reallocation.
        let mut nodes = Vec::with_capacity(4 * items.len() / LEAF + 1);
        let len = items.len();
        build(&mut items, 0, len, &mut nodes);
        PatchIndex {
            data,
            width,
            size,
            max_x: width - size,
            max_y: height - size,
            candidates: items,
            nodes,
        }
    }

    /// SSD between the query patch (in `query`, at (qx, qy) of a `query_width`-wide image) and
    /// the candidate at (x, y), stopping once it exceeds `bound`.
    #[allow(clippy::too_many_arguments)]
    fn ssd(
        &self,
        query: &[f32],
        query_width: usize,
        qx: usize,
        qy: usize,
        x: usize,
        y: usize,
        bound: f32,
    ) -> f32 {
        let len = self.size * C;
        let mut sum = 0.0;
        for dy in 0..self.size {
            let a = &query[((qy + dy) * query_width + qx) * C..][..len];
            let b = &self.data[((y + dy) * self.width + x) * C..][..len];
            sum += a.iter().zip(b).map(|(p, q)| (p - q) * (p - q)).sum::<f32>();
            if sum > bound {
                return sum;
            }
        }
        sum
    }

    /// The smallest SSD from the patch at (qx, qy) of `query` to any indexed patch. (Native
    /// only: the wasm build scores with hints.)
    #[cfg(any(test, not(target_arch = "wasm32")))]
    #[must_use]
    pub fn nearest(&self, query: &[f32], query_width: usize, qx: usize, qy: usize) -> f32 {
        self.nearest_from(query, query_width, qx, qy, &[]).0
    }

    /// [`PatchIndex::nearest`], trying the candidate corners `hints` first (any outside the
    /// indexed image are skipped), and the corner of a nearest patch. The distance is exact
    /// whatever the hints: they only tighten the bound the search starts with.
    #[must_use]
    pub fn nearest_from(
        &self,
        query: &[f32],
        query_width: usize,
        qx: usize,
        qy: usize,
        hints: &[(usize, usize)],
    ) -> (f32, (usize, usize)) {
        let mut best = (f32::INFINITY, (0, 0));
        for &(x, y) in hints {
            if x <= self.max_x && y <= self.max_y {
                let d = self.ssd(query, query_width, qx, qy, x, y, best.0);
                if d < best.0 {
                    best = (d, (x, y));
                }
            }
        }
        let own = summary(query, query_width, self.size, qx, qy);
        let query = Query {
            values: query,
            width: query_width,
            x: qx,
            y: qy,
            summary: own,
        };
        self.search(&query, 0, &mut best);
        best
    }

    /// Depth-first search below node `n`, nearer child first.
    fn search(&self, q: &Query<'_>, n: u32, best: &mut (f32, (usize, usize))) {
        let node = &self.nodes[n as usize];
        if node.left == 0 {
            for i in node.start as usize..node.end as usize {
                let (summary, (x, y)) = &self.candidates[i];
                if squared_distance(&q.summary, summary) >= best.0 {
                    continue;
                }
                let (x, y) = (*x as usize, *y as usize);
                let d = self.ssd(q.values, q.width, q.x, q.y, x, y, best.0);
                if d < best.0 {
                    *best = (d, (x, y));
                }
            }
            return;
        }
        let (a, b) = (
            &self.nodes[node.left as usize],
            &self.nodes[node.right as usize],
        );
        let (da, db) = (
            box_distance(&q.summary, &a.lo, &a.hi),
            box_distance(&q.summary, &b.lo, &b.hi),
        );
        let ((near, dn), (far, df)) = if da <= db {
            ((node.left, da), (node.right, db))
        } else {
            ((node.right, db), (node.left, da))
        };
        if dn < best.0 {
            self.search(q, near, best);
        }
        if df < best.0 {
            self.search(q, far, best);
        }
    }
}

/// A query patch: where it is and its summary.
struct Query<'a> {
    values: &'a [f32],
    width: usize,
    x: usize,
    y: usize,
    summary: Summary,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// Brute-force smallest SSD from the `size` patch at (qx, qy) of `out` to any patch of `ex`.
    #[allow(clippy::too_many_arguments)]
    fn brute(
        ex: &[f32],
        ew: usize,
        eh: usize,
        out: &[f32],
        ow: usize,
        qx: usize,
        qy: usize,
        size: usize,
    ) -> f32 {
        let mut best = f32::INFINITY;
        for y in 0..=eh - size {
            for x in 0..=ew - size {
                let mut d = 0.0;
                for dy in 0..size {
                    for dx in 0..size * 3 {
                        let a = out[((qy + dy) * ow + qx) * 3 + dx];
                        let b = ex[((y + dy) * ew + x) * 3 + dx];
                        d += (a - b) * (a - b);
                    }
                }
                best = best.min(d);
            }
        }
        best
    }

    /// Every query patch of `out` (`ow` x `oh`) against the brute-force nearest distance in the
    /// indexed exemplar, within 1e-4 relative; `more(qx, qy, distance)` checks further.
    fn assert_every_query_exact(
        index: &PatchIndex<'_>,
        (ex, ew, eh): (&[f32], usize, usize),
        out: &[f32],
        (ow, oh): (usize, usize),
        size: usize,
        mut more: impl FnMut(usize, usize, f32),
    ) {
        for qy in 0..=oh - size {
            for qx in 0..=ow - size {
                let expected = brute(ex, ew, eh, out, ow, qx, qy, size);
                let fast = index.nearest(out, ow, qx, qy);
                assert!(
                    (fast - expected).abs() <= 1e-4 * expected.max(1e-3),
                    "({qx}, {qy}): {fast} vs {expected}"
                );
                more(qx, qy, fast);
            }
        }
    }

    #[test]
    fn repeated_and_flat_patches_are_indexed_once_and_searches_stay_exact() {
        // A 6x6 tile repeated, with a flat band across it: many identical patches.
        let mut rng = Rng::new(5);
        let tile: Vec<f32> = (0..6 * 6 * 3).map(|_| rng.next_f32()).collect();
        let (ew, eh, size) = (30, 24, 5);
        let ex: Vec<f32> = (0..ew * eh * 3)
            .map(|i| {
                let (p, c) = (i / 3, i % 3);
                let (x, y) = (p % ew, p / ew);
                if (10..17).contains(&y) {
                    0.5
                } else {
                    tile[((y % 6) * 6 + x % 6) * 3 + c]
                }
            })
            .collect();
        let index = PatchIndex::new(&ex, ew, eh, size);
        let patches = (ew - size + 1) * (eh - size + 1);
        assert!(
            index.candidates.len() < patches / 3,
            "{} of {patches} patches kept",
            index.candidates.len()
        );
        let (ow, oh) = (14, 12);
        let out: Vec<f32> = (0..ow * oh * 3)
            .map(|_| rng.next_f32() * 0.6 + 0.2)
            .collect();
        assert_every_query_exact(&index, (&ex, ew, eh), &out, (ow, oh), size, |_, _, _| {});
        // A query that is one of the repeated patches finds it at distance 0.
        assert_eq!(index.nearest(&ex, ew, 7, 1), 0.0);
        assert_eq!(index.nearest(&ex, ew, 20, 11), 0.0);
    }

    #[test]
    fn equals_brute_force() {
        let mut rng = Rng::new(3);
        let (ew, eh, ow, oh, size) = (23, 19, 17, 15, 5);
        // Smoothish data so that many candidates are close.
        let mut ex: Vec<f32> = (0..ew * eh * 3).map(|_| rng.next_f32()).collect();
        for i in 3..ex.len() {
            ex[i] = 0.6 * ex[i] + 0.4 * ex[i - 3];
        }
        let out: Vec<f32> = (0..ow * oh * 3)
            .map(|_| rng.next_f32() * 0.8 + 0.1)
            .collect();
        let index = PatchIndex::new(&ex, ew, eh, size);
        assert_every_query_exact(
            &index,
            (&ex, ew, eh),
            &out,
            (ow, oh),
            size,
            |qx, qy, fast| {
                // Hints (in range, out of range, the answer itself) change nothing but the
                // search's start.
                let hints = [(rng.index(ew), rng.index(eh)), (ew, 0), (qx, qy)];
                let (hinted, at) = index.nearest_from(&out, ow, qx, qy, &hints);
                assert_eq!(hinted, fast, "({qx}, {qy}) with hints {hints:?}");
                assert_eq!(index.ssd(&out, ow, qx, qy, at.0, at.1, f32::INFINITY), fast);
            },
        );
    }
}
