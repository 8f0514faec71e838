//! The detail metric: how much of an output is *flat*, smoother than the exemplar ever is.
//!
//! Coherence and completeness miss wash-out: a flat 7x7 patch lies close to the smooth parts of
//! many exemplars, so an output whose large areas are featureless colour can still score well on
//! both. The flat fraction looks at local contrast instead. For every pixel whose 7x7 window fits
//! the image, the local contrast is the standard deviation of luminance in the window. A pixel
//! of the output is flat when its contrast is below the exemplar's own 10th percentile of local
//! contrast; the flat fraction is the share of such pixels. The exemplar scored against itself
//! gives about 0.10 by construction, an even micro-texture that keeps the exemplar's contrast
//! scores near 0.10 too, and a wash-out scores up to 1. It catches flat regions, blur and
//! averaging of misaligned neighbourhoods; it does not see repetition or wrong structure (the
//! other three metrics do).

use crate::core::Image;

/// Side of the window whose luminance standard deviation is the local contrast.
pub const WINDOW: usize = 7;
/// The exemplar's percentile of local contrast below which an output pixel is flat.
pub const FLAT_PERCENTILE: f64 = 0.10;

/// Rec. 709 luminance of an RGB image (3 channels), one value per pixel.
fn luminance(rgb: &Image) -> Vec<f32> {
    rgb.data()
        .chunks_exact(3)
        .map(|p| 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2])
        .collect()
}

/// Local contrast at every position where a `WINDOW` x `WINDOW` window fits, by summed-area
/// tables of the values and their squares (linear in the image size).
#[must_use]
pub fn local_contrast(rgb: &Image) -> Vec<f32> {
    let (w, h) = (rgb.width(), rgb.height());
    if w < WINDOW || h < WINDOW {
        return Vec::new();
    }
    let lum = luminance(rgb);
    let stride = w + 1;
    let mut sum = vec![0.0f64; stride * (h + 1)];
    let mut sq = vec![0.0f64; stride * (h + 1)];
    for y in 0..h {
        let (mut run, mut run_sq) = (0.0f64, 0.0f64);
        for x in 0..w {
            let v = f64::from(lum[y * w + x]);
            run += v;
            run_sq += v * v;
            sum[(y + 1) * stride + x + 1] = sum[y * stride + x + 1] + run;
            sq[(y + 1) * stride + x + 1] = sq[y * stride + x + 1] + run_sq;
        }
    }
    let area = |t: &[f64], x: usize, y: usize| {
        t[(y + WINDOW) * stride + x + WINDOW]
            - t[y * stride + x + WINDOW]
            - t[(y + WINDOW) * stride + x]
            + t[y * stride + x]
    };
    let n = (WINDOW * WINDOW) as f64;
    let mut out = Vec::with_capacity((w - WINDOW + 1) * (h - WINDOW + 1));
    for y in 0..=h - WINDOW {
        for x in 0..=w - WINDOW {
            let mean = area(&sum, x, y) / n;
            let var = (area(&sq, x, y) / n - mean * mean).max(0.0);
            out.push(var.sqrt() as f32);
        }
    }
    out
}

/// The exemplar's `FLAT_PERCENTILE` of local contrast: below it, an output pixel is flat.
#[must_use]
pub fn flat_threshold(exemplar_rgb: &Image) -> f32 {
    let mut contrast = local_contrast(exemplar_rgb);
    if contrast.is_empty() {
        return 0.0;
    }
    let k = ((contrast.len() as f64 * FLAT_PERCENTILE) as usize).min(contrast.len() - 1);
    *contrast.select_nth_unstable_by(k, f32::total_cmp).1
}

/// The share of `output_rgb`'s windows whose contrast is below `threshold`.
#[must_use]
pub fn flat_fraction(output_rgb: &Image, threshold: f32) -> f64 {
    let contrast = local_contrast(output_rgb);
    if contrast.is_empty() {
        return 0.0;
    }
    contrast.iter().filter(|&&c| c < threshold).count() as f64 / contrast.len() as f64
}
