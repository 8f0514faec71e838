//! Native benchmark of texture optimisation: `cargo run --release -p texsynth-bench --bin bench [-- SEARCH...]`.
//! Synthesises 256x256 (`BENCH_SIZE=1024`: 1024x1024) from the 128x128 and 64x64 samples with each search and prints total time,
//! time per step (median, max), final energy and the search used. `scripts/bench.sh` runs this and
//! the same cases as wasm in Node. `BENCH_WRITE=dir` also writes each output as a PNG;
//! `BENCH_VERBOSE=1` prints every step; `BENCH_ITERATIONS` sets the iterations per level;
//! `BENCH_SEED` the seed (1).

use std::time::Instant;

use texsynth::core::decode;
use texsynth::methods::optimization::{EventKind, Options, Session};
use texsynth::solvers::nn::Search;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let searches: Vec<Search> = if args.is_empty() {
        vec![Search::PatchMatch, Search::KMeansTree, Search::Exact]
    } else {
        args.iter()
            .map(|a| Search::from_name(a).unwrap_or_else(|| panic!("unknown search {a}")))
            .collect()
    };
    let samples =
        std::env::var("BENCH_SAMPLES").unwrap_or_else(|_| "gravel_128,gravel_64,tiles_128".into());
    let size: usize = std::env::var("BENCH_SIZE").map_or(256, |v| v.parse().expect("BENCH_SIZE"));
    let seed: u64 = std::env::var("BENCH_SEED").map_or(1, |v| v.parse().expect("BENCH_SEED"));
    println!(
        "native texture optimization, {size}x{size} output, default schedule (r = 0.8, seed {seed})"
    );
    println!(
        "{:<12} {:<12} {:>6} {:>9} {:>10} {:>10} {:>12}",
        "exemplar", "search", "steps", "total ms", "median ms", "max ms", "final energy"
    );
    for name in samples.split(',') {
        let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
        let exemplar =
            decode(&std::fs::read(&path).expect("sample exists")).expect("sample decodes");
        for &search in &searches {
            let options = Options {
                search,
                output_width: size,
                output_height: size,
                seed,
                iterations: std::env::var("BENCH_ITERATIONS")
                    .map_or(Options::default().iterations, |v| {
                        v.parse().expect("BENCH_ITERATIONS")
                    }),
                ..Options::default()
            };
            let start = Instant::now();
            let mut session = Session::new(&exemplar, options).expect("valid options");
            let mut steps = Vec::new();
            let energy = loop {
                let t = Instant::now();
                let cpu = cpu_ns();
                let event = session.step().expect("step");
                steps.push(t.elapsed().as_secs_f64() * 1e3);
                if std::env::var_os("BENCH_VERBOSE").is_some() {
                    println!(
                        "  level {} (octave {}, w {}) iteration {} {:?} {:?} at {:.2}: {:.1} ms (cpu {:.1} ms), {} changed",
                        event.level,
                        event.octave,
                        event.size,
                        event.iteration,
                        event.kind,
                        event.phase,
                        event.progress,
                        steps[steps.len() - 1],
                        (cpu_ns() - cpu) as f64 / 1e6,
                        event.changed
                    );
                }
                if event.kind == EventKind::Done {
                    break event.energy;
                }
            };
            let total = start.elapsed().as_secs_f64() * 1e3;
            steps.sort_by(f64::total_cmp);
            let median = steps[steps.len() / 2];
            let max = steps[steps.len() - 1];
            if let Ok(dir) = std::env::var("BENCH_WRITE") {
                let output = session.output_full_size().expect("output");
                let png = texsynth::core::encode_png(&output).expect("png");
                std::fs::write(format!("{dir}/{name}-{}.png", search.name()), png).expect("write");
            }
            println!(
                "{name:<12} {:<12} {:>6} {total:>9.1} {median:>10.1} {max:>10.1} {energy:>12.6}",
                search.name(),
                steps.len()
            );
        }
    }
}

/// This thread's time on a CPU in nanoseconds (Linux's schedstat; 0 elsewhere): step times that
/// other processes on the machine do not inflate.
fn cpu_ns() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}
