//! Every method with a camera-sized exemplar: `cargo run --release -p texsynth-bench --bin
//! large_exemplar`. Builds a 4000x3000 exemplar (a mosaic of the 128x128 samples, bilinearly
//! upscaled 4x with a gentle brightness ramp so no two tiles repeat exactly) and runs each method
//! to done at 512x512 (a couple of frames for flow; texture design's tileable and global
//! deformation work on the exemplar itself), printing total time, steps, the longest step and
//! the median step. `LARGE_SIZE=WxH`, `LARGE_OUTPUT=512` and `LARGE_METHODS=graphcut-entire,...`
//! change the case.

use std::time::Instant;

use texsynth::core::sample::resize_bilinear;
use texsynth::core::{Edge, Image, Result, decode};
use texsynth::methods::design::layers::{Layer, LayerDesign, LayerOptions};
use texsynth::methods::design::{Deformation, TileableOptions, TileableSession, deform};
use texsynth::methods::features::{FeatureOptions, FeatureSynthesis};
use texsynth::methods::flow::{
    Component, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};
use texsynth::methods::{graphcut, optimization};

const SAMPLES: [&str; 8] = [
    "gravel_128",
    "rock_128",
    "dirt_128",
    "sand_128",
    "stone_128",
    "ballast_128",
    "grass_128",
    "paving_128",
];

fn exemplar(width: usize, height: usize) -> Image {
    let tiles: Vec<Image> = SAMPLES
        .iter()
        .map(|name| {
            let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
            decode(&std::fs::read(path).expect("sample")).expect("decodes")
        })
        .collect();
    // A mosaic a quarter of the size, tile k at (x, y) from sample (x + 3y) mod 8 ...
    let (mw, mh) = (width.div_ceil(4), height.div_ceil(4));
    let mosaic = Image::from_fn(mw, mh, 3, |x, y, c| {
        let (tx, ty) = (x / 128, y / 128);
        let tile = &tiles[(tx + 3 * ty) % tiles.len()];
        let v = tile.pixel(x % 128, y % 128)[c.min(tile.channels() - 1)];
        // ... with a slow brightness ramp, so that no two tiles are the same.
        (v * (0.85 + 0.3 * (x + 2 * y) as f32 / (mw + 2 * mh) as f32)).min(1.0)
    })
    .expect("size");
    // ... upscaled 4x, bilinearly, to the photo's size.
    resize_bilinear(&mosaic, width, height, Edge::Clamp).expect("resize")
}

/// Runs `step` until it reports done; returns (total ms, steps, longest ms, median ms).
fn run(mut step: impl FnMut() -> Result<bool>) -> Result<(f64, usize, f64, f64)> {
    let start = Instant::now();
    let mut times = Vec::new();
    loop {
        let t = Instant::now();
        let done = step()?;
        times.push(t.elapsed().as_secs_f64() * 1e3);
        if done {
            break;
        }
    }
    let total = start.elapsed().as_secs_f64() * 1e3;
    let n = times.len();
    times.sort_by(f64::total_cmp);
    Ok((total, n, times[n - 1], times[n / 2]))
}

fn main() {
    let (width, height) = std::env::var("LARGE_SIZE").map_or((4000, 3000), |v| {
        let (w, h) = v.split_once('x').expect("WxH");
        (w.parse().expect("W"), h.parse().expect("H"))
    });
    let size: usize = std::env::var("LARGE_OUTPUT").map_or(512, |v| v.parse().expect("size"));
    let methods = std::env::var("LARGE_METHODS").unwrap_or_else(|_| {
        "optimization,flow,graphcut-random,graphcut-entire,graphcut-sub,features,tileable,deform,layers"
            .into()
    });
    let t = Instant::now();
    let ex = exemplar(width, height);
    println!(
        "{width}x{height} exemplar (built in {:.0} ms), {size}x{size} output, native release",
        t.elapsed().as_secs_f64() * 1e3
    );
    println!(
        "{:<18} {:>10} {:>7} {:>12} {:>11}  setup ms",
        "method", "total ms", "steps", "longest ms", "median ms"
    );
    for method in methods.split(',') {
        let setup = Instant::now();
        let result = match method {
            "optimization" => optimization::Session::new(
                &ex,
                optimization::Options {
                    output_width: size,
                    output_height: size,
                    ..optimization::Options::default()
                },
            )
            .map(|mut s| {
                (
                    setup.elapsed(),
                    run(move || {
                        s.step()?;
                        Ok(s.is_done())
                    }),
                )
            }),
            "flow" => FlowSpec::new(vec![Component::new(FlowKind::Vortex, 1.0)]).and_then(|spec| {
                FlowSession::new(
                    &ex,
                    FlowSource::Generator(spec),
                    FlowOptions {
                        output_width: size,
                        output_height: size,
                        frames: 2,
                        ..FlowOptions::default()
                    },
                )
                .map(|mut s| {
                    (
                        setup.elapsed(),
                        run(move || {
                            s.step()?;
                            Ok(s.is_done())
                        }),
                    )
                })
            }),
            "graphcut-random" | "graphcut-entire" | "graphcut-sub" => {
                let placement = match method {
                    "graphcut-random" => graphcut::Placement::Random,
                    "graphcut-entire" => graphcut::Placement::EntirePatch,
                    _ => graphcut::Placement::SubPatch,
                };
                graphcut::Session::new(
                    &ex,
                    graphcut::Options {
                        placement,
                        output_width: size,
                        output_height: size,
                        ..graphcut::Options::default()
                    },
                )
                .map(|mut s| (setup.elapsed(), run(move || Ok(s.step()?.done))))
            }
            "features" => FeatureSynthesis::new(
                &ex,
                None,
                FeatureOptions {
                    output_width: size,
                    output_height: size,
                    ..FeatureOptions::default()
                },
            )
            .map(|mut s| (setup.elapsed(), run(move || Ok(s.step()?.done)))),
            "tileable" => TileableSession::new(&ex, TileableOptions::default())
                .map(|mut s| (setup.elapsed(), run(move || Ok(s.step()?.done)))),
            "deform" => Ok((
                setup.elapsed(),
                run(|| {
                    deform(
                        &ex,
                        &[
                            Deformation::Rotate { degrees: 30.0 },
                            Deformation::Scale { factor: 0.5 },
                            Deformation::Mirror,
                        ],
                    )
                    .map(|_| true)
                }),
            )),
            "layers" => LayerDesign::new(
                &[Layer {
                    texture: ex.clone(),
                    deformations: Vec::new(),
                }],
                &vec![0u8; size * size],
                LayerOptions {
                    output_width: size,
                    output_height: size,
                    ..LayerOptions::default()
                },
            )
            .map(|mut s| (setup.elapsed(), run(move || Ok(s.step()?.done)))),
            other => panic!("unknown method {other}"),
        };
        match result {
            Ok((setup, Ok((total, steps, longest, median)))) => println!(
                "{method:<18} {total:>10.0} {steps:>7} {longest:>12.1} {median:>11.1}  {:.0}",
                setup.as_secs_f64() * 1e3
            ),
            Ok((_, Err(e))) => println!("{method:<18} step failed: {e}"),
            Err(e) => println!("{method:<18} refused: {e}"),
        }
    }
}
