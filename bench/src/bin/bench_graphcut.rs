//! Native benchmark of graph-cut textures: `cargo run --release -p texsynth-bench --bin bench_graphcut`.
//! Synthesises 256x256 from the samples with each placement mode and prints total time, time per
//! placement (median, max), patches placed and the final total seam cost. `BENCH_SIZE=1024` and
//! `BENCH_PLACEMENTS=entire-patch,sub-patch` pick the output size and placements. `scripts/bench.sh` runs
//! this and the same cases as wasm in Node. `BENCH_WRITE=dir` also writes the outputs as PNGs;
//! `BENCH_QUALITY=1` prints the quality metrics of each output; `BENCH_SEED` sets the seed;
//! `BENCH_ERROR_REGION` the error region's side (0: the default, a third of the exemplar);
//! `BENCH_REFINE` the refinement patches placed once the output is covered (24).

use std::time::Instant;

use texsynth::core::{decode, encode_png};
use texsynth::methods::graphcut::{Options, Placement, Session};

fn main() {
    let samples = std::env::var("BENCH_SAMPLES").unwrap_or_else(|_| "gravel_128,gravel_64".into());
    let size: usize = std::env::var("BENCH_SIZE").map_or(256, |v| v.parse().expect("BENCH_SIZE"));
    let placements: Vec<Placement> = std::env::var("BENCH_PLACEMENTS").map_or(
        vec![
            Placement::Random,
            Placement::EntirePatch,
            Placement::SubPatch,
        ],
        |v| {
            v.split(',')
                .map(|p| Placement::from_name(p).expect("random, entire-patch or sub-patch"))
                .collect()
        },
    );
    println!(
        "native graph-cut textures, {size}x{size} output, default options (seed 1, 24 refinement patches)"
    );
    println!(
        "{:<12} {:<13} {:>8} {:>9} {:>10} {:>10} {:>12}",
        "exemplar", "placement", "patches", "total ms", "median ms", "max ms", "seam cost"
    );
    for name in samples.split(',') {
        let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
        let exemplar =
            decode(&std::fs::read(&path).expect("sample exists")).expect("sample decodes");
        for &placement in &placements {
            let start = Instant::now();
            let mut session = Session::new(
                &exemplar,
                Options {
                    placement,
                    output_width: size,
                    output_height: size,
                    seed: std::env::var("BENCH_SEED").map_or(1, |v| v.parse().expect("BENCH_SEED")),
                    error_region: std::env::var("BENCH_ERROR_REGION")
                        .map_or(0, |v| v.parse().expect("BENCH_ERROR_REGION")),
                    refinement_patches: std::env::var("BENCH_REFINE")
                        .map_or(24, |v| v.parse().expect("BENCH_REFINE")),
                    ..Options::default()
                },
            )
            .expect("valid options");
            let mut steps = Vec::new();
            let event = loop {
                let t = Instant::now();
                let event = session.step().expect("step");
                steps.push(t.elapsed().as_secs_f64() * 1e3);
                if event.done {
                    break event;
                }
            };
            let total = start.elapsed().as_secs_f64() * 1e3;
            steps.sort_by(f64::total_cmp);
            let (median, max) = (steps[steps.len() / 2], steps[steps.len() - 1]);
            if std::env::var("BENCH_QUALITY").is_ok() {
                let q = texsynth::methods::quality::quality(
                    &exemplar,
                    &session.output().expect("output"),
                )
                .expect("quality");
                println!(
                    "  quality: coherence {:.4e} completeness {:.4e} histogram {:.4e} flat {:.3}",
                    q.coherence, q.completeness, q.histogram, q.flat
                );
            }
            if let Ok(dir) = std::env::var("BENCH_WRITE") {
                let png = encode_png(&session.output().expect("output")).expect("png");
                std::fs::write(
                    format!("{dir}/{name}-graphcut-{}.png", placement.name()),
                    png,
                )
                .expect("write");
            }
            println!(
                "{name:<12} {:<13} {:>8} {total:>9.1} {median:>10.1} {max:>10.1} {:>12.1}",
                placement.name(),
                event.patches_placed,
                event.total_seam_cost
            );
        }
    }
}
