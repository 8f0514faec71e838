//! The JS-facing feature-guided synthesis (Wu & Yu 2004), as JavaScript calls it (Node and
//! Chromium): detection and editing of a feature map, the session, the teaching data, the
//! broken-feature measure, and bad input.

use js_sys::{Array, Uint8ClampedArray};
use texsynth::bindings::{
    Exemplar, FeatureMap, FeatureSynthesis, GraphcutTextures, detect_features,
    measure_broken_features,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

const TILES_64: &[u8] = include_bytes!("../../www/samples/tiles_64.png");

#[wasm_bindgen_test]
fn a_feature_map_is_detected_edited_and_used() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let mut map = detect_features(&ex, JsValue::UNDEFINED).unwrap();
    let before = map.count();
    assert!(before > 100, "{before}");
    map.paint(10.0, 10.0, 3.0, false).unwrap();
    assert!(map.count() <= before);
    map.paint(40.0, 40.0, 1.0, true).unwrap();
    let rgba = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    map.render_into(&rgba).unwrap();
    assert!(rgba.to_vec().chunks(4).any(|p| p[3] == 255));
    let mut s = FeatureSynthesis::with_feature_map(
        &ex,
        &map,
        options(&[
            ("outputWidth", 96.into()),
            ("outputHeight", 96.into()),
            ("patchSize", 32.into()),
            ("placement", "scan".into()),
        ]),
    )
    .unwrap();
    let mut steps = 0;
    let mut warped = 0;
    while !s.done() {
        let e = s.step().unwrap();
        steps += 1;
        if get(&e, "warp").as_string().unwrap() != "none" {
            warped += 1;
        }
        assert!(steps < 100);
    }
    assert!(warped > 0, "some patch was bent onto the context");
    let p = s.placement();
    assert_eq!(get(&p, "size").as_f64().unwrap(), 32.0);
    let out = Uint8ClampedArray::new_with_length(96 * 96 * 4);
    s.render_into(&out).unwrap();
    s.render_features_into(&out).unwrap();
    s.render_into(&out).unwrap();
    let broken = measure_broken_features(&ex, &out.to_vec(), 96, 96, JsValue::UNDEFINED).unwrap();
    assert!(broken.is_finite());
    // The edited map sent as a mask, as the page sends it to its worker.
    let mut again = FeatureSynthesis::new(
        &ex,
        options(&[
            ("outputWidth", 96.into()),
            ("outputHeight", 96.into()),
            ("patchSize", 32.into()),
            ("featureMask", map.to_mask().into()),
        ]),
    )
    .unwrap();
    // The default, graph-cut placement: it cannot warp and says so, and the feature cost joins
    // the choice once there is made output to match.
    let mut priced = 0;
    while !again.done() {
        let e = again.step().unwrap();
        assert_eq!(get(&e, "warp").as_string().unwrap(), "unavailable");
        if get(&e, "featureCost").as_f64().unwrap() > 0.0 {
            priced += 1;
        }
    }
    assert!(priced > 0, "graph-cut placement priced features");
    let out2 = Uint8ClampedArray::new_with_length(96 * 96 * 4);
    again.render_into(&out2).unwrap();
    let mut third = FeatureSynthesis::with_feature_map(
        &ex,
        &map,
        options(&[
            ("outputWidth", 96.into()),
            ("outputHeight", 96.into()),
            ("patchSize", 32.into()),
            ("placement", "scan".into()),
        ]),
    )
    .unwrap();
    while !third.done() {
        third.step().unwrap();
    }
    let out3 = Uint8ClampedArray::new_with_length(96 * 96 * 4);
    third.render_into(&out3).unwrap();
    assert_eq!(
        out.to_vec(),
        out3.to_vec(),
        "with_feature_map repeats exactly"
    );
    assert!(
        out2.to_vec().chunks(4).all(|p| p[3] == 255),
        "the edited map sent as a mask runs"
    );
    assert!(
        error_message(FeatureSynthesis::new(
            &ex,
            options(&[("featureMask", js_sys::Uint8Array::new_with_length(5).into())])
        ))
        .contains("featureMask has length 5")
    );
}

#[wasm_bindgen_test]
fn bad_feature_input_is_named() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let msg = |v: JsValue| error_message(FeatureSynthesis::new(&ex, v));
    assert!(msg(options(&[("patchSize", 100.into())])).contains("patchSize"));
    assert!(
        msg(options(&[("features", "corners".into())])).contains("'edges', 'ridges' or 'both'")
    );
    assert!(msg(options(&[("threshold", 2.into())])).contains("threshold"));
    assert!(msg(options(&[("featureWeight", f64::NAN.into())])).contains("featureWeight"));
    assert!(
        msg(options(&[(
            "extraInputs",
            Array::of1(&"spin".into()).into()
        )]))
        .contains("extraInputs")
    );
    assert!(msg(options(&[("warpp", true.into())])).contains("unknown option 'warpp'"));
    let mut map = detect_features(&ex, JsValue::UNDEFINED).unwrap();
    assert!(error_message(map.paint(f32::NAN, 1.0, 2.0, true)).contains("invalid x"));
    assert!(
        error_message(measure_broken_features(
            &ex,
            &[0; 12],
            4,
            4,
            JsValue::UNDEFINED
        ))
        .contains("length")
    );
}
#[wasm_bindgen_test]
fn a_feature_mask_sent_as_bytes_gives_the_map_s_synthesis() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let map = detect_features(&ex, JsValue::UNDEFINED).unwrap();
    let opts = |extra: Option<JsValue>| {
        let mut e = vec![
            ("outputWidth", 96.into()),
            ("outputHeight", 96.into()),
            ("patchSize", 32.into()),
        ];
        if let Some(m) = extra {
            e.push(("featureMask", m));
        }
        options(&e)
    };
    let run = |mut s: FeatureSynthesis| {
        while !s.done() {
            s.step().unwrap();
        }
        let o = Uint8ClampedArray::new_with_length(96 * 96 * 4);
        s.render_into(&o).unwrap();
        o.to_vec()
    };
    let detected = run(FeatureSynthesis::new(&ex, opts(None)).unwrap());
    assert_eq!(
        run(FeatureSynthesis::new(&ex, opts(Some(map.to_mask().into()))).unwrap()),
        detected
    );
    assert_eq!(
        run(FeatureSynthesis::with_feature_map(&ex, &map, opts(None)).unwrap()),
        detected
    );
}

#[wasm_bindgen_test]
fn a_constructed_map_strokes_and_counts_broken_features_as_measured() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let opts = || options(&[("features", "edges".into()), ("threshold", 0.85.into())]);
    let mut map = FeatureMap::new(&ex, opts()).unwrap();
    let detected = detect_features(&ex, opts()).unwrap();
    assert_eq!(map.to_mask().to_vec(), detected.to_mask().to_vec());
    // A stroke in one move paints a gapless curve across the map; a wide erase clears a band.
    map.paint_line(-20.0, 31.5, 90.0, 31.5, 0.5, false).unwrap();
    map.paint_line(0.0, 31.0, 63.0, 31.0, 0.5, true).unwrap();
    let mask = map.to_mask().to_vec();
    assert!((0..64).all(|x| mask[31 * 64 + x] == 1), "row 31 painted");
    map.paint_line(20.0, 0.0, 20.0, 63.0, 3.0, false).unwrap();
    let mask = map.to_mask().to_vec();
    assert!(
        (0..64).all(|y| (18..=22).all(|x| mask[y * 64 + x] == 0)),
        "band erased"
    );
    // An output scored against the map: the exemplar as detected, not as edited.
    let mut s = FeatureSynthesis::with_feature_map(
        &ex,
        &map,
        options(&[
            ("outputWidth", 80.into()),
            ("outputHeight", 72.into()),
            ("patchSize", 32.into()),
        ]),
    )
    .unwrap();
    while !s.done() {
        s.step().unwrap();
    }
    let out = Uint8ClampedArray::new_with_length(80 * 72 * 4);
    s.render_into(&out).unwrap();
    let pixels = out.to_vec();
    let measured = measure_broken_features(&ex, &pixels, 80, 72, opts()).unwrap();
    assert_eq!(map.broken_features(&pixels, 80, 72).unwrap(), measured);
    assert_eq!(detected.broken_features(&pixels, 80, 72).unwrap(), measured);
    assert!(error_message(map.broken_features(&pixels, 80, 71)).contains("expected"));
    assert!(error_message(map.paint_line(0.0, 0.0, f32::NAN, 1.0, 1.0, true)).contains("x1"));
    // Its view at its own size is renderInto's; at a quarter of it every painted row and column
    // still shows, and upscaled each map pixel covers a block.
    let full = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    map.render_into(&full).unwrap();
    assert_eq!(map.scaled_view(64, 64).unwrap().to_vec(), full.to_vec());
    let small = map.scaled_view(16, 16).unwrap().to_vec();
    let shown = |v: &[u8], w: usize, x: usize, y: usize| v[(y * w + x) * 4 + 3] == 255;
    // (View column 5 holds map columns 20-23, all in the erased band.)
    assert!(
        (0..16).all(|x| shown(&small, 16, x, 7) == (x != 5)),
        "row 31 in view row 7"
    );
    assert!((0..16).all(|y| !shown(&small, 16, 5, y)), "the erased band");
    let big = map.scaled_view(128, 96).unwrap().to_vec();
    // Map row 31 is view row 47; map columns 17-23 (erased) are view columns 34-47.
    assert!((0..128).all(|x| shown(&big, 128, x, 47) != (34..48).contains(&x)));
    assert!(error_message(map.scaled_view(0, 5)).contains("width"));
    assert!(error_message(map.scaled_view(5, 5000)).contains("height"));
}

#[wasm_bindgen_test]
fn carried_counts_score_both_methods_on_the_same_map() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let map = detect_features(&ex, JsValue::UNDEFINED).unwrap();
    let size = || {
        options(&[
            ("outputWidth", 96.into()),
            ("outputHeight", 96.into()),
            ("seed", 2.into()),
        ])
    };
    let mut fg = FeatureSynthesis::with_feature_map(&ex, &map, size()).unwrap();
    while !fg.done() {
        fg.step().unwrap();
    }
    let mut gc = GraphcutTextures::new(&ex, size()).unwrap();
    while !gc.done() {
        gc.step().unwrap();
    }
    let mask = map.to_mask().to_vec();
    let (ours, theirs) = (
        fg.carried_broken_features(),
        gc.carried_broken_features(&mask).unwrap(),
    );
    assert!(ours.is_finite() && theirs.is_finite(), "{ours} {theirs}");
    // Ends per 1000 curve pixels: a tiles output has curves, and cannot end more than every one.
    assert!(ours.abs() < 1000.0 && theirs.abs() < 1000.0);
    // The map itself counts as its mask does, edits included (a worker passes the map).
    assert_eq!(gc.carried_broken_features_of(&map).unwrap(), theirs);
    let mut edited = detect_features(&ex, JsValue::UNDEFINED).unwrap();
    edited
        .paint_line(0.0, 40.0, 63.0, 40.0, 3.0, false)
        .unwrap();
    assert_eq!(
        gc.carried_broken_features_of(&edited).unwrap(),
        gc.carried_broken_features(&edited.to_mask().to_vec())
            .unwrap()
    );
    assert_ne!(
        edited.to_mask().to_vec(),
        mask,
        "the erased band is in the mask"
    );
    // No curves carried: nothing to count.
    assert_eq!(
        gc.carried_broken_features(&vec![0u8; 64 * 64]).unwrap(),
        0.0
    );
    assert!(error_message(gc.carried_broken_features(&mask[1..])).contains("featureMask"));
    let mut deformed = GraphcutTextures::new(
        &ex,
        options(&[
            ("outputWidth", 64.into()),
            ("outputHeight", 64.into()),
            ("mirror", true.into()),
        ]),
    )
    .unwrap();
    deformed.step().unwrap();
    assert!(error_message(deformed.carried_broken_features(&mask)).contains("sources"));
    assert!(error_message(deformed.carried_broken_features_of(&map)).contains("map"));
}
