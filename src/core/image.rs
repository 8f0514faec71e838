//! The image buffer every layer works on: `f32` values in 0..1, channels interleaved, rows top to
//! bottom. One flat `Vec` so that hot loops walk contiguous memory.

use super::error::{Error, Result, check_size};

/// A `width` x `height` image with 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA) channels.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    width: usize,
    height: usize,
    channels: usize,
    data: Vec<f32>,
}

impl Image {
    /// A black (all-zero) image. Fails on an empty or oversized size or a bad channel count.
    pub fn new(width: usize, height: usize, channels: usize) -> Result<Self> {
        check_size("image", width, height)?;
        check_channels(channels)?;
        Ok(Self {
            width,
            height,
            channels,
            data: vec![0.0; width * height * channels],
        })
    }

    /// Wraps existing interleaved values; the length must be `width * height * channels`.
    pub fn from_vec(width: usize, height: usize, channels: usize, data: Vec<f32>) -> Result<Self> {
        check_size("image", width, height)?;
        check_channels(channels)?;
        let expected = width * height * channels;
        if data.len() != expected {
            return Err(Error::LengthMismatch {
                what: "image data",
                expected,
                actual: data.len(),
            });
        }
        Ok(Self {
            width,
            height,
            channels,
            data,
        })
    }

    /// Builds an image by calling `f(x, y, c)` for every value.
    pub fn from_fn(
        width: usize,
        height: usize,
        channels: usize,
        mut f: impl FnMut(usize, usize, usize) -> f32,
    ) -> Result<Self> {
        let mut image = Self::new(width, height, channels)?;
        for y in 0..height {
            for x in 0..width {
                for c in 0..channels {
                    image.data[(y * width + x) * channels + c] = f(x, y, c);
                }
            }
        }
        Ok(image)
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> usize {
        self.height
    }

    /// Values per pixel, 1 to 4.
    #[must_use]
    pub fn channels(&self) -> usize {
        self.channels
    }

    /// Number of pixels, `width * height`.
    #[must_use]
    pub fn pixel_count(&self) -> usize {
        self.width * self.height
    }

    /// The interleaved values, row by row.
    #[must_use]
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The interleaved values, row by row, for writing.
    pub fn data_mut(&mut self) -> &mut [f32] {
        &mut self.data
    }

    /// The interleaved values, row by row, without copying them.
    #[must_use]
    pub fn into_vec(self) -> Vec<f32> {
        self.data
    }

    /// Index of the first channel of pixel (x, y) in [`Image::data`].
    #[inline]
    #[must_use]
    pub fn index(&self, x: usize, y: usize) -> usize {
        (y * self.width + x) * self.channels
    }

    /// The channel values of pixel (x, y).
    #[inline]
    #[must_use]
    pub fn pixel(&self, x: usize, y: usize) -> &[f32] {
        let i = self.index(x, y);
        &self.data[i..i + self.channels]
    }

    /// The channel values of pixel (x, y), for writing.
    #[inline]
    pub fn pixel_mut(&mut self, x: usize, y: usize) -> &mut [f32] {
        let i = self.index(x, y);
        let c = self.channels;
        &mut self.data[i..i + c]
    }

    /// The `w` x `h` rectangle whose top-left corner is (x, y); it must lie inside the image.
    pub fn crop(&self, x: usize, y: usize, w: usize, h: usize) -> Result<Image> {
        check_size("crop", w, h)?;
        if x.checked_add(w).is_none_or(|r| r > self.width)
            || y.checked_add(h).is_none_or(|b| b > self.height)
        {
            return Err(Error::InvalidSize {
                what: "crop",
                width: w,
                height: h,
                reason: format!(
                    "the rectangle at ({x}, {y}) does not fit inside the {}x{} image",
                    self.width, self.height
                ),
            });
        }
        let c = self.channels;
        let mut data = Vec::with_capacity(w * h * c);
        for row in y..y + h {
            let start = self.index(x, row);
            data.extend_from_slice(&self.data[start..start + w * c]);
        }
        Image::from_vec(w, h, c, data)
    }

    /// The same picture with `channels` channels: grey is replicated to RGB, a missing alpha is
    /// opaque, and colour becomes grey by Rec. 601 luma.
    pub fn with_channels(&self, channels: usize) -> Result<Image> {
        check_channels(channels)?;
        if channels == self.channels {
            return Ok(self.clone());
        }
        let mut out = Image::new(self.width, self.height, channels)?;
        let (src_c, dst_c) = (self.channels, channels);
        for (src, dst) in self
            .data
            .chunks_exact(src_c)
            .zip(out.data.chunks_exact_mut(dst_c))
        {
            let (rgb, alpha) = split_colour(src);
            match dst_c {
                1 => dst[0] = luma(rgb),
                2 => {
                    dst[0] = luma(rgb);
                    dst[1] = alpha;
                }
                _ => {
                    dst[..3].copy_from_slice(&rgb);
                    if dst_c == 4 {
                        dst[3] = alpha;
                    }
                }
            }
        }
        Ok(out)
    }

    /// The same picture with the fewest channels that keep it exactly: alpha is dropped when every
    /// pixel is opaque, colour when every pixel has R = G = B. Decoders call this so that a grey
    /// photograph saved as RGB is synthesised (and searched) as one channel, three times faster.
    pub fn compact(&self) -> Result<Image> {
        let c = self.channels;
        let alpha = self.has_transparency();
        let grey = c <= 2
            || self
                .data
                .chunks_exact(c)
                .all(|p| p[0] == p[1] && p[1] == p[2]);
        let target = match (grey, alpha) {
            (true, false) => 1,
            (true, true) => {
                if c <= 2 {
                    2
                } else {
                    4
                }
            }
            (false, false) => 3,
            (false, true) => 4,
        };
        self.with_channels(target)
    }

    /// Whether any pixel is not fully opaque (always false without an alpha channel).
    #[must_use]
    pub fn has_transparency(&self) -> bool {
        match self.channels {
            2 | 4 => self
                .data
                .chunks_exact(self.channels)
                .any(|p| p[self.channels - 1] < 1.0),
            _ => false,
        }
    }
}

/// Accepts 1 to 4 channels.
pub fn check_channels(channels: usize) -> Result<()> {
    if (1..=4).contains(&channels) {
        Ok(())
    } else {
        Err(Error::UnsupportedChannels(channels))
    }
}

/// Splits a pixel of any channel count into RGB and alpha.
fn split_colour(p: &[f32]) -> ([f32; 3], f32) {
    match p.len() {
        1 => ([p[0]; 3], 1.0),
        2 => ([p[0]; 3], p[1]),
        3 => ([p[0], p[1], p[2]], 1.0),
        _ => ([p[0], p[1], p[2]], p[3]),
    }
}

fn luma(rgb: [f32; 3]) -> f32 {
    0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn from_vec_checks_length_and_channels() {
        assert!(Image::from_vec(2, 2, 3, vec![0.0; 12]).is_ok());
        let err = Image::from_vec(2, 2, 3, vec![0.0; 11]).unwrap_err();
        assert_eq!(
            err,
            Error::LengthMismatch {
                what: "image data",
                expected: 12,
                actual: 11
            }
        );
        assert_eq!(
            Image::new(2, 2, 5).unwrap_err(),
            Error::UnsupportedChannels(5)
        );
        assert!(Image::new(0, 2, 1).is_err());
    }

    #[test]
    fn crop_takes_the_rectangle() {
        let img = Image::from_fn(5, 4, 1, |x, y, _| (y * 10 + x) as f32).unwrap();
        let c = img.crop(1, 2, 3, 2).unwrap();
        assert_eq!((c.width(), c.height()), (3, 2));
        assert_eq!(c.data(), &[21.0, 22.0, 23.0, 31.0, 32.0, 33.0]);
        assert!(
            img.crop(3, 0, 3, 1)
                .unwrap_err()
                .to_string()
                .contains("does not fit")
        );
        assert!(img.crop(0, 0, 0, 1).is_err());
        assert!(img.crop(usize::MAX, 0, 1, 1).is_err());
    }

    #[test]
    fn channel_conversion() {
        let grey = Image::from_vec(1, 1, 1, vec![0.5]).unwrap();
        assert_eq!(grey.with_channels(4).unwrap().data(), &[0.5, 0.5, 0.5, 1.0]);
        let rgb = Image::from_vec(1, 1, 3, vec![1.0, 0.0, 0.0]).unwrap();
        assert!((rgb.with_channels(1).unwrap().data()[0] - 0.299).abs() < 1e-6);
        let rgba = Image::from_vec(1, 1, 4, vec![0.1, 0.2, 0.3, 0.5]).unwrap();
        assert!(rgba.has_transparency());
        assert_eq!(rgba.with_channels(2).unwrap().data()[1], 0.5);
        assert!(!rgb.has_transparency());
    }
}
