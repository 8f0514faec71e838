//! Layer 4: the only code that knows about JavaScript. Each file wraps one JS-visible type; inputs
//! are validated here and every failure becomes a JS `Error` whose message names the problem.

mod anatomy;
mod brush;
mod design;
mod error;
mod exemplar;
mod exemplars;
mod features;
mod flow;
mod graphcut;
mod inpainting;
mod layers;
mod merge;
mod object;
mod optimization;
mod options;
mod pixels;
mod quality;
mod schema;
mod session;
mod threads;
mod video;

pub use brush::TextureBrush;
pub use design::{TileableTexture, deform_texture, deformation_set, make_tileable};
pub use exemplar::Exemplar;
pub use features::{FeatureMap, FeatureSynthesis, detect_features, measure_broken_features};
pub use flow::{FlowAnimation, flow_field};
pub use graphcut::GraphcutTextures;
pub use inpainting::{Inpainting, extend_border};
pub use layers::LayerDesign;
pub use merge::GraphcutMerge;
pub use optimization::TextureOptimization;
pub use quality::measure_quality;
pub use threads::{thread_count, threaded};
pub use video::{VideoClip, VideoTextures};

use wasm_bindgen::prelude::*;

/// Runs once when the module is instantiated: panics (each one a bug) reach the console with a
/// readable message instead of "unreachable executed".
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

/// The declared options and events of every class, as `[{ class, optionsName, options: [{ key,
/// ts, default, doc, choices }], required, eventName, event: [{ key, ts, doc }] }]`. Not part of
/// the public API: the build writes the package's `schema.d.ts` from it, and the drift test
/// checks real sessions against it.
#[wasm_bindgen(js_name = __schema, skip_typescript)]
pub fn schema() -> js_sys::Array {
    [
        &optimization::SCHEMA,
        &graphcut::SCHEMA,
        &inpainting::SCHEMA,
        &merge::SCHEMA,
        &flow::SCHEMA,
        &flow::COMPONENT_SCHEMA,
        &design::RANGE_SCHEMA,
        &design::RANGES_SCHEMA,
        &design::TILEABLE_SCHEMA,
        &brush::BRUSH_SCHEMA,
        &layers::LAYER_SCHEMA,
        &features::DETECT_SCHEMA,
        &features::SCHEMA,
        &video::SCHEMA,
    ]
    .into_iter()
    .map(|s| s.to_js())
    .collect()
}

/// The library's version, from `Cargo.toml`.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
