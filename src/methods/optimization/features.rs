//! What the energy compares: a pixel's colour, plus its forward differences scaled by sqrt(mu) when
//! the gradient energy is on, so that one weighted distance gives
//! ||x_p - z_p||^2 + mu ||Dx_p - Dz_p||^2.

use crate::core::{Edge, Image};
use crate::solvers::nn::FeatureMap;

/// The feature map of an image: `channels` values per pixel, or `3 * channels` (colour, then
/// sqrt(mu) d/dx, then sqrt(mu) d/dy, forward differences) when `mu > 0`. With `Edge::Clamp` the
/// difference past the last column or row is zero.
#[must_use]
pub fn feature_map(image: &Image, mu: f32, edge: Edge) -> FeatureMap {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    if mu <= 0.0 {
        return FeatureMap {
            width: w,
            height: h,
            dims: c,
            data: image.data().to_vec(),
        };
    }
    let scale = mu.sqrt();
    let dims = 3 * c;
    let mut data = Vec::with_capacity(w * h * dims);
    for y in 0..h {
        let down = edge.resolve(y as isize + 1, h);
        for x in 0..w {
            let right = edge.resolve(x as isize + 1, w);
            let (here, r, d) = (
                image.pixel(x, y),
                image.pixel(right, y),
                image.pixel(x, down),
            );
            data.extend_from_slice(here);
            data.extend(r.iter().zip(here).map(|(a, b)| scale * (a - b)));
            data.extend(d.iter().zip(here).map(|(a, b)| scale * (a - b)));
        }
    }
    FeatureMap {
        width: w,
        height: h,
        dims,
        data,
    }
}

/// `map` with the channels of `guide` (the map's size) appended to every pixel, scaled by
/// `scale`: the distance of two such vectors gains `scale^2 ||g - g'||^2`, the guide term of
/// guided synthesis (Hertzmann et al. 2001's image analogies, Embark's guide maps).
#[must_use]
pub fn append_guide(map: FeatureMap, guide: &Image, scale: f32) -> FeatureMap {
    let g = guide.channels();
    let dims = map.dims + g;
    let mut data = Vec::with_capacity(map.width * map.height * dims);
    for (pixel, extra) in map.data.chunks_exact(map.dims).zip(guide.data().chunks_exact(g)) {
        data.extend_from_slice(pixel);
        data.extend(extra.iter().map(|v| v * scale));
    }
    FeatureMap {
        width: map.width,
        height: map.height,
        dims,
        data,
    }
}

/// Copies the `size` x `size` neighbourhood with top-left (x0, y0) into `out`, row by row,
/// wrapping around the borders when `wrap` (the caller keeps it inside otherwise).
pub fn gather(map: &FeatureMap, x0: usize, y0: usize, size: usize, wrap: bool, out: &mut [f32]) {
    let row_len = size * map.dims;
    for dy in 0..size {
        let y = if wrap {
            (y0 + dy) % map.height
        } else {
            y0 + dy
        };
        let dst = &mut out[dy * row_len..(dy + 1) * row_len];
        if !wrap || x0 + size <= map.width {
            dst.copy_from_slice(map.row(x0, y, size));
        } else {
            let first = map.width - x0;
            dst[..first * map.dims].copy_from_slice(map.row(x0, y, first));
            dst[first * map.dims..].copy_from_slice(map.row(0, y, size - first));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradient_features_hold_scaled_forward_differences() {
        let img = Image::from_fn(3, 2, 1, |x, y, _| (x * x + 10 * y) as f32).unwrap();
        let map = feature_map(&img, 4.0, Edge::Clamp);
        assert_eq!(map.dims, 3);
        assert_eq!(&map.data[0..3], &[0.0, 2.0, 20.0]); // (0,0): value, 2*(1-0), 2*(10-0)
        assert_eq!(&map.data[6..9], &[4.0, 0.0, 20.0]); // (2,0): last column, no right neighbour
        assert_eq!(feature_map(&img, 0.0, Edge::Clamp).data, img.data());
    }

    #[test]
    fn gather_wraps_rows_and_columns() {
        let img = Image::from_fn(4, 3, 1, |x, y, _| (10 * y + x) as f32).unwrap();
        let map = feature_map(&img, 0.0, Edge::Wrap);
        let mut out = [0.0; 4];
        gather(&map, 3, 2, 2, true, &mut out);
        assert_eq!(out, [23.0, 20.0, 3.0, 0.0]);
        gather(&map, 1, 0, 2, false, &mut out);
        assert_eq!(out, [1.0, 2.0, 11.0, 12.0]);
    }
}
