//! Laying a patch down along the minimum-cost seam (sections 3, 3.1 and 3.2).
//!
//! The graph has a node per output pixel under the patch. The source terminal is A, the
//! existing output; the sink terminal is B, the new patch. Pixels no patch covered yet must take
//! B; covered pixels on the border of the patch whose outside neighbour is covered must keep A
//! (a surrounded region keeps its border). Neighbouring pixels are joined by an arc of cost
//! M(s, t, A, B). Where an old seam runs between two pixels, a seam node sits between them with
//! arcs M(s, t, A_s, B) and M(s, t, B, A_t) to the pixels and an arc of the old seam's cost to B:
//! cutting that arc keeps the old seam, cutting a pixel arc makes a new seam there, and cutting
//! neither overwrites the seam (it then costs nothing).

use super::canvas::{Patch, UNCOVERED};
use super::synthesis::Synthesis;
use crate::core::Result;
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

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
        let footprint = self.footprint(patch);
        let (w, h) = (self.canvas.width, self.canvas.height);
        // Node of every output pixel under the patch, indexed within the patch's rectangle: a
        // table the size of the output would cost as much to clear as a 4096x4096 output has
        // pixels, at every placement.
        let (pw, ph) = self.patch_extent(patch.source as usize);
        let wrap = self.canvas.wrap;
        let local = |j: usize| -> Option<usize> {
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
        };
        let canvas = &self.canvas;
        let covered = |i: usize| canvas.label[i] != UNCOVERED;
        // Only covered pixels get a node. An uncovered pixel must take B, so it would sit on the
        // sink's side with an infinite arc: its arc to a covered neighbour is the same as an arc
        // from that neighbour to the sink, and the graph shrinks to the overlap (about half the
        // patch while the output is being covered).
        let mut nodes = vec![u32::MAX; pw * ph];
        let mut node_count = 0usize;
        for &i in footprint.iter().filter(|&&i| covered(i)) {
            nodes[local(i).expect("footprint pixels lie under the patch")] = node_count as u32;
            node_count += 1;
        }
        let node_of = |j: usize| local(j).map(|k| nodes[k]).filter(|&n| n != u32::MAX);
        let mut graph = Graph::with_capacity(node_count, 2 * node_count)?;
        for &i in &footprint {
            let Some(n) = node_of(i) else { continue };
            let neighbours = [canvas.right(i), canvas.down(i), self.left(i), self.up(i)];
            if neighbours
                .into_iter()
                .flatten()
                .any(|j| local(j).is_none() && covered(j))
            {
                graph.add_terminal(n as usize, HARD_CONSTRAINT, 0.0)?;
            }
        }
        for n in keep_old.iter().filter_map(|&i| node_of(i)) {
            graph.add_terminal(n as usize, HARD_CONSTRAINT, 0.0)?;
        }
        for n in force_new.iter().filter_map(|&i| node_of(i)) {
            graph.add_terminal(n as usize, 0.0, HARD_CONSTRAINT)?;
        }
        for &s in &footprint {
            for (t, horizontal) in [(canvas.right(s), true), (canvas.down(s), false)] {
                let Some(t) = t.filter(|&t| local(t).is_some()) else {
                    continue;
                };
                match (self.patch_of(s), self.patch_of(t)) {
                    (None, None) => {}
                    (Some(a_s), Some(a_t)) if a_s != a_t => {
                        // An old seam: its node, its cost to B, and the two new-seam arcs.
                        let (n, m) = (node_of(s).expect("covered"), node_of(t).expect("covered"));
                        let old = if horizontal {
                            canvas.h_seam[s]
                        } else {
                            canvas.v_seam[s]
                        };
                        let seam = graph.add_node();
                        let to_s = self.seam_cost(s, t, horizontal, a_s, patch);
                        let to_t = self.seam_cost(s, t, horizontal, patch, a_t);
                        graph.add_edge(n as usize, seam, to_s, to_s)?;
                        graph.add_edge(seam, m as usize, to_t, to_t)?;
                        graph.add_terminal(seam, 0.0, old)?;
                    }
                    (a_s, a_t) => {
                        // The same old patch A on both sides, or one pixel uncovered (it takes
                        // B): the seam left if a covered pixel keeps A costs M(A, B). With one
                        // uncovered, only that pixel's ||A - B|| counts: A does not reach the
                        // uncovered one (match_cost), whatever the empty canvas shows there.
                        let a = a_s.or(a_t).expect("one of them is covered");
                        let cost = self.seam_cost(s, t, horizontal, a, patch);
                        match (node_of(s), node_of(t)) {
                            (Some(n), Some(m)) => {
                                graph.add_edge(n as usize, m as usize, cost, cost)?
                            }
                            (Some(n), None) | (None, Some(n)) => {
                                graph.add_terminal(n as usize, 0.0, cost)?;
                            }
                            (None, None) => unreachable!("one of them is covered"),
                        }
                    }
                }
            }
        }
        let cut_cost = graph.maxflow();
        let taken: Vec<usize> = footprint
            .iter()
            .copied()
            .filter(|&i| node_of(i).is_none_or(|n| !graph.is_source_side(n as usize)))
            .collect();
        let index = self.canvas.patches.len();
        self.canvas.patches.push(patch);
        self.used.insert(patch);
        let source = &self.sources[patch.source as usize];
        for &i in &taken {
            let (x, y) = (i % w, i / w);
            let (sx, sy) = self
                .canvas
                .source_coords(patch, source, x, y)
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
