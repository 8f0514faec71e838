//! `GraphcutMerge`: interactive merging of several images (graph-cut textures, section 6.B). Add
//! sources at positions, paint which output pixels must come from which source, then `step()`
//! lays the sources down one by one, each with the seam the graph cut finds.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::object;
use super::pixels::{render_into, write_rgba};
use crate::core::error::check_size;
use crate::core::{Error, Image};
use crate::methods::graphcut::merge::Merge;
use crate::methods::graphcut::teaching::{label_map, seam_overlay};

/// A merge of up to 8 source images into a `width` x `height` output.
#[wasm_bindgen]
pub struct GraphcutMerge {
    width: usize,
    height: usize,
    sources: Vec<(Image, i32, i32)>,
    constraints: Vec<u8>,
    gradient_cost: bool,
    anatomy: bool,
    merge: Option<Merge>,
}

#[wasm_bindgen]
impl GraphcutMerge {
    /// An empty merge; `gradientCost` chooses the seam cost M' (eq. 5), which favours seams
    /// along edges.
    #[wasm_bindgen(constructor)]
    pub fn new(width: u32, height: u32, gradient_cost: Option<bool>) -> JsResult<GraphcutMerge> {
        let (width, height) = (width as usize, height as usize);
        check_size("output", width, height)?;
        Ok(GraphcutMerge {
            width,
            height,
            sources: Vec::new(),
            constraints: vec![0; width * height],
            gradient_cost: gradient_cost.unwrap_or(true),
            anatomy: false,
            merge: None,
        })
    }

    /// Adds a source with its top-left corner at (x, y) of the output; returns its index. Starts
    /// the merge over.
    #[wasm_bindgen(js_name = addSource)]
    pub fn add_source(&mut self, exemplar: &Exemplar, x: i32, y: i32) -> JsResult<u32> {
        if self.sources.len() == 8 {
            return Err(Error::InvalidParameter {
                name: "sources",
                reason: "at most 8 sources".into(),
            }
            .into());
        }
        self.sources.push((exemplar.image().clone(), x, y));
        self.merge = None;
        Ok(self.sources.len() as u32 - 1)
    }

    /// The brush constraints: one byte per output pixel, 0 for free and k for "must come from
    /// source k - 1". Starts the merge over.
    #[wasm_bindgen(js_name = setConstraints)]
    pub fn set_constraints(&mut self, mask: &[u8]) -> JsResult<()> {
        if mask.len() != self.width * self.height {
            return Err(Error::LengthMismatch {
                what: "constraint mask",
                expected: self.width * self.height,
                actual: mask.len(),
            }
            .into());
        }
        self.constraints = mask.to_vec();
        self.merge = None;
        Ok(())
    }

    /// Lays the next source down. Returns `{ kind: 'merged' | 'done', done, source, cutCost }`.
    pub fn step(&mut self) -> JsResult<JsValue> {
        if self.merge.is_none() {
            self.merge = Some(Merge::new(
                self.width,
                self.height,
                self.sources.clone(),
                self.constraints.clone(),
                self.gradient_cost,
            )?);
        }
        let anatomy = self.anatomy;
        let merge = self.merge.as_mut().expect("built above");
        merge.set_anatomy(anatomy);
        let result = merge.step()?;
        let done = merge.is_done();
        let (source, cut) =
            result.map_or((JsValue::NULL, 0.0), |(k, cut)| ((k as u32).into(), cut));
        Ok(object(&[
            ("kind", if done { "done" } else { "merged" }.into()),
            ("done", done.into()),
            ("source", source),
            ("cutCost", cut.into()),
        ]))
    }

    /// Records each step's seam graph for [`Self::placement_graph`] (off by default).
    #[wasm_bindgen(js_name = setAnatomy)]
    pub fn set_anatomy(&mut self, on: bool) {
        self.anatomy = on;
        if let Some(merge) = &mut self.merge {
            merge.set_anatomy(on);
        }
    }

    /// The last step's seam graph, as `GraphcutTextures.placementGraph()` gives it (kind 3:
    /// held to the composite so far, the border or paint for an earlier source; kind 4: painted
    /// for the new source); null unless `setAnatomy(true)` came before the step.
    #[wasm_bindgen(js_name = placementGraph)]
    pub fn placement_graph(&self) -> JsValue {
        self.merge
            .as_ref()
            .and_then(Merge::placement_graph)
            .map_or(JsValue::NULL, super::graphcut::graph_object)
    }

    #[wasm_bindgen(getter)]
    pub fn done(&self) -> bool {
        self.merge.as_ref().is_some_and(Merge::is_done)
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.width as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.height as u32
    }

    /// The merged image so far (black where no source reaches yet).
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => render_into(&m.synthesis().canvas.pixels, target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }

    /// The seams between sources, red over transparent.
    #[wasm_bindgen(js_name = renderSeams)]
    pub fn render_seams(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => write_rgba(&seam_overlay(&m.synthesis().canvas), target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }

    /// Which source each pixel shows, one colour per source.
    #[wasm_bindgen(js_name = renderSources)]
    pub fn render_sources(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => write_rgba(&label_map(&m.synthesis().canvas), target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }
}
