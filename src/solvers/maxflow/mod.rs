//! Max-flow / min-cut for the seam graphs of graph-cut textures (Kwatra et al. 2003, section 3).
//!
//! A patch placement builds one graph: a node per pixel of the overlap region, 4-connected arcs
//! weighted by the matching cost `M(s, t, A, B)`, a few extra *seam nodes* where old seams are
//! remembered (section 3.1), and terminal arcs to the old patches `A` (the source) and the new
//! patch `B` (the sink). The minimum cut tells which pixels keep the old texture and which copy the
//! new patch.
//!
//! The paper computed its cuts with Boykov et al.'s code (section 3.1); the solver here is those
//! authors' augmenting-path algorithm (Boykov and Kolmogorov, "An experimental comparison of
//! min-cut/max-flow algorithms for energy minimization in vision", PAMI 2004). It grows two
//! search trees, one from each terminal, and *reuses* them after every augmentation instead of
//! searching from scratch: on grid graphs with short seams this is much faster than Dinic or
//! push-relabel in practice.
//!
//! The pieces, one per file:
//!
//! - `graph`: the public builder ([`Graph`]), input checks and the [`HARD_CONSTRAINT`] value;
//! - `residual`: the residual network in flat arrays (compressed adjacency, paired arcs);
//! - `boykov_kolmogorov`: growth, augmentation and adoption on the residual network;
//! - `oracle`, `tests`, `timing` (tests only): reference max-flows, checks and measurements.
//!
//! Capacities are `f32` and the flow total is `f64`. Seam costs are sums of a few colour
//! differences, so seven significant digits per arc are plenty, and `f32` shrinks the memory the
//! search walks through (12 bytes per arc instead of 16); the total is a sum of up to millions
//! of bottlenecks, where `f32` would lose the small ones against a large running sum.
//!
//! ```
//! use texsynth::solvers::maxflow::{Graph, HARD_CONSTRAINT};
//! // Pixels 0 - 1 - 2 in a row; 0 must keep the old patch A, 2 must take the new patch B.
//! let mut graph = Graph::new(3).unwrap();
//! graph.add_edge(0, 1, 5.0, 5.0).unwrap();
//! graph.add_edge(1, 2, 2.0, 2.0).unwrap();
//! graph.add_terminal(0, HARD_CONSTRAINT, 0.0).unwrap();
//! graph.add_terminal(2, 0.0, HARD_CONSTRAINT).unwrap();
//! assert_eq!(graph.maxflow(), 2.0); // the seam goes between pixels 1 and 2
//! assert!(graph.is_source_side(1));
//! assert!(!graph.is_source_side(2));
//! ```

mod boykov_kolmogorov;
mod graph;
mod residual;

#[cfg(test)]
pub(crate) mod oracle;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod timing;

pub use graph::{Graph, HARD_CONSTRAINT, MAX_NODES, NodeId};
