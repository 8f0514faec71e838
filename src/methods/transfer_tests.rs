//! Transfers of real sessions: graph cut's map reproduces its output exactly, texture
//! optimisation's comes close to it, and a coordinate image transfers to the map itself.

use crate::core::Image;
use crate::core::testing::sample;
use crate::methods::{graphcut, optimization};

/// An image whose pixel (x, y) holds (x, y): transferred, it shows the map.
fn coordinates(w: usize, h: usize) -> Image {
    Image::from_fn(w, h, 2, |x, y, k| if k == 0 { x as f32 } else { y as f32 }).unwrap()
}

#[test]
fn graph_cut_transfer_of_the_exemplar_is_its_output() {
    let exemplar = sample("tiles_64");
    for tileable in [false, true] {
        let options = graphcut::Options {
            output_width: 96,
            output_height: 80,
            tileable,
            ..graphcut::Options::default()
        };
        let mut session = graphcut::Session::new(&exemplar, options).unwrap();
        while !session.is_done() {
            session.step().unwrap();
        }
        let map = session.source_map().unwrap();
        assert_eq!(map.transfer(&exemplar).unwrap(), session.output().unwrap());
        let coords = map.transfer(&coordinates(64, 64)).unwrap();
        for i in 0..96 * 80 {
            let (x, y) = map.source_of(i).unwrap();
            assert_eq!(coords.pixel(i % 96, i / 96), &[x as f32, y as f32]);
        }
    }
    let rotated = graphcut::Options {
        output_width: 64,
        output_height: 64,
        transforms: graphcut::Transforms {
            rotate: true,
            ..graphcut::Transforms::default()
        },
        ..graphcut::Options::default()
    };
    let session = graphcut::Session::new(&exemplar, rotated).unwrap();
    assert!(session.source_map().unwrap_err().to_string().contains("sources"));
}

#[test]
fn optimisation_transfer_of_the_exemplar_is_close_to_its_output() {
    let exemplar = sample("gravel_64").with_channels(3).unwrap();
    let options = optimization::Options {
        output_width: 80,
        output_height: 80,
        histogram_matching: 0.0,
        ..optimization::Options::default()
    };
    let mut session = optimization::Session::new(&exemplar, options).unwrap();
    assert!(session.source_map().is_err(), "no map before a step");
    while !session.is_done() {
        session.step().unwrap();
    }
    let map = session.source_map().unwrap();
    let transferred = map.transfer(&exemplar).unwrap();
    let output = session.output_full_size().unwrap();
    let error = transferred
        .data()
        .iter()
        .zip(output.data())
        .map(|(a, b)| f64::from((a - b).abs()))
        .sum::<f64>()
        / output.data().len() as f64;
    // Against a map that copies nothing of the output: the exemplar shifted by half a period.
    let mean = output.data().iter().map(|&v| f64::from(v)).sum::<f64>() / output.data().len() as f64;
    let spread = output
        .data()
        .iter()
        .map(|&v| (f64::from(v) - mean).abs())
        .sum::<f64>()
        / output.data().len() as f64;
    assert!(error < 0.5 * spread, "mean error {error} against spread {spread}");
    // Every source pixel lies in the exemplar, and a coordinate image shows the map.
    let coords = map.transfer(&coordinates(64, 64)).unwrap();
    for i in 0..80 * 80 {
        let (x, y) = map.source_of(i).unwrap();
        assert_eq!(coords.pixel(i % 80, i / 80), &[x as f32, y as f32]);
    }
}
