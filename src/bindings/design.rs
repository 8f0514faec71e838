//! Texture design (Shen et al. 2009) for JS: `deformTexture` and `deformationSet` (stage 1) and
//! `makeTileable` / `TileableTexture` (section 4). The brush (stage 2) is in `brush.rs`, the
//! layer-based design (stage 4) in `layers.rs`; stage 3, the wavelet energy, is the `energy`
//! option of `TextureOptimization`.

use js_sys::{Array, Uint8ClampedArray};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::{OptionsReader, object};
use super::pixels::render_into;
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, Schema, boolean, invalid, kind_field, number,
};
use super::session::{JsSession, js_session};
use crate::methods::design::{
    Deformation, DeformationRanges, Steps, Tileable, TileableOptions, deform,
};

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
pub(super) fn read_deformations(value: &JsValue) -> JsResult<Vec<Deformation>> {
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
