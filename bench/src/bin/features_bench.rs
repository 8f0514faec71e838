//! Feature-guided synthesis (graph-cut placement) at one output size, for profiling how its
//! cost grows with the output: `cargo run --profile explore -p texsynth-bench --bin features_bench -- SAMPLE
//! SIZE` (tiles_128, 1024). Prints the set-up time, then the time of every tenth of the steps.

use std::time::Instant;
use texsynth::core::decode;
use texsynth::methods::features::{FeatureOptions, FeatureSynthesis};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("tiles_128", String::as_str);
    let size: usize = args.get(1).map_or(1024, |s| s.parse().expect("SIZE"));
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let exemplar = decode(&std::fs::read(path).expect("sample")).expect("decodes");
    let options = FeatureOptions {
        output_width: size,
        output_height: size,
        memory_budget_mib: texsynth::core::budget::MAX_MEMORY_BUDGET_MIB,
        ..FeatureOptions::default()
    };
    let start = Instant::now();
    let mut session = FeatureSynthesis::new(&exemplar, None, options).expect("session");
    println!("set-up {:.2} s", start.elapsed().as_secs_f64());
    let mut steps = Vec::new();
    while !session.is_done() {
        let t = Instant::now();
        session.step().expect("step");
        steps.push(t.elapsed().as_secs_f64());
    }
    let tenth = steps.len().div_ceil(10).max(1);
    for (i, chunk) in steps.chunks(tenth).enumerate() {
        println!(
            "steps {:4}-{:4}: {:.2} s",
            i * tenth,
            i * tenth + chunk.len() - 1,
            chunk.iter().sum::<f64>()
        );
    }
    println!(
        "{name} {size}x{size}: {} steps, {:.2} s",
        steps.len(),
        start.elapsed().as_secs_f64()
    );
}
