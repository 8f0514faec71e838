//! `Inpainting`: the JS-visible hole filling (and uncrop, with `extendBorder`). Each `step()`
//! places one patch of the graph-cut fill, then runs an EM iteration of the texture
//! optimisation; the image renders into the caller's buffer, the known pixels exactly as given.

use js_sys::{Uint8Array, Uint8ClampedArray};
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::object::object;
use super::options::OptionsReader;
use super::pixels::{render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, SEED, Schema, boolean, kind_field, number,
};
use super::session::{JsSession, js_session};
use crate::core::Error;
use crate::methods::inpainting::{Border, Event, EventKind, Options, Session, extend};
use crate::solvers::nn::Search;

pub(crate) const SCHEMA: Schema = Schema {
    class: "Inpainting",
    options_name: "InpaintingOptions",
    options: &[
        MEMORY_BUDGET,
        SEED,
        Opt {
            key: "patchSize",
            kind: Kind::Integer { min: 4, max: 256 },
            default: Some("32"),
            doc: "Side of the graph-cut fill's patches (halved while the image has no window of that side outside the hole).",
        },
        number(
            "k",
            Some("0.01"),
            "The fill draws source windows with probability exp(-C / (k sigma^2)).",
        ),
        Opt {
            key: "levels",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("1"),
            doc: "Resolution levels of the texture optimisation; more break up the structure the fill laid (coarse levels where the hole leaves no neighbourhood outside it are dropped).",
        },
        Opt {
            key: "neighbourhoodSizes",
            kind: Kind::Integers {
                min: 0,
                max: 1 << 20,
            },
            default: Some("[16, 8]"),
            doc: "The optimisation's neighbourhood sizes, largest first; the largest is also the margin of known pixels it works on.",
        },
        Opt {
            key: "iterations",
            kind: Kind::Integer {
                min: 0,
                max: 1 << 20,
            },
            default: Some("5"),
            doc: "EM iterations per level at most.",
        },
        number(
            "r",
            Some("2"),
            "IRLS exponent of the optimisation; below 2 the neighbourhoods across the hole's boundary weigh less and a seam shows there.",
        ),
        Opt {
            key: "search",
            kind: Kind::Choice(&["patchmatch", "kmeans-tree", "exact"]),
            default: Some("'patchmatch'"),
            doc: "The optimisation's nearest-neighbour search.",
        },
        number(
            "histogramMatching",
            Some("1"),
            "How far the filled pixels' colour histogram is matched to that of the known pixels around the hole (0..1); the known pixels never move.",
        ),
        number(
            "completeness",
            Some("1"),
            "Weight of the occurrence penalty that spreads the hole's matches over the exemplar.",
        ),
        boolean(
            "optimize",
            "true",
            "Run the texture optimisation after the fill (false: the fill is the result).",
        ),
    ],
    required: &[],
    event_name: "InpaintingEvent",
    event: &[
        kind_field("'placed' | 'part' | 'level' | 'iteration' | 'done'"),
        DONE,
        EventField {
            key: "stage",
            ts: "'fill' | 'optimization'",
            doc: "The pass the step belongs to: the graph-cut fill, then the texture optimisation.",
        },
        EventField {
            key: "patch",
            ts: "{ x: number; y: number; size: number; sourceX: number; sourceY: number; cutCost: number } | null",
            doc: "The fill's patch of this step: its corner in the image, its side, the corner of the window it copies (in the exemplar, or in the image itself) and its cut's cost; null in the optimisation.",
        },
        EventField {
            key: "patchesPlaced",
            ts: "number",
            doc: "Patches the fill placed so far.",
        },
        EventField {
            key: "pixelsFilled",
            ts: "number",
            doc: "Hole pixels filled so far.",
        },
        EventField {
            key: "holePixels",
            ts: "number",
            doc: "Pixels in the hole.",
        },
        EventField {
            key: "level",
            ts: "number | null",
            doc: "The optimisation's level (0-based); null during the fill.",
        },
        EventField {
            key: "levelCount",
            ts: "number | null",
            doc: "Levels of the optimisation's schedule; null during the fill.",
        },
        EventField {
            key: "iteration",
            ts: "number | null",
            doc: "Iteration within the level, 1-based; null during the fill.",
        },
        EventField {
            key: "energy",
            ts: "number | null",
            doc: "Texture energy of the optimisation's iteration; null during the fill and before a level's first iteration.",
        },
    ],
};

fn read_options(value: &JsValue) -> JsResult<Options> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = Options::default();
    let options = Options {
        memory_budget_mib: js.memory_budget()?,
        seed: js.integer("seed")?.unwrap_or(d.seed),
        patch_size: js.size("patchSize")?.unwrap_or(d.patch_size),
        k: js.number("k")?.map_or(d.k, |v| v as f32),
        levels: js.size("levels")?.unwrap_or(d.levels),
        neighbourhood_sizes: js
            .integers("neighbourhoodSizes")?
            .map_or(d.neighbourhood_sizes, |v| {
                v.into_iter().map(|s| s as usize).collect()
            }),
        iterations: js.size("iterations")?.unwrap_or(d.iterations),
        r: js.number("r")?.map_or(d.r, |v| v as f32),
        search: js.choice("search", Search::from_name)?.unwrap_or(d.search),
        histogram_matching: js
            .number("histogramMatching")?
            .map_or(d.histogram_matching, |v| v as f32),
        completeness: js
            .number("completeness")?
            .map_or(d.completeness, |v| v as f32),
        optimize: js.boolean("optimize")?.unwrap_or(d.optimize),
    };
    js.finish()?;
    Ok(options)
}

fn event_object(e: &Event) -> JsResult<JsValue> {
    let kind = match e.kind {
        EventKind::Placed => "placed",
        EventKind::Part => "part",
        EventKind::Level => "level",
        EventKind::Iteration => "iteration",
        EventKind::Done => "done",
    };
    let patch = e.patch.map_or(JsValue::NULL, |p| {
        object(&[
            ("x", (p.x as u32).into()),
            ("y", (p.y as u32).into()),
            ("size", (p.size as u32).into()),
            ("sourceX", (p.source_x as u32).into()),
            ("sourceY", (p.source_y as u32).into()),
            ("cutCost", p.cut_cost.into()),
        ])
    });
    let or_null = |v: Option<usize>| v.map_or(JsValue::NULL, |v| (v as u32).into());
    SCHEMA.event(&[
        ("kind", kind.into()),
        ("done", (e.kind == EventKind::Done).into()),
        ("stage", e.stage.name().into()),
        ("patch", patch),
        ("patchesPlaced", (e.patches_placed as u32).into()),
        ("pixelsFilled", (e.pixels_filled as u32).into()),
        ("holePixels", (e.hole_pixels as u32).into()),
        ("level", or_null(e.level)),
        ("levelCount", or_null(e.level_count)),
        ("iteration", or_null(e.iteration)),
        ("energy", e.energy.map_or(JsValue::NULL, JsValue::from)),
    ])
}

/// Fills a hole in an image (and, with `extendBorder`, extends its borders) you advance with
/// `step()`.
#[wasm_bindgen]
pub struct Inpainting {
    session: Session,
}

js_session!(Inpainting);

/// A fill patch, then an EM iteration, per step.
impl JsSession for Inpainting {
    fn step_event(&mut self) -> JsResult<JsValue> {
        event_object(&self.session.step()?)
    }

    fn is_done(&self) -> bool {
        self.session.is_done()
    }

    fn size(&self) -> (usize, usize) {
        let hole = self.session.hole();
        (hole.width, hole.height)
    }

    fn memory_bytes(&self) -> u64 {
        self.session.memory_estimate()
    }

    /// The image: the known pixels as given, the hole as filled so far.
    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(&self.session.output()?, target)
    }
}

#[wasm_bindgen]
impl Inpainting {
    /// Fills the pixels of `image` where `mask` (one byte per pixel) is non-zero from the rest
    /// of the image. Options: see [`SCHEMA`]. A mask of the wrong size, an empty mask and a full
    /// one throw, as do unknown keys and impossible values.
    #[wasm_bindgen(constructor)]
    pub fn new(image: &Exemplar, mask: &[u8], options: JsValue) -> JsResult<Inpainting> {
        let options = read_options(&options)?;
        Ok(Inpainting {
            session: Session::new(image.image(), mask, None, options)?,
        })
    }

    /// Like the constructor, filling from `exemplar` (the image's channels) instead of the
    /// image's known part.
    #[wasm_bindgen(js_name = withExemplar)]
    pub fn with_exemplar(
        image: &Exemplar,
        mask: &[u8],
        exemplar: &Exemplar,
        options: JsValue,
    ) -> JsResult<Inpainting> {
        let options = read_options(&options)?;
        let source = exemplar.image().with_channels(image.image().channels())?;
        Ok(Inpainting {
            session: Session::new(image.image(), mask, Some(&source), options)?,
        })
    }

    /// The part of the image the session works on: the hole's bounds and a margin, `{ x, y,
    /// width, height }`.
    #[wasm_bindgen(getter)]
    pub fn region(&self) -> JsValue {
        let r = self.session.region();
        object(&[
            ("x", (r.x as u32).into()),
            ("y", (r.y as u32).into()),
            ("width", (r.width as u32).into()),
            ("height", (r.height as u32).into()),
        ])
    }

    /// The fill's patches, each in its own colour; known pixels grey, unfilled ones
    /// transparent (image size).
    #[wasm_bindgen(js_name = renderPatchesInto)]
    pub fn render_patches_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        let hole = self.session.hole();
        let r = self.session.region();
        let labels = self.session.fill().labels();
        let mut rgba = vec![0u8; hole.width * hole.height * 4];
        for (i, px) in rgba.chunks_exact_mut(4).enumerate() {
            let (x, y) = (i % hole.width, i / hole.width);
            let inside = x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
            let label = if inside {
                labels[(y - r.y) * r.width + x - r.x]
            } else {
                1
            };
            px.copy_from_slice(&match label {
                0 => [0, 0, 0, 0],
                1 => [128, 128, 128, 255],
                p => {
                    let [r, g, b] = crate::methods::graphcut::teaching::label_colour(p - 2);
                    [r, g, b, 255]
                }
            });
        }
        write_rgba(&rgba, target)
    }
}

/// Uncrop's input: `image` inside a border of `border` pixels (one number for all four sides, or
/// `{ top, right, bottom, left }`), returned as `{ image: Exemplar, mask: Uint8Array }` with the
/// border marked as the hole, to give to `new Inpainting(image, mask, options)`.
#[wasm_bindgen(js_name = extendBorder)]
pub fn extend_border(image: &Exemplar, border: JsValue) -> JsResult<JsValue> {
    let width = |v: JsValue, name: &'static str| -> JsResult<usize> {
        match v.as_f64() {
            Some(n) if n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= 1e6 => Ok(n as usize),
            _ => Err(Error::InvalidParameter {
                name,
                reason: format!("must be a whole number of pixels from 0, got {v:?}"),
            }
            .into()),
        }
    };
    let border = if border.as_f64().is_some() {
        Border::all(width(border, "border")?)
    } else if border.is_object() {
        let side = |key: &str| js_sys::Reflect::get(&border, &key.into()).unwrap_or_default();
        let or_zero = |v: JsValue| {
            if v.is_undefined() {
                JsValue::from(0)
            } else {
                v
            }
        };
        let object: &js_sys::Object = border.unchecked_ref();
        for key in js_sys::Object::keys(object).iter() {
            let key = key.as_string().unwrap_or_default();
            if !["top", "right", "bottom", "left"].contains(&key.as_str()) {
                return Err(Error::UnknownOption(format!(
                    "border.{key} (the sides are top, right, bottom, left)"
                ))
                .into());
            }
        }
        Border {
            top: width(or_zero(side("top")), "border.top")?,
            right: width(or_zero(side("right")), "border.right")?,
            bottom: width(or_zero(side("bottom")), "border.bottom")?,
            left: width(or_zero(side("left")), "border.left")?,
        }
    } else {
        return Err(Error::InvalidParameter {
            name: "border",
            reason: "must be a number or { top, right, bottom, left }".into(),
        }
        .into());
    };
    let (big, mask) = extend(image.image(), border)?;
    Ok(object(&[
        ("image", Exemplar::from_image(big).into()),
        ("mask", Uint8Array::from(&mask[..]).into()),
    ]))
}
