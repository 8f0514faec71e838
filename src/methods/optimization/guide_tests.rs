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
