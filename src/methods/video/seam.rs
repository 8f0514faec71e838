//! Laying a spatio-temporal patch down along the minimum-cost seam surface (sections 3, 3.1, 3.2
//! and 7): the image version's seam graph (`graphcut/seam_graph.rs`) over 6-connected voxels,
//! with the fixed frames of 7.D held to what they show ("links of infinite cost between these
//! pixels and the patches they are constrained to copy from").

use super::canvas::{Patch, UNCOVERED};
use super::source::AXES;
use super::synthesis::Synthesis;
use crate::core::Result;
pub use crate::methods::graphcut::seam_graph::SeamGraph;
use crate::methods::graphcut::seam_graph::{Footprint, SeamGrid};

/// What a placement did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placed {
    pub index: usize,
    pub patch: Patch,
    /// Output voxels that now come from the new patch.
    pub voxels_taken: usize,
    /// Cost of the minimum cut: the seams within the patch after placement.
    pub cut_cost: f64,
}

impl Synthesis {
    /// The seam graph for placing `patch` (the image version's, over 6-connected voxels);
    /// `force_new` voxels must take it (the centre of a covered error region, so a refinement
    /// cannot be rejected whole); fixed voxels (7.D) keep what they show.
    pub fn seam_graph(&self, patch: Patch, force_new: &[usize]) -> SeamGraph {
        let footprint = self.footprint(patch);
        // Voxels are found in the patch's box, not in tables the size of the output, which would
        // cost as much to clear as the output has voxels at every placement.
        let (w, h, _) = self.canvas.size();
        let [xs, ys, ts] = self.footprint_box(patch);
        let (bw, bh) = (xs.len(), ys.len());
        let local = |j: usize| -> Option<usize> {
            let (x, y, t) = (j % w, (j / w) % h, j / (w * h));
            (xs.contains(&x) && ys.contains(&y) && ts.contains(&t))
                .then(|| ((t - ts.start) * bh + (y - ys.start)) * bw + (x - xs.start))
        };
        SeamGraph::new(
            self,
            &Footprint {
                cells: &footprint,
                local,
                box_len: footprint.len(),
            },
            patch,
            force_new,
            |i| self.canvas.fixed[i],
        )
    }

    /// Places `patch` with the seam surface the graph cut chooses.
    pub fn place(&mut self, patch: Patch, force_new: &[usize]) -> Result<Placed> {
        let graph = self.seam_graph(patch, force_new);
        let (cut_cost, taken) = graph.solve_with(&mut self.graph)?;
        self.last_graph = self
            .record_anatomy
            .then(|| self.graph_slice(&graph, patch, &taken));
        let index = self.canvas.patches.len();
        self.canvas.patches.push(patch);
        self.take(index, patch, &taken);
        Ok(Placed {
            index,
            patch,
            voxels_taken: taken.len(),
            cut_cost,
        })
    }

    /// Gives `voxels` to patch number `index` and updates the seam memory around them.
    pub fn take(&mut self, index: usize, patch: Patch, voxels: &[usize]) {
        let source = patch.source as usize;
        for &i in voxels {
            let k = self
                .source_voxel(patch, i)
                .expect("voxels taken lie under the patch");
            let colour: [f32; 3] = self.sources[source]
                .volume
                .voxel(k)
                .try_into()
                .expect("three channels");
            self.canvas.pixels.voxel_mut(i).copy_from_slice(&colour);
            if self.canvas.label[i] == UNCOVERED {
                self.canvas.covered += 1;
            }
            self.canvas.label[i] = index as u32;
        }
        // Only edges touching a voxel that changed can have a different seam now.
        for &i in voxels {
            for axis in AXES {
                for (s, t) in [
                    (Some(i), self.canvas.next(i, axis)),
                    (self.canvas.prev(i, axis), Some(i)),
                ] {
                    let (Some(s), Some(t)) = (s, t) else { continue };
                    let cost = match (self.patch_of(s), self.patch_of(t)) {
                        (Some(a), Some(b)) => self.seam_cost(s, t, axis, a, b),
                        _ => 0.0,
                    };
                    self.canvas.seam[axis as usize][s] = cost;
                }
            }
        }
    }
}

/// Voxels as the seam graph's grid: axes x, y and t.
impl SeamGrid for Synthesis {
    type Label = Patch;
    const AXES: usize = 3;

    fn next(&self, i: usize, axis: usize) -> Option<usize> {
        self.canvas.next(i, AXES[axis])
    }

    fn prev(&self, i: usize, axis: usize) -> Option<usize> {
        self.canvas.prev(i, AXES[axis])
    }

    fn label_of(&self, i: usize) -> Option<Patch> {
        self.patch_of(i)
    }

    fn old_seam(&self, s: usize, axis: usize) -> f32 {
        self.canvas.seam[axis][s]
    }

    fn seam_cost(&self, s: usize, t: usize, axis: usize, a: Patch, b: Patch) -> f32 {
        Synthesis::seam_cost(self, s, t, AXES[axis], a, b)
    }
}
