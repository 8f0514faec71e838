//! Material sets: a synthesis's source-coordinate map (which exemplar pixel each output pixel
//! shows) applied to other images of the exemplar's size, so that an albedo, its normal map and
//! its roughness map come out aligned.
//!
//! A transfer re-indexes: every output pixel copies one pixel of the other image, and nothing
//! is averaged. A normal map's vectors so stay unit length (no renormalisation is needed, and
//! none is done), and a height or roughness map keeps its values. What the map is depends on the
//! method: graph cut's labels and offsets give it exactly; texture optimisation's output averages
//! overlapping neighbourhoods, and its map takes each pixel from the neighbourhood whose centre
//! is nearest (see `optimization::Session::source_map`).

use crate::core::{Error, Image, Result};

/// No source pixel (an uncovered graph-cut pixel).
const NONE: u32 = u32::MAX;

/// For every output pixel, the exemplar pixel it shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SourceMap {
    width: usize,
    height: usize,
    source_width: usize,
    source_height: usize,
    /// `y * source_width + x` of the source pixel, per output pixel; [`NONE`] where none.
    index: Vec<u32>,
}

impl SourceMap {
    /// A map of a `width` x `height` output over a `source` (width, height) exemplar, from the
    /// source coordinates of each output pixel in scan order.
    pub fn new(
        (width, height): (usize, usize),
        (source_width, source_height): (usize, usize),
        coords: impl IntoIterator<Item = Option<(usize, usize)>>,
    ) -> Result<SourceMap> {
        let index: Vec<u32> = coords
            .into_iter()
            .map(|c| match c {
                Some((x, y)) if x < source_width && y < source_height => {
                    (y * source_width + x) as u32
                }
                _ => NONE,
            })
            .collect();
        if index.len() != width * height {
            return Err(Error::LengthMismatch {
                what: "source map",
                expected: width * height,
                actual: index.len(),
            });
        }
        Ok(SourceMap {
            width,
            height,
            source_width,
            source_height,
            index,
        })
    }

    /// The output's size.
    #[must_use]
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The size an image must have to be transferred: the exemplar's.
    #[must_use]
    pub fn source_size(&self) -> (usize, usize) {
        (self.source_width, self.source_height)
    }

    /// The source pixel output pixel `i` shows, if any.
    #[must_use]
    pub fn source_of(&self, i: usize) -> Option<(usize, usize)> {
        let k = self.index[i];
        (k != NONE).then(|| (k as usize % self.source_width, k as usize / self.source_width))
    }

    /// `image` (the exemplar's size, any channels) re-indexed by the map: output pixel i is
    /// the image's pixel at `source_of(i)`, zero where there is none.
    pub fn transfer(&self, image: &Image) -> Result<Image> {
        let (sw, sh) = (self.source_width, self.source_height);
        if (image.width(), image.height()) != (sw, sh) {
            return Err(Error::InvalidSize {
                what: "transferred image",
                width: image.width(),
                height: image.height(),
                reason: format!("must have the exemplar's size, {sw}x{sh}"),
            });
        }
        let c = image.channels();
        let mut out = Image::new(self.width, self.height, c)?;
        let src = image.data();
        for (px, &k) in out.data_mut().chunks_exact_mut(c).zip(&self.index) {
            if k != NONE {
                let k = k as usize * c;
                px.copy_from_slice(&src[k..k + c]);
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_transfer_is_a_re_indexing() {
        let map = SourceMap::new(
            (3, 1),
            (2, 2),
            [Some((1, 0)), None, Some((0, 1))],
        )
        .unwrap();
        let image = Image::from_fn(2, 2, 2, |x, y, k| (10 * y + x + 100 * k) as f32).unwrap();
        let out = map.transfer(&image).unwrap();
        assert_eq!(out.data(), &[1.0, 101.0, 0.0, 0.0, 10.0, 110.0]);
        let wrong = Image::new(3, 2, 1).unwrap();
        assert!(map.transfer(&wrong).unwrap_err().to_string().contains("exemplar's size, 2x2"));
    }
}
