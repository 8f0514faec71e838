//! The transcendental functions (exp, pow, sin, cos, ln, atan2, hypot, ...) every platform
//! computes the same, bit for bit. `f32::exp` and friends call the platform's C library: glibc
//! natively, the `libm` crate's port of musl on wasm32-unknown-unknown. The two round about one
//! result in ten differently in the last bit (measured: 172 of the 1,360 Gaussian fall-off
//! weights of sizes 4..32, 10% of `powf(d, -1.2)` over 1e-3..1e3), and a last-bit difference in
//! a weight grows into a different output pixel. Calling the `libm` crate on every target runs
//! the same Rust code natively as in wasm, so a native run reproduces the wasm output exactly
//! (and the wasm output itself is unchanged: its std already uses this code, so on wasm32 these
//! call std, which keeps a second copy of the same functions out of the `.wasm`).
//!
//! Use these instead of the `f32`/`f64` methods in anything that feeds an output; `sqrt`, `abs`,
//! `floor`, `min`/`max` and the arithmetic operators are exact under IEEE 754 and need nothing.
//!
//! [`lesser`] and [`greater`] are `min` and `max` for hot loops: `f32::min`/`max` are IEEE
//! minNum/maxNum, which wasm has no instruction for, so in wasm each one is a call to
//! `fminf`/`fmaxf` and their NaN cases (in a max-flow path walk, 7% of a graph-cut synthesis).

/// e^x.
#[inline]
#[must_use]
pub fn expf(x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.exp()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::expf(x)
    }
}

/// e^x.
#[inline]
#[must_use]
pub fn exp(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.exp()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::exp(x)
    }
}

/// x^y.
#[inline]
#[must_use]
pub fn powf(x: f32, y: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.powf(y)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::powf(x, y)
    }
}

/// x^y.
#[inline]
#[must_use]
pub fn pow(x: f64, y: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.powf(y)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::pow(x, y)
    }
}

/// Natural logarithm.
#[inline]
#[must_use]
pub fn lnf(x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.ln()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::logf(x)
    }
}

/// Natural logarithm.
#[inline]
#[must_use]
pub fn ln(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.ln()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::log(x)
    }
}

/// Base-2 logarithm.
#[inline]
#[must_use]
pub fn log2f(x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.log2()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::log2f(x)
    }
}

/// sin x, radians.
#[inline]
#[must_use]
pub fn sinf(x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.sin()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::sinf(x)
    }
}

/// cos x, radians.
#[inline]
#[must_use]
pub fn cosf(x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.cos()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::cosf(x)
    }
}

/// sin x, radians.
#[inline]
#[must_use]
pub fn sin(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.sin()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::sin(x)
    }
}

/// cos x, radians.
#[inline]
#[must_use]
pub fn cos(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.cos()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::cos(x)
    }
}

/// arcsin x.
#[inline]
#[must_use]
pub fn asin(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.asin()
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::asin(x)
    }
}

/// The angle of (x, y), radians.
#[inline]
#[must_use]
pub fn atan2f(y: f32, x: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        y.atan2(x)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::atan2f(y, x)
    }
}

/// sqrt(x^2 + y^2) without overflow.
#[inline]
#[must_use]
pub fn hypotf(x: f32, y: f32) -> f32 {
    #[cfg(target_arch = "wasm32")]
    {
        x.hypot(y)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::hypotf(x, y)
    }
}

/// sqrt(x^2 + y^2) without overflow.
#[inline]
#[must_use]
pub fn hypot(x: f64, y: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        x.hypot(y)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        libm::hypot(x, y)
    }
}

/// The smaller of `a` and `b` by one comparison: `b` if `b < a`, else `a`. The same as
/// `f32::min` for numbers (up to the sign of a zero when both are zero); a NaN `b` gives `a`, a
/// NaN `a` gives `a`. So `lesser(bound, x)` keeps a NaN `x` out.
#[inline(always)]
#[must_use]
pub fn lesser(a: f32, b: f32) -> f32 {
    if b < a { b } else { a }
}

/// The larger of `a` and `b` by one comparison: `b` if `b > a`, else `a` (see [`lesser`]).
/// `greater(0.0, x)` is `x.max(0.0)`, a NaN `x` giving 0 as it does there.
#[inline(always)]
#[must_use]
pub fn greater(a: f32, b: f32) -> f32 {
    if b > a { b } else { a }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The values are libm's, which the wasm build's std computes too; these pin a few of them
    /// so that a change of implementation shows (each is within an ulp of the exact value).
    #[test]
    fn agrees_with_std_to_an_ulp() {
        let close = |a: f32, b: f32| (a.to_bits() as i64 - b.to_bits() as i64).abs() <= 1;
        for i in 0..2000 {
            let x = -20.0 + i as f32 * 0.0123;
            assert!(close(expf(x), x.exp()), "exp({x})");
            let d = 1e-3 + i as f32 * 0.37;
            assert!(close(powf(d, -1.2), d.powf(-1.2)), "pow({d})");
            assert!(
                close(sinf(x), x.sin()) || (sinf(x) - x.sin()).abs() < 1e-7,
                "sin({x})"
            );
            assert!(close(hypotf(x, d), x.hypot(d)), "hypot({x}, {d})");
        }
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(pow(2.0, 10.0), 1024.0);
    }

    #[test]
    fn lesser_and_greater_are_min_and_max_without_the_call() {
        let values = [
            -3.5f32,
            -0.0,
            0.0,
            1e-30,
            2.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(lesser(a, b), a.min(b), "lesser({a}, {b})");
                assert_eq!(greater(a, b), a.max(b), "greater({a}, {b})");
            }
            // A NaN never comes out of a bound: the accumulator keeps its value.
            assert_eq!(lesser(a, f32::NAN), a);
            assert_eq!(greater(a, f32::NAN), a);
        }
        assert_eq!(greater(0.0, f32::NAN), 0.0, "as f32::NAN.max(0.0)");
    }
}
