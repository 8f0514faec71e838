//! Moving pixels across the JS boundary: reading `ImageData`-shaped objects and writing into a
//! caller's `Uint8ClampedArray` without handing out a new buffer each frame.

use js_sys::{Reflect, Uint8ClampedArray};
use wasm_bindgen::{JsCast, JsValue};

use super::error::JsResult;
use super::schema::invalid;
use crate::core::{Error, Image, from_rgba8, to_rgba8};

/// Reads `{ data, width, height }` (a canvas `ImageData`, or any object of that shape, so it works
/// in Node too) into an image.
pub fn image_from_image_data(value: &JsValue) -> JsResult<Image> {
    if !value.is_object() {
        return Err(invalid(
            "imageData",
            "expected an ImageData or { data, width, height }",
        ));
    }
    let width = dimension(value, "width")?;
    let height = dimension(value, "height")?;
    let data =
        Reflect::get(value, &"data".into()).map_err(|_| invalid("imageData.data", "missing"))?;
    let bytes: Vec<u8> = if let Some(clamped) = data.dyn_ref::<Uint8ClampedArray>() {
        clamped.to_vec()
    } else if let Some(plain) = data.dyn_ref::<js_sys::Uint8Array>() {
        plain.to_vec()
    } else {
        return Err(invalid(
            "imageData.data",
            "must be a Uint8ClampedArray or Uint8Array",
        ));
    };
    Ok(from_rgba8(width, height, &bytes)?)
}

fn dimension(value: &JsValue, name: &'static str) -> JsResult<usize> {
    let v = Reflect::get(value, &name.into())
        .ok()
        .and_then(|v| v.as_f64());
    match v {
        Some(n) if n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= u32::MAX as f64 => {
            Ok(n as usize)
        }
        _ => Err(invalid(
            if name == "width" {
                "imageData.width"
            } else {
                "imageData.height"
            },
            "must be a non-negative whole number",
        )),
    }
}

/// Refuses a target that is not a byte array (`null`, a number, a plain array) before any method
/// is called on it: reading `.length` of `null` would throw inside Rust, and a JS exception that
/// unwinds through a `&self` method leaves the session borrowed for good ("recursive use of an
/// object detected" on every later call). Found by the bad-input corpus (tests/node), rows
/// "renderInto(null) leaves the session usable" and "Exemplar.renderInto: null".
pub fn check_target(target: &JsValue) -> JsResult<()> {
    if target.is_instance_of::<Uint8ClampedArray>() || target.is_instance_of::<js_sys::Uint8Array>()
    {
        Ok(())
    } else {
        Err(invalid(
            "target",
            "must be a Uint8ClampedArray or Uint8Array of width * height * 4 bytes",
        ))
    }
}

/// Checks that `target` is a byte array of exactly `width * height * 4` bytes, before any work
/// whose result it is to receive.
pub fn check_target_size(target: &JsValue, width: usize, height: usize) -> JsResult<()> {
    check_target(target)?;
    let target: &Uint8ClampedArray = target.unchecked_ref();
    let (expected, actual) = (width * height * 4, target.length() as usize);
    if actual != expected {
        return Err(Error::LengthMismatch {
            what: "target pixel array",
            expected,
            actual,
        }
        .into());
    }
    Ok(())
}

/// Writes the image as RGBA8 into the caller's array, which must be exactly `width * height * 4`
/// long (the `data` of an `ImageData` of the image's size).
pub fn render_into(image: &Image, target: &Uint8ClampedArray) -> JsResult<()> {
    check_target_size(target, image.width(), image.height())?;
    target.copy_from(&to_rgba8(image));
    Ok(())
}

/// Copies ready-made RGBA8 pixels into the caller's array, checking its length.
pub fn write_rgba(rgba: &[u8], target: &Uint8ClampedArray) -> JsResult<()> {
    check_target_size(target, rgba.len() / 4, 1)?;
    target.copy_from(rgba);
    Ok(())
}
