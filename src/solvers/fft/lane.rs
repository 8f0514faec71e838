//! One complex value as one SIMD register where the target has 128-bit vectors (wasm `simd128`:
//! `f64x2` holds `re, im`), plain `f64` pairs elsewhere. The butterflies are written once against
//! this type; LLVM does not find the pairing in scalar complex code by itself, and in wasm the
//! vector form makes graph cut's searches about a fifth faster.

use super::Complex;

type C = Complex<f64>;

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod imp {
    use core::arch::wasm32::{
        f64x2, f64x2_add, f64x2_extract_lane, f64x2_mul, f64x2_splat, f64x2_sub, i64x2_shuffle,
        v128,
    };

    use super::C;

    #[derive(Clone, Copy)]
    pub(in super::super) struct Lane(v128);

    impl Lane {
        #[inline(always)]
        pub(in super::super) fn load(value: C) -> Lane {
            Lane(f64x2(value.re, value.im))
        }

        #[inline(always)]
        pub(in super::super) fn get(self) -> C {
            C::new(
                f64x2_extract_lane::<0>(self.0),
                f64x2_extract_lane::<1>(self.0),
            )
        }

        #[inline(always)]
        pub(in super::super) fn add(self, other: Lane) -> Lane {
            Lane(f64x2_add(self.0, other.0))
        }

        #[inline(always)]
        pub(in super::super) fn sub(self, other: Lane) -> Lane {
            Lane(f64x2_sub(self.0, other.0))
        }

        #[inline(always)]
        pub(in super::super) fn scale(self, factor: f64) -> Lane {
            Lane(f64x2_mul(self.0, f64x2_splat(factor)))
        }

        /// The complex product: `(a.re w.re - a.im w.im, a.im w.re + a.re w.im)`.
        #[inline(always)]
        pub(in super::super) fn mul(self, w: Lane) -> Lane {
            let re = i64x2_shuffle::<0, 0>(w.0, w.0);
            let im = i64x2_shuffle::<1, 1>(w.0, w.0);
            let swapped = i64x2_shuffle::<1, 0>(self.0, self.0);
            let signed_im = f64x2_mul(im, f64x2(-1.0, 1.0));
            Lane(f64x2_add(
                f64x2_mul(self.0, re),
                f64x2_mul(swapped, signed_im),
            ))
        }

        /// `self * conj(w)`: `(a.re w.re + a.im w.im, a.im w.re - a.re w.im)`.
        #[inline(always)]
        pub(in super::super) fn mul_conj(self, w: Lane) -> Lane {
            let re = i64x2_shuffle::<0, 0>(w.0, w.0);
            let im = i64x2_shuffle::<1, 1>(w.0, w.0);
            let swapped = i64x2_shuffle::<1, 0>(self.0, self.0);
            let signed_im = f64x2_mul(im, f64x2(1.0, -1.0));
            Lane(f64x2_add(
                f64x2_mul(self.0, re),
                f64x2_mul(swapped, signed_im),
            ))
        }

        /// Times `-i` (forward) or `+i` (inverse).
        #[inline(always)]
        pub(in super::super) fn rotate<const INVERSE: bool>(self) -> Lane {
            let swapped = i64x2_shuffle::<1, 0>(self.0, self.0);
            let signs = if INVERSE {
                f64x2(-1.0, 1.0)
            } else {
                f64x2(1.0, -1.0)
            };
            Lane(f64x2_mul(swapped, signs))
        }
    }
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
mod imp {
    use super::C;

    #[derive(Clone, Copy)]
    pub(in super::super) struct Lane(C);

    impl Lane {
        #[inline(always)]
        pub(in super::super) fn load(value: C) -> Lane {
            Lane(value)
        }

        #[inline(always)]
        pub(in super::super) fn get(self) -> C {
            self.0
        }

        #[inline(always)]
        pub(in super::super) fn add(self, other: Lane) -> Lane {
            Lane(self.0 + other.0)
        }

        #[inline(always)]
        pub(in super::super) fn sub(self, other: Lane) -> Lane {
            Lane(self.0 - other.0)
        }

        #[inline(always)]
        pub(in super::super) fn scale(self, factor: f64) -> Lane {
            Lane(self.0 * factor)
        }

        #[inline(always)]
        pub(in super::super) fn mul(self, w: Lane) -> Lane {
            Lane(self.0 * w.0)
        }

        #[inline(always)]
        pub(in super::super) fn mul_conj(self, w: Lane) -> Lane {
            Lane(self.0 * w.0.conj())
        }

        /// Times `-i` (forward) or `+i` (inverse).
        #[inline(always)]
        pub(in super::super) fn rotate<const INVERSE: bool>(self) -> Lane {
            if INVERSE {
                Lane(C::new(-self.0.im, self.0.re))
            } else {
                Lane(C::new(self.0.im, -self.0.re))
            }
        }
    }
}

pub(super) use imp::Lane;
