//! Tests of the FFT SSD search against a direct SSD loop.
use super::*;
use crate::core::Rng;

/// The obvious SSD: every translation, every patch pixel. Returns `(costs, areas)` laid out
/// like [`SsdMap`].
fn direct_ssd(
    output: &Image,
    output_weights: Option<&[f32]>,
    patch: &Image,
    patch_weights: Option<&[f32]>,
    boundary: Boundary,
) -> (Vec<f64>, Vec<f64>) {
    let (ow, oh) = (output.width() as isize, output.height() as isize);
    let (pw, ph) = (patch.width() as isize, patch.height() as isize);
    let (xs, ys) = match boundary {
        Boundary::Open => (1 - pw..ow, 1 - ph..oh),
        Boundary::Periodic => (0..ow, 0..oh),
    };
    let weight = |w: Option<&[f32]>, i: usize| f64::from(w.map_or(1.0, |w| w[i]));
    let (mut costs, mut areas) = (Vec::new(), Vec::new());
    for ty in ys {
        for tx in xs.clone() {
            let (mut cost, mut area) = (0.0, 0.0);
            for v in 0..ph {
                for u in 0..pw {
                    let (mut x, mut y) = (u + tx, v + ty);
                    if boundary == Boundary::Periodic {
                        (x, y) = (x.rem_euclid(ow), y.rem_euclid(oh));
                    } else if x < 0 || y < 0 || x >= ow || y >= oh {
                        continue;
                    }
                    let o = (y * ow + x) as usize;
                    let p = (v * pw + u) as usize;
                    let w = weight(output_weights, o) * weight(patch_weights, p);
                    if w == 0.0 {
                        continue;
                    }
                    area += w;
                    let (a, b) = (
                        output.pixel(x as usize, y as usize),
                        patch.pixel(u as usize, v as usize),
                    );
                    cost += w * a
                        .iter()
                        .zip(b)
                        .map(|(&a, &b)| f64::from(a - b).powi(2))
                        .sum::<f64>();
                }
            }
            costs.push(cost);
            areas.push(area);
        }
    }
    (costs, areas)
}

fn random_image(rng: &mut Rng, width: usize, height: usize, channels: usize) -> Image {
    Image::from_fn(width, height, channels, |_, _, _| rng.next_f32()).unwrap()
}

/// Binary masks (a filled region with holes), soft weights, or none.
fn random_weights(rng: &mut Rng, pixels: usize, kind: u32) -> Option<Vec<f32>> {
    match kind {
        0 => None,
        1 => Some((0..pixels).map(|_| f32::from(rng.below(3) > 0)).collect()),
        _ => Some(
            (0..pixels)
                .map(|_| {
                    if rng.below(4) == 0 {
                        0.0
                    } else {
                        rng.next_f32()
                    }
                })
                .collect(),
        ),
    }
}

/// Entry `index` of `map` equals the direct `(cost, area)` to a relative 1e-5.
fn assert_entry(
    map: &SsdMap,
    index: usize,
    (cost, area): (f64, f64),
    context: impl Fn() -> String,
) {
    let (got_cost, got_area) = (f64::from(map.costs()[index]), f64::from(map.areas()[index]));
    assert!(
        (got_area - area).abs() <= 1e-5 * (1.0 + area),
        "area {got_area} vs {area}: {}",
        context()
    );
    assert!(
        (got_cost - cost).abs() <= 1e-5 * (1.0 + cost),
        "cost {got_cost} vs {cost}: {}",
        context()
    );
}

fn assert_matches_direct(rng: &mut Rng, boundary: Boundary, rounds: usize, max_side: usize) {
    let mut search = SsdSearch::new();
    for round in 0..rounds {
        let channels = 1 + rng.index(4);
        let (ow, oh) = (1 + rng.index(max_side), 1 + rng.index(max_side));
        let (pw, ph) = (1 + rng.index(max_side), 1 + rng.index(max_side));
        let output = random_image(rng, ow, oh, channels);
        let patch = random_image(rng, pw, ph, channels);
        let kinds = (rng.below(3), rng.below(3));
        let output_weights = random_weights(rng, ow * oh, kinds.0);
        let patch_weights = random_weights(rng, pw * ph, kinds.1);
        let (ow_ref, pw_ref) = (output_weights.as_deref(), patch_weights.as_deref());
        let map = search
            .search(&output, ow_ref, &patch, pw_ref, boundary)
            .unwrap();
        let (costs, areas) = direct_ssd(&output, ow_ref, &patch, pw_ref, boundary);
        assert_eq!(map.costs().len(), costs.len(), "round {round}");
        assert_eq!(map.width() * map.height(), costs.len());
        for (index, (&cost, &area)) in costs.iter().zip(&areas).enumerate() {
            let context = || {
                format!(
                    "round {round}, {boundary:?}, {ow}x{oh} output, {pw}x{ph} patch, {channels} channels, offset {:?}",
                    map.offset(index)
                )
            };
            assert_entry(&map, index, (cost, area), context);
        }
    }
}

#[test]
fn open_boundary_matches_direct_ssd() {
    assert_matches_direct(&mut Rng::new(11), Boundary::Open, 150, 13);
}

#[test]
fn periodic_boundary_matches_direct_ssd() {
    // Patches may be larger than the output here: they fold onto the torus.
    assert_matches_direct(&mut Rng::new(12), Boundary::Periodic, 150, 13);
}

#[test]
fn larger_images_match_direct_ssd_at_sampled_offsets() {
    let mut rng = Rng::new(13);
    let output = random_image(&mut rng, 61, 47, 3);
    let patch = random_image(&mut rng, 23, 31, 3);
    let weights = random_weights(&mut rng, 61 * 47, 1).unwrap();
    for boundary in [Boundary::Open, Boundary::Periodic] {
        let map = ssd_map(&output, Some(&weights), &patch, None, boundary).unwrap();
        let (costs, areas) = direct_ssd(&output, Some(&weights), &patch, None, boundary);
        for index in (0..costs.len()).step_by(7) {
            let got = f64::from(map.costs()[index]);
            assert!(
                (got - costs[index]).abs() <= 1e-5 * (1.0 + costs[index]),
                "{boundary:?} {index}"
            );
            assert_eq!(
                f64::from(map.areas()[index]),
                areas[index],
                "binary areas are whole numbers"
            );
        }
    }
}

#[test]
fn a_patch_cut_from_the_output_matches_exactly_where_it_came_from() {
    let mut rng = Rng::new(14);
    let output = random_image(&mut rng, 40, 30, 3);
    let patch = output.crop(9, 5, 16, 12).unwrap();
    for boundary in [Boundary::Open, Boundary::Periodic] {
        let map = ssd_map(&output, None, &patch, None, boundary).unwrap();
        let (cost, area) = map.get(9, 5).unwrap();
        assert!(cost < 1e-4, "{boundary:?}: {cost}");
        assert_eq!(area, 16.0 * 12.0);
        let (best, _) = map
            .costs()
            .iter()
            .enumerate()
            .filter(|&(i, _)| map.areas()[i] == 16.0 * 12.0)
            .min_by(|a, b| a.1.total_cmp(b.1))
            .unwrap();
        assert_eq!(map.offset(best), (9, 5));
    }
}

#[test]
fn map_layout_and_overlap_areas() {
    let output = Image::new(5, 4, 1).unwrap();
    let patch = Image::new(3, 2, 1).unwrap();
    let open = ssd_map(&output, None, &patch, None, Boundary::Open).unwrap();
    assert_eq!((open.width(), open.height()), (7, 5));
    assert_eq!(open.first_offset(), (-2, -1));
    assert_eq!(open.offset(0), (-2, -1));
    assert_eq!(open.offset(7 * 5 - 1), (4, 3));
    assert_eq!(
        open.get(-2, -1),
        Some((0.0, 1.0)),
        "one corner pixel overlaps"
    );
    assert_eq!(open.get(1, 1), Some((0.0, 6.0)), "whole patch inside");
    assert_eq!(open.get(4, 3), Some((0.0, 1.0)));
    assert_eq!(open.get(5, 0), None);
    assert_eq!(open.get(-3, 0), None);
    let periodic = ssd_map(&output, None, &patch, None, Boundary::Periodic).unwrap();
    assert_eq!(
        (periodic.width(), periodic.height(), periodic.first_offset()),
        (5, 4, (0, 0))
    );
    assert!(
        periodic.areas().iter().all(|&a| a == 6.0),
        "the whole patch always overlaps"
    );
}

#[test]
fn no_overlap_means_zero_area_and_zero_cost() {
    let output = Image::from_fn(6, 6, 2, |x, y, c| (x + y + c) as f32).unwrap();
    let patch = Image::from_fn(3, 3, 2, |_, _, _| 0.5).unwrap();
    // Only the left half of the output is filled.
    let weights: Vec<f32> = (0..36).map(|i| f32::from(i % 6 < 3)).collect();
    let map = ssd_map(&output, Some(&weights), &patch, None, Boundary::Open).unwrap();
    let (cost, area) = map.get(4, 2).unwrap();
    assert_eq!((cost, area), (0.0, 0.0));
    assert!(map.costs().iter().all(|&c| c >= 0.0));
}

#[test]
fn unfilled_pixels_are_not_read_but_filled_ones_must_be_finite() {
    let mut output = Image::from_fn(4, 4, 1, |x, _, _| x as f32 / 4.0).unwrap();
    output.pixel_mut(3, 3)[0] = f32::NAN;
    let patch = Image::from_fn(2, 2, 1, |_, _, _| 0.25).unwrap();
    let mut weights = vec![1.0; 16];
    weights[15] = 0.0;
    let map = ssd_map(&output, Some(&weights), &patch, None, Boundary::Open).unwrap();
    assert!(map.costs().iter().all(|c| c.is_finite()));
    let err = ssd_map(&output, None, &patch, None, Boundary::Open).unwrap_err();
    assert!(err.to_string().contains("not finite"), "{err}");
}

#[test]
fn bad_input_is_a_named_error() {
    let grey = Image::new(4, 4, 1).unwrap();
    let colour = Image::new(2, 2, 3).unwrap();
    let err = ssd_map(&grey, None, &colour, None, Boundary::Open).unwrap_err();
    assert!(err.to_string().contains("3 channels"), "{err}");
    let err = ssd_map(&grey, Some(&[1.0; 15]), &grey, None, Boundary::Open).unwrap_err();
    assert_eq!(
        err,
        Error::LengthMismatch {
            what: "output weights",
            expected: 16,
            actual: 15
        }
    );
    let mut weights = [1.0f32; 16];
    weights[3] = -1.0;
    let err = ssd_map(&grey, None, &grey, Some(&weights), Boundary::Open).unwrap_err();
    assert!(
        matches!(err, Error::InvalidParameter { name: "patch", .. }),
        "{err}"
    );
    weights[3] = f32::NAN;
    assert!(ssd_map(&grey, Some(&weights), &grey, None, Boundary::Periodic).is_err());
    let wide = Image::new(4000, 1, 1).unwrap();
    let tall = Image::new(1, 4000, 1).unwrap();
    let big = Image::new(1500, 1500, 1).unwrap();
    let err = ssd_map(&big, None, &big, None, Boundary::Open).unwrap_err();
    assert!(err.to_string().contains("FFT search"), "{err}");
    assert!(ssd_map(&wide, None, &tall, None, Boundary::Open).is_err());
}

#[test]
fn a_reused_search_gives_the_same_maps_as_a_fresh_one() {
    let mut rng = Rng::new(15);
    let mut search = SsdSearch::new();
    for (size, boundary) in [
        (9, Boundary::Open),
        (14, Boundary::Periodic),
        (9, Boundary::Open),
    ] {
        let output = random_image(&mut rng, size, size + 3, 2);
        let patch = random_image(&mut rng, 5, 4, 2);
        let reused = search
            .search(&output, None, &patch, None, boundary)
            .unwrap();
        let fresh = ssd_map(&output, None, &patch, None, boundary).unwrap();
        assert_eq!(reused, fresh);
    }
}

#[test]
fn a_keyed_search_reuses_the_patch_and_matches_a_fresh_one() {
    let mut rng = Rng::new(17);
    let mut search = SsdSearch::new();
    let patches = [
        random_image(&mut rng, 5, 4, 3),
        random_image(&mut rng, 5, 4, 3),
    ];
    // Keys 0, 0, 1, 0 (recomputed when the key changes back), with changing outputs and sizes.
    for (key, size, boundary) in [
        (0, 9, Boundary::Open),
        (0, 9, Boundary::Open),
        (1, 9, Boundary::Open),
        (0, 12, Boundary::Periodic),
    ] {
        let output = random_image(&mut rng, size, size + 2, 3);
        let weights = random_weights(&mut rng, size * (size + 2), 1).unwrap();
        let patch = &patches[key as usize];
        let keyed = search
            .search_keyed(&output, Some(&weights), patch, None, boundary, Some(key))
            .unwrap();
        let fresh = ssd_map(&output, Some(&weights), patch, None, boundary).unwrap();
        assert_eq!(keyed, fresh);
    }
}

/// A measurement, not a check: `cargo test --release --lib -- --ignored --nocapture fft_ssd_timing`.
#[test]
#[ignore = "a timing report; run with --release --ignored --nocapture"]
fn fft_ssd_timing() {
    let mut rng = Rng::new(16);
    let mut search = SsdSearch::new();
    for (out_side, patch_side) in [(128, 64), (256, 128), (512, 256)] {
        let output = random_image(&mut rng, out_side, out_side, 3);
        let patch = random_image(&mut rng, patch_side, patch_side, 3);
        let weights = random_weights(&mut rng, out_side * out_side, 1).unwrap();
        for boundary in [Boundary::Open, Boundary::Periodic] {
            search
                .search(&output, Some(&weights), &patch, None, boundary)
                .unwrap();
            let started = std::time::Instant::now();
            let map = search
                .search(&output, Some(&weights), &patch, None, boundary)
                .unwrap();
            println!(
                "{out_side}x{out_side} output, {patch_side}x{patch_side} patch, RGB, {boundary:?}: \
                 {} translations in {:.1} ms",
                map.costs().len(),
                started.elapsed().as_secs_f64() * 1e3
            );
        }
    }
}

/// A search over a range of offsets gives, at each of them, what the direct SSD gives: ranges
/// inside the usual open range, reaching past it on any side, and of one offset, on random
/// sizes, channels and weights (the transform is then smaller than the output plus the patch).
#[test]
fn a_range_search_matches_direct_ssd_on_its_offsets() {
    let mut rng = Rng::new(21);
    let mut search = SsdSearch::new();
    let mut smaller = 0;
    for round in 0..150 {
        let channels = 1 + rng.index(3);
        let (ow, oh) = (1 + rng.index(14), 1 + rng.index(14));
        let (pw, ph) = (1 + rng.index(14), 1 + rng.index(14));
        let output = random_image(&mut rng, ow, oh, channels);
        let patch = random_image(&mut rng, pw, ph, channels);
        let kinds = (rng.below(3), rng.below(3));
        let output_weights = random_weights(&mut rng, ow * oh, kinds.0);
        let patch_weights = random_weights(&mut rng, pw * ph, kinds.1);
        let (ow_ref, pw_ref) = (output_weights.as_deref(), patch_weights.as_deref());
        // Any start from 3 before the usual first offset to 3 past the output, any count.
        let start = |p: usize, o: usize, rng: &mut Rng| -> isize {
            rng.index(p + o + 6) as isize - p as isize - 2
        };
        let first = (start(pw, ow, &mut rng), start(ph, oh, &mut rng));
        let count = (1 + rng.index(ow + pw), 1 + rng.index(oh + ph));
        let range = OffsetRange { first, count };
        let map = search
            .search_range((&output, ow_ref), (&patch, pw_ref), range, None)
            .unwrap();
        assert_eq!(
            (map.width(), map.height(), map.first_offset()),
            (count.0, count.1, first)
        );
        let (costs, areas) = direct_ssd(&output, ow_ref, &patch, pw_ref, Boundary::Open);
        let full_width = (ow + pw - 1) as isize;
        for index in 0..count.0 * count.1 {
            let (tx, ty) = map.offset(index);
            let (i, j) = (tx + pw as isize - 1, ty + ph as isize - 1);
            let inside = (0..full_width).contains(&i) && (0..(oh + ph - 1) as isize).contains(&j);
            let (cost, area) = if inside {
                let k = (j * full_width + i) as usize;
                (costs[k], areas[k])
            } else {
                (0.0, 0.0) // no overlap at all
            };
            let context = || {
                format!(
                    "round {round}, {ow}x{oh} output, {pw}x{ph} patch, {range:?}, offset ({tx}, {ty})"
                )
            };
            assert_entry(&map, index, (cost, area), context);
        }
        let full = transform_size((ow, oh), (pw, ph), Boundary::Open);
        let used = search.transform.as_ref().map(|t| (t.nx, t.ny)).unwrap();
        smaller += usize::from(used.0 * used.1 < full.0 * full.1);
    }
    assert!(
        smaller > 20,
        "the range made the transform smaller in {smaller} of 150 rounds"
    );
}
