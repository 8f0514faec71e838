//! Feature-guided synthesis (Wu & Yu 2004): detect the exemplar's curvilinear features, then
//! synthesise with a cost that keeps those curves joined across patches.
//!
//! ```sh
//! cargo run --release --example 05_features -- www/samples/paving_128.png /tmp/out
//! ```
//!
//! writes `features.png` (the exemplar's feature map: white where a feature pixel is) and
//! `synthesis.png`.

#[path = "shared/args.rs"]
mod args;

use texsynth::{Image, Session, features};

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("05_features")?;
    // Ridges and valleys above the 90th percentile of the detector's response, followed down to
    // alpha times that threshold where they continue a curve.
    let map = features::detect(&exemplar, features::DetectOptions::default())?;
    println!(
        "{} feature pixels of {}",
        map.count(),
        map.width * map.height
    );
    let shown = Image::from_fn(map.width, map.height, 1, |x, y, _| {
        if map.mask[y * map.width + x] {
            1.0
        } else {
            0.0
        }
    })?;
    args::save(&folder, "features.png", &shown)?;

    let options = features::Options {
        output_width: 2 * exemplar.width(),
        output_height: 2 * exemplar.height(),
        seed: 1,
        ..Default::default()
    };
    // A map of your own (edited, or detected with other options) goes in place of `None`.
    let mut session = features::Session::new(&exemplar, Some(map), options)?;
    while !session.is_done() {
        let event = session.step()?;
        println!(
            "patch {}/{} from ({}, {}): feature cost {:.3}, colour cost {:.4}",
            event.patch + 1,
            event.patches,
            event.source_x,
            event.source_y,
            event.feature_cost,
            event.colour_cost
        );
    }
    args::save(&folder, "synthesis.png", &Session::output(&session)?)?;
    Ok(())
}
