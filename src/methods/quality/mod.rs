//! Quality metrics that judge any synthesis, independent of the method's own parameters:
//!
//! - **coherence**: mean over output patches (7x7, stride 2) of the distance to the nearest
//!   exemplar patch, as per-value mean squared error on 0..1 RGB: does every part of the output
//!   look like some part of the exemplar? (The texture energy of Kwatra et al. 2005, made
//!   method-independent.)
//! - **completeness**: the same from exemplar patches (stride 2) to the nearest output patch:
//!   does the output use all of the exemplar?
//! - **histogram distance**: per-channel earth mover's distance between the colour histograms
//!   (256 bins on 0..1), averaged over R, G, B; 0 means identical colour distributions.
//! - **flat fraction** (the detail metric, see [`detail`]): the share of output pixels whose
//!   7x7 luminance contrast is below the exemplar's 10th percentile of it; the exemplar itself
//!   scores about 0.10, a washed-out output up to 1. Coherence and completeness do not see
//!   flat regions: a flat patch lies close to the smooth parts of many exemplars.
//!
//! Lower is better for all four.

pub mod detail;
mod nearest;

use crate::core::budget::{DEFAULT_MEMORY_BUDGET_MIB, WorkingSet, image_bytes};
use crate::core::{Error, Image, Result};
use nearest::PatchIndex;

/// Patch side of coherence and completeness.
pub const PATCH: usize = 7;
/// Spacing of the query patches.
pub const STRIDE: usize = 2;
const BINS: usize = 256;

/// The four metrics of one output against its exemplar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quality {
    /// Mean distance of the output's 7x7 patches to their nearest exemplar patches (per-value
    /// squared error on 0..1 RGB): does every part of the output look like the exemplar?
    pub coherence: f64,
    /// The same from the exemplar's patches to the output's: does the output use all of it?
    pub completeness: f64,
    /// Earth mover's distance between the colour histograms, averaged over R, G, B (0: same).
    pub histogram: f64,
    /// Share of flat output pixels (see `detail`); about 0.10 for the exemplar itself.
    pub flat: f64,
}

/// Scores `output` against `exemplar` (any channel counts; both are compared as RGB).
pub fn quality(exemplar: &Image, output: &Image) -> Result<Quality> {
    for (what, img) in [("exemplar", exemplar), ("output", output)] {
        if img.width() < PATCH || img.height() < PATCH {
            return Err(Error::InvalidSize {
                what,
                width: img.width(),
                height: img.height(),
                reason: format!("quality metrics need at least {PATCH}x{PATCH}"),
            });
        }
    }
    check_budget(
        (exemplar.width(), exemplar.height()),
        (output.width(), output.height()),
    )?;
    let ex = exemplar.with_channels(3)?;
    let out = output.with_channels(3)?;
    Ok(Quality {
        coherence: directed(&out, &ex),
        completeness: directed(&ex, &out),
        histogram: histogram_distance(&ex, &out),
        flat: detail::flat_fraction(&out, detail::flat_threshold(&ex)),
    })
}

/// What [`quality`] holds at its peak for an exemplar and an output of the given sizes: both
/// images as RGB, the index of the output's patches (completeness searches them; the
/// exemplar's index, for coherence, is gone by then) and the output's local contrast. A
/// 4096x4096 output would need about 1.6 GiB, more than the default budget, so it is refused
/// with an error rather than run the wasm memory out; a 2048x2048 one needs about 400 MiB.
#[must_use]
pub fn working_set(exemplar: (usize, usize), output: (usize, usize)) -> WorkingSet {
    WorkingSet::new()
        .with("exemplar", image_bytes(exemplar.0, exemplar.1, 3))
        .with("output", image_bytes(output.0, output.1, 3))
        .with(
            "patch index",
            patches(output).max(patches(exemplar)) * nearest::BYTES_PER_PATCH,
        )
        .with("local contrast", image_bytes(output.0, output.1, 1))
}

/// The patches of a `(width, height)` image (top-left corners of its 7x7 patches).
fn patches((w, h): (usize, usize)) -> u64 {
    (w.saturating_sub(PATCH) + 1) as u64 * (h.saturating_sub(PATCH) + 1) as u64
}

/// Refuses, before anything is allocated, a scoring that would pass the default memory budget,
/// naming what makes it large (the image with more patches to index: a photo used whole as the
/// exemplar, or a huge output) and what to do about it (the caller has no budget to raise).
pub fn check_budget(exemplar: (usize, usize), output: (usize, usize)) -> Result<()> {
    let (what, (w, h), remedy) = if patches(exemplar) > patches(output) {
        (
            "exemplar",
            exemplar,
            "shrink or crop the exemplar first (Exemplar.resized, Exemplar.cropped)",
        )
    } else {
        (
            "output",
            output,
            "measure a window of the output (the page scores its central 512x512)",
        )
    };
    working_set(exemplar, output).check_with_remedy(
        &format!("{what} {w}x{h}"),
        "measuring quality",
        DEFAULT_MEMORY_BUDGET_MIB,
        remedy,
    )
}

/// Coherence against the exemplar at whole and half-pixel positions: each output patch's
/// distance to the nearest patch of the exemplar or of the exemplar moved by half a pixel
/// (Lanczos) along x, y or both. For frames that move by fractions of a pixel (flow animation
/// with sub-pixel matches): plain coherence measures the pixel grid there, since the exemplar
/// itself moved by half a pixel scores 0.0009 (tiles_128) to 0.004 (gravel_128), worse than a
/// good synthesis. Native only: a diagnostic of the flow examples, kept out of the wasm package,
/// where a second caller of the patch search stopped the compiler inlining it (2.8 KB).
#[cfg(not(target_arch = "wasm32"))]
pub fn sub_pixel_coherence(exemplar: &Image, output: &Image) -> Result<f64> {
    use crate::core::{Edge, sample::shift};
    quality(exemplar, output)?;
    let ex = exemplar.with_channels(3)?;
    let out = output.with_channels(3)?;
    let moved: Vec<Image> = [(0.0, 0.0), (0.5, 0.0), (0.0, 0.5), (0.5, 0.5)]
        .iter()
        .map(|&(dx, dy)| shift(&ex, dx, dy, Edge::Clamp))
        .collect();
    Ok(directed_to_any(&out, &moved))
}

/// Mean over the patches of `from` (stride 2) of the per-value MSE to the nearest patch of `to`.
fn directed(from: &Image, to: &Image) -> f64 {
    let (mut total, mut count) = (0.0f64, 0usize);
    directed_each(from, to, |_, _, distance| {
        total += distance;
        count += 1;
    });
    total / count as f64
}

/// Calls `visit(x, y, distance)` for every patch of `from` (top-left corner, stride 2, row by
/// row) with the per-value MSE to its nearest patch of `to`. Each search starts from the matches
/// of the query to the left and the one above, moved on by the stride (see
/// [`PatchIndex::nearest_from`]).
fn directed_each(from: &Image, to: &Image, mut visit: impl FnMut(usize, usize, f64)) {
    let index = PatchIndex::new(to.data(), to.width(), to.height(), PATCH);
    let values = (PATCH * PATCH * 3) as f64;
    let columns = (from.width() - PATCH) / STRIDE + 1;
    // The matches of the previous row of queries, by column.
    let mut above: Vec<Option<(usize, usize)>> = vec![None; columns];
    for y in (0..=from.height() - PATCH).step_by(STRIDE) {
        let mut left: Option<(usize, usize)> = None;
        for (column, x) in (0..=from.width() - PATCH).step_by(STRIDE).enumerate() {
            let mut hints = [(usize::MAX, usize::MAX); 2];
            if let Some((mx, my)) = left {
                hints[0] = (mx + STRIDE, my);
            }
            if let Some((mx, my)) = above[column] {
                hints[1] = (mx, my + STRIDE);
            }
            let (distance, at) = index.nearest_from(from.data(), from.width(), x, y, &hints);
            left = Some(at);
            above[column] = Some(at);
            visit(x, y, f64::from(distance) / values);
        }
    }
}

/// Coherence patch by patch: `(x, y, distance)` for every patch that [`quality`]'s coherence
/// averages (top-left corners, stride 2), so that their mean is the coherence. For bounds that
/// hold patch by patch, such as how close to a given image any equally coherent image can lie
/// (`examples/flow_detail.rs`, `BOUND=1`). Native only, like [`sub_pixel_coherence`].
#[cfg(not(target_arch = "wasm32"))]
pub fn coherence_by_patch(exemplar: &Image, output: &Image) -> Result<Vec<(usize, usize, f64)>> {
    quality(exemplar, output)?;
    let ex = exemplar.with_channels(3)?;
    let out = output.with_channels(3)?;
    let mut patches = Vec::new();
    directed_each(&out, &ex, |x, y, d| patches.push((x, y, d)));
    Ok(patches)
}

/// The coherence of `output` against the patches of any of `parts` (each at least 7x7; any
/// channels, compared as RGB): the mean over `output`'s 7x7 patches (stride 2) of the distance
/// to the nearest patch lying wholly inside one part. Scores a filled hole against the known
/// pixels around it, given as the rectangles they make up.
#[cfg(not(target_arch = "wasm32"))]
pub fn coherence_against(parts: &[Image], output: &Image) -> Result<f64> {
    let parts: Vec<Image> = parts
        .iter()
        .filter(|p| p.width() >= PATCH && p.height() >= PATCH)
        .map(|p| p.with_channels(3))
        .collect::<Result<_>>()?;
    if parts.is_empty() || output.width() < PATCH || output.height() < PATCH {
        return Err(Error::InvalidParameter {
            name: "parts",
            reason: format!("need a part and an output of at least {PATCH}x{PATCH}"),
        });
    }
    Ok(directed_to_any(&output.with_channels(3)?, &parts))
}

/// [`directed`] to the nearest patch of any of `to`.
#[cfg(not(target_arch = "wasm32"))]
fn directed_to_any(from: &Image, to: &[Image]) -> f64 {
    let indexes: Vec<PatchIndex<'_>> = to
        .iter()
        .map(|t| PatchIndex::new(t.data(), t.width(), t.height(), PATCH))
        .collect();
    let values = (PATCH * PATCH * 3) as f64;
    let (mut total, mut count) = (0.0f64, 0usize);
    for y in (0..=from.height() - PATCH).step_by(STRIDE) {
        for x in (0..=from.width() - PATCH).step_by(STRIDE) {
            let nearest = indexes
                .iter()
                .map(|i| i.nearest(from.data(), from.width(), x, y))
                .fold(f32::INFINITY, f32::min);
            total += f64::from(nearest) / values;
            count += 1;
        }
    }
    total / count as f64
}

/// Per-channel earth mover's distance between 256-bin histograms, in units of the 0..1 range
/// (the 1-D EMD is the area between the two cumulative distributions).
fn histogram_distance(a: &Image, b: &Image) -> f64 {
    let histogram = |img: &Image, channel: usize| {
        let mut h = [0.0f64; BINS];
        for px in img.data().chunks_exact(3) {
            let bin = ((px[channel].clamp(0.0, 1.0) * (BINS - 1) as f32).round()) as usize;
            h[bin] += 1.0;
        }
        let n = img.pixel_count() as f64;
        h.map(|v| v / n)
    };
    let mut total = 0.0;
    for channel in 0..3 {
        let (ha, hb) = (histogram(a, channel), histogram(b, channel));
        let (mut ca, mut cb, mut emd) = (0.0, 0.0, 0.0);
        for k in 0..BINS {
            ca += ha[k];
            cb += hb[k];
            emd += (ca - cb).abs();
        }
        total += emd / (BINS - 1) as f64;
    }
    total / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::{noise, sample};

    #[test]
    fn a_crop_of_the_exemplar_is_perfectly_coherent_but_incomplete() {
        let ex = sample("gravel_64");
        let crop = ex.crop(8, 8, 32, 32).unwrap();
        let q = quality(&ex, &crop).unwrap();
        assert!(q.coherence < 1e-9, "{q:?}");
        assert!(
            q.completeness > 1e-3,
            "a crop misses most of the exemplar: {q:?}"
        );
        let itself = quality(&ex, &ex).unwrap();
        assert!(itself.coherence < 1e-9 && itself.completeness < 1e-9 && itself.histogram < 1e-12);
    }

    #[test]
    #[cfg(not(target_arch = "wasm32"))]
    fn the_exemplar_moved_half_a_pixel_is_coherent_only_at_sub_pixel_positions() {
        use crate::core::{Edge, sample::shift};
        let ex = sample("gravel_64");
        let moved = shift(&ex, 0.5, 0.5, Edge::Clamp);
        let plain = quality(&ex, &moved).unwrap().coherence;
        let sub = sub_pixel_coherence(&ex, &moved).unwrap();
        assert!(plain > 1e-3 && sub < 1e-9, "plain {plain}, sub-pixel {sub}");
        assert!(sub_pixel_coherence(&ex, &ex).unwrap() < 1e-9);
        assert!(sub_pixel_coherence(&ex, &Image::new(4, 4, 3).unwrap()).is_err());
    }

    #[test]
    #[cfg(not(target_arch = "wasm32"))]
    fn coherence_by_patch_is_the_brute_force_nearest_patch_and_averages_to_coherence() {
        let ex = sample("gravel_64").crop(0, 0, 24, 20).unwrap();
        let out = noise(17, 15, 3, 9);
        let (ex3, out3) = (ex.with_channels(3).unwrap(), out.with_channels(3).unwrap());
        let patches = coherence_by_patch(&ex, &out).unwrap();
        // Corners 0, 2, .., 10 across and 0, 2, .., 8 down.
        assert_eq!(patches.len(), 6 * 5);
        for &(x, y, d) in &patches {
            let mut best = f64::INFINITY;
            for ey in 0..=ex.height() - PATCH {
                for ex_x in 0..=ex.width() - PATCH {
                    let mut sum = 0.0f64;
                    for dy in 0..PATCH {
                        for dx in 0..PATCH {
                            let (a, b) =
                                (out3.pixel(x + dx, y + dy), ex3.pixel(ex_x + dx, ey + dy));
                            sum += (0..3).map(|k| f64::from(a[k] - b[k]).powi(2)).sum::<f64>();
                        }
                    }
                    best = best.min(sum / (PATCH * PATCH * 3) as f64);
                }
            }
            assert!((d - best).abs() < 1e-5, "patch at {x},{y}: {d} vs {best}");
        }
        let mean = patches.iter().map(|p| p.2).sum::<f64>() / patches.len() as f64;
        let coherence = quality(&ex, &out).unwrap().coherence;
        assert!((mean - coherence).abs() < 1e-12, "{mean} vs {coherence}");
    }

    #[test]
    fn noise_scores_worse_than_the_exemplar_and_histograms_shift() {
        let ex = sample("sand_64");
        let q = quality(&ex, &noise(48, 48, 3, 1)).unwrap();
        assert!(
            q.coherence > 0.01 && q.completeness > 0.01 && q.histogram > 0.05,
            "{q:?}"
        );
        // A uniform shift of every value by d moves each histogram by d.
        let flat = Image::from_fn(16, 16, 3, |_, _, _| 0.25).unwrap();
        let shifted = Image::from_fn(16, 16, 3, |_, _, _| 0.5).unwrap();
        let h = quality(&flat, &shifted).unwrap().histogram;
        assert!((h - 0.25).abs() < 0.01, "{h}");
    }

    #[test]
    fn flat_fraction_of_the_exemplar_a_flat_image_and_a_quarter_flat_one() {
        let ex = sample("gravel_128");
        let itself = quality(&ex, &ex).unwrap().flat;
        assert!((itself - 0.10).abs() < 0.01, "{itself}");
        let grey = Image::from_fn(64, 64, 3, |_, _, _| 0.4).unwrap();
        assert_eq!(quality(&ex, &grey).unwrap().flat, 1.0);
        // The top-left quarter of a 2x2 tiling of the exemplar replaced by its mean colour: a
        // quarter of the windows, less those that straddle the border, are flat on top of the
        // exemplar's own 10%.
        let tiled = Image::from_fn(256, 256, 3, |x, y, k| {
            if x < 128 && y < 128 {
                0.45
            } else {
                ex.pixel(x % 128, y % 128)[k.min(ex.channels() - 1)]
            }
        })
        .unwrap();
        let quarter = quality(&ex, &tiled).unwrap().flat;
        let expected = (122.0 * 122.0 + 0.10 * (250.0 * 250.0 - 128.0 * 128.0)) / (250.0 * 250.0);
        assert!((quarter - expected).abs() < 0.03, "{quarter} vs {expected}");
    }

    #[test]
    fn contrast_is_the_window_standard_deviation() {
        let img = noise(12, 9, 3, 4);
        let contrast = detail::local_contrast(&img);
        assert_eq!(contrast.len(), 6 * 3);
        for (i, &c) in contrast.iter().enumerate() {
            let (x0, y0) = (i % 6, i / 6);
            let lum: Vec<f64> = (y0..y0 + 7)
                .flat_map(|y| (x0..x0 + 7).map(move |x| (x, y)))
                .map(|(x, y)| {
                    let p = img.pixel(x, y);
                    0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2])
                })
                .collect();
            let mean = lum.iter().sum::<f64>() / 49.0;
            let sd = (lum.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 49.0).sqrt();
            assert!((f64::from(c) - sd).abs() < 1e-4, "{c} vs {sd}");
        }
    }

    #[test]
    fn a_refusal_names_the_image_that_makes_the_index_large_and_what_to_do() {
        // A photo used whole as the exemplar of a small output: the exemplar is named, with
        // shrinking or cropping it as the way out (measureQuality takes no budget option).
        // A huge output with a small exemplar: the output is named, with measuring a window.
        let cases = [
            (
                (4000, 3000),
                (256, 256),
                "exemplar 4000x3000: measuring quality needs about 1.1 GiB",
                "Exemplar.resized",
            ),
            (
                (128, 128),
                (4096, 4096),
                "output 4096x4096: measuring quality",
                "window of the output",
            ),
        ];
        for (exemplar, output, start, remedy) in cases {
            let msg = check_budget(exemplar, output).unwrap_err().to_string();
            assert!(
                msg.starts_with(start) && msg.contains(remedy) && !msg.contains("memoryBudgetMiB"),
                "{msg}"
            );
        }
        assert!(check_budget((2000, 1500), (512, 512)).is_ok());
    }

    #[test]
    fn an_output_whose_index_would_pass_the_memory_budget_is_refused_by_its_estimate() {
        use crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB;
        let mib = |w: usize| working_set((128, 128), (w, w)).bytes() as f64 / (1u64 << 20) as f64;
        assert!(
            (350.0..450.0).contains(&mib(2048)),
            "2048: {} MiB",
            mib(2048)
        );
        assert!(
            mib(4096) > DEFAULT_MEMORY_BUDGET_MIB as f64,
            "4096: {} MiB",
            mib(4096)
        );
        // quality() checks the estimate before it converts or indexes anything: a grey
        // 4096x4096 output (64 MiB here) is refused with the size, the estimate and the limit.
        let ex = sample("gravel_64");
        let big = Image::new(4096, 4096, 1).unwrap();
        let msg = quality(&ex, &big).unwrap_err().to_string();
        assert!(
            msg.contains("output 4096x4096")
                && msg.contains("patch index")
                && msg.contains("1024 MiB"),
            "{msg}"
        );
    }

    #[test]
    fn too_small_images_are_refused() {
        let tiny = Image::new(6, 20, 1).unwrap();
        let msg = quality(&tiny, &tiny).unwrap_err().to_string();
        assert!(msg.contains("exemplar size 6x20"), "{msg}");
    }
}

#[cfg(test)]
mod timing {
    /// A measurement, not a check: `cargo test --release --lib -- --ignored --nocapture quality_timing`.
    #[test]
    #[ignore = "a timing report; run with --release --ignored --nocapture"]
    fn quality_timing() {
        use crate::core::testing::sample;
        use crate::methods::graphcut::{Options, Session};
        let ex = sample("tiles_128");
        let mut session = Session::new(&ex, Options::default()).unwrap();
        while !session.step().unwrap().done {}
        let out = session.output().unwrap();
        let start = std::time::Instant::now();
        let q = super::quality(&ex, &out).unwrap();
        println!(
            "quality of a 256x256 graph-cut output of tiles_128: {q:?} in {:.0} ms",
            start.elapsed().as_secs_f64() * 1e3
        );
    }
}
