//! Tests of the video syntheses on small procedural clips.

use std::collections::HashSet;

use super::canvas::{Canvas, Patch};
use super::options::{Mode, Options, Placement};
use super::session::Session;
use super::source::{AXES, Source};
use super::synthesis::Synthesis;
use super::volume::Volume;
use crate::core::Rng;
use crate::solvers::maxflow::oracle::Spec;

/// Moving waves with some static grain: no frame repeats exactly, every region moves.
fn clip(w: usize, h: usize, frames: usize, seed: u64) -> Volume {
    let mut rng = Rng::new(seed);
    let grain: Vec<f32> = (0..w * h).map(|_| rng.next_f32() * 0.1).collect();
    Volume::from_fn(w, h, frames, |x, y, t| {
        let (x, y, t) = (x as f32, y as f32, t as f32);
        let a = (0.45 * x + 0.2 * y - 0.55 * t).sin();
        let b = (0.17 * x - 0.38 * y + 0.31 * t + 1.0).sin();
        let g = grain[y as usize * w + x as usize];
        [
            0.5 + 0.3 * a + g,
            0.5 + 0.2 * b + 0.1 * a,
            0.4 + 0.2 * (a * b) + g,
        ]
    })
    .unwrap()
}

/// A synthesis over a small canvas with two overlapping patches already placed (so old seams
/// exist) and the seam graph of a third.
fn three_patches(seed: u64) -> (Synthesis, Patch) {
    let mut rng = Rng::new(seed);
    let input = clip(4, 4, 3, seed);
    let canvas = Canvas::new(6, 5, 5).unwrap();
    let mut s = Synthesis::new(vec![Source::new(input)], canvas, false);
    let offset = |rng: &mut Rng| Patch {
        source: 0,
        tx: rng.index(3) as i32,
        ty: rng.index(2) as i32,
        tt: rng.index(3) as i32,
    };
    let first = offset(&mut rng);
    s.place(first, &[]).unwrap();
    let mut second = offset(&mut rng);
    while second == first {
        second = offset(&mut rng);
    }
    s.place(second, &[]).unwrap();
    let mut third = offset(&mut rng);
    while third == first || third == second {
        third = offset(&mut rng);
    }
    (s, third)
}

#[test]
fn the_3d_seam_graph_max_flow_equals_the_reference_solver() {
    let mut with_seam_nodes = 0;
    for seed in 0..12 {
        let (s, patch) = three_patches(seed);
        let g = s.seam_graph(patch, &[]);
        with_seam_nodes += usize::from(g.nodes > g.cells.len());
        let spec = Spec {
            nodes: g.nodes,
            edges: g
                .edges
                .iter()
                .map(|&(a, b, c)| (a as usize, b as usize, c, c))
                .collect(),
            terminals: g
                .terminals
                .iter()
                .map(|&(n, a, b)| (n as usize, a, b))
                .collect(),
        };
        let flow = g.build().unwrap().maxflow();
        let reference = spec.reference_flow_f64();
        assert!(
            (flow - reference).abs() <= 1e-4 * (1.0 + reference),
            "seed {seed}: {flow} vs {reference}"
        );
    }
    assert!(with_seam_nodes > 3, "old seams must be exercised");
}

#[test]
fn the_cut_equals_the_seam_energy_of_the_chosen_labelling() {
    for seed in 0..12 {
        let (mut s, patch) = three_patches(seed);
        let footprint = s.footprint(patch);
        let placed = s.place(patch, &[]).unwrap();
        let inside: HashSet<usize> = footprint.iter().copied().collect();
        // Every seam left on an edge inside the patch: old ones kept, new ones cut.
        let mut energy = 0.0f64;
        for &i in &footprint {
            for axis in AXES {
                if let Some(j) = s.canvas.next(i, axis)
                    && inside.contains(&j)
                {
                    energy += f64::from(s.canvas.seam[axis as usize][i]);
                }
            }
        }
        assert!(
            (energy - placed.cut_cost).abs() <= 1e-3 * (1.0 + energy),
            "seed {seed}: energy {energy} vs cut {}",
            placed.cut_cost
        );
    }
}

fn run(session: &mut Session) {
    for _ in 0..10_000 {
        if session.step().unwrap().done {
            return;
        }
    }
    panic!("the session did not finish");
}

fn frame_difference(a: &[f32], b: &[f32]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| f64::from(x - y).powi(2))
        .sum::<f64>()
        / a.len() as f64
}

#[test]
fn a_loop_is_continuous_where_it_closes_and_across_its_seam() {
    let input = clip(20, 16, 48, 7);
    let mean_input = (1..48)
        .map(|t| input.frame_difference(t - 1, t))
        .sum::<f64>()
        / 47.0;
    let mut session = Session::new(input, Options::default()).unwrap();
    run(&mut session);
    let tr = session.transition().unwrap();
    let (_, _, frames) = session.size();
    assert_eq!(frames, tr.period());
    let step = |t: usize| frame_difference(session.frame(t), session.frame((t + 1) % frames));
    let wrap = step(frames - 1);
    assert!(wrap <= mean_input, "wrap {wrap} vs mean {mean_input}");
    // Across the seam window the loop is no worse than the best single-frame jump of Schödl
    // et al. would be, frame for frame.
    let worst = (0..frames).map(step).fold(0.0, f64::max);
    assert!(
        worst <= mean_input.max(tr.distance) * 1.5,
        "worst consecutive difference {worst}, mean {mean_input}, best jump {}",
        tr.distance
    );
    assert!(session.step().unwrap().done);
}

#[test]
fn the_fixed_frames_of_7d_stay_unchanged_and_the_video_loops() {
    let input = clip(12, 10, 12, 3);
    let options = Options {
        mode: Mode::Extend,
        output_width: Some(18),
        output_height: Some(14),
        output_frames: Some(16),
        fixed_frames: Some(3),
        ..Options::default()
    };
    let mut session = Session::new(input.clone(), options).unwrap();
    let (w, h, total) = session.synthesis().canvas.size();
    let k = 3;
    let plane = w * h * 3;
    // The constraint phase first; then snapshot the fixed frames.
    while session.synthesis().canvas.fixed.iter().all(|&f| !f) {
        session.step().unwrap();
    }
    let snapshot = |s: &Session| {
        let d = s.synthesis().canvas.pixels.data();
        (d[..k * plane].to_vec(), d[(total - k) * plane..].to_vec())
    };
    let (first, last) = snapshot(&session);
    assert_eq!(first, last, "the last k frames equal the first k");
    for _ in 0..10_000 {
        let done = session.step().unwrap().done;
        assert_eq!(snapshot(&session), (first.clone(), last.clone()));
        if done {
            break;
        }
    }
    assert!(session.is_done());
    // After removing the first k, the last frame is canvas frame k - 1, which frame 0 (canvas
    // frame k) followed while synthesising: the loop closes with the video's own transition.
    let frames = session.size().2;
    assert_eq!(frames, 16);
    assert_eq!(session.frame(frames - 1), &first[(k - 1) * plane..]);
}

#[test]
fn equal_frames_fix_the_inputs_own_first_frames() {
    let input = clip(10, 8, 10, 5);
    let options = Options {
        mode: Mode::Offsets,
        output_frames: Some(18),
        fixed_frames: Some(2),
        ..Options::default()
    };
    let mut session = Session::new(input.clone(), options).unwrap();
    run(&mut session);
    let canvas = &session.synthesis().canvas;
    let plane = 10 * 8 * 3;
    assert_eq!(
        &canvas.pixels.data()[..2 * plane],
        &input.data()[..2 * plane]
    );
    assert!(canvas.is_covered());
}

#[test]
fn the_spatially_extended_output_has_the_requested_size_and_no_uncovered_voxel() {
    for placement in [Placement::Random, Placement::EntirePatch, Placement::SubPatch] {
        let options = Options {
            mode: Mode::Extend,
            output_width: Some(26),
            output_height: Some(21),
            output_frames: Some(14),
            fixed_frames: Some(2),
            placement,
            ..Options::default()
        };
        let mut session = Session::new(clip(12, 10, 8, 11), options).unwrap();
        run(&mut session);
        assert_eq!(session.size(), (26, 21, 14));
        assert!(session.synthesis().canvas.is_covered(), "{placement:?}");
        assert!(session.synthesis().canvas.patches.len() > 4);
    }
}

#[test]
fn random_temporal_offsets_cover_a_longer_video() {
    let options = Options {
        mode: Mode::Offsets,
        output_frames: Some(30),
        fixed_frames: Some(0),
        ..Options::default()
    };
    let mut session = Session::new(clip(8, 8, 10, 2), options).unwrap();
    run(&mut session);
    let s = session.synthesis();
    assert!(s.canvas.is_covered());
    assert!(s.canvas.patches.iter().all(|p| p.tx == 0 && p.ty == 0));
    assert_eq!(session.size(), (8, 8, 30));
}

#[test]
fn the_same_seed_gives_the_same_video() {
    let options = Options {
        mode: Mode::Extend,
        output_width: Some(16),
        output_frames: Some(10),
        fixed_frames: Some(2),
        seed: 9,
        ..Options::default()
    };
    let mut a = Session::new(clip(10, 8, 8, 4), options.clone()).unwrap();
    let mut b = Session::new(clip(10, 8, 8, 4), options).unwrap();
    run(&mut a);
    run(&mut b);
    assert_eq!(a.synthesis().canvas.pixels, b.synthesis().canvas.pixels);
}

#[test]
fn bad_input_gives_named_errors() {
    let err = Volume::from_rgba_frames(4, 4, 2, &[0; 10])
        .unwrap_err()
        .to_string();
    assert!(err.contains("RGBA frames") && err.contains("128"), "{err}");
    let err = Volume::from_rgba_frames(0, 4, 2, &[])
        .unwrap_err()
        .to_string();
    assert!(err.contains("0x4x2"), "{err}");
    let small = clip(8, 8, 10, 1);
    // A loop closes through 7.A's transition: 7.D's k is refused, even at its default value.
    for k in [0, 10] {
        let loop_with_k = Options {
            fixed_frames: Some(k),
            ..Options::default()
        };
        let err = Session::new(small.clone(), loop_with_k)
            .err()
            .unwrap()
            .to_string();
        assert!(err.contains("fixedFrames") && err.contains("'loop'"), "{err}");
    }
    let too_big = Options {
        mode: Mode::Extend,
        output_width: Some(2048),
        output_height: Some(2048),
        output_frames: Some(100),
        ..Options::default()
    };
    let err = Session::new(small.clone(), too_big)
        .err()
        .unwrap()
        .to_string();
    assert!(
        err.contains("2048x2048x100") && err.contains("memory budget of 1024 MiB"),
        "{err}"
    );
    let err = Session::new(
        small.clone(),
        Options {
            output_frames: Some(20),
            ..Options::default()
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(err.contains("outputFrames"), "{err}");
    let err = Session::new(
        small.clone(),
        Options {
            mode: Mode::Offsets,
            output_width: Some(20),
            ..Options::default()
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(err.contains("outputWidth"), "{err}");
    let err = Session::new(
        small.clone(),
        Options {
            mode: Mode::Extend,
            fixed_frames: Some(11),
            ..Options::default()
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(err.contains("fixedFrames"), "{err}");
    let err = Session::new(clip(8, 8, 5, 1), Options::default())
        .err()
        .unwrap()
        .to_string();
    assert!(err.contains("at least 7 frames"), "{err}");
}

/// Regression (fuzz target `options`): an 'extend' output of 65536 a side overflowed the working
/// set estimate (a panic natively, a wrapped-round estimate in wasm32) instead of being refused.
#[test]
fn a_huge_extended_output_is_refused_by_name() {
    // The last: sizes near 2^32 overflowed even the u64 voxel count (fuzz smoke run in CI).
    let big = u32::MAX as usize;
    for (w, h, t) in [
        (65536, 65536, 65536),
        (65536, 65536, 2),
        (1 << 20, 8, 8),
        (big, big, big),
    ] {
        let options = Options {
            mode: Mode::Extend,
            output_width: Some(w),
            output_height: Some(h),
            output_frames: Some(t),
            fixed_frames: Some(0),
            ..Options::default()
        };
        let err = Session::new(clip(8, 8, 6, 1), options)
            .err()
            .expect("refused");
        assert!(err.to_string().contains("output"), "{err}");
    }
}

/// 7.A's seam is a surface, not a frame cut: in a clip of noise where the left part of the loop's
/// two ends agrees early in the seam window and the right part late, each part switches from
/// the first copy to the second where it agrees.
#[test]
fn the_loop_seam_switches_each_pixel_at_its_own_frame() {
    let (w, h, n) = (32usize, 12usize, 48usize);
    let mut rng = Rng::new(17);
    let noise: Vec<[f32; 3]> = (0..w * h * n)
        .map(|_| [rng.next_f32(), rng.next_f32(), rng.next_f32()])
        .collect();
    // The seam window holds clip frames 26-40 (first copy, canvas frames 0-14) over clip frames
    // 2-16 (second copy, canvas frames 1-15). Frame 34 repeats frame 10, so 34 -> 10 is the
    // transition; the left third repeats frames 5-6 at 29-30 (canvas frames 3-4), the right
    // third frames 13-14 at 37-38 (canvas frames 11-12).
    let source = |x: usize, y: usize, t: usize| -> usize {
        let repeat = match t {
            34 => Some(10),
            29 | 30 if x < w / 3 => Some(t - 24),
            37 | 38 if x >= w - w / 3 => Some(t - 24),
            _ => None,
        };
        (repeat.unwrap_or(t) * h + y) * w + x
    };
    let input = Volume::from_fn(w, h, n, |x, y, t| noise[source(x, y, t)]).unwrap();
    let options = Options {
        refinement_patches: 0,
        ..Options::default()
    };
    let mut session = Session::new(input, options).unwrap();
    let tr = session.transition().unwrap();
    assert_eq!((tr.from, tr.to, tr.half_window), (34, 10, 7));
    run(&mut session);
    let canvas = &session.synthesis().canvas;
    let (cw, ch, frames) = canvas.size();
    // Per pixel, the first canvas frame that shows the second copy.
    let switch = |x: usize, y: usize| {
        (0..frames)
            .find(|&t| {
                let label = canvas.label[(t * ch + y) * cw + x];
                canvas.patches[label as usize].source == 1
            })
            .expect("the second copy ends the window")
    };
    for y in 0..h {
        for x in 0..w / 3 - 1 {
            assert_eq!(switch(x, y), 4, "left pixel ({x}, {y})");
        }
        for x in w - w / 3 + 1..w {
            assert_eq!(switch(x, y), 12, "right pixel ({x}, {y})");
        }
    }
}
