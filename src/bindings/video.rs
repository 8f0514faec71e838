//! `VideoClip` and `VideoTextures`: graph-cut video textures (Kwatra et al. 2003, section 7) for
//! JS. Each `step()` places one spatio-temporal patch; frames, the seam overlay and the x-t slice
//! render into the caller's `Uint8Array`s.

use js_sys::Uint8Array;
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::graphcut::{costs_object, graph_object};
use super::options::{OptionsReader, object};
use super::pixels::check_target;
use crate::core::Error;
use crate::methods::video::teaching::{frame_rgba, seams_rgba, slice_xt_rgba};
use crate::methods::video::{Event, Mode, Options, Placement, Session, Volume};

/// A video clip held in wasm memory: frames of RGB.
#[wasm_bindgen]
pub struct VideoClip {
    volume: Volume,
}

#[wasm_bindgen]
impl VideoClip {
    /// Takes `frames` RGBA8 frames of `width` x `height`, one after another
    /// (`width * height * 4 * frames` bytes). Alpha is ignored.
    #[wasm_bindgen(js_name = fromFrames)]
    pub fn from_frames(width: u32, height: u32, frames: u32, rgba: &[u8]) -> JsResult<VideoClip> {
        Ok(VideoClip {
            volume: Volume::from_rgba_frames(
                width as usize,
                height as usize,
                frames as usize,
                rgba,
            )?,
        })
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.volume.width() as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.volume.height() as u32
    }

    #[wasm_bindgen(getter)]
    pub fn frames(&self) -> u32 {
        self.volume.frames() as u32
    }
}

const KNOWN: &[&str] = &[
    "mode",
    "outputWidth",
    "outputHeight",
    "outputFrames",
    "fixedFrames",
    "transitionWindow",
    "placement",
    "seed",
    "k",
    "refinementPatches",
    "gradientCost",
    "memoryBudgetMiB",
];

fn read_options(value: &JsValue) -> JsResult<Options> {
    let js = OptionsReader::new(value, KNOWN)?;
    let d = Options::default();
    let mode = match js.string("mode")? {
        None => d.mode,
        Some(name) => Mode::from_name(&name).ok_or_else(|| Error::InvalidParameter {
            name: "mode",
            reason: format!("must be 'loop', 'offsets' or 'extend', got '{name}'"),
        })?,
    };
    let placement = match js.string("placement")? {
        None => d.placement,
        Some(name) => Placement::from_name(&name).ok_or_else(|| Error::InvalidParameter {
            name: "placement",
            reason: format!("must be 'random' or 'matching', got '{name}'"),
        })?,
    };
    let size =
        |name| -> JsResult<Option<usize>> { Ok(js.integer(name, 1, 1 << 16)?.map(|v| v as usize)) };
    let k = match js.number("k")? {
        Some(v) if v <= 0.0 => {
            return Err(Error::InvalidParameter {
                name: "k",
                reason: format!("must be a positive number, got {v}"),
            }
            .into());
        }
        v => v.map_or(d.k, |v| v as f32),
    };
    Ok(Options {
        memory_budget_mib: js.memory_budget()?,
        mode,
        output_width: size("outputWidth")?,
        output_height: size("outputHeight")?,
        output_frames: size("outputFrames")?,
        fixed_frames: js
            .integer("fixedFrames", 0, 1 << 16)?
            .map_or(d.fixed_frames, |v| v as usize),
        transition_window: js
            .integer("transitionWindow", 3, 1 << 16)?
            .map_or(d.transition_window, |v| v as usize),
        placement,
        seed: js.integer("seed", 0, (1 << 53) - 1)?.unwrap_or(d.seed),
        k,
        refinement_patches: js
            .integer("refinementPatches", 0, 1 << 10)?
            .map_or(d.refinement_patches, |v| v as usize),
        gradient_cost: js.boolean("gradientCost")?.unwrap_or(d.gradient_cost),
    })
}

fn event_object(e: &Event) -> JsValue {
    let (tx, ty, tt) = e.offset;
    object(&[
        ("done", e.done.into()),
        ("patch", e.patch.map_or(-1.0, |p| p as f64).into()),
        ("patches", (e.patches as u32).into()),
        ("tx", tx.into()),
        ("ty", ty.into()),
        ("tt", tt.into()),
        ("voxelsTaken", (e.voxels_taken as f64).into()),
        ("cutCost", e.cut_cost.into()),
        ("covered", e.covered.into()),
        ("coverage", e.coverage.into()),
        ("loopFrame", e.loop_frame.map_or(-1.0, |f| f as f64).into()),
    ])
}

/// A graph-cut video synthesis you advance with `step()`.
#[wasm_bindgen]
pub struct VideoTextures {
    session: Session,
    /// A reusable RGBA buffer for the renderers.
    buffer: Vec<u8>,
    /// The first frame the last placed patch reached into.
    last_frame: usize,
}

#[wasm_bindgen]
impl VideoTextures {
    /// Options (all optional): `mode` ('loop' | 'offsets' | 'extend', default 'loop'),
    /// `outputWidth`, `outputHeight` (the clip's; only 'extend' may change them), `outputFrames`
    /// (twice the clip's for 'offsets', the clip's for 'extend'; not for 'loop'), `fixedFrames`
    /// (10; 0 = no loop), `transitionWindow` (60), `placement` ('random' | 'matching'), `seed`
    /// (1), `k` (0.01), `refinementPatches` (2), `gradientCost` (false). Unknown keys, bad values
    /// and videos beyond the memory budget (`memoryBudgetMiB`, default 1024 MiB) throw.
    #[wasm_bindgen(constructor)]
    pub fn new(clip: &VideoClip, options: JsValue) -> JsResult<VideoTextures> {
        let options = read_options(&options)?;
        Ok(VideoTextures {
            session: Session::new(clip.volume.clone(), options)?,
            buffer: Vec::new(),
            last_frame: 0,
        })
    }

    /// Places one patch. Returns `{ done, patch, patches, tx, ty, tt, voxelsTaken, cutCost,
    /// covered, coverage, loopFrame }` (`patch` and `loopFrame` are -1 when none).
    pub fn step(&mut self) -> JsResult<JsValue> {
        let event = self.session.step()?;
        if event.patch.is_some() {
            let d = self.session.size().2 as i64;
            self.last_frame = i64::from(event.offset.2).clamp(0, (d - 1).max(0)) as usize;
        }
        Ok(event_object(&event))
    }

    #[wasm_bindgen(getter)]
    pub fn done(&self) -> bool {
        self.session.is_done()
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.session.size().0 as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.session.size().1 as u32
    }

    #[wasm_bindgen(getter)]
    pub fn frames(&self) -> u32 {
        self.session.size().2 as u32
    }

    /// Output frame `t` as RGBA into `rgba` (`width * height * 4`).
    #[wasm_bindgen(js_name = frameInto)]
    pub fn frame_into(&mut self, t: u32, rgba: &Uint8Array) -> JsResult<()> {
        self.render(rgba, |s, out| frame_rgba(s, t as usize, out))
    }

    /// The seam overlay of frame `t`: spatial seams opaque red, temporal ones translucent yellow,
    /// transparent elsewhere (`width * height * 4`).
    #[wasm_bindgen(js_name = seamsInto)]
    pub fn seams_into(&mut self, t: u32, rgba: &Uint8Array) -> JsResult<()> {
        self.render(rgba, |s, out| seams_rgba(s, t as usize, out))
    }

    /// The x-t slice at row `y` (`width` x `frames`, row t = frame t) with seams in red
    /// (`width * frames * 4`).
    #[wasm_bindgen(js_name = sliceXtInto)]
    pub fn slice_xt_into(&mut self, y: u32, rgba: &Uint8Array) -> JsResult<()> {
        self.render(rgba, |s, out| slice_xt_rgba(s, y as usize, out))
    }

    /// Output frame `t` as a new RGBA `Uint8Array` (for workers, where a buffer cannot be
    /// filled across the boundary).
    pub fn frame(&self, t: u32) -> JsResult<Vec<u8>> {
        self.rendered(self.pixels(), |s, out| frame_rgba(s, t as usize, out))
    }

    /// The seam overlay of frame `t` as a new RGBA `Uint8Array` (see `seamsInto`).
    pub fn seams(&self, t: u32) -> JsResult<Vec<u8>> {
        self.rendered(self.pixels(), |s, out| seams_rgba(s, t as usize, out))
    }

    /// The x-t slice at row `y` as a new RGBA `Uint8Array`, `width` x `frames` (see `sliceXtInto`).
    #[wasm_bindgen(js_name = sliceXt)]
    pub fn slice_xt(&self, y: u32) -> JsResult<Vec<u8>> {
        let (w, _, d) = self.session.size();
        self.rendered(w * d, |s, out| slice_xt_rgba(s, y as usize, out))
    }

    /// Turns the placement anatomy on or off (as `GraphcutTextures.setAnatomy`): while on, every
    /// placement keeps one slice of its cost surface and of its seam graph for
    /// `placementCosts()` and `placementGraph()` (off by default).
    #[wasm_bindgen(js_name = setAnatomy)]
    pub fn set_anatomy(&mut self, on: bool) {
        self.session.set_anatomy(on);
    }

    /// The last placement's cost surface, as `GraphcutTextures.placementCosts()` returns it,
    /// over one slice of the 3-D offsets: with `axes: 'xy'` the spatial offsets (x + column, y +
    /// row) at the drawn temporal offset `tt` (output frames), the probabilities of eq. 3 given
    /// that `tt`; with `axes: 't'` (temporal offsets only, 7.B) a row over the temporal offsets
    /// (x + column is tt). `null` unless `setAnatomy(true)` came before the step, and for
    /// placements without matching costs (placement 'random', loops, 7.D's fixed frames, the
    /// first patch).
    #[wasm_bindgen(js_name = placementCosts)]
    pub fn placement_costs(&self) -> JsValue {
        let Some(slice) = self.session.placement_costs() else {
            return JsValue::NULL;
        };
        let value = costs_object(&slice.surface);
        let tt = self.session.output_frame(i64::from(slice.tt)) as f64;
        set(
            &value,
            "axes",
            if slice.temporal { "t" } else { "xy" }.into(),
        );
        set(&value, "tt", tt.into());
        if slice.temporal {
            // The row's x is the canvas tt: shift it to output frames as `tt` is.
            let shift = tt - f64::from(slice.tt);
            set(&value, "x", (slice.surface.x as f64 + shift).into());
        }
        value
    }

    /// The last placement's seam graph in one frame of the patch's box, as
    /// `GraphcutTextures.placementGraph()` returns it (x, y: the box's corner in the output),
    /// with `frame` (the output frame shown: the box's frame with the most graph nodes, where
    /// most of the seam surface is cut), `firstFrame` and `frames` (the box along time). Arcs
    /// along time are not in the slice. `null` unless `setAnatomy(true)` came before the step.
    #[wasm_bindgen(js_name = placementGraph)]
    pub fn placement_graph(&self) -> JsValue {
        let Some(slice) = self.session.placement_graph() else {
            return JsValue::NULL;
        };
        let value = graph_object(&slice.view);
        let frame = |t: usize| self.session.output_frame(t as i64) as f64;
        set(&value, "frame", frame(slice.t).into());
        set(&value, "firstFrame", frame(slice.first_frame).into());
        set(&value, "frames", (slice.frames as u32).into());
        value
    }

    /// The frame the last patch reached into (frame 0 before the first step), as RGBA: what a
    /// generic progress view (a worker's step image, the CLI) shows.
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&mut self, rgba: &Uint8Array) -> JsResult<()> {
        let t = self.current_frame();
        self.render(rgba, |s, out| frame_rgba(s, t, out))
    }
}

impl VideoTextures {
    fn pixels(&self) -> usize {
        let (w, h, _) = self.session.size();
        w * h
    }

    fn current_frame(&self) -> usize {
        let (_, _, d) = self.session.size();
        self.last_frame.min(d.saturating_sub(1))
    }

    fn rendered(
        &self,
        pixels: usize,
        draw: impl FnOnce(&Session, &mut [u8]) -> crate::core::Result<()>,
    ) -> JsResult<Vec<u8>> {
        let mut out = vec![0u8; pixels * 4];
        draw(&self.session, &mut out)?;
        Ok(out)
    }

    fn render(
        &mut self,
        rgba: &Uint8Array,
        draw: impl FnOnce(&Session, &mut [u8]) -> crate::core::Result<()>,
    ) -> JsResult<()> {
        check_target(rgba)?;
        self.buffer.resize(rgba.length() as usize, 0);
        draw(&self.session, &mut self.buffer)?;
        rgba.copy_from(&self.buffer);
        Ok(())
    }
}

/// Sets `key` on an object this module made (it cannot fail on a plain object).
fn set(object: &JsValue, key: &str, value: JsValue) {
    let _ = js_sys::Reflect::set(object, &key.into(), &value);
}
