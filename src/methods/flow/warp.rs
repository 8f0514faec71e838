//! Moving a frame along a flow: the backward (semi-Lagrangian) warp. Pixel q of the new frame
//! takes the colour at q - f(q) of the old one, so every pixel gets a value (no holes to fill)
//! and a whole-pixel translation is an exact shift. Sampling is bicubic (Catmull-Rom, clamped
//! against ringing): each frame starts from the previous one warped, so the warp's blur
//! compounds over the animation, and bilinear sampling's is about twice as strong.

use super::field::FlowField;
use crate::core::sample::sample_bicubic;
use crate::core::{Edge, Error, Image, Result};

/// The warped frame and, per pixel, whether its source lay inside the old frame (1) or outside
/// it (0; the colour was clamped from the border). With `Edge::Wrap` every source is inside.
pub struct Warped {
    pub image: Image,
    pub inside: Vec<f32>,
}

/// Warps `frame` by `flow` (same size), reading past the borders by `edge`.
pub fn warp(frame: &Image, flow: &FlowField, edge: Edge) -> Result<Warped> {
    let (w, h, c) = (frame.width(), frame.height(), frame.channels());
    if (flow.width(), flow.height()) != (w, h) {
        return Err(Error::InvalidSize {
            what: "flow field",
            width: flow.width(),
            height: flow.height(),
            reason: format!("must match the frame size {w}x{h}"),
        });
    }
    let mut image = Image::new(w, h, c)?;
    let mut inside = vec![1.0f32; w * h];
    let (max_x, max_y) = ((w - 1) as f32, (h - 1) as f32);
    let mut px = [0.0f32; 4];
    for y in 0..h {
        for x in 0..w {
            let (vx, vy) = flow.at(x, y);
            let (sx, sy) = (x as f32 - vx, y as f32 - vy);
            // Half a pixel of slack: a source on the border pixel's outer half is still inside.
            let outside =
                !(-0.5..=max_x + 0.5).contains(&sx) || !(-0.5..=max_y + 0.5).contains(&sy);
            if edge == Edge::Clamp && outside {
                inside[y * w + x] = 0.0;
            }
            sample_bicubic(frame, sx, sy, edge, &mut px);
            image.pixel_mut(x, y).copy_from_slice(&px[..c]);
        }
    }
    Ok(Warped { image, inside })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::noise;

    #[test]
    fn a_zero_flow_is_the_identity() {
        let frame = noise(9, 7, 3, 1);
        let out = warp(&frame, &FlowField::zero(9, 7).unwrap(), Edge::Clamp).unwrap();
        assert_eq!(out.image, frame);
        assert!(out.inside.iter().all(|&m| m == 1.0));
    }

    #[test]
    fn a_whole_pixel_translation_is_an_exact_shift() {
        let frame = noise(10, 8, 2, 2);
        let flow = FlowField::from_fn(10, 8, |_, _| (3.0, -2.0)).unwrap();
        let out = warp(&frame, &flow, Edge::Clamp).unwrap();
        for y in 0..6 {
            for x in 3..10 {
                assert_eq!(out.image.pixel(x, y), frame.pixel(x - 3, y + 2));
                assert_eq!(out.inside[y * 10 + x], 1.0);
            }
        }
        // Sources left of the frame or below it are outside.
        assert_eq!(out.inside[0], 0.0);
        assert_eq!(out.inside[7 * 10 + 5], 0.0);
        // Wrapped, the shift is exact everywhere.
        let wrapped = warp(&frame, &flow, Edge::Wrap).unwrap();
        assert_eq!(wrapped.image.pixel(0, 7), frame.pixel(7, 1));
        assert!(wrapped.inside.iter().all(|&m| m == 1.0));
    }

    #[test]
    fn the_flow_must_match_the_frame() {
        let frame = noise(9, 7, 1, 3);
        let msg = warp(&frame, &FlowField::zero(7, 9).unwrap(), Edge::Clamp)
            .err()
            .unwrap()
            .to_string();
        assert!(msg.contains("9x7"), "{msg}");
    }
}
