//! Per-channel weights of the match distance: a channel of weight 0 is carried along without
//! steering the matches; a heavier channel is followed more closely.

use super::initial::Start;
use super::{Energy, Options, Session};
use crate::core::Image;
use crate::core::testing::{noise, sample};

/// An RGBA exemplar: `rgb`'s colours with `alpha` (one channel of the same size) as the fourth.
fn with_alpha(rgb: &Image, alpha: &Image) -> Image {
    Image::from_fn(rgb.width(), rgb.height(), 4, |x, y, c| {
        if c < 3 {
            rgb.pixel(x, y)[c]
        } else {
            alpha.pixel(x, y)[0]
        }
    })
    .unwrap()
}

fn run(exemplar: &Image, options: Options) -> Image {
    let mut session = Session::new(exemplar, options).unwrap();
    while !session.is_done() {
        session.step().unwrap();
    }
    session.output_full_size().unwrap()
}

fn channel(image: &Image, c: usize) -> Vec<u32> {
    image
        .data()
        .chunks_exact(image.channels())
        .map(|p| p[c].to_bits())
        .collect()
}

fn options() -> Options {
    Options {
        output_width: 48,
        output_height: 40,
        start: Start::Patches,
        ..Options::default()
    }
}

#[test]
fn a_channel_of_weight_0_follows_the_matches_without_steering_them() {
    let rgb = sample("gravel_64").with_channels(3).unwrap();
    let one = with_alpha(&rgb, &noise(64, 64, 1, 1));
    let other = with_alpha(&rgb, &noise(64, 64, 1, 2));
    let weighted = Options {
        channel_weights: vec![1.0, 1.0, 1.0, 0.0],
        ..options()
    };
    let (a, b) = (run(&one, weighted.clone()), run(&other, weighted));
    // Different fourth channels, the same matches: the colours agree to the bit.
    for c in 0..3 {
        assert_eq!(channel(&a, c), channel(&b, c), "channel {c}");
    }
    assert_ne!(channel(&a, 3), channel(&b, 3), "the fourth channel is carried");
    // Unweighted, the fourth channel steers the matches and the colours differ.
    let (a, b) = (run(&one, options()), run(&other, options()));
    assert_ne!(channel(&a, 0), channel(&b, 0));
}

/// Channel `c` of `image` alone.
#[cfg(not(target_arch = "wasm32"))]
fn plane(image: &Image, c: usize) -> Image {
    Image::from_fn(image.width(), image.height(), 1, |x, y, _| image.pixel(x, y)[c]).unwrap()
}

// The coherence measure is native only.
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn a_heavier_channel_is_followed_more_closely() {
    // Colours from one texture, the fourth channel from another: the matches cannot suit
    // both, and the weights say which to follow. The fourth channel's coherence (its 7x7
    // patches to the nearest patch of the exemplar's fourth channel) with the colours at
    // weight 0 equals that of the fourth channel synthesised alone, and is worse with the
    // fourth channel at weight 0.
    let exemplar = with_alpha(
        &sample("gravel_64").with_channels(3).unwrap(),
        &sample("tiles_64").with_channels(1).unwrap(),
    );
    let coherence = |weights: Vec<f32>| {
        let out = run(
            &exemplar,
            Options {
                channel_weights: weights,
                ..options()
            },
        );
        crate::methods::quality::coherence_against(&[plane(&exemplar, 3)], &plane(&out, 3))
            .unwrap()
    };
    let (light, heavy) = (
        coherence(vec![1.0, 1.0, 1.0, 0.0]),
        coherence(vec![0.0, 0.0, 0.0, 1.0]),
    );
    // The fourth channel synthesised alone, for scale.
    let alone = {
        let fourth = plane(&exemplar, 3);
        let out = run(&fourth, options());
        crate::methods::quality::coherence_against(&[fourth], &out).unwrap()
    };
    assert!(
        (heavy - alone).abs() <= 0.01 * alone,
        "weighed alone, the fourth channel is as coherent as synthesised alone: {heavy} vs {alone}"
    );
    assert!(
        light > 1.3 * heavy,
        "at weight 0 it is followed less closely: {light} against {heavy}"
    );
}

#[test]
fn bad_channel_weights_are_named() {
    let exemplar = sample("gravel_64").with_channels(3).unwrap();
    let message = |options: Options| {
        Session::new(&exemplar, options)
            .err()
            .expect("refused")
            .to_string()
    };
    let wrong_length = message(Options {
        channel_weights: vec![1.0, 1.0],
        ..options()
    });
    assert!(
        wrong_length.contains("channelWeights") && wrong_length.contains("(3)"),
        "{wrong_length}"
    );
    let wavelet = message(Options {
        channel_weights: vec![1.0, 1.0, 1.0],
        energy: Energy::Haar,
        neighbourhood_sizes: vec![16, 8],
        ..options()
    });
    assert!(
        wavelet.contains("channelWeights") && wavelet.contains("haar"),
        "{wavelet}"
    );
}
