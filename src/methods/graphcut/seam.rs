//! Laying a patch down along the minimum-cost seam (sections 3, 3.1 and 3.2): the graph is the
//! shared one of `seam_graph.rs` over 4-connected pixels (video uses it over voxels); here, what
//! a placement does with its cut, and the seam memory it keeps.

use super::anatomy::GraphView;
use super::canvas::{Patch, UNCOVERED};
use super::seam_graph::{Footprint, SeamGraph, SeamGrid};
use super::synthesis::Synthesis;
use crate::core::Result;

/// What a placement did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placed {
    /// Index of the patch in the canvas's patch list.
    pub index: usize,
    pub patch: Patch,
    /// Output pixels that now come from the new patch.
    pub pixels_taken: usize,
    /// Cost of the minimum cut (the seams within the patch after placement).
    pub cut_cost: f64,
}

impl Synthesis {
    /// Places `patch` with the seam the graph cut chooses. `force_new` names output pixels that
    /// must take the new patch (the centre of a fully covered region, so that a placement cannot
    /// be rejected whole; or pixels a user painted for it when merging), `keep_old` pixels that
    /// must keep what they show.
    pub fn place(
        &mut self,
        patch: Patch,
        force_new: &[usize],
        keep_old: &[usize],
    ) -> Result<Placed> {
        let w = self.canvas.width;
        let (pw, ph) = self.patch_extent(patch.source as usize);
        let local = self.local_index(patch);
        let graph = self.seam_graph(self, patch, force_new, keep_old);
        let (cut_cost, taken) = graph.solve_with(&mut self.graph)?;
        let view = self.record_anatomy.then(|| {
            GraphView::new(
                &graph,
                (i64::from(patch.tx), i64::from(patch.ty)),
                (pw, ph),
                &local,
                &|i, axis| self.next(i, axis),
                &taken,
            )
        });
        self.last_graph = view;
        let index = self.canvas.patches.len();
        self.canvas.patches.push(patch);
        self.used.insert(patch);
        let source = &self.sources[patch.source as usize];
        for &i in &taken {
            let (x, y) = (i % w, i / w);
            let (sx, sy) = self
                .source_coords(patch, x, y)
                .expect("footprint pixels are covered by the patch");
            self.canvas
                .pixels
                .pixel_mut(x, y)
                .copy_from_slice(source.image.pixel(sx, sy));
            if self.canvas.label[i] == UNCOVERED {
                self.canvas.covered += 1;
            }
            self.canvas.label[i] = index as u32;
        }
        // Only edges touching a pixel that changed can have a different seam now.
        self.update_seams(&taken);
        Ok(Placed {
            index,
            patch,
            pixels_taken: taken.len(),
            cut_cost,
        })
    }

    /// The index of output pixel `j` within `patch`'s rectangle (`None` outside it). Pixels are
    /// found within the rectangle: a table the size of the output would cost as much to clear
    /// as a 4096x4096 output has pixels, at every placement.
    pub(super) fn local_index(&self, patch: Patch) -> impl Fn(usize) -> Option<usize> + use<> {
        let (w, h) = (self.canvas.width, self.canvas.height);
        let (pw, ph) = self.patch_extent(patch.source as usize);
        let wrap = self.canvas.wrap;
        move |j: usize| -> Option<usize> {
            let (mut u, mut v) = (
                (j % w) as i64 - i64::from(patch.tx),
                (j / w) as i64 - i64::from(patch.ty),
            );
            if wrap {
                u = u.rem_euclid(w as i64);
                v = v.rem_euclid(h as i64);
            }
            ((0..pw as i64).contains(&u) && (0..ph as i64).contains(&v))
                .then(|| v as usize * pw + u as usize)
        }
    }

    /// The seam graph of placing `patch` (see [`Synthesis::place`]), with the costs `grid` gives
    /// (the synthesis itself, or in tests a view of it without its shortcuts).
    pub(super) fn seam_graph<G: SeamGrid<Label = Patch>>(
        &self,
        grid: &G,
        patch: Patch,
        force_new: &[usize],
        keep_old: &[usize],
    ) -> SeamGraph {
        let footprint = self.footprint(patch);
        let (pw, ph) = self.patch_extent(patch.source as usize);
        let local = self.local_index(patch);
        let mut keep = vec![false; pw * ph];
        for k in keep_old.iter().filter_map(|&i| local(i)) {
            keep[k] = true;
        }
        SeamGraph::new(
            grid,
            &Footprint {
                cells: &footprint,
                local: &local,
                box_len: pw * ph,
            },
            patch,
            force_new,
            |i| local(i).is_some_and(|k| keep[k]),
        )
    }

    /// Recomputes the remembered seam cost of every edge touching `pixels`.
    fn update_seams(&mut self, pixels: &[usize]) {
        for &i in pixels {
            let edges = [
                (Some(i), self.canvas.right(i), true),
                (Some(i), self.canvas.down(i), false),
                (self.left(i), Some(i), true),
                (self.up(i), Some(i), false),
            ];
            for (s, t, horizontal) in edges {
                let (Some(s), Some(t)) = (s, t) else { continue };
                let cost = match (self.patch_of(s), self.patch_of(t)) {
                    (Some(a), Some(b)) => self.seam_cost(s, t, horizontal, a, b),
                    _ => 0.0,
                };
                self.canvas.set_seam(s, horizontal, cost);
            }
        }
    }

    /// The left neighbour of pixel `i`.
    #[must_use]
    pub fn left(&self, i: usize) -> Option<usize> {
        let w = self.canvas.width;
        if !i.is_multiple_of(w) {
            Some(i - 1)
        } else if self.canvas.wrap && w > 1 {
            Some(i + w - 1)
        } else {
            None
        }
    }

    /// The neighbour above pixel `i`.
    #[must_use]
    pub fn up(&self, i: usize) -> Option<usize> {
        let (w, n) = (self.canvas.width, self.canvas.width * self.canvas.height);
        if i >= w {
            Some(i - w)
        } else if self.canvas.wrap && self.canvas.height > 1 {
            Some(i + n - w)
        } else {
            None
        }
    }
}

/// Pixels as the seam graph's grid: axis 0 joins a pixel to its right neighbour, axis 1 to the
/// one below, wrapping where the output wraps.
impl SeamGrid for Synthesis {
    type Label = Patch;
    const AXES: usize = 2;

    fn next(&self, i: usize, axis: usize) -> Option<usize> {
        if axis == 0 {
            self.canvas.right(i)
        } else {
            self.canvas.down(i)
        }
    }

    fn prev(&self, i: usize, axis: usize) -> Option<usize> {
        if axis == 0 { self.left(i) } else { self.up(i) }
    }

    fn label_of(&self, i: usize) -> Option<Patch> {
        self.patch_of(i)
    }

    fn old_seam(&self, s: usize, axis: usize) -> f32 {
        if axis == 0 {
            self.canvas.h_seam[s]
        } else {
            self.canvas.v_seam[s]
        }
    }

    fn seam_cost(&self, s: usize, t: usize, axis: usize, a: Patch, b: Patch) -> f32 {
        Synthesis::seam_cost(self, s, t, axis == 0, a, b)
    }

    fn cell_term(&self, i: usize, a: Patch, b: Patch) -> Option<f32> {
        Synthesis::cell_term(self, i, a, b)
    }
}
