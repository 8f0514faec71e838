//! Histogram matching of the E-step's output to the exemplar, per channel.
//!
//! The E-step averages the overlapping matched neighbourhoods. Where neighbouring matches are
//! not shifted copies of each other, the average is a colour none of them proposed: contrast
//! shrinks, thin dark features (cracks, mortar, grain) fade, and the next M-step finds the
//! exemplar's smooth areas to be the nearest neighbourhoods, which the next average spreads.
//! Matching the output's histogram to the exemplar's after every E-step (as Kopf et al. 2007
//! and Kaspar et al. 2015 do in texture optimisation) puts the lost contrast back before the
//! M-step sees it, and keeps the output's colour distribution the exemplar's.

use crate::core::math::greater;
use crate::core::{Image, parallel};

/// Buckets of the ranking between a channel's minimum and maximum (16 KB of counts: they stay
/// in the first-level cache while a million pixels are ranked).
const BUCKETS: usize = 4096;

/// A histogram matching under way (reused between matchings): three passes over the pixels
/// (each channel's range, the bucket counts, the new values), resumable after any pixel so that
/// a session can spread one over several steps.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    /// The pass under way (0 to 2; 3 when done) and the next pixel in it.
    pass: u8,
    next: usize,
    lo: [f32; 4],
    hi: [f32; 4],
    scale: [f32; 4],
    /// Per channel, the pixels below each bucket (`BUCKETS + 1` counts).
    starts: Vec<u32>,
    /// Per channel, the exemplar value of the rank at each bucket boundary (`BUCKETS + 1`
    /// values): the transfer function, made once the counts are known.
    transfer: Vec<f32>,
}

impl Scratch {
    /// Starts a new matching.
    pub fn restart(&mut self) {
        self.pass = 0;
        self.next = 0;
        self.lo = [f32::INFINITY; 4];
        self.hi = [f32::NEG_INFINITY; 4];
    }

    /// The share of the matching done, 0 to 1, over `pixels` pixels.
    #[must_use]
    pub fn fraction(&self, pixels: usize) -> f64 {
        (f64::from(self.pass) + self.next as f64 / pixels.max(1) as f64) / 3.0
    }
}

/// Exemplars up to this many pixels give their quantiles from every pixel.
pub const MAX_QUANTILE_PIXELS: usize = 1 << 20;

/// Each channel's values of the exemplar, sorted: the target quantiles.
#[derive(Debug, Clone)]
pub struct SortedChannels {
    channels: Vec<Vec<f32>>,
}

impl SortedChannels {
    /// The quantiles of `exemplar`, from every pixel up to [`MAX_QUANTILE_PIXELS`] and from an
    /// even subsample of a larger one (a 4000x3000 photo: sorting 12 million values per channel
    /// takes seconds at each level's start, for quantiles that a million samples give as well).
    #[must_use]
    pub fn new(exemplar: &Image) -> Self {
        Self::of_pixels(exemplar, None)
    }

    /// The quantiles of the pixels of `image` where `keep` is true (every pixel with `None`),
    /// subsampled like [`SortedChannels::new`]. Inpainting matches the hole to the known pixels
    /// around it so, not to the whole exemplar: a wall's windows are not in the hole's share.
    #[must_use]
    pub fn of_pixels(image: &Image, keep: Option<&[bool]>) -> Self {
        let c = image.channels();
        let kept: Vec<f32>;
        let data = match keep {
            None => image.data(),
            Some(keep) => {
                kept = image
                    .data()
                    .chunks_exact(c)
                    .zip(keep)
                    .filter(|(_, k)| **k)
                    .flat_map(|(p, _)| p.iter().copied())
                    .collect();
                &kept
            }
        };
        let pixels = data.len() / c;
        let every = pixels.div_ceil(MAX_QUANTILE_PIXELS).max(1);
        let channels = (0..c)
            .map(|k| {
                let mut v: Vec<f32> = data
                    .iter()
                    .skip(k)
                    .step_by(c * every)
                    .copied()
                    .collect();
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
    /// (three sequential passes, where a sort of a million pixels per E-step takes a quarter of
    /// a 1024x1024 synthesis). The transfer function is piecewise linear: at each bucket
    /// boundary it gives the exemplar quantile of the rank there (the count of pixels below),
    /// and a value inside a bucket is interpolated by its place in the bucket. Equal values get
    /// equal new values, so a flat area stays flat, and the order of values is kept.
    pub fn match_histogram(
        &self,
        output: &mut Image,
        strength: f32,
        fixed: Option<&[f32]>,
        scratch: &mut Scratch,
    ) {
        scratch.restart();
        let mut unlimited = usize::MAX;
        self.resume(output, strength, fixed, scratch, &mut unlimited);
    }

    /// [`SortedChannels::match_histogram`] in parts: at most `budget` more pixel visits from
    /// where `scratch` stopped (after [`Scratch::restart`]), taken off `budget`; the result
    /// does not depend on where it stops, as long as `output` is left alone in between.
    /// Returns true when done.
    pub fn resume(
        &self,
        output: &mut Image,
        strength: f32,
        fixed: Option<&[f32]>,
        scratch: &mut Scratch,
        budget: &mut usize,
    ) -> bool {
        let c = output.channels().min(self.channels.len());
        let stride = output.channels();
        let free = |i: usize| fixed.is_none_or(|f| f[i] <= 0.0);
        let data = output.data_mut();
        let pixels = data.len() / stride;
        while scratch.pass < 3 && *budget > 0 {
            let range = scratch.next..pixels.min(scratch.next.saturating_add(*budget));
            *budget -= range.len();
            scratch.next = range.end;
            let Scratch {
                pass,
                lo,
                hi,
                scale,
                starts,
                transfer,
                ..
            } = scratch;
            // Whole pixels and nothing fixed (the usual case): the passes in loops over a
            // channel count known at compile time (grey and RGB), which the compiler unrolls and
            // vectorises; the arithmetic per value is the general loops' below. (Other counts,
            // RGBA among them, are rare enough to keep the package smaller: each instance is
            // about 1 KB of gzipped wasm.)
            let plain = fixed.is_none() && c == stride && matches!(c, 1 | 3);
            if plain {
                let values = &mut data[range.start * stride..range.end * stride];
                let tables = Tables {
                    scale,
                    transfer,
                    strength,
                };
                if c == 1 {
                    plain_pass::<1, 4>(*pass, values, lo, hi, starts, &tables);
                } else {
                    plain_pass::<3, 12>(*pass, values, lo, hi, starts, &tables);
                }
            }
            // All channels in each pass over the interleaved values: the image is read three
            // times, not three times per channel.
            match pass {
                _ if plain => {}
                0 => {
                    for i in range.filter(|&i| free(i)) {
                        for k in 0..c {
                            let v = data[i * stride + k];
                            // Compares, not f32::min/max: those also order NaNs, at four
                            // more instructions a value in wasm. A NaN is skipped either way.
                            if v < lo[k] {
                                lo[k] = v;
                            }
                            if v > hi[k] {
                                hi[k] = v;
                            }
                        }
                    }
                }
                1 => {
                    for i in range.filter(|&i| free(i)) {
                        for k in 0..c {
                            starts[k * (BUCKETS + 1)
                                + bucket(data[i * stride + k], lo[k], scale[k])
                                + 1] += 1;
                        }
                    }
                }
                _ => {
                    // Every channel of a pixel in one pass over the image. A value's new value
                    // is one load from a 16 KB table per channel (the boundaries around its
                    // bucket), not a count then an exemplar value at the rank it gives (a
                    // dependent load from the whole sorted exemplar: most of this pass's time).
                    let transfers: [Option<Transfer<'_>>; 4] = std::array::from_fn(|k| {
                        (k < c).then(|| Transfer::of(transfer, k, lo, scale))
                    });
                    let pixels =
                        data[range.start * stride..range.end * stride].chunks_exact_mut(stride);
                    let apply = |px: &mut [f32]| {
                        for (v, transfer) in px.iter_mut().zip(&transfers) {
                            if let Some(transfer) = transfer {
                                *v += strength * (transfer.value(*v) - *v);
                            }
                        }
                    };
                    match fixed {
                        None => pixels.for_each(apply),
                        Some(f) => pixels
                            .zip(&f[range.clone()])
                            .filter(|(_, f)| **f <= 0.0)
                            .for_each(|(px, _)| apply(px)),
                    }
                }
            }
            if scratch.next < pixels {
                continue;
            }
            // The pass is done: prepare the next.
            scratch.next = 0;
            scratch.pass += 1;
            match scratch.pass {
                1 => {
                    if scratch.lo[0] > scratch.hi[0] {
                        scratch.pass = 3; // nothing free
                    }
                    for k in 0..c {
                        scratch.scale[k] = if scratch.hi[k] > scratch.lo[k] {
                            BUCKETS as f32 / (scratch.hi[k] - scratch.lo[k])
                        } else {
                            0.0
                        };
                    }
                    scratch.starts.clear();
                    scratch.starts.resize(c * (BUCKETS + 1), 0);
                }
                2 => {
                    for table in scratch.starts.chunks_exact_mut(BUCKETS + 1) {
                        for b in 0..BUCKETS {
                            table[b + 1] += table[b];
                        }
                    }
                    scratch.transfer.clear();
                    for (k, below) in scratch.starts.chunks_exact(BUCKETS + 1).enumerate() {
                        let target = &self.channels[k];
                        let pixels = below[BUCKETS];
                        scratch
                            .transfer
                            .extend(below.iter().map(|&r| quantile(target, r, pixels)));
                    }
                }
                _ => {}
            }
        }
        scratch.pass >= 3
    }
}

/// Pixels in a piece of a pass that runs in parallel ([`crate::core::parallel`]): fixed, so
/// the pieces do not depend on the thread count. The minima, maxima and counts of the pieces
/// combine exactly, and the new values are per value, so the result is the serial one.
const PIECE_PIXELS: usize = 1 << 14;

/// What the last two passes read, made between passes.
struct Tables<'a> {
    scale: &'a [f32; 4],
    transfer: &'a [f32],
    strength: f32,
}

/// One pass of [`SortedChannels::resume`] over `values`, whole pixels of `C` channels none of
/// which is fixed; `N` is four pixels' values (`4 * C`). The pass runs over pieces of
/// [`PIECE_PIXELS`] pixels in parallel: each piece's range or counts, then those combined in
/// piece order; or each piece's new values.
fn plain_pass<const C: usize, const N: usize>(
    pass: u8,
    values: &mut [f32],
    lo: &mut [f32; 4],
    hi: &mut [f32; 4],
    starts: &mut [u32],
    tables: &Tables<'_>,
) {
    let piece = PIECE_PIXELS * C;
    let pieces = values.len().div_ceil(piece);
    let part = |p: usize| &values[p * piece..values.len().min((p + 1) * piece)];
    match pass {
        0 => {
            for (low, high) in parallel::map(pieces, |p| range_pass::<C, N>(part(p))) {
                for k in 0..C {
                    if low[k] < lo[k] {
                        lo[k] = low[k];
                    }
                    if high[k] > hi[k] {
                        hi[k] = high[k];
                    }
                }
            }
        }
        1 if pieces <= 1 => count_pass::<C>(values, lo, tables.scale, starts),
        1 => {
            let counts = parallel::map(pieces, |p| {
                let mut counts = vec![0u32; C * (BUCKETS + 1)];
                count_pass::<C>(part(p), lo, tables.scale, &mut counts);
                counts
            });
            for counts in counts {
                for (total, n) in starts.iter_mut().zip(counts) {
                    *total += n;
                }
            }
        }
        _ => {
            let transfers: [Transfer<'_>; C] =
                std::array::from_fn(|k| Transfer::of(tables.transfer, k, lo, tables.scale));
            let strength = tables.strength;
            parallel::for_each_piece_mut(values, piece, |_, values| {
                for px in values.chunks_exact_mut(C) {
                    for (v, t) in px.iter_mut().zip(&transfers) {
                        *v += strength * (t.value(*v) - *v);
                    }
                }
            });
        }
    }
}

/// Each channel's minimum and maximum over `values` (NaNs left out). It keeps `N` running
/// minima and maxima (value `j` of every four pixels in lane `j`) and folds the lanes into the
/// channels at the end: the same minimum and maximum, in a loop over fixed-size blocks.
fn range_pass<const C: usize, const N: usize>(values: &[f32]) -> ([f32; 4], [f32; 4]) {
    let (mut low, mut high) = ([f32::INFINITY; N], [f32::NEG_INFINITY; N]);
    let blocks = values.chunks_exact(N);
    let rest = blocks.remainder();
    let mut take = |lane: usize, v: f32| {
        if v < low[lane] {
            low[lane] = v;
        }
        if v > high[lane] {
            high[lane] = v;
        }
    };
    for block in blocks {
        for (lane, &v) in block.iter().enumerate() {
            take(lane, v);
        }
    }
    for (lane, &v) in rest.iter().enumerate() {
        take(lane, v);
    }
    let (mut lo, mut hi) = ([f32::INFINITY; 4], [f32::NEG_INFINITY; 4]);
    for lane in 0..N {
        let k = lane % C;
        if low[lane] < lo[k] {
            lo[k] = low[lane];
        }
        if high[lane] > hi[k] {
            hi[k] = high[lane];
        }
    }
    (lo, hi)
}

/// Adds the bucket counts of `values` to `starts` (a table of `BUCKETS + 1` per channel).
fn count_pass<const C: usize>(values: &[f32], lo: &[f32; 4], scale: &[f32; 4], starts: &mut [u32]) {
    let mut tables = starts.chunks_exact_mut(BUCKETS + 1);
    let counts: [&mut [u32; BUCKETS + 1]; C] = std::array::from_fn(|_| {
        tables
            .next()
            .and_then(|t| t.try_into().ok())
            .expect("a table per channel")
    });
    for px in values.chunks_exact(C) {
        for k in 0..C {
            counts[k][bucket(px[k], lo[k], scale[k]) + 1] += 1;
        }
    }
}

/// The bucket of value `v` in a channel whose range starts at `lo`, `scale` buckets per unit.
/// (A truncating cast, not floor(): floor is a library call on baseline x86-64.)
#[inline]
fn bucket(v: f32, lo: f32, scale: f32) -> usize {
    (greater(0.0, (v - lo) * scale) as usize).min(BUCKETS - 1)
}

/// The exemplar value at output rank `rank` of `pixels`: the sorted exemplar read at the same
/// share of its length, between the centres of its values, linearly between neighbours.
fn quantile(target: &[f32], rank: u32, pixels: u32) -> f32 {
    let last = target.len() - 1;
    let at = (f64::from(rank) / f64::from(pixels.max(1)) * target.len() as f64 - 0.5)
        .clamp(0.0, last as f64);
    let i = at as usize;
    let (a, b) = (target[i], target[(i + 1).min(last)]);
    (f64::from(a) + (at - i as f64) * f64::from(b - a)) as f32
}

/// One channel's transfer function: the exemplar quantiles at the bucket boundaries.
struct Transfer<'a> {
    /// Non-decreasing.
    table: &'a [f32; BUCKETS + 1],
    lo: f32,
    scale: f32,
}

impl<'a> Transfer<'a> {
    /// Channel `k`'s, from the tables of all channels.
    fn of(tables: &'a [f32], k: usize, lo: &[f32; 4], scale: &[f32; 4]) -> Self {
        let table = &tables[k * (BUCKETS + 1)..(k + 1) * (BUCKETS + 1)];
        Transfer {
            table: table.try_into().expect("a table per channel"),
            lo: lo[k],
            scale: scale[k],
        }
    }

    /// The new value of `v`: between the quantiles at its bucket's two boundaries, by its place
    /// in the bucket.
    #[inline]
    fn value(&self, v: f32) -> f32 {
        let at = greater(0.0, (v - self.lo) * self.scale);
        let b = (at as u32).min(BUCKETS as u32 - 1) as usize;
        let (a, c) = (self.table[b], self.table[b + 1]);
        a + (at - b as f32) * (c - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::noise;

    /// The loops for whole pixels with nothing fixed give the general loops' values to the bit
    /// (an all-zero mask takes the general loops and fixes nothing), for grey and RGB (and the
    /// general loops alone for two and four channels), at full and half strength, in one run
    /// and resumed after an odd number of pixels; in one piece, and over several pieces (the
    /// parallel passes) with a last one cut short.
    #[test]
    fn plain_pixel_loops_equal_the_general_loops_to_the_bit() {
        for ((w, h), resume_after) in [((37, 29), 97), ((211, 173), 20_011)] {
            plain_loops_equal_general_loops(w, h, resume_after);
        }
    }

    fn plain_loops_equal_general_loops(w: usize, h: usize, resume_after: usize) {
        for channels in [1, 3, 2, 4] {
            let ex = noise(24, 20, channels, 3);
            // Values outside the exemplar's range, another range per channel, a flat run, and a
            // size that leaves a remainder after blocks of four pixels.
            let out = Image::from_fn(w, h, channels, |x, y, k| {
                let spread = 1.0 + k as f32;
                if y == 3 {
                    0.5
                } else {
                    ((x * 7 + y * 13 + k * 5) % 31) as f32 / 20.0 * spread - 0.2 * spread
                }
            })
            .unwrap();
            let none = vec![0.0f32; w * h];
            let sorted = SortedChannels::new(&ex);
            for strength in [1.0, 0.5] {
                let mut general = out.clone();
                sorted.match_histogram(
                    &mut general,
                    strength,
                    Some(&none),
                    &mut Scratch::default(),
                );
                let mut plain = out.clone();
                sorted.match_histogram(&mut plain, strength, None, &mut Scratch::default());
                let mut resumed = out.clone();
                let mut scratch = Scratch::default();
                scratch.restart();
                loop {
                    let mut budget = resume_after;
                    if sorted.resume(&mut resumed, strength, None, &mut scratch, &mut budget) {
                        break;
                    }
                }
                let bits = |i: &Image| i.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
                assert_ne!(bits(&general), bits(&out));
                assert_eq!(bits(&plain), bits(&general), "{channels} channels");
                assert_eq!(
                    bits(&resumed),
                    bits(&general),
                    "{channels} channels, resumed"
                );
            }
        }
    }

    #[test]
    fn full_strength_gives_the_exemplar_histogram_and_keeps_the_order() {
        let ex = noise(16, 16, 3, 1);
        let mut out =
            Image::from_fn(32, 16, 3, |x, y, k| 0.4 + 0.001 * (x + 40 * y + k) as f32).unwrap();
        let before = out.clone();
        SortedChannels::new(&ex).match_histogram(&mut out, 1.0, None, &mut Scratch::default());
        for k in 0..3 {
            let mut a: Vec<f32> = ex.data().iter().skip(k).step_by(3).copied().collect();
            a.sort_by(f32::total_cmp);
            // The oracle: every output pixel's exact rank, by sorting the input.
            let values = |img: &Image| -> Vec<f32> {
                img.data().iter().skip(k).step_by(3).copied().collect()
            };
            let (input, matched) = (values(&before), values(&out));
            let mut order: Vec<usize> = (0..input.len()).collect();
            order.sort_by(|&i, &j| input[i].total_cmp(&input[j]));
            for (rank, &i) in order.iter().enumerate() {
                // The output has twice the pixels: the pixel of rank r takes the exemplar's
                // value of rank r / 2, or lies between it and a neighbour.
                let (below, above) = (a[(rank / 2).saturating_sub(1)], a[(rank / 2 + 1).min(255)]);
                assert!(
                    (below..=above).contains(&matched[i]),
                    "channel {k}, rank {rank}: {} not in {below}..={above}",
                    matched[i]
                );
                // The order is kept.
                if rank > 0 {
                    assert!(matched[i] >= matched[order[rank - 1]], "rank {rank}");
                }
            }
            assert_eq!(matched[order[0]], a[0]);
            assert_eq!(matched[order[511]], a[255]);
        }
        // In parts (a few pixels per call), the same values.
        let mut parts = before.clone();
        let mut scratch = Scratch::default();
        scratch.restart();
        let sorted = SortedChannels::new(&ex);
        let mut calls = 0;
        while !sorted.resume(&mut parts, 1.0, None, &mut scratch, &mut 37) {
            calls += 1;
        }
        assert!(calls >= 3 * 512 / 37 - 1, "{calls} calls");
        assert_eq!(parts, out);
        let mut same = before.clone();
        SortedChannels::new(&ex).match_histogram(&mut same, 0.0, None, &mut Scratch::default());
        assert_eq!(same, before);
        // Equal values get equal new values: a flat area stays flat.
        let mut flat = Image::from_fn(32, 16, 3, |x, _, k| {
            if x < 20 {
                0.3 + 0.1 * k as f32
            } else {
                0.01 * x as f32
            }
        })
        .unwrap();
        SortedChannels::new(&ex).match_histogram(&mut flat, 1.0, None, &mut Scratch::default());
        for y in 0..16 {
            for x in 0..20 {
                assert_eq!(flat.pixel(x, y), flat.pixel(0, 0), "({x}, {y})");
            }
        }
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
        scratch.restart();
        for pass in 0..3 {
            let t = std::time::Instant::now();
            let mut budget = 1024 * 1024;
            sorted.resume(&mut out, 1.0, None, &mut scratch, &mut budget);
            println!("pass {pass}: {:.1} ms", t.elapsed().as_secs_f64() * 1000.0);
        }
    }
}
