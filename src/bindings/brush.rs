//! `TextureBrush`: local deformation with a brush (Shen et al. 2009, stage 2) for JS, with undo.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::OptionsReader;
use super::pixels::{render_into, write_rgba};
use super::schema::{EventField, Kind, MEMORY_BUDGET, Opt, Schema, boolean, number};
use crate::methods::design::{
    BrushOptions, LabellingWeights, LocalDeformation, Stroke, StrokeResult,
};

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

    /// Sets nu of eq. 2 (the cost of a brushed pixel that keeps the base) for the strokes to
    /// come; the strokes made and the undo history stay.
    #[wasm_bindgen(js_name = setNu)]
    pub fn set_nu(&mut self, nu: f64) -> JsResult<()> {
        let weights = self.design.options().weights;
        self.design.set_weights(LabellingWeights {
            nu: nu as f32,
            ..weights
        })?;
        Ok(())
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
