//! The JS-facing graph-cut video textures (Kwatra et al. 2003, section 7), as JavaScript calls
//! them (Node and Chromium), on the repository's demo clip: a loop that is continuous where it
//! wraps, the views, a spatial extension, and bad input.

use js_sys::Uint8ClampedArray;
use texsynth::bindings::{Exemplar, VideoClip, VideoTextures};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::js_helpers::{error_message, get, options};

/// `scripts/make-demo-clip.mjs`: 60 frames of 128x128 stacked top to bottom.
const WATER: &[u8] = include_bytes!("../../www/samples/clips/water.png");

/// The first `frames` frames of the demo clip, every `step`-th pixel (a small clip runs fast).
fn demo_clip(frames: u32, step: usize) -> VideoClip {
    let strip = Exemplar::from_bytes(WATER).unwrap();
    assert_eq!((strip.width(), strip.height()), (128, 128 * 60));
    let rgba = strip.to_rgba().to_vec();
    let side = 128 / step;
    let mut out = Vec::with_capacity(side * side * 4 * frames as usize);
    for t in 0..frames as usize {
        for y in 0..side {
            for x in 0..side {
                let i = ((t * 128 + y * step) * 128 + x * step) * 4;
                out.extend_from_slice(&rgba[i..i + 4]);
            }
        }
    }
    VideoClip::from_frames(side as u32, side as u32, frames, &out).unwrap()
}

fn mean_difference(a: &[u8], b: &[u8]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| f64::from(x.abs_diff(y)))
        .sum::<f64>()
        / a.len() as f64
}

#[wasm_bindgen_test]
fn the_demo_clip_loops_without_a_jump() {
    let clip = demo_clip(30, 4);
    let mut video = VideoTextures::new(&clip, JsValue::UNDEFINED).unwrap();
    let mut steps = 0;
    let mut last = JsValue::UNDEFINED;
    while !video.done() {
        last = video.step().unwrap();
        steps += 1;
        assert!(steps < 500, "the loop finishes");
    }
    assert!(get(&last, "done").as_bool().unwrap());
    let (w, h, d) = (video.width(), video.height(), video.frames());
    assert_eq!((w, h), (32, 32));
    assert!(d >= 2);
    let frames: Vec<Vec<u8>> = (0..d).map(|t| video.frame(t).unwrap().to_vec()).collect();
    let consecutive = (1..frames.len())
        .map(|t| mean_difference(&frames[t - 1], &frames[t]))
        .sum::<f64>()
        / (frames.len() - 1) as f64;
    let wrap = mean_difference(&frames[frames.len() - 1], &frames[0]);
    assert!(
        wrap <= consecutive * 1.5 + 1e-9,
        "the jump from the last frame to the first ({wrap:.2}) is like a step between frames ({consecutive:.2})"
    );
    // The views: the frame filled in, an x-t slice of width x frames, a seam overlay.
    let into = Uint8ClampedArray::new_with_length(w * h * 4);
    video.render_frame_into(0, &into).unwrap();
    assert_eq!(into.to_vec(), frames[0]);
    assert!(frames[0].chunks(4).all(|p| p[3] == 255));
    assert_eq!(video.slice_xt(h / 2).unwrap().length(), w * d * 4);
    assert_eq!(video.seams(0).unwrap().length(), w * h * 4);
    assert!(error_message(video.frame(d)).contains("frame"));
    assert!(error_message(video.slice_xt(h)).contains("row"));
}

#[wasm_bindgen_test]
fn a_spatial_extension_covers_every_voxel() {
    let clip = demo_clip(12, 8);
    for placement in ["random", "entire-patch", "sub-patch"] {
        let mut video = VideoTextures::new(
            &clip,
            options(&[
                ("mode", "extend".into()),
                ("placement", placement.into()),
                ("outputWidth", 24.into()),
                ("outputHeight", 20.into()),
                ("outputFrames", 16.into()),
                ("fixedFrames", 0.into()),
            ]),
        )
        .unwrap();
        let mut steps = 0;
        while !video.done() {
            video.step().unwrap();
            steps += 1;
            assert!(steps < 2000, "{placement}");
        }
        assert_eq!(
            (video.width(), video.height(), video.frames()),
            (24, 20, 16)
        );
        for t in 0..16 {
            let frame = video.frame(t).unwrap().to_vec();
            assert!(frame.chunks(4).all(|p| p[3] == 255), "{placement}");
        }
    }
}

#[wasm_bindgen_test]
fn bad_video_input_is_named() {
    assert!(error_message(VideoClip::from_frames(4, 4, 3, &[0; 10])).contains("length"));
    let clip = demo_clip(12, 8);
    let msg = |v: JsValue| error_message(VideoTextures::new(&clip, v));
    assert!(msg(options(&[("mode", "bounce".into())])).contains("'loop', 'offsets' or 'extend'"));
    assert!(msg(options(&[("k", f64::NAN.into())])).contains('k'));
    assert!(msg(options(&[("colour", 1.into())])).contains("colour"));
    assert!(
        msg(options(&[
            ("mode", "extend".into()),
            ("fixedFrames", 40.into())
        ]))
        .contains("fixedFrames")
    );
}
