//! The direction of a transform and its twiddle factors.

use num_complex::Complex;

/// Which way a transform goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// `e^{-2 pi i j k / n}`.
    Forward,
    /// `e^{+2 pi i j k / n}`, unnormalised.
    Inverse,
}

/// `e^{sign 2 pi i numerator / denominator}` with `sign` from the direction, computed directly
/// (no recurrence), so every twiddle is accurate to the last bits.
pub(super) fn twiddle(numerator: usize, denominator: usize, direction: Direction) -> Complex<f64> {
    let angle = -2.0 * std::f64::consts::PI * (numerator as f64) / (denominator as f64);
    let (sin, cos) = (crate::core::math::sin(angle), crate::core::math::cos(angle));
    match direction {
        Direction::Forward => Complex::new(cos, sin),
        Direction::Inverse => Complex::new(cos, -sin),
    }
}
