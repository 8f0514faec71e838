//! `FlowAnimation`: the JS-visible flow-guided texture animation, and `flowField` to preview a
//! flow without running one. Flows are a generator description (`{ type: 'vortex', strength }`,
//! or `{ components: [...] }` for combinations) or the caller's own fields as `Float32Array`s.

use js_sys::{Array, Float32Array, Float64Array, Uint8ClampedArray};
use wasm_bindgen::{JsCast, prelude::*};

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::{OptionsReader, object};
use super::pixels::{check_target, render_into, write_rgba};
use crate::core::Error;
use crate::core::error::check_size;
use crate::methods::flow::{
    Component, FlowEvent, FlowEventKind, FlowField, FlowKind, FlowOptions, FlowSession, FlowSource,
    FlowSpec,
};
use crate::solvers::nn::Search;

const KNOWN: &[&str] = &[
    "outputWidth",
    "outputHeight",
    "frames",
    "lambda",
    "frameSizes",
    "frameIterations",
    "seed",
    "search",
    "subPixel",
    "r",
    "tileable",
    "flow",
    "histogramMatching",
    "memoryBudgetMiB",
];

const COMPONENT_KEYS: &[&str] = &[
    "type", "strength", "centerX", "centerY", "angle", "period", "turn",
];

fn invalid(name: &'static str, reason: impl Into<String>) -> JsError {
    Error::InvalidParameter {
        name,
        reason: reason.into(),
    }
    .into()
}

/// `{ type, strength, centerX, centerY, angle, period, turn }`; only `type` is required.
fn read_component(value: &JsValue) -> JsResult<Component> {
    let js = OptionsReader::new(value, COMPONENT_KEYS)?;
    let names = FlowKind::ALL.map(FlowKind::name).join("', '");
    let kind = match js.string("type")? {
        Some(name) => FlowKind::from_name(&name).ok_or_else(|| {
            invalid(
                "flow.type",
                format!("must be one of '{names}', got '{name}'"),
            )
        })?,
        None => {
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
    Ok(Component {
        kind,
        strength: num("strength", d.strength)?,
        center: (num("centerX", d.center.0)?, num("centerY", d.center.1)?),
        angle: num("angle", d.angle)?,
        period: num("period", d.period)?,
        turn: num("turn", d.turn)?,
    })
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
    let js = OptionsReader::new(value, KNOWN)?;
    let d = FlowOptions::default();
    let search = match js.string("search")? {
        None => d.search,
        Some(name) => Search::from_name(&name).ok_or_else(|| {
            invalid(
                "search",
                format!("must be 'patchmatch', 'kmeans-tree' or 'exact', got '{name}'"),
            )
        })?,
    };
    let options = FlowOptions {
        memory_budget_mib: js.memory_budget()?,
        output_width: js
            .integer("outputWidth", 1, 1 << 20)?
            .map_or(d.output_width, |v| v as usize),
        output_height: js
            .integer("outputHeight", 1, 1 << 20)?
            .map_or(d.output_height, |v| v as usize),
        frames: js
            .integer("frames", 0, 1 << 32)?
            .map_or(d.frames, |v| v as usize),
        lambda: js.number("lambda")?.map_or(d.lambda, |v| v as f32),
        histogram_matching: js
            .number("histogramMatching")?
            .map_or(d.histogram_matching, |v| v as f32),
        frame_sizes: js
            .integers("frameSizes", 0, 1 << 20)?
            .map_or(d.frame_sizes, |v| {
                v.into_iter().map(|s| s as usize).collect()
            }),
        frame_iterations: js
            .integer("frameIterations", 0, 1 << 20)?
            .map_or(d.frame_iterations, |v| v as usize),
        seed: js.integer("seed", 0, (1 << 53) - 1)?.unwrap_or(d.seed),
        search,
        r: js.number("r")?.map_or(d.r, |v| v as f32),
        tileable: js.boolean("tileable")?.unwrap_or(d.tileable),
        sub_pixel: js.boolean("subPixel")?.unwrap_or(d.sub_pixel),
    };
    let flow = read_flow(
        js.value("flow")?,
        options.output_width,
        options.output_height,
    )?;
    Ok((options, flow))
}

fn event_object(e: &FlowEvent) -> JsValue {
    let kind = match e.kind {
        FlowEventKind::Part => "part",
        FlowEventKind::Iteration => "iteration",
        FlowEventKind::Frame => "frame",
        FlowEventKind::Done => "done",
    };
    object(&[
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

#[wasm_bindgen]
impl FlowAnimation {
    /// Options (all optional): `outputWidth`, `outputHeight` (128), `frames` (60), `lambda`
    /// (0.2), `frameSizes` ([32, 16, 8]; sizes wider than the exemplar or the frame are
    /// skipped), `frameIterations` (3), `seed` (1), `search`, `r` (0.8),
    /// `tileable` (false), and `flow`: a generator `{ type: 'sink' | 'source' | 'vortex' | 'shear'
    /// | 'translation', strength (px/frame), centerX, centerY (0..1), angle (deg), period
    /// (frames), turn (deg/frame) }`, a combination `{ components: [...] }`, one `Float32Array`
    /// of `(vx, vy)` per pixel (a stationary flow) or an array of them (f_1, f_2, ..., cycled).
    /// Default flow: a vortex of strength 2. Unknown keys and impossible values throw.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<FlowAnimation> {
        let (options, flow) = read_options(&options)?;
        Ok(FlowAnimation {
            session: FlowSession::new(exemplar.image(), flow, options)?,
        })
    }

    /// Runs one EM iteration. Returns `{ kind: 'part' | 'iteration' | 'frame' | 'done', done,
    /// frameFinished, frame, iteration, neighbourhoodSize, textureEnergy, flowEnergy, changed,
    /// totalIterations, phase, progress }`; after a `frame` (or `done`) event, `renderInto`
    /// gives that frame. Frames larger than 256x512 split each iteration over steps of about
    /// 60 ms (kind 'part', with the `phase` it stopped in and the `progress` of the iteration,
    /// 0 to 1), and setting up a frame is a step or more of its own; where they split changes
    /// nothing. A whole iteration reports phase 'm-step', or 'e-step' for a frame's last
    /// iteration at a neighbourhood size (its M-step only measures the kept matches).
    pub fn step(&mut self) -> JsResult<JsValue> {
        Ok(event_object(&self.session.step()?))
    }

    /// The estimated peak memory of this session, in bytes: what the constructor compared with
    /// the memory budget (`memoryBudgetMiB`, default 1024 MiB).
    #[wasm_bindgen(getter, js_name = memoryEstimate)]
    pub fn memory_estimate(&self) -> f64 {
        self.session.working_set().bytes() as f64
    }

    #[wasm_bindgen(getter)]
    pub fn done(&self) -> bool {
        self.session.is_done()
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.session.options().output_width as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.session.options().output_height as u32
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

    /// Writes the frame being made (or the last one finished) as RGBA8 into `target`.
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.frame_image()?, target)
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
        let expected = (self.width() * self.height()) as usize * 4;
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
