//! Makes an exemplar cyclic (Shen et al. 2009, section 4): two graph-cut stitches, one across
//! the columns and one across the rows, so that copies of the result meet without a seam.
//!
//! ```sh
//! cargo run --release --example 02_tileable -- www/samples/brick_128.png /tmp/out
//! ```
//!
//! writes `tileable.png` and `tiled.png`, 2x2 copies of it side by side, to look at the joins.

#[path = "shared/args.rs"]
mod args;

use texsynth::Image;
use texsynth::design::tileable;

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, folder) = args::exemplar_and_folder("02_tileable")?;
    let mut session = tileable::Session::new(&exemplar, tileable::Options::default())?;
    while !session.is_done() {
        let event = session.step()?;
        println!("stitch: {event:?}");
    }
    let result = session
        .result()
        .ok_or("the session finished without a result")?;
    println!(
        "cut open at column {} and row {}; seam costs {:.3} and {:.3}",
        result.cut_x, result.cut_y, result.seam_cost_x, result.seam_cost_y
    );
    let image = &result.image;
    args::save(&folder, "tileable.png", image)?;

    // Four copies: a seam across the wrap-around edges would show as a cross in the middle.
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let tiled = Image::from_fn(2 * w, 2 * h, c, |x, y, k| image.pixel(x % w, y % h)[k])?;
    args::save(&folder, "tiled.png", &tiled)?;
    Ok(())
}
