//! Guided synthesis: the output follows the target guide where the source guide says which
//! exemplar parts look like what.

use super::{Options, Session};
use crate::core::Image;
use crate::core::testing::sample;

/// Mean of channel 0 over the columns `x0..x1` of `image`.
fn mean(image: &Image, x0: usize, x1: usize) -> f32 {
    let mut sum = 0.0;
    for y in 0..image.height() {
        for x in x0..x1 {
            sum += image.pixel(x, y)[0];
        }
    }
    sum / ((x1 - x0) * image.height()) as f32
}

fn run(mut session: Session) -> Image {
    while !session.is_done() {
        session.step().unwrap();
    }
    session.output_full_size().unwrap()
}

#[test]
fn the_output_follows_the_target_guide() {
    // The exemplar's own values as its guide; the target asks for dark on the left, bright on
    // the right. Unguided, both halves have the exemplar's mean.
    let exemplar = sample("gravel_64").with_channels(1).unwrap();
    let target = Image::from_fn(64, 48, 1, |x, _, _| if x < 32 { 0.2 } else { 0.8 }).unwrap();
    let options = Options {
        output_width: 64,
        output_height: 48,
        histogram_matching: 0.0,
        completeness: 0.0,
        ..Options::default()
    };
    let plain = run(Session::new(&exemplar, options.clone()).unwrap());
    let mut guided = Session::new(&exemplar, options).unwrap();
    guided.set_guides(&exemplar, &target, 4.0).unwrap();
    let guided = run(guided);
    let (left, right) = (mean(&guided, 0, 24), mean(&guided, 40, 64));
    let (plain_left, plain_right) = (mean(&plain, 0, 24), mean(&plain, 40, 64));
    assert!(right - left > 0.15, "guided: left {left}, right {right}");
    assert!((plain_right - plain_left).abs() < 0.1, "plain: {plain_left}, {plain_right}");
}

#[test]
fn bad_guides_are_named() {
    let exemplar = sample("gravel_64");
    let options = Options {
        output_width: 40,
        output_height: 40,
        ..Options::default()
    };
    let mut s = Session::new(&exemplar, options).unwrap();
    let target = Image::new(40, 40, 1).unwrap();
    let grey = exemplar.with_channels(1).unwrap();
    let msg = |r: crate::core::Result<()>| r.unwrap_err().to_string();
    assert!(msg(s.set_guides(&target, &target, 1.0)).contains("sourceGuide"));
    assert!(msg(s.set_guides(&grey, &Image::new(8, 8, 1).unwrap(), 1.0)).contains("targetGuide"));
    assert!(msg(s.set_guides(&grey, &Image::new(40, 40, 2).unwrap(), 1.0)).contains("channels"));
    assert!(msg(s.set_guides(&grey, &target, f32::NAN)).contains("guideWeight"));
    assert!(s.set_guides(&grey, &target, 1.0).is_ok());
    s.step().unwrap();
    assert!(msg(s.set_guides(&grey, &target, 1.0)).contains("before the first step"));
}

#[test]
fn with_several_exemplars_each_guide_steers_towards_its_exemplar() {
    // Two exemplars of different textures, each with a flat source guide of its own value: a
    // target guide of 0 on the left and 1 on the right takes the first exemplar's matches on
    // the left and the second's on the right.
    let first = sample("gravel_64");
    let second = sample("tiles_64");
    let flat = |v: f32| Image::from_fn(64, 64, 1, move |_, _, _| v).unwrap();
    let target = Image::from_fn(64, 48, 1, |x, _, _| if x < 32 { 0.0 } else { 1.0 }).unwrap();
    let options = Options {
        output_width: 64,
        output_height: 48,
        ..Options::default()
    };
    let mut s = Session::with_exemplars(&[first, second], options).unwrap();
    s.set_exemplar_guides(&[flat(0.0), flat(1.0)], &target, 4.0).unwrap();
    let s = {
        let mut s = s;
        while !s.is_done() {
            s.step().unwrap();
        }
        s
    };
    let map = s.exemplar_map().unwrap();
    let level = s.current_level();
    let (w, h) = (level.output_width, level.output_height);
    let share_of_second = |x0: usize, x1: usize| {
        let (mut second, mut all) = (0, 0);
        for y in 0..h {
            for x in x0..x1 {
                second += map[y * w + x];
                all += 1;
            }
        }
        second as f32 / all as f32
    };
    let (left, right) = (share_of_second(0, w * 3 / 8), share_of_second(w * 5 / 8, w));
    assert!(left < 0.1 && right > 0.9, "second exemplar's share: left {left}, right {right}");
}

#[test]
fn bad_guides_of_several_exemplars_are_named() {
    let (first, second) = (sample("gravel_64"), sample("tiles_64"));
    let options = Options {
        output_width: 40,
        output_height: 40,
        ..Options::default()
    };
    let mut s = Session::with_exemplars(&[first.clone(), second], options.clone()).unwrap();
    let target = Image::new(40, 40, 1).unwrap();
    let guide = Image::new(64, 64, 1).unwrap();
    let msg = |r: crate::core::Result<()>| r.unwrap_err().to_string();
    // One guide for a session of two, a guide of the wrong size, the single-exemplar call.
    assert!(msg(s.set_exemplar_guides(std::slice::from_ref(&guide), &target, 1.0)).contains("one source guide per exemplar (2)"));
    let small = Image::new(32, 32, 1).unwrap();
    assert!(msg(s.set_exemplar_guides(&[guide.clone(), small], &target, 1.0)).contains("guide 2 is 32x32"));
    assert!(msg(s.set_guides(&guide, &target, 1.0)).contains("several exemplars"));
    assert!(s.set_exemplar_guides(&[guide.clone(), guide.clone()], &target, 1.0).is_ok());
    // With one exemplar, one guide is set_guides.
    let mut one = Session::new(&first, options).unwrap();
    assert!(one.set_exemplar_guides(&[guide], &target, 1.0).is_ok());
}
