//! The Boykov-Kolmogorov solver against two slow, obvious oracles: enumeration of every cut on
//! tiny graphs, and petgraph's Dinic max-flow on larger random graphs and grids. Every solve is
//! also checked for a feasible flow whose value equals the cost of the cut it reports.

use super::oracle::{Spec, check_solution, overlap_grid, random_graph, random_grid};
use super::{Graph, HARD_CONSTRAINT};
use crate::core::{Error, Rng};

#[test]
fn hand_made_graphs_have_the_expected_cuts() {
    // source -> 0 -> 1 -> sink with a bottleneck in the middle.
    let path = Spec {
        nodes: 2,
        edges: vec![(0, 1, 3.0, 7.0)],
        terminals: vec![(0, 5.0, 0.0), (1, 0.0, 4.0)],
    };
    let mut graph = path.build();
    assert_eq!(check_solution(&path, &mut graph), 3.0);
    assert!(graph.is_source_side(0) && !graph.is_source_side(1));

    // Flow through both terminal arcs of one node, and an isolated node.
    let direct = Spec {
        nodes: 2,
        edges: vec![],
        terminals: vec![(0, 2.5, 4.0)],
    };
    let mut graph = direct.build();
    assert_eq!(check_solution(&direct, &mut graph), 2.5);
    assert!(
        !graph.is_source_side(0),
        "the sink arc keeps residual capacity"
    );
    assert!(
        !graph.is_source_side(1),
        "unreached nodes count as sink side"
    );

    // No terminal arcs at all: nothing flows.
    let empty = Spec {
        nodes: 3,
        edges: vec![(0, 1, 1.0, 1.0), (1, 2, 1.0, 1.0)],
        terminals: vec![],
    };
    assert_eq!(check_solution(&empty, &mut empty.build()), 0.0);
    assert_eq!(Graph::new(0).unwrap().maxflow(), 0.0);
}

#[test]
fn matches_brute_force_min_cut_on_tiny_random_graphs() {
    let mut rng = Rng::new(1);
    for round in 0..400 {
        let nodes = 2 + rng.index(9);
        let edges = rng.index(3 * nodes);
        let spec = random_graph(&mut rng, nodes, edges);
        let flow = check_solution(&spec, &mut spec.build());
        assert_eq!(flow, spec.brute_force_min_cut(), "round {round}: {spec:?}");
    }
}

#[test]
fn matches_dinic_on_random_graphs() {
    let mut rng = Rng::new(2);
    for round in 0..300 {
        let nodes = 2 + rng.index(80);
        let edges = rng.index(5 * nodes);
        let spec = random_graph(&mut rng, nodes, edges);
        let flow = check_solution(&spec, &mut spec.build());
        assert_eq!(
            flow,
            spec.reference_flow() as f64,
            "round {round}: {spec:?}"
        );
    }
}

#[test]
fn matches_dinic_on_random_grids_with_seam_nodes() {
    let mut rng = Rng::new(3);
    for round in 0..200 {
        let (width, height) = (1 + rng.index(24), 1 + rng.index(24));
        let seams = rng.index(width * height / 4 + 1);
        let max = 1 + rng.below(20);
        let spec = random_grid(&mut rng, width, height, seams, max);
        let flow = check_solution(&spec, &mut spec.build());
        assert_eq!(flow, spec.reference_flow() as f64, "round {round}");
    }
}

#[test]
fn hard_constraints_keep_their_pixels_on_their_side() {
    let mut rng = Rng::new(4);
    for round in 0..60 {
        let (width, height) = (2 + rng.index(12), 1 + rng.index(30));
        let spec = overlap_grid(&mut rng, width, height, 10);
        let mut graph = spec.build();
        let flow = check_solution(&spec, &mut graph);
        assert_eq!(flow, spec.reference_flow() as f64, "round {round}");
        assert!(flow < f64::from(HARD_CONSTRAINT));
        for y in 0..height {
            assert!(graph.is_source_side(y * width), "left column keeps A");
            assert!(
                !graph.is_source_side(y * width + width - 1),
                "right column takes B"
            );
        }
    }
}

#[test]
fn contradicting_hard_constraints_show_in_the_flow() {
    // Pixel 1 is forced to both sides: no finite cut exists.
    let mut graph = Graph::new(3).unwrap();
    graph.add_edge(0, 1, 1.0, 1.0).unwrap();
    graph.add_edge(1, 2, f32::INFINITY, f32::INFINITY).unwrap();
    graph.add_terminal(0, f32::INFINITY, 0.0).unwrap();
    graph.add_terminal(1, HARD_CONSTRAINT, 0.0).unwrap();
    graph.add_terminal(2, 0.0, 3.0e30).unwrap();
    let flow = graph.maxflow();
    assert!(flow >= f64::from(HARD_CONSTRAINT), "{flow}");
    assert!(flow.is_finite());
}

#[test]
fn terminal_capacities_add_up() {
    let mut twice = Graph::new(2).unwrap();
    twice.add_edge(0, 1, 10.0, 10.0).unwrap();
    twice.add_terminal(0, 1.5, 0.0).unwrap();
    twice.add_terminal(0, 2.0, 0.5).unwrap();
    twice.add_terminal(1, 0.0, 9.0).unwrap();
    // Source 3.5 and sink 0.5 at node 0: 0.5 goes straight through, 3.0 on to node 1. That
    // saturates the source arc, so no node stays reachable from the source.
    assert_eq!(twice.maxflow(), 3.5);
    assert!(!twice.is_source_side(0) && !twice.is_source_side(1));
    // Once more source capacity than the sink can take: node 0 stays on the source side.
    twice.add_terminal(0, 7.0, 0.0).unwrap();
    assert_eq!(twice.maxflow(), 9.5);
    assert!(twice.is_source_side(0) && twice.is_source_side(1));
}

#[test]
fn float_capacities_match_dinic_closely() {
    let mut rng = Rng::new(5);
    for _ in 0..100 {
        let (width, height) = (2 + rng.index(20), 2 + rng.index(20));
        let mut spec = random_grid(&mut rng, width, height, width, 1);
        for edge in &mut spec.edges {
            edge.2 = rng.next_f32() * 3.0;
            edge.3 = rng.next_f32() * 3.0;
        }
        for terminal in &mut spec.terminals {
            terminal.1 = if terminal.1 > 0.0 {
                rng.next_f32() * 5.0
            } else {
                0.0
            };
            terminal.2 = if terminal.2 > 0.0 {
                rng.next_f32() * 5.0
            } else {
                0.0
            };
        }
        let flow = check_solution(&spec, &mut spec.build());
        let reference = spec.reference_flow_f64();
        assert!(
            (flow - reference).abs() < 1e-4 * (1.0 + reference),
            "{flow} vs {reference}"
        );
    }
}

#[test]
fn bad_input_is_a_named_error_and_changes_nothing() {
    let mut graph = Graph::new(2).unwrap();
    let message = |e: Error| e.to_string();
    assert!(message(graph.add_edge(0, 1, f32::NAN, 1.0).unwrap_err()).contains("NaN"));
    assert!(message(graph.add_edge(0, 1, 1.0, -2.0).unwrap_err()).contains("-2"));
    assert!(message(graph.add_edge(0, 2, 1.0, 1.0).unwrap_err()).contains("node 2"));
    assert!(message(graph.add_edge(1, 1, 1.0, 1.0).unwrap_err()).contains("two different"));
    assert!(matches!(
        graph.add_terminal(0, -0.5, 0.0),
        Err(Error::InvalidParameter {
            name: "max-flow source capacity",
            ..
        })
    ));
    assert!(graph.add_terminal(0, 1.0, f32::NAN).is_err());
    assert!(graph.add_terminal(5, 1.0, 1.0).is_err());
    assert_eq!(graph.edge_count(), 0);
    assert_eq!(graph.maxflow(), 0.0, "failed calls added nothing");
    // -0.0 is a valid zero.
    graph.add_terminal(0, -0.0, -0.0).unwrap();
    assert!(Graph::new(usize::MAX).is_err());
}

#[test]
fn changes_after_a_solve_are_solved_again_and_reset_reuses_the_graph() {
    let mut rng = Rng::new(6);
    let spec = random_grid(&mut rng, 12, 9, 10, 8);
    let mut graph = spec.build();
    let first = graph.maxflow();
    assert_eq!(graph.maxflow(), first, "solving twice gives the same flow");
    let node = graph.add_node();
    graph.add_edge(0, node, 4.0, 4.0).unwrap();
    graph.add_terminal(node, 0.0, 4.0).unwrap();
    let mut extended = spec.clone();
    extended.nodes += 1;
    extended.edges.push((0, node, 4.0, 4.0));
    extended.terminals.push((node, 0.0, 4.0));
    assert_eq!(
        check_solution(&extended, &mut graph),
        extended.reference_flow() as f64
    );

    let other = random_graph(&mut rng, 30, 90);
    graph.reset(other.nodes).unwrap();
    for &(a, b, ab, ba) in &other.edges {
        graph.add_edge(a, b, ab, ba).unwrap();
    }
    for &(n, s, t) in &other.terminals {
        graph.add_terminal(n, s, t).unwrap();
    }
    assert_eq!(
        check_solution(&other, &mut graph),
        other.reference_flow() as f64
    );
}

#[test]
fn a_256_by_256_grid_solves_correctly() {
    let mut rng = Rng::new(7);
    let spec = random_grid(&mut rng, 256, 256, 2000, 50);
    let started = std::time::Instant::now();
    let mut graph = spec.build();
    let flow = graph.maxflow();
    let elapsed = started.elapsed();
    check_solution(&spec, &mut graph);
    assert!(flow > 0.0);
    // Generous even for the unoptimised test profile; in release it takes a few milliseconds.
    assert!(elapsed.as_secs_f64() < 5.0, "{elapsed:?}");
}
