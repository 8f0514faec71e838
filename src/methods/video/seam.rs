//! Laying a spatio-temporal patch down along the minimum-cost seam surface (sections 3, 3.1, 3.2
//! and 7): the image version's graph, over 6-connected voxels instead of 4-connected pixels.
//!
//! The source terminal is A, the existing output; the sink is B, the new patch. Voxels no patch
//! covered yet must take B; covered voxels on the border of the patch whose outside neighbour is
//! covered must keep A (a surrounded region keeps its border), and so must fixed voxels (the
//! constrained frames of 7.D: "links of infinite cost between these pixels and the patches they
//! are constrained to copy from"). Neighbours are joined by an arc of cost M(s, t, A, B); where an
//! old seam runs between them, a seam node sits between them with arcs M(s, t, A_s, B) and
//! M(s, t, B, A_t) and an arc of the old seam's cost to B (section 3.1).
//!
//! One saving over the image version: an uncovered voxel is forced to B anyway, so it gets no
//! node. Its arc to a covered neighbour n becomes a terminal arc n -> B of the same cost (cut
//! exactly when n keeps A), and uncovered voxels away from the overlap cost nothing at all. While
//! a video is being covered most of a patch is new, so the graph shrinks to the overlap.

use super::canvas::{Patch, UNCOVERED};
use super::source::{AXES, Axis};
use super::synthesis::Synthesis;
use crate::core::Result;
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

/// The graph of one placement as plain data, so that tests can hand it to a reference solver.
#[derive(Debug, Clone, Default)]
pub struct SeamGraph {
    /// Node count: the covered voxels under the patch first (`voxels[n]` is node n's voxel), then
    /// the seam nodes.
    pub nodes: usize,
    pub voxels: Vec<usize>,
    /// Undirected arcs (a, b, capacity).
    pub edges: Vec<(u32, u32, f32)>,
    /// (node, capacity from A, capacity to B).
    pub terminals: Vec<(u32, f32, f32)>,
    /// The uncovered voxels under the patch: they take B whatever the cut.
    pub uncovered: Vec<usize>,
}

impl SeamGraph {
    /// The solver's graph.
    pub fn build(&self) -> Result<Graph> {
        let mut graph = Graph::with_capacity(self.nodes, self.edges.len())?;
        for &(a, b, c) in &self.edges {
            graph.add_edge(a as usize, b as usize, c, c)?;
        }
        for &(n, a, b) in &self.terminals {
            graph.add_terminal(n as usize, a, b)?;
        }
        Ok(graph)
    }
}

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
    /// The seam graph for placing `patch`; `force_new` voxels must take it (the centre of a
    /// covered error region, so a refinement cannot be rejected whole).
    pub fn seam_graph(&self, patch: Patch, force_new: &[usize]) -> SeamGraph {
        let canvas = &self.canvas;
        let footprint = self.footprint(patch);
        // Voxels are found in the patch's box, not in tables the size of the output, which would
        // cost as much to clear as the output has voxels at every placement.
        let (w, h, _) = canvas.size();
        let [xs, ys, ts] = self.footprint_box(patch);
        let (bw, bh) = (xs.len(), ys.len());
        let local = |j: usize| -> Option<usize> {
            let (x, y, t) = (j % w, (j / w) % h, j / (w * h));
            (xs.contains(&x) && ys.contains(&y) && ts.contains(&t))
                .then(|| ((t - ts.start) * bh + (y - ys.start)) * bw + (x - xs.start))
        };
        let inside = |j: usize| local(j).is_some();
        let mut nodes = vec![u32::MAX; footprint.len()];
        let mut g = SeamGraph::default();
        for &i in &footprint {
            if canvas.label[i] == UNCOVERED {
                g.uncovered.push(i);
            } else {
                nodes[local(i).expect("footprint voxels lie in its box")] = g.voxels.len() as u32;
                g.voxels.push(i);
            }
        }
        let node_of = |j: usize| local(j).map_or(u32::MAX, |k| nodes[k]);
        g.nodes = g.voxels.len();
        for (n, &i) in g.voxels.iter().enumerate() {
            let n = n as u32;
            let border = AXES.iter().any(|&axis| {
                [canvas.next(i, axis), canvas.prev(i, axis)]
                    .into_iter()
                    .flatten()
                    .any(|j| !inside(j) && canvas.label[j] != UNCOVERED)
            });
            if border || canvas.fixed[i] {
                g.terminals.push((n, HARD_CONSTRAINT, 0.0));
            }
        }
        for &i in force_new {
            if node_of(i) != u32::MAX && !canvas.fixed[i] {
                g.terminals.push((node_of(i), 0.0, HARD_CONSTRAINT));
            }
        }
        // Every edge with at least one covered end inside the patch, seen once from its first
        // voxel s (t = s's next neighbour along the axis).
        for &s in &footprint {
            for axis in AXES {
                let Some(t) = canvas.next(s, axis).filter(|&t| inside(t)) else {
                    continue;
                };
                self.add_edge(&mut g, &node_of, s, t, axis, patch);
            }
        }
        g
    }

    fn add_edge(
        &self,
        g: &mut SeamGraph,
        node_of: &impl Fn(usize) -> u32,
        s: usize,
        t: usize,
        axis: Axis,
        patch: Patch,
    ) {
        match (self.patch_of(s), self.patch_of(t)) {
            (None, None) => {}
            (Some(a_s), Some(a_t)) if a_s != a_t => {
                let old = self.canvas.seam[axis as usize][s];
                let seam = g.nodes as u32;
                g.nodes += 1;
                let to_s = self.seam_cost(s, t, axis, a_s, patch);
                let to_t = self.seam_cost(s, t, axis, patch, a_t);
                g.edges.push((node_of(s), seam, to_s));
                g.edges.push((seam, node_of(t), to_t));
                g.terminals.push((seam, 0.0, old));
            }
            (Some(a), Some(_)) => {
                let cost = self.seam_cost(s, t, axis, a, patch);
                g.edges.push((node_of(s), node_of(t), cost));
            }
            (Some(a), None) => {
                // t is new and takes B: cut when s keeps A.
                let cost = self.seam_cost(s, t, axis, a, patch);
                g.terminals.push((node_of(s), 0.0, cost));
            }
            (None, Some(a)) => {
                let cost = self.seam_cost(s, t, axis, patch, a);
                g.terminals.push((node_of(t), 0.0, cost));
            }
        }
    }

    /// Places `patch` with the seam surface the graph cut chooses.
    pub fn place(&mut self, patch: Patch, force_new: &[usize]) -> Result<Placed> {
        let g = self.seam_graph(patch, force_new);
        let mut graph = g.build()?;
        let cut_cost = graph.maxflow();
        let index = self.canvas.patches.len();
        self.canvas.patches.push(patch);
        let mut taken = g.uncovered.clone();
        taken.extend(
            g.voxels
                .iter()
                .enumerate()
                .filter(|&(n, _)| !graph.is_source_side(n))
                .map(|(_, &i)| i),
        );
        drop(graph);
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
