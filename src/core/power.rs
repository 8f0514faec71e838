//! A power x^y for the hot loops that need many of them at modest accuracy: the IRLS weights of
//! texture optimisation, one per grid node per iteration (`powf` from `libm` would be 4% of a flow
//! frame's time at 512x512). It is plain arithmetic on the float's bits, so every target gives
//! the same result, bit for bit, as [`super::math`] requires of anything that feeds an output.

/// x^y for a positive, normal `x` and a `y` with |y * log2 x| below 126, to about one ulp of
/// f32 (relative error 6e-8 at worst over the test's sweep; the series are summed in f64).
/// Outside that domain the result is not meaningful; callers floor `x` first.
///
/// log2 x splits into the exponent and log2 of the mantissa m, taken in [sqrt(1/2), sqrt(2)) and
/// computed from the series of atanh: log2 m = (2 / ln 2) (t + t^3/3 + t^5/5 + t^7/7 + t^9/9)
/// with t = (m - 1) / (m + 1), |t| < 0.172. Then 2^(y log2 x) = 2^n 2^f with n the nearest
/// integer and |f| <= 1/2, and 2^f = e^(f ln 2) from its Taylor series to the seventh power.
#[inline]
#[must_use]
pub fn pow_positive(x: f32, y: f32) -> f32 {
    const LOG2_E_TIMES_2: f64 = 2.0 * std::f64::consts::LOG2_E;
    let bits = x.to_bits();
    let mut exponent = ((bits >> 23) & 0xff) as i32 - 127;
    let mut m = f64::from(f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000));
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        exponent += 1;
    }
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    let series = t * (1.0 + t2 * (1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 / 9.0))));
    let log2_x = f64::from(exponent) + LOG2_E_TIMES_2 * series;
    let z = (f64::from(y) * log2_x).clamp(-126.0, 126.0);
    // The nearest integer by truncating a positive number (a conversion instruction; `round`
    // is a library call natively).
    let n = ((z + 126.5) as i64 - 126) as f64;
    let g = (z - n) * std::f64::consts::LN_2;
    let two_f = 1.0
        + g * (1.0
            + g * (1.0 / 2.0
                + g * (1.0 / 6.0
                    + g * (1.0 / 24.0 + g * (1.0 / 120.0 + g * (1.0 / 720.0 + g / 5040.0))))));
    // 2^n as a double's exponent field: n lies in [-126, 126].
    let scale = f64::from_bits(((n as i64 + 1023) as u64) << 52);
    (two_f * scale) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_libm_over_the_weights_domain() {
        // Squared distances from the IRLS floor (1e-6) to far beyond any neighbourhood's, and
        // the exponents (r - 2) / 2 for r from 0 to 2 and beyond.
        let mut worst = 0.0f64;
        for y in [-1.0f32, -0.95, -0.6, -0.5, -0.25, -0.05, 0.0, 0.4, 1.0, 2.5] {
            let mut x = 1e-6f32;
            while x < 1e6 {
                let exact = f64::from(x).powf(f64::from(y));
                let got = f64::from(pow_positive(x, y));
                worst = worst.max((got - exact).abs() / exact);
                x *= 1.0137;
            }
        }
        assert!(worst < 2e-7, "worst relative error {worst:e}");
    }

    #[test]
    fn is_exact_at_powers_of_two_and_one() {
        assert_eq!(pow_positive(1.0, -0.6), 1.0);
        assert_eq!(pow_positive(4.0, 0.5), 2.0);
        assert_eq!(pow_positive(0.25, -1.0), 4.0);
        assert_eq!(pow_positive(3.7, 0.0), 1.0);
    }

    #[test]
    fn continuous_where_the_mantissa_folds() {
        // Around sqrt(2), where the mantissa folds, the result stays continuous and monotone.
        let below = pow_positive(std::f32::consts::SQRT_2 * 0.999_999, -0.6);
        let above = pow_positive(std::f32::consts::SQRT_2 * 1.000_001, -0.6);
        assert!(below > above && (below - above) / below < 1e-5);
    }
}
