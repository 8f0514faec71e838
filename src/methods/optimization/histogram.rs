//! Histogram matching of the E-step's output to the exemplar, per channel.
//!
//! The E-step averages the overlapping matched neighbourhoods. Where neighbouring matches are
//! not shifted copies of each other, the average is a colour none of them proposed: contrast
//! shrinks, thin dark features (cracks, mortar, grain) fade, and the next M-step finds the
//! exemplar's smooth areas to be the nearest neighbourhoods, which the next average spreads.
//! Matching the output's histogram to the exemplar's after every E-step (as Kopf et al. 2007
//! and Kaspar et al. 2015 do in texture optimisation) puts the lost contrast back before the
//! M-step sees it, and keeps the output's colour distribution the exemplar's.

use crate::core::Image;

/// Buckets of the ranking: values closer than (max - min) / 65536 rank in pixel order.
const BUCKETS: usize = 1 << 16;

/// Reused buffers of the ranking: one bucket per value step, and each free pixel's bucket.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    starts: Vec<u32>,
    buckets: Vec<u32>,
}

/// Each channel's values of the exemplar, sorted: the target quantiles.
#[derive(Debug, Clone)]
pub struct SortedChannels {
    channels: Vec<Vec<f32>>,
}

impl SortedChannels {
    #[must_use]
    pub fn new(exemplar: &Image) -> Self {
        let c = exemplar.channels();
        let channels = (0..c)
            .map(|k| {
                let mut v: Vec<f32> = exemplar.data().iter().skip(k).step_by(c).copied().collect();
                v.sort_unstable_by(f32::total_cmp);
                v
            })
            .collect();
        SortedChannels { channels }
    }

    /// Moves every value of `output` towards the exemplar value of the same rank, by `strength`
    /// (0 leaves it, 1 matches the histograms exactly). Pixels where `fixed` is above 0 (the
    /// soft constraints' mask: the user's colours, which need not be the exemplar's) keep their
    /// values and are left out of the ranking.
    ///
    /// Ranks come from a counting sort over 65,536 value buckets between the channel's minimum
    /// and maximum: two sequential passes instead of a sort of a million pixels per E-step
    /// (a comparison sort took a quarter of a 1024x1024 synthesis). Values in one bucket, closer
    /// than 1/65,536 of the range, rank in pixel order, the same on every platform.
    pub fn match_histogram(
        &self,
        output: &mut Image,
        strength: f32,
        fixed: Option<&[f32]>,
        scratch: &mut Scratch,
    ) {
        let c = output.channels();
        let free = |i: usize| fixed.is_none_or(|f| f[i] <= 0.0);
        let data = output.data_mut();
        let pixels = data.len() / c;
        for (k, target) in self.channels.iter().enumerate().take(c) {
            let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
            for i in (0..pixels).filter(|&i| free(i)) {
                let v = data[i * c + k];
                lo = lo.min(v);
                hi = hi.max(v);
            }
            if lo > hi {
                return; // nothing free
            }
            let scale = if hi > lo {
                (BUCKETS - 1) as f32 / (hi - lo)
            } else {
                0.0
            };
            let bucket_of = |v: f32| (((v - lo) * scale) as usize).min(BUCKETS - 1) as u32;
            scratch.starts.clear();
            scratch.starts.resize(BUCKETS + 1, 0);
            scratch.buckets.clear();
            scratch.buckets.resize(pixels, 0);
            let mut n = 0usize;
            for i in 0..pixels {
                if free(i) {
                    let b = bucket_of(data[i * c + k]);
                    scratch.buckets[i] = b;
                    scratch.starts[b as usize + 1] += 1;
                    n += 1;
                }
            }
            for b in 0..BUCKETS {
                scratch.starts[b + 1] += scratch.starts[b];
            }
            let m = target.len();
            let per_rank = m as f64 / n as f64;
            for i in 0..pixels {
                if !free(i) {
                    continue;
                }
                let b = scratch.buckets[i] as usize;
                let rank = scratch.starts[b];
                scratch.starts[b] += 1;
                // The exemplar value at the same quantile (centre of the rank's bin).
                let q = ((f64::from(rank) + 0.5) * per_rank) as usize;
                let v = &mut data[i * c + k];
                *v += strength * (target[q.min(m - 1)] - *v);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::noise;

    #[test]
    fn full_strength_gives_the_exemplar_histogram_and_keeps_the_order() {
        let ex = noise(16, 16, 3, 1);
        let mut out =
            Image::from_fn(32, 16, 3, |x, y, k| 0.4 + 0.001 * (x + 40 * y + k) as f32).unwrap();
        let before = out.clone();
        SortedChannels::new(&ex).match_histogram(&mut out, 1.0, None, &mut Scratch::default());
        for k in 0..3 {
            let mut a: Vec<f32> = ex.data().iter().skip(k).step_by(3).copied().collect();
            let mut b: Vec<f32> = out.data().iter().skip(k).step_by(3).copied().collect();
            a.sort_by(f32::total_cmp);
            b.sort_by(f32::total_cmp);
            // The output has twice the pixels: each exemplar value appears twice.
            for (i, v) in b.iter().enumerate() {
                assert_eq!(*v, a[i / 2]);
            }
        }
        // Ranks are kept: a brighter input pixel stays at least as bright.
        let (p, q) = (before.pixel(3, 2)[0], before.pixel(9, 5)[0]);
        assert!(p < q && out.pixel(3, 2)[0] <= out.pixel(9, 5)[0]);
        let mut same = before.clone();
        SortedChannels::new(&ex).match_histogram(&mut same, 0.0, None, &mut Scratch::default());
        assert_eq!(same, before);
        // Fixed pixels keep their values.
        let mut fixed = vec![0.0; 32 * 16];
        fixed[5] = 1.0;
        let mut partly = before.clone();
        SortedChannels::new(&ex).match_histogram(
            &mut partly,
            1.0,
            Some(&fixed),
            &mut Scratch::default(),
        );
        assert_eq!(partly.pixel(5, 0), before.pixel(5, 0));
        assert_ne!(partly.pixel(6, 0), before.pixel(6, 0));
    }
}
