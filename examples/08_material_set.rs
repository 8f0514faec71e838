//! A material set: an albedo and its normal map synthesised together. The normal map is made
//! from the exemplar's luminance (as a height field), the albedo is synthesised by graph cut, and
//! the output's source map carries the normal map along, so the two line up pixel for pixel.
//!
//! ```sh
//! cargo run --release --example 08_material_set -- www/samples/brick_128.png /tmp/out
//! ```
//!
//! writes `albedo.png`, `normal.png` and `set.png` (the two side by side).

#[path = "shared/args.rs"]
mod args;

use texsynth::{Image, Session, graphcut};

/// A tangent-space normal map of `image` read as a height field (its luminance), encoded as
/// RGB in 0..1: n = (-dh/dx, -dh/dy, 1) / |...| mapped by n / 2 + 1 / 2.
fn normal_map(image: &Image, strength: f32) -> Result<Image, texsynth::Error> {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let height = |x: usize, y: usize| {
        let p = image.pixel(x, y);
        if c >= 3 {
            0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]
        } else {
            p[0]
        }
    };
    Image::from_fn(w, h, 3, |x, y, k| {
        let dx = height((x + 1).min(w - 1), y) - height(x.saturating_sub(1), y);
        let dy = height(x, (y + 1).min(h - 1)) - height(x, y.saturating_sub(1));
        let n = [-dx * strength, -dy * strength, 1.0];
        let length = (n[0] * n[0] + n[1] * n[1] + 1.0).sqrt();
        n[k] / length * 0.5 + 0.5
    })
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("08_material_set")?;
    let normals = normal_map(&exemplar, 4.0)?;
    let options = graphcut::Options {
        output_width: 2 * exemplar.width(),
        output_height: 2 * exemplar.height(),
        ..graphcut::Options::default()
    };
    let mut session = graphcut::Session::new(&exemplar, options)?;
    while !Session::is_done(&session) {
        Session::step(&mut session)?;
    }
    let albedo = Session::output(&session)?.with_channels(3)?;
    // The source map re-indexes: each output pixel takes the normal of the exemplar pixel it
    // shows, so the normals stay unit vectors and follow the albedo across every seam.
    let normal = session.source_map()?.transfer(&normals)?;
    args::save(&folder, "albedo.png", &albedo)?;
    args::save(&folder, "normal.png", &normal)?;
    let (w, h) = (albedo.width(), albedo.height());
    let set = Image::from_fn(2 * w, h, 3, |x, y, k| {
        if x < w {
            albedo.pixel(x, y)[k]
        } else {
            normal.pixel(x - w, y)[k]
        }
    })?;
    args::save(&folder, "set.png", &set)?;
    Ok(())
}
