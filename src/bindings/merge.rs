//! `GraphcutMerge`: interactive merging of several images (graph-cut textures, section 6.B). Add
//! sources at positions, paint which output pixels must come from which source, then `step()`
//! lays the sources down one by one, each with the seam the graph cut finds.

use js_sys::{Uint8ClampedArray, Uint32Array};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::OptionsReader;
use super::pixels::{render_into, write_rgba};
use super::schema::{DONE, EventField, Kind, Opt, Schema, kind_field, output_size};
use super::session::{JsSession, js_session};
use crate::core::error::check_size;
use crate::core::{Error, Image};
use crate::methods::graphcut::Blend;
use crate::methods::graphcut::memory::working_set;
use crate::methods::graphcut::merge::Merge;
use crate::methods::graphcut::teaching::{label_map, seam_overlay};

pub(crate) const SCHEMA: Schema = Schema {
    class: "GraphcutMerge",
    options_name: "GraphcutMergeOptions",
    options: &[
        output_size("outputWidth", 8192, Some("256"), "Output width in pixels."),
        output_size(
            "outputHeight",
            8192,
            Some("256"),
            "Output height in pixels.",
        ),
        Opt {
            key: "gradientCost",
            kind: Kind::Boolean,
            default: Some("true"),
            doc: "Seam cost M' of eq. 5, which favours seams along edges, instead of M of eq. 1.",
        },
    ],
    required: &[],
    event_name: "GraphcutMergeEvent",
    event: &[
        kind_field("'merged' | 'done'"),
        DONE,
        EventField {
            key: "source",
            ts: "number | null",
            doc: "The source laid down by this step (an index of `addSource`); null when none was.",
        },
        EventField {
            key: "cutCost",
            ts: "number",
            doc: "Cost of this step's min cut.",
        },
    ],
};

/// A merge of up to 8 source images into an `outputWidth` x `outputHeight` output.
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

js_session!(GraphcutMerge);

/// One source laid down per step.
impl JsSession for GraphcutMerge {
    fn step_event(&mut self) -> JsResult<JsValue> {
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
        let e = merge.step()?;
        SCHEMA.event(&[
            ("kind", if e.done { "done" } else { "merged" }.into()),
            ("done", e.done.into()),
            (
                "source",
                e.source.map_or(JsValue::NULL, |k| (k as u32).into()),
            ),
            ("cutCost", e.cut_cost.into()),
        ])
    }

    fn is_done(&self) -> bool {
        self.merge.as_ref().is_some_and(Merge::is_done)
    }

    fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The merge's working set once built; before, the same estimate from the sources added.
    fn memory_bytes(&self) -> u64 {
        if let Some(m) = &self.merge {
            return m.synthesis().working_set().bytes();
        }
        let dims: Vec<(usize, usize)> = self
            .sources
            .iter()
            .map(|(s, _, _)| (s.width(), s.height()))
            .collect();
        let channels = self.sources.iter().map(|(s, _, _)| s.channels()).max();
        let largest = dims.iter().map(|&(w, h)| w * h).max().unwrap_or(0);
        working_set(
            (self.width, self.height, channels.unwrap_or(4)),
            &dims,
            largest,
            0,
            Blend::None,
        )
        .bytes()
    }

    /// The merged image so far (black where no source reaches yet).
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => render_into(&m.synthesis().canvas.pixels, target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }
}

#[wasm_bindgen]
impl GraphcutMerge {
    /// An empty merge: `new GraphcutMerge({ outputWidth, outputHeight, gradientCost })` (see
    /// [`SCHEMA`]); add sources with `addSource`.
    #[wasm_bindgen(constructor)]
    pub fn new(options: JsValue) -> JsResult<GraphcutMerge> {
        let js = OptionsReader::new(&options, &SCHEMA)?;
        let width = js.size("outputWidth")?.unwrap_or(256);
        let height = js.size("outputHeight")?.unwrap_or(256);
        let gradient_cost = js.boolean("gradientCost")?.unwrap_or(true);
        js.finish()?;
        check_size("output", width, height)?;
        Ok(GraphcutMerge {
            width,
            height,
            sources: Vec::new(),
            constraints: vec![0; width * height],
            gradient_cost,
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
            .map_or(JsValue::NULL, super::anatomy::graph_object)
    }

    /// The seams between sources, red over transparent.
    #[wasm_bindgen(js_name = renderSeamsInto)]
    pub fn render_seams_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => write_rgba(&seam_overlay(&m.synthesis().canvas), target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }

    /// How many output pixels each source shows so far, by `addSource`'s index (all 0 before
    /// the first step).
    #[wasm_bindgen(js_name = sourcePixels)]
    pub fn source_pixels(&self) -> Uint32Array {
        let mut counts = vec![0u32; self.sources.len()];
        if let Some(m) = &self.merge {
            let synthesis = m.synthesis();
            for i in 0..self.width * self.height {
                if let Some(patch) = synthesis.patch_of(i)
                    && let Some(c) = counts.get_mut(patch.source as usize)
                {
                    *c += 1;
                }
            }
        }
        Uint32Array::from(&counts[..])
    }

    /// Which source each pixel shows, one colour per source.
    #[wasm_bindgen(js_name = renderSourcesInto)]
    pub fn render_sources_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.merge {
            Some(m) => write_rgba(&label_map(&m.synthesis().canvas), target),
            None => write_rgba(&vec![0; self.width * self.height * 4], target),
        }
    }
}
