//! Inpainting's tests: the known pixels never change, the fill follows the texture, the hole
//! fills completely, and the fill's choice agrees with a brute-force search on a tiny case.

use super::*;
use crate::core::testing::{noise, sample};
use crate::core::Image;

/// A centred square hole of `share` of the image's pixels.
fn centred_hole(w: usize, h: usize, share: f64) -> Vec<u8> {
    let side = ((w * h) as f64 * share).sqrt() as usize;
    let (x0, y0) = ((w - side) / 2, (h - side) / 2);
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            u8::from(x >= x0 && x < x0 + side && y >= y0 && y < y0 + side)
        })
        .collect()
}

/// A sample texture's top-left `w` x `h` corner.
fn sample_image(w: usize, h: usize) -> Image {
    sample("gravel_128").with_channels(3).unwrap().crop(0, 0, w, h).unwrap()
}

fn run(session: &mut Session) -> Vec<Event> {
    let mut events = Vec::new();
    for _ in 0..100_000 {
        let e = session.step().unwrap();
        events.push(e);
        if e.kind == EventKind::Done {
            return events;
        }
    }
    panic!("the session never finished");
}

#[test]
fn known_pixels_never_change_and_the_hole_fills() {
    // A quarter and 40% of a small image: coarse levels and large neighbourhoods that find
    // nothing outside the larger hole are dropped, not refused.
    for share in [0.25, 0.4] {
        let image = sample_image(64, 64);
        let mask = centred_hole(64, 64, share);
        let mut session = Session::new(&image, &mask, None, Options::default()).unwrap();
        let events = run(&mut session);
        let out = session.output().unwrap();
        for (i, &m) in mask.iter().enumerate() {
            if m == 0 {
                assert_eq!(out.pixel(i % 64, i / 64), image.pixel(i % 64, i / 64), "pixel {i}");
            }
        }
        // The fill reached every hole pixel, then the optimisation ran to the end.
        let fill_end = events.iter().rposition(|e| e.stage == Stage::Fill).unwrap();
        assert_eq!(events[fill_end].pixels_filled, events[fill_end].hole_pixels);
        assert!(
            events
                .iter()
                .any(|e| e.stage == Stage::Optimization && e.energy.is_some())
        );
        // Every filled value is finite and in the image's range.
        assert!(
            out.data()
                .iter()
                .all(|v| v.is_finite() && (-0.01..=1.01).contains(v))
        );
    }
}

#[test]
fn a_periodic_texture_is_continued_across_the_hole() {
    // Stripes of period 8: a fill from the image itself must continue them exactly (the
    // source holds the same stripes at every phase), so the filled region equals the stripes.
    let stripes = |x: usize, y: usize| if (x + 2 * y) % 8 < 4 { 0.9 } else { 0.1 };
    let image = Image::from_fn(80, 80, 1, |x, y, _| stripes(x, y)).unwrap();
    let mask = centred_hole(80, 80, 0.16);
    let options = Options {
        optimize: false,
        ..Options::default()
    };
    let mut session = Session::new(&image, &mask, None, options).unwrap();
    run(&mut session);
    let out = session.output().unwrap();
    let wrong = (0..80 * 80)
        .filter(|&i| (out.pixel(i % 80, i / 80)[0] - stripes(i % 80, i / 80)).abs() > 1e-6)
        .count();
    assert_eq!(wrong, 0, "{wrong} pixels break the stripes");
}

#[test]
fn the_fill_takes_the_best_source_window_by_brute_force() {
    // With k tiny, eq. 3 picks the best window: check it against a direct SSD over every usable
    // window, on a 20x20 random image with a 4x4 hole and patches of 6.
    let image = noise(20, 20, 3, 3);
    let mut mask = vec![0u8; 400];
    for y in 8..12 {
        for x in 8..12 {
            mask[y * 20 + x] = 1;
        }
    }
    let hole = Hole::new(20, 20, &mask).unwrap();
    let known: Vec<bool> = hole.mask.iter().map(|&m| !m).collect();
    let source = fill::FillSource {
        image: image.clone(),
        unknown: Some(hole.mask.clone()),
        region_origin: Some((0, 0)),
    };
    let mut f = fill::Fill::new(image.clone(), known.clone(), source, 6, 1e-9, 1).unwrap();
    let placed = f.place().unwrap();
    let (x0, y0) = (placed.x, placed.y);
    let mut best = (f64::INFINITY, (0, 0));
    for sy in 0..=14 {
        for sx in 0..=14 {
            let usable = (sy..sy + 6).all(|y| (sx..sx + 6).all(|x| !hole.mask[y * 20 + x]));
            if !usable {
                continue;
            }
            let mut ssd = 0.0f64;
            for v in 0..6 {
                for u in 0..6 {
                    if known[(y0 + v) * 20 + x0 + u] {
                        for c in 0..3 {
                            let d = image.pixel(x0 + u, y0 + v)[c] - image.pixel(sx + u, sy + v)[c];
                            ssd += f64::from(d * d);
                        }
                    }
                }
            }
            if ssd < best.0 {
                best = (ssd, (sx, sy));
            }
        }
    }
    assert_eq!((placed.source_x, placed.source_y), best.1);
}

#[test]
fn uncrop_extends_the_border_and_keeps_the_image() {
    let image = sample_image(48, 40);
    let (big, mask) = extend(&image, Border::all(8)).unwrap();
    let mut session = Session::new(&big, &mask, None, Options::default()).unwrap();
    run(&mut session);
    let out = session.output().unwrap();
    assert_eq!((out.width(), out.height()), (64, 56));
    let inner = out.crop(8, 8, 48, 40).unwrap();
    assert_eq!(inner.data(), image.data());
}

#[test]
fn a_separate_exemplar_fills_and_bad_inputs_are_named() {
    let image = sample_image(48, 48);
    let exemplar = sample_image(32, 32);
    let mask = centred_hole(48, 48, 0.3);
    let mut session = Session::new(&image, &mask, Some(&exemplar), Options::default()).unwrap();
    run(&mut session);
    let msg = |r: crate::core::Result<Session>| r.err().unwrap().to_string();
    assert!(msg(Session::new(&image, &mask[1..], None, Options::default())).contains("mask"));
    assert!(msg(Session::new(&image, &vec![0; 48 * 48], None, Options::default())).contains("empty"));
    assert!(msg(Session::new(&image, &vec![1; 48 * 48], None, Options::default())).contains("full"));
    let grey = exemplar.with_channels(1).unwrap();
    assert!(msg(Session::new(&image, &mask, Some(&grey), Options::default())).contains("exemplar"));
    let small = sample_image(12, 40);
    assert!(msg(Session::new(&small, &vec![1; 480], None, Options::default())).contains("16x16"));
    let bad = Options {
        patch_size: 2,
        ..Options::default()
    };
    assert!(msg(Session::new(&image, &mask, None, bad)).contains("patchSize"));
}

#[test]
fn same_seed_same_bytes() {
    let image = sample_image(48, 48);
    let mask = centred_hole(48, 48, 0.2);
    let out = || {
        let mut s = Session::new(&image, &mask, None, Options::default()).unwrap();
        run(&mut s);
        s.output().unwrap().into_vec()
    };
    assert_eq!(out(), out());
}
