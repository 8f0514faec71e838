//! 7.A's seam surface: on the page's demo clips the loop's cut is a time per pixel, not one frame
//! cut, and the coarse-to-fine band keeps it within a few percent of the exact cut's cost.

use super::canvas::Canvas;
use crate::methods::graphcut::blend::FEATHER_RADIUS;
use super::loop_band::{COPY_A, COPY_B, EXACT_PIXELS, place_second_copy};
use super::options::{Blend, Options};
use super::procedural::waves;
use super::session::Session;
use super::source::Source;
use super::synthesis::Synthesis;
use super::transition::{Transition, best_transition, good_transitions};
use super::volume::Volume;

const RIPPLES: &[u8] = include_bytes!("../../../www/samples/clips/ripples.png");
const WATER: &[u8] = include_bytes!("../../../www/samples/clips/water.png");

/// A demo clip (128x128 frames stacked top to bottom), every `step`-th pixel of each frame.
fn demo_clip(strip: &[u8], step: usize) -> Volume {
    let image = crate::decode(strip).unwrap();
    let side = image.width();
    let frames = image.height() / side;
    Volume::from_fn(side / step, side / step, frames, |x, y, t| {
        let p = image.pixel(x * step, t * side + y * step);
        [p[0], p[1], p[2]]
    })
    .unwrap()
}

/// Per pixel, the canvas frames of the seam window that keep copy A: the loop's transition time
/// at that pixel.
fn transition_times(clip: Volume) -> Vec<usize> {
    let mut session = Session::new(clip, Options::default()).unwrap();
    while !session.is_done() {
        session.step().unwrap();
    }
    let canvas = &session.synthesis().canvas;
    let (w, h, d) = canvas.size();
    (0..w * h)
        .map(|i| (0..d).filter(|&t| canvas.label[t * w * h + i] == 0).count())
        .collect()
}

/// The share of pixels whose transition lies at least 3 frames from the median pixel's.
fn off_the_median(times: &[usize]) -> f64 {
    let mut sorted = times.to_vec();
    sorted.sort_unstable();
    let median = sorted[sorted.len() / 2];
    times.iter().filter(|&&t| t.abs_diff(median) >= 3).count() as f64 / times.len() as f64
}

/// At the page's default size (64x64 frames), half the ripples' pixels cut 3 or more frames from
/// the median pixel's time, and over a quarter of the water's do. (Were a cut at the window's last
/// frame to count one copy's difference only, every pixel would cut there.)
#[test]
fn the_loop_cuts_at_different_times_across_the_frame() {
    let ripples = off_the_median(&transition_times(demo_clip(RIPPLES, 2)));
    let water = off_the_median(&transition_times(demo_clip(WATER, 2)));
    assert!(ripples >= 0.3, "ripples: {ripples:.3} of pixels cut 3+ frames from the median");
    assert!(water >= 0.15, "water: {water:.3} of pixels cut 3+ frames from the median");
}

/// The loop's canvas and copies for `clip`'s best transition, as the session makes them, with
/// copy A placed.
fn loop_synthesis(clip: &Volume) -> Synthesis {
    loop_synthesis_for(clip, best_transition(clip, 60).unwrap())
}

/// The same for transition `tr`.
fn loop_synthesis_for(clip: &Volume, tr: Transition) -> Synthesis {
    let h = tr.half_window;
    let a = clip.frames_range(tr.from - h - 1, 2 * h + 2).unwrap();
    let b = clip.frames_range(tr.to - h, 2 * h + 1).unwrap();
    let canvas = Canvas::new(clip.width(), clip.height(), 2 * h + 2).unwrap();
    let mut s = Synthesis::new(vec![Source::new(a), Source::new(b)], canvas, false);
    s.place(COPY_A, &[]).unwrap();
    s
}

/// The exact cut (over the whole window) is the minimum; the banded one, found from a cut on
/// frames of half the size, costs at most 5% more.
#[test]
fn the_banded_cut_costs_within_five_percent_of_the_exact_cut() {
    for seed in [1, 2] {
        let clip = waves(40, 40, 30, seed).unwrap();
        let mut exact = loop_synthesis(&clip);
        let exact = place_second_copy(&mut exact, usize::MAX).unwrap().cut_cost;
        let mut banded = loop_synthesis(&clip);
        let banded = place_second_copy(&mut banded, 20 * 20).unwrap().cut_cost;
        assert!(banded >= exact * (1.0 - 1e-6), "seed {seed}: banded {banded} below the exact {exact}");
        assert!(banded <= 1.05 * exact, "seed {seed}: banded {banded}, exact {exact}");
    }
}

/// The good transitions: the best by frame SSD first, then others of loop lengths of their own,
/// each pair within the half window of the best pair's frames, by frame SSD.
#[test]
fn good_transitions_lie_around_the_best_with_loop_lengths_of_their_own() {
    let clip = waves(16, 16, 60, 3).unwrap();
    let best = best_transition(&clip, 60).unwrap();
    let good = good_transitions(&clip, 60, 4).unwrap();
    assert_eq!(good[0], best);
    assert_eq!(good.len(), 4);
    let h = best.half_window;
    let mut periods: Vec<usize> = good.iter().map(|t| t.period()).collect();
    periods.dedup();
    periods.sort_unstable();
    periods.dedup();
    assert_eq!(periods.len(), 4, "{good:?}");
    for t in &good[1..] {
        assert!(t.from.abs_diff(best.from) <= h && t.to.abs_diff(best.to) <= h, "{t:?}");
        assert!(t.to >= h && t.from + h < 60 && t.period() > 2 * h, "{t:?}");
        assert!(t.distance >= best.distance);
    }
    assert!(good.windows(2).skip(1).all(|w| w[0].distance <= w[1].distance));
}

/// With several transitions the loop keeps the one whose seam costs least, and says so on its
/// last event; with one it seams the best transition by frame SSD.
#[test]
fn the_loop_keeps_the_transition_whose_seam_costs_least() {
    let clip = demo_clip(WATER, 4);
    let options = |transitions| Options {
        transitions,
        ..Options::default()
    };
    let mut session = Session::new(clip.clone(), options(3)).unwrap();
    let mut seams = Vec::new();
    let mut last = None;
    while !session.is_done() {
        let event = session.step().unwrap();
        if event.patch == Some(1) {
            seams.push((event.cut_cost, event.transition));
        }
        last = Some(event);
    }
    assert_eq!(seams.len(), 3);
    let numbers: Vec<usize> = seams[..2].iter().map(|s| s.1.unwrap().0).collect();
    assert_eq!(numbers, vec![0, 1], "the events name the transition each step seamed");
    // The third transition's seam, found apart from the session, as the session seams it.
    let third = good_transitions(&clip, 60, 3).unwrap()[2];
    let mut apart = loop_synthesis_for(&clip, third);
    let third_cost = place_second_copy(&mut apart, EXACT_PIXELS).unwrap().cut_cost;
    let costs = [seams[0].0, seams[1].0, third_cost];
    let cheapest = (0..3).min_by(|&a, &b| costs[a].total_cmp(&costs[b])).unwrap();
    let kept = last.unwrap().transition.expect("a loop's transition");
    assert_eq!((kept.0, kept.1), (cheapest, 3), "costs {costs:?}");
    assert_eq!(seams[2].0, costs[cheapest], "the last step reports the kept seam");
    assert_eq!(session.transition().unwrap().period(), kept.2);
    assert_eq!(session.size().2, kept.2, "the output is the kept loop");
    // The canvas is the kept seam's: its seams cost what the kept step's cut did.
    let total = session.synthesis().canvas.total_seam_cost();
    assert!((total - costs[cheapest]).abs() < 1e-3 * costs[cheapest], "{total} vs {costs:?}");

    let mut one = Session::new(clip.clone(), options(1)).unwrap();
    while !one.is_done() {
        one.step().unwrap();
    }
    assert_eq!(one.transition(), Some(best_transition(&clip, 60).unwrap()));
}

/// Feathering a loop mixes copies A and B only near its seam surface, in time as in space: a
/// voxel with one label within the window keeps its value, and a voxel at the seam becomes a
/// mix of the two copies' values there. Splining is for images and is refused by name.
#[test]
fn feathering_mixes_the_copies_near_the_seam_surface_only() {
    let clip = demo_clip(WATER, 4);
    let run = |blend| {
        let mut s = Session::new(
            clip.clone(),
            Options {
                blend,
                transitions: 1,
                ..Options::default()
            },
        )
        .unwrap();
        while !s.is_done() {
            s.step().unwrap();
        }
        s
    };
    let (plain, feathered) = (run(Blend::None), run(Blend::Feather));
    let canvas = &plain.synthesis().canvas;
    let (w, h, d) = canvas.size();
    let r = FEATHER_RADIUS as isize;
    let (mut mixed, mut kept) = (0, 0);
    for t in 0..plain.size().2.min(d - 1) {
        let (a, b) = (plain.frame(t), feathered.frame(t));
        for y in 0..h {
            for x in 0..w {
                let i = ((t + 1) * h + y) * w + x;
                let own = canvas.label[i];
                let near = (-r..=r).any(|dt| {
                    (-r..=r).any(|dy| {
                        (-r..=r).any(|dx| {
                            let at = |c: usize, d: isize, n: usize| (c as isize + d).clamp(0, n as isize - 1) as usize;
                            let j = (at(t + 1, dt, d) * h + at(y, dy, h)) * w + at(x, dx, w);
                            canvas.label[j] != own
                        })
                    })
                });
                let p = (y * w + x) * 3;
                if !near {
                    assert_eq!(a[p..p + 3], b[p..p + 3], "({x}, {y}, {t}) is far from the seam");
                    kept += 1;
                    continue;
                }
                let synthesis = plain.synthesis();
                let (va, vb) = (
                    synthesis.sources[0].volume.voxel(synthesis.source_voxel(COPY_A, i).unwrap()),
                    synthesis.sources[1].volume.voxel(synthesis.source_voxel(COPY_B, i).unwrap()),
                );
                for k in 0..3 {
                    let (lo, hi) = (va[k].min(vb[k]), va[k].max(vb[k]));
                    assert!((lo - 1e-5..=hi + 1e-5).contains(&b[p + k]), "({x}, {y}, {t})");
                }
                mixed += usize::from(a[p..p + 3] != b[p..p + 3]);
            }
        }
    }
    assert!(mixed > 100 && kept > 100, "{mixed} mixed, {kept} kept");
    let spline = Options {
        blend: Blend::Spline,
        ..Options::default()
    };
    let err = Session::new(clip, spline).err().expect("refused").to_string();
    assert!(err.contains("blend"), "{err}");
}
