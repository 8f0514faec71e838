//! Exact nearest patch by sum of squared differences, fast enough to score whole images: every
//! candidate patch is indexed by its mean value, and a query visits candidates in order of
//! distance from its own mean, stopping when the bound n (mean_q - mean_e)^2, a lower bound of
//! the SSD (Cauchy-Schwarz), reaches the best distance found. Per-channel means give a tighter
//! bound that is checked before the full comparison, which itself stops early.

/// All `size` x `size` patches of an image (RGB, 3 values per pixel), with their means.
pub struct PatchIndex<'a> {
    data: &'a [f32],
    width: usize,
    size: usize,
    /// Candidate top-left corners sorted by overall mean, with the mean and per-channel means.
    sorted: Vec<(f32, [f32; 3], u32, u32)>,
}

/// Values per pixel.
const C: usize = 3;

/// Per-channel means of the patch at (x, y).
fn channel_means(data: &[f32], width: usize, size: usize, x: usize, y: usize) -> [f32; 3] {
    let mut sums = [0.0f32; 3];
    for dy in 0..size {
        let row = &data[((y + dy) * width + x) * C..((y + dy) * width + x + size) * C];
        for px in row.chunks_exact(C) {
            for c in 0..C {
                sums[c] += px[c];
            }
        }
    }
    let n = (size * size) as f32;
    sums.map(|s| s / n)
}

impl<'a> PatchIndex<'a> {
    /// Indexes every patch of a `width` x `height` RGB image (`data`, interleaved).
    #[must_use]
    pub fn new(data: &'a [f32], width: usize, height: usize, size: usize) -> Self {
        let mut sorted = Vec::with_capacity((width - size + 1) * (height - size + 1));
        for y in 0..=height - size {
            for x in 0..=width - size {
                let means = channel_means(data, width, size, x, y);
                sorted.push((
                    (means[0] + means[1] + means[2]) / 3.0,
                    means,
                    x as u32,
                    y as u32,
                ));
            }
        }
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        PatchIndex {
            data,
            width,
            size,
            sorted,
        }
    }

    /// SSD between the query patch (in `query`, at (qx, qy) of a `query_width`-wide image) and
    /// the candidate at (x, y), stopping once it exceeds `bound`.
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

    /// The smallest SSD from the patch at (qx, qy) of `query` to any indexed patch.
    #[must_use]
    pub fn nearest(&self, query: &[f32], query_width: usize, qx: usize, qy: usize) -> f32 {
        let means = channel_means(query, query_width, self.size, qx, qy);
        let mean = (means[0] + means[1] + means[2]) / 3.0;
        let n = (self.size * self.size) as f32;
        let start = self.sorted.partition_point(|e| e.0 < mean);
        let mut best = f32::INFINITY;
        let (mut lo, mut hi) = (start, start);
        // Walk outwards from the query's mean, always taking the side with the closer mean.
        loop {
            let below = lo.checked_sub(1).map(|i| (mean - self.sorted[i].0, i));
            let above = (hi < self.sorted.len()).then(|| (self.sorted[hi].0 - mean, hi));
            let (gap, i) = match (below, above) {
                (Some(b), Some(a)) => {
                    if b.0 <= a.0 {
                        b
                    } else {
                        a
                    }
                }
                (Some(b), None) => b,
                (None, Some(a)) => a,
                (None, None) => break,
            };
            // Overall-mean bound: 3n values differ at least by the mean difference on average.
            if 3.0 * n * gap * gap >= best {
                break;
            }
            if i < lo {
                lo = i
            } else {
                hi = i + 1
            }
            let (_, cm, x, y) = self.sorted[i];
            let channel_bound: f32 = (0..C).map(|c| (means[c] - cm[c]).powi(2)).sum::<f32>() * n;
            if channel_bound >= best {
                continue;
            }
            let d = self.ssd(query, query_width, qx, qy, x as usize, y as usize, best);
            if d < best {
                best = d;
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

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
        for qy in 0..=oh - size {
            for qx in 0..=ow - size {
                let mut brute = f32::INFINITY;
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
                        brute = brute.min(d);
                    }
                }
                let fast = index.nearest(&out, ow, qx, qy);
                assert!(
                    (fast - brute).abs() <= 1e-4 * brute.max(1e-3),
                    "({qx}, {qy}): {fast} vs {brute}"
                );
            }
        }
    }
}
