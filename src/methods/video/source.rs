//! The volumes patches are copied from, each with its gradient magnitudes along x, y and t, which
//! the gradient-scaled seam cost M' (eq. 5) divides by: along an edge in time, the gradient is
//! the change of a voxel from one frame to the next, so seams hide in fast motion as they hide in
//! busy texture in 2-D.

use super::volume::Volume;

/// The three axes of the lattice; an edge joins a voxel and its neighbour along one of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    X = 0,
    Y = 1,
    T = 2,
}

pub const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::T];

/// One source volume.
#[derive(Debug, Clone)]
pub struct Source {
    pub volume: Volume,
    /// |dV/dx|, |dV/dy|, |dV/dt| per voxel (norm over channels), central differences clamped at
    /// the border (the same definition as the image version's gradients).
    pub gradient: [Vec<f32>; 3],
}

impl Source {
    #[must_use]
    pub fn new(volume: Volume) -> Source {
        let gradient = AXES.map(|axis| gradient_along(&volume, axis));
        Source { volume, gradient }
    }
}

/// The gradient magnitude of every voxel along `axis`.
fn gradient_along(v: &Volume, axis: Axis) -> Vec<f32> {
    let (w, h, d) = (v.width(), v.height(), v.frames());
    let mut out = vec![0.0f32; v.voxel_count()];
    for t in 0..d {
        for y in 0..h {
            for x in 0..w {
                let (lo, hi) = match axis {
                    Axis::X => (
                        v.index(x.saturating_sub(1), y, t),
                        v.index((x + 1).min(w - 1), y, t),
                    ),
                    Axis::Y => (
                        v.index(x, y.saturating_sub(1), t),
                        v.index(x, (y + 1).min(h - 1), t),
                    ),
                    Axis::T => (
                        v.index(x, y, t.saturating_sub(1)),
                        v.index(x, y, (t + 1).min(d - 1)),
                    ),
                };
                let norm: f32 = v
                    .voxel(hi)
                    .iter()
                    .zip(v.voxel(lo))
                    .map(|(a, b)| ((a - b) * 0.5).powi(2))
                    .sum();
                out[v.index(x, y, t)] = norm.sqrt();
            }
        }
    }
    out
}
