//! The one door to the float backend.
//!
//! Every square root and transcendental function the crate evaluates goes
//! through this file, so that a backend can be swapped (feature `fast-math`),
//! stubbed by a proof harness, or replaced by a faster kernel in one place.
//!
//! - default: [`libm`], the Rust port of musl's libm (itself from FreeBSD's
//!   msun). Its f32 kernels evaluate in f64 internally and are accurate to
//!   within one ulp; the sweep tests at the bottom of this file measure each
//!   one against `std`'s f64 functions.
//! - `fast-math`: [`micromath`]'s approximations of atan2, sin, cos and tan,
//!   smaller and faster, with the much larger errors the sweep tests measure
//!   for them (see [`crate::accuracy`]), guarded where micromath breaks
//!   down: rescaled arguments, Taylor terms near zero, and libm for zero,
//!   huge or non-finite arguments. The square root stays libm's (see [`sqrt`]).
//!
//! It also holds [`scale_for_squares`], the overflow- and underflow-free sum of
//! squares behind every `norm` and `normalize` of the crate.

/// Square root: libm's, correctly rounded (0.5 ulp), with both backends.
///
/// `fast-math` keeps it on purpose: micromath's `sqrt` is a single
/// bit-level estimate with a relative error of up to 6.1 % (6.066e-2 over
/// [1e-3, 4], `micromaths_sqrt_is_too_coarse_for_normalize`; and its
/// `sqrt(0)` is 8e-20), which would leave `normalize` nearly useless.
#[inline]
#[must_use]
pub(crate) fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// Four-quadrant arctangent of `y / x`, in [-pi, pi]. libm: within 1 ulp
/// (FreeBSD's `e_atan2f.c` argument reduction onto `atanf`). fast-math:
/// micromath's rational approximation, absolute error about 3e-3 rad
/// (measured by `sweep_atan2` below), on arguments with magnitudes within
/// [2^-20, 2^20] (others are first divided by the larger magnitude), where
/// its squares cannot overflow or underflow
/// (micromath's `atan2(1e-30, 1e-30)` is NaN); libm where either argument is
/// zero or not finite. The result gets the sign of `y`, as atan2's always
/// has: micromath returns +pi instead of -pi for a tiny negative `y` against
/// a negative `x`.
#[inline]
#[must_use]
pub(crate) fn atan2(y: f32, x: f32) -> f32 {
    #[cfg(feature = "fast-math")]
    if y.is_finite() && x.is_finite() && y != 0.0 && x != 0.0 {
        let largest = y.abs().max(x.abs());
        let (y, x) = if (FAST_ATAN2_LOW..=FAST_ATAN2_HIGH).contains(&largest) {
            (y, x)
        } else {
            (y / largest, x / largest)
        };
        // The smaller argument may now be tiny beside the larger, or even
        // zero: its square then vanishes, which only rounds the angle to 0,
        // pi/2 or pi, as it should.
        return micromath::F32Ext::atan2(y, x).copysign(y);
    }
    libm::atan2f(y, x)
}

/// Sine and cosine of `x` (radians), as `(sin, cos)`. libm: within 1 ulp for
/// every finite `x`, with exact (Payne-Hanek) argument reduction for huge
/// arguments. fast-math: micromath's parabola approximations, absolute error
/// about 1e-3 (measured by `sweep_sin_cos` below), for `2^-6 <= |x| <= 2^16`;
/// libm beyond, where micromath's own reduction returns infinities. Below
/// 2^-6, where micromath's absolute error would swamp small rotations (its
/// `sin(1e-5)` is 0), Taylor polynomials of degree 3 and 2 instead: error
/// below `x^5 / 120` (8e-12) and `x^4 / 24` (2.5e-9, under half an ulp of 1).
#[inline]
#[must_use]
pub(crate) fn sin_cos(x: f32) -> (f32, f32) {
    #[cfg(feature = "fast-math")]
    {
        let a = x.abs();
        if a < FAST_SIN_COS_TAYLOR {
            let x2 = x * x;
            // The x^4 / 24 term of the cosine is below 2.5e-9, under half an
            // ulp of 1: f32 cannot hold it.
            return (x - x * x2 * (1.0 / 6.0), 1.0 - x2 * 0.5);
        }
        if a <= FAST_SIN_COS_LIMIT {
            return (micromath::F32Ext::sin(x), micromath::F32Ext::cos(x));
        }
    }
    libm::sincosf(x)
}

/// Tangent of `x` (radians). libm: within 1 ulp. fast-math: micromath's
/// tangent (about 1 % relative error over half fields of view, measured by
/// `sweep_tan` below) for `|x| <= 2^16`, libm beyond.
#[inline]
#[must_use]
pub(crate) fn tan(x: f32) -> f32 {
    #[cfg(feature = "fast-math")]
    if x.abs() <= FAST_SIN_COS_LIMIT {
        return micromath::F32Ext::tan(x);
    }
    libm::tanf(x)
}

/// `e^x - 1`, accurate also where `e^x` is close to 1: libm's `expm1f`
/// (within 1 ulp), with both backends (micromath has no `exp_m1`, and the
/// smoothing factors `1 - e^(-dt/tau)` built on it need relative accuracy
/// for `dt` far below `tau`).
#[inline]
#[must_use]
pub(crate) fn exp_m1(x: f32) -> f32 {
    libm::expm1f(x)
}

/// 2^-6: below this, fast-math's sine and cosine are Taylor polynomials.
#[cfg(feature = "fast-math")]
const FAST_SIN_COS_TAYLOR: f32 = 0.015625;
/// 2^16: beyond this, micromath's f32 range reduction loses the argument.
#[cfg(feature = "fast-math")]
const FAST_SIN_COS_LIMIT: f32 = 65536.0;
/// 2^20 and 2^-20: the range in which micromath's atan2 squares its arguments safely.
#[cfg(feature = "fast-math")]
const FAST_ATAN2_HIGH: f32 = f32::from_bits((127 + 20) << 23);
#[cfg(feature = "fast-math")]
const FAST_ATAN2_LOW: f32 = f32::from_bits((127 - 20) << 23);

/// 2^-100: below this, a sum of squares may have lost precision to underflow.
/// A component whose square underflows contributes at most 2^-150 of absolute
/// error, so above this threshold the relative error it causes is at most
/// 2^-50, far below one ulp (2^-24).
const SQUARES_UNDERFLOW: f32 = f32::from_bits((127 - 100) << 23);
/// 2^100, exact scale for small inputs: when the sum of squares is below
/// 2^-100, every component is below 2^-50 and becomes less than 2^50, while
/// the smallest subnormal (2^-149) becomes 2^-49, whose square is normal.
const SCALE_UP_SMALL: f32 = f32::from_bits((127 + 100) << 23);
/// 2^-66, exact scale for huge inputs: f32::MAX (< 2^128) becomes < 2^62,
/// whose square, times four, stays below 2^126.
const SCALE_DOWN_HUGE: f32 = f32::from_bits((127 - 66) << 23);

/// The components of a vector, scaled by an exact power of two, and the sum
/// of their squares.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScaledSquares {
    /// The input components times `scale`.
    pub(crate) v: [f32; 4],
    /// The power of two the components were multiplied by (1 in the common case).
    pub(crate) scale: f32,
    /// The sum of the squares of `v` (NaN if any input was NaN, infinite if
    /// any input was infinite, 0 only if every input was zero).
    pub(crate) sum: f32,
}

impl ScaledSquares {
    /// The Euclidean norm of the original, unscaled components (may round
    /// to infinity when the true norm exceeds `f32::MAX`).
    #[inline]
    #[must_use]
    pub(crate) fn norm(self) -> f32 {
        sqrt(self.sum) / self.scale
    }

    /// The original components divided by their norm, or `None` if they are
    /// all zero or any is NaN or infinite.
    #[inline]
    #[must_use]
    pub(crate) fn unit(self) -> Option<[f32; 4]> {
        if !(self.sum > 0.0 && self.sum <= f32::MAX) {
            return None;
        }
        let n = sqrt(self.sum);
        let [a, b, c, d] = self.v;
        Some([a / n, b / n, c / n, d / n])
    }
}

/// Sum of squares of `v` without overflow or underflow: the method of LAPACK's
/// `xNRM2` and of C's `hypot`, with exact power-of-two scaling.
///
/// In the common case (the sum of squares lies in [2^-100, f32::MAX]) this is
/// four multiplications and three additions with `scale == 1`. Otherwise the
/// components are multiplied by 2^100 (the sum underflowed) or 2^-66 (it
/// overflowed) and squared again, so that subnormal vectors (down to 2^-149)
/// and vectors with components up to `f32::MAX` keep full precision. The
/// resulting norm is within 2 ulp (`normalize_is_within_its_bound_from_subnormal_to_huge`
/// in `tests/differential.rs` measures 1.653 ulp over 10^7 draws).
#[must_use]
pub(crate) fn scale_for_squares(v: [f32; 4]) -> ScaledSquares {
    let sum = sum_of_squares(v);
    // NaN is in no range: it is returned as it is, with the sum NaN.
    if (SQUARES_UNDERFLOW..=f32::MAX).contains(&sum) || sum.is_nan() {
        return ScaledSquares { v, scale: 1.0, sum };
    }
    // The sum overflowed (some component is at least 2^63, or infinite) or may
    // have lost precision to underflow (every component is below 2^-50). Zero
    // and infinite components survive the scaling unchanged.
    let scale = if sum.is_infinite() {
        SCALE_DOWN_HUGE
    } else {
        SCALE_UP_SMALL
    };
    let v = v.map(|c| c * scale);
    ScaledSquares {
        v,
        scale,
        sum: sum_of_squares(v),
    }
}

#[inline]
fn sum_of_squares([a, b, c, d]: [f32; 4]) -> f32 {
    a * a + b * b + c * c + d * d
}

#[cfg(test)]
mod tests {
    //! Sweeps of each kernel against `std`'s f64 functions, as libm tests its
    //! own: many points spread over the range `pow`, `slerp` and `perspective`
    //! use, with the error measured in units in the last place of the f32
    //! result.
    use super::*;
    use crate::accuracy;

    /// Distance from `got` to the exact `want`, in ulps of `want` rounded to f32.
    fn ulps(got: f32, want: f64) -> f64 {
        let w = want as f32;
        let ulp = (f32::from_bits(w.abs().to_bits() + 1) - w.abs()) as f64;
        (got as f64 - want).abs() / ulp
    }

    /// `n` points evenly spread over [lo, hi], endpoints included.
    fn spread(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f32> {
        (0..=n).map(move |i| (lo + (hi - lo) * i as f64 / n as f64) as f32)
    }

    #[test]
    fn sweep_sqrt() {
        let mut worst: f64 = 0.0;
        for x in spread(0.0, 4.0, 200_000).chain(spread(1e-30, 1e30, 10_000)) {
            worst = worst.max(ulps(sqrt(x), (x as f64).sqrt()) * f32::EPSILON as f64);
        }
        std::println!("sqrt: max relative error {worst:.3e}");
        assert!(worst <= accuracy::SQRT_MAX_REL_ERROR as f64, "{worst}");
    }

    #[test]
    fn sweep_exp_m1() {
        let mut worst: f64 = 0.0;
        // The smoothing factors' range: -dt/tau from -1e-7 to -50.
        for x in spread(-50.0, 0.0, 200_000).chain(spread(-1e-3, -1e-7, 10_000)) {
            worst = worst.max(ulps(exp_m1(x), (x as f64).exp_m1()));
        }
        std::println!("exp_m1: max error {worst:.3} ulp");
        assert!(worst <= 1.0, "{worst}");
        assert_eq!(exp_m1(f32::NEG_INFINITY), -1.0);
        assert!(exp_m1(f32::NAN).is_nan());
    }

    #[test]
    fn sweep_atan2() {
        let mut worst: f64 = 0.0;
        let pi = core::f64::consts::PI;
        for t in spread(-pi, pi, 200_000) {
            let (y, x) = ((t as f64).sin() as f32, (t as f64).cos() as f32);
            let want = (y as f64).atan2(x as f64);
            worst = worst.max((atan2(y, x) as f64 - want).abs());
        }
        std::println!("atan2: max absolute error {worst:.3e} rad");
        assert!(worst <= accuracy::ATAN2_MAX_ABS_ERROR as f64, "{worst}");
    }

    #[test]
    fn sweep_sin_cos() {
        let mut worst: f64 = 0.0;
        for x in spread(-10.0, 10.0, 400_000) {
            let (s, c) = sin_cos(x);
            worst = worst
                .max((s as f64 - (x as f64).sin()).abs())
                .max((c as f64 - (x as f64).cos()).abs());
        }
        std::println!("sin_cos: max absolute error {worst:.3e}");
        assert!(worst <= accuracy::SIN_COS_MAX_ABS_ERROR as f64, "{worst}");
    }

    #[test]
    fn sin_cos_is_relatively_accurate_near_zero() {
        // Small rotations need relative, not absolute, accuracy: within an
        // ulp of x for the sine, of 1 for the cosine, inside (-2^-6, 2^-6).
        for x in spread(-0.01562, 0.01562, 20_000).chain([1e-5, -3e-30, 1e-45]) {
            let (s, c) = sin_cos(x);
            let x64 = x as f64;
            assert!(
                (s as f64 - x64.sin()).abs() <= x64.abs() * 1.2e-7,
                "sin {x}: {s}"
            );
            assert!((c as f64 - x64.cos()).abs() <= 1.2e-7, "cos {x}: {c}");
        }
    }

    #[test]
    fn atan2_of_edge_arguments() {
        use core::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        let cases = [
            (0.0, 1.0, 0.0),
            (0.0, -1.0, PI),
            (-0.0, -1.0, -PI),
            (-1e-30, -1.0, -PI),
            (1.0, 0.0, FRAC_PI_2),
            (1e-30, 1e-30, FRAC_PI_4),
            (-1e-40, 1e-40, -FRAC_PI_4),
            (3e38, 3e38, FRAC_PI_4),
            (1e-45, 1e30, 0.0),
            (1e30, -1e-45, FRAC_PI_2),
            (f32::INFINITY, 1.0, FRAC_PI_2),
            (f32::INFINITY, f32::INFINITY, FRAC_PI_4),
            (1.0, f32::NEG_INFINITY, PI),
            (0.0, 0.0, 0.0),
        ];
        for (y, x, want) in cases {
            let got = atan2(y, x);
            assert!(
                (got - want).abs() <= accuracy::ATAN2_MAX_ABS_ERROR,
                "atan2({y}, {x}) = {got}"
            );
        }
        assert!(atan2(f32::NAN, 1.0).is_nan() && atan2(1.0, f32::NAN).is_nan());
    }

    /// The feature does what it says: inside their ranges the kernels are
    /// micromath's, bit for bit (the accuracy sweeps alone would also pass
    /// if everything had quietly fallen back to libm).
    #[cfg(feature = "fast-math")]
    #[test]
    fn fast_math_kernels_are_micromaths_inside_their_ranges() {
        use micromath::F32Ext;
        for (y, x) in [(0.5f32, 0.7f32), (-3.0, 2.0), (1e5, -3e5), (-1e-3, -2e-3)] {
            assert_eq!(atan2(y, x), F32Ext::atan2(y, x), "atan2({y}, {x})");
        }
        for x in [0.5f32, -2.0, 1000.0, -60000.0] {
            assert_eq!(sin_cos(x), (F32Ext::sin(x), F32Ext::cos(x)), "sin_cos({x})");
        }
        for x in [0.3f32, 1.2] {
            assert_eq!(tan(x), F32Ext::tan(x), "tan({x})");
        }
    }

    /// Why fast-math keeps libm's square root: micromath's (2.1) is off by
    /// several percent, as the `sqrt` doc says.
    #[cfg(feature = "fast-math")]
    #[test]
    fn micromaths_sqrt_is_too_coarse_for_normalize() {
        let mut worst: f64 = 0.0;
        for x in spread(1e-3, 4.0, 100_000) {
            let got = micromath::F32Ext::sqrt(x) as f64;
            worst = worst.max((got - (x as f64).sqrt()).abs() / (x as f64).sqrt());
        }
        std::println!("micromath sqrt: max relative error {worst:.3e}");
        assert!(
            worst > 0.05,
            "micromath's sqrt improved to {worst}: reconsider using it"
        );
        assert!(micromath::F32Ext::sqrt(0.0f32) != 0.0);
    }

    #[test]
    fn sin_cos_of_huge_arguments_stays_in_range() {
        for x in [1e10_f32, -3e20, 1e38, f32::MAX, -f32::MAX] {
            let (s, c) = sin_cos(x);
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
        }
    }

    #[test]
    fn sweep_tan() {
        let mut worst: f64 = 0.0;
        // Half of a field of view between 1 and 179 degrees.
        for x in spread(0.0087, 1.5621, 100_000) {
            let want = (x as f64).tan();
            worst = worst.max((tan(x) as f64 - want).abs() / want);
        }
        std::println!("tan: max relative error {worst:.3e}");
        assert!(worst <= accuracy::TAN_MAX_REL_ERROR as f64, "{worst}");
    }

    #[test]
    fn scaled_norm_is_exact_to_an_ulp_from_subnormal_to_max() {
        let cases: [[f32; 4]; 7] = [
            [3.0, 4.0, 0.0, 0.0],
            [3e-45, 4e-45, 0.0, 0.0],
            [1e-30, 1e-30, 1e-30, 1e-30],
            [f32::MAX, 0.0, 0.0, 0.0],
            [1e30, 1e30, 1e30, 1e30],
            [f32::MAX / 2.0, f32::MAX / 2.0, 0.0, 0.0],
            [1e-20, 0.0, 0.0, 1e-20],
        ];
        for v in cases {
            let exact = v
                .iter()
                .map(|&c| (c as f64) * (c as f64))
                .sum::<f64>()
                .sqrt();
            let got = scale_for_squares(v).norm();
            // Subnormal results have coarser ulps; compare relative to f32 ulps of the exact norm.
            assert!(ulps(got, exact) <= 2.0, "{v:?}: {got} vs {exact}");
        }
    }

    #[test]
    fn unit_of_degenerate_vectors_is_none() {
        assert!(scale_for_squares([0.0; 4]).unit().is_none());
        assert!(scale_for_squares([f32::NAN, 1.0, 0.0, 0.0])
            .unit()
            .is_none());
        assert!(scale_for_squares([f32::INFINITY, 1.0, 0.0, 0.0])
            .unit()
            .is_none());
        let u = scale_for_squares([1e-45, 0.0, 0.0, 0.0]).unit();
        assert_eq!(u, Some([1.0, 0.0, 0.0, 0.0]));
        let [a, b, c, d] = scale_for_squares([f32::MAX, f32::MAX, 0.0, 0.0])
            .unit()
            .expect("finite");
        let h = core::f64::consts::FRAC_1_SQRT_2;
        assert!(ulps(a, h) <= 1.0 && ulps(b, h) <= 1.0, "{a} {b}");
        assert_eq!((c, d), (0.0, 0.0));
    }

    #[test]
    fn nan_and_infinity_survive_the_norm() {
        assert!(scale_for_squares([f32::NAN, 0.0, 0.0, 0.0]).norm().is_nan());
        assert_eq!(
            scale_for_squares([f32::NEG_INFINITY, 0.0, 0.0, 0.0]).norm(),
            f32::INFINITY
        );
        assert_eq!(scale_for_squares([0.0, -0.0, 0.0, 0.0]).norm(), 0.0);
    }
}
