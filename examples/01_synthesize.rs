//! A texture twice the exemplar's size, by texture optimisation and by graph-cut textures:
//!
//! ```sh
//! cargo run --release --example 01_synthesize -- www/samples/tiles_64.png /tmp/out
//! ```
//!
//! Every method is a session: built from the exemplar and its options, stepped until done. A
//! viewer would draw `session.output()` after each step to watch the texture form.

#[path = "shared/args.rs"]
mod args;

use texsynth::{Image, Result, Session, graphcut, optimization};

/// Steps a session until it is done and returns its output.
fn run<S: Session>(mut session: S) -> Result<Image> {
    while !session.is_done() {
        session.step()?;
    }
    session.output()
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("01_synthesize")?;
    let (width, height) = (2 * exemplar.width(), 2 * exemplar.height());

    // Texture optimisation: EM over overlapping neighbourhoods, coarse to fine.
    let options = optimization::Options {
        output_width: width,
        output_height: height,
        seed: 1,
        ..Default::default()
    };
    let mut session = optimization::Session::new(&exemplar, options)?;
    while !session.is_done() {
        let event = session.step()?;
        println!(
            "optimization: {:?} level {} energy {:.4}",
            event.kind, event.level, event.energy
        );
    }
    args::save(&folder, "optimization.png", &Session::output(&session)?)?;

    // Graph-cut textures: whole patches joined along minimum-cost seams.
    let options = graphcut::Options {
        output_width: width,
        output_height: height,
        placement: graphcut::Placement::SubPatch,
        seed: 1,
        ..Default::default()
    };
    args::save(
        &folder,
        "graphcut.png",
        &run(graphcut::Session::new(&exemplar, options)?)?,
    )?;
    Ok(())
}
