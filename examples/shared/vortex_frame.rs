//! Frame 1 of a vortex animation, as the flow examples that study one frame start: the sample
//! read from `www/samples`, the session with `seed` and two frames, stepped until frame 1 is
//! done. Included with `#[path]` (an example is a crate of its own).

use texsynth::core::{Image, decode};
use texsynth::methods::flow::{
    Component, FlowKind, FlowOptions, FlowSession, FlowSource, FlowSpec,
};

/// The exemplar, the session (at frame 1, its field still available) and frame 1.
pub fn vortex_frame_one(
    name: &str,
    size: usize,
    strength: f32,
    seed: u64,
) -> (Image, FlowSession, Image) {
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    let exemplar = decode(&std::fs::read(path).expect("sample")).expect("decodes");
    let flow = FlowSource::Generator(
        FlowSpec::new(vec![Component::new(FlowKind::Vortex, strength)]).expect("spec"),
    );
    let options = FlowOptions {
        output_width: size,
        output_height: size,
        frames: 2,
        seed,
        ..FlowOptions::default()
    };
    let mut session = FlowSession::new(&exemplar, flow, options).expect("session");
    while session.frame() < 1 {
        session.step().expect("step");
    }
    let frame = session.frame_image().expect("frame 1");
    (exemplar, session, frame)
}
