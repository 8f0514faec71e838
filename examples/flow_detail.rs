//! Do flow frames keep their detail? `cargo run --profile explore --example flow_detail --
//! [SAMPLE] [SIZE] [FRAMES]` (defaults: the page's `tiles_128 256 60`, a vortex of strength 2).
//! Prints frame 1's flat fraction, coherence and flow energy, the means over frames 30-60 and
//! their ratios to frame 1, beside the naive warp's; `WRITE=dir` writes frames 1 and the last as
//! PNGs, `ERRMAP=dir` the last frame's flow error per pixel (white: the 0.5% largest) and how
//! concentrated it is. Coherence is given plain and against the exemplar at half-pixel positions too
//! (`quality::sub_pixel_coherence`: sub-pixel matches place content between pixels). Options from the
//! environment: `HIST` (histogramMatching, 1), `LAMBDA` (0.2),
//! `FRAME_ITERATIONS` (3), `FRAME_SIZES` (the default, 32,16,8), `EVERY` (1); `KIND` and
//! `STRENGTH` pick another single flow (vortex, 2); `SUB_PIXEL=1` sub-pixel matches; `SEED`
//! the seed (1): the ratios move by about a tenth from seed to seed, so compare changes
//! over several.

use texsynth::core::{decode, encode_png};
use texsynth::methods::flow::{
    Component, FlowEventKind, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};
use texsynth::methods::quality::quality;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("tiles_128", String::as_str);
    let size: usize = args.get(1).map_or(256, |s| s.parse().expect("size"));
    let frames: usize = args.get(2).map_or(60, |s| s.parse().expect("frames"));
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let exemplar = decode(&std::fs::read(path).expect("sample")).expect("decodes");
    let flow = FlowSource::Generator(
        FlowSpec::new(vec![Component::new(
            std::env::var("KIND").map_or(FlowKind::Vortex, |k| {
                FlowKind::from_name(&k).expect("a flow kind")
            }),
            std::env::var("STRENGTH").map_or(2.0, |v| v.parse().expect("number")),
        )])
        .expect("spec"),
    );
    let options = FlowOptions {
        output_width: size,
        output_height: size,
        frames,
        histogram_matching: std::env::var("HIST").map_or(1.0, |v| v.parse().expect("number")),
        lambda: std::env::var("LAMBDA").map_or(0.2, |v| v.parse().expect("number")),
        frame_sizes: std::env::var("FRAME_SIZES").map_or(FlowOptions::default().frame_sizes, |v| {
            v.split(',').map(|s| s.parse().expect("size")).collect()
        }),
        sub_pixel: std::env::var("SUB_PIXEL").is_ok_and(|v| v == "1"),
        frame_iterations: std::env::var("FRAME_ITERATIONS")
            .map_or(3, |v| v.parse().expect("number")),
        seed: std::env::var("SEED").map_or(1, |v| v.parse().expect("number")),
        ..FlowOptions::default()
    };
    // `EVERY=n` measures only frame 1 and every n-th frame from 30 on (quicker sweeps).
    let every: usize = std::env::var("EVERY").map_or(1, |v| v.parse().expect("number"));
    let mut session = FlowSession::new(&exemplar, flow, options).expect("session");
    let start = std::time::Instant::now();
    let mut rows = Vec::new();
    loop {
        let event = session.step().expect("step");
        if matches!(event.kind, FlowEventKind::Frame | FlowEventKind::Done) {
            let frame = session.frame_image().expect("frame");
            let index = session.frame();
            if index == 1
                || (index >= 30 && index.is_multiple_of(every))
                || (every == 1 && index <= 6)
            {
                let q = quality(&exemplar, &frame).expect("quality");
                let sub = sub_pixel_coherence(&exemplar, &frame);
                rows.push((index, q.flat, q.coherence, event.flow_energy, sub));
                let naive = if every == 1 {
                    quality(&exemplar, &session.naive_image().expect("naive")).expect("quality")
                } else {
                    q
                };
                println!(
                    "frame {index:>3}: flat {:.3} coherence {:.5} (sub-pixel {sub:.5}) flow energy {:.5} (naive warp: flat {:.3} coherence {:.5})",
                    q.flat, q.coherence, event.flow_energy, naive.flat, naive.coherence
                );
            }
            if let (Ok(dir), Some(c), true) = (
                std::env::var("ERRMAP"),
                session.warped_previous(),
                index == frames,
            ) {
                error_map(&frame, c, &format!("{dir}/{name}-{size}-error{index}.png"));
            }
            if let (Ok(dir), true) = (std::env::var("WRITE"), index == 1 || index == frames) {
                let png = encode_png(&frame).expect("png");
                std::fs::write(format!("{dir}/{name}-{size}-frame{index}.png"), png)
                    .expect("write");
            }
        }
        if event.kind == FlowEventKind::Done {
            break;
        }
    }
    let later: Vec<_> = rows.iter().filter(|r| r.0 >= 30).collect();
    let mean = |f: fn(&(usize, f64, f64, f64, f64)) -> f64| {
        later.iter().map(|r| f(r)).sum::<f64>() / later.len() as f64
    };
    let first = rows[0];
    let (flat, coherence, flow, sub) = (mean(|r| r.1), mean(|r| r.2), mean(|r| r.3), mean(|r| r.4));
    println!(
        "{name} {size}x{size}: frames 30-{frames} mean flat {flat:.3} ({:.2}x frame 1), coherence {coherence:.5} ({:.2}x), sub-pixel coherence {sub:.5} ({:.2}x), flow energy {flow:.5}; {:.1} s",
        flat / first.1,
        coherence / first.2,
        sub / first.4,
        start.elapsed().as_secs_f64()
    );
}

/// Coherence against the exemplar at half-pixel positions too (native only, like the metric).
#[cfg(not(target_arch = "wasm32"))]
fn sub_pixel_coherence(exemplar: &texsynth::core::Image, frame: &texsynth::core::Image) -> f64 {
    texsynth::methods::quality::sub_pixel_coherence(exemplar, frame).expect("quality")
}

#[cfg(target_arch = "wasm32")]
fn sub_pixel_coherence(_: &texsynth::core::Image, _: &texsynth::core::Image) -> f64 {
    f64::NAN
}

/// Writes the per-pixel flow error (squared difference to the warped previous frame, as a
/// grey level) and prints how concentrated it is.
fn error_map(
    frame: &texsynth::core::Image,
    c: &texsynth::methods::optimization::constraints::Constraint,
    path: &str,
) {
    let ch = frame.channels();
    let errs: Vec<f64> = frame
        .data()
        .chunks(ch)
        .zip(c.target.data().chunks(ch))
        .zip(&c.mask)
        .map(|((a, b), &m)| {
            if m > 0.0 {
                a.iter()
                    .zip(b)
                    .take(3)
                    .map(|(x, y)| f64::from(x - y).powi(2))
                    .sum::<f64>()
                    / 3.0
            } else {
                0.0
            }
        })
        .collect();
    let total: f64 = errs.iter().sum();
    let mut sorted = errs.clone();
    sorted.sort_by(|a, b| b.partial_cmp(a).unwrap());
    let n = sorted.len();
    let share = |f: f64| sorted[..(n as f64 * f) as usize].iter().sum::<f64>() / total;
    println!(
        "flow error: mean {:.5}; top 5% of pixels carry {:.2}, top 10% {:.2}, top 25% {:.2}, top 50% {:.2}",
        total / n as f64,
        share(0.05),
        share(0.1),
        share(0.25),
        share(0.5)
    );
    let max = sorted[n / 200].max(1e-9);
    let img = texsynth::core::Image::from_fn(frame.width(), frame.height(), 1, |x, y, _| {
        (errs[y * frame.width() + x] / max).min(1.0) as f32
    })
    .expect("image");
    std::fs::write(path, texsynth::core::encode_png(&img).expect("png")).expect("write");
}
