//! Whole-session tests of the wavelet-based texture energy (Shen et al. 2009, eq. 4).

use super::level::{LevelSetup, LevelSolver};
use super::wavelet_energy::{WaveletEnergy, levels_for};
use super::{Energy, EventKind, Options, Session};
use crate::core::testing::sample;
use crate::core::{Image, Rng};
use crate::solvers::nn::patches::gaussian_falloff;
use crate::solvers::nn::{FeatureMap, Neighbourhoods, Pos, Search};
use crate::solvers::wavelet::Wavelet;

fn run(exemplar: &Image, options: Options) -> Session {
    let mut session = Session::new(exemplar, options).unwrap();
    while session.step().unwrap().kind != EventKind::Done {}
    session
}

/// The periodic analysis matrix of one level of a 1-D transform of `n` samples, built from the
/// filter definition: row i < n/2 holds h_k at column (2i + k) mod n, row n/2 + i holds
/// g_k = (-1)^k h_(L-1-k).
fn analysis_matrix(wavelet: Wavelet, n: usize) -> Vec<Vec<f64>> {
    let h: Vec<f64> = match wavelet {
        Wavelet::Haar => vec![0.5f64.sqrt(); 2],
        Wavelet::Daubechies4 => {
            let (s3, k) = (3f64.sqrt(), 4.0 * 2f64.sqrt());
            vec![
                (1.0 + s3) / k,
                (3.0 + s3) / k,
                (3.0 - s3) / k,
                (1.0 - s3) / k,
            ]
        }
    };
    let taps = h.len();
    let mut m = vec![vec![0.0; n]; n];
    for i in 0..n / 2 {
        for k in 0..taps {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            m[i][(2 * i + k) % n] += h[k];
            m[n / 2 + i][(2 * i + k) % n] += sign * h[taps - 1 - k];
        }
    }
    m
}

/// The 2-D multi-level transform by matrix products, B <- M B M^T on the shrinking top-left
/// square, in f64: an oracle independent of the in-place lifting code.
fn naive_dwt(wavelet: Wavelet, block: &[f64], size: usize, levels: usize) -> Vec<f64> {
    let mut b: Vec<Vec<f64>> = (0..size)
        .map(|y| block[y * size..(y + 1) * size].to_vec())
        .collect();
    for level in 0..levels {
        let n = size >> level;
        let m = analysis_matrix(wavelet, n);
        let mut t = vec![vec![0.0; n]; n];
        for i in 0..n {
            for j in 0..n {
                t[i][j] = (0..n)
                    .map(|a| (0..n).map(|c| m[i][a] * b[a][c] * m[j][c]).sum::<f64>())
                    .sum();
            }
        }
        for i in 0..n {
            b[i][..n].copy_from_slice(&t[i]);
        }
    }
    b.concat()
}

/// Eq. 4 directly: fall-off weighted pixel SSD + sum_i w_i (c_x^i - c_z^i)^2, with c the naive
/// transform of the windowed neighbourhood, w_i = 1 on the approximation and `detail` elsewhere.
fn naive_distance(
    wavelet: Wavelet,
    x: &[f32],
    z: &[f32],
    size: usize,
    dims: usize,
    detail: f32,
) -> f64 {
    let g = gaussian_falloff(size, 1);
    let levels = levels_for(size);
    let mut total = 0.0;
    for c in 0..dims {
        let plane = |v: &[f32]| -> Vec<f64> {
            (0..size * size)
                .map(|p| f64::from(g[p]).sqrt() * f64::from(v[p * dims + c]))
                .collect()
        };
        let (px, pz) = (plane(x), plane(z));
        total += px
            .iter()
            .zip(&pz)
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f64>();
        let (cx, cz) = (
            naive_dwt(wavelet, &px, size, levels),
            naive_dwt(wavelet, &pz, size, levels),
        );
        let approx = size >> levels;
        for y in 0..size {
            for xx in 0..size {
                let w = if xx < approx && y < approx {
                    1.0
                } else {
                    f64::from(detail)
                };
                let d = cx[y * size + xx] - cz[y * size + xx];
                total += w * d * d;
            }
        }
    }
    total
}

#[test]
fn transformed_neighbourhood_distance_equals_the_naive_weighted_coefficient_sum() {
    let exemplar = sample("brick_64");
    let (w, h, dims) = (exemplar.width(), exemplar.height(), exemplar.channels());
    let map = FeatureMap {
        width: w,
        height: h,
        dims,
        data: exemplar.data().to_vec(),
    };
    let mut rng = Rng::new(11);
    for wavelet in [Wavelet::Haar, Wavelet::Daubechies4] {
        for size in [8, 16] {
            let detail = 3.0;
            let e = WaveletEnergy::new(wavelet, size, dims, dims, detail);
            let mut scratch = vec![0.0; size];
            let space =
                Neighbourhoods::transformed(map.clone(), size, e.weights().to_vec(), |v, out| {
                    e.transform(v, out, &mut scratch)
                });
            let plain = Neighbourhoods::new(map.clone(), size);
            let len = space.vector_len();
            let x: Vec<f32> = (0..len).map(|_| rng.next_f32()).collect();
            let mut query = vec![0.0; len];
            e.transform(&x, &mut query, &mut vec![0.0; size]);
            for pos in [
                Pos::new(0, 0),
                Pos::new(w - size, h - size),
                Pos::new(17, 5),
            ] {
                let mut z = vec![0.0; len];
                plain.copy_to(pos, &mut z);
                let fast = f64::from(space.distance(&query, pos, f32::INFINITY));
                let slow = naive_distance(wavelet, &x, &z, size, dims, detail);
                assert!(
                    (fast - slow).abs() < 1e-4 * slow,
                    "{wavelet:?} {size} {pos:?}: {fast} vs {slow}"
                );
            }
        }
    }
}

fn small(energy: Energy, search: Search) -> Options {
    Options {
        output_width: 48,
        output_height: 40,
        levels: 2,
        neighbourhood_sizes: vec![16, 8],
        search,
        energy,
        ..Options::default()
    }
}

#[test]
fn with_all_weights_one_the_matches_are_the_pixel_energys() {
    // Parseval: every distance is exactly twice the pixel distance up to float rounding, so an
    // M-step on the same output from the same matches picks the same matches. (Over a whole run
    // the two drift apart: the sums round differently, pixel order vs coefficient order, a
    // near-tie flips now and then, and EM carries the difference on: 327 to 357 of 357 final
    // matches equal on tiles_64.)
    let exemplar = sample("tiles_64");
    let mut rng = Rng::new(3);
    let output = Image::from_fn(64, 56, exemplar.channels(), |_, _, _| rng.next_f32()).unwrap();
    let smooth = crate::core::sample::resize_bilinear(
        &crate::core::sample::resize_bilinear(&output, 16, 14, crate::core::Edge::Clamp).unwrap(),
        64,
        56,
        crate::core::Edge::Clamp,
    )
    .unwrap();
    for search in [Search::PatchMatch, Search::Exact] {
        for size in [16, 8] {
            let setup = |energy| LevelSetup {
                search,
                energy,
                ..LevelSetup::plain(64, 56, size)
            };
            let mut pixels = LevelSolver::new(&exemplar, setup(Energy::Pixels), &mut Rng::new(5));
            pixels.m_step(&smooth, None, &mut Rng::new(6));
            for energy in [Energy::Haar, Energy::Daubechies] {
                let mut wavelet = LevelSolver::new(&exemplar, setup(energy), &mut Rng::new(5));
                wavelet.m_step(&smooth, None, &mut Rng::new(6));
                let (a, b) = (pixels.matches(), wavelet.matches());
                let same = a.iter().zip(b).filter(|(p, q)| p == q).count();
                assert_eq!(same, a.len(), "{search:?} {size} {energy:?}");
                let (ea, eb) = (pixels.energy(), wavelet.energy());
                assert!((ea - eb).abs() <= 1e-4 * ea, "{ea} vs {eb}");
                let (ma, mb) = (pixels.match_energy(), wavelet.match_energy());
                assert!(
                    (mb - 2f64.powf(0.4) * ma).abs() <= 1e-4 * mb,
                    "{ma} vs {mb}"
                );
            }
        }
    }
}

#[test]
fn detail_weight_changes_the_matches_and_energy_reports_the_pixel_term() {
    let exemplar = sample("tiles_64");
    let pixels = run(&exemplar, small(Energy::Pixels, Search::Exact));
    let mut session = Session::new(&exemplar, small(Energy::Daubechies, Search::Exact)).unwrap();
    loop {
        let e = session.step().unwrap();
        // The M-step's energy adds the weighted wavelet term to the reported pixel term: every
        // coefficient weighs at least 1 + 1, and the energy is sum d^(r/2) with r = 0.8.
        assert!(e.match_energy >= 2f64.powf(0.4) * e.energy * 0.999, "{e:?}");
        if e.kind == EventKind::Done {
            break;
        }
    }
    assert_ne!(pixels.matches().unwrap().2, session.matches().unwrap().2);
}

#[test]
fn haar_and_daubechies_runs_finish_and_keep_detail() {
    for name in ["paving_64", "stone_64"] {
        let exemplar = sample(name);
        for energy in [Energy::Haar, Energy::Daubechies] {
            for search in [Search::PatchMatch, Search::KMeansTree] {
                let session = run(
                    &exemplar,
                    Options {
                        output_width: 128,
                        output_height: 128,
                        energy,
                        search,
                        ..Options::default()
                    },
                );
                let q = crate::methods::quality::quality(
                    &exemplar,
                    &session.output_full_size().unwrap(),
                )
                .unwrap();
                assert!(
                    q.flat <= 0.25,
                    "{name} {energy:?} {search:?}: flat fraction {}",
                    q.flat
                );
            }
        }
    }
    // The gradient energy is honoured alongside.
    let exemplar = sample("stone_64");
    let session = run(
        &exemplar,
        Options {
            output_width: 96,
            output_height: 96,
            energy: Energy::Haar,
            mu: 10.0,
            ..Options::default()
        },
    );
    let q =
        crate::methods::quality::quality(&exemplar, &session.output_full_size().unwrap()).unwrap();
    assert!(q.flat <= 0.25, "mu 10 haar: flat fraction {}", q.flat);
}

#[test]
fn wavelet_energies_refuse_constraints_and_oversized_stores_by_name() {
    let exemplar = sample("tiles_64");
    let mut session = Session::new(&exemplar, small(Energy::Haar, Search::PatchMatch)).unwrap();
    let c = exemplar.channels();
    let target = Image::from_fn(48, 40, c, |_, _, _| 1.0).unwrap();
    let constraints = super::SoftConstraints::new(target, vec![1.0; 48 * 40], 1.0).unwrap();
    let err = session
        .set_constraints(Some(constraints))
        .unwrap_err()
        .to_string();
    assert!(err.contains("energy") && err.contains("pixels"), "{err}");
    session.set_constraints(None).unwrap();
    let big = Image::new(512, 512, 3).unwrap();
    let err = Session::new(
        &big,
        Options {
            energy: Energy::Daubechies,
            levels: 1,
            neighbourhood_sizes: vec![32],
            ..Options::default()
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        err.contains("exemplar neighbourhoods") && err.contains("memory budget of 1024 MiB"),
        "{err}"
    );
}
