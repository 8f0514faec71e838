//! The public face of the max-flow solver: build a graph, solve, read the cut.

use super::residual::{Edge, MAX_ARCS, Residual};
use crate::core::{Error, Result};

/// A node of the graph: nodes are numbered `0..node_count()` in the order they were made, so a
/// `width` x `height` pixel grid can use `y * width + x` directly.
pub type NodeId = usize;

/// The largest number of nodes a graph may have (node indices are stored in 32 bits).
pub const MAX_NODES: usize = (u32::MAX - 3) as usize;

/// The capacity that stands for "infinite" in the paper's *constraint arcs* (a pixel that must come
/// from the old or the new patch). Capacities above it, `f32::INFINITY` included, are stored as
/// this value.
///
/// It is finite so that flow arithmetic never makes `inf - inf = NaN`, and large enough that no
/// cut through finite arcs can cost as much: `f32` keeps 7 digits, so subtracting any flow below
/// `1e12` from it leaves it unchanged, exactly like infinity. Keep the finite capacities of one
/// graph summing to far less than `1e12` (seam costs are a few units per pixel pair). A max-flow of
/// `HARD_CONSTRAINT` or more means the hard constraints contradict each other: some path runs from
/// a pixel forced to one side to a pixel forced to the other through hard arcs only.
pub const HARD_CONSTRAINT: f32 = 1.0e20;

/// A directed graph with a source and a sink terminal, solved for its minimum cut by the
/// Boykov-Kolmogorov algorithm.
///
/// The source stands for the old patches `A` and the sink for the new patch `B` in the paper's
/// figures, but nothing here depends on that reading.
#[derive(Debug, Default)]
pub struct Graph {
    pub(super) edges: Vec<Edge>,
    /// `[source, sink]` capacity of each node's terminal arcs.
    pub(super) terminals: Vec<[f32; 2]>,
    pub(super) residual: Residual,
    /// The flow of the last solve, `None` if the graph changed since.
    solved: Option<f64>,
}

impl Graph {
    /// A graph with `node_count` nodes and no arcs.
    pub fn new(node_count: usize) -> Result<Self> {
        Self::with_capacity(node_count, 0)
    }

    /// Like [`Graph::new`], with room reserved for `edge_count` calls of [`Graph::add_edge`]
    /// (a `w` x `h` grid has `(w - 1) * h + w * (h - 1)` edges).
    pub fn with_capacity(node_count: usize, edge_count: usize) -> Result<Self> {
        let mut graph = Graph::default();
        graph.reset(node_count)?;
        graph.edges.reserve(edge_count);
        Ok(graph)
    }

    /// Empties the graph and gives it `node_count` nodes, keeping the memory of earlier graphs:
    /// a synthesis solves one graph per patch placement, and reusing the buffers avoids
    /// reallocating them every time.
    pub fn reset(&mut self, node_count: usize) -> Result<()> {
        if node_count > MAX_NODES {
            return Err(Error::InvalidParameter {
                name: "max-flow node count",
                reason: format!("{node_count} nodes is more than the {MAX_NODES} supported"),
            });
        }
        self.edges.clear();
        self.terminals.clear();
        self.terminals.resize(node_count, [0.0, 0.0]);
        self.solved = None;
        Ok(())
    }

    /// Reserves room for `additional` more calls of [`Graph::add_edge`].
    pub fn reserve(&mut self, additional: usize) {
        self.edges.reserve(additional);
    }

    #[must_use]
    pub fn node_count(&self) -> usize {
        self.terminals.len()
    }

    /// The number of edges added (each edge is a pair of opposite arcs).
    #[must_use]
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// Adds a node with no arcs (for example a seam node of section 3.1) and returns it.
    ///
    /// # Panics
    /// If the graph already has [`MAX_NODES`] nodes, far more than memory can hold.
    pub fn add_node(&mut self) -> NodeId {
        assert!(
            self.terminals.len() < MAX_NODES,
            "max-flow graph is full: {MAX_NODES} nodes"
        );
        self.terminals.push([0.0, 0.0]);
        self.solved = None;
        self.terminals.len() - 1
    }

    /// Adds an edge between two different nodes: capacity `cap_ab` from `a` to `b` and `cap_ba`
    /// from `b` to `a` (equal for the symmetric matching cost `M` of the paper). Several edges
    /// between the same nodes add up.
    ///
    /// Fails, leaving the graph unchanged, on an unknown node, `a == b`, or a capacity that is
    /// NaN or negative. Capacities above [`HARD_CONSTRAINT`] (and infinity) are stored as it.
    pub fn add_edge(&mut self, a: NodeId, b: NodeId, cap_ab: f32, cap_ba: f32) -> Result<()> {
        self.check_node(a)?;
        self.check_node(b)?;
        if a == b {
            return Err(Error::InvalidParameter {
                name: "max-flow edge",
                reason: format!("an edge joins two different nodes, got {a} -> {b}"),
            });
        }
        let cap_ab = capacity("max-flow edge capacity", cap_ab)?;
        let cap_ba = capacity("max-flow edge capacity", cap_ba)?;
        if (self.edges.len() + 1) * 2 > MAX_ARCS {
            return Err(Error::InvalidParameter {
                name: "max-flow edge count",
                reason: format!("more than {} edges are not supported", MAX_ARCS / 2),
            });
        }
        self.edges.push(Edge {
            a: a as u32,
            b: b as u32,
            cap_ab,
            cap_ba,
        });
        self.solved = None;
        Ok(())
    }

    /// Adds `cap_source` to the capacity of the arc source -> `node` and `cap_sink` to that of
    /// `node` -> sink. A [`HARD_CONSTRAINT`] (or infinite) capacity forces the node to that
    /// terminal's side, like the paper's constraint arcs.
    ///
    /// Fails, leaving the graph unchanged, on an unknown node or a capacity that is NaN or
    /// negative. Sums above [`HARD_CONSTRAINT`] are stored as it.
    pub fn add_terminal(&mut self, node: NodeId, cap_source: f32, cap_sink: f32) -> Result<()> {
        self.check_node(node)?;
        let cap_source = capacity("max-flow source capacity", cap_source)?;
        let cap_sink = capacity("max-flow sink capacity", cap_sink)?;
        let [source, sink] = &mut self.terminals[node];
        *source = (*source + cap_source).min(HARD_CONSTRAINT);
        *sink = (*sink + cap_sink).min(HARD_CONSTRAINT);
        self.solved = None;
        Ok(())
    }

    /// Computes the maximum flow from the source to the sink, which equals the cost of the
    /// minimum cut. Solving again without changes returns the same value without work; after a
    /// change the graph is solved from scratch.
    pub fn maxflow(&mut self) -> f64 {
        if let Some(flow) = self.solved {
            return flow;
        }
        let direct = self.residual.build(&self.edges, &self.terminals);
        let flow = direct + self.residual.solve();
        self.solved = Some(flow);
        flow
    }

    /// Whether `node` is on the source side of the minimum cut found by the last
    /// [`Graph::maxflow`]. The source side is the smallest one: the nodes still reachable from the
    /// source through unsaturated arcs. Nodes that neither terminal reaches count as sink side
    /// (either side gives a cut of the same cost).
    ///
    /// # Panics
    /// If `node` does not exist. In debug builds also if the graph changed since the last solve.
    #[must_use]
    pub fn is_source_side(&self, node: NodeId) -> bool {
        assert!(
            node < self.node_count(),
            "max-flow node {node} does not exist; the graph has {} nodes",
            self.node_count()
        );
        debug_assert!(
            self.solved.is_some(),
            "is_source_side called before maxflow (or after changing the graph)"
        );
        self.solved.is_some() && self.residual.in_source_tree(node)
    }

    fn check_node(&self, node: NodeId) -> Result<()> {
        if node < self.node_count() {
            Ok(())
        } else {
            Err(Error::InvalidParameter {
                name: "max-flow node",
                reason: format!(
                    "node {node} does not exist; the graph has {} nodes",
                    self.node_count()
                ),
            })
        }
    }
}

/// Checks one capacity: NaN and negative values are refused (a negative arc has no meaning as a
/// seam cost and would break the algorithm); large values become [`HARD_CONSTRAINT`].
fn capacity(name: &'static str, value: f32) -> Result<f32> {
    if value.is_nan() || value < 0.0 {
        return Err(Error::InvalidParameter {
            name,
            reason: format!("must be a non-negative number, got {value}"),
        });
    }
    // `+ 0.0` turns -0.0 into 0.0, so that a zero terminal capacity never looks negative.
    Ok(value.min(HARD_CONSTRAINT) + 0.0)
}
