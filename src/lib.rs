//! # texsynth
//!
//! Texture synthesis from a small example image, in Rust compiled to WebAssembly, built as
//! progressive-refinement sessions so a page can show every step live.
//!
//! The module tree mirrors the layers of the design:
//!
//! - [`core`]: image buffers, decoding/encoding, resampling, pyramids, gradients, seeded RNG, errors;
//! - [`bindings`]: the JavaScript-facing types (`wasm-bindgen`), the only layer that knows about JS.
//!
//! Layers 2 (solvers) and 3 (methods) arrive with the methods that use them.

pub mod bindings;
pub mod core;
pub mod methods;
pub mod solvers;
