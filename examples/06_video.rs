//! Graph-cut video textures (Kwatra et al. 2003, section 7.A): an endless loop from a clip, cut
//! along the seam surface through space and time where the clip's end matches its start best.
//!
//! ```sh
//! cargo run --release --example 06_video -- /tmp/out
//! ```
//!
//! makes its own clip (ripples travelling across a 48x48 frame for 40 frames, with a drift that
//! keeps the last frame from matching the first) and writes the loop's frames as
//! `loop01.png`, `loop02.png`, ...

use std::path::{Path, PathBuf};

use texsynth::{Image, video};

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let folder = std::env::args().nth(1).map_or_else(
        || Path::new("target/examples/06_video").to_path_buf(),
        PathBuf::from,
    );
    std::fs::create_dir_all(&folder)?;
    // A clip is a volume of RGB voxels in 0..1; `Volume::from_rgba_frames` takes decoded frames.
    let clip = video::Volume::from_fn(48, 48, 40, |x, y, t| {
        let (x, y, t) = (x as f32, y as f32, t as f32);
        let wave = (0.35 * x + 0.2 * y - 0.4 * t).sin() * (0.15 * y - 0.3 * t + 0.02 * t * t).cos();
        let v = 0.5 + 0.4 * wave;
        [0.2 * v, 0.4 + 0.3 * v, 0.6 + 0.4 * v]
    })?;
    let mut session = video::Session::new(
        clip,
        video::Options {
            mode: video::Mode::Loop,
            ..Default::default()
        },
    )?;
    while !session.is_done() {
        let event = session.step()?;
        println!("{event:?}");
    }
    let (w, h, frames) = session.size();
    for t in 0..frames {
        let rgb = session.frame(t);
        let frame = Image::from_fn(w, h, 3, |x, y, c| rgb[(y * w + x) * 3 + c])?;
        std::fs::write(
            folder.join(format!("loop{:02}.png", t + 1)),
            texsynth::encode_png(&frame)?,
        )?;
    }
    println!("{frames} frames of {w}x{h} in {}", folder.display());
    Ok(())
}
