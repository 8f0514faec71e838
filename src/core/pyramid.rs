//! Gaussian pyramids: blur with the binomial kernel [1 4 6 4 1] / 16 (Burt & Adelson), then keep
//! every other pixel. Used for coarse-to-fine synthesis and for multi-resolution splining.

use super::error::Result;
use super::image::Image;
use super::sample::Edge;

const KERNEL: [f32; 5] = [1.0 / 16.0, 4.0 / 16.0, 6.0 / 16.0, 4.0 / 16.0, 1.0 / 16.0];

/// Size of the next coarser level: half, rounded up, never zero.
#[must_use]
pub fn half_size(len: usize) -> usize {
    len.div_ceil(2).max(1)
}

/// Blurs with the 5-tap binomial kernel, separably.
pub fn blur(image: &Image, edge: Edge) -> Image {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let mut tmp = vec![0.0f32; image.data().len()];
    blur_lines(image.data(), &mut tmp, (w, c), (h, w * c), c, edge);
    let mut out = vec![0.0f32; tmp.len()];
    blur_lines(&tmp, &mut out, (h, w * c), (w, c), c, edge);
    Image::from_vec(w, h, c, out).expect("same size as the input")
}

/// One pass of [`blur`] along `lines` lines of `len` pixels, `(len, step)` along a line and
/// `(lines, line_step)` across them (in values), reading past a line's ends by `edge`. One
/// function serves both axes: pyramids are built once per level, so the code's size matters
/// more here than a specialised loop per axis.
#[inline(never)]
fn blur_lines(
    src: &[f32],
    out: &mut [f32],
    (len, step): (usize, usize),
    (lines, line_step): (usize, usize),
    c: usize,
    edge: Edge,
) {
    for line in 0..lines {
        let base = line * line_step;
        for i in 0..len {
            let o = base + i * step;
            for (t, &k) in KERNEL.iter().enumerate() {
                let s = base + edge.resolve(i as isize + t as isize - 2, len) * step;
                for ch in 0..c {
                    out[o + ch] += k * src[s + ch];
                }
            }
        }
    }
}

/// One level down: blur, then keep the even pixels. A `w` x `h` image becomes
/// `ceil(w/2)` x `ceil(h/2)`.
pub fn downsample(image: &Image, edge: Edge) -> Image {
    let blurred = blur(image, edge);
    let (w, h, c) = (
        half_size(image.width()),
        half_size(image.height()),
        image.channels(),
    );
    let mut data = Vec::with_capacity(w * h * c);
    for y in 0..h {
        for x in 0..w {
            data.extend_from_slice(blurred.pixel(2 * x, 2 * y));
        }
    }
    Image::from_vec(w, h, c, data).expect("size is at least 1x1")
}

/// The Gaussian pyramid, finest first: `levels` images (at least one, the input itself).
pub fn gaussian_pyramid(image: &Image, levels: usize, edge: Edge) -> Result<Vec<Image>> {
    let mut pyramid = vec![image.clone()];
    for _ in 1..levels.max(1) {
        let next = downsample(pyramid.last().expect("never empty"), edge);
        pyramid.push(next);
    }
    Ok(pyramid)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pyramid_sizes_halve_rounding_up() {
        let img = Image::new(37, 20, 3).unwrap();
        let sizes: Vec<_> = gaussian_pyramid(&img, 7, Edge::Clamp)
            .unwrap()
            .iter()
            .map(|l| (l.width(), l.height()))
            .collect();
        assert_eq!(
            sizes,
            [(37, 20), (19, 10), (10, 5), (5, 3), (3, 2), (2, 1), (1, 1)]
        );
    }

    #[test]
    fn blur_keeps_constants_and_the_mean_of_periodic_images() {
        let flat = Image::from_fn(9, 4, 2, |_, _, c| 0.3 + c as f32 * 0.1).unwrap();
        let b = blur(&flat, Edge::Clamp);
        assert!(
            b.data()
                .iter()
                .zip(flat.data())
                .all(|(a, e)| (a - e).abs() < 1e-6)
        );
        let noise = Image::from_fn(8, 8, 1, |x, y, _| ((x * 7 + y * 3) % 5) as f32).unwrap();
        let mean = |i: &Image| i.data().iter().sum::<f32>() / i.data().len() as f32;
        let wrapped = blur(&noise, Edge::Wrap);
        assert!((mean(&wrapped) - mean(&noise)).abs() < 1e-5);
    }

    #[test]
    fn blur_spreads_an_impulse_by_the_binomial_kernel() {
        let mut img = Image::new(5, 5, 1).unwrap();
        img.pixel_mut(2, 2)[0] = 256.0;
        let b = blur(&img, Edge::Clamp);
        assert_eq!(b.pixel(2, 2)[0], 36.0);
        assert_eq!(b.pixel(0, 2)[0], 6.0);
        assert_eq!(b.pixel(1, 1)[0], 16.0);
    }

    #[test]
    fn downsample_of_checkerboard_is_grey() {
        let img = Image::from_fn(16, 16, 1, |x, y, _| ((x + y) % 2) as f32).unwrap();
        let d = downsample(&img, Edge::Wrap);
        assert!(
            d.data().iter().all(|v| (v - 0.5).abs() < 0.07),
            "{:?}",
            d.data()
        );
    }
}
