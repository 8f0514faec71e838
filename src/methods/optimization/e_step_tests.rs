//! Tests of the E-step: the sums against brute-force weighted averages (plain, wrapping,
//! fixed-size rows), the minimiser with and without gradients, and the robust weights.

use super::*;
use crate::core::Rng;
use crate::methods::optimization::features::{feature_map, gather};
use crate::solvers::nn::{Neighbourhoods, patches::gaussian_falloff};

/// One whole E-step: every node's sums, then the minimiser (the session adds the nodes in
/// parts; the sums are the same).
fn e_step(m: &Matches<'_>, output: &mut Image, constraint: Option<&Constraint>) -> usize {
    let mut sums = Sums::new(output, m.mu > 0.0);
    sums.add(m, 0..m.matches.len(), sums.bands());
    sums.finish(m, output, constraint)
}

fn setup() -> (Image, Vec<usize>, Vec<usize>, Vec<Pos>, Vec<f32>) {
    let mut rng = Rng::new(21);
    let exemplar = Image::from_fn(12, 10, 2, |_, _, _| rng.next_f32()).unwrap();
    let (cols, rows) = (vec![0, 2, 4, 5], vec![0, 2, 3]);
    let matches: Vec<Pos> = (0..12)
        .map(|_| Pos::new(rng.index(9), rng.index(7)))
        .collect();
    let omegas: Vec<f32> = (0..12).map(|_| 0.5 + rng.next_f32()).collect();
    (exemplar, cols, rows, matches, omegas)
}

/// The inputs of an E-step without the gradient term; the neighbourhood's size is the
/// fall-off's side.
fn plain_matches<'a>(
    exemplar: &'a Image,
    (cols, rows): (&'a [usize], &'a [usize]),
    matches: &'a [Pos],
    node_weights: &'a [f32],
    falloff: &'a [f32],
    wrap: bool,
) -> Matches<'a> {
    Matches {
        exemplar,
        cols,
        rows,
        matches,
        node_weights,
        falloff,
        size: falloff.len().isqrt(),
        wrap,
        mu: 0.0,
    }
}

#[test]
fn equals_a_brute_force_weighted_average_on_a_tiny_case() {
    let (exemplar, cols, rows, matches, omegas) = setup();
    let size = 4;
    let falloff: Vec<f32> = gaussian_falloff(size, 1);
    let m = plain_matches(
        &exemplar,
        (&cols, &rows),
        &matches,
        &omegas,
        &falloff,
        false,
    );
    let mut out = Image::new(9, 7, 2).unwrap();
    e_step(&m, &mut out, None);
    // Brute force: for every output pixel, visit every neighbourhood that contains it.
    for y in 0..7 {
        for x in 0..9 {
            let (mut num, mut den) = ([0.0f64; 2], 0.0f64);
            for (node, z) in matches.iter().enumerate() {
                let (ox, oy) = (cols[node % 4], rows[node / 4]);
                if (ox..ox + size).contains(&x) && (oy..oy + size).contains(&y) {
                    let (dx, dy) = (x - ox, y - oy);
                    let g = f64::from(omegas[node] * falloff[dy * size + dx]);
                    let p = exemplar.pixel(z.x as usize + dx, z.y as usize + dy);
                    num[0] += g * f64::from(p[0]);
                    num[1] += g * f64::from(p[1]);
                    den += g;
                }
            }
            for (got, want) in out.pixel(x, y).iter().zip(num) {
                assert!((f64::from(*got) - want / den).abs() < 1e-5);
            }
        }
    }
}

/// A wrapping output taller than a band (three bands, neighbourhoods that wrap across the
/// bottom and right borders into the first band), added in uneven parts: every pixel is the
/// brute-force average of the neighbourhoods that cover it.
#[test]
fn bands_of_a_wrapping_output_equal_a_brute_force_average() {
    let mut rng = Rng::new(33);
    let exemplar = Image::from_fn(16, 14, 2, |_, _, _| rng.next_f32()).unwrap();
    let (w, h, size) = (11, 2 * BAND_ROWS + 5, 5);
    let cols: Vec<usize> = (0..w).step_by(2).collect();
    let rows: Vec<usize> = (0..h).step_by(3).collect();
    let nodes = cols.len() * rows.len();
    let matches: Vec<Pos> = (0..nodes)
        .map(|_| Pos::new(rng.index(16 - size + 1), rng.index(14 - size + 1)))
        .collect();
    let omegas: Vec<f32> = (0..nodes).map(|_| 0.5 + rng.next_f32()).collect();
    let falloff = gaussian_falloff(size, 1);
    let m = plain_matches(&exemplar, (&cols, &rows), &matches, &omegas, &falloff, true);
    let mut out = Image::new(w, h, 2).unwrap();
    let mut sums = Sums::new(&out, false);
    for part in [0..7, 7..8, 8..nodes] {
        sums.add(&m, part, sums.bands());
    }
    sums.finish(&m, &mut out, None);
    for y in 0..h {
        for x in 0..w {
            let (mut num, mut den) = ([0.0f64; 2], 0.0f64);
            for (node, z) in matches.iter().enumerate() {
                let (ox, oy) = (cols[node % cols.len()], rows[node / cols.len()]);
                let (dx, dy) = ((x + w - ox) % w, (y + h - oy) % h);
                if dx < size && dy < size {
                    let g = f64::from(omegas[node] * falloff[dy * size + dx]);
                    let p = exemplar.pixel(z.x as usize + dx, z.y as usize + dy);
                    num[0] += g * f64::from(p[0]);
                    num[1] += g * f64::from(p[1]);
                    den += g;
                }
            }
            for (got, want) in out.pixel(x, y).iter().zip(num) {
                assert!((f64::from(*got) - want / den).abs() < 1e-5, "pixel {x}, {y}");
            }
        }
    }
}

/// The loops for neighbourhoods of fixed sizes (8, 16, 32; grey and RGB, no wrap) give the
/// general loop's sums to the bit: with `wrap` set on a grid whose neighbourhoods all lie
/// inside the output the general loop runs the same sums, in the same order.
#[test]
fn fixed_size_rows_equal_the_general_loop_to_the_bit() {
    for channels in [1, 3] {
        for size in [8, 16, 32] {
            let mut rng = Rng::new(size as u64);
            let exemplar = Image::from_fn(40, 36, channels, |_, _, _| rng.next_f32()).unwrap();
            let (w, h) = (size * 2 + 5, size + 7);
            let step = size / 4;
            let cols: Vec<usize> = (0..=w - size).step_by(step).collect();
            let rows: Vec<usize> = (0..=h - size).step_by(step).collect();
            let nodes = cols.len() * rows.len();
            let matches: Vec<Pos> = (0..nodes)
                .map(|_| Pos::new(rng.index(41 - size), rng.index(37 - size)))
                .collect();
            let omegas: Vec<f32> = (0..nodes).map(|_| 0.5 + rng.next_f32()).collect();
            let falloff = gaussian_falloff(size, 1);
            let run = |wrap: bool| {
                let m =
                    plain_matches(&exemplar, (&cols, &rows), &matches, &omegas, &falloff, wrap);
                let mut out = Image::new(w, h, channels).unwrap();
                // In parts: the nodes in two, then the second part's bands in two, as a
                // session adds them.
                let mut sums = Sums::new(&out, false);
                let bands = sums.bands();
                let half = bands.start + bands.len() / 2;
                sums.add(&m, 0..nodes / 3, bands.clone());
                sums.add(&m, nodes / 3..nodes, bands.start..half);
                sums.add(&m, nodes / 3..nodes, half..bands.end);
                sums.finish(&m, &mut out, None);
                out.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            };
            let (plain, general) = (run(false), run(true));
            assert!(plain.iter().any(|&b| b != 0));
            assert_eq!(plain, general, "size {size}, {channels} channels");
        }
    }
}

/// The quadratic energy sum_p omega_p d(x_p, z_p) through the same features the M-step uses.
fn energy(out: &Image, m: &Matches<'_>) -> f64 {
    let space = Neighbourhoods::new(feature_map(m.exemplar, m.mu, Edge::Clamp), m.size);
    let map = feature_map(out, m.mu, edge(m.wrap));
    let mut q = vec![0.0; space.vector_len()];
    let nx = m.cols.len();
    m.matches
        .iter()
        .enumerate()
        .map(|(n, &z)| {
            gather(&map, m.cols[n % nx], m.rows[n / nx], m.size, m.wrap, &mut q);
            f64::from(m.node_weights[n]) * f64::from(space.distance(&q, z, f32::INFINITY))
        })
        .sum()
}

#[test]
fn the_e_step_is_the_minimiser_with_and_without_gradients() {
    let (exemplar, cols, rows, matches, omegas) = setup();
    for mu in [0.0, 10.0] {
        let size = 4;
        let falloff = gaussian_falloff(size, 1);
        let m = Matches {
            exemplar: &exemplar,
            cols: &cols,
            rows: &rows,
            matches: &matches,
            node_weights: &omegas,
            falloff: &falloff,
            size,
            wrap: false,
            mu,
        };
        let mut out = Image::new(9, 7, 2).unwrap();
        e_step(&m, &mut out, None);
        let best = energy(&out, &m);
        // Any perturbation of any pixel raises the energy.
        let mut rng = Rng::new(2);
        for _ in 0..20 {
            let mut moved = out.clone();
            let i = rng.index(moved.data().len());
            moved.data_mut()[i] += if rng.next_f32() < 0.5 { 0.01 } else { -0.01 };
            assert!(energy(&moved, &m) > best - 1e-6, "mu {mu}");
        }
    }
}

#[test]
fn robust_weights_and_their_energy_equal_the_direct_formulas() {
    // Exact matches, distances under the weight's floor, ordinary ones, and none yet.
    let d = [
        0.0f32,
        1e-9,
        4e-7,
        1e-6,
        2e-3,
        0.25,
        3.0,
        40.0,
        f32::INFINITY,
    ];
    for r in [0.8f32, 1.2, 2.0] {
        let mut w = Vec::new();
        let energy = super::robust_weights(&d[..8], r, &mut w);
        let direct: f64 = d[..8]
            .iter()
            .map(|&d| f64::from(d).powf(f64::from(r) / 2.0))
            .sum();
        assert!(
            (energy - direct).abs() <= 1e-6 * direct,
            "r {r}: {energy} vs {direct}"
        );
        for (&w, &d) in w.iter().zip(&d) {
            assert_eq!(w.to_bits(), robust_weight(d, r).to_bits());
        }
        // Every tiny distance's own term: the floor must not leak into the energy.
        for &tiny in &d[..4] {
            let e = super::robust_weights(&[tiny], r, &mut w);
            let exact = f64::from(tiny).powf(f64::from(r) / 2.0);
            assert!(
                (e - exact).abs() <= 1e-9 + 1e-6 * exact,
                "{tiny}: {e} vs {exact}"
            );
        }
        let e = super::robust_weights(&d, r, &mut w);
        assert!(e.is_infinite() && w[8] == 1.0);
    }
}

#[test]
fn robust_weights() {
    assert_eq!(robust_weight(0.25, 2.0), 1.0);
    assert!((robust_weight(0.25, 0.8) - 0.5f32.powf(-1.2)).abs() < 1e-5);
    assert!(robust_weight(0.0, 0.8).is_finite());
}
