//! Texture design (Shen et al. 2009) for JS: `deformTexture` and `deformationSet` (stage 1),
//! `TextureBrush` (stage 2, local deformation with undo), `LayerDesign` (stage 4, a session that
//! steps one row of patches at a time) and `makeTileable` (section 4). Stage 3, the wavelet
//! energy, is the `energy` option of `TextureOptimization`.

use js_sys::{Array, Uint8ClampedArray};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::{OptionsReader, object};
use super::pixels::{render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, Schema, invalid, kind_field, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::{Error, Image};
use crate::methods::design::layers::{
    Layer, LayerDesign as Design, LayerOptions, LayerPlacement, LayerSearch,
};
use crate::methods::design::{
    BrushOptions, Deformation, DeformationRanges, LabellingWeights, LocalDeformation, Steps,
    Stroke, StrokeResult, Tileable, TileableOptions, deform,
};

const fn boolean(key: &'static str, default: &'static str, doc: &'static str) -> Opt {
    Opt {
        key,
        kind: Kind::Boolean,
        default: Some(default),
        doc,
    }
}

const fn number(key: &'static str, default: Option<&'static str>, doc: &'static str) -> Opt {
    Opt {
        key,
        kind: Kind::Number,
        default,
        doc,
    }
}

/// One deformation object of `deformTexture` and `addLayer` (its TypeScript is the hand-written
/// union `Deformation`: exactly one key).
const DEFORMATION_SCHEMA: Schema = Schema {
    class: "deformation",
    options_name: "",
    options: &[
        number("rotate", None, "Degrees, counter-clockwise."),
        Opt {
            key: "shift",
            kind: Kind::Numbers,
            default: None,
            doc: "[dx, dy], whole pixels, wrapping.",
        },
        boolean("mirror", "false", "Mirror left to right."),
        boolean("flip", "false", "Flip top to bottom."),
        number("scale", None, "Scale factor."),
    ],
    required: &[],
    event_name: "",
    event: &[],
};

/// A range `{ from, to, step }` of `deformationSet`.
pub(crate) const RANGE_SCHEMA: Schema = Schema {
    class: "range",
    options_name: "Range",
    options: &[
        number("from", None, "First value."),
        number("to", None, "Last value (included when the steps reach it)."),
        number("step", None, "Step between values."),
    ],
    required: &["from", "to", "step"],
    event_name: "",
    event: &[],
};

pub(crate) const RANGES_SCHEMA: Schema = Schema {
    class: "deformationSet",
    options_name: "DeformationRanges",
    options: &[
        Opt {
            key: "rotation",
            kind: Kind::Value("Range"),
            default: None,
            doc: "Rotations, in degrees.",
        },
        Opt {
            key: "scale",
            kind: Kind::Value("Range"),
            default: None,
            doc: "Scale factors.",
        },
        Opt {
            key: "shift",
            kind: Kind::Value("Range"),
            default: None,
            doc: "Shifts along both axes, as a fraction of the size.",
        },
        boolean("mirror", "false", "Also the mirrored texture."),
        boolean("flip", "false", "Also the flipped texture."),
    ],
    required: &[],
    event_name: "",
    event: &[],
};

/// One deformation from `{ rotate: 30 }`, `{ shift: [dx, dy] }`, `{ mirror: true }`,
/// `{ flip: true }` or `{ scale: 1.5 }`.
fn read_deformation(value: &JsValue) -> JsResult<Option<Deformation>> {
    let js = OptionsReader::new(value, &DEFORMATION_SCHEMA)?;
    let mut found = Vec::new();
    if let Some(degrees) = js.number("rotate")? {
        found.push(Deformation::Rotate { degrees });
    }
    if let Some(shift) = js.numbers("shift")? {
        if shift.len() != 2 || shift.iter().any(|v| v.fract() != 0.0 || v.abs() > 1e6) {
            return Err(invalid(
                "shift",
                "must be [dx, dy], two whole numbers of pixels",
            ));
        }
        found.push(Deformation::Shift {
            dx: shift[0] as isize,
            dy: shift[1] as isize,
        });
    }
    if js.boolean("mirror")? == Some(true) {
        found.push(Deformation::Mirror);
    }
    if js.boolean("flip")? == Some(true) {
        found.push(Deformation::Flip);
    }
    if let Some(factor) = js.number("scale")? {
        found.push(Deformation::Scale { factor });
    }
    js.finish()?;
    if found.len() > 1 {
        return Err(invalid(
            "deformation",
            "each object names one deformation; give an array for several, in order",
        ));
    }
    if let Some(d) = found.first() {
        d.validate()?;
    }
    Ok(found.first().copied())
}

/// A deformation object or an array of them.
fn read_deformations(value: &JsValue) -> JsResult<Vec<Deformation>> {
    if value.is_undefined() || value.is_null() {
        return Ok(Vec::new());
    }
    let items: Vec<JsValue> = if Array::is_array(value) {
        Array::from(value).iter().collect()
    } else {
        vec![value.clone()]
    };
    if items.len() > 16 {
        return Err(invalid(
            "deformations",
            format!("at most 16 in a row, got {}", items.len()),
        ));
    }
    let mut out = Vec::new();
    for item in &items {
        if let Some(d) = read_deformation(item)? {
            out.push(d);
        }
    }
    Ok(out)
}

/// Applies global deformations (stage 1) in order: `deformTexture(exemplar, [{ rotate: 30 },
/// { scale: 0.75 }])`. Rotation by a multiple of 90 degrees, mirror, flip and shift are exact;
/// other angles and scales resample and keep only pixels from inside the texture.
#[wasm_bindgen(js_name = deformTexture)]
pub fn deform_texture(exemplar: &Exemplar, deformations: JsValue) -> JsResult<Exemplar> {
    let list = read_deformations(&deformations)?;
    Ok(Exemplar::from_image(deform(exemplar.image(), &list)?))
}

fn read_steps(js: &OptionsReader, name: &'static str) -> JsResult<Option<Steps>> {
    let Some(value) = js.value(name)? else {
        return Ok(None);
    };
    // Named here: the reader below would call a non-object just "options" (corpus row
    // "deformationSet { rotation: 5 }").
    if !value.is_object() {
        return Err(invalid(name, "must be a range { from, to, step }"));
    }
    let r = OptionsReader::new(&value, &RANGE_SCHEMA)?;
    let need = |v: Option<f64>, key: &str| {
        v.ok_or_else(|| {
            invalid(
                name,
                format!("needs '{key}' (a range is {{ from, to, step }})"),
            )
        })
    };
    let steps = Steps {
        from: need(r.number("from")?, "from")?,
        to: need(r.number("to")?, "to")?,
        step: need(r.number("step")?, "step")?,
    };
    r.finish()?;
    Ok(Some(steps))
}

/// The set of deformed textures I_g1..I_gk (stage 1): one per value of each range,
/// `deformationSet(exemplar, { rotation: { from: 0, to: 90, step: 30 }, scale: { from: 0.5,
/// to: 1.5, step: 0.5 }, shift: { from: 0.25, to: 0.5, step: 0.25 }, mirror: true, flip: true
/// })` (shift as a fraction of the size). Returns `[{ label, exemplar }]`, at most 64.
#[wasm_bindgen(js_name = deformationSet)]
pub fn deformation_set(exemplar: &Exemplar, ranges: JsValue) -> JsResult<Array> {
    let js = OptionsReader::new(&ranges, &RANGES_SCHEMA)?;
    let ranges = DeformationRanges {
        rotation: read_steps(&js, "rotation")?,
        scale: read_steps(&js, "scale")?,
        shift: read_steps(&js, "shift")?,
        mirror: js.boolean("mirror")?.unwrap_or(false),
        flip: js.boolean("flip")?.unwrap_or(false),
    };
    js.finish()?;
    let image = exemplar.image();
    let out = Array::new();
    for d in ranges.expand(image.width(), image.height())? {
        out.push(&object(&[
            ("label", d.label().into()),
            ("exemplar", Exemplar::from_image(d.apply(image)?).into()),
        ]));
    }
    Ok(out)
}

pub(crate) const TILEABLE_SCHEMA: Schema = Schema {
    class: "TileableTexture",
    options_name: "TileableOptions",
    options: &[
        MEMORY_BUDGET,
        Opt {
            key: "overlapX",
            kind: Kind::Integer { min: 0, max: 4096 },
            default: None,
            doc: "Overlap of the horizontal stitch in pixels. Default: a sixth of the width, at most 64.",
        },
        Opt {
            key: "overlapY",
            kind: Kind::Integer { min: 0, max: 4096 },
            default: None,
            doc: "Overlap of the vertical stitch in pixels. Default: a sixth of the height, at most 64.",
        },
    ],
    required: &[],
    event_name: "TileableEvent",
    event: &[
        kind_field("'stitched' | 'done'"),
        DONE,
        EventField {
            key: "axis",
            ts: "'x' | 'y'",
            doc: "The stitch made: 'x' joins the left and right edges, 'y' the top and bottom.",
        },
        EventField {
            key: "cut",
            ts: "number",
            doc: "Where the stitch's overlap starts.",
        },
        EventField {
            key: "seamCost",
            ts: "number",
            doc: "Cost of the stitch's min cut.",
        },
    ],
};

fn read_tileable_options(options: &JsValue) -> JsResult<TileableOptions> {
    let js = OptionsReader::new(options, &TILEABLE_SCHEMA)?;
    let options = TileableOptions {
        memory_budget_mib: Some(js.memory_budget()?),
        overlap_x: js.size("overlapX")?,
        overlap_y: js.size("overlapY")?,
    };
    js.finish()?;
    Ok(options)
}

fn tileable_object(t: &Tileable) -> JsValue {
    let seam: Vec<u8> = t
        .seam
        .iter()
        .flat_map(|&s| if s { [255, 40, 40, 255] } else { [0, 0, 0, 0] })
        .collect();
    object(&[
        ("exemplar", Exemplar::from_image(t.image.clone()).into()),
        ("cutX", (t.cut_x as u32).into()),
        ("cutY", (t.cut_y as u32).into()),
        ("seamCostX", t.seam_cost_x.into()),
        ("seamCostY", t.seam_cost_y.into()),
        ("seam", Uint8ClampedArray::from(seam.as_slice()).into()),
    ])
}

/// Makes an image cyclic (section 4) in one call: `makeTileable(exemplar, { overlapX, overlapY
/// })` (defaults: a sixth of each side, at most 64). Returns `{ exemplar, cutX, cutY, seamCostX,
/// seamCostY, seam }` (`seam`: RGBA, red on the stitches); the image is smaller than the input
/// by the overlaps. For large images use `TileableTexture`, which makes one stitch per step.
#[wasm_bindgen(js_name = makeTileable)]
pub fn make_tileable(exemplar: &Exemplar, options: JsValue) -> JsResult<JsValue> {
    let t =
        crate::methods::design::make_tileable(exemplar.image(), read_tileable_options(&options)?)?;
    Ok(tileable_object(&t))
}

/// Making an image cyclic one graph cut per step: the horizontal stitch, then the vertical.
#[wasm_bindgen]
pub struct TileableTexture {
    session: crate::methods::design::TileableSession,
}

js_session!(TileableTexture);

/// One stitch per step.
impl JsSession for TileableTexture {
    fn step_event(&mut self) -> JsResult<JsValue> {
        let e = self.session.step()?;
        TILEABLE_SCHEMA.event(&[
            ("kind", if e.done { "done" } else { "stitched" }.into()),
            ("done", e.done.into()),
            ("axis", if e.vertical { "y" } else { "x" }.into()),
            ("cut", (e.cut as u32).into()),
            ("seamCost", e.seam_cost.into()),
        ])
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    /// The image as far as it is made (it shrinks by the overlap at each stitch).
    fn size(&self) -> (usize, usize) {
        (self.session.image().width(), self.session.image().height())
    }

    fn memory_bytes(&self) -> u64 {
        self.session.working_set().bytes()
    }

    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(self.session.image(), target)
    }
}

#[wasm_bindgen]
impl TileableTexture {
    /// `new TileableTexture(exemplar, { overlapX, overlapY })`.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<TileableTexture> {
        Ok(TileableTexture {
            session: crate::methods::design::TileableSession::new(
                exemplar.image(),
                read_tileable_options(&options)?,
            )?,
        })
    }

    /// The finished texture, as `makeTileable` returns it.
    pub fn result(&self) -> JsResult<JsValue> {
        self.session
            .result()
            .map(tileable_object)
            .ok_or_else(|| invalid("tileable texture", "is not done: step() until done"))
    }
}

pub(crate) const BRUSH_SCHEMA: Schema = Schema {
    class: "TextureBrush",
    options_name: "TextureBrushOptions",
    options: &[
        MEMORY_BUDGET,
        number(
            "nu",
            Some("1000"),
            "Weight of the brushed-pixel term of eq. 1.",
        ),
        number(
            "k1",
            Some("0.5"),
            "Weight k1 of the smoothness term of eq. 3.",
        ),
        number(
            "k2",
            Some("0.5"),
            "Weight k2 of the smoothness term of eq. 3.",
        ),
        Opt {
            key: "margin",
            kind: Kind::Integer { min: 0, max: 256 },
            default: Some("12"),
            doc: "Pixels around the stroke the graph cut may use.",
        },
        boolean(
            "poisson",
            "true",
            "Poisson paste of the reference's pixels.",
        ),
    ],
    required: &[],
    event_name: "BrushStroke",
    event: &[
        EventField {
            key: "x",
            ts: "number",
            doc: "Left of the box the stroke changed.",
        },
        EventField {
            key: "y",
            ts: "number",
            doc: "Top of the box the stroke changed.",
        },
        EventField {
            key: "width",
            ts: "number",
            doc: "Width of that box.",
        },
        EventField {
            key: "height",
            ts: "number",
            doc: "Height of that box.",
        },
        EventField {
            key: "pixelsTaken",
            ts: "number",
            doc: "Base pixels that took the reference.",
        },
        EventField {
            key: "energy",
            ts: "number",
            doc: "The labelling energy of eqs. 1-3.",
        },
        EventField {
            key: "poissonIterations",
            ts: "number",
            doc: "Iterations of the Poisson solve (0 without Poisson paste).",
        },
    ],
};

/// Local deformation with a brush (stage 2): paint over texture elements of a reference, drag
/// them onto the base, and the graph cut (eqs. 1-3) and Poisson paste put them in. Undoable.
#[wasm_bindgen]
pub struct TextureBrush {
    design: LocalDeformation,
    last: Option<StrokeResult>,
}

#[wasm_bindgen]
impl TextureBrush {
    /// `new TextureBrush(base, { nu: 1000, k1: 0.5, k2: 0.5, margin: 12, poisson: true })`.
    #[wasm_bindgen(constructor)]
    pub fn new(base: &Exemplar, options: JsValue) -> JsResult<TextureBrush> {
        let js = OptionsReader::new(&options, &BRUSH_SCHEMA)?;
        let d = BrushOptions::default();
        let options = BrushOptions {
            weights: LabellingWeights {
                nu: js.number("nu")?.map_or(d.weights.nu, |v| v as f32),
                k1: js.number("k1")?.map_or(d.weights.k1, |v| v as f32),
                k2: js.number("k2")?.map_or(d.weights.k2, |v| v as f32),
            },
            margin: js.size("margin")?.unwrap_or(d.margin),
            poisson: js.boolean("poisson")?.unwrap_or(d.poisson),
            memory_budget_mib: js.memory_budget()?,
        };
        js.finish()?;
        Ok(TextureBrush {
            design: LocalDeformation::new(base.image(), options)?,
            last: None,
        })
    }

    /// The estimated peak memory of this session, in bytes: what the constructor compared with
    /// the memory budget (`memoryBudgetMiB`, default 1024 MiB).
    #[wasm_bindgen(getter, js_name = memoryEstimate)]
    pub fn memory_estimate(&self) -> f64 {
        self.design.working_set().bytes() as f64
    }

    /// One stroke: `mask` has one byte per reference pixel (non-zero where painted); the painted
    /// elements move by (dx, dy) onto the base. Returns `{ x, y, width, height, taken, energy,
    /// poissonIterations }` (the window on the base, the pixels that took the reference, E(L)).
    pub fn stroke(
        &mut self,
        reference: &Exemplar,
        mask: &[u8],
        dx: i32,
        dy: i32,
    ) -> JsResult<JsValue> {
        let mask: Vec<bool> = mask.iter().map(|&m| m != 0).collect();
        let r = self.design.stroke(&Stroke {
            reference: reference.image(),
            mask: &mask,
            dx: dx as isize,
            dy: dy as isize,
        })?;
        let event = BRUSH_SCHEMA.event(&[
            ("x", (r.x as u32).into()),
            ("y", (r.y as u32).into()),
            ("width", (r.width as u32).into()),
            ("height", (r.height as u32).into()),
            ("pixelsTaken", (r.taken as u32).into()),
            ("energy", r.energy.into()),
            ("poissonIterations", (r.poisson_iterations as u32).into()),
        ])?;
        self.last = Some(r);
        Ok(event)
    }

    /// Goes back one stroke; false when there is none.
    pub fn undo(&mut self) -> bool {
        self.last = None;
        self.design.undo()
    }

    #[wasm_bindgen(getter, js_name = undoDepth)]
    pub fn undo_depth(&self) -> u32 {
        self.design.undo_depth() as u32
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.design.image().width() as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.design.image().height() as u32
    }

    /// The base as it is now.
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(self.design.image(), target)
    }

    /// The last stroke's labelling over the base (Fig. 3e): blue where the pixels took the
    /// reference, brighter where brushed, red along the seam, transparent elsewhere.
    #[wasm_bindgen(js_name = renderLabelsInto)]
    pub fn render_labels_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        let (w, h) = (self.width() as usize, self.height() as usize);
        let mut rgba = vec![0u8; w * h * 4];
        if let Some(r) = &self.last {
            let label = |x: usize, y: usize| r.labels[y * r.width + x];
            for y in 0..r.height {
                for x in 0..r.width {
                    let l = label(x, y);
                    let taken = l > 0;
                    let seam = [(x + 1 < r.width, x + 1, y), (y + 1 < r.height, x, y + 1)]
                        .iter()
                        .any(|&(ok, xx, yy)| ok && (label(xx, yy) > 0) != taken)
                        || (x > 0 && (label(x - 1, y) > 0) != taken)
                        || (y > 0 && (label(x, y - 1) > 0) != taken);
                    let px = match (seam, l) {
                        (true, _) => [255, 40, 40, 255],
                        (false, 2) => [80, 170, 255, 150],
                        (false, 1) => [80, 120, 255, 90],
                        _ => [0, 0, 0, 0],
                    };
                    let i = ((r.y + y) * w + r.x + x) * 4;
                    rgba[i..i + 4].copy_from_slice(&px);
                }
            }
        }
        write_rgba(&rgba, target)
    }

    /// The base as an `Exemplar`, to synthesise from or to use as another stroke's reference.
    #[wasm_bindgen(js_name = toExemplar)]
    pub fn to_exemplar(&self) -> Exemplar {
        Exemplar::from_image(self.design.image().clone())
    }
}

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
