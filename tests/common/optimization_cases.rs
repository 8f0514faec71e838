//! The JS-facing `TextureOptimization` session, as JavaScript calls it (Node and Chromium).

use js_sys::{Array, Uint8ClampedArray};
use texsynth::bindings::{Exemplar, TextureOptimization};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

const GRAVEL_64: &[u8] = include_bytes!("../../www/samples/gravel_64.png");

#[wasm_bindgen_test]
fn a_session_steps_renders_and_finishes() {
    let ex = Exemplar::from_bytes(GRAVEL_64).unwrap();
    let opts = options(&[
        ("outputWidth", 48.into()),
        ("outputHeight", 40.into()),
        ("iterations", 2.into()),
        ("seed", 3.into()),
    ]);
    let mut session = TextureOptimization::new(&ex, opts).unwrap();
    assert_eq!((session.width(), session.height()), (48, 40));
    assert_eq!(session.search(), "patchmatch");
    assert!(session.field().is_null());
    let first = session.step().unwrap();
    assert_eq!(get(&first, "kind").as_string().unwrap(), "level");
    assert!(get(&first, "energy").as_f64().unwrap() > 0.0);
    // No gradient energy by default: no Poisson solve.
    assert_eq!(get(&first, "solverIterations").as_f64().unwrap(), 0.0);
    let target = Uint8ClampedArray::new_with_length(48 * 40 * 4);
    session.render_into(&target).unwrap();
    let before = target.to_vec();
    let mut steps = 1;
    while !session.done() {
        let event = session.step().unwrap();
        steps += 1;
        assert!(steps < 100, "the session finishes");
        if get(&event, "done").as_bool().unwrap() {
            assert_eq!(get(&event, "kind").as_string().unwrap(), "done");
        }
    }
    session.render_into(&target).unwrap();
    assert_ne!(
        before,
        target.to_vec(),
        "the image changes as the synthesis runs"
    );
    assert_eq!(session.energy_history().length() as usize, steps);
    assert_eq!(session.history_levels().length() as usize, steps);
    let field = session.field();
    let columns = get(&field, "columns")
        .dyn_into::<js_sys::Uint32Array>()
        .unwrap()
        .length();
    let rows = get(&field, "rows")
        .dyn_into::<js_sys::Uint32Array>()
        .unwrap()
        .length();
    let matches = get(&field, "matches")
        .dyn_into::<js_sys::Uint32Array>()
        .unwrap()
        .length();
    assert_eq!(matches, 2 * columns * rows);
    session.render_offset_map_into(&target).unwrap();
    assert!(Array::from(&session.schedule().into()).length() >= 1);
}

#[wasm_bindgen_test]
fn same_seed_same_pixels() {
    let ex = Exemplar::from_bytes(GRAVEL_64).unwrap();
    let render = || {
        let opts = options(&[
            ("outputWidth", 40.into()),
            ("outputHeight", 40.into()),
            ("iterations", 2.into()),
        ]);
        let mut s = TextureOptimization::new(&ex, opts).unwrap();
        while !s.done() {
            s.step().unwrap();
        }
        let t = Uint8ClampedArray::new_with_length(40 * 40 * 4);
        s.render_into(&t).unwrap();
        t.to_vec()
    };
    assert_eq!(render(), render());
}

#[wasm_bindgen_test]
fn bad_options_are_errors_that_name_them() {
    let ex = Exemplar::from_bytes(GRAVEL_64).unwrap();
    let msg = |entries: &[(&str, JsValue)]| {
        error_message(TextureOptimization::new(&ex, options(entries)))
    };
    assert!(msg(&[("outputWidht", 5.into())]).contains("unknown option 'outputWidht'"));
    assert!(msg(&[("outputWidth", 0.into())]).contains("invalid outputWidth"));
    assert!(msg(&[("outputWidth", 2.5.into())]).contains("invalid outputWidth"));
    assert!(
        msg(&[
            ("outputWidth", 100000.into()),
            ("outputHeight", 100000.into())
        ])
        .contains("100000x100000")
    );
    assert!(msg(&[("r", f64::NAN.into())]).contains("invalid r"));
    assert!(msg(&[("mu", "ten".into())]).contains("invalid mu"));
    assert!(msg(&[("histogramMatching", 2.into())]).contains("invalid histogramMatching"));
    assert!(msg(&[("seed", (-1).into())]).contains("invalid seed"));
    assert!(msg(&[("search", "fast".into())]).contains("invalid search"));
    assert!(msg(&[("neighbourhoodSizes", 8.into())]).contains("neighbourhoodSizes"));
    assert!(msg(&[("tileable", 1.into())]).contains("invalid tileable"));
    let ex16 = Exemplar::from_rgba(&[9; 8 * 8 * 4], 8, 8).unwrap();
    let small = error_message(TextureOptimization::new(&ex16, JsValue::UNDEFINED));
    assert!(small.contains("exemplar size 8x8"), "{small}");
    let not_object = error_message(TextureOptimization::new(&ex, JsValue::from(3)));
    assert!(not_object.contains("options"), "{not_object}");
    let ok = TextureOptimization::new(&ex, JsValue::NULL).unwrap();
    let target = Uint8ClampedArray::new_with_length(7);
    assert!(ok.render_into(&target).is_err());
}

#[wasm_bindgen_test]
fn the_m_steps_own_gradient_weight_runs_from_js_and_bad_values_are_named() {
    let ex = Exemplar::from_bytes(GRAVEL_64).unwrap();
    let opts = options(&[
        ("outputWidth", 32.into()),
        ("outputHeight", 32.into()),
        ("iterations", 2.into()),
        ("neighbourhoodSizes", Array::of1(&8.into()).into()),
        ("mu", 10.into()),
        ("mStepMu", 1.into()),
    ]);
    let mut session = TextureOptimization::new(&ex, opts).unwrap();
    let mut steps = 0;
    while !session.done() {
        let event = session.step().unwrap();
        assert!(get(&event, "energy").as_f64().unwrap().is_finite());
        steps += 1;
        assert!(steps < 100, "the session finishes");
    }
    let msg = |value: JsValue| {
        error_message(TextureOptimization::new(
            &ex,
            options(&[("mStepMu", value)]),
        ))
    };
    for bad in [(-1).into(), f64::NAN.into(), 1e4.into(), "big".into()] {
        let m = msg(bad);
        assert!(m.contains("invalid mStepMu"), "{m}");
    }
}

#[wasm_bindgen_test]
fn wavelet_energies_run_from_js_and_bad_values_are_named() {
    let ex = Exemplar::from_bytes(GRAVEL_64).unwrap();
    for energy in ["haar", "daubechies"] {
        let opts = options(&[
            ("outputWidth", 40.into()),
            ("outputHeight", 40.into()),
            ("iterations", 2.into()),
            (
                "neighbourhoodSizes",
                Array::of2(&16.into(), &8.into()).into(),
            ),
            ("energy", energy.into()),
            ("waveletDetailWeight", 8.into()),
        ]);
        let mut session = TextureOptimization::new(&ex, opts).unwrap();
        assert_eq!(session.energy(), energy);
        let mut steps = 0;
        while !session.done() {
            let event = session.step().unwrap();
            // The reported energy is the pixel term; the M-step's adds the wavelet term.
            let (e, m) = (
                get(&event, "energy").as_f64().unwrap(),
                get(&event, "matchEnergy").as_f64().unwrap(),
            );
            assert!(e > 0.0 && m > e, "{energy}: energy {e}, matchEnergy {m}");
            steps += 1;
            assert!(steps < 100, "the session finishes");
        }
        // Soft constraints need the pixel energy.
        let paint = vec![255u8; 40 * 40 * 4];
        let err = error_message(session.set_constraints(&paint, 1.0));
        assert!(err.contains("invalid energy"), "{err}");
    }
    let plain = TextureOptimization::new(&ex, JsValue::UNDEFINED).unwrap();
    assert_eq!(plain.energy(), "pixels");
    let msg = |entries: &[(&str, JsValue)]| {
        error_message(TextureOptimization::new(&ex, options(entries)))
    };
    assert!(msg(&[("energy", "db4".into())]).contains("invalid energy"));
    assert!(msg(&[("energy", 2.into())]).contains("invalid energy"));
    assert!(msg(&[("waveletDetailWeight", (-1).into())]).contains("invalid waveletDetailWeight"));
    assert!(
        msg(&[("waveletDetailWeight", f64::NAN.into())]).contains("invalid waveletDetailWeight")
    );
    assert!(msg(&[("waveletDetailWeight", "big".into())]).contains("invalid waveletDetailWeight"));
    let odd = msg(&[
        ("energy", "haar".into()),
        ("neighbourhoodSizes", Array::of1(&12.into()).into()),
    ]);
    assert!(odd.contains("invalid neighbourhoodSizes"), "{odd}");
}

#[wasm_bindgen_test]
fn a_huge_output_is_refused_by_the_constructor_naming_the_budget() {
    // An RGB exemplar (gravel_64 is grey: a third of the colour buffers, under 1024 MiB).
    let ex = Exemplar::from_bytes(include_bytes!("../../www/samples/tiles_64.png")).unwrap();
    let huge = |budget: Option<JsValue>| {
        let mut entries = vec![("outputWidth", 4096.into()), ("outputHeight", 4096.into())];
        if let Some(b) = budget {
            entries.push(("memoryBudgetMiB", b));
        }
        error_message(TextureOptimization::new(&ex, options(&entries)))
    };
    // The default budget (1024 MiB) holds 4096x4096 (about 1 GiB); a smaller one refuses it.
    assert!(
        TextureOptimization::new(
            &ex,
            options(&[("outputWidth", 4096.into()), ("outputHeight", 4096.into())])
        )
        .is_ok()
    );
    let msg = huge(Some(512.into()));
    assert!(
        msg.starts_with("output 4096x4096: texture optimisation needs about")
            && msg.contains("memory budget of 512 MiB")
            && msg.contains("memoryBudgetMiB"),
        "{msg}"
    );
    assert!(huge(Some(256.into())).contains("memory budget of 256 MiB"));
    for bad in [
        JsValue::from(f64::NAN),
        8.into(),
        4096.into(),
        "1024".into(),
    ] {
        let msg = huge(Some(bad));
        assert!(msg.starts_with("invalid memoryBudgetMiB"), "{msg}");
    }
    // Under the budget: constructing only (the estimate is read, nothing is run).
    let session = TextureOptimization::new(
        &ex,
        options(&[
            ("outputWidth", 2048.into()),
            ("outputHeight", 2048.into()),
            ("memoryBudgetMiB", 2048.into()),
        ]),
    )
    .unwrap();
    assert!(session.memory_estimate() > 64.0 * 1048576.0);
}
