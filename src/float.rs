//! The one door to the float kernels.
//!
//! Every square root and transcendental function the crate evaluates goes
//! through the functions of this file, so that a kernel can be stubbed by
//! a proof harness or replaced by a faster one in one place. Behind the door, one file per kernel family:
//!
//! | file | what | error |
//! | --- | --- | --- |
//! | `float/atan2.rs` | [`atan2_kernel`](atan2::atan2_kernel): one division onto [-tan(1/2), tan(1/2)] and a degree-13 odd minimax polynomial | [`ATAN2_MAX_ULP`](crate::accuracy::ATAN2_MAX_ULP) |
//! | `float/sin_cos.rs` | [`sin_cos_kernel`](sin_cos::sin_cos_kernel): a degree-7 and a degree-8 minimax polynomial on [-pi/4, pi/4], one subtraction up to 3 pi/4 | [`SIN_COS_NARROW_MAX_ULP`](crate::accuracy::SIN_COS_NARROW_MAX_ULP), [`SIN_COS_MAX_ULP`](crate::accuracy::SIN_COS_MAX_ULP) beyond |
//! | `float/reduce.rs` | reduction by quarter turns for every finite f32 (Payne and Hanek, in integers), into a head and a tail | checked through the sine and cosine beyond 3 pi/4 ([`SIN_COS_MAX_ULP`](crate::accuracy::SIN_COS_MAX_ULP)) |
//! | `float/sqrt.rs` | the processor's square root instruction (Arm hard-float `vsqrt.f32`, x86-64 `sqrtss`, AArch64 `fsqrt`, the last two in a form a loop can vectorize), libm's `sqrtf` elsewhere | 0.5 ulp |
//! | `float/norm.rs` | the overflow- and underflow-free sum of squares behind every `norm` and `normalize` | 2 ulp |
//!
//! The one exception is slerp's own f64 polynomials, its arc and
//! `sin(x) / x` on x86-64 and AArch64, which live with slerp
//! (`quat/slerp/in_f64.rs`): nothing else evaluates
//! them. Nothing
//! here is evaluated in f64, so on a Cortex-M4F (single-precision FPU) no
//! soft-float helper is linked. Their
//! coefficients come from `tools/minimax.py` (Remez exchange in multiple
//! precision), and the tests of each file sweep every 997th f32 of its
//! range against f64 (every f32, with `exhaustive_kernel_sweep`). The tangent, used only by
//! `Matrix4::perspective`, is libm's `tanf`; `exp_m1`, used by the
//! smoothing factors, libm's `expm1f`.

mod atan2;
mod bits;
mod head_tail;
mod norm;
mod reduce;
mod sin_cos;
mod sqrt;
#[cfg(any(kernels_exported, test))]
mod sqrt_kani;
#[cfg(test)]
pub(crate) mod sweep;

pub(crate) use bits::SIGN;
pub(crate) use norm::{needs_no_rescaling, scale_for_squares, ScaledSquares};
pub(crate) use sin_cos::sin3;
pub use sqrt::sqrt;
#[cfg(feature = "kernel-contracts")]
pub use sqrt_kani::is_correctly_rounded_sqrt;

/// Four-quadrant arctangent of `y / x`, in [-pi, pi], with IEEE 754's
/// results for zeros and infinities (`atan2(+-0, -0) = +-pi`,
/// `atan2(inf, inf) = pi/4`, ...) and NaN for NaN.
///
/// [`atan2_kernel`](atan2::atan2_kernel), within
/// [`accuracy::ATAN2_MAX_ULP`](crate::accuracy::ATAN2_MAX_ULP) of the
/// result.
#[inline]
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    atan2::atan2_kernel(y, x)
}

/// Sine and cosine of `x` (radians), as `(sin, cos)`.
///
/// [`sin_cos_kernel`](sin_cos::sin_cos_kernel), within
/// [`accuracy::SIN_COS_NARROW_MAX_ULP`](crate::accuracy::SIN_COS_NARROW_MAX_ULP)
/// for `|x| <= 3 pi/4` and within
/// [`accuracy::SIN_COS_MAX_ULP`](crate::accuracy::SIN_COS_MAX_ULP) for
/// every other finite `x` (exact argument reduction for any size).
#[inline]
#[must_use]
pub fn sin_cos(x: f32) -> (f32, f32) {
    sin_cos::sin_cos_kernel(x)
}

/// Tangent of `x` (radians), for `Matrix4::perspective` only: libm's
/// `tanf`, within 1 ulp.
#[inline]
#[must_use]
pub(crate) fn tan(x: f32) -> f32 {
    libm::tanf(x)
}

/// `e^x - 1`, accurate also where `e^x` is close to 1: libm's `expm1f`
/// (within 1 ulp): the smoothing factors `1 - e^(-dt/tau)` built on it
/// need relative accuracy for `dt` far below `tau`.
#[inline]
#[must_use]
pub(crate) fn exp_m1(x: f32) -> f32 {
    libm::expm1f(x)
}

#[cfg(test)]
mod tests {
    //! The door's functions against `std`'s
    //! f64 functions over the ranges `pow`, `slerp` and `perspective` use.
    use super::*;
    use crate::accuracy;
    use sweep::{spread, ulps};

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

    /// The largest `error` over `xs` and where it occurs (a NaN error
    /// counts as the worst), printed and checked against `bound`.
    fn check_largest(
        what: &str,
        xs: impl Iterator<Item = f32>,
        error: impl Fn(f32) -> f64,
        bound: f32,
    ) {
        let mut worst: (f64, f32) = (0.0, 0.0);
        for x in xs {
            let e = error(x);
            if e > worst.0 || e.is_nan() {
                worst = (e, x);
            }
        }
        std::println!("{what}: max {:.4e} at {:e}", worst.0, worst.1);
        assert!(worst.0 <= bound as f64, "{what}: {worst:?}");
    }

    /// The absolute error of `sin_cos` over `x` and `-x` for every
    /// `step`-th f32 `x` of [0, 10], and the relative error of `tan` over
    /// every `step`-th f32 of [0.0087, 1.5621] (half of a field of view
    /// between 1 and 179 degrees), checked against `SIN_COS_MAX_ABS_ERROR`
    /// and `TAN_MAX_REL_ERROR`.
    fn sin_cos_and_tan_sweep(step: usize) {
        check_largest(
            "sin_cos, [-10, 10], absolute error",
            sweep::floats(0.0, 10.0, step).flat_map(|x| [x, -x]),
            |x| {
                let (s, c) = sin_cos(x);
                let x = x as f64;
                (s as f64 - x.sin()).abs().max((c as f64 - x.cos()).abs())
            },
            accuracy::SIN_COS_MAX_ABS_ERROR,
        );
        check_largest(
            "tan, [0.0087, 1.5621], relative error",
            sweep::floats(0.0087, 1.5621, step),
            |x| (tan(x) as f64 / (x as f64).tan() - 1.0).abs(),
            accuracy::TAN_MAX_REL_ERROR,
        );
    }

    sweep::sweep_tests!(sin_cos_and_tan_sweep);

    /// The largest absolute error of `sin_cos` over 400,000 points of
    /// [lo, hi], checked against `SIN_COS_MAX_ABS_ERROR`.
    fn sweep_sin_cos_over(what: &str, lo: f64, hi: f64) {
        let mut worst: f64 = 0.0;
        for x in spread(lo, hi, 400_000) {
            let (s, c) = sin_cos(x);
            worst = worst
                .max((s as f64 - (x as f64).sin()).abs())
                .max((c as f64 - (x as f64).cos()).abs());
        }
        std::println!("{what}: max absolute error {worst:.3e}");
        assert!(worst <= accuracy::SIN_COS_MAX_ABS_ERROR as f64, "{worst}");
    }

    #[test]
    fn sweep_sin_cos_of_large_arguments() {
        // The turns pow and slerp hand to sin_cos with large exponents.
        sweep_sin_cos_over("sin_cos of large arguments", -70_000.0, 70_000.0);
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

    #[test]
    fn sin_cos_of_huge_arguments_stays_in_range() {
        for x in [1e10_f32, -3e20, 1e38, f32::MAX, -f32::MAX] {
            let (s, c) = sin_cos(x);
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
        }
    }
}
