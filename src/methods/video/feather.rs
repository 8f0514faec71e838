//! Feathering of video seams (section 5 applied to voxels): the image version's feathering
//! (`graphcut::blend::feather`) over the canvas's voxels, across seams in x, y and time.

use super::canvas::UNCOVERED;
use super::source::Axis;
use super::synthesis::Synthesis;
use super::volume::{CHANNELS, Volume};
use crate::methods::graphcut::blend::{FeatherGrid, feather};

/// The canvas's voxels as a feathering grid: clamped at every border.
impl FeatherGrid for Synthesis {
    fn extent(&self) -> [usize; 3] {
        let (w, h, d) = self.canvas.size();
        [w, h, d]
    }

    fn channels(&self) -> usize {
        CHANNELS
    }

    fn label(&self, i: usize) -> u32 {
        self.canvas.label[i]
    }

    fn resolve(&self, axis: usize, c: isize) -> usize {
        let len = self.extent()[axis];
        c.clamp(0, len as isize - 1) as usize
    }

    fn value(&self, label: u32, i: usize) -> &[f32] {
        if label == UNCOVERED {
            return self.canvas.pixels.voxel(i);
        }
        let patch = self.canvas.patches[label as usize];
        self.sample(patch, i, Axis::X)
            .map_or_else(|| self.canvas.pixels.voxel(i), |s| s.colour)
    }
}

impl Synthesis {
    /// The canvas with its seams feathered.
    #[must_use]
    pub fn feathered(&self) -> Volume {
        let mut out = self.canvas.pixels.clone();
        feather(self, out.data_mut());
        out
    }
}
