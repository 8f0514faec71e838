//! Feature-guided synthesis (Wu & Yu 2004) for JS: `detectFeatures` gives an editable
//! `FeatureMap`, `FeatureSynthesis` places one patch per step and shows its feature map, context,
//! correspondences and warp, and `measureBrokenFeatures` scores any output.

use js_sys::{Array, Float32Array, Uint8ClampedArray};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use super::error::JsResult;
use super::exemplar::Exemplar;
use super::options::{OptionsReader, object};
use super::pixels::{render_into, write_rgba};
use super::schema::{
    DONE, EventField, Kind, MEMORY_BUDGET, Opt, Schema, invalid, kind_field, output_size,
};
use super::session::{JsSession, js_session};
use crate::core::{Error, from_rgba8};
use crate::methods::design::Deformation;
use crate::methods::features::broken::{BrokenBaseline, broken_features};
use crate::methods::features::{
    DetectOptions, FeatureKind, FeatureMap as Map, FeatureOptions, FeaturePlacement,
    FeatureSynthesis as Synthesis, WarpKind, detect,
};

const FEATURES: Opt = Opt {
    key: "features",
    kind: Kind::Choice(&["edges", "ridges", "both"]),
    default: Some("'ridges'"),
    doc: "Which curves make the map.",
};
const THRESHOLD: Opt = Opt {
    key: "threshold",
    kind: Kind::Number,
    default: Some("0.9"),
    doc: "Percentile of the responses above which a pixel is a strong feature, 0.5..0.999.",
};
const ALPHA: Opt = Opt {
    key: "alpha",
    kind: Kind::Number,
    default: Some("0.3"),
    doc: "Weak features: at least alpha times a nearby strong response, 0..1.",
};

/// The feature detector's options (`detectFeatures`, `FeatureMap`); `FeatureSynthesis` takes
/// the same keys among its own.
pub(crate) const DETECT_SCHEMA: Schema = Schema {
    class: "FeatureMap",
    options_name: "DetectFeaturesOptions",
    options: &[FEATURES, THRESHOLD, ALPHA],
    required: &[],
    event_name: "",
    event: &[],
};

fn read_detect(js: &OptionsReader) -> JsResult<DetectOptions> {
    let d = DetectOptions::default();
    let kind = |name: &str| match name {
        "edges" => Some(FeatureKind::Edges),
        "ridges" => Some(FeatureKind::Ridges),
        "both" => Some(FeatureKind::Both),
        _ => None,
    };
    let options = DetectOptions {
        kind: js.choice("features", kind)?.unwrap_or(d.kind),
        percentile: js.number("threshold")?.map_or(d.percentile, |v| v as f32),
        alpha: js.number("alpha")?.map_or(d.alpha, |v| v as f32),
    };
    options.validate()?;
    Ok(options)
}

/// An exemplar's feature map: curves one pixel wide with their tangents. Paint and erase to
/// correct it, then hand it to `FeatureSynthesis.withFeatureMap`.
#[wasm_bindgen]
pub struct FeatureMap {
    map: Map,
    /// The exemplar's map as detected, for `brokenFeatures` (edits do not move it).
    baseline: BrokenBaseline,
}

impl FeatureMap {
    /// The curves as edited, one flag per exemplar pixel.
    pub(crate) fn mask(&self) -> &[bool] {
        &self.map.mask
    }

    /// The map's width and height (the exemplar's).
    pub(crate) fn size(&self) -> (usize, usize) {
        (self.map.width, self.map.height)
    }

    fn detect(exemplar: &Exemplar, options: &JsValue) -> JsResult<FeatureMap> {
        let js = OptionsReader::new(options, &DETECT_SCHEMA)?;
        let options = read_detect(&js)?;
        js.finish()?;
        let map = detect(exemplar.image(), options)?;
        Ok(FeatureMap {
            baseline: BrokenBaseline::of(&map, options),
            map,
        })
    }
}

fn check_finite(values: &[(&'static str, f32)]) -> JsResult<()> {
    for &(name, v) in values {
        if !v.is_finite() {
            return Err(invalid(name, format!("must be a finite number, got {v}")));
        }
    }
    Ok(())
}

fn check_radius(radius: f32) -> JsResult<()> {
    if !(0.0..=64.0).contains(&radius) {
        return Err(invalid(
            "radius",
            format!("must be between 0 and 64, got {radius}"),
        ));
    }
    Ok(())
}

/// Detects the feature map of an exemplar: `detectFeatures(exemplar, { features: 'ridges' |
/// 'edges' | 'both', threshold: 0.9, alpha: 0.3 })` (threshold: the percentile of responses above
/// which a pixel is a strong feature).
#[wasm_bindgen(js_name = detectFeatures)]
pub fn detect_features(exemplar: &Exemplar, options: JsValue) -> JsResult<FeatureMap> {
    FeatureMap::detect(exemplar, &options)
}

#[wasm_bindgen]
impl FeatureMap {
    /// The same as `detectFeatures(exemplar, options)`, as a constructor, so that a worker can
    /// make one (the package's worker makes any exported class): a photo's map detected and
    /// edited there, off the page's thread.
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<FeatureMap> {
        FeatureMap::detect(exemplar, &options)
    }

    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.map.width as u32
    }

    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.map.height as u32
    }

    /// Feature pixels.
    #[wasm_bindgen(getter)]
    pub fn count(&self) -> u32 {
        self.map.count() as u32
    }

    /// Paints (`on` true) or erases a disc of `radius` pixels at (x, y).
    pub fn paint(&mut self, x: f32, y: f32, radius: f32, on: bool) -> JsResult<()> {
        check_finite(&[("x", x), ("y", y), ("radius", radius)])?;
        check_radius(radius)?;
        self.map.paint(x, y, radius, on);
        Ok(())
    }

    /// Paints (`on` true) or erases the stroke from (x0, y0) to (x1, y1) with a disc of `radius`
    /// pixels: a brush's move, without gaps however far apart the pointer reported it (the part
    /// off the map is left out).
    #[wasm_bindgen(js_name = paintLine)]
    pub fn paint_line(
        &mut self,
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        radius: f32,
        on: bool,
    ) -> JsResult<()> {
        check_finite(&[
            ("x0", x0),
            ("y0", y0),
            ("x1", x1),
            ("y1", y1),
            ("radius", radius),
        ])?;
        check_radius(radius)?;
        // Ends further off are a caller's mistake (and would lose the stroke's precision).
        for (name, v) in [("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1)] {
            if v.abs() > 1e9 {
                return Err(invalid(
                    name,
                    format!("must be within 1e9 pixels of the map, got {v}"),
                ));
            }
        }
        self.map.paint_line((x0, y0), (x1, y1), radius, on);
        Ok(())
    }

    /// The broken-feature count of an RGBA output against this map's exemplar, as
    /// `measureBrokenFeatures(exemplar, rgba, width, height, options)` gives it with the options
    /// this map was detected with, without detecting the exemplar again (seconds for a photo).
    /// Edits to the map do not change it: outputs are scored against the exemplar as detected.
    #[wasm_bindgen(js_name = brokenFeatures)]
    pub fn broken_features(&self, rgba: &[u8], width: u32, height: u32) -> JsResult<f64> {
        let output = from_rgba8(width as usize, height as usize, rgba)?;
        Ok(self.baseline.broken(&output))
    }

    /// The curves as a mask, one byte per pixel (1 on a curve): `featureMask` of
    /// `FeatureSynthesis`.
    #[wasm_bindgen(js_name = toMask)]
    pub fn to_mask(&self) -> js_sys::Uint8Array {
        let bytes: Vec<u8> = self.map.mask.iter().map(|&m| u8::from(m)).collect();
        js_sys::Uint8Array::from(bytes.as_slice())
    }

    /// The curves as RGBA: coloured by orientation bucket, transparent elsewhere.
    #[wasm_bindgen(js_name = renderInto)]
    pub fn render_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        write_rgba(&feature_rgba(&self.map.mask, &self.map.angle), target)
    }

    /// The curves as `width` x `height` RGBA (1 to 4096 a side), each pixel showing a curve pixel
    /// of its footprint if it has one: a photo's map, drawn the size of its view, keeps every
    /// one-pixel curve (a browser's scaling of the full-size view averages them away).
    #[wasm_bindgen(js_name = scaledView)]
    pub fn scaled_view(&self, width: u32, height: u32) -> JsResult<Uint8ClampedArray> {
        for (name, v) in [("width", width), ("height", height)] {
            if !(1..=4096).contains(&v) {
                return Err(invalid(name, format!("must be 1 to 4096, got {v}")));
            }
        }
        let (w, h) = (width as usize, height as usize);
        let (mw, mh) = (self.map.width, self.map.height);
        let mut rgba = vec![0u8; w * h * 4];
        // Footprint of view pixel t along a side: map pixels [t * m / v, (t + 1) * m / v), at
        // least one.
        let span = |t: usize, m: usize, v: usize| {
            let a = t * m / v;
            a..((t + 1) * m / v).max(a + 1).min(m)
        };
        for ty in 0..h {
            for tx in 0..w {
                let hit = span(ty, mh, h)
                    .flat_map(|y| span(tx, mw, w).map(move |x| y * mw + x))
                    .find(|&i| self.map.mask[i]);
                if let Some(i) = hit {
                    let colour =
                        BUCKET_COLOURS[crate::methods::features::detect::bucket(self.map.angle[i])];
                    rgba[(ty * w + tx) * 4..][..4].copy_from_slice(&colour);
                }
            }
        }
        Ok(Uint8ClampedArray::from(rgba.as_slice()))
    }
}

/// The four bucket colours of the feature views.
const BUCKET_COLOURS: [[u8; 4]; 4] = [
    [255, 90, 80, 255],
    [250, 210, 70, 255],
    [90, 200, 255, 255],
    [170, 120, 255, 255],
];

fn feature_rgba(mask: &[bool], angle: &[f32]) -> Vec<u8> {
    mask.iter()
        .zip(angle)
        .flat_map(|(&m, &a)| {
            if m {
                BUCKET_COLOURS[crate::methods::features::detect::bucket(a)]
            } else {
                [0, 0, 0, 0]
            }
        })
        .collect()
}

pub(crate) const SCHEMA: Schema = Schema {
    class: "FeatureSynthesis",
    options_name: "FeatureSynthesisOptions",
    options: &[
        MEMORY_BUDGET,
        output_size("outputWidth", 8192, Some("256"), "Output width in pixels."),
        output_size(
            "outputHeight",
            8192,
            Some("256"),
            "Output height in pixels.",
        ),
        Opt {
            key: "placement",
            kind: Kind::Choice(&["graphcut", "scan"]),
            default: Some("'graphcut'"),
            doc: "'graphcut': graph-cut placement of the whole exemplar, offsets chosen by colour SSD plus the feature cost over the band where the patch meets the made output, seams that also pay for cutting curves (no warp); 'scan': the paper's patches in scan order, warped.",
        },
        Opt {
            key: "seamFeatureWeight",
            kind: Kind::Number,
            default: Some("1"),
            doc: "Graph-cut placement: seam cost per pixel where the two patches disagree on a curve, in units of the exemplar's feature contrast, 0..100.",
        },
        Opt {
            key: "patchSize",
            kind: Kind::Integer { min: 1, max: 4096 },
            default: None,
            doc: "16..128, at most the exemplar's shorter side (scan placement; graph-cut placement's feature band is a quarter of it). Default: 64, or the exemplar's shorter side when smaller (the exemplar needs at least 16x16).",
        },
        Opt {
            key: "overlap",
            kind: Kind::Integer { min: 1, max: 4096 },
            default: None,
            doc: "Context-region width (scan), or the width of the feature-cost band (graphcut). Default: a quarter of patchSize.",
        },
        Opt {
            key: "featureWeight",
            kind: Kind::Number,
            default: Some("0.5"),
            doc: "Weight of the feature cost against the colour SSD, 0..1.",
        },
        Opt {
            key: "warp",
            kind: Kind::Boolean,
            default: Some("true"),
            doc: "Bend each patch onto the context's features. Scan placement only: graph-cut placement (the default) cannot warp, and its events say warp 'unavailable'.",
        },
        Opt {
            key: "tolerance",
            kind: Kind::Number,
            default: Some("0.1"),
            doc: "Scan placement: candidates within (1 + tolerance) of the best are drawn at random, 0..10.",
        },
        Opt {
            key: "featureCandidates",
            kind: Kind::Integer {
                min: 1,
                max: 100_000,
            },
            default: None,
            doc: "Best candidates by colour whose feature cost is computed. Default: 64 for graph-cut placement, 256 for scan.",
        },
        Opt {
            key: "extraInputs",
            kind: Kind::Value("Array<'rotate90' | 'rotate180' | 'rotate270' | 'mirror' | 'flip'>"),
            default: Some("[]"),
            doc: "Deformed copies of the exemplar as extra inputs.",
        },
        FEATURES,
        THRESHOLD,
        ALPHA,
        Opt {
            key: "seed",
            kind: Kind::Integer {
                min: 0,
                max: 0xffff_ffff,
            },
            default: Some("1"),
            doc: "Seed of the random choices: the same seed, options and input give the same bytes.",
        },
        Opt {
            key: "featureMask",
            kind: Kind::Value("Uint8Array"),
            default: None,
            doc: "An edited feature map, one byte per exemplar pixel, non-zero on a curve (`FeatureMap.toMask()`), so that an edited map can be sent to a worker; the tangents still come from the exemplar. Default: the detected map.",
        },
    ],
    required: &[],
    event_name: "FeatureSynthesisEvent",
    event: &[
        kind_field("'placed' | 'done'"),
        DONE,
        EventField {
            key: "patchesPlaced",
            ts: "number",
            doc: "Patches placed so far, this step's included.",
        },
        EventField {
            key: "patchesPlanned",
            ts: "number",
            doc: "Patches the output takes (with graph-cut placement, a lower bound that grows until the output is covered).",
        },
        EventField {
            key: "x",
            ts: "number",
            doc: "Left of the patch in the output.",
        },
        EventField {
            key: "y",
            ts: "number",
            doc: "Top of the patch in the output.",
        },
        EventField {
            key: "input",
            ts: "number",
            doc: "The input the patch came from (0: the exemplar, then `extraInputs` in order).",
        },
        EventField {
            key: "sourceX",
            ts: "number",
            doc: "Left of the patch in its input.",
        },
        EventField {
            key: "sourceY",
            ts: "number",
            doc: "Top of the patch in its input.",
        },
        EventField {
            key: "featureCost",
            ts: "number",
            doc: "The feature cost of eq. 2 of the chosen candidate.",
        },
        EventField {
            key: "colourCost",
            ts: "number",
            doc: "Mean squared colour difference of the chosen candidate.",
        },
        EventField {
            key: "contextFeatures",
            ts: "number",
            doc: "Feature pixels in the patch's context region.",
        },
        EventField {
            key: "correspondences",
            ts: "number",
            doc: "Feature correspondences the warp used.",
        },
        EventField {
            key: "warp",
            ts: "'none' | 'spline' | 'shepard' | 'skipped' | 'unavailable'",
            doc: "The warp applied to the patch: 'none' (nothing to align, or `warp` off), 'spline', 'shepard' (the spline failed), 'skipped' (it would move pixels too far), 'unavailable' (graph-cut placement, which cannot warp).",
        },
        EventField {
            key: "colourOnly",
            ts: "boolean",
            doc: "True when the choice used colour only (no oriented features to match).",
        },
    ],
};

/// The options; `featureMask` is returned raw, for the constructor to check against the
/// exemplar.
fn read_options(value: &JsValue) -> JsResult<(FeatureOptions, Option<JsValue>)> {
    let js = OptionsReader::new(value, &SCHEMA)?;
    let d = FeatureOptions::default();
    let mut extra = Vec::new();
    if let Some(v) = js.value("extraInputs")? {
        if !Array::is_array(&v) {
            return Err(invalid(
                "extraInputs",
                "must be an array such as ['rotate90', 'mirror']",
            ));
        }
        for item in Array::from(&v).iter() {
            extra.push(match item.as_string().as_deref() {
                Some("rotate90") => Deformation::Rotate { degrees: 90.0 },
                Some("rotate180") => Deformation::Rotate { degrees: 180.0 },
                Some("rotate270") => Deformation::Rotate { degrees: 270.0 },
                Some("mirror") => Deformation::Mirror,
                Some("flip") => Deformation::Flip,
                _ => {
                    return Err(invalid(
                        "extraInputs",
                        format!("entries are 'rotate90', 'rotate180', 'rotate270', 'mirror' or 'flip', got {item:?}"),
                    ));
                }
            });
        }
    }
    let options = FeatureOptions {
        memory_budget_mib: js.memory_budget()?,
        placement: js
            .choice("placement", FeaturePlacement::from_name)?
            .unwrap_or(d.placement),
        seam_feature_weight: js
            .number("seamFeatureWeight")?
            .map_or(d.seam_feature_weight, |v| v as f32),
        output_width: js.size("outputWidth")?.unwrap_or(d.output_width),
        output_height: js.size("outputHeight")?.unwrap_or(d.output_height),
        patch_size: js.size("patchSize")?,
        overlap: js.size("overlap")?,
        feature_weight: js
            .number("featureWeight")?
            .map_or(d.feature_weight, |v| v as f32),
        warp: js.boolean("warp")?.unwrap_or(d.warp),
        tolerance: js.number("tolerance")?.map_or(d.tolerance, |v| v as f32),
        feature_candidates: js.size("featureCandidates")?,
        extra_inputs: extra,
        detect: read_detect(&js)?,
        seed: js.integer("seed")?.unwrap_or(d.seed),
    };
    let mask = js.value("featureMask")?;
    js.finish()?;
    Ok((options, mask))
}

/// Feature-guided synthesis (Wu & Yu 2004), one patch per step.
#[wasm_bindgen]
pub struct FeatureSynthesis {
    synthesis: Synthesis,
}

js_session!(FeatureSynthesis);

/// One patch per step.
impl JsSession for FeatureSynthesis {
    fn step_event(&mut self) -> JsResult<JsValue> {
        let e = self.synthesis.step()?;
        let warp = match e.warp {
            WarpKind::None => "none",
            WarpKind::Spline => "spline",
            WarpKind::Shepard(_) => "shepard",
            WarpKind::Skipped => "skipped",
            WarpKind::Unavailable => "unavailable",
        };
        SCHEMA.event(&[
            ("kind", if e.done { "done" } else { "placed" }.into()),
            ("done", e.done.into()),
            ("patchesPlaced", (e.patch as u32 + 1).into()),
            ("patchesPlanned", (e.patches as u32).into()),
            ("x", (e.x as u32).into()),
            ("y", (e.y as u32).into()),
            ("input", (e.input as u32).into()),
            ("sourceX", (e.source_x as u32).into()),
            ("sourceY", (e.source_y as u32).into()),
            ("featureCost", e.feature_cost.into()),
            ("colourCost", e.colour_cost.into()),
            ("contextFeatures", (e.context_features as u32).into()),
            ("correspondences", (e.correspondences as u32).into()),
            ("warp", warp.into()),
            ("colourOnly", e.colour_only.into()),
        ])
    }

    fn is_done(&self) -> bool {
        self.synthesis.is_done()
    }

    fn size(&self) -> (usize, usize) {
        let o = self.synthesis.options();
        (o.output_width, o.output_height)
    }

    fn memory_bytes(&self) -> u64 {
        self.synthesis.working_set().bytes()
    }

    fn render(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        render_into(self.synthesis.image(), target)
    }
}

#[wasm_bindgen]
impl FeatureSynthesis {
    /// `new FeatureSynthesis(exemplar, options)`: see [`SCHEMA`] (every key optional).
    #[wasm_bindgen(constructor)]
    pub fn new(exemplar: &Exemplar, options: JsValue) -> JsResult<FeatureSynthesis> {
        let (parsed, mask) = read_options(&options)?;
        let map = match mask {
            None => None,
            Some(v) => {
                let Some(bytes) = v.dyn_ref::<js_sys::Uint8Array>() else {
                    return Err(invalid(
                        "featureMask",
                        "must be a Uint8Array, one byte per exemplar pixel",
                    ));
                };
                let img = exemplar.image();
                let n = img.width() * img.height();
                if bytes.length() as usize != n {
                    return Err(Error::LengthMismatch {
                        what: "featureMask",
                        expected: n,
                        actual: bytes.length() as usize,
                    }
                    .into());
                }
                let mut map = detect(img, parsed.detect)?;
                for (m, b) in map.mask.iter_mut().zip(bytes.to_vec()) {
                    *m = b != 0;
                }
                Some(map)
            }
        };
        Ok(FeatureSynthesis {
            synthesis: Synthesis::new(exemplar.image(), map, parsed)?,
        })
    }

    /// Like the constructor, with a feature map the caller detected (and perhaps edited).
    #[wasm_bindgen(js_name = withFeatureMap)]
    pub fn with_feature_map(
        exemplar: &Exemplar,
        map: &FeatureMap,
        options: JsValue,
    ) -> JsResult<FeatureSynthesis> {
        Ok(FeatureSynthesis {
            synthesis: Synthesis::new(
                exemplar.image(),
                Some(map.map.clone()),
                read_options(&options)?.0,
            )?,
        })
    }

    /// The broken-feature count on the synthesised feature map: its curve ends per 1000 curve
    /// pixels above those of the exemplar map it carries (the curves the seams cut; compare
    /// `GraphcutTextures.carriedBrokenFeatures(mask)` with the same map's mask).
    #[wasm_bindgen(js_name = carriedBrokenFeatures)]
    pub fn carried_broken_features(&self) -> f64 {
        self.synthesis.carried_broken()
    }

    /// Turns on the placement anatomy of graph-cut placement (see `GraphcutTextures.setAnatomy`;
    /// the cost surface is the colour cost of eq. 2, which the feature cost then re-ranks among
    /// the best candidates). A scan-placement synthesis has no graph cut: an error names it.
    #[wasm_bindgen(js_name = setAnatomy)]
    pub fn set_anatomy(&mut self, on: bool) -> JsResult<()> {
        let session = self.synthesis.graphcut_session_mut().ok_or_else(|| {
            crate::core::Error::InvalidParameter {
                name: "setAnatomy",
                reason: "the placement anatomy needs placement 'graphcut'".into(),
            }
        })?;
        session.set_anatomy(on);
        Ok(())
    }

    /// The last graph-cut placement's cost surface (see `GraphcutTextures.placementCosts`), or
    /// null.
    #[wasm_bindgen(js_name = placementCosts)]
    pub fn placement_costs(&self) -> JsValue {
        self.synthesis
            .graphcut_session()
            .and_then(|s| s.placement_costs())
            .map_or(JsValue::NULL, super::anatomy::costs_object)
    }

    /// The last graph-cut placement's seam graph (see `GraphcutTextures.placementGraph`), or
    /// null.
    #[wasm_bindgen(js_name = placementGraph)]
    pub fn placement_graph(&self) -> JsValue {
        self.synthesis
            .graphcut_session()
            .and_then(|s| s.placement_graph())
            .map_or(JsValue::NULL, super::anatomy::graph_object)
    }

    /// The synthesised feature map, coloured by orientation (output size).
    #[wasm_bindgen(js_name = renderFeaturesInto)]
    pub fn render_features_into(&self, target: &Uint8ClampedArray) -> JsResult<()> {
        write_rgba(
            &feature_rgba(
                self.synthesis.feature_mask(),
                self.synthesis.feature_angles(),
            ),
            target,
        )
    }

    /// The last placement: `{ x, y, size, top, left, pairs, grid }`: the patch's place, its
    /// context region (rows at the top, columns at the left), the correspondences as a flat
    /// Float32Array (context x, y, then where its partner lay in the patch, x, y, in output
    /// coordinates), and the warp's displacements every 4 pixels (dx, dy pairs).
    pub fn placement(&self) -> JsValue {
        let p = self.synthesis.placement();
        let pairs: Vec<f32> = p
            .pairs
            .iter()
            .flat_map(|&((a, b), (c, d))| [a, b, c, d])
            .collect();
        let grid: Vec<f32> = p.grid.iter().flat_map(|&(a, b)| [a, b]).collect();
        object(&[
            ("x", (p.x as u32).into()),
            ("y", (p.y as u32).into()),
            ("size", (p.size as u32).into()),
            ("top", p.region.map_or(0, |r| r.top as u32).into()),
            ("left", p.region.map_or(0, |r| r.left as u32).into()),
            ("pairs", Float32Array::from(pairs.as_slice()).into()),
            ("grid", Float32Array::from(grid.as_slice()).into()),
        ])
    }
}

/// The broken-feature count of an RGBA output against an exemplar: curve ends per 1000 curve
/// pixels in the output's detected feature map minus the exemplar's (lower is better).
#[wasm_bindgen(js_name = measureBrokenFeatures)]
pub fn measure_broken_features(
    exemplar: &Exemplar,
    rgba: &[u8],
    width: u32,
    height: u32,
    options: JsValue,
) -> JsResult<f64> {
    let js = OptionsReader::new(&options, &DETECT_SCHEMA)?;
    let detect = read_detect(&js)?;
    js.finish()?;
    let output = from_rgba8(width as usize, height as usize, rgba)?;
    Ok(broken_features(exemplar.image(), &output, detect)?)
}
