//! The JS-facing `FlowAnimation`, `flowField` and the soft constraints of
//! `TextureOptimization`, as JavaScript calls them (Node and Chromium).

use js_sys::{Array, Float32Array, Uint8ClampedArray};
use texsynth::bindings::{Exemplar, FlowAnimation, TextureOptimization, flow_field};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

const GRASS_64: &[u8] = include_bytes!("../../www/samples/grass_64.png");

fn small(flow: JsValue, frames: u32) -> JsValue {
    options(&[
        ("outputWidth", 40.into()),
        ("outputHeight", 32.into()),
        ("frames", frames.into()),
        ("flow", flow),
    ])
}

#[wasm_bindgen_test]
fn an_animation_makes_its_frames_and_the_naive_warp() {
    let ex = Exemplar::from_bytes(GRASS_64).unwrap();
    let vortex = options(&[("type", "vortex".into()), ("strength", 1.5.into())]);
    let mut anim = FlowAnimation::new(&ex, small(vortex, 3)).unwrap();
    assert_eq!((anim.width(), anim.height(), anim.frames()), (40, 32, 3));
    let target = Uint8ClampedArray::new_with_length(40 * 32 * 4);
    let naive = Uint8ClampedArray::new_with_length(40 * 32 * 4);
    let mut frames = Vec::new();
    let mut steps = 0;
    while !anim.done() {
        let e = anim.step().unwrap();
        steps += 1;
        assert!(steps < 200, "the animation finishes");
        // A small frame steps whole iterations: the last phase, all of it (the E-step where a
        // later frame's last iteration at a size only measures its matches).
        assert_ne!(get(&e, "kind").as_string().unwrap(), "part");
        let phase = get(&e, "phase").as_string().unwrap();
        let later = get(&e, "frame").as_f64().unwrap() > 0.0;
        assert!(
            phase == "m-step" || (later && phase == "e-step"),
            "{phase} in frame {}",
            get(&e, "frame").as_f64().unwrap()
        );
        assert_eq!(get(&e, "progress").as_f64().unwrap(), 1.0);
        if get(&e, "frameFinished").as_bool().unwrap() {
            anim.render_into(&target).unwrap();
            frames.push(target.to_vec());
            assert_eq!(
                get(&e, "frame").as_f64().unwrap() as usize,
                frames.len() - 1
            );
            assert!(get(&e, "flowEnergy").as_f64().unwrap().is_finite());
        }
    }
    assert_eq!(frames.len(), 3);
    assert_ne!(frames[1], frames[2], "the texture moves");
    anim.render_naive_into(&naive).unwrap();
    assert_ne!(
        naive.to_vec(),
        frames[2],
        "the naive warp is not the synthesis"
    );
    assert_eq!(anim.texture_energy_history().length(), 3);
    assert_eq!(anim.flow_energy_history().length(), 3);
    assert_eq!(anim.flow_field(0).unwrap().length(), 40 * 32 * 2);
    // A finished animation keeps answering with its last event.
    assert!(get(&anim.step().unwrap(), "done").as_bool().unwrap());
}

#[wasm_bindgen_test]
fn flows_can_be_fields_combinations_and_time_varying() {
    let ex = Exemplar::from_bytes(GRASS_64).unwrap();
    let field = Float32Array::from(vec![0.5f32; 40 * 32 * 2].as_slice());
    assert!(FlowAnimation::new(&ex, small(field.clone().into(), 2)).is_ok());
    let list: Array = [field.clone(), field].iter().collect();
    assert!(FlowAnimation::new(&ex, small(list.into(), 2)).is_ok());
    let combo = options(&[(
        "components",
        [
            options(&[("type", "sink".into()), ("strength", 1.into())]),
            options(&[
                ("type", "translation".into()),
                ("angle", 90.into()),
                ("turn", 10.into()),
            ]),
        ]
        .iter()
        .collect::<Array>()
        .into(),
    )]);
    let f0 = flow_field(combo.clone(), 16, 16, 0).unwrap().to_vec();
    let f1 = flow_field(combo, 16, 16, 1).unwrap().to_vec();
    assert_eq!(f0.len(), 16 * 16 * 2);
    assert_ne!(f0, f1, "a turning translation changes over time");
}

#[wasm_bindgen_test]
fn sub_pixel_matches_are_an_option() {
    // A quarter pixel per frame: both kinds of match run; the option takes booleans only.
    let ex = Exemplar::from_bytes(GRASS_64).unwrap();
    let field: JsValue = Float32Array::from([0.25f32, 0.0].repeat(40 * 32).as_slice()).into();
    let with = |sub_pixel: JsValue| {
        options(&[
            ("outputWidth", 40.into()),
            ("outputHeight", 32.into()),
            ("frames", 3.into()),
            ("flow", field.clone()),
            ("subPixel", sub_pixel),
        ])
    };
    for sub_pixel in [true, false] {
        let mut anim = FlowAnimation::new(&ex, with(sub_pixel.into())).unwrap();
        while !anim.done() {
            anim.step().unwrap();
        }
        assert_eq!(anim.flow_energy_history().length(), 3);
    }
    let msg = error_message(FlowAnimation::new(&ex, with("yes".into())));
    assert!(msg.contains("subPixel"), "{msg}");
}

#[wasm_bindgen_test]
fn bad_flows_and_options_are_named_errors() {
    let ex = Exemplar::from_bytes(GRASS_64).unwrap();
    let short = Float32Array::from(vec![0.0f32; 10].as_slice());
    let msg = error_message(FlowAnimation::new(&ex, small(short.into(), 2)));
    assert!(msg.contains("expected 2560"), "{msg}");
    let mut bad = vec![0.0f32; 40 * 32 * 2];
    bad[7] = f32::NAN;
    let nan = Float32Array::from(bad.as_slice());
    let msg = error_message(FlowAnimation::new(&ex, small(nan.into(), 2)));
    assert!(msg.contains("NaN"), "{msg}");
    let unknown = options(&[("type", "whirlpool".into())]);
    let msg = error_message(FlowAnimation::new(&ex, small(unknown, 2)));
    assert!(msg.contains("whirlpool") && msg.contains("vortex"), "{msg}");
    let nan_strength = options(&[("type", "sink".into()), ("strength", f64::NAN.into())]);
    let msg = error_message(FlowAnimation::new(&ex, small(nan_strength, 2)));
    assert!(msg.contains("strength"), "{msg}");
    let msg = error_message(FlowAnimation::new(&ex, small("vortex".into(), 2)));
    assert!(msg.contains("flow"), "{msg}");
    let msg = error_message(FlowAnimation::new(&ex, options(&[("lambda", (-1).into())])));
    assert!(msg.contains("lambda"), "{msg}");
    let msg = error_message(FlowAnimation::new(
        &ex,
        options(&[("histogramMatching", f64::NAN.into())]),
    ));
    assert!(msg.contains("histogramMatching"), "{msg}");
    let msg = error_message(FlowAnimation::new(&ex, options(&[("speed", 1.into())])));
    assert!(msg.contains("speed"), "{msg}");
    let msg = error_message(flow_field(JsValue::NULL, 8, 8, 0));
    assert!(msg.contains("flow"), "{msg}");
}

#[wasm_bindgen_test]
fn painted_constraints_pull_a_texture_optimization() {
    let ex = Exemplar::from_bytes(GRASS_64).unwrap();
    let opts = options(&[
        ("outputWidth", 32.into()),
        ("outputHeight", 32.into()),
        ("iterations", 2.into()),
    ]);
    let mut session = TextureOptimization::new(&ex, opts).unwrap();
    while !session.done() {
        session.step().unwrap();
    }
    // Paint the left half pure red, fully constrained.
    let mut rgba = vec![0u8; 32 * 32 * 4];
    for (i, px) in rgba.chunks_exact_mut(4).enumerate() {
        if i % 32 < 16 {
            px.copy_from_slice(&[255, 0, 0, 255]);
        }
    }
    session.set_constraints(&rgba, 4.0).unwrap();
    let free = session.constraint_energy();
    assert!(!session.done(), "painting reopens the finest level");
    while !session.done() {
        session.step().unwrap();
    }
    assert!(session.constraint_energy() < 0.5 * free);
    let msg = error_message(session.set_constraints(&rgba[4..], 1.0));
    assert!(msg.contains("4096"), "{msg}");
    let msg = error_message(session.set_constraints(&rgba, f64::NAN));
    assert!(msg.contains("lambda"), "{msg}");
    session.clear_constraints().unwrap();
    assert_eq!(session.constraint_energy(), 0.0);
}
