//! The residual network the Boykov-Kolmogorov search runs on, in flat arrays.
//!
//! Every edge `{a, b}` becomes two *sister* arcs `a -> b` and `b -> a`; pushing flow along one
//! lowers its residual capacity and raises its sister's by the same amount, so the pair needs no
//! separate flow value. The arcs leaving a node are contiguous (compressed adjacency: node `i`
//! owns `arcs[first_arc[i]..first_arc[i + 1]]`), so a growth step reads one short run of memory.
//! Each node also keeps its tree state: the two search trees are stored as a parent arc per node.

use std::collections::VecDeque;

/// `parent` of a node in neither search tree (a *free* node).
pub(super) const NO_PARENT: u32 = u32::MAX;
/// `parent` of a tree root: a node joined to its terminal directly by a terminal arc.
pub(super) const TERMINAL: u32 = u32::MAX - 1;
/// `parent` of an *orphan*: a tree node whose parent arc was just saturated.
pub(super) const ORPHAN: u32 = u32::MAX - 2;
/// Arc indices must stay below the three markers above.
pub(super) const MAX_ARCS: usize = (u32::MAX - 3) as usize;

/// One edge as the caller added it, before the arcs are laid out per node.
#[derive(Debug, Clone, Copy)]
pub(super) struct Edge {
    pub a: u32,
    pub b: u32,
    pub cap_ab: f32,
    pub cap_ba: f32,
}

/// A directed arc of the residual network.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Arc {
    /// The node the arc points to. Its tail is `arcs[sister].head`.
    pub head: u32,
    /// The reverse arc of the same edge.
    pub sister: u32,
    /// How much more flow the arc can carry.
    pub residual: f32,
}

/// A node's terminal capacity and its place in the search trees.
#[derive(Debug, Clone, Copy)]
pub(super) struct NodeState {
    /// Residual terminal capacity: positive means residual capacity from the source into the
    /// node, negative means from the node to the sink. (Flow through both terminal arcs of one
    /// node is pushed at the start, so at most one of the two is left.)
    pub terminal: f32,
    /// The arc between this node and its parent in its tree, in the direction flow takes along
    /// it (parent -> node in the source tree, node -> parent in the sink tree), so that an
    /// augmentation reads and pushes it without looking up its sister; or one of the markers
    /// above.
    pub parent: u32,
    /// The parent node itself (the head of `parent`), valid while `parent` is an arc. The walks
    /// to the root follow it, so each step waits on one load instead of two (node, then arc):
    /// augmentations walk paths of about 80 nodes, thousands of times per seam graph.
    pub parent_node: u32,
    /// The value of the solver's clock when `distance` was last known to be exact.
    pub timestamp: u32,
    /// Number of arcs from this node to its terminal along parent arcs (roots have 1).
    pub distance: u32,
    /// Which tree the node belongs to when `parent` is not [`NO_PARENT`].
    pub in_sink_tree: bool,
    /// Whether the node sits in the queue of active nodes (or is the node being grown).
    pub queued: bool,
}

/// The residual network plus the solver's working queues, all reused between solves.
#[derive(Debug, Default)]
pub(super) struct Residual {
    /// `first_arc[i]..first_arc[i + 1]` are the arcs leaving node `i`; length `nodes + 1`.
    pub first_arc: Vec<u32>,
    pub arcs: Vec<Arc>,
    pub nodes: Vec<NodeState>,
    /// Active nodes: tree nodes at the tree boundary that may still grow (first in, first out).
    pub active: VecDeque<u32>,
    /// Orphans waiting for a new parent after an augmentation.
    pub orphans: VecDeque<u32>,
    /// The solver's clock: one tick per growth step, used to trust recently checked distances.
    pub time: u32,
    /// Scratch for laying out the arcs: the next free slot of each node.
    cursor: Vec<u32>,
    /// Scratch for an augmentation: the (node, parent arc) pairs of its path.
    pub path: Vec<(u32, u32)>,
}

impl Residual {
    /// Lays out the residual network for `edges` and the terminal capacities `[source, sink]` of
    /// each node, and pushes the flow that goes straight from the source through a node to the
    /// sink. Returns that flow. Reuses the memory of the previous solve.
    pub fn build(&mut self, edges: &[Edge], terminals: &[[f32; 2]]) -> f64 {
        let node_count = terminals.len();
        // Counting sort of the arcs by tail: count, prefix sum, then place.
        self.first_arc.clear();
        self.first_arc.resize(node_count + 1, 0);
        for edge in edges {
            self.first_arc[edge.a as usize + 1] += 1;
            self.first_arc[edge.b as usize + 1] += 1;
        }
        for i in 0..node_count {
            self.first_arc[i + 1] += self.first_arc[i];
        }
        self.cursor.clear();
        self.cursor.extend_from_slice(&self.first_arc[..node_count]);
        self.arcs.clear();
        self.arcs.resize(edges.len() * 2, Arc::default());
        for edge in edges {
            let ab = self.cursor[edge.a as usize];
            let ba = self.cursor[edge.b as usize];
            self.cursor[edge.a as usize] += 1;
            self.cursor[edge.b as usize] += 1;
            self.arcs[ab as usize] = Arc {
                head: edge.b,
                sister: ba,
                residual: edge.cap_ab,
            };
            self.arcs[ba as usize] = Arc {
                head: edge.a,
                sister: ab,
                residual: edge.cap_ba,
            };
        }

        self.nodes.clear();
        self.active.clear();
        self.orphans.clear();
        self.time = 0;
        let mut flow = 0.0f64;
        for (i, &[source, sink]) in terminals.iter().enumerate() {
            flow += f64::from(source.min(sink));
            let terminal = source - sink;
            let rooted = terminal != 0.0;
            self.nodes.push(NodeState {
                terminal,
                parent: if rooted { TERMINAL } else { NO_PARENT },
                parent_node: 0,
                timestamp: 0,
                distance: 1,
                in_sink_tree: terminal < 0.0,
                queued: rooted,
            });
            if rooted {
                self.active.push_back(i as u32);
            }
        }
        flow
    }

    /// The arcs leaving `node`, as a range of indices into `arcs`.
    #[inline]
    pub fn arcs_of(&self, node: u32) -> std::ops::Range<usize> {
        self.first_arc[node as usize] as usize..self.first_arc[node as usize + 1] as usize
    }

    /// Whether `node` ended in the source tree, i.e. is reachable from the source in the residual
    /// network after the solve.
    #[inline]
    pub fn in_source_tree(&self, node: usize) -> bool {
        let state = &self.nodes[node];
        state.parent != NO_PARENT && !state.in_sink_tree
    }
}
