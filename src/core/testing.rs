//! Test-only helpers shared by the unit tests of every layer.

use super::{Image, Rng, decode};

/// A sample texture from `www/samples/` (e.g. "gravel_64"), decoded.
pub fn sample(name: &str) -> Image {
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    decode(&std::fs::read(path).expect("the sample exists")).expect("the sample decodes")
}

/// Uniform noise in 0..1, `channels` per pixel.
pub fn noise(width: usize, height: usize, channels: usize, seed: u64) -> Image {
    let mut rng = Rng::new(seed);
    Image::from_fn(width, height, channels, |_, _, _| rng.next_f32()).expect("valid size")
}
