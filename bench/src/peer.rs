//! The peer: the texture-synthesis crate (Embark Studios, 0.8.2), a multi-resolution patch-based
//! synthesizer, with its default settings, as many threads as texsynth is given, and the same exemplar pixels, output size
//! and seed as texsynth's methods. It uses image 0.23, so pixels cross as raw RGBA8 bytes.

use std::time::Instant;

use texsynth::core::{Image, from_rgba8, to_rgba8};
use texture_synthesis as ts;
use ts::image as image023;

use crate::methods::{Run, ms};

pub fn run(
    exemplar: &Image,
    (width, height): (usize, usize),
    seed: u64,
    threads: usize,
) -> Result<Run, String> {
    // The conversion to the peer's image type is input preparation, like decoding: not timed.
    let rgba = to_rgba8(exemplar);
    let input =
        image023::RgbaImage::from_raw(exemplar.width() as u32, exemplar.height() as u32, rgba)
            .ok_or("exemplar buffer does not match its size")?;
    let input = image023::DynamicImage::ImageRgba8(input);

    let start = Instant::now();
    // build() makes the exemplar pyramids (the counterpart of texsynth's Session::new), run()
    // synthesises; both are timed. The peer gets the threads texsynth gets; on one thread it is
    // also deterministic.
    let session = ts::Session::builder()
        .add_example(input)
        .output_size(ts::Dims::new(width as u32, height as u32))
        .seed(seed)
        .max_thread_count(threads)
        .build()
        .map_err(|e| format!("texture-synthesis: {e}"))?;
    let generated = session.run(None);
    let total_ms = ms(start);

    let out = generated.into_image().to_rgba8();
    let output = from_rgba8(out.width() as usize, out.height() as usize, out.as_raw())
        .map_err(|e| e.to_string())?;
    Ok(Run {
        total_ms,
        // The peer's run is one call: there are no steps a user could show or interrupt.
        steps: 0,
        max_step_ms: total_ms,
        output,
        seams: None,
    })
}
