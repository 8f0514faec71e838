//! Shared by the fuzz targets: a small exemplar from fuzz bytes, option values as a JS caller
//! could give them, and one function that builds any session type from them and steps it.
#![allow(dead_code)]

use arbitrary::{Result, Unstructured};
use texsynth::core::Image;
use texsynth::methods::design::layers::{
    Layer, LayerDesign, LayerOptions, LayerPlacement, LayerSearch,
};
use texsynth::methods::design::{
    BrushOptions, LabellingWeights, LocalDeformation, Stroke, TileableOptions, TileableSession,
};
use texsynth::methods::features::{
    DetectOptions, FeatureKind, FeatureOptions, FeaturePlacement, FeatureSynthesis,
};
use texsynth::methods::flow::{
    Component, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};
use texsynth::methods::video::{self, Volume};
use texsynth::methods::{graphcut, optimization};
use texsynth::solvers::nn::Search;

/// How wild the option values are: `Small` keeps sizes and counts small so sessions run
/// (session_steps); `Wild` draws anything the bindings let through (options).
#[derive(Clone, Copy, PartialEq)]
pub enum Values {
    Small,
    Wild,
}

/// The memory budget of every fuzzed session: large outputs are refused, not allocated.
const BUDGET_MIB: usize = 64;

/// A 16x16 RGB exemplar with some structure (for the options target, which fuzzes only options).
pub fn fixed_exemplar() -> Image {
    Image::from_fn(16, 16, 3, |x, y, c| {
        ((x * 7 + y * 13 + c * 5) % 17) as f32 / 16.0
    })
    .expect("16x16")
}

/// An exemplar of 1 to 24 pixels a side, 1, 3 or 4 channels, values in 0..=1.
pub fn exemplar(u: &mut Unstructured) -> Result<Image> {
    let w = u.int_in_range(1..=24)?;
    let h = u.int_in_range(1..=24)?;
    let c = *u.choose(&[1usize, 3, 4])?;
    let flat = u.ratio(1, 8)?;
    let mut data = Vec::with_capacity(w * h * c);
    for i in 0..w * h * c {
        let v = if flat && i >= c {
            data[i % c]
        } else {
            f32::from(u.arbitrary::<u8>()?) / 255.0
        };
        data.push(v);
    }
    Ok(Image::from_vec(w, h, c, data).expect("sizes in range"))
}

/// A whole number: small, or (wild) anything a JS number can hold whole.
fn count(u: &mut Unstructured, small: usize, values: Values) -> Result<usize> {
    if values == Values::Wild && u.ratio(1, 4)? {
        return Ok(*u.choose(&[0usize, 1, 2, 255, 4096, 1 << 20, usize::MAX >> 12])?);
    }
    u.int_in_range(0..=small)
}

fn size(u: &mut Unstructured, values: Values) -> Result<usize> {
    Ok(count(u, 40, values)?.max(1))
}

/// A finite number: near the usual range, or (wild) anything finite.
fn real(u: &mut Unstructured, usual: f32, values: Values) -> Result<f32> {
    if values == Values::Wild && u.ratio(1, 3)? {
        let v: f32 = u.arbitrary()?;
        return Ok(if v.is_finite() { v } else { f32::MAX });
    }
    Ok(usual * f32::from(u.int_in_range(0u8..=40)?) / 10.0)
}

fn seed(u: &mut Unstructured) -> Result<u64> {
    u.arbitrary::<u32>().map(u64::from)
}

fn search(u: &mut Unstructured) -> Result<Search> {
    let name = *u.choose(&["patchmatch", "kmeans-tree", "exact"])?;
    Ok(Search::from_name(name).expect("a known name"))
}

/// Builds one session type chosen by the input and steps it up to `steps` times. Errors are
/// fine (they are what a JS caller sees); a panic is the bug the fuzzer looks for.
pub fn drive(u: &mut Unstructured, ex: &Image, values: Values, steps: usize) -> Result<()> {
    let v = values;
    match u.int_in_range(0u8..=8)? {
        0 => {
            let n = u.int_in_range(0..=3)?;
            let mut sizes = Vec::new();
            for _ in 0..n {
                sizes.push(count(u, 16, v)?);
            }
            let o = optimization::Options {
                output_width: size(u, v)?,
                output_height: size(u, v)?,
                seed: seed(u)?,
                levels: count(u, 4, v)?,
                neighbourhood_sizes: sizes,
                iterations: count(u, 3, v)?,
                r: real(u, 0.8, v)?,
                mu: real(u, 1.0, v)?,
                m_step_mu: if u.arbitrary()? {
                    Some(real(u, 1.0, v)?)
                } else {
                    None
                },
                search: search(u)?,
                tileable: u.arbitrary()?,
                completeness: real(u, 1.0, v)?,
                histogram_matching: real(u, 1.0, v)?,
                energy: *u.choose(&[
                    optimization::Energy::from_name("pixels").expect("known"),
                    optimization::Energy::from_name("haar").expect("known"),
                    optimization::Energy::from_name("daubechies").expect("known"),
                ])?,
                wavelet_detail_weight: real(u, 4.0, v)?,
                start: optimization::Start::from_name(*u.choose(&["graphcut", "patches"])?)
                    .expect("known"),
                memory_budget_mib: BUDGET_MIB,
                channel_weights: (0..u.int_in_range(0..=5)?)
                    .map(|_| real(u, 1.0, v))
                    .collect::<Result<_>>()?,
            };
            if let Ok(mut s) = optimization::Session::new(ex, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
                let _ = s.output_full_size();
            }
        }
        1 => {
            let o = graphcut::Options {
                output_width: size(u, v)?,
                output_height: size(u, v)?,
                seed: seed(u)?,
                placement: graphcut::Placement::from_name(*u.choose(&[
                    "random",
                    "entire-patch",
                    "sub-patch",
                ])?)
                .expect("known"),
                k: real(u, 0.01, v)?,
                error_region: count(u, 16, v)?,
                refinement_patches: count(u, 4, v)?,
                gradient_cost: u.arbitrary()?,
                blend: graphcut::Blend::from_name(*u.choose(&["none", "feather", "spline"])?)
                    .expect("known"),
                transforms: graphcut::Transforms {
                    rotate: u.arbitrary()?,
                    mirror: u.arbitrary()?,
                    scales: [
                        if u.arbitrary()? {
                            Some(real(u, 0.5, v)?)
                        } else {
                            None
                        },
                        None,
                        None,
                        None,
                    ],
                    perspective: u.arbitrary()?,
                },
                tileable: u.arbitrary()?,
                memory_budget_mib: BUDGET_MIB,
            };
            if let Ok(mut s) = graphcut::Session::new(ex, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
                let _ = s.output();
            }
        }
        2 => {
            let kind = *u.choose(&FlowKind::ALL)?;
            let mut component = Component::new(kind, real(u, 2.0, v)?);
            component.period = real(u, 10.0, v)?;
            component.angle = real(u, 90.0, v)?;
            let Ok(spec) = FlowSpec::new(vec![component]) else {
                return Ok(());
            };
            let o = FlowOptions {
                output_width: size(u, v)?,
                output_height: size(u, v)?,
                frames: count(u, 3, v)?,
                lambda: real(u, 0.2, v)?,
                frame_sizes: vec![count(u, 12, v)?],
                frame_iterations: count(u, 2, v)?,
                seed: seed(u)?,
                search: search(u)?,
                r: real(u, 0.8, v)?,
                tileable: u.arbitrary()?,
                histogram_matching: real(u, 1.0, v)?,
                memory_budget_mib: BUDGET_MIB,
                sub_pixel: u.arbitrary()?,
            };
            if let Ok(mut s) = FlowSession::new(ex, FlowSource::Generator(spec), o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
                let _ = s.frame_image();
            }
        }
        3 => {
            let frames = u.int_in_range(1..=6)?;
            let (w, h) = (ex.width().min(12), ex.height().min(12));
            let mut rgba = Vec::with_capacity(w * h * 4 * frames);
            for t in 0..frames {
                for y in 0..h {
                    for x in 0..w {
                        let p = ex.pixel((x + t) % ex.width(), y);
                        let g = (p[0] * 255.0) as u8;
                        rgba.extend_from_slice(&[g, g / 2, 255 - g, 255]);
                    }
                }
            }
            let Ok(clip) = Volume::from_rgba_frames(w, h, frames, &rgba) else {
                return Ok(());
            };
            let pick = |u: &mut Unstructured, v| -> Result<Option<usize>> {
                Ok(if u.arbitrary()? {
                    Some(size(u, v)?)
                } else {
                    None
                })
            };
            let mode =
                video::Mode::from_name(*u.choose(&["loop", "offsets", "extend"])?).expect("known");
            let o = video::Options {
                mode,
                output_width: pick(u, v)?,
                output_height: pick(u, v)?,
                output_frames: pick(u, v)?,
                fixed_frames: if u.arbitrary()? {
                    Some(count(u, 4, v)?)
                } else {
                    None
                },
                transition_window: count(u, 8, v)?.max(3),
                transitions: count(u, 3, v)?,
                placement: video::Placement::from_name(
                    *u.choose(&["random", "entire-patch", "sub-patch", "matching"])?,
                )
                .expect("known"),
                seed: seed(u)?,
                k: real(u, 0.01, v)?.max(1e-6),
                refinement_patches: count(u, 2, v)?.min(1024),
                gradient_cost: u.arbitrary()?,
                blend: video::Blend::from_name(*u.choose(&["none", "feather", "spline"])?)
                    .expect("known"),
                memory_budget_mib: BUDGET_MIB,
            };
            if let Ok(mut s) = video::Session::new(clip, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
            }
        }
        4 => {
            let o = TileableOptions {
                overlap_x: if u.arbitrary()? {
                    Some(count(u, 12, v)?)
                } else {
                    None
                },
                overlap_y: if u.arbitrary()? {
                    Some(count(u, 12, v)?)
                } else {
                    None
                },
                memory_budget_mib: Some(BUDGET_MIB),
            };
            if let Ok(mut s) = TileableSession::new(ex, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
            }
        }
        5 => {
            let o = BrushOptions {
                weights: LabellingWeights {
                    nu: real(u, 1000.0, v)?,
                    k1: real(u, 0.5, v)?,
                    k2: real(u, 0.5, v)?,
                },
                margin: count(u, 16, v)?.min(256),
                poisson: u.arbitrary()?,
                memory_budget_mib: BUDGET_MIB,
            };
            if let Ok(mut brush) = LocalDeformation::new(ex, o) {
                let mask: Vec<bool> = (0..ex.pixel_count())
                    .map(|_| u.arbitrary().unwrap_or(false))
                    .collect();
                let dx = u.int_in_range(-30isize..=30)?;
                let dy = u.int_in_range(-30isize..=30)?;
                let _ = brush.stroke(&Stroke {
                    reference: ex,
                    mask: &mask,
                    dx,
                    dy,
                });
                brush.undo();
            }
        }
        6 => {
            let o = LayerOptions {
                output_width: size(u, v)?,
                output_height: size(u, v)?,
                patch_size: count(u, 16, v)?.clamp(8, 256),
                overlap: if u.arbitrary()? {
                    Some(count(u, 8, v)?.clamp(1, 127))
                } else {
                    None
                },
                search: if u.arbitrary()? {
                    LayerSearch::Qtp
                } else {
                    LayerSearch::Exhaustive
                },
                keep: count(u, 8, v)?.clamp(1, 256),
                placement: *u.choose(&[
                    LayerPlacement::Logistic,
                    LayerPlacement::Random,
                    LayerPlacement::Best,
                ])?,
                tolerance: real(u, 0.3, v)?,
                seed: seed(u)?,
                memory_budget_mib: BUDGET_MIB,
            };
            let n = o.output_width.saturating_mul(o.output_height);
            if n > 1 << 16 {
                return Ok(());
            }
            let layout = vec![0u8; n];
            let layer = Layer {
                texture: ex.clone(),
                deformations: vec![],
            };
            if let Ok(mut s) = LayerDesign::new(&[layer], &layout, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
            }
        }
        _ => {
            let o = FeatureOptions {
                output_width: size(u, v)?.min(8192),
                output_height: size(u, v)?.min(8192),
                placement: FeaturePlacement::from_name(*u.choose(&["graphcut", "scan"])?)
                    .expect("known"),
                seam_feature_weight: real(u, 1.0, v)?,
                patch_size: if u.arbitrary()? {
                    Some(count(u, 24, v)?.clamp(1, 4096))
                } else {
                    None
                },
                overlap: if u.arbitrary()? {
                    Some(count(u, 8, v)?.clamp(1, 4096))
                } else {
                    None
                },
                feature_weight: real(u, 0.5, v)?,
                warp: u.arbitrary()?,
                tolerance: real(u, 0.1, v)?,
                feature_candidates: if u.arbitrary()? {
                    Some(count(u, 64, v)?.clamp(1, 100_000))
                } else {
                    None
                },
                extra_inputs: vec![],
                detect: DetectOptions {
                    kind: *u.choose(&[
                        FeatureKind::Edges,
                        FeatureKind::Ridges,
                        FeatureKind::Both,
                    ])?,
                    percentile: real(u, 0.9, v)?,
                    alpha: real(u, 0.3, v)?,
                },
                seed: seed(u)?,
                memory_budget_mib: BUDGET_MIB,
            };
            if let Ok(mut s) = FeatureSynthesis::new(ex, None, o) {
                for _ in 0..steps {
                    if s.is_done() || s.step().is_err() {
                        break;
                    }
                }
            }
        }
    }
    Ok(())
}
