//! Tests of the coarsest level's start (see [`super::initial`]): the graph-cut start against
//! random patches, its memory, and the canvas shown while it runs.

use super::tests::run;
use super::{EventKind, Options, Session};
use crate::core::testing::sample;

/// The graph-cut start keeps a regular texture's lattice whole (random patches start it at a
/// phase per patch, and EM does not realign runs): squares_64 and tiles_64 at 128x128, seeds
/// 1-3. Measured: coherence 0.35-0.5x the random-patch start's (0.24-0.46x at 256x256 in the
/// comparison).
#[test]
fn the_graph_cut_start_keeps_a_lattice_that_random_patches_break() {
    use crate::methods::quality::quality;
    for name in ["squares_64", "tiles_64"] {
        let exemplar = sample(name);
        let coherence = |start: super::Start| {
            (1..=3)
                .map(|seed| {
                    let options = Options {
                        output_width: 128,
                        output_height: 128,
                        seed,
                        start,
                        ..Options::default()
                    };
                    let (s, _) = run(&exemplar, options);
                    quality(&exemplar, s.output().unwrap()).unwrap().coherence
                })
                .sum::<f64>()
                / 3.0
        };
        let (cut, patches) = (
            coherence(super::Start::Graphcut),
            coherence(super::Start::Patches),
        );
        assert!(
            cut < 0.75 * patches,
            "{name}: graph-cut start {cut:.5}, random patches {patches:.5}"
        );
    }
}

/// The graph-cut start's working set counts when it is the larger (a single full-size level).
#[test]
fn the_graph_cut_start_is_in_the_memory_estimate() {
    let exemplar = sample("gravel_64");
    let with = |start: super::Start| {
        Session::new(
            &exemplar,
            Options {
                levels: 1,
                start,
                ..Options::default()
            },
        )
        .unwrap()
        .working_set(false)
        .bytes()
    };
    // Here the graph cut over the whole 256x256 output (its canvas, sources and FFT search:
    // 3.3 MB) outweighs the one level of this grey exemplar (2.0 MB).
    let (cut, patches) = (with(super::Start::Graphcut), with(super::Start::Patches));
    assert!(cut > patches, "{cut} {patches}");
}

/// While a split graph-cut start is under way, the output shows its canvas so far.
#[test]
fn a_split_start_shows_its_canvas() {
    let exemplar = sample("gravel_64");
    let mut s = Session::new(
        &exemplar,
        Options {
            output_width: 256,
            output_height: 256,
            levels: 1,
            ..Options::default()
        },
    )
    .unwrap();
    s.set_step_budget(Some(0.0), 3000);
    let e = s.step().unwrap();
    assert_eq!(
        (e.kind, e.phase),
        (EventKind::Part, super::session::Phase::Start)
    );
    assert!(s.output().is_none(), "the start is not done");
    let covered = |s: &Session| {
        let shown = s.output_full_size().unwrap();
        shown.data().iter().filter(|&&v| v > 0.0).count()
    };
    let first = covered(&s);
    for _ in 0..3 {
        s.step().unwrap();
    }
    let later = covered(&s);
    assert!(
        first > 0 && later > first,
        "{first} then {later} values shown"
    );
}
