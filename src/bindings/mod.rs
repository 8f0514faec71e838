//! Layer 4: the only code that knows about JavaScript. Each file wraps one JS-visible type; inputs
//! are validated here and every failure becomes a JS `Error` whose message names the problem.

mod design;
mod error;
mod exemplar;
mod features;
mod flow;
mod graphcut;
mod merge;
mod optimization;
mod options;
mod pixels;
mod quality;
mod schema;
mod session;
mod video;

pub use design::{
    LayerDesign, TextureBrush, TileableTexture, deform_texture, deformation_set, make_tileable,
};
pub use exemplar::Exemplar;
pub use features::{FeatureMap, FeatureSynthesis, detect_features, measure_broken_features};
pub use flow::{FlowAnimation, flow_field};
pub use graphcut::GraphcutTextures;
pub use merge::GraphcutMerge;
pub use optimization::TextureOptimization;
pub use quality::measure_quality;
pub use video::{VideoClip, VideoTextures};

use wasm_bindgen::prelude::*;

/// Runs once when the module is instantiated: panics (each one a bug) reach the console with a
/// readable message instead of "unreachable executed".
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

/// The library's version, from `Cargo.toml`.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
