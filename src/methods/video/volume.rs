//! Video as an (x, y, t) volume of voxels (section 7: "a 3D collection of voxels, where one of
//! the axes is time"): frames of interleaved RGB `f32` in 0..1, frame after frame, as
//! `core::Image` keeps one frame. An image is the one-frame volume.

use super::budget::check_volume;
use crate::core::{Error, Result, codec::to_byte};

/// Colour channels of a video voxel: RGB (alpha is dropped on input and opaque on output).
pub const CHANNELS: usize = 3;

/// A video clip or a synthesised video: `data[((t * height + y) * width + x) * 3 + c]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Volume {
    width: usize,
    height: usize,
    frames: usize,
    data: Vec<f32>,
}

impl Volume {
    /// A black volume. Fails on an empty size or one beyond the memory budget.
    pub fn new(width: usize, height: usize, frames: usize) -> Result<Volume> {
        check_volume("video volume", width, height, frames)?;
        Ok(Volume {
            width,
            height,
            frames,
            data: vec![0.0; width * height * frames * CHANNELS],
        })
    }

    /// From RGBA8 frames, `width * height * 4 * frames` bytes, frame after frame.
    pub fn from_rgba_frames(
        width: usize,
        height: usize,
        frames: usize,
        rgba: &[u8],
    ) -> Result<Volume> {
        check_volume("video clip", width, height, frames)?;
        let expected = width * height * 4 * frames;
        if rgba.len() != expected {
            return Err(Error::LengthMismatch {
                what: "RGBA frames (width * height * 4 * frames)",
                expected,
                actual: rgba.len(),
            });
        }
        let data = rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]].map(|v| f32::from(v) / 255.0))
            .collect();
        Ok(Volume {
            width,
            height,
            frames,
            data,
        })
    }

    /// A volume whose voxel (x, y, t) has colour `f(x, y, t)`.
    pub fn from_fn(
        width: usize,
        height: usize,
        frames: usize,
        f: impl Fn(usize, usize, usize) -> [f32; 3],
    ) -> Result<Volume> {
        let mut v = Volume::new(width, height, frames)?;
        for t in 0..frames {
            for y in 0..height {
                for x in 0..width {
                    let i = v.index(x, y, t);
                    v.data[i * CHANNELS..(i + 1) * CHANNELS].copy_from_slice(&f(x, y, t));
                }
            }
        }
        Ok(v)
    }

    /// Frame width in pixels.
    #[must_use]
    pub fn width(&self) -> usize {
        self.width
    }

    /// Frame height in pixels.
    #[must_use]
    pub fn height(&self) -> usize {
        self.height
    }

    /// Number of frames.
    #[must_use]
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Number of voxels, `width * height * frames`.
    #[must_use]
    pub fn voxel_count(&self) -> usize {
        self.width * self.height * self.frames
    }

    /// The RGB values, interleaved, row by row and frame after frame.
    #[must_use]
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The RGB values to change in place (as [`Volume::data`] lays them out).
    #[must_use]
    pub fn data_mut(&mut self) -> &mut [f32] {
        &mut self.data
    }

    /// Voxel index of (x, y, t).
    #[inline]
    #[must_use]
    pub fn index(&self, x: usize, y: usize, t: usize) -> usize {
        (t * self.height + y) * self.width + x
    }

    /// Colour of voxel `i`.
    #[inline]
    #[must_use]
    pub fn voxel(&self, i: usize) -> &[f32] {
        &self.data[i * CHANNELS..(i + 1) * CHANNELS]
    }

    /// Colour of voxel `i`, for writing.
    #[inline]
    pub fn voxel_mut(&mut self, i: usize) -> &mut [f32] {
        &mut self.data[i * CHANNELS..(i + 1) * CHANNELS]
    }

    /// The RGB values of frame `t`.
    #[must_use]
    pub fn frame(&self, t: usize) -> &[f32] {
        let n = self.width * self.height * CHANNELS;
        &self.data[t * n..(t + 1) * n]
    }

    /// Frames `first..first + count` as a volume of their own.
    pub fn frames_range(&self, first: usize, count: usize) -> Result<Volume> {
        if count == 0 || first + count > self.frames {
            return Err(Error::InvalidParameter {
                name: "frame range",
                reason: format!(
                    "frames {first}..{} do not lie in a clip of {} frames",
                    first + count,
                    self.frames
                ),
            });
        }
        let n = self.width * self.height * CHANNELS;
        Ok(Volume {
            width: self.width,
            height: self.height,
            frames: count,
            data: self.data[first * n..(first + count) * n].to_vec(),
        })
    }

    /// Frame `t` as RGBA8 into `out` (`width * height * 4` bytes), opaque.
    pub fn write_frame_rgba(&self, t: usize, out: &mut [u8]) -> Result<()> {
        check_frame(t, self.frames)?;
        let expected = self.width * self.height * 4;
        if out.len() != expected {
            return Err(Error::LengthMismatch {
                what: "frame RGBA buffer (width * height * 4)",
                expected,
                actual: out.len(),
            });
        }
        for (o, p) in out.chunks_exact_mut(4).zip(self.frame(t).chunks_exact(3)) {
            o[..3].copy_from_slice(&[to_byte(p[0]), to_byte(p[1]), to_byte(p[2])]);
            o[3] = 255;
        }
        Ok(())
    }

    /// Mean squared difference per voxel channel between frames `a` and `b`.
    #[must_use]
    pub fn frame_difference(&self, a: usize, b: usize) -> f64 {
        let (fa, fb) = (self.frame(a), self.frame(b));
        fa.iter()
            .zip(fb)
            .map(|(x, y)| f64::from(x - y).powi(2))
            .sum::<f64>()
            / fa.len() as f64
    }
}

/// Fails unless `t` is a frame of a `frames`-frame video.
pub fn check_frame(t: usize, frames: usize) -> Result<()> {
    if t < frames {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            name: "frame",
            reason: format!(
                "frame {t} does not exist; the video has {frames} frames (0..{frames})"
            ),
        })
    }
}
