//! Finding the texture patch whose boundary zone best matches what is already synthesised: the
//! search of patch-based sampling (Liang et al. 2001), exhaustive or through a quadtree pyramid
//! (QTP, their section 4.2), as Shen et al. 2009 use it to make layer-based design five times
//! faster.
//!
//! The query is a `size` x `size` window of the output with a mask of the pixels already made
//! (the boundary zone); the cost of a candidate position in the texture is the SSD over the
//! masked pixels. QTP builds 2x2 box-filter pyramids of the texture and of the query (a coarse
//! query pixel counts only if its four children are made), searches the coarsest level
//! exhaustively, keeps the best `keep` positions, and at each finer level tries the four children
//! of each kept position and their neighbours, keeping the best `keep` again.

use crate::core::Image;

/// A texture ready for searching: its box pyramid, finest first.
pub struct SearchTexture {
    levels: Vec<Level>,
}

struct Level {
    width: usize,
    height: usize,
    channels: usize,
    data: Vec<f32>,
}

impl Level {
    fn from_image(image: &Image) -> Level {
        Level {
            width: image.width(),
            height: image.height(),
            channels: image.channels(),
            data: image.data().to_vec(),
        }
    }

    /// The 2x2 box average (odd last rows/columns dropped).
    fn half(&self) -> Level {
        let (w, h, c) = (self.width / 2, self.height / 2, self.channels);
        let mut data = Vec::with_capacity(w * h * c);
        for y in 0..h {
            for x in 0..w {
                for k in 0..c {
                    let at = |xx: usize, yy: usize| self.data[(yy * self.width + xx) * c + k];
                    data.push(
                        0.25 * (at(2 * x, 2 * y)
                            + at(2 * x + 1, 2 * y)
                            + at(2 * x, 2 * y + 1)
                            + at(2 * x + 1, 2 * y + 1)),
                    );
                }
            }
        }
        Level {
            width: w,
            height: h,
            channels: c,
            data,
        }
    }
}

/// A query window at one pyramid level: values and which of them count.
pub struct Query {
    pub size: usize,
    pub channels: usize,
    pub values: Vec<f32>,
    pub mask: Vec<bool>,
}

impl Query {
    fn half(&self) -> Query {
        let (s, c) = (self.size / 2, self.channels);
        let mut values = Vec::with_capacity(s * s * c);
        let mut mask = Vec::with_capacity(s * s);
        for y in 0..s {
            for x in 0..s {
                let kids = [
                    (2 * y) * self.size + 2 * x,
                    (2 * y) * self.size + 2 * x + 1,
                    (2 * y + 1) * self.size + 2 * x,
                    (2 * y + 1) * self.size + 2 * x + 1,
                ];
                mask.push(kids.iter().all(|&i| self.mask[i]));
                for k in 0..c {
                    values.push(0.25 * kids.iter().map(|&i| self.values[i * c + k]).sum::<f32>());
                }
            }
        }
        Query {
            size: s,
            channels: c,
            values,
            mask,
        }
    }

    /// The masked pixels as (column, row, index in the window): the SSD loop walks only these.
    fn active(&self) -> Vec<(usize, usize, usize)> {
        (0..self.size * self.size)
            .filter(|&i| self.mask[i])
            .map(|i| (i % self.size, i / self.size, i))
            .collect()
    }
}

/// Search statistics, for the benchmark.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SearchCount {
    /// Candidate positions whose SSD was computed, at every level.
    pub positions: usize,
    /// Pixel differences those SSDs took: the work done.
    pub pixels: usize,
    /// The most candidate positions one search computed: what bounding the searched area bounds.
    pub largest: usize,
}

impl SearchTexture {
    /// The pyramid of `image` down to where a `patch`-sized window is still 4 pixels wide.
    #[must_use]
    pub fn new(image: &Image, patch: usize) -> SearchTexture {
        let mut levels = vec![Level::from_image(image)];
        let mut p = patch;
        while p / 2 >= 4 {
            let next = levels.last().expect("one level").half();
            if next.width < p / 2 || next.height < p / 2 {
                break;
            }
            levels.push(next);
            p /= 2;
        }
        SearchTexture { levels }
    }

    #[must_use]
    pub fn width(&self) -> usize {
        self.levels[0].width
    }

    #[must_use]
    pub fn height(&self) -> usize {
        self.levels[0].height
    }

    /// SSD of the query against the texture window at (x, y) of `level`, over `active` pixels.
    fn ssd(
        level: &Level,
        query: &Query,
        active: &[(usize, usize, usize)],
        x: usize,
        y: usize,
    ) -> f32 {
        let (c, w) = (level.channels, level.width);
        let mut sum = 0.0f32;
        for &(qx, qy, i) in active {
            let t = ((y + qy) * w + x + qx) * c;
            let q = i * c;
            for k in 0..c {
                let d = level.data[t + k] - query.values[q + k];
                sum += d * d;
            }
        }
        sum
    }

    /// Every position, the best first: the oracle and the "exhaustive" search of the paper.
    pub fn exhaustive(&self, query: &Query, count: &mut SearchCount) -> Vec<(f32, usize, usize)> {
        let level = &self.levels[0];
        let active = query.active();
        let (nx, ny) = (level.width - query.size + 1, level.height - query.size + 1);
        let mut all = Vec::with_capacity(nx * ny);
        for y in 0..ny {
            for x in 0..nx {
                all.push((Self::ssd(level, query, &active, x, y), x, y));
            }
        }
        count.positions += all.len();
        count.pixels += all.len() * active.len();
        count.largest = count.largest.max(all.len());
        all.sort_by(|a, b| a.0.total_cmp(&b.0));
        all
    }

    /// The quadtree-pyramid search: up to `keep` positions at the finest level, the best first.
    pub fn qtp(
        &self,
        query: &Query,
        keep: usize,
        count: &mut SearchCount,
    ) -> Vec<(f32, usize, usize)> {
        let keep = keep.max(1);
        let before = count.positions;
        // The query's pyramid, as deep as the texture's (and while the mask keeps some pixels).
        let mut queries = vec![Query {
            size: query.size,
            channels: query.channels,
            values: query.values.clone(),
            mask: query.mask.clone(),
        }];
        while queries.len() < self.levels.len() {
            let next = queries.last().expect("one").half();
            // Stop while the boundary zone is still at least 2 pixels wide on average: a zone
            // of 1 coarse pixel matches too many wrong places to steer the search.
            let active = next.mask.iter().filter(|&&m| m).count();
            if next.size < 4 || active < 2 * next.size {
                break;
            }
            queries.push(next);
        }
        let top = queries.len() - 1;
        // Exhaustive at the top.
        let (level, q) = (&self.levels[top], &queries[top]);
        let active = q.active();
        let (nx, ny) = (level.width - q.size + 1, level.height - q.size + 1);
        let mut best: Vec<(f32, usize, usize)> = Vec::with_capacity(nx * ny);
        for y in 0..ny {
            for x in 0..nx {
                best.push((Self::ssd(level, q, &active, x, y), x, y));
            }
        }
        count.positions += best.len();
        count.pixels += best.len() * active.len();
        // Keeping more than an eighth of the top level's positions would make the descent cost
        // as much as the exhaustive search it replaces (large patches on a small texture leave
        // few positions).
        let keep = keep.min((best.len() / 8).max(4));
        truncate_best(&mut best, keep);
        // Down the pyramid: children of the kept positions, with one pixel of slack for the
        // odd sizes the box filter dropped.
        for l in (0..top).rev() {
            let (level, q) = (&self.levels[l], &queries[l]);
            let active = q.active();
            let (nx, ny) = (level.width - q.size + 1, level.height - q.size + 1);
            let mut next: Vec<(f32, usize, usize)> = Vec::with_capacity(best.len() * 16);
            for &(_, px, py) in &best {
                for y in (2 * py).saturating_sub(1)..(2 * py + 3).min(ny) {
                    for x in (2 * px).saturating_sub(1)..(2 * px + 3).min(nx) {
                        next.push((0.0, x, y));
                    }
                }
            }
            next.sort_unstable_by_key(|&(_, x, y)| (y, x));
            next.dedup_by_key(|&mut (_, x, y)| (x, y));
            for cand in &mut next {
                cand.0 = Self::ssd(level, q, &active, cand.1, cand.2);
            }
            count.positions += next.len();
            count.pixels += next.len() * active.len();
            truncate_best(&mut next, keep);
            best = next;
        }
        count.largest = count.largest.max(count.positions - before);
        best
    }
}

/// Keeps the `keep` smallest costs, sorted, ties broken by position so results are repeatable.
fn truncate_best(list: &mut Vec<(f32, usize, usize)>, keep: usize) {
    let key = |a: &(f32, usize, usize), b: &(f32, usize, usize)| {
        a.0.total_cmp(&b.0).then((a.2, a.1).cmp(&(b.2, b.1)))
    };
    if list.len() > keep {
        list.select_nth_unstable_by(keep - 1, key);
        list.truncate(keep);
    }
    list.sort_by(key);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;

    /// An L-shaped boundary zone of width `zone` in a `size` window.
    fn l_mask(size: usize, zone: usize) -> Vec<bool> {
        (0..size * size)
            .map(|i| i % size < zone || i / size < zone)
            .collect()
    }

    fn query_at(tex: &Image, x0: usize, y0: usize, size: usize, zone: usize) -> Query {
        let c = tex.channels();
        let mut values = Vec::with_capacity(size * size * c);
        for y in 0..size {
            for x in 0..size {
                values.extend_from_slice(tex.pixel(x0 + x, y0 + y));
            }
        }
        Query {
            size,
            channels: c,
            values,
            mask: l_mask(size, zone),
        }
    }

    #[test]
    fn qtp_finds_a_planted_window_as_the_exhaustive_search_does() {
        let tex = sample("tiles_128");
        let search = SearchTexture::new(&tex, 32);
        assert!(search.levels.len() >= 3);
        for (x0, y0) in [(10, 20), (77, 3), (50, 96), (0, 0), (96, 96)] {
            let q = query_at(&tex, x0, y0, 32, 6);
            let mut count = SearchCount::default();
            let exact = search.exhaustive(&q, &mut count);
            assert_eq!((exact[0].1, exact[0].2), (x0, y0));
            assert_eq!(exact[0].0, 0.0);
            let mut fast = SearchCount::default();
            let found = search.qtp(&q, 8, &mut fast);
            assert_eq!(
                (found[0].1, found[0].2),
                (x0, y0),
                "planted at ({x0}, {y0})"
            );
            assert!(fast.pixels * 5 < count.pixels, "{fast:?} vs {count:?}");
        }
    }

    #[test]
    fn exhaustive_search_costs_are_the_direct_ssd() {
        let tex = sample("gravel_64");
        let search = SearchTexture::new(&tex, 16);
        let mut q = query_at(&tex, 5, 7, 16, 3);
        for v in &mut q.values {
            *v = (*v * 0.9 + 0.03).min(1.0);
        }
        let all = search.exhaustive(&q, &mut SearchCount::default());
        let direct = |x: usize, y: usize| -> f32 {
            let mut s = 0.0;
            for j in 0..16 {
                for i in 0..16 {
                    if q.mask[j * 16 + i] {
                        for (a, b) in tex
                            .pixel(x + i, y + j)
                            .iter()
                            .zip(&q.values[(j * 16 + i) * tex.channels()..])
                        {
                            s += (a - b) * (a - b);
                        }
                    }
                }
            }
            s
        };
        for &(cost, x, y) in all.iter().step_by(97) {
            assert!((cost - direct(x, y)).abs() < 1e-3, "({x}, {y})");
        }
        assert!(all.windows(2).all(|p| p[0].0 <= p[1].0));
    }
}
