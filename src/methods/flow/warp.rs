//! Moving a frame along a flow: the backward (semi-Lagrangian) warp. Pixel q of the new frame
//! takes the colour at q - f(q) of the old one, so every pixel gets a value (no holes to fill)
//! and a whole-pixel translation is an exact shift. Sampling is bicubic (Catmull-Rom, clamped
//! against ringing): each frame starts from the previous one warped, so the warp's blur
//! compounds over the animation, and bilinear sampling's is about twice as strong.

use super::field::FlowField;
use crate::core::sample::sample_bicubic;
use crate::core::{Edge, Error, Image, Result, parallel};

/// Rows in a piece of the warp that runs on one thread.
const WARP_ROWS: usize = 16;

/// The warped frame and, per pixel, whether its source lay inside the old frame (1) or outside
/// it (0; the colour was clamped from the border). With `Edge::Wrap` every source is inside.
pub struct Warped {
    pub image: Image,
    pub inside: Vec<f32>,
}

/// Warps `frame` by `flow` (same size), reading past the borders by `edge`.
pub fn warp(frame: &Image, flow: &FlowField, edge: Edge) -> Result<Warped> {
    let mut warping = Warping::new(frame, flow)?;
    warping.rows(frame, flow, edge, frame.height());
    Ok(warping.finish())
}

/// A warp made a band of rows at a time (a large frame's warp is split over steps); the rows
/// are the same whatever the bands.
pub struct Warping {
    warped: Warped,
    next_row: usize,
}

impl Warping {
    /// A warp of `frame` by `flow`, no row made yet; the sizes must match.
    pub fn new(frame: &Image, flow: &FlowField) -> Result<Warping> {
        let (w, h, c) = (frame.width(), frame.height(), frame.channels());
        if (flow.width(), flow.height()) != (w, h) {
            return Err(Error::InvalidSize {
                what: "flow field",
                width: flow.width(),
                height: flow.height(),
                reason: format!("must match the frame size {w}x{h}"),
            });
        }
        Ok(Warping {
            warped: Warped {
                image: Image::new(w, h, c)?,
                inside: vec![1.0f32; w * h],
            },
            next_row: 0,
        })
    }

    /// Makes up to `count` more rows (of the same `frame` and `flow` as every call); returns
    /// whether every row is made. Each pixel is its own sample, so the rows run in parallel
    /// pieces with the same result.
    pub fn rows(&mut self, frame: &Image, flow: &FlowField, edge: Edge, count: usize) -> bool {
        let (w, h, c) = (frame.width(), frame.height(), frame.channels());
        let (max_x, max_y) = ((w - 1) as f32, (h - 1) as f32);
        let (start, end) = (self.next_row, (self.next_row + count).min(h));
        let Warped { image, inside } = &mut self.warped;
        let mut rows: Vec<(&mut [f32], &mut [f32])> = image
            .data_mut()
            .chunks_mut(w * c)
            .zip(inside.chunks_mut(w))
            .skip(start)
            .take(end - start)
            .collect();
        parallel::for_each_piece_mut(&mut rows, WARP_ROWS, |piece, rows| {
            let mut px = [0.0f32; 4];
            for (k, (colours, inside)) in rows.iter_mut().enumerate() {
                let y = start + piece * WARP_ROWS + k;
                for x in 0..w {
                    let (vx, vy) = flow.at(x, y);
                    let (sx, sy) = (x as f32 - vx, y as f32 - vy);
                    // Half a pixel of slack: a source on the border pixel's outer half is
                    // still inside.
                    let outside = !(-0.5..=max_x + 0.5).contains(&sx)
                        || !(-0.5..=max_y + 0.5).contains(&sy);
                    if edge == Edge::Clamp && outside {
                        inside[x] = 0.0;
                    }
                    sample_bicubic(frame, sx, sy, edge, &mut px);
                    colours[x * c..(x + 1) * c].copy_from_slice(&px[..c]);
                }
            }
        });
        self.next_row = end;
        self.done()
    }

    /// Whether every row is made.
    #[must_use]
    pub fn done(&self) -> bool {
        self.next_row >= self.warped.image.height()
    }

    /// The warped frame (rows not made yet are black, and inside).
    #[must_use]
    pub fn finish(self) -> Warped {
        self.warped
    }
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
    fn a_warp_made_in_bands_equals_the_whole_warp() {
        let frame = noise(13, 11, 3, 4);
        let flow = FlowField::from_fn(13, 11, |x, y| (0.3 * x - 2.0, 1.7 - 0.2 * y)).unwrap();
        let whole = warp(&frame, &flow, Edge::Clamp).unwrap();
        let mut bands = Warping::new(&frame, &flow).unwrap();
        let mut calls = 0;
        while !bands.rows(&frame, &flow, Edge::Clamp, 4) {
            calls += 1;
        }
        assert_eq!(calls, 2, "rows 0-3, 4-7, then 8-10");
        let banded = bands.finish();
        assert_eq!(banded.image, whole.image);
        assert_eq!(banded.inside, whole.inside);
        assert!(whole.inside.contains(&0.0) && whole.inside.contains(&1.0));
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
