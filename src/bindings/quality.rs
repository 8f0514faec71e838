//! `measureQuality`: the method-independent quality metrics of any output, from JS.

use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::object;
use crate::core::from_rgba8;
use crate::methods::quality::quality;

/// Scores an output (RGBA8 pixels, e.g. what a session rendered) against its exemplar:
/// `{ coherence, completeness, histogram, flat }`, all lower-is-better (see the README).
#[wasm_bindgen(js_name = measureQuality)]
pub fn measure_quality(
    exemplar: &Exemplar,
    rgba: &[u8],
    width: u32,
    height: u32,
) -> JsResult<JsValue> {
    let output = from_rgba8(width as usize, height as usize, rgba)?;
    let q = quality(exemplar.image(), &output)?;
    Ok(object(&[
        ("coherence", q.coherence.into()),
        ("completeness", q.completeness.into()),
        ("histogram", q.histogram.into()),
        ("flat", q.flat.into()),
    ]))
}
