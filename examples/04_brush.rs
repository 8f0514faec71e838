//! The texture brush (Shen et al. 2009, section 3.2): paint part of one texture onto another;
//! a graph cut finds where the painted patch should end, and a Poisson paste hides the join.
//! Every stroke can be undone.
//!
//! ```sh
//! cargo run --release --example 04_brush -- www/samples/tiles_64.png /tmp/out www/samples/brick_64.png
//! ```
//!
//! writes `base.png` (a graph-cut texture made from the exemplar), `stroke1.png` (a round
//! stroke of the brick texture), `stroke2.png` (a second stroke) and `undone.png`
//! (the second undone: the same pixels as `stroke1.png`).

#[path = "shared/args.rs"]
mod args;

use texsynth::design::{BrushOptions, LocalDeformation, Stroke};
use texsynth::{Session, graphcut};

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("04_brush")?;
    let (w, h) = (2 * exemplar.width(), 2 * exemplar.height());
    let options = graphcut::Options {
        output_width: w,
        output_height: h,
        seed: 1,
        ..Default::default()
    };
    let mut base = graphcut::Session::new(&exemplar, options)?;
    while !base.is_done() {
        base.step()?;
    }
    let base = Session::output(&base)?;
    args::save(&folder, "base.png", &base)?;

    // What the brush paints from: another texture (the third argument, default the 64x64 brick
    // sample).
    let path = std::env::args()
        .nth(3)
        .unwrap_or_else(|| "www/samples/brick_64.png".into());
    let reference = texsynth::decode(&std::fs::read(&path).map_err(|e| format!("{path}: {e}"))?)?;
    let (ew, eh) = (reference.width(), reference.height());
    // A disc over the reference's middle, as a painted stroke would mark it.
    let radius = ew.min(eh) as f32 / 3.0;
    let disc: Vec<bool> = (0..ew * eh)
        .map(|i| {
            ((i % ew) as f32 - ew as f32 / 2.0).hypot((i / ew) as f32 - eh as f32 / 2.0) < radius
        })
        .collect();

    let mut brush = LocalDeformation::new(&base, BrushOptions::default())?;
    // A reference pixel (x, y) lands on the base at (x + dx, y + dy).
    let first = brush.stroke(&Stroke {
        reference: &reference,
        mask: &disc,
        dx: 8,
        dy: 8,
    })?;
    println!(
        "stroke 1: window {}x{} at ({}, {}), energy {:.3}",
        first.width, first.height, first.x, first.y, first.energy
    );
    args::save(&folder, "stroke1.png", brush.image())?;
    let after_first = brush.image().clone();
    let offset = (w / 2) as isize;
    brush.stroke(&Stroke {
        reference: &reference,
        mask: &disc,
        dx: offset,
        dy: offset,
    })?;
    args::save(&folder, "stroke2.png", brush.image())?;
    brush.undo();
    assert_eq!(
        brush.image(),
        &after_first,
        "undo gives back the image of the first stroke"
    );
    args::save(&folder, "undone.png", brush.image())?;
    Ok(())
}
