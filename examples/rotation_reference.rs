//! What following a turning flow exactly costs in coherence. `cargo run --profile explore
//! --example rotation_reference -- [SAMPLE] [SIZE] [STRENGTH]` (defaults: the page's
//! `tiles_128 256 2`): makes frame 1 of the flow animation, then frame 1 turned about the
//! frame's centre by the angle the vortex has turned it at frames 1, 6, 15, 30, 45 and 60
//! (STRENGTH pixels per frame at half the frame's side: STRENGTH / (SIZE / 2) radians a frame),
//! resampled once by the animation's warp (Catmull-Rom). Prints the flat fraction and coherence of
//! the central square that stays inside the frame at every angle, against the same square of
//! frame 1 unturned; the exemplar turned likewise, against frame 1's coherence.
//!
//! An animation that follows the flow exactly is frame 1 turned, so these ratios are where the
//! coherence of a perfectly followed vortex ends up, with no blur from repeated warps and no flow
//! energy beyond one resampling's: the other end of the frontier that `flow_detail`'s lambda sweep
//! moves along.

#[path = "shared/vortex_frame.rs"]
mod vortex_frame;

use texsynth::core::{Edge, Image};
use texsynth::methods::flow::FlowField;
use texsynth::methods::flow::warp::warp;
use texsynth::methods::quality::quality;
use vortex_frame::vortex_frame_one;

/// `image` turned by `angle` radians about its centre, by the animation's own warp (a field
/// whose backward step from every pixel is the exact turn back), cropped to the central `side`
/// x `side`.
fn turned(image: &Image, angle: f64, side: usize) -> Image {
    let (w, h) = (image.width(), image.height());
    let (cx, cy) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
    let (s, c) = angle.sin_cos();
    let field = FlowField::from_fn(w, h, |x, y| {
        let (px, py) = (f64::from(x) - cx, f64::from(y) - cy);
        // The warp reads q - f(q): f is q minus q turned back.
        let (sx, sy) = (c * px + s * py, -s * px + c * py);
        ((px - sx) as f32, (py - sy) as f32)
    })
    .expect("field");
    let turned = warp(image, &field, Edge::Clamp).expect("warp").image;
    turned
        .crop((w - side) / 2, (h - side) / 2, side, side)
        .expect("crop")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("tiles_128", String::as_str);
    let size: usize = args.get(1).map_or(256, |s| s.parse().expect("size"));
    let strength: f64 = args.get(2).map_or(2.0, |s| s.parse().expect("strength"));
    let seed = std::env::var("SEED").map_or(1, |v| v.parse().expect("number"));
    let (exemplar, _, frame) = vortex_frame_one(name, size, strength as f32, seed);
    let per_frame = strength / (size as f64 / 2.0);
    // The largest square inside the frame at every angle, with a 2-pixel margin for the sampler.
    let side = |n: usize| ((n as f64 / std::f64::consts::SQRT_2) as usize).saturating_sub(4);
    let (frame_side, exemplar_side) = (side(size), side(exemplar.width().min(exemplar.height())));
    let frame_0 = quality(&exemplar, &turned(&frame, 0.0, frame_side)).expect("quality");
    let exemplar_0 = quality(&exemplar, &turned(&exemplar, 0.0, exemplar_side)).expect("quality");
    println!(
        "{name}, frame {size}x{size} (centre {frame_side}x{frame_side}): frame 1 flat {:.3} coherence {:.6}; exemplar centre {exemplar_side}x{exemplar_side} flat {:.3} coherence {:.6}; {:.2} degrees a frame",
        frame_0.flat,
        frame_0.coherence,
        exemplar_0.flat,
        exemplar_0.coherence,
        per_frame.to_degrees()
    );
    for t in [1usize, 6, 15, 30, 45, 60] {
        let angle = per_frame * t as f64;
        let f = quality(&exemplar, &turned(&frame, angle, frame_side)).expect("quality");
        let e = quality(&exemplar, &turned(&exemplar, angle, exemplar_side)).expect("quality");
        println!(
            "frame {t:>2} ({:>5.1} deg): frame 1 turned: flat {:.3} ({:.2}x) coherence {:.6} ({:.2}x); exemplar turned: flat {:.3} coherence {:.6} ({:.2}x frame 1's)",
            angle.to_degrees(),
            f.flat,
            f.flat / frame_0.flat,
            f.coherence,
            f.coherence / frame_0.coherence,
            e.flat,
            e.coherence,
            e.coherence / frame_0.coherence,
        );
    }
}
