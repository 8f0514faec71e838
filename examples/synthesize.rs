//! Makes a texture from a PNG or JPEG with each method, using only the crate's public surface:
//!
//! ```sh
//! cargo run --release --example synthesize -- www/samples/tiles_64.png /tmp/out
//! ```
//!
//! writes `optimization.png`, `graphcut.png`, `features.png`, `flow.png` (the last frame of a
//! short animation), `layers.png` and `tileable.png` into the output folder.

use std::path::Path;

use texsynth::design::{layers, tileable};
use texsynth::{
    Image, Result, Session, decode, encode_png, features, flow, graphcut, optimization,
};

/// Steps a session until it is done and returns its output.
fn run<S: Session>(mut session: S) -> Result<Image> {
    while !session.is_done() {
        session.step()?;
    }
    session.output()
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let (Some(input), Some(out)) = (args.get(1), args.get(2)) else {
        return Err("usage: synthesize INPUT.png OUTPUT_DIR".into());
    };
    let exemplar = decode(&std::fs::read(input)?)?;
    let out = Path::new(out);
    std::fs::create_dir_all(out)?;
    let save = |name: &str, image: &Image| -> std::result::Result<(), Box<dyn std::error::Error>> {
        std::fs::write(out.join(name), encode_png(image)?)?;
        println!("{}: {}x{}", name, image.width(), image.height());
        Ok(())
    };

    let options = optimization::Options {
        output_width: 192,
        output_height: 192,
        ..Default::default()
    };
    save(
        "optimization.png",
        &run(optimization::Session::new(&exemplar, options)?)?,
    )?;

    let options = graphcut::Options {
        output_width: 192,
        output_height: 192,
        ..Default::default()
    };
    save(
        "graphcut.png",
        &run(graphcut::Session::new(&exemplar, options)?)?,
    )?;

    let options = features::Options {
        output_width: 192,
        output_height: 192,
        ..Default::default()
    };
    save(
        "features.png",
        &run(features::Session::new(&exemplar, None, options)?)?,
    )?;

    let vortex = flow::FlowSpec::new(vec![flow::Component::new(flow::FlowKind::Vortex, 2.0)])?;
    let options = flow::Options {
        frames: 4,
        ..Default::default()
    };
    let animation = flow::Session::new(&exemplar, flow::FlowSource::Generator(vortex), options)?;
    save("flow.png", &run(animation)?)?;

    let layer = layers::Layer {
        texture: exemplar.clone(),
        deformations: vec![],
    };
    let options = layers::Options {
        output_width: 192,
        output_height: 192,
        patch_size: 24.min(exemplar.width()).min(exemplar.height()),
        ..Default::default()
    };
    let layout = vec![0u8; 192 * 192];
    save(
        "layers.png",
        &run(layers::Session::new(&[layer], &layout, options)?)?,
    )?;

    save(
        "tileable.png",
        &run(tileable::Session::new(
            &exemplar,
            tileable::Options::default(),
        )?)?,
    )?;
    Ok(())
}
