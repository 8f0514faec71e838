//! Native benchmark of graph-cut video textures (section 7):
//! `cargo run --profile explore -p texsynth-bench --bin video_bench`. On a procedural wave clip it times a
//! 128x128x60 loop (7.A), a spatial extension of 96x96x30 to 192x192x60 (7.E with 7.D: random,
//! entire-patch and sub-patch placement), and the
//! 3-D FFT SSD search against a direct SSD on a small volume (correctness and speed).
//! `scripts/bench-video.mjs` runs the first two as wasm in Node.

use std::time::Instant;

use texsynth::methods::video::procedural::waves;
use texsynth::methods::video::{Mode, Options, Placement, Session};
use texsynth::solvers::fft_ssd::{VolumeView, volume_ssd_map};

fn run(label: &str, clip: texsynth::methods::video::Volume, options: Options) {
    let start = Instant::now();
    let mut session = Session::new(clip, options).expect("valid options");
    let mut steps = Vec::new();
    loop {
        let t = Instant::now();
        let e = session.step().expect("step");
        steps.push(t.elapsed().as_secs_f64());
        if e.done {
            let (w, h, d) = session.size();
            println!(
                "{label:<34} {:>8.2} s  {:>3} patches, max step {:>6.2} s, output {w}x{h}x{d}, \
                 seam cost {:.1}{}",
                start.elapsed().as_secs_f64(),
                e.patches,
                steps.iter().copied().fold(0.0, f64::max),
                session.synthesis().canvas.total_seam_cost(),
                session
                    .transition()
                    .map(|t| format!(
                        ", transition {} -> {}, loop {} frames, window {}",
                        t.from,
                        t.to,
                        t.period(),
                        2 * t.half_window + 1
                    ))
                    .unwrap_or_default()
            );
            return;
        }
    }
}

fn main() {
    println!("native graph-cut video textures (procedural wave clip, seed 1)");
    run(
        "loop 128x128x60 (7.A)",
        waves(128, 128, 60, 1).unwrap(),
        Options::default(),
    );
    for (name, placement) in [
        ("random", Placement::Random),
        ("entire", Placement::EntirePatch),
        ("sub-patch", Placement::SubPatch),
    ] {
        run(
            &format!("extend 96x96x30 -> 192x192x60 {name}"),
            waves(96, 96, 30, 1).unwrap(),
            Options {
                mode: Mode::Extend,
                output_width: Some(192),
                output_height: Some(192),
                output_frames: Some(60),
                placement,
                ..Options::default()
            },
        );
    }
    run(
        "offsets 64x64x20 -> 60 frames (7.B)",
        waves(64, 64, 20, 1).unwrap(),
        Options {
            mode: Mode::Offsets,
            output_frames: Some(60),
            ..Options::default()
        },
    );
    fft_versus_direct();
}

/// The 3-D FFT search of a 12x12x6 region over a 32x32x16 clip, against the direct sum.
fn fft_versus_direct() {
    let region = waves(12, 12, 6, 2).unwrap();
    let input = waves(32, 32, 16, 3).unwrap();
    fn view(v: &texsynth::methods::video::Volume) -> VolumeView<'_> {
        VolumeView {
            data: v.data(),
            width: v.width(),
            height: v.height(),
            depth: v.frames(),
            channels: 3,
            weights: None,
        }
    }
    let start = Instant::now();
    let map = volume_ssd_map(view(&region), view(&input)).unwrap();
    let fft = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let mut worst = 0.0f64;
    let (rw, rh, rd) = (12i64, 12i64, 6i64);
    for tt in -15..6i64 {
        for ty in -31..12i64 {
            for tx in -31..12i64 {
                let mut cost = 0.0f64;
                for z in 0..16i64 {
                    for y in 0..32i64 {
                        for x in 0..32i64 {
                            let (ox, oy, oz) = (x + tx, y + ty, z + tt);
                            if ox < 0 || oy < 0 || oz < 0 || ox >= rw || oy >= rh || oz >= rd {
                                continue;
                            }
                            let o = ((oz * rh + oy) * rw + ox) as usize;
                            let p = ((z * 32 + y) * 32 + x) as usize;
                            for c in 0..3 {
                                let d = f64::from(region.data()[o * 3 + c])
                                    - f64::from(input.data()[p * 3 + c]);
                                cost += d * d;
                            }
                        }
                    }
                }
                let (c, _) = map.get(tx as isize, ty as isize, tt as isize).unwrap();
                worst = worst.max((f64::from(c) - cost).abs() / (1.0 + cost));
            }
        }
    }
    let direct = start.elapsed().as_secs_f64();
    println!(
        "3-D FFT SSD 12x12x6 over 32x32x16: {} translations, FFT {:.1} ms, direct {:.1} ms, \
         largest relative difference {worst:.2e}",
        map.costs.len(),
        fft * 1e3,
        direct * 1e3
    );
}
