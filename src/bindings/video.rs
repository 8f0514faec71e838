//! `VideoClip` and `VideoTextures`: graph-cut video textures (Kwatra et al. 2003, section 7) for
//! JS. Each `step()` places one spatio-temporal patch; frames, the seam overlay and the x-t slice
//! render into the caller's `Uint8ClampedArray`s.

use js_sys::Uint8ClampedArray;
use wasm_bindgen::prelude::*;

use super::anatomy::{costs_object, graph_object};
use super::error::JsResult;
use super::object::set;
use super::options::{OptionsReader, object};
use super::pixels::check_target;
use super::schema::{DONE, EventField, Kind, MEMORY_BUDGET, Opt, SEED, Schema, kind_field};
use super::session::{JsSession, js_session};
use crate::core::Error;
use crate::methods::video::teaching::{frame_rgba, seams_rgba, slice_xt_rgba};
use crate::methods::video::{Blend, Event, Mode, Options, Placement, Session, Volume};

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

const fn count(
    key: &'static str,
    min: u64,
    max: u64,
    default: Option<&'static str>,
    doc: &'static str,
) -> Opt {
    Opt {
        key,
        kind: Kind::Integer { min, max },
        default,
        doc,
    }
}

pub(crate) const SCHEMA: Schema = Schema {
    class: "VideoTextures",
    options_name: "VideoTexturesOptions",
    options: &[
        MEMORY_BUDGET,
        Opt {
            key: "mode",
            kind: Kind::Choice(&["loop", "offsets", "extend"]),
            default: Some("'loop'"),
            doc: "'loop' (7.A: best transition by frame-pair SSD, optimal seam surface around it; the output is the loop), 'offsets' (7.B: the whole clip at random temporal offsets), 'extend' (7.C/7.E: spatio-temporal patches; frames may be larger).",
        },
        count(
            "outputWidth",
            1,
            1 << 16,
            None,
            "Only 'extend' may differ from the clip. Default: the clip's width.",
        ),
        count(
            "outputHeight",
            1,
            1 << 16,
            None,
            "Only 'extend' may differ from the clip. Default: the clip's height.",
        ),
        count(
            "outputFrames",
            1,
            1 << 16,
            None,
            "Not for 'loop' (it chooses the loop length). Default: twice the clip's frames ('offsets'), the clip's ('extend').",
        ),
        count(
            "fixedFrames",
            0,
            1 << 16,
            None,
            "k of 7.D for 'offsets' and 'extend': the first and last k frames fixed, then the first k removed, so the output loops; 0 = no loop. At most the clip's frame count. Default: 10. Refused for 'loop', which loops through 7.A's transition.",
        ),
        count(
            "transitionWindow",
            3,
            1 << 16,
            Some("60"),
            "'loop': the most frames of the seam window around the transition (shorter clips get at most a sixth of their frames on either side).",
        ),
        count(
            "transitions",
            1,
            16,
            Some("3"),
            "'loop': how many good transitions get a seam surface (the best by frame SSD, then the next best of other loop lengths within the window around it); the cheapest seam is kept. 1 seams the best transition only.",
        ),
        Opt {
            key: "blend",
            kind: Kind::Choice(&["none", "feather"]),
            default: Some("'none'"),
            doc: "'none', or 'feather' (section 5: a Gaussian-weighted mix of the patches meeting near a seam, over x, y and time; applied once done). Splining is for images only.",
        },
        Opt {
            key: "placement",
            kind: Kind::Choice(&["random", "entire-patch", "sub-patch", "matching"]),
            default: Some("'random'"),
            doc: "'random'; 'entire-patch' (eq. 2: the SSD of the whole clip at every translation that covers the error region, over all it overlaps, by 3-D FFT, drawn by eq. 3); or 'sub-patch' (7.C: the SSD of the error region against every translation, eq. 4). 'matching' is 'sub-patch'.",
        },
        SEED,
        Opt {
            key: "k",
            kind: Kind::Number,
            default: Some("0.01"),
            doc: "k of eq. 3 for matching placement, > 0.",
        },
        count(
            "refinementPatches",
            0,
            1 << 10,
            Some("2"),
            "Patches placed over the worst seams once covered.",
        ),
        Opt {
            key: "gradientCost",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Seam cost M' (eq. 5, divided by the gradients) instead of M.",
        },
    ],
    required: &[],
    event_name: "VideoTexturesEvent",
    event: &[
        kind_field("'placed' | 'done'"),
        DONE,
        EventField {
            key: "patch",
            ts: "{ index: number; offsetX: number; offsetY: number; offsetT: number } | null",
            doc: "The patch placed by this step: its number and its offset in the output (x, y in pixels, t in output frames); null when the step placed none.",
        },
        EventField {
            key: "patchesPlaced",
            ts: "number",
            doc: "Patches placed so far.",
        },
        EventField {
            key: "pixelsTaken",
            ts: "number",
            doc: "Output pixels (voxels: pixels of all frames) the new patch took.",
        },
        EventField {
            key: "cutCost",
            ts: "number",
            doc: "Cost of this placement's min cut.",
        },
        EventField {
            key: "covered",
            ts: "boolean",
            doc: "Whether every output voxel has been covered.",
        },
        EventField {
            key: "coverage",
            ts: "number",
            doc: "Share of the output voxels covered, 0 to 1.",
        },
        EventField {
            key: "loopFrame",
            ts: "number | null",
            doc: "'loop': the output frame where the loop's transition lies, once known; null otherwise.",
        },
        EventField {
            key: "transition",
            ts: "{ index: number; count: number; loopLength: number } | null",
            doc: "'loop': the transition this step seamed (the one kept, on the last step): its number among the good transitions (0 is the best by frame SSD), how many there are, and its loop length in frames; null for the other modes.",
        },
    ],
};

fn read_options(value: &JsValue) -> JsResult<Options> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = Options::default();
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
    let options = Options {
        memory_budget_mib: js.memory_budget()?,
        mode: js.choice("mode", Mode::from_name)?.unwrap_or(d.mode),
        output_width: js.size("outputWidth")?,
        output_height: js.size("outputHeight")?,
        output_frames: js.size("outputFrames")?,
        fixed_frames: js.size("fixedFrames")?,
        transition_window: js.size("transitionWindow")?.unwrap_or(d.transition_window),
        transitions: js.size("transitions")?.unwrap_or(d.transitions),
        placement: js
            .choice("placement", Placement::from_name)?
            .unwrap_or(d.placement),
        seed: js.integer("seed")?.unwrap_or(d.seed),
        k,
        refinement_patches: js
            .size("refinementPatches")?
            .unwrap_or(d.refinement_patches),
        gradient_cost: js.boolean("gradientCost")?.unwrap_or(d.gradient_cost),
        blend: js.choice("blend", Blend::from_name)?.unwrap_or(d.blend),
    };
    js.finish()?;
    Ok(options)
}

fn event_object(e: &Event) -> JsResult<JsValue> {
    let (tx, ty, tt) = e.offset;
    let patch = e.patch.map_or(JsValue::NULL, |index| {
        object(&[
            ("index", (index as u32).into()),
            ("offsetX", tx.into()),
            ("offsetY", ty.into()),
            ("offsetT", tt.into()),
        ])
    });
    SCHEMA.event(&[
        ("kind", if e.done { "done" } else { "placed" }.into()),
        ("done", e.done.into()),
        ("patch", patch),
        ("patchesPlaced", (e.patches as u32).into()),
        ("pixelsTaken", (e.voxels_taken as f64).into()),
        ("cutCost", e.cut_cost.into()),
        ("covered", e.covered.into()),
        ("coverage", e.coverage.into()),
        (
            "loopFrame",
            e.loop_frame.map_or(JsValue::NULL, |f| (f as f64).into()),
        ),
        (
            "transition",
            e.transition
                .map_or(JsValue::NULL, |(index, count, length)| {
                    object(&[
                        ("index", (index as u32).into()),
                        ("count", (count as u32).into()),
                        ("loopLength", (length as u32).into()),
                    ])
                }),
        ),
    ])
}

/// A graph-cut video synthesis you advance with `step()`.
#[wasm_bindgen]
pub struct VideoTextures {
    session: Session,
    /// The first frame the last placed patch reached into.
    last_frame: usize,
}

js_session!(VideoTextures);

/// One spatio-temporal patch per step.
impl JsSession for VideoTextures {
    fn step_event(&mut self) -> JsResult<JsValue> {
        let event = self.session.step()?;
        if event.patch.is_some() {
            let d = self.session.size().2 as i64;
            self.last_frame = i64::from(event.offset.2).clamp(0, (d - 1).max(0)) as usize;
        }
        event_object(&event)
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    fn size(&self) -> (usize, usize) {
        let (w, h, _) = self.session.size();
        (w, h)
    }

    fn memory_bytes(&self) -> u64 {
        self.session.working_set().bytes()
    }

    /// The frame the last patch reached into (frame 0 before the first step): what a generic
    /// progress view (a worker's step image, the CLI) shows.
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        let t = self.current_frame();
        self.render(target, |s, out| frame_rgba(s, t, out))
    }
}

#[wasm_bindgen]
impl VideoTextures {
    /// Options: see [`SCHEMA`] (every key optional). Unknown keys, bad values and videos beyond
    /// the memory budget throw.
    #[wasm_bindgen(constructor)]
    pub fn new(clip: &VideoClip, options: JsValue) -> JsResult<VideoTextures> {
        let options = read_options(&options)?;
        Ok(VideoTextures {
            session: Session::new(clip.volume.clone(), options)?,
            last_frame: 0,
        })
    }

    #[wasm_bindgen(getter)]
    pub fn frames(&self) -> u32 {
        self.session.size().2 as u32
    }

    /// Output frame `t` as RGBA into `target` (`width * height * 4`).
    #[wasm_bindgen(js_name = renderFrameInto)]
    pub fn render_frame_into(&self, t: u32, target: &Uint8ClampedArray) -> JsResult<()> {
        self.render(target, |s, out| frame_rgba(s, t as usize, out))
    }

    /// The seam overlay of frame `t`: spatial seams opaque red, temporal ones translucent yellow,
    /// transparent elsewhere (`width * height * 4`).
    #[wasm_bindgen(js_name = renderSeamsInto)]
    pub fn render_seams_into(&self, t: u32, target: &Uint8ClampedArray) -> JsResult<()> {
        self.render(target, |s, out| seams_rgba(s, t as usize, out))
    }

    /// The x-t slice at row `y` (`width` x `frames`, row t = frame t) with seams in red
    /// (`width * frames * 4`).
    #[wasm_bindgen(js_name = renderSliceXtInto)]
    pub fn render_slice_xt_into(&self, y: u32, target: &Uint8ClampedArray) -> JsResult<()> {
        self.render(target, |s, out| slice_xt_rgba(s, y as usize, out))
    }

    /// Output frame `t` as a new RGBA `Uint8ClampedArray` (for workers, where a buffer cannot
    /// be filled across the boundary).
    pub fn frame(&self, t: u32) -> JsResult<Uint8ClampedArray> {
        self.rendered(self.pixels(), |s, out| frame_rgba(s, t as usize, out))
    }

    /// The seam overlay of frame `t` as a new RGBA `Uint8ClampedArray` (see `renderSeamsInto`).
    pub fn seams(&self, t: u32) -> JsResult<Uint8ClampedArray> {
        self.rendered(self.pixels(), |s, out| seams_rgba(s, t as usize, out))
    }

    /// The x-t slice at row `y` as a new RGBA `Uint8ClampedArray`, `width` x `frames` (see
    /// `renderSliceXtInto`).
    #[wasm_bindgen(js_name = sliceXt)]
    pub fn slice_xt(&self, y: u32) -> JsResult<Uint8ClampedArray> {
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
    ) -> JsResult<Uint8ClampedArray> {
        let mut out = vec![0u8; pixels * 4];
        draw(&self.session, &mut out)?;
        Ok(Uint8ClampedArray::from(out.as_slice()))
    }

    /// Draws into a buffer of the target's length (the drawing checks it against the view's
    /// size), then copies it into the target.
    fn render(
        &self,
        target: &Uint8ClampedArray,
        draw: impl FnOnce(&Session, &mut [u8]) -> crate::core::Result<()>,
    ) -> JsResult<()> {
        check_target(target)?;
        let mut buffer = vec![0u8; target.length() as usize];
        draw(&self.session, &mut buffer)?;
        target.copy_from(&buffer);
        Ok(())
    }
}
