//! Several exemplars in one texture optimisation: stacked one below another into one image, the
//! searches run over it unchanged, and every neighbourhood that reaches past an exemplar (into
//! the padding right of a narrower one, or into the gap between two) is excluded (see
//! `super::exclusion`). A match so lies inside one exemplar, and the band it lies in says which.

use super::exclusion::halve;
use crate::core::pyramid::half_size;
use crate::core::{Image, Result};

/// Rows of padding between two exemplars: the pyramid's blur reads two pixels across a border
/// at every octave, so the gap keeps the exemplars apart down to the coarsest levels.
pub const GAP: usize = 8;

/// The exemplars stacked.
#[derive(Debug, Clone)]
pub struct Stack {
    /// The exemplars one below another, left-aligned, `GAP` rows apart (zero in the padding).
    pub image: Image,
    /// True on padding pixels.
    pub padding: Vec<bool>,
    /// Per exemplar: its first row in the stack, and its size.
    pub bands: Vec<(usize, usize, usize)>,
}

/// Stacks `exemplars` (at least one, with the same channel count).
pub fn stack(exemplars: &[Image]) -> Result<Stack> {
    let width = exemplars.iter().map(Image::width).max().unwrap_or(1);
    let height = exemplars.iter().map(Image::height).sum::<usize>()
        + GAP * exemplars.len().saturating_sub(1);
    crate::core::error::check_size("stacked exemplars", width, height)?;
    let c = exemplars[0].channels();
    let mut image = Image::new(width, height, c)?;
    let mut padding = vec![true; width * height];
    let mut bands = Vec::with_capacity(exemplars.len());
    let mut y0 = 0;
    for e in exemplars {
        for y in 0..e.height() {
            for x in 0..e.width() {
                image.pixel_mut(x, y0 + y).copy_from_slice(e.pixel(x, y));
                padding[(y0 + y) * width + x] = false;
            }
        }
        bands.push((y0, e.width(), e.height()));
        y0 += e.height() + GAP;
    }
    Ok(Stack {
        image,
        padding,
        bands,
    })
}

impl Stack {
    /// Which exemplar the stack's row `y` (at full resolution) lies in: the band holding it, or
    /// the nearest one above for a gap row.
    #[must_use]
    pub fn exemplar_at(&self, y: usize) -> usize {
        self.bands
            .iter()
            .rposition(|&(y0, _, _)| y0 <= y)
            .unwrap_or(0)
    }
}

/// The exemplars of a session over several.
pub struct Several {
    /// The exemplars stacked.
    pub stack: Stack,
    /// Each exemplar's Gaussian pyramid, index = octave.
    pub pyramids: Vec<Vec<Image>>,
}

impl Several {
    /// Every exemplar at `octave`.
    pub fn at_octave(&self, octave: usize) -> Vec<Image> {
        self.pyramids.iter().map(|p| p[octave].clone()).collect()
    }

    /// The stack's pixels at `octave` that no padding reaches through the pyramid's blur.
    pub fn kept_at(&self, octave: usize) -> Vec<bool> {
        let (mut w, mut h) = (self.stack.image.width(), self.stack.image.height());
        let mut padding = self.stack.padding.clone();
        for _ in 0..octave {
            padding = halve(&padding, w, h);
            (w, h) = (half_size(w), half_size(h));
        }
        padding.iter().map(|&p| !p).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stacking_keeps_every_exemplar_and_pads_the_rest() {
        let a = Image::from_fn(4, 3, 1, |x, y, _| (1 + x + 4 * y) as f32).unwrap();
        let b = Image::from_fn(2, 2, 1, |_, _, _| 50.0).unwrap();
        let s = stack(&[a.clone(), b]).unwrap();
        assert_eq!((s.image.width(), s.image.height()), (4, 3 + GAP + 2));
        assert_eq!(s.image.crop(0, 0, 4, 3).unwrap(), a);
        assert_eq!(s.image.pixel(1, 3 + GAP + 1), &[50.0]);
        assert!(s.padding[(3 + GAP) * 4 + 2], "right of the narrower exemplar");
        assert!(s.padding[3 * 4], "the gap");
        assert_eq!(s.padding.iter().filter(|&&p| !p).count(), 12 + 4);
        assert_eq!((s.exemplar_at(2), s.exemplar_at(3 + GAP), s.exemplar_at(4)), (0, 1, 0));
    }
}
