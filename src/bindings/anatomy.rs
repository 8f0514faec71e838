//! The placement anatomy as JS objects: the cost surface of a placement and its seam graph, as
//! graph cut, feature-guided synthesis, merging and video return them.

use js_sys::{Float32Array, Uint8Array};
use wasm_bindgen::JsValue;

use super::object::object;
use crate::methods::graphcut::anatomy::{CostSurface, GraphView};

/// A cost surface as the JS object `placementCosts()` returns.
pub fn costs_object(c: &CostSurface) -> JsValue {
    let (cx, cy) = c.chosen.map_or((-1.0, -1.0), |(x, y)| (x as f64, y as f64));
    object(&[
        ("x", (c.x as f64).into()),
        ("y", (c.y as f64).into()),
        ("width", (c.width as u32).into()),
        ("height", (c.height as u32).into()),
        ("cost", Float32Array::from(c.cost.as_slice()).into()),
        (
            "probability",
            Float32Array::from(c.probability.as_slice()).into(),
        ),
        ("chosenX", cx.into()),
        ("chosenY", cy.into()),
        ("temperature", c.temperature.into()),
    ])
}

/// A seam graph view as the JS object `placementGraph()` returns.
pub fn graph_object(g: &GraphView) -> JsValue {
    object(&[
        ("x", (g.x as f64).into()),
        ("y", (g.y as f64).into()),
        ("width", (g.width as u32).into()),
        ("height", (g.height as u32).into()),
        ("kind", Uint8Array::from(g.kind.as_slice()).into()),
        ("right", Float32Array::from(g.right.as_slice()).into()),
        ("down", Float32Array::from(g.down.as_slice()).into()),
        (
            "oldRight",
            Float32Array::from(g.old_right.as_slice()).into(),
        ),
        ("oldDown", Float32Array::from(g.old_down.as_slice()).into()),
        ("taken", Uint8Array::from(g.taken.as_slice()).into()),
    ])
}
