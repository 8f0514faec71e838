//! `FlowAnimation`: the JS-visible flow-guided texture animation, and `flowField` to preview a
//! flow without running one. Flows are a generator description (`{ type: 'vortex', strength }`,
//! or `{ components: [...] }` for combinations) or the caller's own fields as `Float32Array`s.

use js_sys::{Array, Float32Array, Float64Array, Uint8ClampedArray};
use wasm_bindgen::{JsCast, prelude::*};

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::OptionsReader;
use super::pixels::{check_target, render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, SEED, Schema, invalid, kind_field, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::Error;
use crate::core::error::check_size;
use crate::methods::flow::{
    Component, FlowEvent, FlowEventKind, FlowField, FlowKind, FlowOptions, FlowSession, FlowSource,
    FlowSpec,
};
use crate::solvers::nn::Search;

pub(crate) const SCHEMA: Schema = Schema {
    class: "FlowAnimation",
    options_name: "FlowAnimationOptions",
    options: &[
        MEMORY_BUDGET,
        output_size(
            "outputWidth",
            1 << 20,
            Some("128"),
            "Frame width in pixels.",
        ),
        output_size(
            "outputHeight",
            1 << 20,
            Some("128"),
            "Frame height in pixels.",
        ),
        Opt {
            key: "frames",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 32,
            },
            default: Some("60"),
            doc: "Frames to make.",
        },
        Opt {
            key: "lambda",
            kind: Kind::Number,
            default: Some("0.2"),
            doc: "Weight of the flow (soft-constraint) energy, eq. 3.",
        },
        Opt {
            key: "frameSizes",
            kind: Kind::Integers {
                min: 0,
                max: 1 << 20,
            },
            default: Some("[32, 16, 8]"),
            doc: "Neighbourhood sizes of the frames after the first; sizes that do not fit the exemplar (4 widths) or the frame are skipped; where none fits, the smallest at most half the exemplar.",
        },
        Opt {
            key: "frameIterations",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("3"),
            doc: "Iterations per size per frame; the last one's M-step only measures its matches (it reports 0 changed).",
        },
        SEED,
        Opt {
            key: "search",
            kind: Kind::Choice(&["patchmatch", "kmeans-tree", "exact"]),
            default: Some("'patchmatch'"),
            doc: "Nearest-neighbour search.",
        },
        Opt {
            key: "subPixel",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Matches at half-pixel precision: flows slower than half a pixel per frame move the texture (with whole-pixel matches they do not), for slightly softer frames.",
        },
        Opt {
            key: "r",
            kind: Kind::Number,
            default: Some("0.8"),
            doc: "Robust IRLS exponent, as for TextureOptimization.",
        },
        Opt {
            key: "tileable",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Make the frames tile seamlessly.",
        },
        Opt {
            key: "flow",
            kind: Kind::Value("Flow"),
            default: None,
            doc: "The flow: a generator `{ type, ... }`, a sum `{ components: [...] }`, one Float32Array of (vx, vy) per pixel (a stationary flow) or an array of them (f_1, f_2, ..., cycled). Default: a vortex of strength 2.",
        },
        Opt {
            key: "histogramMatching",
            kind: Kind::Number,
            default: Some("1"),
            doc: "How far each frame's colour histogram is matched to the exemplar's (0..1), as for TextureOptimization.",
        },
    ],
    required: &[],
    event_name: "FlowAnimationEvent",
    event: &[
        kind_field("'part' | 'iteration' | 'frame' | 'done'"),
        DONE,
        EventField {
            key: "frameFinished",
            ts: "boolean",
            doc: "A frame was finished by this step: `renderInto` gives it.",
        },
        EventField {
            key: "frame",
            ts: "number",
            doc: "The frame worked on, 0 for the first.",
        },
        EventField {
            key: "iteration",
            ts: "number",
            doc: "Iteration within the frame.",
        },
        EventField {
            key: "neighbourhoodSize",
            ts: "number",
            doc: "Neighbourhood size of the iteration.",
        },
        EventField {
            key: "textureEnergy",
            ts: "number",
            doc: "Texture energy of the frame.",
        },
        EventField {
            key: "flowEnergy",
            ts: "number",
            doc: "Flow energy of eq. 3 (0 in the first frame).",
        },
        EventField {
            key: "changed",
            ts: "number",
            doc: "Matches that changed in this iteration.",
        },
        EventField {
            key: "totalIterations",
            ts: "number",
            doc: "Iterations so far over all frames.",
        },
        EventField {
            key: "phase",
            ts: "'start' | 'first-match' | 'e-step' | 'm-step'",
            doc: "The half of the iteration a 'part' step stopped in (a whole iteration: 'm-step'; 'e-step' for a later frame's last iteration at a size, whose M-step only measures).",
        },
        EventField {
            key: "progress",
            ts: "number",
            doc: "Share of the iteration done, 0 to 1 (1 for a whole iteration).",
        },
    ],
};

/// One flow generator of the `flow` option.
pub(crate) const COMPONENT_SCHEMA: Schema = Schema {
    class: "flow",
    options_name: "FlowComponent",
    options: &[
        Opt {
            key: "type",
            kind: Kind::Choice(&["sink", "source", "vortex", "shear", "translation"]),
            default: None,
            doc: "The generator.",
        },
        Opt {
            key: "strength",
            kind: Kind::Number,
            default: Some("1"),
            doc: "Pixels per frame at half the frame's shorter side (the animation's default vortex has 2).",
        },
        Opt {
            key: "centreX",
            kind: Kind::Number,
            default: Some("0.5"),
            doc: "Centre, 0..1 of the width.",
        },
        Opt {
            key: "centreY",
            kind: Kind::Number,
            default: Some("0.5"),
            doc: "Centre, 0..1 of the height.",
        },
        Opt {
            key: "angle",
            kind: Kind::Number,
            default: Some("0"),
            doc: "Degrees (translation and shear).",
        },
        Opt {
            key: "period",
            kind: Kind::Number,
            default: Some("0"),
            doc: "Frames; the strength oscillates with this period (0: constant).",
        },
        Opt {
            key: "turn",
            kind: Kind::Number,
            default: Some("0"),
            doc: "Degrees per frame the angle turns.",
        },
    ],
    required: &["type"],
    event_name: "",
    event: &[],
};

/// `{ type, strength, centreX, centreY, angle, period, turn }`; only `type` is required.
fn read_component(value: &JsValue) -> JsResult<Component> {
    let js = OptionsReader::new(value, &COMPONENT_SCHEMA)?;
    let names = FlowKind::ALL.map(FlowKind::name).join("', '");
    let kind = match js.choice("type", FlowKind::from_name) {
        Ok(Some(kind)) => kind,
        Err(_) => {
            let got = js
                .value("type")?
                .and_then(|v| v.as_string())
                .map_or(String::new(), |name| format!(", got '{name}'"));
            return Err(invalid(
                "flow.type",
                format!("must be one of '{names}'{got}"),
            ));
        }
        Ok(None) => {
            return Err(invalid(
                "flow.type",
                format!("is required: one of '{names}'"),
            ));
        }
    };
    let d = Component::new(kind, 1.0);
    let num = |name: &'static str, default: f32| -> JsResult<f32> {
        Ok(js.number(name)?.map_or(default, |v| v as f32))
    };
    let component = Component {
        kind,
        strength: num("strength", d.strength)?,
        center: (num("centreX", d.center.0)?, num("centreY", d.center.1)?),
        angle: num("angle", d.angle)?,
        period: num("period", d.period)?,
        turn: num("turn", d.turn)?,
    };
    js.finish()?;
    Ok(component)
}

/// A generator (`{ type, ... }` or `{ components: [{ type, ... }, ...] }`).
fn read_spec(value: &JsValue) -> JsResult<FlowSpec> {
    let components = js_sys::Reflect::get(value, &"components".into()).unwrap_or_default();
    let list = if components.is_undefined() {
        vec![read_component(value)?]
    } else {
        if !Array::is_array(&components) {
            return Err(invalid("flow.components", "must be an array of components"));
        }
        Array::from(&components)
            .iter()
            .map(|c| read_component(&c))
            .collect::<JsResult<Vec<_>>>()?
    };
    Ok(FlowSpec::new(list)?)
}

/// A `Float32Array` of `width * height * 2` displacements.
fn read_field(value: &JsValue, width: usize, height: usize) -> JsResult<FlowField> {
    let Some(array) = value.dyn_ref::<Float32Array>() else {
        return Err(invalid(
            "flow",
            "fields must be Float32Arrays of (vx, vy) per pixel",
        ));
    };
    Ok(FlowField::from_vec(width, height, array.to_vec())?)
}

/// The `flow` option: a generator object, one field, or an array of fields (one per frame).
fn read_flow(value: Option<JsValue>, width: usize, height: usize) -> JsResult<FlowSource> {
    let Some(value) = value else {
        return Ok(FlowSource::Generator(FlowSpec::new(vec![Component::new(
            FlowKind::Vortex,
            2.0,
        )])?));
    };
    if value.is_instance_of::<Float32Array>() {
        return Ok(FlowSource::Fields(vec![read_field(&value, width, height)?]));
    }
    if Array::is_array(&value) {
        let fields = Array::from(&value)
            .iter()
            .map(|f| read_field(&f, width, height))
            .collect::<JsResult<Vec<_>>>()?;
        return Ok(FlowSource::Fields(fields));
    }
    if value.is_object() {
        return Ok(FlowSource::Generator(read_spec(&value)?));
    }
    Err(invalid(
        "flow",
        "must be { type: 'vortex', ... }, { components: [...] }, a Float32Array or an array of them",
    ))
}

/// Reads the options object; absent keys keep the defaults of [`FlowOptions`].
fn read_options(value: &JsValue) -> JsResult<(FlowOptions, FlowSource)> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = FlowOptions::default();
    let options = FlowOptions {
        memory_budget_mib: js.memory_budget()?,
        output_width: js.size("outputWidth")?.unwrap_or(d.output_width),
        output_height: js.size("outputHeight")?.unwrap_or(d.output_height),
        frames: js.size("frames")?.unwrap_or(d.frames),
        lambda: js.number("lambda")?.map_or(d.lambda, |v| v as f32),
        histogram_matching: js
            .number("histogramMatching")?
            .map_or(d.histogram_matching, |v| v as f32),
        frame_sizes: js.integers("frameSizes")?.map_or(d.frame_sizes, |v| {
            v.into_iter().map(|s| s as usize).collect()
        }),
        frame_iterations: js.size("frameIterations")?.unwrap_or(d.frame_iterations),
        seed: js.integer("seed")?.unwrap_or(d.seed),
        search: js.choice("search", Search::from_name)?.unwrap_or(d.search),
        r: js.number("r")?.map_or(d.r, |v| v as f32),
        tileable: js.boolean("tileable")?.unwrap_or(d.tileable),
        sub_pixel: js.boolean("subPixel")?.unwrap_or(d.sub_pixel),
    };
    let flow = read_flow(
        js.value("flow")?,
        options.output_width,
        options.output_height,
    )?;
    js.finish()?;
    Ok((options, flow))
}

fn event_object(e: &FlowEvent) -> JsResult<JsValue> {
    let kind = match e.kind {
        FlowEventKind::Part => "part",
        FlowEventKind::Iteration => "iteration",
        FlowEventKind::Frame => "frame",
        FlowEventKind::Done => "done",
    };
    SCHEMA.event(&[
        ("kind", kind.into()),
        ("done", (e.kind == FlowEventKind::Done).into()),
        (
            "frameFinished",
            matches!(e.kind, FlowEventKind::Frame | FlowEventKind::Done).into(),
        ),
        ("frame", (e.frame as u32).into()),
        ("iteration", (e.iteration as u32).into()),
        ("neighbourhoodSize", (e.size as u32).into()),
        ("textureEnergy", e.texture_energy.into()),
        ("flowEnergy", e.flow_energy.into()),
        ("changed", (e.changed as u32).into()),
        ("totalIterations", (e.total_iterations as u32).into()),
        ("phase", super::optimization::phase_name(e.phase).into()),
        ("progress", e.progress.into()),
    ])
}

/// The field f_t (`t` = 0, 1, ...) of a generator description for a `width` x `height` frame,
/// as `(vx, vy)` pixel displacements per pixel: for drawing a flow before animating with it.
#[wasm_bindgen(js_name = flowField)]
pub fn flow_field(flow: JsValue, width: u32, height: u32, t: u32) -> JsResult<Float32Array> {
    if !flow.is_object() {
        return Err(invalid(
            "flow",
            "must be { type: 'vortex', ... } or { components: [...] }",
        ));
    }
    // The size first: an unchecked 2^32 - 1 (what JS -1 becomes) overflowed the field's
    // allocation, a trap (corpus rows "flowField: huge" and "flowField: -1 width").
    check_size("flow field", width as usize, height as usize)?;
    let field = read_spec(&flow)?.field(width as usize, height as usize, t as usize)?;
    Ok(Float32Array::from(field.data()))
}

/// A flow-guided texture animation (Kwatra et al. 2005, section 4.1) you advance with `step()`.
#[wasm_bindgen]
pub struct FlowAnimation {
    session: FlowSession,
}

js_session!(FlowAnimation);

/// One EM iteration per step; frames larger than 256x512 split each iteration over steps of
/// about 60 ms (kind 'part'), and setting up a frame is a step or more of its own; where they
/// split changes nothing. After a 'frame' (or 'done') event, `renderInto` gives that frame.
impl JsSession for FlowAnimation {
    fn step_event(&mut self) -> JsResult<JsValue> {
        event_object(&self.session.step()?)
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    fn size(&self) -> (usize, usize) {
        let o = self.session.options();
        (o.output_width, o.output_height)
    }

    fn memory_bytes(&self) -> u64 {
        self.session.working_set().bytes()
    }

    /// The frame being made (or the last one finished).
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.frame_image()?, target)
    }
}

#[wasm_bindgen]
impl FlowAnimation {
    /// Options: see [`SCHEMA`] (every key optional), the flow's generators [`COMPONENT_SCHEMA`].
    /// Unknown keys and impossible values throw.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<FlowAnimation> {
        let (options, flow) = read_options(&options)?;
        Ok(FlowAnimation {
            session: FlowSession::new(exemplar.image(), flow, options)?,
        })
    }

    /// Frames finished so far.
    #[wasm_bindgen(getter, js_name = framesFinished)]
    pub fn frames_finished(&self) -> u32 {
        self.session.frame() as u32
    }

    /// Frames the animation will have.
    #[wasm_bindgen(getter)]
    pub fn frames(&self) -> u32 {
        self.session.options().frames as u32
    }

    /// Writes the naive baseline (the first frame warped along the flow, without synthesis) at
    /// the current frame into `target`.
    #[wasm_bindgen(js_name = renderNaiveInto)]
    pub fn render_naive_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.naive_image()?, target)
    }

    /// The field f_t of this animation as `(vx, vy)` per pixel.
    #[wasm_bindgen(js_name = flowField)]
    pub fn flow_field(&self, t: u32) -> JsResult<Float32Array> {
        Ok(Float32Array::from(
            self.session.field_at(t as usize)?.data(),
        ))
    }

    /// Texture energy each finished frame ended with.
    #[wasm_bindgen(js_name = textureEnergyHistory)]
    pub fn texture_energy_history(&self) -> Float64Array {
        let v: Vec<f64> = self.session.history().iter().map(|e| e.texture).collect();
        Float64Array::from(v.as_slice())
    }

    /// Flow energy each finished frame ended with (0 for the first).
    #[wasm_bindgen(js_name = flowEnergyHistory)]
    pub fn flow_energy_history(&self) -> Float64Array {
        let v: Vec<f64> = self.session.history().iter().map(|e| e.flow).collect();
        Float64Array::from(v.as_slice())
    }

    /// Step anatomy (as `TextureOptimization.setHalfSteps`): with `true` every step ends after
    /// one half of an EM iteration, in frame 1's multi-level synthesis and in every later frame:
    /// a part event `{ kind: 'part', phase: 'first-match' }` after the M-step on a frame's warped
    /// start (or a level's up-sampled output), `'e-step'` after each E-step, then the
    /// iteration's event after its M-step. `false` steps whole iterations again. The frames are
    /// the same either way.
    #[wasm_bindgen(js_name = setHalfSteps)]
    pub fn set_half_steps(&mut self, on: bool) {
        self.session.set_half_steps(on);
    }

    /// The neighbourhood grid and matches the last step worked on, as
    /// `TextureOptimization.field()` returns them (`{ columns, rows, neighbourhoodSize,
    /// levelWidth, levelHeight, exemplarWidth, exemplarHeight, matches, distances, weights, r }`):
    /// frame 1's current level, then the frame level (one per frame neighbourhood size, at full
    /// resolution) last iterated. `null` before the first step and from the step that finishes
    /// frame 1 until frame 2 iterates.
    pub fn field(&self) -> JsValue {
        match self.session.anatomy_field() {
            Some((f, solver)) => {
                super::optimization::field_object(&f, Some(solver), self.session.options().r)
            }
            None => JsValue::NULL,
        }
    }

    /// Writes the previous frame carried along the flow into `target` (RGBA8, `width * height
    /// * 4`): the soft-constraint target of eq. 3 and the start of the current frame, with alpha
    /// 0 where the warp's source lies outside the frame (the constraint's mask). Throws during
    /// frame 1, which has no previous frame.
    #[wasm_bindgen(js_name = renderWarpedInto)]
    pub fn render_warped_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        // The target first, as every renderer checks it: a bad buffer is named whatever the frame.
        check_target(target)?;
        let (w, h) = JsSession::size(self);
        let expected = w * h * 4;
        if target.length() as usize != expected {
            return Err(Error::LengthMismatch {
                what: "target pixel array",
                expected,
                actual: target.length() as usize,
            }
            .into());
        }
        let Some(constraint) = self.session.warped_previous() else {
            return Err(invalid(
                "renderWarpedInto",
                "frame 1 has no warped previous frame (it is plain texture optimisation); \
                 call it once frame 2 has begun",
            ));
        };
        // The mask as alpha, so that a canvas shows where the constraint does not hold.
        let mut rgba = crate::core::to_rgba8(&constraint.target);
        for (pixel, &m) in rgba.chunks_exact_mut(4).zip(&constraint.mask) {
            pixel[3] = (m.clamp(0.0, 1.0) * 255.0).round() as u8;
        }
        write_rgba(&rgba, target)
    }
}
