//! Bilinear and bicubic sampling, resizing to any size, and shrinking by area averaging. Coordinates
//! put pixel (i, j)'s centre at (i, j).

use super::error::{Error, Result};
use super::image::Image;
use super::math::{greater, lesser};

/// What lies beyond the border: the border pixel repeated, or the image repeated periodically
/// (for tileable textures).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Edge {
    #[default]
    Clamp,
    Wrap,
}

impl Edge {
    /// Maps an integer coordinate onto `0..len`.
    #[inline]
    #[must_use]
    pub fn resolve(self, i: isize, len: usize) -> usize {
        match self {
            Edge::Clamp => i.clamp(0, len as isize - 1) as usize,
            Edge::Wrap => i.rem_euclid(len as isize) as usize,
        }
    }
}

/// Bilinearly interpolates the image at (x, y) into `out` (one value per channel).
pub fn sample_bilinear(image: &Image, x: f32, y: f32, edge: Edge, out: &mut [f32]) {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let (fx, fy) = (x.floor(), y.floor());
    let (tx, ty) = (x - fx, y - fy);
    let (ix, iy) = (fx as isize, fy as isize);
    let x0 = edge.resolve(ix, w);
    let x1 = edge.resolve(ix + 1, w);
    let y0 = edge.resolve(iy, h);
    let y1 = edge.resolve(iy + 1, h);
    let d = image.data();
    let (i00, i10, i01, i11) = (
        (y0 * w + x0) * c,
        (y0 * w + x1) * c,
        (y1 * w + x0) * c,
        (y1 * w + x1) * c,
    );
    for (k, o) in out.iter_mut().enumerate().take(c) {
        let top = d[i00 + k] + (d[i10 + k] - d[i00 + k]) * tx;
        let bottom = d[i01 + k] + (d[i11 + k] - d[i01 + k]) * tx;
        *o = top + (bottom - top) * ty;
    }
}

/// Catmull-Rom weights of the four samples at offsets -1, 0, 1, 2 for a fraction `t` in [0, 1).
#[inline]
fn catmull_rom(t: f32) -> [f32; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

/// Bicubic (Catmull-Rom) interpolation at (x, y) into `out`, clamped to the range of the four
/// nearest pixels so that edges do not ring. Sharper than bilinear: a frame warped again and
/// again (flow animation) keeps its detail far longer, and it still returns the pixel at a
/// pixel centre, so whole-pixel shifts stay exact.
pub fn sample_bicubic(image: &Image, x: f32, y: f32, edge: Edge, out: &mut [f32]) {
    // RGB, what every warp in the library samples, in one pass over the taps; other channel
    // counts channel by channel (each instance of the one-pass form is about 600 bytes of
    // compressed wasm).
    match image.channels() {
        3 => bicubic::<3>(image, x, y, edge, out),
        _ => sample_bicubic_per_channel(image, x, y, edge, out),
    }
}

/// [`sample_bicubic`] for `C` channels: every channel of a tap at once (one pass over the 16
/// taps, not one per channel: twice as fast), each channel's sums added in the same order as
/// [`sample_bicubic_per_channel`], so the values are the same to the bit.
fn bicubic<const C: usize>(image: &Image, x: f32, y: f32, edge: Edge, out: &mut [f32]) {
    let (w, h) = (image.width(), image.height());
    let (fx, fy) = (x.floor(), y.floor());
    let (wx, wy) = (catmull_rom(x - fx), catmull_rom(y - fy));
    let (ix, iy) = (fx as isize, fy as isize);
    let xs = [-1isize, 0, 1, 2].map(|d| edge.resolve(ix + d, w) * C);
    let ys = [-1isize, 0, 1, 2].map(|d| edge.resolve(iy + d, h) * w * C);
    let d = image.data();
    let tap = |at: usize| -> [f32; C] { d[at..at + C].try_into().expect("C values") };
    let mut sum = [0.0f32; C];
    for (j, &row_start) in ys.iter().enumerate() {
        let mut row = [0.0f32; C];
        for (i, &col) in xs.iter().enumerate() {
            let px = tap(row_start + col);
            for k in 0..C {
                row[k] += wx[i] * px[k];
            }
        }
        for k in 0..C {
            sum[k] += wy[j] * row[k];
        }
    }
    // Clamped to the four nearest pixels' range (min and max are exact in any order).
    let near = [ys[1] + xs[1], ys[1] + xs[2], ys[2] + xs[1], ys[2] + xs[2]].map(tap);
    for (k, o) in out.iter_mut().enumerate().take(C) {
        let lo = near.iter().fold(f32::INFINITY, |m, p| lesser(m, p[k]));
        let hi = near.iter().fold(f32::NEG_INFINITY, |m, p| greater(m, p[k]));
        *o = sum[k].clamp(lo, hi);
    }
}

/// [`sample_bicubic`] one channel at a time: the direct form, and the one-pass form's test
/// oracle.
fn sample_bicubic_per_channel(image: &Image, x: f32, y: f32, edge: Edge, out: &mut [f32]) {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let (fx, fy) = (x.floor(), y.floor());
    let (wx, wy) = (catmull_rom(x - fx), catmull_rom(y - fy));
    let (ix, iy) = (fx as isize, fy as isize);
    let xs = [-1isize, 0, 1, 2].map(|d| edge.resolve(ix + d, w));
    let ys = [-1isize, 0, 1, 2].map(|d| edge.resolve(iy + d, h));
    let d = image.data();
    for (k, o) in out.iter_mut().enumerate().take(c) {
        let mut sum = 0.0f32;
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        for (j, &yy) in ys.iter().enumerate() {
            let mut row = 0.0f32;
            for (i, &xx) in xs.iter().enumerate() {
                let v = d[(yy * w + xx) * c + k];
                row += wx[i] * v;
                if (1..=2).contains(&i) && (1..=2).contains(&j) {
                    lo = lesser(lo, v);
                    hi = greater(hi, v);
                }
            }
            sum += wy[j] * row;
        }
        *o = sum.clamp(lo, hi);
    }
}

/// Lanczos-3 weights of the six samples at offsets -2..=3 for a fraction `t` in [0, 1),
/// normalised to sum to 1.
fn lanczos3(t: f32) -> [f32; 6] {
    if t == 0.0 {
        // Exactly the pixel (sin(pi k) is not exactly 0 in floating point).
        return [0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    }
    let sinc = |x: f32| {
        if x.abs() < 1e-6 {
            1.0
        } else {
            let px = std::f32::consts::PI * x;
            crate::core::math::sinf(px) / px
        }
    };
    let mut w = [0.0f32; 6];
    for (k, wk) in w.iter_mut().enumerate() {
        let x = k as f32 - 2.0 - t;
        *wk = sinc(x) * sinc(x / 3.0);
    }
    let sum: f32 = w.iter().sum();
    w.map(|v| v / sum)
}

/// The image moved by a fraction of a pixel: pixel (x, y) of the result is the image at
/// (x + dx, y + dy), interpolated by separable Lanczos-3 (not clamped, so the map is linear).
/// Whole-pixel shifts are exact. Lanczos rather than Catmull-Rom because it is nearly
/// band-limited: a half-pixel move of gravel_128 by Catmull-Rom raises its flat fraction from
/// 0.10 to 0.155, by Lanczos-3 to 0.109. Used for the sub-pixel node phases of flow frames.
pub fn shift(image: &Image, dx: f32, dy: f32, edge: Edge) -> Image {
    let dims = (image.width(), image.height(), image.channels());
    let rows = shift_axis(image.data(), dims, dx, true, edge);
    let data = shift_axis(&rows, dims, dy, false, edge);
    Image::from_vec(dims.0, dims.1, dims.2, data).expect("same size as the image")
}

/// One pass of [`shift`]: every value moved by `d` along x (`along_x`) or y. A plain loop over
/// the values: it runs once per exemplar, and unrolled per channel it would take 14 KB of wasm.
fn shift_axis(
    src: &[f32],
    (w, h, c): (usize, usize, usize),
    d: f32,
    along_x: bool,
    edge: Edge,
) -> Vec<f32> {
    let f = d.floor();
    let (taps, start) = (lanczos3(d - f), f as isize - 2);
    let (len, stride) = if along_x { (w, c) } else { (h, w * c) };
    (0..src.len())
        .map(|i| {
            let pos = if along_x { (i / c) % w } else { i / (w * c) };
            let base = i - pos * stride;
            let mut sum = 0.0f32;
            for (k, &t) in taps.iter().enumerate() {
                sum +=
                    t * src[base + edge.resolve(pos as isize + start + k as isize, len) * stride];
            }
            sum
        })
        .collect()
}

/// Resizes to `width` x `height` by bilinear interpolation, pixel centres aligned (the usual
/// convention of `(i + 0.5) * scale - 0.5`). Good for up-sampling a coarse level to any size;
/// for shrinking by more than 2 use [`super::pyramid::downsample`] first to avoid aliasing.
pub fn resize_bilinear(image: &Image, width: usize, height: usize, edge: Edge) -> Result<Image> {
    let mut out = Image::new(width, height, image.channels())?;
    let sx = image.width() as f32 / width as f32;
    let sy = image.height() as f32 / height as f32;
    let c = image.channels();
    let mut px = [0.0f32; 4];
    for y in 0..height {
        let src_y = (y as f32 + 0.5) * sy - 0.5;
        for x in 0..width {
            let src_x = (x as f32 + 0.5) * sx - 0.5;
            sample_bilinear(image, src_x, src_y, edge, &mut px);
            out.pixel_mut(x, y).copy_from_slice(&px[..c]);
        }
    }
    Ok(out)
}

/// Shrinks `image` to `ow` x `oh` (each at most the image's own side) by area averaging: each
/// output pixel is the mean of the source area it covers, so nothing aliases (a photo shrunk to
/// an exemplar keeps its fine texture as texture, not as noise).
pub fn shrink_area(image: &Image, ow: usize, oh: usize) -> Result<Image> {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    if ow == 0 || oh == 0 || ow > w || oh > h {
        return Err(Error::InvalidSize {
            what: "shrunk image",
            width: ow,
            height: oh,
            reason: format!("must be at least 1x1 and at most the {w}x{h} image"),
        });
    }
    let (fx, fy) = (w as f64 / ow as f64, h as f64 / oh as f64);
    // Per output column: the source columns it covers and their weights.
    let spans = |out_len: usize, step: f64, in_len: usize| -> Vec<Vec<(usize, f64)>> {
        (0..out_len)
            .map(|i| {
                let (a, b) = (i as f64 * step, (i as f64 + 1.0) * step);
                (a.floor() as usize..(b.ceil() as usize).min(in_len))
                    .map(|s| (s, (b.min(s as f64 + 1.0) - a.max(s as f64)) / step))
                    .filter(|&(_, wgt)| wgt > 0.0)
                    .collect()
            })
            .collect()
    };
    let (cols, rows) = (spans(ow, fx, w), spans(oh, fy, h));
    let mut out = Image::new(ow, oh, c)?;
    for (y, row) in rows.iter().enumerate() {
        for (x, col) in cols.iter().enumerate() {
            let mut acc = [0.0f64; 4];
            for &(sy, wy) in row {
                for &(sx, wx) in col {
                    for (a, v) in acc.iter_mut().zip(image.pixel(sx, sy)) {
                        *a += wx * wy * f64::from(*v);
                    }
                }
            }
            for (o, a) in out.pixel_mut(x, y).iter_mut().zip(acc) {
                *o = a as f32;
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shrinking_averages_areas_and_refuses_to_enlarge() {
        // 6x4 to 3x2: every output pixel is the mean of a 2x2 block exactly.
        let img = Image::from_fn(6, 4, 1, |x, y, _| (x + 10 * y) as f32).unwrap();
        let out = shrink_area(&img, 3, 2).unwrap();
        for (x, y) in [(0, 0), (2, 1), (1, 1)] {
            let block = [(0, 0), (1, 0), (0, 1), (1, 1)]
                .iter()
                .map(|&(dx, dy)| img.pixel(2 * x + dx, 2 * y + dy)[0])
                .sum::<f32>()
                / 4.0;
            assert!((out.pixel(x, y)[0] - block).abs() < 1e-5);
        }
        // A non-integer ratio keeps the image's mean.
        let odd = shrink_area(&img, 4, 3).unwrap();
        let mean = |i: &Image| i.data().iter().sum::<f32>() / i.data().len() as f32;
        assert!((mean(&odd) - mean(&img)).abs() < 1e-4);
        assert!(shrink_area(&img, 7, 4).is_err());
        assert!(shrink_area(&img, 0, 2).is_err());
    }

    #[test]
    fn shifting_is_exact_on_whole_pixels_and_on_ramps() {
        let img =
            Image::from_fn(9, 8, 2, |x, y, c| ((x * 13 + y * 7 + c * 3) % 11) as f32).unwrap();
        let whole = shift(&img, 2.0, -1.0, Edge::Wrap);
        assert_eq!(whole.pixel(1, 3), img.pixel(3, 2));
        assert_eq!(whole.pixel(8, 0), img.pixel(1, 7));
        // A half-pixel move is symmetric, so a ramp stays exact away from the borders.
        let ramp = Image::from_fn(12, 11, 1, |x, y, _| (2 * x + 3 * y) as f32).unwrap();
        let moved = shift(&ramp, 0.5, -0.5, Edge::Clamp);
        for (x, y) in [(4, 4), (6, 5), (3, 6)] {
            let want = 2.0 * (x as f32 + 0.5) + 3.0 * (y as f32 - 0.5);
            assert!((moved.pixel(x, y)[0] - want).abs() < 1e-4, "({x}, {y})");
        }
        // It is the Lanczos-3 filter: at the midpoint, six taps symmetric about it.
        let half = shift(&img, 0.5, 0.0, Edge::Wrap);
        let taps = lanczos3(0.5);
        assert!((taps[2] - taps[3]).abs() < 1e-6 && (taps[0] - taps[5]).abs() < 1e-6);
        assert!(taps[0] > 0.0 && taps[1] < 0.0);
        let want: f32 = (0..6).map(|k| taps[k] * img.pixel((2 + k) % 9, 2)[1]).sum();
        assert!((half.pixel(4, 2)[1] - want).abs() < 1e-5);
    }

    #[test]
    fn sampling_at_pixel_centres_returns_the_pixel() {
        let img = Image::from_fn(4, 3, 2, |x, y, c| (x + 10 * y + 100 * c) as f32).unwrap();
        let mut out = [0.0; 2];
        sample_bilinear(&img, 2.0, 1.0, Edge::Clamp, &mut out);
        assert_eq!(out, [12.0, 112.0]);
        sample_bilinear(&img, 2.5, 1.5, Edge::Clamp, &mut out);
        assert_eq!(out, [17.5, 117.5]);
        sample_bilinear(&img, -3.0, 9.0, Edge::Clamp, &mut out);
        assert_eq!(out, [20.0, 120.0]);
        sample_bilinear(&img, 3.5, 0.0, Edge::Wrap, &mut out);
        assert_eq!(out, [1.5, 101.5]); // halfway between x = 3 and x = 0 (wrapped)
    }

    #[test]
    fn resize_to_odd_sizes_keeps_constant_images_and_ramps() {
        let flat = Image::from_fn(5, 5, 3, |_, _, c| c as f32 * 0.25).unwrap();
        let big = resize_bilinear(&flat, 37, 23, Edge::Clamp).unwrap();
        assert_eq!((big.width(), big.height(), big.channels()), (37, 23, 3));
        assert!(big.data().chunks(3).all(|p| p == [0.0, 0.25, 0.5]));
        // A horizontal ramp stays monotonic and within the source range.
        let ramp = Image::from_fn(8, 1, 1, |x, _, _| x as f32).unwrap();
        let up = resize_bilinear(&ramp, 29, 3, Edge::Clamp).unwrap();
        let row = &up.data()[..29];
        assert!(row.windows(2).all(|w| w[1] >= w[0]));
        assert_eq!(row[0], 0.0);
        assert_eq!(row[28], 7.0);
    }

    #[test]
    fn bicubic_returns_pixels_at_centres_keeps_ramps_and_stays_in_range() {
        let img = Image::from_fn(6, 5, 2, |x, y, c| (x + 10 * y + 100 * c) as f32).unwrap();
        let mut out = [0.0; 2];
        sample_bicubic(&img, 2.0, 3.0, Edge::Clamp, &mut out);
        assert_eq!(out, [32.0, 132.0]);
        // A linear ramp is reproduced exactly away from the border.
        sample_bicubic(&img, 2.25, 1.5, Edge::Clamp, &mut out);
        assert!((out[0] - 17.25).abs() < 1e-4, "{out:?}");
        // A step edge does not overshoot.
        let step = Image::from_fn(8, 1, 1, |x, _, _| if x < 4 { 0.0 } else { 1.0 }).unwrap();
        let mut v = [0.0];
        for i in 0..70 {
            sample_bicubic(&step, i as f32 * 0.1, 0.0, Edge::Clamp, &mut v);
            assert!((0.0..=1.0).contains(&v[0]));
        }
        // Wrapped sampling reads across the border.
        sample_bicubic(&img, 5.5, 0.0, Edge::Wrap, &mut out);
        assert!((0.0..=5.0).contains(&out[0]));
    }

    #[test]
    fn bicubic_all_channels_at_once_equals_channel_by_channel_to_the_bit() {
        // The one-pass form against the per-channel one, on noise, at random points inside, on
        // and past the borders, both edges, 1 to 4 channels (all an image can have; the library
        // uses the one-pass form for 3).
        let mut rng = crate::core::Rng::new(7);
        for c in 1..=4 {
            let img = crate::core::testing::noise(13, 9, c, c as u64);
            for edge in [Edge::Clamp, Edge::Wrap] {
                for _ in 0..500 {
                    let x = rng.next_f64() as f32 * 17.0 - 2.0;
                    let y = rng.next_f64() as f32 * 13.0 - 2.0;
                    let (mut a, mut b) = ([0.0f32; 4], [0.0f32; 4]);
                    match c {
                        1 => bicubic::<1>(&img, x, y, edge, &mut a),
                        2 => bicubic::<2>(&img, x, y, edge, &mut a),
                        3 => bicubic::<3>(&img, x, y, edge, &mut a),
                        _ => bicubic::<4>(&img, x, y, edge, &mut a),
                    }
                    sample_bicubic_per_channel(&img, x, y, edge, &mut b);
                    assert_eq!(
                        a.map(f32::to_bits),
                        b.map(f32::to_bits),
                        "at ({x}, {y}), {c} channels"
                    );
                }
            }
        }
    }

    #[test]
    fn resize_to_same_size_is_identity() {
        let img = Image::from_fn(6, 4, 1, |x, y, _| (x * y) as f32).unwrap();
        assert_eq!(resize_bilinear(&img, 6, 4, Edge::Clamp).unwrap(), img);
        assert!(resize_bilinear(&img, 0, 4, Edge::Clamp).is_err());
    }
}
