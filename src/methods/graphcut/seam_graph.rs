//! The graph whose minimum cut is the seam (sections 3, 3.1, 3.2), for images and for video: one
//! builder over any grid of cells, 4-connected pixels or 6-connected voxels.
//!
//! The source terminal is A, the existing output; the sink is B, the new patch. Cells no patch
//! covered yet must take B; covered cells on the border of the patch whose outside neighbour is
//! covered must keep A (a surrounded region keeps its border), and so must cells the caller
//! holds (a user's "keep" paint, the fixed frames of 7.D). Neighbours are joined by an arc of cost
//! M(s, t, A, B); where an old seam runs between them, a seam node sits between them with arcs
//! M(s, t, A_s, B) and M(s, t, B, A_t) and an arc of the old seam's cost to B (section 3.1):
//! cutting that arc keeps the old seam, cutting a cell arc makes a new seam there, and cutting
//! neither overwrites the seam.
//!
//! An uncovered cell is forced to B anyway, so it gets no node: its arc to a covered neighbour n
//! becomes a terminal arc n -> B of the same cost (cut exactly when n keeps A). While the output
//! is being covered most of a patch is new, so the graph shrinks to the overlap.

use crate::core::Result;
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

/// What the seam graph needs to know of an output grid.
pub trait SeamGrid {
    /// What a covered cell shows (a placed patch).
    type Label: Copy + PartialEq;
    /// The number of axes: 2 for images (x, y), 3 for video (x, y, t).
    const AXES: usize;
    /// The neighbour after cell `i` along `axis`, if any (wrapping where the output wraps).
    fn next(&self, i: usize, axis: usize) -> Option<usize>;
    /// The neighbour before cell `i` along `axis`, if any.
    fn prev(&self, i: usize, axis: usize) -> Option<usize>;
    /// What cell `i` shows, or `None` while uncovered.
    fn label_of(&self, i: usize) -> Option<Self::Label>;
    /// The remembered cost of the seam between `s` and its next neighbour along `axis`.
    fn old_seam(&self, s: usize, axis: usize) -> f32;
    /// M (or M') between `s` and its next neighbour `t` along `axis` when `s` shows `a` and `t`
    /// shows `b` (0 when `a == b`).
    fn seam_cost(&self, s: usize, t: usize, axis: usize, a: Self::Label, b: Self::Label) -> f32;
    /// Where M is a sum of one term per cell (eq. 1: `||A(s) - B(s)|| + ||A(t) - B(t)||`, no
    /// gradients, no other terms), cell `i`'s term when it shows `a` and the new patch is `b`,
    /// such that `seam_cost(s, t, axis, a, b)` is `cell_term(s, a, b) + cell_term(t, a, b)` to
    /// the bit; otherwise `None`. Most arcs of a seam graph join two cells showing the same old
    /// patch, so the graph then computes each cell's term once instead of once per arc.
    fn cell_term(&self, _i: usize, _a: Self::Label, _b: Self::Label) -> Option<f32> {
        None
    }
}

/// The graph of one placement as plain data, so that tests can hand it to a reference solver.
#[derive(Debug, Clone, Default)]
pub struct SeamGraph {
    /// Node count: the covered cells under the patch first (`cells[n]` is node n's cell), then
    /// the seam nodes.
    pub nodes: usize,
    pub cells: Vec<usize>,
    /// Undirected arcs (a, b, capacity).
    pub edges: Vec<(u32, u32, f32)>,
    /// (node, capacity from A, capacity to B).
    pub terminals: Vec<(u32, f32, f32)>,
    /// The uncovered cells under the patch: they take B whatever the cut.
    pub uncovered: Vec<usize>,
    /// The two cells (s, t) an old seam runs between, per seam node (node `cells.len() + k`).
    pub seams: Vec<(usize, usize)>,
}

/// Where a placement's cells are: its footprint, and the index of a cell within the patch's box
/// (`None` outside it), so that nothing the size of the output is touched.
pub struct Footprint<'a, F: Fn(usize) -> Option<usize>> {
    pub cells: &'a [usize],
    pub local: F,
    /// The number of local indices (the box's size).
    pub box_len: usize,
}

impl SeamGraph {
    /// The graph for placing `patch` over `footprint`. `force_new` cells must take the patch
    /// (the centre of a covered error region, painted cells), `keep_old` covered cells must keep
    /// what they show (painted cells, fixed frames); `keep_old` wins.
    pub fn new<G: SeamGrid, F: Fn(usize) -> Option<usize>>(
        grid: &G,
        footprint: &Footprint<'_, F>,
        patch: G::Label,
        force_new: &[usize],
        keep_old: impl Fn(usize) -> bool,
    ) -> SeamGraph {
        let local = &footprint.local;
        let mut nodes = vec![u32::MAX; footprint.box_len];
        // Room for every cell and for an edge per cell and axis up front: growing the vectors
        // as edges come in copied them several times per placement.
        let cells = footprint.cells.len();
        let mut g = SeamGraph {
            cells: Vec::with_capacity(cells),
            edges: Vec::with_capacity(cells * G::AXES),
            ..SeamGraph::default()
        };
        for &i in footprint.cells {
            if grid.label_of(i).is_none() {
                g.uncovered.push(i);
            } else {
                nodes[local(i).expect("footprint cells lie in the patch's box")] =
                    g.cells.len() as u32;
                g.cells.push(i);
            }
        }
        g.nodes = g.cells.len();
        let node_of = |j: usize| local(j).map_or(u32::MAX, |k| nodes[k]);
        for (n, &i) in g.cells.iter().enumerate() {
            let border = (0..G::AXES).any(|axis| {
                [grid.next(i, axis), grid.prev(i, axis)]
                    .into_iter()
                    .flatten()
                    .any(|j| local(j).is_none() && grid.label_of(j).is_some())
            });
            if border || keep_old(i) {
                g.terminals.push((n as u32, HARD_CONSTRAINT, 0.0));
            }
        }
        for &i in force_new {
            let n = node_of(i);
            if n != u32::MAX && !keep_old(i) {
                g.terminals.push((n, 0.0, HARD_CONSTRAINT));
            }
        }
        // Each covered cell's own term of M, when M is made of such terms (empty otherwise).
        let mut terms: Vec<f32> = Vec::with_capacity(g.cells.len());
        for &i in &g.cells {
            match grid.label_of(i).and_then(|a| grid.cell_term(i, a, patch)) {
                Some(term) => terms.push(term),
                None => {
                    terms.clear();
                    break;
                }
            }
        }
        // A cell's term, for M between covered cells that show the same patch and between a
        // covered cell and an uncovered one (whose term is zero: see `seam_cost` in graphcut's
        // synthesis). The zero is added as `seam_cost` adds it, so the capacity has the same
        // bits (a -0.0 term becomes 0.0 either way).
        let by_terms = !terms.is_empty();
        let term = |i: usize| terms[node_of(i) as usize];
        // Every edge with a covered end inside the patch, seen once from its first cell s.
        for &s in footprint.cells {
            for axis in 0..G::AXES {
                let Some(t) = grid.next(s, axis).filter(|&t| local(t).is_some()) else {
                    continue;
                };
                match (grid.label_of(s), grid.label_of(t)) {
                    (None, None) => {}
                    (Some(a_s), Some(a_t)) if a_s != a_t => {
                        let seam = g.nodes as u32;
                        g.nodes += 1;
                        let to_s = grid.seam_cost(s, t, axis, a_s, patch);
                        let to_t = grid.seam_cost(s, t, axis, patch, a_t);
                        g.edges.push((node_of(s), seam, to_s));
                        g.edges.push((seam, node_of(t), to_t));
                        g.terminals.push((seam, 0.0, grid.old_seam(s, axis)));
                        g.seams.push((s, t));
                    }
                    (Some(a), Some(_)) => {
                        let cost = if by_terms {
                            term(s) + term(t)
                        } else {
                            grid.seam_cost(s, t, axis, a, patch)
                        };
                        g.edges.push((node_of(s), node_of(t), cost));
                    }
                    // The other cell is new and takes B: cut when the covered one keeps A.
                    // Only the covered cell's ||A - B|| counts: A does not reach the uncovered
                    // one (match_cost), whatever the empty output shows there.
                    (Some(a), None) => {
                        let cost = if by_terms {
                            term(s) + 0.0
                        } else {
                            grid.seam_cost(s, t, axis, a, patch)
                        };
                        g.terminals.push((node_of(s), 0.0, cost));
                    }
                    (None, Some(a)) => {
                        let cost = if by_terms {
                            0.0 + term(t)
                        } else {
                            grid.seam_cost(s, t, axis, patch, a)
                        };
                        g.terminals.push((node_of(t), 0.0, cost));
                    }
                }
            }
        }
        g
    }

    /// The solver's graph.
    pub fn build(&self) -> Result<Graph> {
        let mut graph = Graph::default();
        self.build_into(&mut graph)?;
        Ok(graph)
    }

    /// [`SeamGraph::build`] into a graph kept between placements (its memory is reused).
    pub fn build_into(&self, graph: &mut Graph) -> Result<()> {
        graph.reset(self.nodes)?;
        graph.reserve(self.edges.len());
        for &(a, b, c) in &self.edges {
            graph.add_edge(a as usize, b as usize, c, c)?;
        }
        for &(n, a, b) in &self.terminals {
            graph.add_terminal(n as usize, a, b)?;
        }
        Ok(())
    }

    /// Solves the cut on `graph` (reset first: a synthesis keeps one between placements, so its
    /// buffers are not allocated anew each time) and returns its cost and the cells that take
    /// the new patch (every uncovered one, and the covered ones on B's side).
    pub fn solve_with(&self, graph: &mut Graph) -> Result<(f64, Vec<usize>)> {
        self.build_into(graph)?;
        let cut_cost = graph.maxflow();
        let mut taken = self.uncovered.clone();
        taken.extend(
            self.cells
                .iter()
                .enumerate()
                .filter(|&(n, _)| !graph.is_source_side(n))
                .map(|(_, &i)| i),
        );
        Ok((cut_cost, taken))
    }
}
