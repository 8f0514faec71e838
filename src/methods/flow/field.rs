//! A 2-D flow field f_i (Kwatra et al. 2005, section 4.1): per pixel, the displacement (in pixels)
//! that carries the pixel from one frame to the next.

use crate::core::{Error, Result, error::check_size};

/// Displacements `(vx, vy)` per pixel, interleaved, row by row.
#[derive(Debug, Clone, PartialEq)]
pub struct FlowField {
    width: usize,
    height: usize,
    data: Vec<f32>,
}

/// The largest displacement accepted, in pixels per frame: beyond it a frame has nothing in
/// common with the previous one and the flow term means nothing.
pub const MAX_DISPLACEMENT: f32 = 1024.0;

impl FlowField {
    /// A zero field.
    pub fn zero(width: usize, height: usize) -> Result<Self> {
        check_size("flow field", width, height)?;
        Ok(FlowField {
            width,
            height,
            data: vec![0.0; width * height * 2],
        })
    }

    /// A field from interleaved `(vx, vy)` values; refuses a wrong length and non-finite or
    /// absurdly large values, naming the first bad one.
    pub fn from_vec(width: usize, height: usize, data: Vec<f32>) -> Result<Self> {
        check_size("flow field", width, height)?;
        if data.len() != width * height * 2 {
            return Err(Error::LengthMismatch {
                what: "flow field (2 values per pixel)",
                expected: width * height * 2,
                actual: data.len(),
            });
        }
        if let Some(i) = data
            .iter()
            .position(|v| !v.is_finite() || v.abs() > MAX_DISPLACEMENT)
        {
            return Err(Error::InvalidParameter {
                name: "flow",
                reason: format!(
                    "value {} at pixel ({}, {}) is not a finite displacement of at most {MAX_DISPLACEMENT} pixels",
                    data[i],
                    (i / 2) % width,
                    (i / 2) / width
                ),
            });
        }
        Ok(FlowField {
            width,
            height,
            data,
        })
    }

    /// A field with `f(x, y)` at every pixel centre.
    pub fn from_fn(
        width: usize,
        height: usize,
        mut f: impl FnMut(f32, f32) -> (f32, f32),
    ) -> Result<Self> {
        let mut data = Vec::with_capacity(width * height * 2);
        for y in 0..height {
            for x in 0..width {
                let (vx, vy) = f(x as f32, y as f32);
                data.extend([vx, vy]);
            }
        }
        Self::from_vec(width, height, data)
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

    /// The interleaved `(vx, vy)` displacements in pixels per frame, row by row.
    #[must_use]
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The displacement at pixel (x, y).
    #[inline]
    #[must_use]
    pub fn at(&self, x: usize, y: usize) -> (f32, f32) {
        let i = (y * self.width + x) * 2;
        (self.data[i], self.data[i + 1])
    }

    /// The displacement at a fractional position, from the nearest pixel (clamped inside).
    #[must_use]
    pub fn near(&self, x: f64, y: f64) -> (f32, f32) {
        let xi = (x.round().max(0.0) as usize).min(self.width - 1);
        let yi = (y.round().max(0.0) as usize).min(self.height - 1);
        self.at(xi, yi)
    }

    /// Divergence dvx/dx + dvy/dy at an interior pixel, by central differences.
    #[must_use]
    pub fn divergence(&self, x: usize, y: usize) -> f32 {
        let (r, l) = (self.at(x + 1, y), self.at(x - 1, y));
        let (d, u) = (self.at(x, y + 1), self.at(x, y - 1));
        0.5 * ((r.0 - l.0) + (d.1 - u.1))
    }

    /// Curl dvy/dx - dvx/dy at an interior pixel, by central differences.
    #[must_use]
    pub fn curl(&self, x: usize, y: usize) -> f32 {
        let (r, l) = (self.at(x + 1, y), self.at(x - 1, y));
        let (d, u) = (self.at(x, y + 1), self.at(x, y - 1));
        0.5 * ((r.1 - l.1) - (d.0 - u.0))
    }

    /// The largest displacement length.
    #[must_use]
    pub fn max_speed(&self) -> f32 {
        self.data
            .chunks_exact(2)
            .map(|v| crate::core::math::hypotf(v[0], v[1]))
            .fold(0.0, f32::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_of_the_wrong_length_or_with_bad_values_are_refused() {
        assert!(
            FlowField::from_vec(4, 3, vec![0.0; 23])
                .unwrap_err()
                .to_string()
                .contains("expected 24")
        );
        let mut data = vec![0.0; 24];
        data[9] = f32::NAN;
        let msg = FlowField::from_vec(4, 3, data).unwrap_err().to_string();
        assert!(msg.contains("NaN") && msg.contains("(0, 1)"), "{msg}");
        assert!(FlowField::from_vec(0, 3, vec![]).is_err());
        let mut huge = vec![0.0; 24];
        huge[0] = 1e9;
        assert!(FlowField::from_vec(4, 3, huge).is_err());
    }
}
