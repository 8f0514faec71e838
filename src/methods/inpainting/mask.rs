//! The hole of an inpainting: which pixels to fill, checked, and the part of the image the
//! synthesis works on. Uncrop is a hole too: the new border of an extended image.

use crate::core::{Error, Image, Result};

/// The pixels to fill of a `width` x `height` image.
#[derive(Debug, Clone, PartialEq)]
pub struct Hole {
    /// The image's width in pixels.
    pub width: usize,
    /// The image's height in pixels.
    pub height: usize,
    /// True where the pixel is to be filled.
    pub mask: Vec<bool>,
    /// The number of pixels to fill.
    pub count: usize,
}

/// A rectangle of an image: top-left corner and size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    /// Left column.
    pub x: usize,
    /// Top row.
    pub y: usize,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
}

impl Hole {
    /// The hole of a mask with one byte per pixel, non-zero meaning fill. Refuses a mask of the
    /// wrong length, one that marks nothing and one that marks everything, each by name.
    pub fn new(width: usize, height: usize, mask: &[u8]) -> Result<Hole> {
        if mask.len() != width * height {
            return Err(Error::LengthMismatch {
                what: "mask (one byte per image pixel)",
                expected: width * height,
                actual: mask.len(),
            });
        }
        let mask: Vec<bool> = mask.iter().map(|&m| m != 0).collect();
        let count = mask.iter().filter(|&&m| m).count();
        if count == 0 {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: "is empty: no pixel is marked to fill (non-zero bytes mark the hole)"
                    .into(),
            });
        }
        if count == mask.len() {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: "is full: every pixel is marked to fill, so nothing is known to fill \
                         from (a whole new texture is a synthesis)"
                    .into(),
            });
        }
        Ok(Hole {
            width,
            height,
            mask,
            count,
        })
    }

    /// The smallest rectangle holding every hole pixel.
    #[must_use]
    pub fn bounds(&self) -> Rect {
        let w = self.width;
        let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
        for (i, _) in self.mask.iter().enumerate().filter(|(_, m)| **m) {
            let (x, y) = (i % w, i / w);
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
        }
        Rect {
            x: x0,
            y: y0,
            width: x1 + 1 - x0,
            height: y1 + 1 - y0,
        }
    }

    /// The mask within `r`, row by row.
    #[must_use]
    pub fn within(&self, r: Rect) -> Vec<bool> {
        (r.y..r.y + r.height)
            .flat_map(|y| self.mask[y * self.width + r.x..y * self.width + r.x + r.width].iter())
            .copied()
            .collect()
    }
}

impl Rect {
    /// The rectangle grown by `margin` on every side, kept inside a `width` x `height` image.
    #[must_use]
    pub fn grown(self, margin: usize, width: usize, height: usize) -> Rect {
        let (x, y) = (self.x.saturating_sub(margin), self.y.saturating_sub(margin));
        let x1 = (self.x + self.width + margin).min(width);
        let y1 = (self.y + self.height + margin).min(height);
        Rect {
            x,
            y,
            width: x1 - x,
            height: y1 - y,
        }
    }
}

/// The widths of a border to add, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Border {
    /// Rows added above.
    pub top: usize,
    /// Columns added on the right.
    pub right: usize,
    /// Rows added below.
    pub bottom: usize,
    /// Columns added on the left.
    pub left: usize,
}

impl Border {
    /// The same width on all four sides.
    #[must_use]
    pub const fn all(width: usize) -> Border {
        Border {
            top: width,
            right: width,
            bottom: width,
            left: width,
        }
    }
}

/// Uncrop's input: `image` placed inside a border of `border`'s widths (the border pixels are
/// zero), and the mask that marks the border as the hole. Refuses a border of width zero all
/// round, and an extended image beyond the size limits.
pub fn extend(image: &Image, border: Border) -> Result<(Image, Vec<u8>)> {
    if border == Border::default() {
        return Err(Error::InvalidParameter {
            name: "border",
            reason: "adds no pixel: give a width above 0 on at least one side".into(),
        });
    }
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let (ew, eh) = (
        w.saturating_add(border.left).saturating_add(border.right),
        h.saturating_add(border.top).saturating_add(border.bottom),
    );
    crate::core::error::check_size("extended image", ew, eh)?;
    let mut out = Image::new(ew, eh, c)?;
    let mut mask = vec![1u8; ew * eh];
    for y in 0..h {
        for x in 0..w {
            let (ox, oy) = (x + border.left, y + border.top);
            out.pixel_mut(ox, oy).copy_from_slice(image.pixel(x, y));
            mask[oy * ew + ox] = 0;
        }
    }
    Ok((out, mask))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_masks_are_refused_by_name() {
        let msg = |r: Result<Hole>| r.unwrap_err().to_string();
        assert!(msg(Hole::new(4, 4, &[0; 15])).contains("mask"));
        assert!(msg(Hole::new(4, 4, &[0; 16])).contains("empty"));
        assert!(msg(Hole::new(4, 4, &[9; 16])).contains("full"));
        let mut m = [0u8; 16];
        m[5] = 255;
        m[10] = 1;
        let hole = Hole::new(4, 4, &m).unwrap();
        assert_eq!(hole.count, 2);
        let b = hole.bounds();
        assert_eq!((b.x, b.y, b.width, b.height), (1, 1, 2, 2));
        assert_eq!(
            b.grown(1, 4, 4),
            Rect {
                x: 0,
                y: 0,
                width: 4,
                height: 4
            }
        );
    }

    #[test]
    fn uncrop_marks_the_border_and_keeps_the_image() {
        let image = Image::from_fn(3, 2, 1, |x, y, _| (1 + x + 3 * y) as f32).unwrap();
        let border = Border {
            top: 1,
            right: 2,
            bottom: 0,
            left: 1,
        };
        let (out, mask) = extend(&image, border).unwrap();
        assert_eq!((out.width(), out.height()), (6, 3));
        assert_eq!(mask.iter().filter(|&&m| m == 0).count(), 6);
        assert_eq!(out.pixel(1, 1), &[1.0]);
        assert_eq!(out.pixel(3, 2), &[6.0]);
        assert_eq!(mask[2 * 6 + 3], 0);
        assert_eq!(mask[6 + 4], 1);
        assert!(extend(&image, Border::default()).unwrap_err().to_string().contains("border"));
    }
}
