//! Teaching views of a texture-optimisation session: where in the exemplar each output pixel
//! comes from, as a colour-coded offset map.

use super::schedule::nearest_corner;
use super::session::Session;
use crate::core::{Image, Result};

/// An RGB image of the output size in which each pixel's colour encodes the exemplar position its
/// neighbourhood was matched to: red grows with exemplar x, green with exemplar y, blue is fixed
/// at one half, so coherent copied regions show as smooth gradients and seams between them as
/// colour jumps. Each pixel takes the match of the grid neighbourhood whose centre is
/// nearest.
pub fn offset_map(session: &Session) -> Result<Image> {
    let opts = session.options();
    let (w, h) = (opts.output_width, opts.output_height);
    let mut map = Image::new(w, h, 3)?;
    let Some((cols, rows, matches)) = session.matches() else {
        return Ok(map);
    };
    let level = session.current_level();
    let half = level.size as f64 / 2.0;
    let column_of: Vec<(usize, f64)> = (0..w)
        .map(|x| {
            nearest(
                cols,
                (x as f64 + 0.5) * level.output_width as f64 / w as f64 - half,
            )
        })
        .collect();
    let (ew, eh) = (level.exemplar_width as f64, level.exemplar_height as f64);
    for y in 0..h {
        let (j, ry) = nearest(
            rows,
            (y as f64 + 0.5) * level.output_height as f64 / h as f64 - half,
        );
        for x in 0..w {
            let (i, rx) = column_of[x];
            let z = matches[j * cols.len() + i];
            let u = ((f64::from(z.x) + rx + half) / ew).clamp(0.0, 1.0) as f32;
            let v = ((f64::from(z.y) + ry + half) / eh).clamp(0.0, 1.0) as f32;
            map.pixel_mut(x, y).copy_from_slice(&[u, v, 0.5]);
        }
    }
    Ok(map)
}
/// The corner nearest to `target` and the offset of `target` from it.
fn nearest(corners: &[usize], target: f64) -> (usize, f64) {
    let i = nearest_corner(corners, target);
    (i, target - corners[i] as f64)
}
