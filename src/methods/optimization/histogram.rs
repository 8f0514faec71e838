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

/// Buckets of the ranking between a channel's minimum and maximum (16 KB of counts: they stay
/// in the first-level cache while a million pixels are ranked).
const BUCKETS: usize = 4096;

/// Reused buffer of the ranking: the pixels below each bucket.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    starts: Vec<u32>,
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
    /// Ranks come from a histogram of 4,096 buckets between the channel's minimum and maximum
    /// (three sequential passes, where a sort of a million pixels per E-step took a quarter of
    /// a 1024x1024 synthesis): a pixel's rank is the count below its bucket plus its place in
    /// the bucket interpolated by value (the piecewise-linear CDF). A bucket holding one pixel
    /// gives the exact rank; equal values get equal ranks, so a flat area stays flat.
    pub fn match_histogram(
        &self,
        output: &mut Image,
        strength: f32,
        fixed: Option<&[f32]>,
        scratch: &mut Scratch,
    ) {
        let c = output.channels().min(self.channels.len());
        let stride = output.channels();
        let free = |i: usize| fixed.is_none_or(|f| f[i] <= 0.0);
        let data = output.data_mut();
        let pixels = data.len() / stride;
        // All channels in each pass over the interleaved values: the image is read three
        // times, not three times per channel.
        let (mut lo, mut hi) = ([f32::INFINITY; 4], [f32::NEG_INFINITY; 4]);
        for i in (0..pixels).filter(|&i| free(i)) {
            for k in 0..c {
                let v = data[i * stride + k];
                lo[k] = lo[k].min(v);
                hi[k] = hi[k].max(v);
            }
        }
        if lo[0] > hi[0] {
            return; // nothing free
        }
        let mut scale = [0.0f32; 4];
        for k in 0..c {
            if hi[k] > lo[k] {
                scale[k] = BUCKETS as f32 / (hi[k] - lo[k]);
            }
        }
        // The value's position in buckets: the bucket, and the fraction through it.
        // (Truncating casts, not floor(): floor is a library call on baseline x86-64.)
        let position = |v: f32, k: usize| {
            let p = ((v - lo[k]) * scale[k]).max(0.0);
            let b = (p as usize).min(BUCKETS - 1);
            (b, p - b as f32)
        };
        let starts = &mut scratch.starts;
        starts.clear();
        starts.resize(c * (BUCKETS + 1), 0);
        for i in (0..pixels).filter(|&i| free(i)) {
            for k in 0..c {
                starts[k * (BUCKETS + 1) + position(data[i * stride + k], k).0 + 1] += 1;
            }
        }
        for table in starts.chunks_exact_mut(BUCKETS + 1) {
            for b in 0..BUCKETS {
                table[b + 1] += table[b];
            }
        }
        let n = starts[BUCKETS] as usize;
        for i in (0..pixels).filter(|&i| free(i)) {
            for (k, target) in self.channels.iter().enumerate().take(c) {
                let table = &starts[k * (BUCKETS + 1)..(k + 1) * (BUCKETS + 1)];
                let v = &mut data[i * stride + k];
                let (b, fraction) = position(*v, k);
                let count = table[b + 1] - table[b];
                let within = ((fraction * count as f32) as u32).min(count - 1);
                let rank = (table[b] + within) as f32;
                // The exemplar value at the same quantile (centre of the rank's bin).
                let m = target.len();
                let q = ((rank + 0.5) * m as f32 / n as f32) as usize;
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

#[cfg(test)]
mod timing {
    use super::*;
    use crate::core::testing::noise;

    #[test]
    #[ignore = "timing: cargo test --release --lib histogram_timing -- --ignored --nocapture"]
    fn histogram_timing() {
        let ex = noise(128, 128, 3, 1);
        let mut out = noise(1024, 1024, 3, 2);
        let sorted = SortedChannels::new(&ex);
        let mut scratch = Scratch::default();
        let t = std::time::Instant::now();
        for _ in 0..10 {
            sorted.match_histogram(&mut out, 1.0, None, &mut scratch);
        }
        println!(
            "match_histogram 1024x1024x3: {:.1} ms",
            t.elapsed().as_secs_f64() * 100.0
        );
    }
}
