//! Test-only: the slow, obvious oracles the solver is checked against (enumeration of every cut,
//! petgraph's Dinic), a check that a solve left a feasible flow equal to its cut, and generators
//! of random graphs shaped like the ones graph-cut textures builds.

use petgraph::algo::dinics;

use super::{Graph, HARD_CONSTRAINT};
use crate::core::Rng;

/// A graph description the oracles and the solver can both be built from.
#[derive(Debug, Clone, Default)]
pub(crate) struct Spec {
    pub nodes: usize,
    pub edges: Vec<(usize, usize, f32, f32)>,
    /// `(node, source capacity, sink capacity)`, added in order (a node may appear twice).
    pub terminals: Vec<(usize, f32, f32)>,
}

impl Spec {
    pub fn build(&self) -> Graph {
        let mut graph = Graph::with_capacity(self.nodes, self.edges.len()).unwrap();
        for &(a, b, ab, ba) in &self.edges {
            graph.add_edge(a, b, ab, ba).unwrap();
        }
        for &(node, source, sink) in &self.terminals {
            graph.add_terminal(node, source, sink).unwrap();
        }
        graph
    }

    /// Cost of the cut that puts the nodes with `source_side[i]` on the source side.
    fn cut_cost(&self, source_side: &[bool]) -> f64 {
        let mut cost = 0.0;
        for &(a, b, ab, ba) in &self.edges {
            if source_side[a] && !source_side[b] {
                cost += f64::from(ab);
            }
            if source_side[b] && !source_side[a] {
                cost += f64::from(ba);
            }
        }
        for &(node, source, sink) in &self.terminals {
            cost += f64::from(if source_side[node] { sink } else { source });
        }
        cost
    }

    /// Exact minimum cut by trying every split of the nodes.
    pub fn brute_force_min_cut(&self) -> f64 {
        assert!(self.nodes <= 16);
        (0u32..1 << self.nodes)
            .map(|mask| {
                let side: Vec<bool> = (0..self.nodes).map(|i| mask >> i & 1 == 1).collect();
                self.cut_cost(&side)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Max-flow by petgraph's Dinic, capacities in `u64` so that the answer is exact. Hard
    /// capacities become a number larger than every finite capacity together, which is what a
    /// hard constraint means. All capacities must be whole numbers.
    pub fn reference_flow(&self) -> u64 {
        let finite: f64 = self
            .edges
            .iter()
            .map(|e| f64::from(e.2) + f64::from(e.3))
            .chain(
                self.terminals
                    .iter()
                    .map(|t| f64::from(t.1) + f64::from(t.2)),
            )
            .filter(|&c| c < f64::from(HARD_CONSTRAINT))
            .sum();
        let hard = finite as u64 + 1;
        let whole = |c: f32| -> u64 {
            if c >= HARD_CONSTRAINT {
                return hard;
            }
            assert_eq!(c.fract(), 0.0, "reference capacities must be whole numbers");
            c as u64
        };
        let mut network = petgraph::Graph::<(), u64>::new();
        let nodes: Vec<_> = (0..self.nodes).map(|_| network.add_node(())).collect();
        let source = network.add_node(());
        let sink = network.add_node(());
        for &(a, b, ab, ba) in &self.edges {
            network.add_edge(nodes[a], nodes[b], whole(ab));
            network.add_edge(nodes[b], nodes[a], whole(ba));
        }
        for &(node, s, t) in &self.terminals {
            network.add_edge(source, nodes[node], whole(s));
            network.add_edge(nodes[node], sink, whole(t));
        }
        dinics(&network, source, sink).0
    }

    /// Max-flow by petgraph's Dinic in `f64`, for capacities that are not whole numbers.
    pub fn reference_flow_f64(&self) -> f64 {
        let mut network = petgraph::Graph::<(), f64>::new();
        let nodes: Vec<_> = (0..self.nodes).map(|_| network.add_node(())).collect();
        let (source, sink) = (network.add_node(()), network.add_node(()));
        for &(a, b, ab, ba) in &self.edges {
            network.add_edge(nodes[a], nodes[b], f64::from(ab));
            network.add_edge(nodes[b], nodes[a], f64::from(ba));
        }
        for &(node, s, t) in &self.terminals {
            network.add_edge(source, nodes[node], f64::from(s));
            network.add_edge(nodes[node], sink, f64::from(t));
        }
        dinics(&network, source, sink).0
    }
}

/// Checks everything that must hold after a solve: the residual arcs describe a feasible flow
/// (capacities respected, conservation at every node) whose value is the one reported, and the
/// reported cut costs exactly that value. Returns the flow.
pub(super) fn check_solution(spec: &Spec, graph: &mut Graph) -> f64 {
    let flow = graph.maxflow();
    let tolerance = 1e-4 * (1.0 + flow.abs());
    let side: Vec<bool> = (0..spec.nodes).map(|i| graph.is_source_side(i)).collect();
    let cut = spec.cut_cost(&side);
    assert!(
        (cut - flow).abs() <= tolerance,
        "cut {cut} differs from flow {flow}"
    );

    // Find each edge's arcs the way `Residual::build` placed them.
    let residual = &graph.residual;
    let mut cursor = residual.first_arc.clone();
    let mut net_out = vec![0.0f64; spec.nodes];
    for edge in &graph.edges {
        let (a, b) = (edge.a as usize, edge.b as usize);
        let (ab, ba) = (cursor[a] as usize, cursor[b] as usize);
        cursor[a] += 1;
        cursor[b] += 1;
        let (r_ab, r_ba) = (residual.arcs[ab].residual, residual.arcs[ba].residual);
        assert!(r_ab >= 0.0 && r_ba >= 0.0, "negative residual");
        let sent = f64::from(edge.cap_ab) - f64::from(r_ab);
        let returned = f64::from(r_ba) - f64::from(edge.cap_ba);
        let scale = 1.0 + f64::from(edge.cap_ab.max(edge.cap_ba));
        assert!(
            (sent - returned).abs() <= 1e-5 * scale,
            "sister arcs disagree"
        );
        net_out[a] += sent;
        net_out[b] -= sent;
    }
    let mut out_of_source = 0.0;
    let mut any_hard = false;
    for (i, &[source, sink]) in graph.terminals.iter().enumerate() {
        let terminal = residual.nodes[i].terminal;
        assert!(
            terminal <= source && -terminal <= sink,
            "terminal residual {terminal} outside [-{sink}, {source}]"
        );
        let from_source = f64::from(source) - f64::from(terminal.max(0.0));
        let to_sink = f64::from(sink) - f64::from((-terminal).max(0.0));
        out_of_source += from_source;
        // A hard terminal arc behaves as infinite: finite flow does not lower it, so the flow
        // through it cannot be read back from the residual.
        if source.max(sink) >= HARD_CONSTRAINT {
            any_hard = true;
        } else {
            assert!(
                (from_source - to_sink - net_out[i]).abs() <= 1e-4 * (1.0 + from_source.abs()),
                "flow is not conserved at node {i}"
            );
        }
        // A node with residual capacity from the source is reachable from it; one with residual
        // capacity to the sink reaches the sink.
        if terminal > 0.0 {
            assert!(
                side[i],
                "node {i} has residual source capacity but is on the sink side"
            );
        }
        if terminal < 0.0 {
            assert!(
                !side[i],
                "node {i} has residual sink capacity but is on the source side"
            );
        }
    }
    if !any_hard {
        assert!((out_of_source - flow).abs() <= tolerance, "flow value");
    }
    flow
}

fn whole(rng: &mut Rng, max: u32) -> f32 {
    rng.below(max + 1) as f32
}

/// A random graph with whole-number capacities, some of them zero, and random terminal arcs.
pub(super) fn random_graph(rng: &mut Rng, nodes: usize, edges: usize) -> Spec {
    let mut spec = Spec {
        nodes,
        ..Spec::default()
    };
    for _ in 0..edges {
        let a = rng.index(nodes);
        let b = (a + 1 + rng.index(nodes - 1)) % nodes;
        spec.edges.push((a, b, whole(rng, 9), whole(rng, 9)));
    }
    for node in 0..nodes {
        match rng.below(4) {
            0 => spec.terminals.push((node, whole(rng, 12), 0.0)),
            1 => spec.terminals.push((node, 0.0, whole(rng, 12))),
            2 => spec.terminals.push((node, whole(rng, 12), whole(rng, 12))),
            _ => {}
        }
    }
    spec
}

/// A `width` x `height` 4-connected grid with `seams` seam nodes of section 3.1 standing between
/// random neighbouring pixel pairs (a seam node replaces the pair's direct edge and has an arc to
/// the sink `B` carrying the old seam cost). Capacities are whole numbers below `max`.
pub(super) fn random_grid(
    rng: &mut Rng,
    width: usize,
    height: usize,
    seams: usize,
    max: u32,
) -> Spec {
    let mut spec = Spec {
        nodes: width * height,
        ..Spec::default()
    };
    let mut pairs = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let p = y * width + x;
            if x + 1 < width {
                pairs.push((p, p + 1));
            }
            if y + 1 < height {
                pairs.push((p, p + width));
            }
        }
    }
    for (k, &(p, q)) in pairs.iter().enumerate() {
        if k % (pairs.len() / seams.max(1)).max(1) == 0 && spec.nodes - width * height < seams {
            let seam = spec.nodes;
            spec.nodes += 1;
            spec.edges.push((p, seam, whole(rng, max), whole(rng, max)));
            spec.edges.push((seam, q, whole(rng, max), whole(rng, max)));
            spec.terminals.push((seam, 0.0, whole(rng, max)));
        } else {
            let cost = whole(rng, max);
            spec.edges.push((p, q, cost, cost));
        }
    }
    for p in 0..width * height {
        match rng.below(5) {
            0 => spec.terminals.push((p, whole(rng, max), 0.0)),
            1 => spec.terminals.push((p, 0.0, whole(rng, max))),
            _ => {}
        }
    }
    spec
}

/// An overlap region as in image quilting: the left column must keep the old patch (source),
/// the right column must take the new one (sink), seam costs in between.
pub(super) fn overlap_grid(rng: &mut Rng, width: usize, height: usize, max: u32) -> Spec {
    let mut spec = random_grid(rng, width, height, 0, max);
    spec.terminals.clear();
    for y in 0..height {
        spec.terminals.push((y * width, HARD_CONSTRAINT, 0.0));
        spec.terminals
            .push((y * width + width - 1, 0.0, f32::INFINITY));
    }
    spec
}
