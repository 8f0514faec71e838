//! Whole-animation tests of flow-guided synthesis on the samples.

use super::*;
use crate::core::testing::{noise, sample};
use crate::core::{Edge, Image};
use crate::methods::quality::quality;
use crate::solvers::nn::Search;

fn vortex(strength: f32) -> FlowSource {
    FlowSource::Generator(FlowSpec::new(vec![Component::new(FlowKind::Vortex, strength)]).unwrap())
}

fn options(frames: usize) -> FlowOptions {
    FlowOptions {
        output_width: 64,
        output_height: 64,
        frames,
        ..FlowOptions::default()
    }
}

/// Runs to the end; returns every finished frame, the naive warp of the last one and the events.
fn animate(
    exemplar: &Image,
    flow: FlowSource,
    opts: FlowOptions,
) -> (Vec<Image>, Image, Vec<FlowEvent>) {
    let mut session = FlowSession::new(exemplar, flow, opts).unwrap();
    let (mut frames, mut events) = (Vec::new(), Vec::new());
    loop {
        let e = session.step().unwrap();
        events.push(e);
        if e.kind != FlowEventKind::Iteration {
            frames.push(session.frame_image().unwrap());
        }
        if e.kind == FlowEventKind::Done {
            return (frames, session.naive_image().unwrap(), events);
        }
    }
}

/// Mean coherence of `frames` relative to `reference`'s.
fn relative_coherence(exemplar: &Image, frames: &[Image], reference: &Image) -> f64 {
    let base = quality(exemplar, reference).unwrap().coherence;
    frames
        .iter()
        .map(|f| quality(exemplar, f).unwrap().coherence)
        .sum::<f64>()
        / frames.len() as f64
        / base
}

#[test]
fn a_vortex_keeps_the_texture_while_the_naive_warp_smears_it() {
    let exemplar = sample("gravel_64");
    let (frames, naive, events) = animate(&exemplar, vortex(2.0), options(50));
    assert_eq!(frames.len(), 50);
    // Observed on gravel_64 (64x64 frames, lambda 0.2, seeds 1-4): the last frames' coherence
    // is 0.0025-0.0029 and the first frame's 0.0020-0.0027, so the flow-guided frames stay
    // within 1.45x of the first; the naive warp reaches 2.2-3.2x, where the blur saturates at
    // this size. A first frame is one synthesis of 64x64, whose coherence varies by a third
    // between seeds: the bounds leave room for that.
    let guided = relative_coherence(&exemplar, &frames[40..], &frames[0]);
    let smeared = relative_coherence(&exemplar, std::slice::from_ref(&naive), &frames[0]);
    assert!(
        guided < 1.6,
        "flow-guided frames: {guided:.2}x the first frame's coherence"
    );
    assert!(
        smeared > 2.1 && smeared > 2.0 * guided,
        "naive warp: {smeared:.2}x the first frame's coherence, guided {guided:.2}x"
    );
    // The frames follow the flow: each is far closer to its predecessor carried along the flow
    // than an unrelated synthesis is (a different seed's first frame, carried the same way).
    let mut other = FlowSession::new(
        &exemplar,
        vortex(2.0),
        FlowOptions {
            seed: 7,
            ..options(1)
        },
    )
    .unwrap();
    while other.step().unwrap().kind != FlowEventKind::Done {}
    let unrelated = {
        let field = vortex(2.0).field(64, 64, 0).unwrap();
        let carried = warp::warp(
            &other.frame_image().unwrap(),
            &field,
            crate::core::Edge::Clamp,
        )
        .unwrap();
        let c = crate::methods::optimization::constraints::Constraint {
            target: carried.image,
            mask: carried.inside,
            lambda: 1.0,
        };
        c.energy(&frames[1])
    };
    let followed: f64 = events
        .iter()
        .filter(|e| e.kind != FlowEventKind::Iteration && e.frame > 0)
        .map(|e| e.flow_energy)
        .sum::<f64>()
        / 49.0;
    assert!(
        followed < 0.25 * unrelated,
        "flow energy {followed:.5} vs unrelated {unrelated:.5}"
    );
}

#[test]
fn events_count_frames_and_iterations_and_end_with_done() {
    let exemplar = sample("grass_64");
    let (frames, _, events) = animate(
        &exemplar,
        vortex(1.0),
        FlowOptions {
            frames: 4,
            ..options(4)
        },
    );
    assert_eq!(frames.len(), 4);
    let ends: Vec<usize> = events
        .iter()
        .filter(|e| e.kind != FlowEventKind::Iteration)
        .map(|e| e.frame)
        .collect();
    assert_eq!(ends, vec![0, 1, 2, 3]);
    assert_eq!(events.last().unwrap().kind, FlowEventKind::Done);
    for e in events.iter().filter(|e| e.frame > 0) {
        assert!([16, 8].contains(&e.size) && e.iteration >= 1 && e.iteration <= 6);
        assert!(e.texture_energy.is_finite() && e.flow_energy.is_finite());
    }
    assert!(
        events
            .windows(2)
            .all(|p| p[1].total_iterations == p[0].total_iterations + 1)
    );
    // Frames differ (the texture moves) but stay close (it moves a little).
    assert_ne!(frames[1], frames[2]);
}

#[test]
fn a_whole_pixel_translation_with_a_strong_constraint_shifts_the_frame() {
    // Tileable frames and a one-pixel translation: the warped frame is an exact shift, and a
    // large lambda keeps it. Histogram matching is off: after each E-step it moves every pixel,
    // the constrained ones too, towards the exemplar's histogram, by up to 0.01-0.02 on these
    // 1,024 pixels (how far depends on the first frame's content), which is not what this
    // test is about.
    let exemplar = sample("grass_64");
    let flow = FlowSource::Fields(vec![FlowField::from_fn(32, 32, |_, _| (1.0, 0.0)).unwrap()]);
    let opts = FlowOptions {
        output_width: 32,
        output_height: 32,
        frames: 2,
        lambda: 1000.0,
        tileable: true,
        histogram_matching: 0.0,
        ..FlowOptions::default()
    };
    let (frames, naive, _) = animate(&exemplar, flow, opts);
    let mut worst = 0.0f32;
    for y in 0..32 {
        for x in 0..32 {
            let (a, b) = (frames[1].pixel(x, y), frames[0].pixel((x + 31) % 32, y));
            worst = a
                .iter()
                .zip(b)
                .map(|(p, q)| (p - q).abs())
                .fold(worst, f32::max);
            assert_eq!(naive.pixel(x, y), b);
        }
    }
    assert!(worst < 1e-3, "largest difference from the shift {worst}");
}

/// How far (in half pixels, 0 to 16) `frame` lies to the right of `first`: the shift of `first`
/// (tileable, wrapped) nearest to `frame`.
fn half_pixels_moved(first: &Image, frame: &Image) -> usize {
    let distance = |k: usize| {
        let moved = crate::core::sample::shift(first, -(k as f32) / 2.0, 0.0, Edge::Wrap);
        moved
            .data()
            .iter()
            .zip(frame.data())
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f32>()
    };
    (0..=16)
        .min_by(|&a, &b| distance(a).total_cmp(&distance(b)))
        .unwrap()
}

#[test]
fn a_slow_flow_moves_the_texture_only_with_sub_pixel_matches() {
    // A quarter pixel per frame to the right, tileable, 16 frames: the flow moves the texture
    // 3.75 px. Whole-pixel matches round every frame's move back to nothing and the texture
    // stays put; sub-pixel matches keep the fractions and carry it along.
    let exemplar = sample("grass_64");
    let flow = FlowSource::Fields(vec![
        FlowField::from_fn(48, 48, |_, _| (0.25, 0.0)).unwrap(),
    ]);
    let run = |sub_pixel| {
        let opts = FlowOptions {
            output_width: 48,
            output_height: 48,
            frames: 16,
            tileable: true,
            sub_pixel,
            ..FlowOptions::default()
        };
        let (frames, ..) = animate(&exemplar, flow.clone(), opts);
        half_pixels_moved(&frames[0], &frames[15])
    };
    let (whole, sub) = (run(false), run(true));
    assert!(whole <= 1, "whole-pixel matches: moved {whole} half pixels");
    assert!(
        (6..=9).contains(&sub),
        "sub-pixel matches: moved {sub} half pixels of 7.5"
    );
}

#[test]
fn sub_pixel_matches_run_with_every_search() {
    // The stacked copies are one neighbourhood space for the tree and exact searches too: every
    // match stays inside one copy, and the frames are finite.
    let exemplar = sample("grass_64");
    for search in [Search::KMeansTree, Search::Exact] {
        let opts = FlowOptions {
            output_width: 32,
            output_height: 32,
            frames: 3,
            frame_sizes: vec![8],
            search,
            sub_pixel: true,
            ..FlowOptions::default()
        };
        let (frames, ..) = animate(&exemplar, vortex(1.0), opts);
        assert_eq!(frames.len(), 3);
        assert!(frames[2].data().iter().all(|v| v.is_finite()), "{search:?}");
    }
}

#[test]
fn flow_fields_of_the_wrong_size_or_with_bad_values_are_refused() {
    let exemplar = sample("grass_64");
    let msg = |flow: FlowSource| {
        FlowSession::new(&exemplar, flow, options(3))
            .err()
            .unwrap()
            .to_string()
    };
    let m = msg(FlowSource::Fields(vec![FlowField::zero(64, 32).unwrap()]));
    assert!(m.contains("64x32") && m.contains("64x64"), "{m}");
    assert!(msg(FlowSource::Fields(vec![])).contains("flow"));
    let m = FlowOptions {
        lambda: f32::NAN,
        ..options(3)
    }
    .validate(64, 64)
    .unwrap_err()
    .to_string();
    assert!(m.contains("lambda"), "{m}");
    let m = FlowOptions {
        frame_sizes: vec![100],
        ..options(3)
    }
    .validate(64, 64)
    .unwrap_err()
    .to_string();
    assert!(m.contains("frameSizes") && m.contains("[100]"), "{m}");
    let m = FlowOptions {
        frame_sizes: vec![16, 200],
        ..options(3)
    }
    .validate(64, 64)
    .unwrap_err()
    .to_string();
    assert!(m.contains("frameSizes") && m.contains("200"), "{m}");
    let m = FlowOptions {
        frames: 0,
        ..options(3)
    }
    .validate(64, 64)
    .unwrap_err()
    .to_string();
    assert!(m.contains("frames"), "{m}");
}

#[test]
fn stationary_and_time_varying_flows_and_caller_fields_cycle() {
    let spec = FlowSpec::new(vec![Component {
        period: 4.0,
        ..Component::new(FlowKind::Vortex, 1.0)
    }])
    .unwrap();
    let source = FlowSource::Generator(spec);
    assert_ne!(
        source.field(8, 8, 0).unwrap(),
        source.field(8, 8, 1).unwrap()
    );
    let a = FlowField::zero(8, 8).unwrap();
    let b = FlowField::from_fn(8, 8, |_, _| (1.0, 0.0)).unwrap();
    let cycle = FlowSource::Fields(vec![a.clone(), b.clone()]);
    assert_eq!(cycle.field(8, 8, 2).unwrap(), a);
    assert_eq!(cycle.field(8, 8, 3).unwrap(), b);
}

#[test]
fn frames_keep_their_detail_along_a_vortex() {
    // tiles_64 at 96x96 for 20 frames. Without histogram matching (`histogram_matching: 0`),
    // frame 20's flat fraction is 2.4x frame 1's (0.235 against 0.098): the grid fades to grey.
    let exemplar = sample("tiles_64");
    let opts = FlowOptions {
        output_width: 96,
        output_height: 96,
        frames: 20,
        ..FlowOptions::default()
    };
    let (frames, naive, _) = animate(&exemplar, vortex(2.0), opts);
    let flat = |img: &Image| quality(&exemplar, img).unwrap().flat;
    let (first, last) = (flat(&frames[0]), flat(&frames[19]));
    assert!(last <= 1.3 * first, "flat fraction {first} -> {last}");
    // The naive warp of frame 1 is what the frames would become without synthesis.
    assert!(
        flat(&naive) > 3.0 * last,
        "naive {} vs {last}",
        flat(&naive)
    );
}

#[test]
fn frame_sizes_wider_than_the_exemplar_or_frame_are_skipped() {
    let opts = FlowOptions {
        output_width: 24,
        output_height: 40,
        ..options(2)
    };
    // 32 needs a 128-pixel exemplar (4 widths) and a frame at least 32 wide.
    assert_eq!(opts.fitting_frame_sizes(128, 128), vec![16, 8]);
    let wide = FlowOptions {
        output_width: 64,
        ..opts.clone()
    };
    assert_eq!(wide.fitting_frame_sizes(128, 130), vec![32, 16, 8]);
    assert_eq!(wide.fitting_frame_sizes(127, 200), vec![16, 8]);
    assert_eq!(opts.fitting_frame_sizes(40, 32), vec![8]);
    let explicit = FlowOptions {
        frame_sizes: vec![8, 16, 8, 2],
        ..opts
    };
    assert_eq!(explicit.fitting_frame_sizes(64, 64), vec![16, 8, 2]);
    // Where none fits by 4 widths, texture optimisation's fallback: the smallest size at most
    // half the exemplar (a 256x24 strip, a 20x20 exemplar), and none under 16.
    assert_eq!(opts.fitting_frame_sizes(256, 24), vec![8]);
    assert_eq!(opts.fitting_frame_sizes(20, 20), vec![8]);
    assert_eq!(opts.fitting_frame_sizes(15, 15), Vec::<usize>::new());
    // The default ladder on a 40x40 exemplar: 32 and 16 are skipped, the animation runs.
    let exemplar = noise(40, 40, 3, 4);
    let (frames, _, events) = animate(
        &exemplar,
        vortex(1.0),
        FlowOptions {
            output_width: 32,
            output_height: 32,
            ..options(2)
        },
    );
    assert_eq!(frames.len(), 2);
    assert!(
        events.iter().all(|e| e.size <= 16),
        "only sizes that fit run"
    );
    // A 24x24 exemplar: texture optimisation falls back to 8 for frame 1, and so do the frames.
    let (frames, _, events) = animate(
        &noise(24, 24, 3, 5),
        vortex(1.0),
        FlowOptions {
            output_width: 32,
            output_height: 32,
            ..options(2)
        },
    );
    assert_eq!(frames.len(), 2);
    assert!(
        events.iter().skip(1).all(|e| e.size == 8),
        "the fallback size"
    );
}

#[test]
fn splitting_frames_over_steps_changes_no_output() {
    let exemplar = sample("tiles_64");
    let opts = FlowOptions {
        output_width: 48,
        output_height: 40,
        ..options(3)
    };
    let run = |split: bool| {
        let mut s = FlowSession::new(&exemplar, vortex(1.5), opts.clone()).unwrap();
        if split {
            // Every chunk of work is a step of its own.
            s.set_step_budget(Some(0.0), 3000);
        }
        let (mut frames, mut parts, mut whole) = (Vec::new(), 0, 0);
        let mut phases = std::collections::HashSet::new();
        loop {
            let e = s.step().unwrap();
            match e.kind {
                FlowEventKind::Part => {
                    parts += 1;
                    phases.insert(format!("{:?}", e.phase));
                    assert!((0.0..1.0).contains(&e.progress), "{e:?}");
                }
                _ => whole += 1,
            }
            assert_eq!(e.total_iterations, whole, "parts are not iterations");
            if matches!(e.kind, FlowEventKind::Frame | FlowEventKind::Done) {
                frames.push(s.frame_image().unwrap());
            }
            if e.kind == FlowEventKind::Done {
                break;
            }
        }
        (frames, parts, whole, phases, s.history().to_vec())
    };
    let plain = run(false);
    let split = run(true);
    assert_eq!(
        plain.1, 0,
        "a small frame steps whole iterations by default"
    );
    assert!(split.1 > 3 * split.2, "{} parts", split.1);
    assert_eq!(split.3.len(), 3, "{:?}", split.3);
    assert_eq!(split.2, plain.2, "the same iterations");
    assert_eq!(split.4, plain.4, "the same energies");
    assert_eq!(split.0, plain.0, "the same frames");
}
