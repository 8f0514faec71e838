//! Several exemplars: graph cut and texture optimisation take patches and matches from all of
//! them, every pixel knows which, and nothing comes from between them.

use crate::core::Image;
use crate::core::testing::sample;
use crate::methods::{graphcut, optimization};

/// Two exemplars a pixel tells apart by colour: a sample tinted red (its blue channel 0) and
/// one tinted blue (red 0), of different sizes.
fn red_and_blue() -> (Image, Image) {
    let tint = |name: &str, keep: usize, side: usize| {
        let e = sample(name).with_channels(3).unwrap();
        let e = e.crop(0, 0, side, side.min(e.height())).unwrap();
        Image::from_fn(e.width(), e.height(), 3, |x, y, k| {
            if k == 2 - keep { 0.0 } else { 0.2 + 0.8 * e.pixel(x, y)[k] }
        })
        .unwrap()
    };
    (tint("gravel_64", 0, 64), tint("brick_64", 2, 48))
}

/// Which exemplar an output pixel's colour comes from: red (0) or blue (1).
fn tint_of(p: &[f32]) -> Option<u32> {
    match (p[0] > 0.05, p[2] > 0.05) {
        (true, false) => Some(0),
        (false, true) => Some(1),
        _ => None,
    }
}

#[test]
fn graph_cut_places_patches_from_every_exemplar() {
    let (red, blue) = red_and_blue();
    let options = graphcut::Options {
        output_width: 160,
        output_height: 160,
        k: 10.0,
        ..graphcut::Options::default()
    };
    let mut session = graphcut::Session::with_exemplars(&[red, blue], options).unwrap();
    while !session.is_done() {
        session.step().unwrap();
    }
    let (out, map) = (session.output().unwrap(), session.exemplar_map());
    let mut seen = [0usize; 2];
    for (i, e) in map.iter().enumerate() {
        let e = e.expect("covered");
        assert_eq!(tint_of(out.pixel(i % 160, i / 160)), Some(e), "pixel {i}");
        seen[e as usize] += 1;
    }
    assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
    let names: Vec<&str> = session.synthesis().sources.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["exemplar 1", "exemplar 2"]);
}

#[test]
fn texture_optimisation_matches_inside_every_exemplar() {
    // The two halves of one texture: the output draws on both, and no match reaches into the
    // gap between them.
    let gravel = sample("gravel_128").with_channels(3).unwrap();
    let halves = [
        gravel.crop(0, 0, 128, 64).unwrap(),
        gravel.crop(0, 64, 128, 64).unwrap(),
    ];
    let options = optimization::Options {
        output_width: 96,
        output_height: 96,
        levels: 2,
        neighbourhood_sizes: vec![16, 8],
        ..optimization::Options::default()
    };
    // Which half wins where depends on the seed's start; over three seeds both are used.
    let mut seen = [0usize; 2];
    let mut last = None;
    for seed in 1..=3 {
        let options = optimization::Options {
            seed,
            ..options.clone()
        };
        let mut session = optimization::Session::with_exemplars(&halves, options).unwrap();
        assert_eq!(session.exemplar_count(), 2);
        while !session.is_done() {
            session.step().unwrap();
        }
        for e in session.exemplar_map().unwrap() {
            seen[e as usize] += 1;
        }
        let size = session.current_level().size;
        let gap = 64..64 + optimization::exemplars::GAP;
        for m in session.level_solver().unwrap().matches() {
            let rows = m.y as usize..m.y as usize + size;
            assert!(rows.end <= gap.start || rows.start >= gap.end, "a match at rows {rows:?}");
        }
        last = Some(session);
    }
    let total = 3 * 96 * 96;
    assert!(seen.iter().all(|&n| n * 10 > total), "{seen:?}");
    let session = last.unwrap();
    assert!(session.source_map().unwrap_err().to_string().contains("one exemplar"));
}

#[test]
fn one_exemplar_in_a_list_is_the_plain_session() {
    let e = sample("gravel_64");
    let options = optimization::Options {
        output_width: 48,
        output_height: 48,
        ..optimization::Options::default()
    };
    let run = |mut s: optimization::Session| {
        while !s.is_done() {
            s.step().unwrap();
        }
        s.output_full_size().unwrap()
    };
    let one = optimization::Session::new(&e, options.clone()).unwrap();
    let list = optimization::Session::with_exemplars(std::slice::from_ref(&e), options).unwrap();
    assert_eq!(run(one), run(list));
    assert!(optimization::Session::with_exemplars(&[], optimization::Options::default()).is_err());
}
