//! The output video being synthesised, as in the image version's canvas: voxel colours, which
//! patch every voxel came from (the label volume), and the seam cost on every edge between
//! 6-connected neighbours, remembered so that later patches can overwrite bad old seams (section
//! 3.1). The seam is then a surface through the volume (section 7, figure 7).

use super::source::Axis;
use super::volume::Volume;
use crate::core::Result;

/// Label of a voxel no patch has covered yet.
pub const UNCOVERED: u32 = u32::MAX;

/// A placed spatio-temporal patch: the whole of source `source`, translated by (tx, ty, tt):
/// output voxel p copies source voxel p - t.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Patch {
    pub source: u32,
    pub tx: i32,
    pub ty: i32,
    pub tt: i32,
}

/// The output volume and its seam memory. It never wraps: a loop is made from translated copies
/// (section 7.A) or temporal constraints (7.D), not from a periodic volume.
#[derive(Debug, Clone)]
pub struct Canvas {
    pub pixels: Volume,
    /// Patch index of every voxel, or [`UNCOVERED`].
    pub label: Vec<u32>,
    pub patches: Vec<Patch>,
    /// Seam cost of the edge from voxel i to its next neighbour along x, y and t, at index i;
    /// zero where both voxels come from the same patch.
    pub seam: [Vec<f32>; 3],
    /// Voxels no placement may change (the constrained frames of section 7.D).
    pub fixed: Vec<bool>,
    pub covered: usize,
}

impl Canvas {
    pub fn new(width: usize, height: usize, frames: usize) -> Result<Canvas> {
        let pixels = Volume::new(width, height, frames)?;
        let n = pixels.voxel_count();
        Ok(Canvas {
            pixels,
            label: vec![UNCOVERED; n],
            patches: Vec::new(),
            seam: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            fixed: vec![false; n],
            covered: 0,
        })
    }

    #[must_use]
    pub fn size(&self) -> (usize, usize, usize) {
        (
            self.pixels.width(),
            self.pixels.height(),
            self.pixels.frames(),
        )
    }

    #[must_use]
    pub fn voxel_count(&self) -> usize {
        self.label.len()
    }

    #[must_use]
    pub fn is_covered(&self) -> bool {
        self.covered == self.label.len()
    }

    /// (x, y, t) of voxel i.
    #[inline]
    #[must_use]
    pub fn coords(&self, i: usize) -> (usize, usize, usize) {
        let (w, h, _) = self.size();
        (i % w, i / w % h, i / (w * h))
    }

    /// The neighbour after voxel i along `axis`.
    #[inline]
    #[must_use]
    pub fn next(&self, i: usize, axis: Axis) -> Option<usize> {
        let (w, h, d) = self.size();
        let (x, y, t) = self.coords(i);
        match axis {
            Axis::X => (x + 1 < w).then_some(i + 1),
            Axis::Y => (y + 1 < h).then_some(i + w),
            Axis::T => (t + 1 < d).then_some(i + w * h),
        }
    }

    /// The neighbour before voxel i along `axis`.
    #[inline]
    #[must_use]
    pub fn prev(&self, i: usize, axis: Axis) -> Option<usize> {
        let (w, h, _) = self.size();
        let (x, y, t) = self.coords(i);
        match axis {
            Axis::X => (x > 0).then(|| i - 1),
            Axis::Y => (y > 0).then(|| i - w),
            Axis::T => (t > 0).then(|| i - w * h),
        }
    }

    /// Sum of every seam cost in the output.
    #[must_use]
    pub fn total_seam_cost(&self) -> f64 {
        self.seam.iter().flatten().map(|&c| f64::from(c)).sum()
    }

    /// Per-voxel seam error: the sum of the seam costs on its six edges (the error that drives
    /// placement once the output is covered).
    #[must_use]
    pub fn seam_error(&self) -> Vec<f32> {
        let mut error = vec![0.0f32; self.voxel_count()];
        for (axis, costs) in [Axis::X, Axis::Y, Axis::T].into_iter().zip(&self.seam) {
            for i in 0..error.len() {
                if costs[i] > 0.0
                    && let Some(j) = self.next(i, axis)
                {
                    error[i] += costs[i];
                    error[j] += costs[i];
                }
            }
        }
        error
    }
}
