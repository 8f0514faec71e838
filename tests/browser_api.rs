//! The JS-facing API in headless Chromium, through chromedriver.
#![cfg(target_arch = "wasm32")]

wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

#[path = "common/js_helpers.rs"]
mod js_helpers;

#[path = "common/exemplar_cases.rs"]
mod exemplar_cases;

#[path = "common/optimization_cases.rs"]
mod optimization_cases;

#[path = "common/graphcut_cases.rs"]
mod graphcut_cases;

#[path = "common/flow_cases.rs"]
mod flow_cases;

#[path = "common/design_cases.rs"]
mod design_cases;

#[path = "common/features_cases.rs"]
mod features_cases;

#[path = "common/video_cases.rs"]
mod video_cases;
