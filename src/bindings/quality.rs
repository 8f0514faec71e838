//! `measureQuality`: the method-independent quality metrics of any output, from JS.

use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::object;
use crate::core::codec::check_rgba8;
use crate::core::from_rgba8;
use crate::methods::quality::{check_budget, quality};

/// Scores an output (RGBA8 pixels, e.g. what a session rendered) against its exemplar:
/// `{ coherence, completeness, histogram, flat }`, all lower-is-better (see the README). An
/// output whose scoring would need more than the default memory budget (4096x4096 does) is
/// refused before its pixels are converted.
#[wasm_bindgen(js_name = measureQuality)]
pub fn measure_quality(
    exemplar: &Exemplar,
    rgba: &[u8],
    width: u32,
    height: u32,
) -> JsResult<JsValue> {
    let (w, h) = (width as usize, height as usize);
    check_rgba8(w, h, rgba.len())?;
    let ex = exemplar.image();
    check_budget((ex.width(), ex.height()), (w, h))?;
    let output = from_rgba8(w, h, rgba)?;
    let q = quality(exemplar.image(), &output)?;
    Ok(object(&[
        ("coherence", q.coherence.into()),
        ("completeness", q.completeness.into()),
        ("histogram", q.histogram.into()),
        ("flat", q.flat.into()),
    ]))
}
