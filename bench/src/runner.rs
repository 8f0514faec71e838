//! Runs every method and seed on one exemplar: first all the timed syntheses, one after another
//! on the asked number of threads (nothing else of ours running), then the quality metrics of all outputs on every
//! core (untimed), then the wasm figures of the same runs are attached.

use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde::Serialize;
use texsynth::core::{Image, from_rgba8, to_rgba8};
use texsynth::methods::features::DetectOptions;
use texsynth::methods::features::broken::broken_features;
use texsynth::methods::quality::{Quality, quality};

use crate::methods::{self, Method, Run};
use crate::peer;
use crate::prepare::{Exemplar, fnv1a};
use crate::stats::RunFigures;
use crate::threads::Pool;
use crate::wasm::WasmResults;

#[derive(Debug, Clone, Serialize)]
pub struct RunError {
    pub seed: u64,
    pub platform: &'static str,
    pub message: String,
}

/// Everything measured for one (exemplar, method).
pub struct MethodRuns {
    pub method: Method,
    pub runs: Vec<RunFigures>,
    pub errors: Vec<RunError>,
    /// The first seed's output, for the contact sheet.
    pub first_output: Option<Image>,
    pub first_ms: Option<f64>,
}

/// A finished synthesis before scoring. The output is kept as the RGBA8 a user gets (canvas,
/// PNG): it is smaller, and the peer's output is 8-bit too, so all are scored alike.
struct Timed {
    method: usize,
    seed: u64,
    run: Run,
    rgba: Vec<u8>,
}

pub fn run_exemplar(
    exemplar: &Exemplar,
    methods: &[Method],
    seeds: &[u64],
    size: (usize, usize),
    pool: &Pool,
    threads: usize,
    wasm: Option<&WasmResults>,
) -> Vec<MethodRuns> {
    let (width, height) = size;
    let mut errors: Vec<Vec<RunError>> = vec![Vec::new(); methods.len()];
    let mut timed = Vec::new();
    for (mi, &method) in methods.iter().enumerate() {
        for &seed in seeds {
            let result = if method.is_peer() {
                peer::run(&exemplar.image, size, seed, threads)
            } else {
                pool.install(|| methods::run_ours(method, &exemplar.image, width, height, seed))
            };
            match result {
                Ok(run) => {
                    eprintln!(
                        "  {:<16} seed {seed:<3} {:>9.1} ms  {} steps",
                        method.name(),
                        run.total_ms,
                        run.steps
                    );
                    let rgba = to_rgba8(&run.output);
                    timed.push(Timed {
                        method: mi,
                        seed,
                        run,
                        rgba,
                    });
                }
                Err(message) => {
                    eprintln!("  {:<16} seed {seed:<3} failed: {message}", method.name());
                    errors[mi].push(RunError {
                        seed,
                        platform: "native",
                        message,
                    });
                }
            }
        }
    }

    let scores = score_all(&exemplar.image, &timed);
    let mut out: Vec<MethodRuns> = methods
        .iter()
        .zip(errors)
        .map(|(&method, errors)| MethodRuns {
            method,
            runs: Vec::new(),
            errors,
            first_output: None,
            first_ms: None,
        })
        .collect();
    for (t, score) in timed.into_iter().zip(scores) {
        let m = &mut out[t.method];
        let (q, broken) = match score {
            Ok(q) => q,
            Err(message) => {
                m.errors.push(RunError {
                    seed: t.seed,
                    platform: "quality",
                    message,
                });
                continue;
            }
        };
        let output_hash = fnv1a(&t.rgba);
        let mut figures = RunFigures {
            seed: t.seed,
            native_ms: t.run.total_ms,
            steps: t.run.steps,
            max_step_ms: t.run.max_step_ms,
            coherence: q.coherence,
            completeness: q.completeness,
            histogram: q.histogram,
            flat: q.flat,
            broken,
            seams: t.run.seams,
            output_hash,
            wasm_ms: None,
            wasm_steps: None,
            wasm_max_step_ms: None,
            wasm_identical: None,
        };
        if let Some(w) = wasm.and_then(|w| w.find(&exemplar.name, m.method, t.seed)) {
            match &w.error {
                Some(message) => m.errors.push(RunError {
                    seed: t.seed,
                    platform: "wasm",
                    message: message.clone(),
                }),
                None => {
                    figures.wasm_ms = w.total_ms;
                    figures.wasm_steps = w.steps;
                    figures.wasm_max_step_ms = w.max_step_ms;
                    figures.wasm_identical =
                        w.output_hash.as_ref().map(|h| *h == figures.output_hash);
                }
            }
        }
        if m.first_output.is_none() && t.seed == seeds[0] {
            m.first_output = Some(t.run.output);
            m.first_ms = Some(t.run.total_ms);
        }
        m.runs.push(figures);
    }
    out
}

/// An output's quality and broken-feature count, or why it could not be scored.
type Score = Result<(Quality, f64), String>;

/// The quality of every output, on all cores: the exact nearest-patch search is the slow part
/// of the whole benchmark, and it is not timed.
fn score_all(exemplar: &Image, timed: &[Timed]) -> Vec<Score> {
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(timed.len().max(1));
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Score>>> = Mutex::new(vec![None; timed.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(t) = timed.get(i) else { break };
                    let (w, h) = (t.run.output.width(), t.run.output.height());
                    let q = from_rgba8(w, h, &t.rgba)
                        .and_then(|out| {
                            let broken = broken_features(exemplar, &out, DetectOptions::default())?;
                            Ok((quality(exemplar, &out)?, broken))
                        })
                        .map_err(|e| e.to_string());
                    results.lock().expect("no thread panics holding the lock")[i] = Some(q);
                }
            });
        }
    });
    results
        .into_inner()
        .expect("no thread panicked")
        .into_iter()
        .map(|q| q.expect("every output was scored"))
        .collect()
}
