//! 7.A's seam surface: on the page's demo clips the loop's cut is a time per pixel, not one frame
//! cut, and the coarse-to-fine band keeps it within a few percent of the exact cut's cost.

use super::canvas::Canvas;
use super::loop_band::{COPY_A, place_second_copy};
use super::options::Options;
use super::procedural::waves;
use super::session::Session;
use super::source::Source;
use super::synthesis::Synthesis;
use super::transition::best_transition;
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

/// The loop's canvas and copies for `clip`, as the session makes them, with copy A placed.
fn loop_synthesis(clip: &Volume) -> Synthesis {
    let tr = best_transition(clip, 60).unwrap();
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
