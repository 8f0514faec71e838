//! The results: the two tables printed to the terminal (figures, then ratios to the peer), and the
//! same figures with every per-seed value in results.json and results.tsv.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::methods::Method;
use crate::runner::{MethodRuns, RunError};
use crate::stats::{self, Cell, Ratios, RunFigures};
use crate::table::{self, NONE, Table};

/// What the figures mean; printed under the tables and stored in the JSON.
pub const NOTES: [&str; 8] = [
    "time: wall time of session construction plus all steps (decoding and file IO excluded), median over seeds; native is this binary (release), wasm is the package in Node (the threaded module when threads > 1); texsynth and the peer get the same number of threads",
    "ms/step: median over seeds of time / steps; max step: the longest single step of any seed (a page's worst frame); the peer runs as one call, so it has no steps (—)",
    "quality: mean over seeds of the library's metrics on the 8-bit output; lower is better for coherence, completeness and histogram",
    "ratios: method / peer on the same exemplar (time: ours native or wasm over the peer's native time on as many threads); below 1 is better; summary rows are geometric means",
    "goal: at least 3x faster than the peer (time ratio <= 0.33) with coherence and completeness ratios <= 1",
    "summary rows of the figures table are arithmetic means over exemplars (max for max step)",
    "flat: the detail metric, the share of output pixels whose 7x7 luminance standard deviation is below the exemplar's 10th percentile of it (the exemplar itself scores about 0.10; a washed-out output up to 1); texture optimization matches the output's histogram to the exemplar's, so its histogram distance is near 0 by construction",
    "broken: curve ends per 1000 curve pixels of the feature map detected on the output, above the exemplar's own (Wu & Yu's curves; lower is better); at seams: the same on the carried map (each output pixel carries the exemplar's curve at the pixel it shows), the curves seams cut, for graph cut without deformations and feature-guided synthesis",
];

#[derive(Serialize)]
pub struct Machine {
    pub cores: usize,
    pub cpu: String,
    pub os: &'static str,
    pub arch: &'static str,
}

impl Machine {
    pub fn detect() -> Machine {
        let cpu = std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(|s| {
                s.lines()
                    .find(|l| l.starts_with("model name"))
                    .and_then(|l| l.split_once(':'))
                    .map(|(_, v)| v.trim().to_string())
            })
            .unwrap_or_else(|| "unknown".into());
        Machine {
            cores: std::thread::available_parallelism().map_or(1, |n| n.get()),
            cpu,
            os: std::env::consts::OS,
            arch: std::env::consts::ARCH,
        }
    }
}

#[derive(Serialize)]
pub struct ExemplarInfo {
    pub name: String,
    pub source: PathBuf,
    pub original_size: (u32, u32),
    pub size: (usize, usize),
    pub png: PathBuf,
    pub png_hash: String,
    pub contact_sheet: PathBuf,
    /// Left to right on the contact sheet.
    pub contact_sheet_order: Vec<String>,
}

#[derive(Serialize)]
pub struct Entry {
    pub exemplar: String,
    pub method: &'static str,
    pub figures: Cell,
    /// None for the peer itself, or when the peer did not run.
    pub ratios: Option<Ratios>,
    pub goal_native: Option<bool>,
    pub goal_wasm: Option<bool>,
    pub runs: Vec<RunFigures>,
    pub errors: Vec<RunError>,
}

#[derive(Serialize)]
pub struct Summary {
    pub method: &'static str,
    pub exemplars: usize,
    pub figures: Cell,
    pub ratios: Option<Ratios>,
    pub goal_native_met: usize,
    pub goal_wasm_met: usize,
}

#[derive(Serialize)]
pub struct Report {
    pub command: Vec<String>,
    pub machine: Machine,
    pub node: Option<String>,
    pub wasm_bytes: Option<u64>,
    pub dir: PathBuf,
    pub output_size: (usize, usize),
    pub seeds: Vec<u64>,
    /// Threads given to texsynth (native rayon pool, wasm thread pool) and to the peer alike.
    pub threads: usize,
    pub methods: Vec<&'static str>,
    pub crop: Option<(usize, usize)>,
    pub exemplar_size: usize,
    pub notes: Vec<&'static str>,
    pub exemplars: Vec<ExemplarInfo>,
    pub skipped: Vec<(PathBuf, String)>,
    pub results: Vec<Entry>,
    pub summary: Vec<Summary>,
}

/// Per exemplar, per method: the cell, and the ratios to the peer's cell on the same exemplar.
pub fn entries(exemplar: &str, all: Vec<MethodRuns>) -> Vec<Entry> {
    let cells: Vec<Cell> = all.iter().map(|m| stats::cell(&m.runs)).collect();
    let peer = all
        .iter()
        .position(|m| m.method.is_peer())
        .map(|i| &cells[i]);
    all.into_iter()
        .zip(cells.iter())
        .map(|(m, cell)| {
            let ratios = peer
                .filter(|_| !m.method.is_peer())
                .map(|p| stats::ratios(cell, p));
            Entry {
                exemplar: exemplar.to_string(),
                method: m.method.name(),
                figures: cell.clone(),
                goal_native: ratios.as_ref().and_then(|r| stats::meets_goal(r, false)),
                goal_wasm: ratios.as_ref().and_then(|r| stats::meets_goal(r, true)),
                ratios,
                runs: m.runs,
                errors: m.errors,
            }
        })
        .collect()
}

pub fn summaries(methods: &[Method], results: &[Entry]) -> Vec<Summary> {
    methods
        .iter()
        .map(|m| {
            let mine: Vec<&Entry> = results.iter().filter(|e| e.method == m.name()).collect();
            let cells: Vec<&Cell> = mine.iter().map(|e| &e.figures).collect();
            let ratios: Vec<&Ratios> = mine.iter().filter_map(|e| e.ratios.as_ref()).collect();
            Summary {
                method: m.name(),
                exemplars: mine.len(),
                figures: stats::summary(&cells),
                ratios: (!ratios.is_empty()).then(|| stats::ratio_summary(&ratios)),
                goal_native_met: mine.iter().filter(|e| e.goal_native == Some(true)).count(),
                goal_wasm_met: mine.iter().filter(|e| e.goal_wasm == Some(true)).count(),
            }
        })
        .collect()
}

fn figure_cells(exemplar: &str, method: &str, c: &Cell) -> Vec<String> {
    let same = match c.wasm_identical {
        Some(true) => "same",
        Some(false) => "differ",
        None => NONE,
    };
    vec![
        exemplar.to_string(),
        method.to_string(),
        table::ms(c.native_ms),
        table::ms(c.wasm_ms),
        table::count(c.steps),
        table::ms(c.ms_per_step),
        table::ms(c.max_step_ms),
        table::metric(c.coherence),
        table::metric(c.completeness),
        table::metric(c.histogram),
        table::flat(c.flat),
        c.broken.map_or(NONE.into(), |b| format!("{b:.1}")),
        c.seams.map_or(NONE.into(), |b| format!("{b:.1}")),
        same.to_string(),
    ]
}

fn ratio_cells(exemplar: &str, method: &str, r: &Ratios, goal: [String; 2]) -> Vec<String> {
    let [native, wasm] = goal;
    vec![
        exemplar.to_string(),
        method.to_string(),
        table::ratio(r.native_time),
        table::ratio(r.wasm_time),
        table::ratio(r.coherence),
        table::ratio(r.completeness),
        table::ratio(r.histogram),
        table::ratio(r.flat),
        native,
        wasm,
    ]
}

fn yes_no(v: Option<bool>) -> String {
    match v {
        Some(true) => "yes".into(),
        Some(false) => "no".into(),
        None => NONE.into(),
    }
}

/// The text printed at the end of a run.
pub fn render(report: &Report) -> String {
    let mut out = String::new();
    let (w, h) = report.output_size;
    let _ = writeln!(
        out,
        "\n{w}x{h} output, seeds {:?}, {} thread(s), {} exemplars from {}; {} cores ({}), node {}",
        report.seeds,
        report.threads,
        report.exemplars.len(),
        report.dir.display(),
        report.machine.cores,
        report.machine.cpu,
        report.node.as_deref().unwrap_or("not run"),
    );
    let mut t = Table::new(
        &[
            "exemplar",
            "method",
            "native ms",
            "wasm ms",
            "steps",
            "ms/step",
            "max step",
            "coherence",
            "completeness",
            "histogram",
            "flat",
            "broken",
            "at seams",
            "wasm px",
        ],
        2,
    );
    let mut last = "";
    for e in &report.results {
        if !last.is_empty() && last != e.exemplar {
            t.rule();
        }
        last = &e.exemplar;
        t.row(figure_cells(&e.exemplar, e.method, &e.figures));
    }
    t.rule();
    for s in &report.summary {
        t.row(figure_cells(
            &format!("mean of {}", s.exemplars),
            s.method,
            &s.figures,
        ));
    }
    let _ = writeln!(
        out,
        "\nFigures (times in ms; quality lower is better; wasm px: wasm output identical to native)\n{}",
        t.render()
    );

    let compared: Vec<&Entry> = report
        .results
        .iter()
        .filter(|e| e.ratios.is_some())
        .collect();
    if compared.is_empty() {
        let _ = writeln!(out, "\nNo ratios: the peer was not run.");
    } else {
        let mut t = Table::new(
            &[
                "exemplar",
                "method",
                "time native",
                "time wasm",
                "coherence",
                "completeness",
                "histogram",
                "flat",
                "goal native",
                "goal wasm",
            ],
            2,
        );
        let mut last = "";
        for e in &compared {
            if !last.is_empty() && last != e.exemplar {
                t.rule();
            }
            last = &e.exemplar;
            let goal = [yes_no(e.goal_native), yes_no(e.goal_wasm)];
            t.row(ratio_cells(
                &e.exemplar,
                e.method,
                e.ratios.as_ref().expect("filtered"),
                goal,
            ));
        }
        t.rule();
        for s in report.summary.iter().filter(|s| s.ratios.is_some()) {
            // "k/n" exemplars where the goal is met; "—" when that time was not measured.
            let met = |k: usize, measured: bool| {
                if measured {
                    format!("{k}/{}", s.exemplars)
                } else {
                    NONE.into()
                }
            };
            let r = s.ratios.as_ref().expect("filtered");
            let goal = [
                met(s.goal_native_met, r.native_time.is_some()),
                met(s.goal_wasm_met, r.wasm_time.is_some()),
            ];
            t.row(ratio_cells(
                &format!("geomean of {}", s.exemplars),
                s.method,
                r,
                goal,
            ));
        }
        let _ = writeln!(
            out,
            "\nRatios method / peer (below 1 is better; goal: time <= 0.33 and coherence, completeness <= 1)\n{}",
            t.render()
        );
    }

    let errors: Vec<String> = report
        .results
        .iter()
        .flat_map(|e| {
            e.errors.iter().map(move |r| {
                format!(
                    "  {} {} seed {} ({}): {}",
                    e.exemplar, e.method, r.seed, r.platform, r.message
                )
            })
        })
        .collect();
    if !errors.is_empty() {
        let _ = writeln!(out, "\nFailed runs:\n{}", errors.join("\n"));
    }
    for (path, why) in &report.skipped {
        let _ = writeln!(out, "skipped {}: {why}", path.display());
    }
    let _ = writeln!(out, "\nNotes:");
    for n in NOTES {
        let _ = writeln!(out, "- {n}");
    }
    out
}

/// results.json (everything) and results.tsv (one line per run and platform).
pub fn write_files(report: &Report, dir: &Path) -> Result<(PathBuf, PathBuf), String> {
    let json = dir.join("results.json");
    let text = serde_json::to_string_pretty(report).map_err(|e| e.to_string())?;
    std::fs::write(&json, text).map_err(|e| format!("cannot write {}: {e}", json.display()))?;

    let tsv = dir.join("results.tsv");
    let mut text = String::from(
        "exemplar\tmethod\tseed\tplatform\ttotal_ms\tsteps\tmax_step_ms\tcoherence\tcompleteness\thistogram\tflat\tbroken\tseams\toutput_hash\n",
    );
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for e in &report.results {
        for r in &e.runs {
            let _ = writeln!(
                text,
                "{}\t{}\t{}\tnative\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}",
                e.exemplar,
                e.method,
                r.seed,
                r.native_ms,
                r.steps,
                r.max_step_ms,
                r.coherence,
                r.completeness,
                r.histogram,
                r.flat,
                r.broken,
                opt(r.seams),
                r.output_hash
            );
            if r.wasm_ms.is_some() {
                // The quality columns stay empty: they were computed on the native output (the
                // wasm output's identity with it is in results.json, wasm_identical).
                let _ = writeln!(
                    text,
                    "{}\t{}\t{}\twasm\t{}\t{}\t{}\t\t\t\t\t\t\t",
                    e.exemplar,
                    e.method,
                    r.seed,
                    opt(r.wasm_ms),
                    r.wasm_steps.map_or(String::new(), |s| s.to_string()),
                    opt(r.wasm_max_step_ms)
                );
            }
        }
    }
    std::fs::write(&tsv, text).map_err(|e| format!("cannot write {}: {e}", tsv.display()))?;
    Ok((json, tsv))
}
