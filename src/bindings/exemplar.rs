//! `Exemplar`: the example image every synthesis starts from.

use js_sys::{Uint8Array, Uint8ClampedArray};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::pixels::{image_from_image_data, render_into};
use crate::core::sample::shrink_area;
use crate::core::{Error, Image, decode, encode_png, from_rgba8, to_rgba8};

/// An example texture, decoded and held in wasm memory.
#[wasm_bindgen]
pub struct Exemplar {
    image: Image,
}

#[wasm_bindgen]
impl Exemplar {
    /// Decodes PNG or JPEG bytes (a `Uint8Array`, e.g. from `fetch(...).arrayBuffer()`).
    #[wasm_bindgen(js_name = fromBytes)]
    pub fn from_bytes(bytes: &[u8]) -> JsResult<Exemplar> {
        Ok(Exemplar {
            image: decode(bytes)?,
        })
    }

    /// Takes the pixels of a canvas `ImageData` (or any `{ data, width, height }` object).
    #[wasm_bindgen(js_name = fromImageData)]
    pub fn from_image_data(image_data: &JsValue) -> JsResult<Exemplar> {
        Ok(Exemplar {
            image: image_from_image_data(image_data)?,
        })
    }

    /// Takes raw RGBA8 pixels, `width * height * 4` bytes.
    #[wasm_bindgen(js_name = fromRgba)]
    pub fn from_rgba(rgba: &[u8], width: u32, height: u32) -> JsResult<Exemplar> {
        Ok(Exemplar {
            image: from_rgba8(width as usize, height as usize, rgba)?,
        })
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.image.width() as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.image.height() as u32
    }

    /// 1 (grey), 3 (RGB) or 4 (RGBA with transparency).
    #[wasm_bindgen(getter)]
    pub fn channels(&self) -> u32 {
        self.image.channels() as u32
    }

    /// Writes the exemplar as RGBA8 into `target` (length `width * height * 4`), e.g. the `data`
    /// of an `ImageData` the caller keeps and reuses.
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.image, target)
    }

    /// The exemplar as a new RGBA8 array.
    #[wasm_bindgen(js_name = toRgba)]
    pub fn to_rgba(&self) -> Uint8ClampedArray {
        Uint8ClampedArray::from(to_rgba8(&self.image).as_slice())
    }

    /// The exemplar encoded as PNG.
    #[wasm_bindgen(js_name = toPng)]
    pub fn to_png(&self) -> JsResult<Uint8Array> {
        Ok(Uint8Array::from(encode_png(&self.image)?.as_slice()))
    }

    /// A copy whose longer side is at most `maxSide`, shrunk by area averaging (a camera photo
    /// becomes a working-size exemplar; its fine texture stays texture instead of aliasing). An
    /// exemplar already within `maxSide` is copied unchanged.
    pub fn resized(&self, max_side: f64) -> JsResult<Exemplar> {
        if !max_side.is_finite() || max_side < 1.0 || max_side.fract() != 0.0 {
            return Err(Error::InvalidParameter {
                name: "maxSide",
                reason: format!("must be a whole number of pixels, at least 1, got {max_side}"),
            }
            .into());
        }
        let (w, h) = (self.image.width(), self.image.height());
        let longer = w.max(h) as f64;
        if longer <= max_side {
            return Ok(Exemplar::from_image(self.image.clone()));
        }
        let factor = max_side / longer;
        let side = |len: usize| ((len as f64 * factor).round() as usize).clamp(1, len);
        Ok(Exemplar::from_image(shrink_area(
            &self.image,
            side(w),
            side(h),
        )?))
    }

    /// The `width` x `height` rectangle whose top-left corner is (`x`, `y`), as a new exemplar
    /// (a region of a photo dragged on the page). It must lie inside the exemplar.
    pub fn cropped(&self, x: f64, y: f64, width: f64, height: f64) -> JsResult<Exemplar> {
        let whole = |name: &'static str, v: f64| -> JsResult<usize> {
            if v.is_finite() && v >= 0.0 && v.fract() == 0.0 && v <= 1e9 {
                Ok(v as usize)
            } else {
                Err(Error::InvalidParameter {
                    name,
                    reason: format!("must be a whole, non-negative number of pixels, got {v}"),
                }
                .into())
            }
        };
        let (x, y) = (whole("x", x)?, whole("y", y)?);
        let (w, h) = (whole("width", width)?, whole("height", height)?);
        Ok(Exemplar::from_image(self.image.crop(x, y, w, h)?))
    }
}

impl Exemplar {
    /// Wraps an image a method made (a deformed or tileable texture, a design's output).
    #[must_use]
    pub fn from_image(image: Image) -> Exemplar {
        Exemplar { image }
    }

    /// The decoded image, for the other session types.
    #[must_use]
    pub fn image(&self) -> &Image {
        &self.image
    }
}
