//! From raw runs to the figures of the table: per (exemplar, method) the median wall time and mean
//! quality over seeds, per method a summary over exemplars, and the ratios to the peer.

use serde::Serialize;

/// One run's figures (native timings, quality of the native output, wasm timings if measured).
#[derive(Debug, Clone, Serialize)]
pub struct RunFigures {
    pub seed: u64,
    pub native_ms: f64,
    /// 0 for the peer (no visible steps).
    pub steps: usize,
    pub max_step_ms: f64,
    pub coherence: f64,
    pub completeness: f64,
    pub histogram: f64,
    /// Flat fraction (the detail metric): about 0.10 for the exemplar itself.
    pub flat: f64,
    /// Broken-feature count (Wu & Yu's curves): curve ends per 1000 curve pixels above the
    /// exemplar's own; lower is better.
    pub broken: f64,
    /// The same count at seams, on the carried feature map (graph cut and feature-guided only).
    pub seams: Option<f64>,
    /// FNV-1a of the output's RGBA8 pixels (native).
    pub output_hash: String,
    pub wasm_ms: Option<f64>,
    pub wasm_steps: Option<usize>,
    pub wasm_max_step_ms: Option<f64>,
    /// Whether the wasm build produced exactly the native output's pixels.
    pub wasm_identical: Option<bool>,
}

/// The figures of one (exemplar, method) over its seeds.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Cell {
    pub native_ms: Option<f64>,
    pub wasm_ms: Option<f64>,
    pub steps: Option<f64>,
    pub ms_per_step: Option<f64>,
    pub max_step_ms: Option<f64>,
    pub coherence: Option<f64>,
    pub completeness: Option<f64>,
    pub histogram: Option<f64>,
    pub flat: Option<f64>,
    pub broken: Option<f64>,
    pub seams: Option<f64>,
    pub wasm_identical: Option<bool>,
}

/// A method's figures divided by the peer's on the same exemplar: below 1 is better everywhere.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Ratios {
    pub native_time: Option<f64>,
    pub wasm_time: Option<f64>,
    pub coherence: Option<f64>,
    pub completeness: Option<f64>,
    pub histogram: Option<f64>,
    pub flat: Option<f64>,
}

/// The goal of the issue: at least 3x faster than the peer with coherence and completeness no
/// worse. Judged on the native time (`wasm` false) or the wasm time.
pub fn meets_goal(r: &Ratios, wasm: bool) -> Option<bool> {
    let time = if wasm { r.wasm_time? } else { r.native_time? };
    Some(time <= 1.0 / 3.0 && r.coherence? <= 1.0 && r.completeness? <= 1.0)
}

pub fn median(values: &[f64]) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    })
}

pub fn mean(values: &[f64]) -> Option<f64> {
    (!values.is_empty()).then(|| values.iter().sum::<f64>() / values.len() as f64)
}

/// The mean for ratios: a method twice as fast on one image and twice as slow on another is even.
pub fn geomean(values: &[f64]) -> Option<f64> {
    if values.is_empty() || values.iter().any(|&v| v <= 0.0) {
        return None;
    }
    Some((values.iter().map(|v| v.ln()).sum::<f64>() / values.len() as f64).exp())
}

/// Median wall time and mean quality over the seeds that ran.
pub fn cell(runs: &[RunFigures]) -> Cell {
    let of = |f: fn(&RunFigures) -> Option<f64>| runs.iter().filter_map(f).collect::<Vec<_>>();
    let per_step = of(|r| (r.steps > 0).then(|| r.native_ms / r.steps as f64));
    let steps = of(|r| (r.steps > 0).then_some(r.steps as f64));
    let identical: Vec<bool> = runs.iter().filter_map(|r| r.wasm_identical).collect();
    Cell {
        native_ms: median(&of(|r| Some(r.native_ms))),
        wasm_ms: median(&of(|r| r.wasm_ms)),
        steps: median(&steps),
        ms_per_step: median(&per_step),
        max_step_ms: of(|r| (r.steps > 0).then_some(r.max_step_ms))
            .into_iter()
            .reduce(f64::max),
        coherence: mean(&of(|r| Some(r.coherence))),
        completeness: mean(&of(|r| Some(r.completeness))),
        histogram: mean(&of(|r| Some(r.histogram))),
        flat: mean(&of(|r| Some(r.flat))),
        broken: mean(&of(|r| Some(r.broken))),
        seams: mean(&of(|r| r.seams)),
        wasm_identical: (!identical.is_empty()).then(|| identical.iter().all(|&b| b)),
    }
}

/// A method's summary over exemplars: arithmetic means (max for the longest step).
pub fn summary(cells: &[&Cell]) -> Cell {
    let of =
        |f: fn(&Cell) -> Option<f64>| mean(&cells.iter().filter_map(|c| f(c)).collect::<Vec<_>>());
    let identical: Vec<bool> = cells.iter().filter_map(|c| c.wasm_identical).collect();
    Cell {
        native_ms: of(|c| c.native_ms),
        wasm_ms: of(|c| c.wasm_ms),
        steps: of(|c| c.steps),
        ms_per_step: of(|c| c.ms_per_step),
        max_step_ms: cells.iter().filter_map(|c| c.max_step_ms).reduce(f64::max),
        coherence: of(|c| c.coherence),
        completeness: of(|c| c.completeness),
        histogram: of(|c| c.histogram),
        flat: of(|c| c.flat),
        broken: of(|c| c.broken),
        seams: of(|c| c.seams),
        wasm_identical: (!identical.is_empty()).then(|| identical.iter().all(|&b| b)),
    }
}

pub fn ratios(ours: &Cell, peer: &Cell) -> Ratios {
    let div = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => Some(a / b),
        _ => None,
    };
    Ratios {
        native_time: div(ours.native_ms, peer.native_ms),
        wasm_time: div(ours.wasm_ms, peer.native_ms),
        coherence: div(ours.coherence, peer.coherence),
        completeness: div(ours.completeness, peer.completeness),
        histogram: div(ours.histogram, peer.histogram),
        flat: div(ours.flat, peer.flat),
    }
}

/// A method's ratios over exemplars: geometric means of the per-exemplar ratios.
pub fn ratio_summary(all: &[&Ratios]) -> Ratios {
    let of = |f: fn(&Ratios) -> Option<f64>| {
        geomean(&all.iter().filter_map(|r| f(r)).collect::<Vec<_>>())
    };
    Ratios {
        native_time: of(|r| r.native_time),
        wasm_time: of(|r| r.wasm_time),
        coherence: of(|r| r.coherence),
        completeness: of(|r| r.completeness),
        histogram: of(|r| r.histogram),
        flat: of(|r| r.flat),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(seed: u64, ms: f64, steps: usize, coherence: f64) -> RunFigures {
        RunFigures {
            seed,
            native_ms: ms,
            steps,
            max_step_ms: ms / 2.0,
            coherence,
            completeness: 2.0 * coherence,
            histogram: 0.01,
            flat: 0.1,
            broken: 1.0,
            seams: None,
            output_hash: String::new(),
            wasm_ms: Some(2.0 * ms),
            wasm_steps: Some(steps),
            wasm_max_step_ms: None,
            wasm_identical: Some(seed != 3),
        }
    }

    #[test]
    fn medians_means_and_geomeans() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0]), Some(2.5));
        assert_eq!(median(&[]), None);
        assert_eq!(mean(&[1.0, 2.0]), Some(1.5));
        let g = geomean(&[0.5, 2.0]).unwrap();
        assert!((g - 1.0).abs() < 1e-12);
        assert_eq!(geomean(&[1.0, 0.0]), None);
    }

    #[test]
    fn a_cell_takes_the_median_time_and_the_mean_quality() {
        let c = cell(&[
            run(1, 100.0, 10, 0.1),
            run(2, 300.0, 20, 0.2),
            run(3, 200.0, 10, 0.3),
        ]);
        assert_eq!(c.native_ms, Some(200.0));
        assert_eq!(c.wasm_ms, Some(400.0));
        assert_eq!(c.steps, Some(10.0));
        assert_eq!(c.ms_per_step, Some(15.0));
        assert_eq!(c.max_step_ms, Some(150.0));
        assert!((c.coherence.unwrap() - 0.2).abs() < 1e-12);
        assert_eq!(c.wasm_identical, Some(false));
        // The peer has no steps: no per-step figures rather than a made-up one.
        let p = cell(&[run(1, 100.0, 0, 0.1)]);
        assert_eq!((p.steps, p.ms_per_step, p.max_step_ms), (None, None, None));
    }

    #[test]
    fn ratios_are_method_over_peer_and_the_goal_needs_all_three() {
        let ours = cell(&[run(1, 100.0, 10, 0.1)]);
        let peer = cell(&[run(1, 400.0, 0, 0.2)]);
        let r = ratios(&ours, &peer);
        assert_eq!(r.native_time, Some(0.25));
        assert_eq!(r.wasm_time, Some(0.5));
        assert_eq!(r.coherence, Some(0.5));
        assert_eq!(meets_goal(&r, false), Some(true));
        assert_eq!(meets_goal(&r, true), Some(false));
        let worse = Ratios {
            completeness: Some(1.01),
            ..r.clone()
        };
        assert_eq!(meets_goal(&worse, false), Some(false));
        let s = ratio_summary(&[
            &r,
            &Ratios {
                native_time: Some(1.0),
                ..r.clone()
            },
        ]);
        assert_eq!(s.native_time, Some(0.5));
    }
}
