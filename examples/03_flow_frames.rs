//! Flow-guided texture animation (Kwatra et al. 2005, section 4.1): frames that follow a
//! vortex, each made by texture optimisation with the warped previous frame as a soft
//! constraint.
//!
//! ```sh
//! cargo run --release --example 03_flow_frames -- www/samples/tiles_64.png /tmp/out
//! ```
//!
//! writes `frame01.png` to `frame08.png`.

#[path = "shared/args.rs"]
mod args;

use texsynth::{Session, flow};

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("03_flow_frames")?;
    // A vortex turning at 2 pixels per frame half way from the centre to the border; other
    // kinds (sink, source, shear, translation) add up as components.
    let vortex = flow::FlowSpec::new(vec![flow::Component::new(flow::FlowKind::Vortex, 2.0)])?;
    let options = flow::Options {
        output_width: 96,
        output_height: 96,
        frames: 8,
        seed: 1,
        ..Default::default()
    };
    let mut session = flow::Session::new(&exemplar, flow::FlowSource::Generator(vortex), options)?;
    while !session.is_done() {
        let event = session.step()?;
        // A frame is finished on its last iteration: render it then to keep it.
        if matches!(event.kind, flow::EventKind::Frame | flow::EventKind::Done) {
            println!(
                "frame {}: texture energy {:.4}, flow energy {:.4}",
                event.frame + 1,
                event.texture_energy,
                event.flow_energy
            );
            args::save(
                &folder,
                &format!("frame{:02}.png", event.frame + 1),
                &Session::output(&session)?,
            )?;
        }
    }
    Ok(())
}
