//! `TextureOptimization`: the JS-visible texture-optimisation session. Each `step()` runs one EM
//! iteration and returns a plain event object; the current image and the teaching views render
//! into the caller's buffers.

use js_sys::{Array, Float32Array, Float64Array, Uint8ClampedArray, Uint32Array};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::exemplars::{ExemplarList, sources_view};
use super::options::{OptionsReader, object};
use super::pixels::{check_target_size, render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, SEED, Schema, kind_field, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::{Error, Image, from_rgba8};
use crate::methods::optimization::SoftConstraints;
use crate::methods::optimization::level::LevelSolver;
use crate::methods::optimization::session::Phase;
use crate::methods::optimization::teaching::{Field, field, offset_map};
use crate::methods::optimization::{Energy, Event, EventKind, Options, Session, Start};
use crate::solvers::nn::Search;

const PHASES: &str = "'start' | 'first-match' | 'e-step' | 'm-step'";

pub(crate) const SCHEMA: Schema = Schema {
    class: "TextureOptimization",
    options_name: "TextureOptimizationOptions",
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
            key: "levels",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("3"),
            doc: "Resolution levels (octaves) of the schedule.",
        },
        Opt {
            key: "neighbourhoodSizes",
            kind: Kind::Integers {
                min: 0,
                max: 1 << 20,
            },
            default: Some("[32, 16, 8]"),
            doc: "Neighbourhood sizes, largest first; sizes that do not fit a level's exemplar are skipped.",
        },
        Opt {
            key: "iterations",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("5"),
            doc: "EM iterations per level and size at most (a level also ends when no match changes).",
        },
        Opt {
            key: "r",
            kind: Kind::Number,
            default: Some("0.8"),
            doc: "Robust IRLS exponent (2 is least squares); 0.8 is the paper's.",
        },
        Opt {
            key: "mu",
            kind: Kind::Number,
            default: Some("0"),
            doc: "Weight of the gradient energy (the paper uses 10); 0 turns it off.",
        },
        Opt {
            key: "mStepMu",
            kind: Kind::Number,
            default: None,
            doc: "The M-step's own gradient weight, where it should differ from `mu` (0..1000; not in the paper). At mu = 10 the search matches by gradient almost alone and outputs drift into colour blotches; 1 keeps a search that sees colour. Default: `mu` up to 1, then 1; set it to `mu` for the paper's single energy.",
        },
        Opt {
            key: "search",
            kind: Kind::Choice(&["patchmatch", "kmeans-tree", "exact"]),
            default: Some("'patchmatch'"),
            doc: "Nearest-neighbour search.",
        },
        Opt {
            key: "tileable",
            kind: Kind::Boolean,
            default: Some("false"),
            doc: "Make the output tile seamlessly.",
        },
        Opt {
            key: "completeness",
            kind: Kind::Number,
            default: Some("1"),
            doc: "Weight of the occurrence penalty that makes the output use all of the exemplar (0: the paper's M-step).",
        },
        Opt {
            key: "histogramMatching",
            kind: Kind::Number,
            default: Some("1"),
            doc: "How far the output's colour histogram is matched to the exemplar's (0..1).",
        },
        Opt {
            key: "channelWeights",
            kind: Kind::Numbers,
            default: Some("[]"),
            doc: "Weight of each exemplar channel in the match distance, one per channel ([] weighs all 1); a channel of weight 0 follows the matches without steering them. Pixel energy only.",
        },
        Opt {
            key: "energy",
            kind: Kind::Choice(&["pixels", "haar", "daubechies"]),
            default: Some("'pixels'"),
            doc: "Texture energy: pixels, or the wavelet energy of Shen et al. 2009.",
        },
        Opt {
            key: "waveletDetailWeight",
            kind: Kind::Number,
            default: Some("4"),
            doc: "Weight of the wavelet detail bands (with a wavelet `energy`).",
        },
        Opt {
            key: "start",
            kind: Kind::Choice(&["graphcut", "patches"]),
            default: Some("'graphcut'"),
            doc: "How the coarsest level starts: a graph-cut synthesis at its size, which keeps lattices and large elements whole, or random exemplar patches (closer to the paper's random start).",
        },
    ],
    required: &[],
    event_name: "TextureOptimizationEvent",
    event: &[
        kind_field("'level' | 'iteration' | 'part' | 'done'"),
        DONE,
        EventField {
            key: "level",
            ts: "number",
            doc: "The level, 0 for the coarsest.",
        },
        EventField {
            key: "levelCount",
            ts: "number",
            doc: "Levels of the schedule.",
        },
        EventField {
            key: "octave",
            ts: "number",
            doc: "The level's octave.",
        },
        EventField {
            key: "scale",
            ts: "number",
            doc: "2^octave: the level is 1/scale of the output size.",
        },
        EventField {
            key: "neighbourhoodSize",
            ts: "number",
            doc: "Neighbourhood size of the iteration.",
        },
        EventField {
            key: "iteration",
            ts: "number",
            doc: "Iteration at this level and size (the one under way for 'part').",
        },
        EventField {
            key: "energy",
            ts: "number",
            doc: "The pixel term ||x_p - z_p||^r, normalised, whatever the `energy` option.",
        },
        EventField {
            key: "matchEnergy",
            ts: "number",
            doc: "What the M-step minimised (equal to `energy` for 'pixels').",
        },
        EventField {
            key: "changed",
            ts: "number",
            doc: "Matches that changed in this iteration.",
        },
        EventField {
            key: "totalIterations",
            ts: "number",
            doc: "Iterations so far over all levels.",
        },
        EventField {
            key: "solverIterations",
            ts: "number",
            doc: "Conjugate-gradient iterations of the gradient solve.",
        },
        EventField {
            key: "phase",
            ts: PHASES,
            doc: "Where the step stopped: making the coarsest level's graph-cut start, the M-step on a level's up-sampled output, the E-step or the M-step.",
        },
        EventField {
            key: "progress",
            ts: "number",
            doc: "Share of the iteration done, 0 to 1 (1 for a whole iteration).",
        },
    ],
};

/// Reads the options object; absent keys keep the defaults of [`Options`].
fn read_options(value: &JsValue) -> JsResult<Options> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = Options::default();
    let options = Options {
        memory_budget_mib: js.memory_budget()?,
        start: js.choice("start", Start::from_name)?.unwrap_or(d.start),
        energy: js.choice("energy", Energy::from_name)?.unwrap_or(d.energy),
        wavelet_detail_weight: js
            .number("waveletDetailWeight")?
            .map_or(d.wavelet_detail_weight, |v| v as f32),
        output_width: js.size("outputWidth")?.unwrap_or(d.output_width),
        output_height: js.size("outputHeight")?.unwrap_or(d.output_height),
        seed: js.integer("seed")?.unwrap_or(d.seed),
        levels: js.size("levels")?.unwrap_or(d.levels),
        neighbourhood_sizes: js
            .integers("neighbourhoodSizes")?
            .map_or(d.neighbourhood_sizes, |v| {
                v.into_iter().map(|s| s as usize).collect()
            }),
        iterations: js.size("iterations")?.unwrap_or(d.iterations),
        r: js.number("r")?.map_or(d.r, |v| v as f32),
        mu: js.number("mu")?.map_or(d.mu, |v| v as f32),
        m_step_mu: js.number("mStepMu")?.map(|v| v as f32),
        search: js.choice("search", Search::from_name)?.unwrap_or(d.search),
        tileable: js.boolean("tileable")?.unwrap_or(d.tileable),
        completeness: js
            .number("completeness")?
            .map_or(d.completeness, |v| v as f32),
        histogram_matching: js
            .number("histogramMatching")?
            .map_or(d.histogram_matching, |v| v as f32),
        channel_weights: js
            .numbers("channelWeights")?
            .map_or(d.channel_weights, |v| {
                v.into_iter().map(|w| w as f32).collect()
            }),
    };
    js.finish()?;
    Ok(options)
}

fn event_object(e: &Event) -> JsResult<JsValue> {
    let kind = match e.kind {
        EventKind::Part => "part",
        EventKind::Level => "level",
        EventKind::Iteration => "iteration",
        EventKind::Done => "done",
    };
    SCHEMA.event(&[
        ("kind", kind.into()),
        ("done", (e.kind == EventKind::Done).into()),
        ("level", (e.level as u32).into()),
        ("levelCount", (e.level_count as u32).into()),
        ("octave", (e.octave as u32).into()),
        ("scale", (1u32 << e.octave).into()),
        ("neighbourhoodSize", (e.size as u32).into()),
        ("iteration", (e.iteration as u32).into()),
        ("energy", e.energy.into()),
        ("matchEnergy", e.match_energy.into()),
        ("changed", (e.changed as u32).into()),
        ("totalIterations", (e.total_iterations as u32).into()),
        ("solverIterations", (e.solver_iterations as u32).into()),
        ("phase", phase_name(e.phase).into()),
        ("progress", e.progress.into()),
    ])
}

/// The JS name of the half of an EM iteration a step stopped in (or 'start' while the coarsest
/// level's graph-cut start is made).
pub(crate) fn phase_name(phase: Phase) -> &'static str {
    match phase {
        Phase::Start => "start",
        Phase::FirstMatch => "first-match",
        Phase::EStep => "e-step",
        Phase::MStep => "m-step",
    }
}

/// A texture-optimisation run (Kwatra et al. 2005) you advance with `step()`.
#[wasm_bindgen]
pub struct TextureOptimization {
    session: Session,
    exemplars: ExemplarList,
    /// The guides given (`setGuides`, `addGuidedExemplar`): a source guide per exemplar, the
    /// target guide and the weight, kept to make the session again over a longer list.
    guides: Option<(Vec<Image>, Image, f32)>,
}

js_session!(TextureOptimization);

/// One EM iteration per step (on a large output, about 512x512 and up, an iteration is split
/// over several steps of kind 'part' so that none blocks for long; see the event table).
impl JsSession for TextureOptimization {
    fn step_event(&mut self) -> JsResult<JsValue> {
        self.exemplars.stepped();
        event_object(&self.session.step()?)
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    /// The full size: coarse levels are up-sampled when rendered.
    fn size(&self) -> (usize, usize) {
        let o = self.session.options();
        (o.output_width, o.output_height)
    }

    fn memory_bytes(&self) -> u64 {
        self.session
            .working_set(self.session.constraints().is_some())
            .bytes()
    }

    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.output_full_size()?, target)
    }
}

#[wasm_bindgen]
impl TextureOptimization {
    /// Plans the schedule for `exemplar` and `options` (see [`SCHEMA`]: every key optional).
    /// Unknown keys and impossible values throw.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<TextureOptimization> {
        let options = read_options(&options)?;
        Ok(TextureOptimization {
            session: Session::new(exemplar.image(), options)?,
            exemplars: ExemplarList::new(exemplar.image()),
            guides: None,
        })
    }

    /// Adds an exemplar the matches may come from (before the first step; the session is
    /// planned again over all of them, for the smallest, and keeps its soft constraints).
    /// Returns its index, as `renderSourcesInto` colours it.
    #[wasm_bindgen(js_name = addExemplar)]
    pub fn add_exemplar(&mut self, exemplar: &Exemplar) -> JsResult<u32> {
        if self.guides.is_some() {
            return Err(Error::InvalidParameter {
                name: "addExemplar",
                reason: "this session has guides: add the exemplar with its source guide, \
                         addGuidedExemplar(exemplar, sourceGuide)"
                    .into(),
            }
            .into());
        }
        let list = self.exemplars.with(exemplar.image())?;
        let mut session = Session::with_exemplars(&list, self.session.options().clone())?;
        session.set_constraints(self.session.constraints().cloned())?;
        self.session = session;
        Ok(self.exemplars.keep(list))
    }

    /// Guided synthesis: `sourceGuide` (the exemplar's size) and `targetGuide` (the output's
    /// size), with the same channels, add `weight ||g_source - g_target||^2` to the M-step's
    /// distance (1: a guide value counts as much as a colour value). Style transfer: the
    /// exemplar's luminance as the source guide, a photo's as the target guide. Before the
    /// first step, with the pixel energy; with several exemplars, before adding them with
    /// `addGuidedExemplar`.
    #[wasm_bindgen(js_name = setGuides)]
    pub fn set_guides(
        &mut self,
        source_guide: &Exemplar,
        target_guide: &Exemplar,
        weight: f64,
    ) -> JsResult<()> {
        let (source, target) = (source_guide.image(), target_guide.image());
        self.session.set_guides(source, target, weight as f32)?;
        self.guides = Some((vec![source.clone()], target.clone(), weight as f32));
        Ok(())
    }

    /// Adds an exemplar with its source guide (the exemplar's size, the guides' channels) to a
    /// guided session (`setGuides` first): each match compares the guide of the exemplar it
    /// lies in with the target guide. Before the first step. Returns the exemplar's index, as
    /// `renderSourcesInto` colours it.
    #[wasm_bindgen(js_name = addGuidedExemplar)]
    pub fn add_guided_exemplar(
        &mut self,
        exemplar: &Exemplar,
        source_guide: &Exemplar,
    ) -> JsResult<u32> {
        let Some((sources, target, weight)) = &self.guides else {
            return Err(Error::InvalidParameter {
                name: "addGuidedExemplar",
                reason: "give the guides first: setGuides(sourceGuide, targetGuide, weight)".into(),
            }
            .into());
        };
        let list = self.exemplars.with(exemplar.image())?;
        let mut sources = sources.clone();
        sources.push(source_guide.image().clone());
        let mut session = Session::with_exemplars(&list, self.session.options().clone())?;
        session.set_constraints(self.session.constraints().cloned())?;
        session.set_exemplar_guides(&sources, target, *weight)?;
        self.session = session;
        let (target, weight) = (target.clone(), *weight);
        self.guides = Some((sources, target, weight));
        Ok(self.exemplars.keep(list))
    }

    /// Which exemplar each output pixel's nearest match lies in, each in its own colour (as
    /// `addExemplar` numbers them; one colour with one exemplar), at the current level
    /// up-sampled; transparent before the first step.
    #[wasm_bindgen(js_name = renderSourcesInto)]
    pub fn render_sources_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        let o = self.session.options();
        let (w, h) = (o.output_width, o.output_height);
        let rgba = match self.session.exemplar_map() {
            Some(map) => {
                let level = self.session.current_level();
                let map: Vec<Option<u32>> = map.into_iter().map(Some).collect();
                sources_view(&map, (level.output_width, level.output_height), (w, h))
            }
            None => vec![0; w * h * 4],
        };
        write_rgba(&rgba, target)
    }

    /// Material sets: `other` (an image of the exemplar's size: a normal, height or roughness
    /// map) re-indexed by this output's source map, written as RGBA into `target` (output
    /// size): each output pixel copies the pixel of `other` under the match of the
    /// neighbourhood whose centre is nearest. Nothing is averaged, so normals stay unit
    /// vectors; the output itself averages neighbourhoods, so transfer the albedo too for maps
    /// that match pixel for pixel. Throws before the finest level has run.
    #[wasm_bindgen(js_name = transferInto)]
    pub fn transfer_into(&self, other: &Exemplar, target: &Uint8ClampedArray) -> JsResult<()> {
        let o = self.session.options();
        check_target_size(target, o.output_width, o.output_height)?;
        let map = self.session.source_map()?;
        render_into(&map.transfer(other.image())?, target)
    }

    /// The search in use: 'patchmatch', 'kmeans-tree' or 'exact'.
    #[wasm_bindgen(getter)]
    pub fn search(&self) -> String {
        self.session.options().search.name().into()
    }

    /// The texture energy in use: 'pixels', 'haar' or 'daubechies'.
    #[wasm_bindgen(getter)]
    pub fn energy(&self) -> String {
        self.session.options().energy.name().into()
    }

    /// Soft constraints (Kwatra et al. 2005, section 4): `rgba` is `outputWidth * outputHeight *
    /// 4` bytes of desired colours whose alpha is the mask (0 = free, 255 = fully constrained),
    /// e.g. the `data` of a canvas the user painted on; `lambda` (0 to 1e6) is the weight,
    /// relative to the texture at each pixel (1 = half way, large = hard). Applies from the next
    /// step; on a finished run it reopens the finest level so the output follows the strokes.
    #[wasm_bindgen(js_name = setConstraints)]
    pub fn set_constraints(&mut self, rgba: &[u8], lambda: f64) -> JsResult<()> {
        let (w, h) = JsSession::size(self);
        if rgba.len() != w * h * 4 {
            return Err(Error::LengthMismatch {
                what: "constraint pixels (RGBA, output size)",
                expected: w * h * 4,
                actual: rgba.len(),
            }
            .into());
        }
        let painted = from_rgba8(w, h, rgba)?;
        let mask: Vec<f32> = rgba
            .chunks_exact(4)
            .map(|p| f32::from(p[3]) / 255.0)
            .collect();
        let channels = self.session.exemplar_channels();
        let target = painted.with_channels(4)?.with_channels(channels)?;
        let constraints = SoftConstraints::new(target, mask, lambda as f32)?;
        self.session.set_constraints(Some(constraints))?;
        Ok(())
    }

    /// Removes the soft constraints.
    #[wasm_bindgen(js_name = clearConstraints)]
    pub fn clear_constraints(&mut self) -> JsResult<()> {
        Ok(self.session.set_constraints(None)?)
    }

    /// Mean squared difference per value between the output and the constraint colours over the
    /// masked pixels (0 without constraints).
    #[wasm_bindgen(getter, js_name = constraintEnergy)]
    pub fn constraint_energy(&self) -> f64 {
        self.session.constraint_energy()
    }

    /// Writes the colour-coded offset map (which exemplar position each pixel comes from: red =
    /// exemplar x, green = exemplar y) into `target`.
    #[wasm_bindgen(js_name = renderOffsetMapInto)]
    pub fn render_offset_map_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&offset_map(&self.session)?, target)
    }

    /// Normalised energy after every iteration so far.
    #[wasm_bindgen(js_name = energyHistory)]
    pub fn energy_history(&self) -> Float64Array {
        let values: Vec<f64> = self.session.history().iter().map(|p| p.energy).collect();
        Float64Array::from(values.as_slice())
    }

    /// The level index of every point of `energyHistory()` (to mark level changes).
    #[wasm_bindgen(js_name = historyLevels)]
    pub fn history_levels(&self) -> Uint32Array {
        let values: Vec<u32> = self
            .session
            .history()
            .iter()
            .map(|p| p.level as u32)
            .collect();
        Uint32Array::from(values.as_slice())
    }

    /// The planned levels: `[{ octave, scale, neighbourhoodSize, spacing, outputWidth,
    /// outputHeight, exemplarWidth, exemplarHeight }]`, coarsest first.
    pub fn schedule(&self) -> Array {
        self.session
            .schedule()
            .iter()
            .map(|l| {
                object(&[
                    ("octave", (l.octave as u32).into()),
                    ("scale", (1u32 << l.octave).into()),
                    ("neighbourhoodSize", (l.size as u32).into()),
                    ("spacing", (l.spacing as u32).into()),
                    ("outputWidth", (l.output_width as u32).into()),
                    ("outputHeight", (l.output_height as u32).into()),
                    ("exemplarWidth", (l.exemplar_width as u32).into()),
                    ("exemplarHeight", (l.exemplar_height as u32).into()),
                ])
            })
            .collect()
    }

    /// Step anatomy: with `true` every step ends after one half of an EM iteration, a part
    /// event `{ kind: 'part', phase: 'first-match' | 'e-step' }` after a level's first M-step
    /// and after each E-step, then the iteration's event after its M-step; `false` steps whole
    /// iterations again. The output is the same either way.
    #[wasm_bindgen(js_name = setHalfSteps)]
    pub fn set_half_steps(&mut self, on: bool) {
        self.session.set_half_steps(on);
    }

    /// The neighbourhood grid X† of the level last iterated (on the step that finishes a level,
    /// still that level's; see `teaching::Field`): `{ columns, rows, neighbourhoodSize,
    /// levelWidth, levelHeight, exemplarWidth, exemplarHeight, matches }`, where `columns`/`rows`
    /// are the top-left corners in level pixels and `matches` holds the chosen exemplar corner
    /// z_p of every node as x, y pairs (row by row), with `distances` (||x_p - z_p|| per node
    /// after the last M-step), `weights` (the next E-step's IRLS weights) and `r`. `null`
    /// before the first step.
    pub fn field(&self) -> JsValue {
        match field(&self.session) {
            Some(f) => field_object(&f, self.session.level_solver(), self.session.options().r),
            None => JsValue::NULL,
        }
    }
}

/// A neighbourhood grid with its matches as the JS object `field()` returns (texture
/// optimisation and the frames of a flow animation share it): the grid, the matches, and from
/// `solver`, ||x_p - z_p|| per node after the last M-step and the IRLS weight of the next
/// E-step (eq. 5: ||x_p - z_p||^(r - 2)), both NaN before the level's first M-step.
pub(crate) fn field_object(f: &Field<'_>, solver: Option<&LevelSolver>, r: f32) -> JsValue {
    let Field {
        level,
        columns,
        rows,
        matches,
    } = *f;
    let to_u32 =
        |v: &[usize]| Uint32Array::from(v.iter().map(|&x| x as u32).collect::<Vec<_>>().as_slice());
    let pairs: Vec<u32> = matches.iter().flat_map(|m| [m.x, m.y]).collect();
    let squared = solver.map_or(&[][..], |s| s.distances());
    let distances: Vec<f32> = squared
        .iter()
        .map(|&d| if d.is_finite() { d.sqrt() } else { f32::NAN })
        .collect();
    let weights: Vec<f32> = squared
        .iter()
        .map(|&d| {
            if d.is_finite() {
                crate::methods::optimization::e_step::robust_weight(d, r)
            } else {
                f32::NAN
            }
        })
        .collect();
    object(&[
        ("distances", Float32Array::from(distances.as_slice()).into()),
        ("weights", Float32Array::from(weights.as_slice()).into()),
        ("r", r.into()),
        ("columns", to_u32(columns).into()),
        ("rows", to_u32(rows).into()),
        ("neighbourhoodSize", (level.size as u32).into()),
        ("levelWidth", (level.output_width as u32).into()),
        ("levelHeight", (level.output_height as u32).into()),
        ("exemplarWidth", (level.exemplar_width as u32).into()),
        ("exemplarHeight", (level.exemplar_height as u32).into()),
        ("matches", Uint32Array::from(pairs.as_slice()).into()),
    ])
}
