//! A measurement, not a check: how long the solver takes on graphs of the sizes graph-cut textures
//! builds, next to the reference Dinic. Run it with
//! `cargo test --release --lib -- --ignored --nocapture maxflow_timing`.

use std::time::{Duration, Instant};

use super::HARD_CONSTRAINT;
use super::oracle::{Spec, overlap_grid, random_grid};
use crate::core::Rng;

/// The fastest of a few runs of `run`, to keep the measurement away from scheduling noise (the
/// machines are shared).
fn fastest<T>(runs: usize, mut run: impl FnMut() -> T) -> (Duration, T) {
    let mut best = Duration::MAX;
    let mut value = None;
    for _ in 0..runs {
        let started = Instant::now();
        let result = run();
        best = best.min(started.elapsed());
        value = Some(result);
    }
    (best, value.expect("at least one run"))
}

fn milliseconds(duration: Duration) -> f64 {
    duration.as_secs_f64() * 1e3
}

/// Times the solver on `spec`, and the reference too when `with_reference` (it takes minutes on
/// the largest graphs).
fn report(name: &str, spec: &Spec, with_reference: bool) {
    let (build_and_solve, flow) = fastest(5, || spec.build().maxflow());
    let solve_only = (0..5)
        .map(|_| {
            let mut graph = spec.build();
            let started = Instant::now();
            graph.maxflow();
            started.elapsed()
        })
        .min()
        .expect("five runs");
    print!(
        "{name}: {} nodes, {} edges: Boykov-Kolmogorov {:.1} ms (build + solve {:.1} ms)",
        spec.nodes,
        spec.edges.len(),
        milliseconds(solve_only),
        milliseconds(build_and_solve),
    );
    if with_reference {
        let (reference_time, reference) = fastest(1, || spec.reference_flow());
        println!(
            ", reference Dinic {:.1} ms; flow {flow} = {reference}",
            milliseconds(reference_time)
        );
        assert_eq!(
            flow, reference as f64,
            "{name}: flow differs from the reference"
        );
    } else {
        println!("; flow {flow}");
    }
}

/// A patch placed over output that is already filled (section 3.2): the border of the region
/// must keep the old pixels, the centre pixel must take the new patch, old seams everywhere.
fn surrounded_region(rng: &mut Rng, side: usize) -> Spec {
    let mut spec = random_grid(rng, side, side, side * side / 16, 100);
    spec.terminals.retain(|&(node, _, _)| node >= side * side); // keep the seam nodes' arcs
    for i in 0..side {
        for node in [i, (side - 1) * side + i, i * side, i * side + side - 1] {
            spec.terminals.push((node, HARD_CONSTRAINT, 0.0));
        }
    }
    spec.terminals
        .push((side / 2 * side + side / 2, 0.0, HARD_CONSTRAINT));
    spec
}

#[test]
#[ignore = "a timing report; run with --release --ignored --nocapture"]
fn maxflow_timing() {
    let mut rng = Rng::new(2003);
    // An overlap band between an old and a new patch, constrained on its two long sides.
    report(
        "64x256 overlap grid",
        &overlap_grid(&mut rng, 64, 256, 100),
        true,
    );
    report(
        "256x256 surrounded region",
        &surrounded_region(&mut rng, 256),
        true,
    );
    // Random terminal arcs everywhere: many short paths, the hard case for the reference, which
    // needs over two minutes at 256x256.
    report(
        "128x128 grid, random terminals",
        &random_grid(&mut rng, 128, 128, 1000, 100),
        true,
    );
    report(
        "256x256 grid, random terminals",
        &random_grid(&mut rng, 256, 256, 4000, 100),
        false,
    );
}
