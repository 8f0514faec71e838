//! The JS-facing `Exemplar` API, exercised through wasm-bindgen exactly as JavaScript calls it.
//! Included by `node_api.rs` (runs in Node) and `browser_api.rs` (runs in headless Chromium).

use js_sys::{Object, Reflect, Uint8Array, Uint8ClampedArray};
use texsynth::bindings::{Exemplar, version};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::error_message;

const BRICK_64: &[u8] = include_bytes!("../../www/samples/brick_64.png");
const TILES_128: &[u8] = include_bytes!("../../www/samples/tiles_128.png");

#[wasm_bindgen_test]
fn version_is_the_crate_version() {
    assert_eq!(version(), env!("CARGO_PKG_VERSION"));
}

#[wasm_bindgen_test]
fn decodes_samples_and_renders_them() {
    let ex = Exemplar::from_bytes(TILES_128).unwrap();
    assert_eq!((ex.width(), ex.height()), (128, 128));
    let target = Uint8ClampedArray::new_with_length(128 * 128 * 4);
    ex.render_into(&target).unwrap();
    assert_eq!(target.to_vec(), ex.to_rgba().to_vec());
    // Every pixel is opaque and not all pixels are equal.
    let px = target.to_vec();
    assert!(px.chunks(4).all(|p| p[3] == 255));
    assert!(px.chunks(4).any(|p| p[..3] != px[..3]));
}

#[wasm_bindgen_test]
fn png_round_trip_through_js() {
    let ex = Exemplar::from_bytes(BRICK_64).unwrap();
    let png: Uint8Array = ex.to_png().unwrap();
    let back = Exemplar::from_bytes(&png.to_vec()).unwrap();
    assert_eq!(back.to_rgba().to_vec(), ex.to_rgba().to_vec());
    assert_eq!(back.channels(), ex.channels());
}

#[wasm_bindgen_test]
fn image_data_shaped_objects_are_accepted() {
    let ex = Exemplar::from_bytes(BRICK_64).unwrap();
    let obj = Object::new();
    Reflect::set(&obj, &"width".into(), &64.into()).unwrap();
    Reflect::set(&obj, &"height".into(), &64.into()).unwrap();
    Reflect::set(&obj, &"data".into(), &ex.to_rgba()).unwrap();
    let copy = Exemplar::from_image_data(&obj).unwrap();
    assert_eq!(copy.to_rgba().to_vec(), ex.to_rgba().to_vec());
    let raw = Exemplar::from_rgba(&ex.to_rgba().to_vec(), 64, 64).unwrap();
    assert_eq!(raw.width(), 64);
}

#[wasm_bindgen_test]
fn bad_input_is_a_js_error_with_a_message() {
    assert!(error_message(Exemplar::from_bytes(&[])).contains("empty input"));
    assert!(error_message(Exemplar::from_bytes(b"GIF89a not really")).contains("could not decode"));
    let truncated = &TILES_128[..TILES_128.len() / 3];
    assert!(error_message(Exemplar::from_bytes(truncated)).contains("could not decode"));
    let msg = error_message(Exemplar::from_rgba(&[], 0, 0));
    assert!(msg.contains("0x0"), "{msg}");
    let msg = error_message(Exemplar::from_rgba(&[0; 16], 100_000, 100_000));
    assert!(msg.contains("100000x100000"), "{msg}");
    let msg = error_message(Exemplar::from_rgba(&[0; 15], 2, 2));
    assert!(
        msg.contains("length 15") && msg.contains("expected 16"),
        "{msg}"
    );
    let msg = error_message(Exemplar::from_image_data(&JsValue::from(3)));
    assert!(msg.contains("imageData"), "{msg}");
    let obj = Object::new();
    Reflect::set(&obj, &"width".into(), &f64::NAN.into()).unwrap();
    assert!(error_message(Exemplar::from_image_data(&obj)).contains("imageData.width"));
    let ex = Exemplar::from_bytes(BRICK_64).unwrap();
    let small = Uint8ClampedArray::new_with_length(10);
    let msg = error_message(ex.render_into(&small));
    assert!(
        msg.contains("target pixel array") && msg.contains("16384"),
        "{msg}"
    );
}

#[wasm_bindgen_test]
fn forged_huge_png_header_is_an_error() {
    let mut png = BRICK_64.to_vec();
    png[16..20].copy_from_slice(&100_000u32.to_be_bytes());
    png[20..24].copy_from_slice(&100_000u32.to_be_bytes());
    let msg = error_message(Exemplar::from_bytes(&png));
    assert!(
        msg.contains("100000") || msg.contains("could not decode"),
        "{msg}"
    );
}

/// A large photo becomes a working-size exemplar: shrunk (area averaging, the mean kept) or a
/// region cropped; bad sizes are named errors.
#[wasm_bindgen_test]
fn a_large_exemplar_is_resized_or_cropped() {
    let ex = Exemplar::from_bytes(TILES_128).unwrap();
    let mean = |e: &Exemplar| {
        let rgba = e.to_rgba().to_vec();
        rgba.chunks(4)
            .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
            .sum::<f64>()
            / (rgba.len() / 4) as f64
    };
    let small = ex.resized(50.0).unwrap();
    assert_eq!((small.width(), small.height()), (50, 50));
    assert!(
        (mean(&small) - mean(&ex)).abs() < 2.0,
        "area averaging keeps the mean"
    );
    let same = ex.resized(4000.0).unwrap();
    assert_eq!(
        same.to_rgba().to_vec(),
        ex.to_rgba().to_vec(),
        "already small enough"
    );
    let region = ex.cropped(10.0, 20.0, 64.0, 32.0).unwrap();
    assert_eq!((region.width(), region.height()), (64, 32));
    let (whole, part) = (ex.to_rgba().to_vec(), region.to_rgba().to_vec());
    assert_eq!(
        &part[..4],
        &whole[(20 * 128 + 10) * 4..(20 * 128 + 10) * 4 + 4]
    );
    assert!(error_message(ex.resized(0.0)).contains("maxSide"));
    assert!(error_message(ex.resized(f64::NAN)).contains("maxSide"));
    assert!(error_message(ex.cropped(100.0, 0.0, 64.0, 64.0)).contains("does not fit"));
    assert!(error_message(ex.cropped(-1.0, 0.0, 8.0, 8.0)).contains('x'));
    assert!(error_message(ex.cropped(0.0, 0.0, 0.0, 8.0)).contains("crop"));
}
