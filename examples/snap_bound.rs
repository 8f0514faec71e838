//! How close can a frame made of whole-pixel content come to the warped previous frame, and
//! how coherent is it? `cargo run --profile explore --example snap_bound -- [SAMPLE] [SIZE]`
//! (defaults `tiles_128 256`, a vortex of strength 2; `STRENGTH`, `SEED`;
//! `FRAMES=n KAPPA=k` repeats the cut frame after frame instead). Synthesises frame 1
//! as the animation does and warps it one step along the flow (the flow energy's target). Then
//! makes the next frame from frame 1's own content moved by whole pixels, with no new content:
//! (a) every pixel picks one of the roundings of its flow vector by graph cut (data cost: the
//! squared distance to the warp; seam cost: `kappa` times graph-cut textures' seam cost between
//! neighbours that move differently), for several `kappa`; (b) every BxB block moves by the
//! shift that fits the warp best there. Prints each frame's flow energy and coherence.
//!
//! Coherence asks for content on whole pixels (frame 1 moved a quarter pixel scores 3.4x), and
//! a rotation cannot be followed by whole-pixel moves without faults, lines where one side is a
//! pixel off the other. So this is about the least flow energy a frame as coherent as these can
//! have after one frame: re-synthesising the faults away (what the animation's EM does) costs
//! flow energy on top.

#[path = "shared/vortex_frame.rs"]
mod vortex_frame;

use texsynth::core::{Edge, Image};
use texsynth::methods::flow::warp::warp;
use texsynth::methods::optimization::constraints::Constraint;
use texsynth::methods::quality::quality;
use vortex_frame::vortex_frame_one;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("tiles_128", String::as_str);
    let size: usize = args.get(1).map_or(256, |s| s.parse().expect("size"));
    let strength = std::env::var("STRENGTH").map_or(2.0, |v| v.parse().expect("number"));
    let seed = std::env::var("SEED").map_or(1, |v| v.parse().expect("number"));
    let (exemplar, session, frame) = vortex_frame_one(name, size, strength, seed);
    let field = session.field_at(0).expect("field");
    let warped = warp(&frame, &field, Edge::Clamp).expect("warp");
    let q1 = quality(&exemplar, &frame).expect("quality");
    let qw = quality(&exemplar, &warped.image).expect("quality");
    println!(
        "{name} {size}x{size}, vortex {strength}: frame 1 coherence {:.5} flat {:.3}; its warp coherence {:.5} ({:.2}x) flat {:.3}",
        q1.coherence,
        q1.flat,
        qw.coherence,
        qw.coherence / q1.coherence,
        qw.flat
    );
    // A made frame's flow energy against the warp, and its quality against frame 1's.
    let report = |label: &str, made: &Image, warped: &texsynth::methods::flow::warp::Warped| {
        let energy = flow_energy(made, &warped.image, &warped.inside);
        let q = quality(&exemplar, made).expect("quality");
        println!(
            "{label}: flow energy {energy:.5}, coherence {:.5} ({:.2}x frame 1), flat {:.3} ({:.2}x)",
            q.coherence,
            q.coherence / q1.coherence,
            q.flat,
            q.flat / q1.flat
        );
    };
    for kappa in [0.0f64, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0] {
        let snapped = labelled(&frame, &warped.image, &warped.inside, &field, kappa);
        report(&format!("cut kappa {kappa}"), &snapped, &warped);
    }
    // `FRAMES=n KAPPA=k`: the same cut frame after frame, with no re-synthesis, to see the faults
    // pile up.
    if let Ok(frames) = std::env::var("FRAMES") {
        let frames: usize = frames.parse().expect("a frame count");
        let kappa = std::env::var("KAPPA").map_or(0.5, |v| v.parse().expect("number"));
        let mut previous = frame.clone();
        for t in 0..frames {
            let field = session.field_at(t).expect("field");
            let warped = warp(&previous, &field, Edge::Clamp).expect("warp");
            previous = labelled(&previous, &warped.image, &warped.inside, &field, kappa);
            if (t + 1) % 5 == 0 || t == 0 {
                let label = format!("frame {:>3} by cuts alone (kappa {kappa})", t + 2);
                report(&label, &previous, &warped);
            }
        }
        return;
    }
    for block in [1, 2, 4, 8, 16, 32] {
        let snapped = snap(&frame, &warped.image, &warped.inside, &field, block);
        report(&format!("block {block:>2}"), &snapped, &warped);
    }
}

/// Every `block`-square block of the result is `frame` moved by the whole-pixel shift (among the
/// roundings of the block's flow vectors and their neighbours) closest to `target` there.
fn snap(
    frame: &Image,
    target: &Image,
    inside: &[f32],
    field: &texsynth::methods::flow::FlowField,
    block: usize,
) -> Image {
    let (w, h, c) = (frame.width(), frame.height(), frame.channels());
    let mut out = Image::new(w, h, c).expect("image");
    let read = |x: i64, y: i64| {
        frame.pixel(
            x.clamp(0, w as i64 - 1) as usize,
            y.clamp(0, h as i64 - 1) as usize,
        )
    };
    for by in (0..h).step_by(block) {
        for bx in (0..w).step_by(block) {
            let mut shifts = Vec::new();
            for y in by..(by + block).min(h) {
                for x in bx..(bx + block).min(w) {
                    let (vx, vy) = field.at(x, y);
                    for sx in [vx.floor(), vx.ceil()] {
                        for sy in [vy.floor(), vy.ceil()] {
                            let s = (sx as i64, sy as i64);
                            if !shifts.contains(&s) {
                                shifts.push(s);
                            }
                        }
                    }
                }
            }
            let cost = |(sx, sy): (i64, i64)| {
                let mut sum = 0.0f64;
                for y in by..(by + block).min(h) {
                    for x in bx..(bx + block).min(w) {
                        if inside[y * w + x] > 0.0 {
                            let a = read(x as i64 - sx, y as i64 - sy);
                            let b = target.pixel(x, y);
                            sum += a
                                .iter()
                                .zip(b)
                                .map(|(p, q)| f64::from(p - q).powi(2))
                                .sum::<f64>();
                        }
                    }
                }
                sum
            };
            let best = shifts
                .iter()
                .copied()
                .min_by(|&a, &b| cost(a).total_cmp(&cost(b)))
                .expect("a shift");
            for y in by..(by + block).min(h) {
                for x in bx..(bx + block).min(w) {
                    let px = read(x as i64 - best.0, y as i64 - best.1).to_vec();
                    out.pixel_mut(x, y).copy_from_slice(&px);
                }
            }
        }
    }
    out
}

/// The animation's flow energy of `frame` against `target` (the warp) over the pixels whose warp
/// source lies inside.
fn flow_energy(frame: &Image, target: &Image, inside: &[f32]) -> f64 {
    Constraint {
        target: target.clone(),
        mask: inside.to_vec(),
        lambda: 1.0,
    }
    .energy(frame)
}

/// The whole-pixel shift of every pixel by alpha-expansion (two sweeps): data cost the squared
/// distance of `frame` moved by the shift to `target`, seam cost `kappa` times graph-cut
/// textures' |A(s) - B(s)| + |A(t) - B(t)| between neighbours with different shifts. A pixel may
/// take only the roundings of its own flow vector.
fn labelled(
    frame: &Image,
    target: &Image,
    inside: &[f32],
    field: &texsynth::methods::flow::FlowField,
    kappa: f64,
) -> Image {
    use texsynth::solvers::maxflow::Graph;
    let (w, h, c) = (frame.width(), frame.height(), frame.channels());
    let read = |x: i64, y: i64| {
        frame.pixel(
            x.clamp(0, w as i64 - 1) as usize,
            y.clamp(0, h as i64 - 1) as usize,
        )
    };
    let shifted = |p: usize, s: (i64, i64)| read((p % w) as i64 - s.0, (p / w) as i64 - s.1);
    let allowed = |p: usize, s: (i64, i64)| {
        let (vx, vy) = field.at(p % w, p / w);
        (s.0 == vx.floor() as i64 || s.0 == vx.ceil() as i64)
            && (s.1 == vy.floor() as i64 || s.1 == vy.ceil() as i64)
    };
    let data = |p: usize, s: (i64, i64)| -> f64 {
        if inside[p] == 0.0 {
            return 0.0;
        }
        shifted(p, s)
            .iter()
            .zip(target.pixel(p % w, p / w))
            .map(|(a, b)| f64::from(a - b).powi(2))
            .sum()
    };
    let norm = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| f64::from(x - y).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    let seam = |p: usize, q: usize, a: (i64, i64), b: (i64, i64)| -> f64 {
        if a == b {
            return 0.0;
        }
        kappa * (norm(shifted(p, a), shifted(p, b)) + norm(shifted(q, a), shifted(q, b)))
    };
    let mut label: Vec<(i64, i64)> = (0..w * h)
        .map(|p| {
            let (vx, vy) = field.at(p % w, p / w);
            (vx.round() as i64, vy.round() as i64)
        })
        .collect();
    let mut labels: Vec<(i64, i64)> = Vec::new();
    for p in 0..w * h {
        let (vx, vy) = field.at(p % w, p / w);
        for sx in [vx.floor() as i64, vx.ceil() as i64] {
            for sy in [vy.floor() as i64, vy.ceil() as i64] {
                if !labels.contains(&(sx, sy)) {
                    labels.push((sx, sy));
                }
            }
        }
    }
    let mut pairs = Vec::new();
    for y in 0..h {
        for x in 0..w {
            if x + 1 < w {
                pairs.push((y * w + x, y * w + x + 1));
            }
            if y + 1 < h {
                pairs.push((y * w + x, (y + 1) * w + x));
            }
        }
    }
    for _sweep in 0..2 {
        for &alpha in &labels {
            let mut g = Graph::new(w * h).expect("graph");
            for (p, &lp) in label.iter().enumerate() {
                let keep = data(p, lp) as f32;
                let switch = if lp == alpha {
                    keep
                } else if allowed(p, alpha) {
                    data(p, alpha) as f32
                } else {
                    f32::INFINITY
                };
                // Source side keeps its label, sink side takes alpha.
                g.add_terminal(p, switch, keep).expect("terminal");
            }
            for &(p, q) in &pairs {
                let (lp, lq) = (label[p], label[q]);
                if lp == lq {
                    let v = seam(p, q, lp, alpha) as f32;
                    if v > 0.0 {
                        g.add_edge(p, q, v, v).expect("edge");
                    }
                } else {
                    let a = g.add_node();
                    let (vpa, vaq, vpq) = (
                        seam(p, q, lp, alpha) as f32,
                        seam(p, q, alpha, lq) as f32,
                        seam(p, q, lp, lq) as f32,
                    );
                    g.add_edge(p, a, vpa, vpa).expect("edge");
                    g.add_edge(a, q, vaq, vaq).expect("edge");
                    g.add_terminal(a, 0.0, vpq).expect("terminal");
                }
            }
            g.maxflow();
            for (p, l) in label.iter_mut().enumerate() {
                if !g.is_source_side(p) {
                    *l = alpha;
                }
            }
        }
    }
    let mut out = Image::new(w, h, c).expect("image");
    for (p, &l) in label.iter().enumerate() {
        let px = shifted(p, l).to_vec();
        out.pixel_mut(p % w, p / w).copy_from_slice(&px);
    }
    out
}
