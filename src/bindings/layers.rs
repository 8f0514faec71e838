//! `LayerDesign`: fast layer-based design (Shen et al. 2009, stage 4) for JS, one row of patches
//! per step.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::prelude::*;

use super::design::read_deformations;
use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::OptionsReader;
use super::pixels::{render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, Schema, invalid, kind_field, number, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::{Error, Image};
use crate::methods::design::deform;
use crate::methods::design::layers::{
    Layer, LayerDesign as Design, LayerOptions, LayerPlacement, LayerSearch,
};

pub(crate) const LAYER_SCHEMA: Schema = Schema {
    class: "LayerDesign",
    options_name: "LayerDesignOptions",
    options: &[
        MEMORY_BUDGET,
        output_size("outputWidth", 8192, Some("360"), "Output width in pixels."),
        output_size(
            "outputHeight",
            8192,
            Some("360"),
            "Output height in pixels.",
        ),
        Opt {
            key: "patchSize",
            kind: Kind::Integer { min: 8, max: 256 },
            default: Some("32"),
            doc: "Side of the square patches.",
        },
        Opt {
            key: "overlap",
            kind: Kind::Integer { min: 1, max: 127 },
            default: None,
            doc: "Overlap between neighbouring patches. Default: a sixth of patchSize, at least 2.",
        },
        Opt {
            key: "search",
            kind: Kind::Choice(&["qtp", "exhaustive"]),
            default: Some("'qtp'"),
            doc: "Candidate search: the quad-tree pyramid (QTP) or every position.",
        },
        Opt {
            key: "keep",
            kind: Kind::Integer { min: 1, max: 256 },
            default: Some("32"),
            doc: "Candidates the QTP keeps per level.",
        },
        Opt {
            key: "placement",
            kind: Kind::Choice(&["logistic", "random", "best"]),
            default: Some("'logistic'"),
            doc: "How a patch is drawn from the candidates.",
        },
        number(
            "tolerance",
            Some("0.3"),
            "Candidates within this share of the best cost are drawn from.",
        ),
        Opt {
            key: "seed",
            kind: Kind::Integer {
                min: 0,
                max: 0xffff_ffff,
            },
            default: Some("1"),
            doc: "Seed of the random choices: the same seed, options and input give the same bytes.",
        },
    ],
    required: &[],
    event_name: "LayerDesignEvent",
    event: &[
        kind_field("'row' | 'done'"),
        DONE,
        EventField {
            key: "row",
            ts: "number",
            doc: "The row of patches made, 0 for the top.",
        },
        EventField {
            key: "rows",
            ts: "number",
            doc: "Rows of patches in the output.",
        },
        EventField {
            key: "rowPatches",
            ts: "number",
            doc: "Patches placed in this row.",
        },
        EventField {
            key: "patchesPlaced",
            ts: "number",
            doc: "Patches placed so far.",
        },
        EventField {
            key: "ssd",
            ts: "number",
            doc: "Sum over this row's patches of the chosen patch's boundary-zone SSD.",
        },
        EventField {
            key: "totalSsd",
            ts: "number",
            doc: "The same over all rows so far.",
        },
        EventField {
            key: "positionsSearched",
            ts: "number",
            doc: "Candidate positions whose cost was computed in this row.",
        },
        EventField {
            key: "pixelsCompared",
            ts: "number",
            doc: "Pixel comparisons those costs took.",
        },
        EventField {
            key: "largestSearch",
            ts: "number",
            doc: "The most positions one patch's search computed (bounded by the search window of a layer larger than 512 a side).",
        },
    ],
};

fn read_layer_options(value: &JsValue) -> JsResult<LayerOptions> {
    let js = OptionsReader::new(value, &LAYER_SCHEMA)?;
    let d = LayerOptions::default();
    let search = |name: &str| match name {
        "qtp" => Some(LayerSearch::Qtp),
        "exhaustive" => Some(LayerSearch::Exhaustive),
        _ => None,
    };
    let placement = |name: &str| match name {
        "logistic" => Some(LayerPlacement::Logistic),
        "random" => Some(LayerPlacement::Random),
        "best" => Some(LayerPlacement::Best),
        _ => None,
    };
    let options = LayerOptions {
        memory_budget_mib: js.memory_budget()?,
        output_width: js.size("outputWidth")?.unwrap_or(d.output_width),
        output_height: js.size("outputHeight")?.unwrap_or(d.output_height),
        patch_size: js.size("patchSize")?.unwrap_or(d.patch_size),
        overlap: js.size("overlap")?,
        search: js.choice("search", search)?.unwrap_or(LayerSearch::Qtp),
        keep: js.size("keep")?.unwrap_or(d.keep),
        placement: js
            .choice("placement", placement)?
            .unwrap_or(LayerPlacement::Logistic),
        tolerance: js.number("tolerance")?.map_or(d.tolerance, |v| v as f32),
        seed: js.integer("seed")?.unwrap_or(d.seed),
    };
    js.finish()?;
    Ok(options)
}

/// Fast layer-based design (stage 4): add layers (designed textures, each with its own global
/// deformations), optionally a layout saying which layer each output pixel takes, then `step()`
/// fills the output one row of patches at a time.
#[wasm_bindgen]
pub struct LayerDesign {
    options: LayerOptions,
    layers: Vec<Layer>,
    layout: Option<Vec<u8>>,
    design: Option<Design>,
}

js_session!(LayerDesign);

/// One row of patches per step.
impl JsSession for LayerDesign {
    fn step_event(&mut self) -> JsResult<JsValue> {
        if self.design.is_none() {
            if self.layers.is_empty() {
                return Err(invalid(
                    "layers",
                    "add at least one layer with addLayer() first",
                ));
            }
            let n = self.options.output_width * self.options.output_height;
            let layout = self.layout.clone().unwrap_or_else(|| vec![0; n]);
            self.design = Some(Design::new(&self.layers, &layout, self.options.clone())?);
        }
        let e = self.design.as_mut().expect("built above").step()?;
        LAYER_SCHEMA.event(&[
            ("kind", if e.done { "done" } else { "row" }.into()),
            ("done", e.done.into()),
            ("row", (e.row as u32).into()),
            ("rows", (e.rows as u32).into()),
            ("rowPatches", (e.patches as u32).into()),
            ("patchesPlaced", (e.total_patches as u32).into()),
            ("ssd", e.ssd.into()),
            ("totalSsd", e.total_ssd.into()),
            ("positionsSearched", (e.positions_searched as f64).into()),
            ("pixelsCompared", (e.pixels_compared as f64).into()),
            ("largestSearch", (e.largest_search as f64).into()),
        ])
    }

    fn is_done(&self) -> bool {
        self.design.as_ref().is_some_and(Design::is_done)
    }

    fn size(&self) -> (usize, usize) {
        (self.options.output_width, self.options.output_height)
    }

    fn memory_bytes(&self) -> u64 {
        let (w, h) = (self.options.output_width, self.options.output_height);
        let dims: Vec<(usize, usize)> = self
            .layers
            .iter()
            .map(|l| (l.texture.width(), l.texture.height()))
            .collect();
        let c = self.layers.iter().map(|l| l.texture.channels()).max();
        crate::methods::design::memory::layers_working_set(
            (w, h, c.unwrap_or(4)),
            self.options.patch_size,
            &dims,
        )
        .bytes()
    }

    /// The output so far (black where no patch is yet).
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        match &self.design {
            Some(d) => render_into(d.image(), target),
            None => write_rgba(
                &vec![0; self.options.output_width * self.options.output_height * 4],
                target,
            ),
        }
    }
}

#[wasm_bindgen]
impl LayerDesign {
    /// `new LayerDesign({ outputWidth: 360, outputHeight: 360, patchSize: 32, overlap,
    /// search: 'qtp' | 'exhaustive', keep: 32, placement: 'logistic' | 'random' | 'best',
    /// tolerance: 0.3, seed: 1 })`.
    #[wasm_bindgen(constructor)]
    pub fn new(options: JsValue) -> JsResult<LayerDesign> {
        let options = read_layer_options(&options)?;
        // The options and the output's memory budget first, before the layout is allocated.
        options.validate()?;
        // Validate now, with a stand-in layer, so that bad options fail here.
        let probe = Image::new(options.patch_size, options.patch_size, 3)?;
        let layout = vec![0u8; options.output_width * options.output_height];
        Design::new(
            &[Layer {
                texture: probe,
                deformations: vec![],
            }],
            &layout,
            options.clone(),
        )?;
        Ok(LayerDesign {
            options,
            layers: Vec::new(),
            layout: None,
            design: None,
        })
    }

    /// Adds a layer; returns its index. `deformations` as in `deformTexture`. Starts over.
    #[wasm_bindgen(js_name = addLayer)]
    pub fn add_layer(&mut self, exemplar: &Exemplar, deformations: JsValue) -> JsResult<u32> {
        if self.layers.len() == crate::methods::design::layers::MAX_LAYERS {
            return Err(invalid("layers", "at most 16 layers"));
        }
        let deformations = read_deformations(&deformations)?;
        // Fail here, not at the first step, if the deformed layer is too small.
        let t = deform(exemplar.image(), &deformations)?;
        if t.width() < self.options.patch_size || t.height() < self.options.patch_size {
            return Err(Error::InvalidSize {
                what: "layer texture",
                width: t.width(),
                height: t.height(),
                reason: format!("is smaller than the patch size {}", self.options.patch_size),
            }
            .into());
        }
        self.layers.push(Layer {
            texture: exemplar.image().clone(),
            deformations,
        });
        self.design = None;
        Ok(self.layers.len() as u32 - 1)
    }

    /// Which layer each output pixel takes: one byte per pixel. Without it every pixel takes
    /// layer 0. Starts over.
    #[wasm_bindgen(js_name = setLayout)]
    pub fn set_layout(&mut self, layout: &[u8]) -> JsResult<()> {
        let n = self.options.output_width * self.options.output_height;
        if layout.len() != n {
            return Err(Error::LengthMismatch {
                what: "layout",
                expected: n,
                actual: layout.len(),
            }
            .into());
        }
        self.layout = Some(layout.to_vec());
        self.design = None;
        Ok(())
    }

    /// The output as an `Exemplar` (for the gallery, `makeTileable` or a PNG).
    #[wasm_bindgen(js_name = toExemplar)]
    pub fn to_exemplar(&self) -> JsResult<Exemplar> {
        match &self.design {
            Some(d) => Ok(Exemplar::from_image(d.image().clone())),
            None => Err(invalid("design", "has not stepped yet")),
        }
    }
}
