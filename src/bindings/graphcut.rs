//! `GraphcutTextures`: the JS-visible graph-cut texture session. Each `step()` places one patch
//! and returns a plain event object; the image and the teaching views render into the caller's
//! buffers.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::prelude::*;

use super::anatomy::{costs_object, graph_object};
use super::error::JsResult;
use super::exemplar::Exemplar;
use super::exemplars::{ExemplarList, sources_view};
use super::features::FeatureMap;
use super::options::{OptionsReader, object};
use super::pixels::{check_target_size, render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, SEED, Schema, kind_field, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::Error;
use crate::methods::features::broken::carried_broken;
use crate::methods::features::carried::carried_mask;
use crate::methods::graphcut::region::Region;
use crate::methods::graphcut::teaching::{label_map, seam_heat_map, seam_overlay};
use crate::methods::graphcut::{Blend, Event, Options, Placement, Session, Transforms};

pub(crate) const SCHEMA: Schema = Schema {
    class: "GraphcutTextures",
    options_name: "GraphcutTexturesOptions",
    options: &[
        MEMORY_BUDGET,
        output_size(
            "outputWidth",
            1 << 20,
            Some("256"),
            "Output width in pixels.",
        ),
        output_size(
            "outputHeight",
            1 << 20,
            Some("256"),
            "Output height in pixels.",
        ),
        SEED,
        Opt {
            key: "placement",
            kind: Kind::Choice(&["random", "entire-patch", "sub-patch"]),
            default: Some("'entire-patch'"),
            doc: "Patch placement (section 3.2).",
        },
        Opt {
            key: "k",
            kind: Kind::Number,
            default: Some("0.01"),
            doc: "Offsets are drawn with probability exp(-C / (k sigma^2)).",
        },
        Opt {
            key: "errorRegion",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("0"),
            doc: "Side of the error region in pixels; 0 is a third of the exemplar's side.",
        },
        Opt {
            key: "refinementPatches",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("24"),
            doc: "Patches placed after the output is covered.",
        },
        Opt {
            key: "gradientCost",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Seam cost M' of eq. 5 (favours edges) instead of M of eq. 1.",
        },
        Opt {
            key: "blend",
            kind: Kind::Choice(&["none", "feather", "spline"]),
            default: Some("'none'"),
            doc: "Blending across seams.",
        },
        Opt {
            key: "rotate",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Also take patches from the exemplar rotated by 90, 180, 270 degrees.",
        },
        Opt {
            key: "mirror",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Also take patches from the mirrored exemplar.",
        },
        Opt {
            key: "scales",
            kind: Kind::Numbers,
            default: Some("[]"),
            doc: "Also take patches from the exemplar scaled by these factors (at most 4).",
        },
        Opt {
            key: "perspective",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "With scales: smaller scales towards the top.",
        },
        Opt {
            key: "tileable",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Make the output tile seamlessly.",
        },
    ],
    required: &[],
    event_name: "GraphcutTexturesEvent",
    event: &[
        kind_field("'placed' | 'done'"),
        DONE,
        EventField {
            key: "patch",
            ts: "{ source: number; offsetX: number; offsetY: number; windowX: number; windowY: number } | null",
            doc: "The patch placed: its source (an index into `sources()`), its offset in the output, and the top-left corner in the source of the window it copies ((0, 0) unless the exemplar is larger than 512 a side); null when no unused offset was left.",
        },
        EventField {
            key: "rect",
            ts: "Rect",
            doc: "The patch's box in the output.",
        },
        EventField {
            key: "region",
            ts: "Rect",
            doc: "The error region the placement aimed at.",
        },
        EventField {
            key: "pixelsTaken",
            ts: "number",
            doc: "Output pixels the new patch took.",
        },
        EventField {
            key: "cutCost",
            ts: "number",
            doc: "Cost of this placement's min cut.",
        },
        EventField {
            key: "covered",
            ts: "boolean",
            doc: "Whether every output pixel has been covered.",
        },
        EventField {
            key: "totalSeamCost",
            ts: "number",
            doc: "Cost of all seams in the output.",
        },
        EventField {
            key: "patchesPlaced",
            ts: "number",
            doc: "Patches placed so far.",
        },
    ],
};

fn read_options(value: &JsValue) -> JsResult<Options> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = Options::default();
    let mut scales = [None; 4];
    if let Some(list) = js.numbers("scales")? {
        if list.len() > 4 {
            return Err(Error::InvalidParameter {
                name: "scales",
                reason: format!("at most 4 scales, got {}", list.len()),
            }
            .into());
        }
        for (slot, s) in scales.iter_mut().zip(list) {
            *slot = Some(s as f32);
        }
    }
    let options = Options {
        memory_budget_mib: js.memory_budget()?,
        output_width: js.size("outputWidth")?.unwrap_or(d.output_width),
        output_height: js.size("outputHeight")?.unwrap_or(d.output_height),
        seed: js.integer("seed")?.unwrap_or(d.seed),
        placement: js
            .choice("placement", Placement::from_name)?
            .unwrap_or(d.placement),
        k: js.number("k")?.map_or(d.k, |v| v as f32),
        error_region: js.size("errorRegion")?.unwrap_or(d.error_region),
        refinement_patches: js
            .size("refinementPatches")?
            .unwrap_or(d.refinement_patches),
        gradient_cost: js.boolean("gradientCost")?.unwrap_or(d.gradient_cost),
        blend: js.choice("blend", Blend::from_name)?.unwrap_or(d.blend),
        transforms: Transforms {
            rotate: js.boolean("rotate")?.unwrap_or(false),
            mirror: js.boolean("mirror")?.unwrap_or(false),
            scales,
            perspective: js.boolean("perspective")?.unwrap_or(false),
        },
        tileable: js.boolean("tileable")?.unwrap_or(d.tileable),
    };
    js.finish()?;
    Ok(options)
}

fn region_object(r: Region) -> JsValue {
    object(&[
        ("x", (r.x as u32).into()),
        ("y", (r.y as u32).into()),
        ("width", (r.width as u32).into()),
        ("height", (r.height as u32).into()),
    ])
}

fn event_object(e: &Event) -> JsResult<JsValue> {
    let patch = e.patch.map_or(JsValue::NULL, |p| {
        object(&[
            ("source", p.source.into()),
            ("offsetX", p.tx.into()),
            ("offsetY", p.ty.into()),
            // The top-left corner, in the source, of the window the patch copies: (0, 0) unless
            // the exemplar is larger than 512 a side (see methods/graphcut/source_window.rs).
            ("windowX", p.window.0.into()),
            ("windowY", p.window.1.into()),
        ])
    });
    let (x, y, w, h) = e.rect;
    SCHEMA.event(&[
        ("kind", if e.done { "done" } else { "placed" }.into()),
        ("done", e.done.into()),
        ("patch", patch),
        (
            "rect",
            object(&[
                ("x", (x as f64).into()),
                ("y", (y as f64).into()),
                ("width", (w as u32).into()),
                ("height", (h as u32).into()),
            ]),
        ),
        ("region", region_object(e.region)),
        ("pixelsTaken", (e.pixels_taken as u32).into()),
        ("cutCost", e.cut_cost.into()),
        ("covered", e.covered.into()),
        ("totalSeamCost", e.total_seam_cost.into()),
        ("patchesPlaced", (e.patches_placed as u32).into()),
    ])
}

/// A graph-cut texture synthesis (Kwatra et al. 2003) you advance with `step()`.
#[wasm_bindgen]
pub struct GraphcutTextures {
    session: Session,
    exemplars: ExemplarList,
}

js_session!(GraphcutTextures);

/// One patch placement per step.
impl JsSession for GraphcutTextures {
    fn step_event(&mut self) -> JsResult<JsValue> {
        self.exemplars.stepped();
        event_object(&self.session.step()?)
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    fn size(&self) -> (usize, usize) {
        let canvas = &self.session.synthesis().canvas;
        (canvas.width, canvas.height)
    }

    fn memory_bytes(&self) -> u64 {
        self.session.synthesis().working_set().bytes()
    }

    /// The output, blended as the options say.
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.output()?, target)
    }
}

#[wasm_bindgen]
impl GraphcutTextures {
    /// Options: see [`SCHEMA`] (every key optional). Unknown keys and impossible values throw.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<GraphcutTextures> {
        let options = read_options(&options)?;
        Ok(GraphcutTextures {
            session: Session::new(exemplar.image(), options)?,
            exemplars: ExemplarList::new(exemplar.image()),
        })
    }

    /// Adds an exemplar patches may come from (before the first step; with its own rotations,
    /// mirrors and scales when the options ask for them). Returns its index, as
    /// `renderSourcesInto` colours it.
    #[wasm_bindgen(js_name = addExemplar)]
    pub fn add_exemplar(&mut self, exemplar: &Exemplar) -> JsResult<u32> {
        let list = self.exemplars.with(exemplar.image())?;
        let options = self.session.synthesis().options.clone();
        self.session = Session::with_exemplars(&list, options)?;
        Ok(self.exemplars.keep(list))
    }

    /// Which exemplar each output pixel comes from, each in its own colour (as `addExemplar`
    /// numbers them); transparent where no patch covered the pixel yet.
    #[wasm_bindgen(js_name = renderSourcesInto)]
    pub fn render_sources_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        let canvas = &self.session.synthesis().canvas;
        let size = (canvas.width, canvas.height);
        write_rgba(
            &sources_view(&self.session.exemplar_map(), size, size),
            target,
        )
    }

    /// The broken-feature count on this output's carried feature map: every made pixel carries
    /// the curve of the exemplar pixel it shows, from `featureMask` (one byte per exemplar pixel,
    /// non-zero on a curve: `FeatureMap.toMask()`), and the count is its curve ends per 1000
    /// curve pixels above the mask's own: the curves the seams cut. A session with deformed
    /// sources (rotations, mirrors, scales) has no mask for them and is refused.
    #[wasm_bindgen(js_name = carriedBrokenFeatures)]
    pub fn carried_broken_features(&self, feature_mask: &[u8]) -> JsResult<f64> {
        let mask: Vec<bool> = feature_mask.iter().map(|&b| b != 0).collect();
        self.carried_broken_of(&mask, "featureMask")
    }

    /// `carriedBrokenFeatures` with the curves of `map` (the exemplar's `FeatureMap`, as
    /// edited) instead of its mask: in a worker the map's own object is passed, and a photo's
    /// map (12 MB of mask at 4000x3000) need not travel to the page and back.
    #[wasm_bindgen(js_name = carriedBrokenFeaturesOf)]
    pub fn carried_broken_features_of(&self, map: &FeatureMap) -> JsResult<f64> {
        let source = &self.session.synthesis().sources[0];
        let (w, h) = map.size();
        if (w, h) != (source.width(), source.height()) {
            return Err(Error::InvalidSize {
                what: "map",
                width: w,
                height: h,
                reason: format!(
                    "must be the exemplar's map, {}x{}",
                    source.width(),
                    source.height()
                ),
            }
            .into());
        }
        self.carried_broken_of(map.mask(), "map")
    }

    /// Material sets: `other` (an image of the exemplar's size: a normal, height or roughness
    /// map) re-indexed by this output's source map, written as RGBA into `target` (output
    /// size). Every output pixel copies the pixel of `other` that the output shows of the
    /// exemplar, so the maps line up with the output and nothing is averaged (normals stay
    /// unit vectors). Uncovered pixels are transparent black. A session with rotated, mirrored
    /// or scaled sources is refused.
    #[wasm_bindgen(js_name = transferInto)]
    pub fn transfer_into(&self, other: &Exemplar, target: &Uint8ClampedArray) -> JsResult<()> {
        let canvas = &self.session.synthesis().canvas;
        check_target_size(target, canvas.width, canvas.height)?;
        let map = self.session.source_map()?;
        render_into(&map.transfer(other.image())?, target)
    }

    /// Seam pixels opaque red, the rest transparent (to draw over the image).
    #[wasm_bindgen(js_name = renderSeamsInto)]
    pub fn render_seams_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        write_rgba(&seam_overlay(&self.session.synthesis().canvas), target)
    }

    /// The per-pixel seam cost as a heat map (black: none, white: the largest).
    #[wasm_bindgen(js_name = renderSeamCostInto)]
    pub fn render_seam_cost_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        write_rgba(&seam_heat_map(&self.session.synthesis().canvas), target)
    }

    /// The label map: every patch in its own colour.
    #[wasm_bindgen(js_name = renderLabelsInto)]
    pub fn render_labels_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        write_rgba(&label_map(&self.session.synthesis().canvas), target)
    }

    /// The error region of the last placement, `{ x, y, width, height }`, or null.
    #[wasm_bindgen(js_name = errorRegion)]
    pub fn error_region(&self) -> JsValue {
        self.session
            .error_region()
            .map_or(JsValue::NULL, region_object)
    }

    /// Turns the placement anatomy on or off: while on, every placement keeps its cost surface
    /// and its graph for `placementCosts()` and `placementGraph()` (off by default).
    #[wasm_bindgen(js_name = setAnatomy)]
    pub fn set_anatomy(&mut self, on: bool) {
        self.session.set_anatomy(on);
    }

    /// The last placement's cost surface (eq. 2 or 4 over every candidate offset) and the
    /// probability eq. 3 gives each: `{ x, y, width, height, cost: Float32Array (Infinity where
    /// no unused candidate is), probability: Float32Array (sums to 1), chosenX, chosenY (grid
    /// cell of the drawn offset), temperature (k sigma^2) }`, offsets in output coordinates of
    /// the patch's corner (`x + column`); null unless `setAnatomy(true)` came before the step.
    #[wasm_bindgen(js_name = placementCosts)]
    pub fn placement_costs(&self) -> JsValue {
        self.session
            .placement_costs()
            .map_or(JsValue::NULL, costs_object)
    }

    /// The last placement's seam graph per pixel of the patch's box: `{ x, y, width, height,
    /// kind: Uint8Array (0 outside, 1 uncovered: takes the patch without a node, 2 free node, 3
    /// held to the old output, 4 held to the new patch), right, down: Float32Array (arc
    /// capacity to the right / lower neighbour, NaN: none), oldRight, oldDown: Float32Array (old
    /// seam cost there, NaN: no old seam), taken: Uint8Array (1: took the new patch) }`; null
    /// unless `setAnatomy(true)` came before the step.
    #[wasm_bindgen(js_name = placementGraph)]
    pub fn placement_graph(&self) -> JsValue {
        self.session
            .placement_graph()
            .map_or(JsValue::NULL, graph_object)
    }

    /// Names of the sources patches come from ("exemplar", "rotate 90", "scale 0.5", ...).
    pub fn sources(&self) -> Vec<String> {
        self.session
            .synthesis()
            .sources
            .iter()
            .map(|s| s.name.clone())
            .collect()
    }
}

impl GraphcutTextures {
    /// The carried count against `mask` (one flag per exemplar pixel); `what` names the argument
    /// in errors.
    fn carried_broken_of(&self, mask: &[bool], what: &'static str) -> JsResult<f64> {
        let s = self.session.synthesis();
        if s.sources.len() != 1 {
            return Err(Error::InvalidParameter {
                name: what,
                reason: format!(
                    "the carried count needs a session of the exemplar alone; this one has {} sources (deformations)",
                    s.sources.len()
                ),
            }
            .into());
        }
        let (sw, sh) = (s.sources[0].width(), s.sources[0].height());
        if mask.len() != sw * sh {
            return Err(Error::LengthMismatch {
                what,
                expected: sw * sh,
                actual: mask.len(),
            }
            .into());
        }
        let carried = carried_mask(s, &[mask]);
        Ok(carried_broken(
            &carried,
            (s.canvas.width, s.canvas.height),
            mask,
            (sw, sh),
        ))
    }
}
