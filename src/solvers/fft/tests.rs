//! Every transform against the direct O(n^2) sum of its definition.

use super::twiddle::twiddle;
use super::*;
use crate::core::Rng;

type C = Complex<f64>;

fn direct(input: &[C], direction: Direction) -> Vec<C> {
    let n = input.len();
    (0..n)
        .map(|k| {
            input
                .iter()
                .enumerate()
                .map(|(j, &x)| x * twiddle((j * k) % n, n, direction))
                .sum()
        })
        .collect()
}

fn random_values(rng: &mut Rng, n: usize) -> Vec<C> {
    (0..n)
        .map(|_| C::new(rng.next_f64() * 2.0 - 1.0, rng.next_f64() * 2.0 - 1.0))
        .collect()
}

fn max_error(a: &[C], b: &[C]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).norm())
        .fold(0.0, f64::max)
}

/// Lengths of every kind: tiny, powers of 2, 3 and 5, mixed, primes (Bluestein), and products of
/// a prime with a smooth part.
const LENGTHS: [usize; 30] = [
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 15, 16, 25, 27, 30, 32, 45, 60, 64, 97, 100, 125, 128,
    243, 250, 257, 270, 1000,
];

#[test]
fn complex_transforms_equal_the_direct_sum() {
    let mut rng = Rng::new(5);
    for n in LENGTHS {
        for direction in [Direction::Forward, Direction::Inverse] {
            let input = random_values(&mut rng, n);
            let plan = Fft::new(n, direction);
            let mut data = input.clone();
            let mut scratch = vec![C::default(); plan.scratch_len()];
            plan.process(&mut data, &mut scratch);
            let error = max_error(&data, &direct(&input, direction));
            // The direct sum itself rounds at about n * 1e-16.
            assert!(
                error < 1e-12 * (n as f64),
                "n = {n} {direction:?}: error {error}"
            );
        }
    }
}

#[test]
fn forward_then_inverse_gives_n_times_the_input() {
    let mut rng = Rng::new(6);
    for n in [2048, 2187, 3125, 4000, 1021] {
        let input = random_values(&mut rng, n);
        let forward = Fft::new(n, Direction::Forward);
        let inverse = Fft::new(n, Direction::Inverse);
        let mut scratch = vec![C::default(); forward.scratch_len().max(inverse.scratch_len())];
        let mut data = input.clone();
        forward.process(&mut data, &mut scratch);
        inverse.process(&mut data, &mut scratch);
        let scaled: Vec<C> = input.iter().map(|&x| x * n as f64).collect();
        let error = max_error(&data, &scaled) / n as f64;
        assert!(error < 1e-13, "n = {n}: error {error}");
    }
}

#[test]
fn real_transforms_equal_the_complex_ones() {
    let mut rng = Rng::new(7);
    for n in LENGTHS {
        let input: Vec<f64> = (0..n).map(|_| rng.next_f64() - 0.5).collect();
        let plan = RealFft::new(n);
        let mut scratch = vec![C::default(); plan.scratch_len()];
        let mut spectrum = vec![C::default(); plan.spectrum_len()];
        plan.forward(&input, &mut spectrum, &mut scratch);
        let complex: Vec<C> = input.iter().map(|&x| C::new(x, 0.0)).collect();
        let expected = direct(&complex, Direction::Forward);
        let error = max_error(&spectrum, &expected[..n / 2 + 1]);
        assert!(error < 1e-12 * (n as f64), "n = {n}: forward error {error}");

        let mut output = vec![0.0; n];
        plan.inverse(&spectrum, &mut output, &mut scratch);
        let error = input
            .iter()
            .zip(&output)
            .map(|(&x, &y)| (x * n as f64 - y).abs())
            .fold(0.0, f64::max);
        assert!(
            error < 1e-11 * (n as f64),
            "n = {n}: round trip error {error}"
        );
    }
}

#[test]
fn real_inverse_ignores_the_impossible_imaginary_parts() {
    let plan = RealFft::new(8);
    let mut scratch = vec![C::default(); plan.scratch_len()];
    let input = [1.0, -2.0, 3.0, 0.5, 0.0, 4.0, -1.0, 2.0];
    let mut spectrum = vec![C::default(); 5];
    plan.forward(&input, &mut spectrum, &mut scratch);
    spectrum[0].im = 0.3;
    spectrum[4].im = -0.7;
    let mut output = [0.0; 8];
    plan.inverse(&spectrum, &mut output, &mut scratch);
    for (x, y) in input.iter().zip(output) {
        assert!((x * 8.0 - y).abs() < 1e-12);
    }
}

#[test]
fn smooth_sizes_have_only_small_prime_factors() {
    let sizes: Vec<usize> = [0, 1, 7, 11, 13, 97, 128, 129].map(smooth_size).to_vec();
    assert_eq!(sizes, [1, 1, 8, 12, 15, 100, 128, 135]);
    assert!(!is_smooth(0) && !is_smooth(7) && is_smooth(1) && is_smooth(2 * 3 * 5 * 4));
}

#[test]
fn a_batch_transforms_each_interleaved_sequence() {
    let mut rng = Rng::new(8);
    for (n, batch) in [(12, 3), (64, 16), (45, 5), (7, 4), (1, 6)] {
        for direction in [Direction::Forward, Direction::Inverse] {
            let plan = Fft::new(n, direction);
            let input = random_values(&mut rng, n * batch);
            let mut data = input.clone();
            let mut scratch = vec![C::default(); plan.batch_scratch_len(batch)];
            plan.process_batch(&mut data, &mut scratch, batch);
            for lane in 0..batch {
                let sequence: Vec<C> = input.iter().skip(lane).step_by(batch).copied().collect();
                let result: Vec<C> = data.iter().skip(lane).step_by(batch).copied().collect();
                let error = max_error(&result, &direct(&sequence, direction));
                assert!(error < 1e-12 * n as f64, "n = {n}, batch {batch}: {error}");
            }
        }
    }
}

#[test]
fn a_batch_of_real_rows_equals_each_row_alone() {
    let mut rng = Rng::new(9);
    for (n, batch) in [(16, 5), (30, 16), (9, 3), (14, 2)] {
        let plan = RealFft::new(n);
        let input: Vec<f64> = (0..n * batch).map(|_| rng.next_f64() - 0.5).collect();
        let width = plan.spectrum_len();
        let mut scratch = vec![C::default(); plan.batch_scratch_len(batch)];
        let mut spectra = vec![C::default(); width * batch];
        plan.forward_batch(&input, &mut spectra, &mut scratch);
        for (row, spectrum) in input.chunks_exact(n).zip(spectra.chunks_exact(width)) {
            let mut alone = vec![C::default(); width];
            plan.forward(row, &mut alone, &mut scratch);
            assert!(max_error(spectrum, &alone) < 1e-13, "n = {n}");
        }
        let mut output = vec![0.0; n * batch];
        plan.inverse_batch(&spectra, &mut output, &mut scratch);
        for (x, y) in input.iter().zip(&output) {
            assert!((x * n as f64 - y).abs() < 1e-11, "n = {n}");
        }
    }
}
