//! The JS-facing graph-cut sessions, as JavaScript calls them (Node and Chromium).

use js_sys::Uint8ClampedArray;
use texsynth::bindings::{Exemplar, GraphcutMerge, GraphcutTextures, measure_quality};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

const TILES_64: &[u8] = include_bytes!("../../www/samples/tiles_64.png");
const SAND_64: &[u8] = include_bytes!("../../www/samples/sand_64.png");

#[wasm_bindgen_test]
fn a_graphcut_session_places_patches_until_done() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let opts = options(&[
        ("outputWidth", 96.into()),
        ("outputHeight", 80.into()),
        ("refinementPatches", 3.into()),
        ("blend", "feather".into()),
    ]);
    let mut session = GraphcutTextures::new(&ex, opts).unwrap();
    assert_eq!((session.width(), session.height()), (96, 80));
    assert!(session.error_region().is_null());
    let first = session.step().unwrap();
    assert_eq!(get(&first, "kind").as_string().unwrap(), "placed");
    assert!(get(&first, "pixelsTaken").as_f64().unwrap() > 0.0);
    let mut steps = 1;
    let mut last = first;
    while !session.done() {
        last = session.step().unwrap();
        steps += 1;
        assert!(steps < 200);
    }
    assert_eq!(get(&last, "kind").as_string().unwrap(), "done");
    assert!(get(&last, "covered").as_bool().unwrap());
    assert!(get(&last, "totalSeamCost").as_f64().unwrap() > 0.0);
    let target = Uint8ClampedArray::new_with_length(96 * 80 * 4);
    session.render_into(&target).unwrap();
    assert!(target.to_vec().chunks(4).all(|p| p[3] == 255));
    session.render_seams_into(&target).unwrap();
    assert!(target.to_vec().chunks(4).any(|p| p[3] == 255), "some seams");
    session.render_seam_cost_into(&target).unwrap();
    session.render_labels_into(&target).unwrap();
    assert!(!get(&session.error_region(), "width").is_undefined());
    assert_eq!(session.sources(), vec!["exemplar".to_string()]);
}

#[wasm_bindgen_test]
fn graphcut_options_are_checked_by_name() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let msg =
        |entries: &[(&str, JsValue)]| error_message(GraphcutTextures::new(&ex, options(entries)));
    assert!(msg(&[("placment", "random".into())]).contains("unknown option 'placment'"));
    assert!(msg(&[("placement", "best".into())]).contains("invalid placement"));
    assert!(msg(&[("k", 0.into())]).contains("invalid k"));
    assert!(msg(&[("k", f64::NAN.into())]).contains("invalid k"));
    assert!(msg(&[("blend", 3.into())]).contains("invalid blend"));
    assert!(msg(&[("scales", "big".into())]).contains("invalid scales"));
    assert!(msg(&[("scales", js_sys::Array::of1(&0.01.into()).into())]).contains("scales"));
    assert!(msg(&[("errorRegion", 500.into())]).contains("errorRegion"));
    let target = Uint8ClampedArray::new_with_length(3);
    let session = GraphcutTextures::new(&ex, JsValue::UNDEFINED).unwrap();
    assert!(error_message(session.render_labels_into(&target)).contains("target pixel array"));
}

#[wasm_bindgen_test]
fn a_merge_honours_painted_constraints() {
    let tiles = Exemplar::from_bytes(TILES_64).unwrap();
    let sand = Exemplar::from_bytes(SAND_64).unwrap();
    let (w, h) = (100usize, 64usize);
    let mut merge = GraphcutMerge::new(options(&[
        ("outputWidth", (w as u32).into()),
        ("outputHeight", (h as u32).into()),
        ("gradientCost", true.into()),
    ]))
    .unwrap();
    assert_eq!(merge.add_source(&tiles, 0, 0).unwrap(), 0);
    assert_eq!(merge.add_source(&sand, 36, 0).unwrap(), 1);
    let mut mask = vec![0u8; w * h];
    for y in 0..h {
        mask[y * w + 40] = 1; // inside the overlap, but painted for the tiles
        mask[y * w + 62] = 2; // painted for the sand
    }
    merge.set_constraints(&mask).unwrap();
    while !merge.done() {
        merge.step().unwrap();
    }
    let target = Uint8ClampedArray::new_with_length((w * h * 4) as u32);
    merge.render_sources_into(&target).unwrap();
    let colours = target.to_vec();
    let colour = |x: usize, y: usize| colours[(y * w + x) * 4..(y * w + x) * 4 + 3].to_vec();
    for y in 0..h {
        assert_eq!(
            colour(40, y),
            colour(0, y),
            "row {y}: painted pixel keeps the first source"
        );
        assert_eq!(
            colour(62, y),
            colour(99, y),
            "row {y}: painted pixel takes the second source"
        );
    }
    // Every pixel comes from one source: the tiles at least up to their paint, the sand at
    // least from its paint to the right edge.
    let counts = merge.source_pixels().to_vec();
    assert_eq!(counts.len(), 2);
    assert_eq!(counts[0] + counts[1], (w * h) as u32);
    assert!(counts[0] >= (41 * h) as u32 && counts[1] >= ((w - 62) * h) as u32);
    merge.render_into(&target).unwrap();
    merge.render_seams_into(&target).unwrap();
    assert!(error_message(merge.set_constraints(&[0; 5])).contains("constraint mask"));
    // Paint for the tiles beyond their right edge: the first step names the pixel.
    let mut outside = GraphcutMerge::new(options(&[
        ("outputWidth", (w as u32).into()),
        ("outputHeight", (h as u32).into()),
    ]))
    .unwrap();
    outside.add_source(&tiles, 0, 0).unwrap();
    outside.add_source(&sand, 36, 0).unwrap();
    mask[3 * w + 80] = 1;
    outside.set_constraints(&mask).unwrap();
    let message = error_message(outside.step());
    assert!(
        message.contains("(80, 3)") && message.contains("does not cover"),
        "{message}"
    );
    assert!(
        error_message(GraphcutMerge::new(options(&[
            ("outputWidth", 0.into()),
            ("outputHeight", 5.into())
        ])))
        .contains("outputWidth")
    );
}

#[wasm_bindgen_test]
fn quality_of_a_rendered_output() {
    let ex = Exemplar::from_bytes(TILES_64).unwrap();
    let opts = options(&[
        ("outputWidth", 64.into()),
        ("outputHeight", 64.into()),
        ("refinementPatches", 2.into()),
    ]);
    let mut session = GraphcutTextures::new(&ex, opts).unwrap();
    while !session.done() {
        session.step().unwrap();
    }
    let target = Uint8ClampedArray::new_with_length(64 * 64 * 4);
    session.render_into(&target).unwrap();
    let q = measure_quality(&ex, &target.to_vec(), 64, 64).unwrap();
    let coherence = get(&q, "coherence").as_f64().unwrap();
    // Graph cut copies exemplar pixels: coherence is near zero except across seams.
    assert!((0.0..0.01).contains(&coherence), "{coherence}");
    // Completeness against an output that uses nothing of the exemplar, scored the same way: one
    // flat colour, the exemplar's mean (0.011 on tiles; noise scores 0.077). Graph cut lays down
    // whole regions of the exemplar (0.0002 to 0.0005 on seeds 1-3), far below a tenth of it.
    let completeness = get(&q, "completeness").as_f64().unwrap();
    let flat = measure_quality(&ex, &flat_rgba(&ex, 64 * 64), 64, 64).unwrap();
    let flat_completeness = get(&flat, "completeness").as_f64().unwrap();
    assert!(
        completeness < flat_completeness / 10.0,
        "completeness {completeness}, a flat image {flat_completeness}"
    );
    // The detail metric: the flat image is flat everywhere, graph cut's output about as often
    // as the exemplar itself (0.10).
    assert_eq!(get(&flat, "flat").as_f64().unwrap(), 1.0);
    let detail = get(&q, "flat").as_f64().unwrap();
    assert!(detail < 0.25, "flat fraction {detail}");
    assert!(error_message(measure_quality(&ex, &[0; 10], 64, 64)).contains("RGBA pixel data"));
    assert!(error_message(measure_quality(&ex, &[0; 4 * 16], 4, 4)).contains("output size 4x4"));
}

/// `pixels` RGBA pixels of the exemplar's mean colour.
fn flat_rgba(ex: &Exemplar, pixels: usize) -> Vec<u8> {
    let rgba = ex.to_rgba().to_vec();
    let mut sums = [0u64; 4];
    for pixel in rgba.chunks_exact(4) {
        for (sum, &v) in sums.iter_mut().zip(pixel) {
            *sum += u64::from(v);
        }
    }
    let n = (rgba.len() / 4) as u64;
    sums.map(|sum| (sum / n) as u8).repeat(pixels)
}

#[wasm_bindgen_test]
fn a_huge_output_is_refused_by_the_constructor_naming_the_budget() {
    let ex = Exemplar::from_bytes(include_bytes!("../../www/samples/gravel_64.png")).unwrap();
    let msg = error_message(GraphcutTextures::new(
        &ex,
        options(&[
            ("outputWidth", 4096.into()),
            ("outputHeight", 4096.into()),
            ("memoryBudgetMiB", 64.into()),
        ]),
    ));
    assert!(
        msg.starts_with("output 4096x4096: graph-cut synthesis needs about")
            && msg.contains("memory budget of 64 MiB"),
        "{msg}"
    );
    let msg = error_message(GraphcutTextures::new(
        &ex,
        options(&[("memoryBudgetMiB", f64::NAN.into())]),
    ));
    assert!(msg.starts_with("invalid memoryBudgetMiB"), "{msg}");
}

/// A photo larger than 512 a side is accepted: each placement copies a window of at
/// most 512x512 of it, drawn afresh, so its steps cost what a 512x512 exemplar's do.
#[wasm_bindgen_test]
fn a_graphcut_session_accepts_a_large_exemplar() {
    let (w, h) = (1600usize, 1200usize);
    let rgba: Vec<u8> = (0..w * h)
        .flat_map(|i| {
            let (x, y) = (i % w, i / w);
            let v = ((x * 7 + y * 3) % 97 + (x / 50 + y / 40) % 3 * 50) as u8;
            [v, v / 2 + 40, 255 - v, 255]
        })
        .collect();
    let ex = Exemplar::from_rgba(&rgba, w as u32, h as u32).unwrap();
    for placement in ["entire-patch", "sub-patch", "random"] {
        let opts = options(&[
            ("outputWidth", 64.into()),
            ("outputHeight", 64.into()),
            ("placement", placement.into()),
            ("refinementPatches", 2.into()),
        ]);
        let mut session = GraphcutTextures::new(&ex, opts).unwrap();
        let mut windows = Vec::new();
        for _ in 0..3 {
            let event = session.step().unwrap();
            let rect = get(&event, "rect");
            assert!(
                get(&rect, "width").as_f64().unwrap() <= 512.0,
                "{placement}"
            );
            assert!(
                get(&rect, "height").as_f64().unwrap() <= 512.0,
                "{placement}"
            );
            let patch = get(&event, "patch");
            let (wx, wy) = (
                get(&patch, "windowX").as_f64().unwrap(),
                get(&patch, "windowY").as_f64().unwrap(),
            );
            assert!(wx + 512.0 <= w as f64 && wy + 512.0 <= h as f64);
            windows.push((wx as u32, wy as u32));
        }
        assert!(
            session.done(),
            "{placement}: covered and refined in 3 steps"
        );
        assert!(windows.iter().any(|&w| w != windows[0]), "{placement}");
    }
}
