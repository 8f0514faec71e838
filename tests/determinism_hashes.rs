//! Prints the FNV-1a hash of the RGBA output of each determinism case, natively, one
//! `name hash` line per case: `tests/node/determinism.test.mjs` runs the same cases (same names,
//! same samples, same options) in the wasm package and compares the lines. Keep the two lists
//! in step; a case missing on either side fails the test.
//!
//! `cargo test --test determinism_hashes`

use texsynth::design::Deformation;
use texsynth::design::layers::{self, Layer};
use texsynth::flow::{self, Component, FlowKind, FlowSource, FlowSpec};
use texsynth::{Image, decode, features, graphcut, optimization, to_rgba8};

fn sample(name: &str) -> Image {
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    decode(&std::fs::read(&path).expect("sample")).expect("decodes")
}

/// 32-bit FNV-1a, as the JS side computes it.
fn fnv1a(bytes: &[u8]) -> u32 {
    bytes.iter().fold(0x811c_9dc5, |h, &b| {
        (h ^ u32::from(b)).wrapping_mul(0x0100_0193)
    })
}

fn optimization(name: &str, energy: optimization::Energy, side: usize) -> u32 {
    let small = side <= 48;
    let d = optimization::Options::default();
    let options = optimization::Options {
        output_width: side,
        output_height: side,
        seed: 3,
        neighbourhood_sizes: if small {
            vec![16, 8]
        } else {
            d.neighbourhood_sizes.clone()
        },
        iterations: if small { 3 } else { d.iterations },
        energy,
        ..d
    };
    let mut s = optimization::Session::new(&sample(name), options).expect("session");
    while !s.is_done() {
        s.step().expect("step");
    }
    fnv1a(&to_rgba8(&s.output_full_size().expect("output")))
}

fn graphcut(name: &str) -> u32 {
    let options = graphcut::Options {
        output_width: 96,
        output_height: 96,
        seed: 3,
        refinement_patches: 4,
        ..graphcut::Options::default()
    };
    let mut s = graphcut::Session::new(&sample(name), options).expect("session");
    while !s.is_done() {
        s.step().expect("step");
    }
    fnv1a(&to_rgba8(&s.output().expect("output")))
}

fn features(name: &str) -> u32 {
    let options = features::Options {
        output_width: 96,
        output_height: 96,
        patch_size: Some(32),
        seed: 3,
        ..features::Options::default()
    };
    let mut s = features::Session::new(&sample(name), None, options).expect("session");
    while !s.is_done() {
        s.step().expect("step");
    }
    fnv1a(&to_rgba8(s.image()))
}

fn layers(name: &str) -> u32 {
    let options = layers::Options {
        output_width: 96,
        output_height: 96,
        patch_size: 16,
        seed: 3,
        ..layers::Options::default()
    };
    let layer = Layer {
        texture: sample(name),
        deformations: vec![Deformation::Rotate { degrees: 30.0 }],
    };
    let layout = vec![0u8; 96 * 96];
    let mut s = layers::Session::new(&[layer], &layout, options).expect("session");
    while !s.is_done() {
        s.step().expect("step");
    }
    fnv1a(&to_rgba8(s.image()))
}

/// Three frames of flow animation (a vortex of strength 2, the default flow): the frames
/// after the first run the M-step under the soft constraint of the warped previous frame.
fn flow(name: &str) -> u32 {
    let options = flow::Options {
        output_width: 48,
        output_height: 48,
        frames: 3,
        seed: 3,
        ..flow::Options::default()
    };
    let vortex = FlowSpec::new(vec![Component::new(FlowKind::Vortex, 2.0)]).expect("flow");
    let mut s =
        flow::Session::new(&sample(name), FlowSource::Generator(vortex), options).expect("session");
    while !s.is_done() {
        s.step().expect("step");
    }
    fnv1a(&to_rgba8(&s.frame_image().expect("frame")))
}

fn main() {
    use optimization::Energy::{Haar, Pixels};
    if std::env::args().any(|a| a == "--large") {
        // The README's comparison size class: default schedule, 128x128 from the 128 samples.
        for name in [
            "gravel_128",
            "tiles_128",
            "brick_128",
            "roof_128",
            "carpet_128",
            "squares_128",
        ] {
            println!(
                "optimization-large/{name} {:08x}",
                optimization(name, Pixels, 128)
            );
        }
        return;
    }
    for name in ["gravel_64", "tiles_64", "brick_64", "grass_64"] {
        println!("optimization/{name} {:08x}", optimization(name, Pixels, 48));
    }
    // The default schedule and IRLS weights (r = 0.8, powf in every E-step): the robust weights
    // go through core::math, so these agree between native and wasm.
    for name in ["carpet_64", "squares_64"] {
        println!(
            "optimization-default/{name} {:08x}",
            optimization(name, Pixels, 96)
        );
    }
    println!(
        "optimization-haar/sand_64 {:08x}",
        optimization("sand_64", Haar, 48)
    );
    for name in ["gravel_64", "tiles_64"] {
        println!("graphcut/{name} {:08x}", graphcut(name));
    }
    println!("features/paving_64 {:08x}", features("paving_64"));
    println!("layers/brick_64 {:08x}", layers("brick_64"));
    println!("flow/gravel_64 {:08x}", flow("gravel_64"));
}
