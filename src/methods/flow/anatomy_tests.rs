//! The step anatomy of a flow animation: half steps (the optimisation session's machinery, run
//! on each frame) change no frame, stop where they say, and the field and the warped previous
//! frame they expose are the ones the frame's iteration uses.

use super::*;
use crate::core::Image;
use crate::core::testing::sample;
use crate::methods::optimization::iteration::Phase;

fn vortex() -> FlowSource {
    FlowSource::Generator(FlowSpec::new(vec![Component::new(FlowKind::Vortex, 1.5)]).unwrap())
}

fn options() -> FlowOptions {
    FlowOptions {
        output_width: 40,
        output_height: 32,
        frames: 3,
        frame_sizes: vec![16, 8],
        frame_iterations: 2,
        ..FlowOptions::default()
    }
}

/// Runs to the end, with or without half steps; returns the finished frames and every event.
fn run(halves: bool) -> (Vec<Image>, Vec<FlowEvent>) {
    let mut s = FlowSession::new(&sample("gravel_64"), vortex(), options()).unwrap();
    s.set_half_steps(halves);
    let (mut frames, mut events) = (Vec::new(), Vec::new());
    loop {
        let e = s.step().unwrap();
        events.push(e);
        if matches!(e.kind, FlowEventKind::Frame | FlowEventKind::Done) {
            frames.push(s.frame_image().unwrap());
        }
        if e.kind == FlowEventKind::Done {
            return (frames, events);
        }
    }
}

#[test]
fn half_steps_change_no_frame_and_split_every_iteration_in_two() {
    let (plain, plain_events) = run(false);
    let (halved, events) = run(true);
    assert_eq!(halved, plain, "the same frames");
    let whole = |ev: &[FlowEvent]| {
        ev.iter()
            .filter(|e| e.kind != FlowEventKind::Part)
            .map(|e| (e.frame, e.iteration, e.kind))
            .collect::<Vec<_>>()
    };
    assert_eq!(whole(&events), whole(&plain_events), "the same iterations");
    // Within a frame after the first: the first M-step on the warped start, then E-step and
    // M-step in turn, except that the last iteration at a size ends with its E-step (its
    // M-step only measures); a new neighbourhood size starts with its own first M-step.
    let later: Vec<(Phase, FlowEventKind)> = events
        .iter()
        .filter(|e| e.frame == 1)
        .map(|e| (e.phase, e.kind))
        .collect();
    use FlowEventKind::{Iteration, Part};
    assert_eq!(
        later[..5],
        [
            (Phase::FirstMatch, Part),
            (Phase::EStep, Part),
            (Phase::MStep, Iteration),
            (Phase::EStep, Iteration),
            (Phase::FirstMatch, Part),
        ],
        "{later:?}"
    );
    // Frame 0 is plain texture optimisation, split the same way.
    assert!(
        events
            .iter()
            .any(|e| e.frame == 0 && e.kind == Part && e.phase == Phase::EStep)
    );
}

#[test]
fn the_field_is_the_frame_solvers_and_the_e_step_moves_the_frame_off_its_warped_start() {
    let mut s = FlowSession::new(&sample("gravel_64"), vortex(), options()).unwrap();
    assert!(s.anatomy_field().is_none(), "nothing before the first step");
    assert!(s.warped_previous().is_none());
    s.set_half_steps(true);
    // Frame 0: the optimisation session's own field.
    let e = s.step().unwrap();
    let (field, _) = s.anatomy_field().expect("frame 0 has a level");
    assert_eq!(field.level.size, e.size);
    assert!(
        s.warped_previous().is_none(),
        "frame 0 has no previous frame"
    );
    while s.step().unwrap().kind != FlowEventKind::Frame {}
    // Frame 1, first half: the M-step on the warped start, which the frame still shows.
    let e = s.step().unwrap();
    assert_eq!((e.frame, e.phase), (1, Phase::FirstMatch));
    let warped = s
        .warped_previous()
        .expect("frame 1 is warped")
        .target
        .clone();
    assert_eq!(
        s.frame_image().unwrap(),
        warped,
        "an M-step changes no pixel"
    );
    let (field, solver) = s.anatomy_field().expect("frame 1 iterated");
    assert_eq!(
        (field.level.size, field.level.output_width),
        (16, 40),
        "the first frame size, at full resolution"
    );
    assert_eq!(field.matches.len(), field.columns.len() * field.rows.len());
    assert!(
        solver.distances().iter().all(|d| d.is_finite()),
        "every node matched"
    );
    assert!(
        field
            .matches
            .iter()
            .all(|m| { (m.x as usize) + 16 <= 64 && (m.y as usize) + 16 <= 64 })
    );
    // Second half: the E-step's average moves the frame off the warped start.
    let e = s.step().unwrap();
    assert_eq!(e.phase, Phase::EStep);
    let after = s.frame_image().unwrap();
    let moved = after
        .data()
        .iter()
        .zip(warped.data())
        .filter(|(a, b)| (*a - *b).abs() > 1e-3)
        .count();
    assert!(moved > after.data().len() / 4, "{moved} values moved");
}
