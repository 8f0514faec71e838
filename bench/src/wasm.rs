//! The hand-over to and from scripts/compare_wasm.mjs: the plan (prepared exemplars, size, seeds,
//! how to build each session) goes out, the wasm timings come back. The results are checked
//! against this run's exemplars so stale or mismatched figures are never merged.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use crate::args::Args;
use crate::methods::Method;
use crate::prepare::Exemplar;

/// Writes `out/plan.json` and returns its path.
pub fn write_plan(args: &Args, exemplars: &[Exemplar]) -> Result<PathBuf, String> {
    let absolute = |p: &Path| std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
    let methods: Vec<Value> = args
        .methods
        .iter()
        .filter_map(|m| {
            let mut s = m.wasm_session()?;
            s["name"] = m.name().into();
            Some(s)
        })
        .collect();
    let plan = json!({
        "size": [args.width, args.height],
        "seeds": args.seeds,
        "threads": args.threads,
        "methods": methods,
        "exemplars": exemplars.iter().map(|e| json!({
            "name": e.name,
            "png": absolute(&e.png_path),
            "hash": e.png_hash,
        })).collect::<Vec<_>>(),
    });
    let path = args.out.join("plan.json");
    let text = serde_json::to_string_pretty(&plan).expect("a JSON value serialises");
    std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(absolute(&path))
}

#[derive(Debug, Clone, Deserialize, Serialize)]
pub struct WasmResults {
    pub node: String,
    pub wasm_bytes: Option<u64>,
    pub size: (usize, usize),
    /// The wasm thread pool's size (1: the single-threaded module).
    #[serde(default = "one")]
    pub threads: usize,
    pub runs: Vec<WasmRun>,
}

fn one() -> usize {
    1
}

#[derive(Debug, Clone, Deserialize, Serialize)]
pub struct WasmRun {
    pub exemplar: String,
    /// Hash of the PNG bytes the wasm Exemplar was made from.
    pub exemplar_hash: String,
    pub method: String,
    pub seed: u64,
    pub total_ms: Option<f64>,
    pub steps: Option<usize>,
    pub max_step_ms: Option<f64>,
    /// Hash of the RGBA8 output (`renderInto`), to compare with the native output.
    pub output_hash: Option<String>,
    pub error: Option<String>,
}

pub fn load(path: &Path, args: &Args, exemplars: &[Exemplar]) -> Result<WasmResults, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the wasm results {}: {e}", path.display()))?;
    let results: WasmResults = serde_json::from_str(&text)
        .map_err(|e| format!("the wasm results {} are malformed: {e}", path.display()))?;
    let stale = |why: String| {
        Err(format!(
            "the wasm results {} do not belong to this run ({why}); rerun scripts/compare_wasm.mjs",
            path.display()
        ))
    };
    if results.size != (args.width, args.height) {
        return stale(format!(
            "output size {}x{}, this run {}x{}",
            results.size.0, results.size.1, args.width, args.height
        ));
    }
    if results.threads != args.threads {
        return stale(format!(
            "{} thread(s), this run {}",
            results.threads, args.threads
        ));
    }
    for run in &results.runs {
        match exemplars.iter().find(|e| e.name == run.exemplar) {
            Some(e) if e.png_hash == run.exemplar_hash => {}
            Some(_) => return stale(format!("exemplar {} has other pixels", run.exemplar)),
            None => return stale(format!("unknown exemplar {}", run.exemplar)),
        }
    }
    Ok(results)
}

impl WasmResults {
    pub fn find(&self, exemplar: &str, method: Method, seed: u64) -> Option<&WasmRun> {
        self.runs
            .iter()
            .find(|r| r.exemplar == exemplar && r.method == method.name() && r.seed == seed)
    }
}
