//! Layer 1: image buffers, decoding and encoding, resampling, pyramids, gradients, the seeded RNG
//! and the error type, the memory budget and a clock. Plain Rust with no JavaScript in sight (the
//! clock reads JavaScript's `Date` in wasm, where `std::time` has none).

pub mod budget;
pub mod clock;
pub mod codec;
pub mod error;
pub mod gradient;
pub mod image;
pub mod math;
pub mod parallel;
pub mod power;
pub mod pyramid;
pub mod rng;
pub mod sample;
#[cfg(test)]
pub mod testing;

pub use codec::{decode, encode_png, from_rgba8, to_rgba8, write_rgba8};
pub use error::{Error, Result};
pub use image::Image;
pub use rng::Rng;
pub use sample::Edge;
