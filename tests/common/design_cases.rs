//! The JS-facing texture-design API (Shen et al. 2009), as JavaScript calls it (Node and
//! Chromium): deformations, the brush with undo, layer-based design and tileable textures, and
//! their bad input.

use js_sys::{Array, Uint8ClampedArray};
use texsynth::bindings::{
    Exemplar, LayerDesign, TextureBrush, TileableTexture, deform_texture, deformation_set,
    make_tileable,
};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

const TILES_64: &[u8] = include_bytes!("../../www/samples/tiles_64.png");
const PAVING_64: &[u8] = include_bytes!("../../www/samples/paving_64.png");

fn range(from: f64, to: f64, step: f64) -> JsValue {
    options(&[
        ("from", from.into()),
        ("to", to.into()),
        ("step", step.into()),
    ])
}

fn pixels(exemplar: &Exemplar) -> Vec<u8> {
    exemplar.to_rgba().to_vec()
}

#[wasm_bindgen_test]
fn deformations_are_exact_where_they_can_be() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let mirror = options(&[("mirror", true.into())]);
    let twice = Array::of2(&mirror, &mirror);
    assert_eq!(
        pixels(&deform_texture(&ex, twice.into()).unwrap()),
        pixels(&ex)
    );
    let quarter = options(&[("rotate", 90.into())]);
    let four = Array::of4(&quarter, &quarter, &quarter, &quarter);
    assert_eq!(
        pixels(&deform_texture(&ex, four.into()).unwrap()),
        pixels(&ex)
    );
    let turned = deform_texture(&ex, options(&[("rotate", 30.into())])).unwrap();
    assert!(turned.width() < 64 && turned.width() > 30);
    let set = deformation_set(
        &ex,
        options(&[
            ("rotation", range(0.0, 60.0, 30.0)),
            ("scale", range(0.5, 1.0, 0.5)),
            ("mirror", true.into()),
        ]),
    )
    .unwrap();
    let labels: Vec<String> = set
        .iter()
        .map(|item| get(&item, "label").as_string().unwrap())
        .collect();
    assert_eq!(labels, ["rotate 30°", "rotate 60°", "scale 0.5x", "mirror"]);
    assert!(get(&set.get(2), "exemplar").is_object());
}

#[wasm_bindgen_test]
fn bad_deformations_are_named_errors() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let msg = |v: JsValue| error_message(deform_texture(&ex, v));
    assert!(msg(options(&[("rotate", f64::NAN.into())])).contains("rotate"));
    assert!(msg(options(&[("scale", 40.into())])).contains("scale"));
    assert!(msg(options(&[("spin", 3.into())])).contains("unknown option 'spin'"));
    assert!(
        msg(options(&[("rotate", 3.into()), ("flip", true.into())])).contains("one deformation")
    );
    assert!(msg(options(&[("shift", "far".into())])).contains("shift"));
    let set = |v: JsValue| error_message(deformation_set(&ex, v));
    assert!(set(options(&[("rotation", range(0.0, 360.0, 1.0))])).contains("at most 64"));
    assert!(set(options(&[("scale", options(&[("from", 1.into())]))])).contains("needs 'to'"));
    assert!(set(options(&[("rotation", range(10.0, 0.0, 1.0))])).contains("rotation"));
}

fn disc(w: usize, h: usize, cx: f64, cy: f64, r: f64) -> Vec<u8> {
    (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f64 - cx, (i / w) as f64 - cy);
            u8::from(x * x + y * y <= r * r)
        })
        .collect()
}

#[wasm_bindgen_test]
fn a_brush_stroke_changes_the_base_and_undo_restores_it() {
    let base = Exemplar::from_bytes(TILES_64).unwrap();
    let reference = Exemplar::from_bytes(PAVING_64).unwrap();
    let mut brush = TextureBrush::new(&base, JsValue::UNDEFINED).unwrap();
    let before = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    brush.render_into(&before).unwrap();
    let mask = disc(64, 64, 30.0, 30.0, 7.0);
    let r = brush.stroke(&reference, &mask, 4, -2).unwrap();
    assert!(get(&r, "pixelsTaken").as_f64().unwrap() >= 150.0);
    assert!(get(&r, "poissonIterations").as_f64().unwrap() > 0.0);
    let after = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    brush.render_into(&after).unwrap();
    assert_ne!(before.to_vec(), after.to_vec());
    let labels = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    brush.render_labels_into(&labels).unwrap();
    assert!(
        labels.to_vec().chunks(4).any(|p| p == [255, 40, 40, 255]),
        "a seam is drawn"
    );
    assert_eq!(brush.undo_depth(), 1);
    assert!(brush.undo());
    brush.render_into(&after).unwrap();
    assert_eq!(before.to_vec(), after.to_vec());
    assert!(!brush.undo());
}

#[wasm_bindgen_test]
fn bad_strokes_are_named_and_change_nothing() {
    let base = Exemplar::from_bytes(TILES_64).unwrap();
    let reference = Exemplar::from_bytes(PAVING_64).unwrap();
    let mut brush = TextureBrush::new(&base, JsValue::UNDEFINED).unwrap();
    assert!(
        error_message(brush.stroke(&reference, &[1; 10], 0, 0))
            .contains("stroke mask has length 10")
    );
    assert!(
        error_message(brush.stroke(&reference, &vec![0; 64 * 64], 0, 0))
            .contains("paints no pixel")
    );
    let mask = disc(64, 64, 30.0, 30.0, 5.0);
    assert!(error_message(brush.stroke(&reference, &mask, 500, 0)).contains("off the 64x64 base"));
    assert_eq!(brush.undo_depth(), 0);
    let msg = |v: JsValue| error_message(TextureBrush::new(&base, v));
    assert!(msg(options(&[("nu", (-1).into())])).contains("nu"));
    assert!(msg(options(&[("k1", f64::NAN.into())])).contains("k1"));
    assert!(msg(options(&[("margins", 3.into())])).contains("unknown option 'margins'"));
}

#[wasm_bindgen_test]
fn a_layer_design_fills_its_layout_row_by_row() {
    let tiles = Exemplar::from_bytes(TILES_64).unwrap();
    let paving = Exemplar::from_bytes(PAVING_64).unwrap();
    let (w, h) = (120usize, 90usize);
    let mut design = LayerDesign::new(options(&[
        ("outputWidth", (w as u32).into()),
        ("outputHeight", (h as u32).into()),
        ("patchSize", 24.into()),
    ]))
    .unwrap();
    assert!(error_message(design.step()).contains("addLayer"));
    assert_eq!(design.add_layer(&tiles, JsValue::UNDEFINED).unwrap(), 0);
    let turn = options(&[("rotate", 90.into())]);
    assert_eq!(design.add_layer(&paving, turn).unwrap(), 1);
    let layout: Vec<u8> = (0..w * h).map(|i| u8::from(i % w >= w / 2)).collect();
    design.set_layout(&layout).unwrap();
    let mut rows = 0;
    while !design.done() {
        let e = design.step().unwrap();
        rows += 1;
        assert!(rows < 50);
        assert!(get(&e, "pixelsCompared").as_f64().unwrap() >= 0.0);
    }
    let out = Uint8ClampedArray::new_with_length((w * h * 4) as u32);
    design.render_into(&out).unwrap();
    assert!(out.to_vec().chunks(4).all(|p| p[3] == 255));
    assert_eq!(design.to_exemplar().unwrap().width(), w as u32);
}

#[wasm_bindgen_test]
fn bad_layer_designs_are_named() {
    let tiles = Exemplar::from_bytes(TILES_64).unwrap();
    let msg = |v: JsValue| error_message(LayerDesign::new(v));
    assert!(msg(options(&[("patchSize", 4.into())])).contains("patchSize"));
    assert!(msg(options(&[("search", "fast".into())])).contains("'qtp' or 'exhaustive'"));
    assert!(msg(options(&[("tolerance", f64::INFINITY.into())])).contains("tolerance"));
    assert!(msg(options(&[("outputWidth", 10.into())])).contains("output"));
    let mut design = LayerDesign::new(options(&[("patchSize", 92.into())])).unwrap();
    assert!(
        error_message(design.add_layer(&tiles, JsValue::UNDEFINED))
            .contains("smaller than the patch size")
    );
    assert!(error_message(design.set_layout(&[0; 3])).contains("layout has length 3"));
}

#[wasm_bindgen_test]
fn make_tileable_returns_a_seamless_smaller_texture() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let t = make_tileable(&ex, JsValue::UNDEFINED).unwrap();
    let out: Exemplar = {
        let v = get(&t, "exemplar");
        // wasm-bindgen hands exported structs to JS as objects wrapping a pointer; take it back.
        Exemplar::from_rgba(
            &js_sys::Reflect::get(&v, &"toRgba".into())
                .unwrap()
                .unchecked_into::<js_sys::Function>()
                .call0(&v)
                .unwrap()
                .unchecked_into::<Uint8ClampedArray>()
                .to_vec(),
            54,
            54,
        )
        .unwrap()
    };
    assert_eq!((out.width(), out.height()), (54, 54));
    assert!(get(&t, "seamCostX").as_f64().unwrap() >= 0.0);
    assert!(
        error_message(make_tileable(&ex, options(&[("overlapX", 40.into())]))).contains("overlapX")
    );
    let tiny = Exemplar::from_rgba(&[0; 8 * 8 * 4], 8, 8).unwrap();
    assert!(error_message(make_tileable(&tiny, JsValue::UNDEFINED)).contains("at least 16"));
    assert!(error_message(TileableTexture::new(&tiny, JsValue::UNDEFINED)).contains("at least 16"));
}

#[wasm_bindgen_test]
fn a_tileable_session_makes_one_stitch_per_step() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let mut s = TileableTexture::new(&ex, JsValue::UNDEFINED).unwrap();
    assert!(error_message(s.result()).contains("not done"));
    let first = s.step().unwrap();
    assert_eq!(get(&first, "axis").as_string().unwrap(), "x");
    assert_eq!((s.width(), s.height()), (54, 64));
    let second = s.step().unwrap();
    assert_eq!(get(&second, "kind").as_string().unwrap(), "done");
    assert!(s.done());
    assert_eq!((s.width(), s.height()), (54, 54));
    assert!(get(&s.result().unwrap(), "cutY").as_f64().is_some());
}
