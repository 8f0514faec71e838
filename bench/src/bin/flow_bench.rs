//! Native timing of flow animation frames: `cargo run --profile explore -p texsynth-bench --bin flow_bench --
//! [SAMPLE] [SIZE] [FRAMES]` (defaults: `tiles_128 512 8`, a vortex of strength 2, the default
//! options). Prints the first frame's time and the frames per second of the frames after it,
//! the figure the scaling table's flow row gives for wasm. No quality is measured (see
//! `flow_detail` for that): at 512x512 measuring one frame costs more than making it.
//! `FLOW_VERBOSE=1` also prints every iteration of the frames after the first (its size, how
//! many matches changed, the energies) and the time spent per neighbourhood size.

use std::time::Instant;

use texsynth::core::decode;
use texsynth::methods::flow::{
    Component, FlowEventKind, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.first().map_or("tiles_128", String::as_str);
    let size: usize = args.get(1).map_or(512, |s| s.parse().expect("size"));
    let frames: usize = args.get(2).map_or(8, |s| s.parse().expect("frames"));
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let exemplar = decode(&std::fs::read(path).expect("sample")).expect("decodes");
    let flow = FlowSource::Generator(
        FlowSpec::new(vec![Component::new(FlowKind::Vortex, 2.0)]).expect("spec"),
    );
    let options = FlowOptions {
        output_width: size,
        output_height: size,
        frames,
        ..FlowOptions::default()
    };
    let verbose = std::env::var_os("FLOW_VERBOSE").is_some();
    let start = Instant::now();
    let mut session = FlowSession::new(&exemplar, flow, options).expect("session");
    let mut first = None;
    let mut per_size = std::collections::BTreeMap::<usize, (f64, usize)>::new();
    loop {
        let t = Instant::now();
        let event = session.step().expect("step");
        if first.is_some() {
            let e = per_size.entry(event.size).or_default();
            e.0 += t.elapsed().as_secs_f64() * 1e3;
            if matches!(event.kind, FlowEventKind::Iteration | FlowEventKind::Frame) {
                e.1 += 1;
                if verbose {
                    println!(
                        "  frame {} w {} iteration {}: {} changed, texture {:.6}, flow {:.6}",
                        event.frame,
                        event.size,
                        event.iteration,
                        event.changed,
                        event.texture_energy,
                        event.flow_energy
                    );
                }
            }
        }
        if matches!(event.kind, FlowEventKind::Frame | FlowEventKind::Done) && first.is_none() {
            first = Some(start.elapsed().as_secs_f64());
        }
        if event.kind == FlowEventKind::Done {
            break;
        }
    }
    let total = start.elapsed().as_secs_f64();
    if verbose {
        for (size, (ms, n)) in &per_size {
            println!("  w {size}: {ms:.0} ms over {n} iterations");
        }
    }
    let first = first.expect("a first frame");
    println!(
        "{name} {size}x{size}: first frame {first:.2} s, then {} frames at {:.2} fps ({:.0} ms a frame)",
        frames - 1,
        (frames - 1) as f64 / (total - first),
        (total - first) * 1e3 / (frames - 1) as f64
    );
}
