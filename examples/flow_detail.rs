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
//!
//! `BOUND=1` also prints, for every measured frame, the least flow energy that any frame as
//! coherent as 1.3x frame 1 could have against that frame's warp target, whatever its content
//! (see [`FlowBound`]), and checks that the frame made obeys the same bound at its own coherence.

use texsynth::core::Image;
use texsynth::core::{decode, encode_png};
use texsynth::methods::flow::{
    Component, FlowEventKind, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};
use texsynth::methods::optimization::constraints::Constraint;
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
    let bound = std::env::var("BOUND").is_ok_and(|v| v == "1");
    let (mut first_coherence, mut bounds) = (f64::NAN, Vec::new());
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
                if let (true, Some(c)) = (bound, session.warped_previous()) {
                    let b = FlowBound::new(&exemplar, c);
                    let goal = 1.3 * first_coherence;
                    let (made, least_made) = (b.energy(&frame), b.least_energy(q.coherence));
                    assert!(
                        made >= least_made * (1.0 - 1e-9),
                        "the bound fails its own frame"
                    );
                    bounds.push((index, b.least_energy(goal)));
                    println!(
                        "           bound: warp target coherence {:.5} ({:.2}x frame 1); least RGB flow energy at coherence 1.3x frame 1: {:.5}; at this frame's coherence {least_made:.5} (made {made:.5})",
                        b.target_coherence,
                        b.target_coherence / first_coherence,
                        b.least_energy(goal),
                    );
                }
                if index == 1 {
                    first_coherence = q.coherence;
                }
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
    let later: Vec<f64> = bounds.iter().filter(|b| b.0 >= 30).map(|b| b.1).collect();
    if !later.is_empty() {
        println!(
            "bound: frames 30-{frames}, mean least RGB flow energy of a frame 1.3x as coherent as frame 1: {:.5} (frames made: {flow:.5})",
            later.iter().sum::<f64>() / later.len() as f64
        );
    }
}

/// How close to the warp target W can any frame X lie whose coherence is c, whatever its
/// content? Patch by patch (the coherence's own patches p, 7x7 at stride 2, those wholly inside
/// the mask: the set Q), the triangle inequality gives sqrt(d_W(p)) <= sqrt(a(p)) + sqrt(d_X(p)),
/// with d the per-value squared distance to the nearest exemplar patch and a(p) the per-value
/// squared distance between X and W over p. Minkowski's inequality carries that to the means over
/// Q. The mean of d_X over Q is at most c P / |Q| (P all the coherence's patches), and the mean of
/// a over Q is at most 16 M e / (49 |Q|): a pixel lies in at most 16 of the patches, and e is the
/// per-value mean over the M masked pixels. So
///
///   e >= 49 |Q| / (16 M) * max(0, sqrt(mean_Q d_W) - sqrt(c P / |Q|))^2.
///
/// It is a lower bound, not an estimate: nothing about how a frame is made enters, and the
/// frame made must obey it at its own coherence (checked).
struct FlowBound {
    /// Coherence of W itself (mean of d_W over all the coherence's patches).
    target_coherence: f64,
    /// Mean of d_W over Q.
    inside_target: f64,
    patches: f64,
    inside_patches: f64,
    masked: f64,
    target: Image,
    mask: Vec<f32>,
}

impl FlowBound {
    fn new(exemplar: &Image, c: &Constraint) -> Self {
        let w = c.target.width();
        assert!(
            c.mask.iter().all(|&m| m == 0.0 || m == 1.0),
            "a mask of 0 and 1"
        );
        let by_patch =
            texsynth::methods::quality::coherence_by_patch(exemplar, &c.target).expect("quality");
        let patch = texsynth::methods::quality::PATCH;
        let inside: Vec<f64> = by_patch
            .iter()
            .filter(|&&(x, y, _)| {
                (y..y + patch).all(|yy| (x..x + patch).all(|xx| c.mask[yy * w + xx] == 1.0))
            })
            .map(|p| p.2)
            .collect();
        FlowBound {
            target_coherence: by_patch.iter().map(|p| p.2).sum::<f64>() / by_patch.len() as f64,
            inside_target: inside.iter().sum::<f64>() / inside.len() as f64,
            patches: by_patch.len() as f64,
            inside_patches: inside.len() as f64,
            masked: c.mask.iter().filter(|&&m| m == 1.0).count() as f64,
            target: c.target.with_channels(3).expect("rgb"),
            mask: c.mask.clone(),
        }
    }

    /// The least per-value RGB flow energy of a frame with this coherence.
    fn least_energy(&self, coherence: f64) -> f64 {
        let gap = (self.inside_target.sqrt()
            - (coherence * self.patches / self.inside_patches).sqrt())
        .max(0.0);
        49.0 * self.inside_patches / (16.0 * self.masked) * gap * gap
    }

    /// A frame's per-value RGB flow energy over the masked pixels (the animation's, when the
    /// frames are RGB).
    fn energy(&self, frame: &Image) -> f64 {
        let frame = frame.with_channels(3).expect("rgb");
        let sum: f64 = frame
            .data()
            .chunks(3)
            .zip(self.target.data().chunks(3))
            .zip(&self.mask)
            .filter(|(_, m)| **m == 1.0)
            .map(|((a, b), _)| {
                a.iter()
                    .zip(b)
                    .map(|(x, y)| f64::from(x - y).powi(2))
                    .sum::<f64>()
            })
            .sum();
        sum / (3.0 * self.masked)
    }
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
