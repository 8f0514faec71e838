//! Image gradients by central differences (one-sided at the borders unless wrapping).

use super::image::Image;
use super::sample::Edge;

/// Horizontal and vertical derivatives of every channel: `(dx, dy)`, each the size of the input.
/// Central differences `(I(x+1) - I(x-1)) / 2`; at a clamped border the difference is one-sided.
#[must_use]
pub fn gradients(image: &Image, edge: Edge) -> (Image, Image) {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let mut dx = image.clone();
    let mut dy = image.clone();
    let src = image.data();
    for y in 0..h {
        for x in 0..w {
            let (xl, xr) = (
                edge.resolve(x as isize - 1, w),
                edge.resolve(x as isize + 1, w),
            );
            let (yu, yd) = (
                edge.resolve(y as isize - 1, h),
                edge.resolve(y as isize + 1, h),
            );
            let span_x = if edge == Edge::Wrap {
                2.0
            } else {
                (xr - xl).max(1) as f32
            };
            let span_y = if edge == Edge::Wrap {
                2.0
            } else {
                (yd - yu).max(1) as f32
            };
            let o = (y * w + x) * c;
            for ch in 0..c {
                dx.data_mut()[o + ch] =
                    (src[(y * w + xr) * c + ch] - src[(y * w + xl) * c + ch]) / span_x;
                dy.data_mut()[o + ch] =
                    (src[(yd * w + x) * c + ch] - src[(yu * w + x) * c + ch]) / span_y;
            }
        }
    }
    (dx, dy)
}

/// Gradient magnitude summed over channels, one value per pixel.
#[must_use]
pub fn gradient_magnitude(image: &Image, edge: Edge) -> Vec<f32> {
    let (dx, dy) = gradients(image, edge);
    let c = image.channels();
    dx.data()
        .chunks_exact(c)
        .zip(dy.data().chunks_exact(c))
        .map(|(gx, gy)| gx.iter().zip(gy).map(|(a, b)| (a * a + b * b).sqrt()).sum())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradient_of_a_linear_ramp_is_its_slope_everywhere() {
        let img = Image::from_fn(6, 5, 1, |x, y, _| 2.0 * x as f32 - 3.0 * y as f32).unwrap();
        let (dx, dy) = gradients(&img, Edge::Clamp);
        assert!(
            dx.data().iter().all(|&v| (v - 2.0).abs() < 1e-6),
            "{:?}",
            dx.data()
        );
        assert!(dy.data().iter().all(|&v| (v + 3.0).abs() < 1e-6));
    }

    #[test]
    fn wrapped_gradient_of_a_periodic_image_sums_to_zero() {
        let img = Image::from_fn(8, 8, 2, |x, y, c| ((x * 3 + y + c) % 8) as f32).unwrap();
        let (dx, dy) = gradients(&img, Edge::Wrap);
        assert!(dx.data().iter().sum::<f32>().abs() < 1e-4);
        assert!(dy.data().iter().sum::<f32>().abs() < 1e-4);
        let mag = gradient_magnitude(&img, Edge::Wrap);
        assert_eq!(mag.len(), 64);
        assert!(mag.iter().all(|m| m.is_finite() && *m >= 0.0));
    }
}
