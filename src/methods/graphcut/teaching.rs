//! Teaching views of a graph-cut synthesis, as RGBA8 pictures of the output size: the seams as an
//! overlay, the per-pixel seam cost as a heat map, and the label map (each patch a colour).

use super::canvas::{Canvas, UNCOVERED};

/// Seam pixels opaque red, everything else transparent: drawn over the image.
#[must_use]
pub fn seam_overlay(canvas: &Canvas) -> Vec<u8> {
    canvas
        .seam_map()
        .iter()
        .flat_map(|&s| {
            if s == 1 {
                [255, 40, 40, 255]
            } else {
                [0, 0, 0, 0]
            }
        })
        .collect()
}

/// Seam cost per pixel (the error map that drives placement), black (none) through red and
/// yellow to white (the largest in the output).
#[must_use]
pub fn seam_heat_map(canvas: &Canvas) -> Vec<u8> {
    let error = canvas.seam_error();
    let max = error.iter().copied().fold(0.0f32, f32::max).max(1e-6);
    error
        .iter()
        .flat_map(|&e| {
            // sqrt stretches the many small costs so that they remain visible.
            let t = (e / max).sqrt();
            let ramp = |v: f32| (v.clamp(0.0, 1.0) * 255.0) as u8;
            [ramp(t * 3.0), ramp(t * 3.0 - 1.0), ramp(t * 3.0 - 2.0), 255]
        })
        .collect()
}

/// Each patch in its own colour (golden-ratio hues, so neighbours differ); uncovered pixels
/// transparent.
#[must_use]
pub fn label_map(canvas: &Canvas) -> Vec<u8> {
    canvas
        .label
        .iter()
        .flat_map(|&l| {
            if l == UNCOVERED {
                return [0, 0, 0, 0];
            }
            let [r, g, b] = label_colour(l);
            [r, g, b, 255]
        })
        .collect()
}

/// The colour of patch `label` in label maps (golden-ratio hues, so neighbours differ).
#[must_use]
pub fn label_colour(label: u32) -> [u8; 3] {
    hsv((label as f32 * 0.618_034).fract(), 0.65, 0.95)
}

fn hsv(h: f32, s: f32, v: f32) -> [u8; 3] {
    let f = |n: f32| {
        let k = (n + h * 6.0) % 6.0;
        let value = v - v * s * (k.min(4.0 - k).clamp(0.0, 1.0));
        (value * 255.0).round() as u8
    };
    [f(5.0), f(3.0), f(1.0)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::graphcut::canvas::Patch;

    #[test]
    fn views_follow_the_labels() {
        let mut canvas = Canvas::new(4, 2, 1, false).unwrap();
        canvas.patches = vec![Patch::new(0, 0, 0), Patch::new(0, 2, 0)];
        canvas.label = vec![0, 0, 1, 1, 0, 0, 1, UNCOVERED];
        canvas.h_seam[1] = 2.0;
        canvas.h_seam[5] = 1.0;
        let overlay = seam_overlay(&canvas);
        assert_eq!(&overlay[4..8], &[255, 40, 40, 255]); // pixel 1 borders patch 1
        assert_eq!(&overlay[0..4], &[0, 0, 0, 0]);
        let heat = seam_heat_map(&canvas);
        assert_eq!(&heat[4..8], &[255, 255, 255, 255]); // the largest cost is white
        assert_eq!(&heat[0..4], &[0, 0, 0, 255]);
        let labels = label_map(&canvas);
        assert_ne!(&labels[0..4], &labels[8..12]);
        assert_eq!(labels[31], 0);
    }
}
