//! The frames of a flow animation at the library's defaults, written out to be scored later:
//! `cargo run --profile explore --example flow_frames -- EXEMPLAR.png SIZE SEED DIR` runs a vortex
//! of strength 2, SIZE x SIZE, 60 frames, and writes frames 1, 30, 36, ..., 60 as
//! `DIR/frameN.png` and each one's flow energy to `DIR/flow.tsv`.
//!
//! It uses only the API that the code issue 10 was filed against (69c6703) already had, so
//! `scripts/flow-at-filing.sh` builds this same file in that commit too: the issue bounds the flow
//! energy at 1.5x "today's", and this measures what "today's" was. `score_frames` scores the
//! frames of both with today's metrics.

use texsynth::core::{decode, encode_png};
use texsynth::methods::flow::{
    Component, FlowEventKind, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [path, size, seed, dir] = args.as_slice() else {
        panic!("usage: flow_frames EXEMPLAR.png SIZE SEED DIR");
    };
    let size: usize = size.parse().expect("size");
    let exemplar = decode(&std::fs::read(path).expect("exemplar")).expect("decodes");
    let flow = FlowSource::Generator(
        FlowSpec::new(vec![Component::new(FlowKind::Vortex, 2.0)]).expect("spec"),
    );
    let options = FlowOptions {
        output_width: size,
        output_height: size,
        frames: 60,
        seed: seed.parse().expect("seed"),
        ..FlowOptions::default()
    };
    let mut session = FlowSession::new(&exemplar, flow, options).expect("session");
    std::fs::create_dir_all(dir).expect("output folder");
    let mut tsv = String::from("frame\tflow_energy\n");
    // Counted here rather than read from the session: the two commits number frames differently.
    let mut frame = 0usize;
    loop {
        let event = session.step().expect("step");
        if matches!(event.kind, FlowEventKind::Frame | FlowEventKind::Done) {
            frame += 1;
            if frame == 1 || (frame >= 30 && frame.is_multiple_of(6)) {
                let png = encode_png(&session.frame_image().expect("frame")).expect("png");
                std::fs::write(format!("{dir}/frame{frame}.png"), png).expect("write");
                tsv += &format!("{frame}\t{}\n", event.flow_energy);
            }
            if event.kind == FlowEventKind::Done {
                break;
            }
        }
    }
    std::fs::write(format!("{dir}/flow.tsv"), tsv).expect("write");
}
