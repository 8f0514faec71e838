//! The methods compared, and one timed native run of each of texsynth's own. Each runs with the
//! library's default options (what a user gets without tuning), only size and seed set.

use std::time::Instant;

use serde_json::{Value, json};
use texsynth::core::Image;
use texsynth::methods::{features, graphcut, optimization};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Texture optimization (Kwatra et al. 2005), default PatchMatch search.
    Optimization,
    /// Graph-cut textures (Kwatra et al. 2003), one per placement mode.
    GraphcutRandom,
    GraphcutEntire,
    GraphcutSub,
    /// Feature-guided synthesis (Wu & Yu 2004).
    Features,
    /// The texture-synthesis crate (see peer.rs).
    Peer,
}

impl Method {
    /// Canonical order: the table, the contact sheet and the files list methods in this order.
    pub const ALL: [Method; 6] = [
        Method::Optimization,
        Method::GraphcutRandom,
        Method::GraphcutEntire,
        Method::GraphcutSub,
        Method::Features,
        Method::Peer,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Optimization => "optimization",
            Method::GraphcutRandom => "graphcut-random",
            Method::GraphcutEntire => "graphcut-entire",
            Method::GraphcutSub => "graphcut-sub",
            Method::Features => "features",
            Method::Peer => "peer",
        }
    }

    pub fn from_name(name: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == name)
    }

    pub fn is_peer(self) -> bool {
        self == Method::Peer
    }

    /// How scripts/compare_wasm.mjs builds the same session from the wasm package: the class and
    /// the options beyond size and seed. None for the peer, which only runs natively. Kept here so
    /// the native and the wasm runs cannot drift apart.
    pub fn wasm_session(self) -> Option<Value> {
        let placement = |p: graphcut::Placement| json!({ "class": "GraphcutTextures", "options": { "placement": p.name() } });
        match self {
            Method::Optimization => Some(json!({ "class": "TextureOptimization", "options": {} })),
            Method::GraphcutRandom => Some(placement(graphcut::Placement::Random)),
            Method::GraphcutEntire => Some(placement(graphcut::Placement::EntirePatch)),
            Method::GraphcutSub => Some(placement(graphcut::Placement::SubPatch)),
            Method::Features => Some(json!({ "class": "FeatureSynthesis", "options": {} })),
            Method::Peer => None,
        }
    }
}

/// One timed synthesis. `steps` is 0 for the peer, whose run is one opaque call.
pub struct Run {
    pub total_ms: f64,
    pub steps: usize,
    pub max_step_ms: f64,
    pub output: Image,
    /// The broken-feature count at seams (on the carried feature map, `features::carried`), for
    /// the patch-based methods whose canvas says which exemplar pixel each output pixel shows:
    /// graph cut (without deformed sources) and feature-guided synthesis. Not timed.
    pub seams: Option<f64>,
}

/// Runs one of texsynth's methods: the timed part is session construction (validation, pyramids,
/// planning) plus every step, as a user's loop would run them; fetching the output is not timed.
pub fn run_ours(
    method: Method,
    exemplar: &Image,
    width: usize,
    height: usize,
    seed: u64,
) -> Result<Run, String> {
    let err = |e: texsynth::core::Error| e.to_string();
    match method {
        Method::Optimization => {
            let options = optimization::Options {
                output_width: width,
                output_height: height,
                seed,
                ..optimization::Options::default()
            };
            let start = Instant::now();
            let mut session = optimization::Session::new(exemplar, options).map_err(err)?;
            let (steps, max_step_ms) = step_all(|| {
                let e = session.step()?;
                Ok(e.kind == optimization::EventKind::Done)
            })?;
            let total_ms = ms(start);
            let output = session.output_full_size().map_err(err)?;
            Ok(Run {
                total_ms,
                steps,
                max_step_ms,
                output,
                seams: None,
            })
        }
        Method::GraphcutRandom | Method::GraphcutEntire | Method::GraphcutSub => {
            let placement = match method {
                Method::GraphcutRandom => graphcut::Placement::Random,
                Method::GraphcutEntire => graphcut::Placement::EntirePatch,
                _ => graphcut::Placement::SubPatch,
            };
            let options = graphcut::Options {
                output_width: width,
                output_height: height,
                seed,
                placement,
                ..graphcut::Options::default()
            };
            let start = Instant::now();
            let mut session = graphcut::Session::new(exemplar, options).map_err(err)?;
            let (steps, max_step_ms) = step_all(|| Ok(session.step()?.done))?;
            let total_ms = ms(start);
            let output = session.output().map_err(err)?;
            let seams = graphcut_seams(exemplar, session.synthesis()).map_err(err)?;
            Ok(Run {
                total_ms,
                steps,
                max_step_ms,
                output,
                seams,
            })
        }
        Method::Features => {
            let options = features::FeatureOptions {
                output_width: width,
                output_height: height,
                seed,
                ..features::FeatureOptions::default()
            };
            let start = Instant::now();
            let mut session =
                features::FeatureSynthesis::new(exemplar, None, options).map_err(err)?;
            let (steps, max_step_ms) = step_all(|| Ok(session.step()?.done))?;
            let total_ms = ms(start);
            Ok(Run {
                total_ms,
                steps,
                max_step_ms,
                output: session.image().clone(),
                seams: Some(session.carried_broken()),
            })
        }
        Method::Peer => unreachable!("the peer runs through peer::run"),
    }
}

/// Graph cut's count at seams: the exemplar's detected curves carried through its canvas (None
/// with deformed sources, which have no map).
fn graphcut_seams(
    exemplar: &Image,
    synthesis: &graphcut::synthesis::Synthesis,
) -> texsynth::core::Result<Option<f64>> {
    if synthesis.sources.len() != 1 {
        return Ok(None);
    }
    let map = features::detect(exemplar, features::DetectOptions::default())?;
    let carried = features::carried::carried_mask(synthesis, &[&map.mask]);
    let (w, h) = (synthesis.canvas.width, synthesis.canvas.height);
    Ok(Some(features::broken::carried_broken(
        &carried,
        (w, h),
        &map.mask,
        (map.width, map.height),
    )))
}

/// Calls `step` until it reports done; returns the number of steps and the longest one in ms.
fn step_all(
    mut step: impl FnMut() -> texsynth::core::Result<bool>,
) -> Result<(usize, f64), String> {
    let (mut steps, mut max) = (0, 0.0f64);
    loop {
        let t = Instant::now();
        let done = step().map_err(|e| e.to_string())?;
        max = max.max(ms(t));
        steps += 1;
        if done {
            return Ok((steps, max));
        }
    }
}

pub fn ms(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1e3
}
