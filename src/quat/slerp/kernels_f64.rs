//! Slerp's angle and sines in f64, on 64-bit desktop targets (x86-64 and
//! AArch64), where an f64 operation costs what an f32 one does: one
//! polynomial each, without the range reductions and their selects that
//! f32 needs for the same accuracy, and with rounding errors far below an
//! f32 ulp. Never compiled for the microcontrollers, whose FPUs have no
//! f64 (the f32 kernels serve them).

use crate::float::sqrt;

/// Minimax coefficients of `(atan(u) - u) / u^3` as a polynomial in `u^2`
/// on [0, 1], for relative error (`tools/minimax.py atan_f64`): the
/// approximation error is 1.7e-8 of the result.
pub(crate) const ATAN: [f64; 8] = [
    -0.333_331_527_378_383_06,
    0.199_937_728_817_470_77,
    -0.142_110_557_110_242_54,
    0.106_660_062_753_114_79,
    -0.075_522_178_037_118_6,
    0.043_211_902_355_727_805,
    -0.016_367_953_412_402_284,
    0.002_920_698_523_972_636,
];

/// Minimax coefficients of `(sin(x) - x) / x^3` as a polynomial in `x^2`
/// on [0, pi/2], for relative error (`tools/minimax.py sin_f64`): the
/// approximation error is 6.1e-9 of the result.
pub(crate) const SIN: [f64; 4] = [
    -0.166_666_595_504_268_43,
    0.008_333_066_246_154_522,
    -0.000_198_096_029_100_214_08,
    2.605_780_657_782_845e-6,
];

/// The sign bit of an f64.
const SIGN: u64 = 0x8000_0000_0000_0000;

/// `atan2(sqrt(w), x)`, the angle in [0, pi/2] of the point
/// `(x, sqrt(w))`, for `w > 0` and `x >= 0` (both from f32, so that `x^2`
/// is exact), without a branch and without taking `sqrt(w)` first.
///
/// With `z` the ratio of the smaller of `w` and `x^2` to the larger, in
/// [0, 1], the angle is `atan(sqrt(z))`, or `pi/2` less it when `w` is the
/// larger; `atan(u) = u + u^3 P(u^2)` with the degree-7 polynomial
/// [`ATAN`], evaluated by Estrin's scheme (a shorter chain of dependent
/// operations than Horner's) while `sqrt(z)` is taken in f32 by the
/// crate's [`sqrt`]. The quarter turn and the sign are applied by
/// arithmetic on the sign of `x^2 - w`, not by a select, which compilers
/// turn into a branch that random inputs mispredict.
///
/// # Preconditions
///
/// `w` is positive and finite, `x` finite and not negative; then no
/// operation makes a NaN or an infinity.
///
/// # Accuracy
///
/// Relative error below
/// [`accuracy::ANGLE_F64_MAX_REL_ERROR`](crate::accuracy::ANGLE_F64_MAX_REL_ERROR):
/// the f32 square root of `z` rounded to f32 (0.75 of an f32 ulp at most),
/// the polynomial's 1.7e-8 and the f64 rounding.
#[inline(always)]
#[must_use]
pub fn atan2_of_root(w: f64, x: f64) -> f64 {
    let x2 = x * x;
    // Comparisons rather than `min` and `max`, whose NaN rules cost
    // instructions (neither is NaN here).
    let below = w < x2;
    let z = if below { w } else { x2 } / if below { x2 } else { w };
    let u = f64::from(sqrt(z as f32));
    let z2 = z * z;
    let z4 = z2 * z2;
    let c = ATAN;
    let low = (c[0] + z * c[1]) + z2 * (c[2] + z * c[3]);
    let high = (c[4] + z * c[5]) + z2 * (c[6] + z * c[7]);
    let p = low + z4 * high;
    let a = u + u * (z * p);
    // x^2 - w is negative exactly when the angle is above pi/4: then
    // pi/2 - a (a quarter turn and the sign of a flipped), else a.
    let d = x2 - w;
    let quarter = 0.5 - 0.5f64.copysign(d);
    let flipped = f64::from_bits(a.to_bits() ^ (d.to_bits() & SIGN));
    quarter * core::f64::consts::FRAC_PI_2 + flipped
}

/// `sin(x)` for `0 <= x <= pi/2`: `x + x^3 P(x^2)` with the degree-3
/// polynomial [`SIN`], in pairs (`x^3` beside `P`).
///
/// # Accuracy
///
/// Relative error below
/// [`accuracy::SIN_F64_MAX_REL_ERROR`](crate::accuracy::SIN_F64_MAX_REL_ERROR):
/// the polynomial's 6.1e-9 and the f64 rounding, a tenth of an f32 ulp.
#[inline(always)]
#[must_use]
pub fn sin_to_quarter_turn(x: f64) -> f64 {
    let s = x * x;
    let p = (SIN[0] + s * SIN[1]) + (s * s) * (SIN[2] + s * SIN[3]);
    x + (x * s) * p
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{ANGLE_F64_MAX_REL_ERROR, SIN_F64_MAX_REL_ERROR};
    use crate::float::sweep::{floats, SAMPLE_STEP};
    use core::f32::consts::FRAC_PI_2;

    /// The largest relative error of [`sin_to_quarter_turn`] over every
    /// `step`-th f32 of [2^-30, pi/2], against `std`'s f64 sine.
    fn sine_sweep(step: usize) -> (f64, f32) {
        let mut worst = (0.0, 0.0);
        for x in floats(9.3e-10, FRAC_PI_2, step) {
            let exact = f64::from(x).sin();
            let err = ((sin_to_quarter_turn(f64::from(x)) - exact) / exact).abs();
            if err > worst.0 {
                worst = (err, x);
            }
        }
        worst
    }

    /// The largest relative error of [`atan2_of_root`] over `(w, x)` =
    /// `(t, 1)` and `(1, t)` for every `step`-th f32 `t` of [2^-30, 1]
    /// (both sides of pi/4; in the first, `sqrt(t)` is rounded), against
    /// `std`'s f64 atan2.
    fn angle_sweep(step: usize) -> (f64, f32) {
        let mut worst = (0.0, 0.0);
        for t in floats(9.3e-10, 1.0, step) {
            for (w, x) in [(f64::from(t), 1.0), (1.0, f64::from(t))] {
                let exact = w.sqrt().atan2(x);
                let err = ((atan2_of_root(w, x) - exact) / exact).abs();
                if err > worst.0 {
                    worst = (err, t);
                }
            }
        }
        worst
    }

    #[test]
    fn sine_is_within_its_bound_on_a_sample() {
        let (err, x) = sine_sweep(SAMPLE_STEP);
        assert!(err <= f64::from(SIN_F64_MAX_REL_ERROR), "{err:e} at {x}");
    }

    #[test]
    fn angle_is_within_its_bound_on_a_sample() {
        let (err, t) = angle_sweep(SAMPLE_STEP);
        assert!(err <= f64::from(ANGLE_F64_MAX_REL_ERROR), "{err:e} at {t}");
    }

    /// Every f32 of the ranges:
    /// `cargo test --release --lib -- --ignored exhaustive_kernel_sweep`.
    #[test]
    #[ignore = "minutes in release: run by hand after changing a kernel"]
    fn exhaustive_kernel_sweep() {
        let (sine, x) = sine_sweep(1);
        let (angle, t) = angle_sweep(1);
        std::println!("sin_to_quarter_turn: {sine:e} at {x}; atan2_of_root: {angle:e} at {t}");
        assert!(sine <= f64::from(SIN_F64_MAX_REL_ERROR));
        assert!(angle <= f64::from(ANGLE_F64_MAX_REL_ERROR));
    }

    /// The edges of the angle's range: 0, pi/4 and pi/2 exactly where the
    /// inputs say so.
    #[test]
    fn angle_meets_its_edges() {
        assert_eq!(atan2_of_root(1.0, 0.0), core::f64::consts::FRAC_PI_2);
        let tiny = atan2_of_root(1e-30, 1.0);
        assert!((tiny / 1e-15 - 1.0).abs() < 1e-7, "{tiny:e}");
        let quarter = atan2_of_root(1.0, 1.0);
        let quarter_error = (quarter / core::f64::consts::FRAC_PI_4 - 1.0).abs();
        assert!(
            quarter_error <= f64::from(ANGLE_F64_MAX_REL_ERROR),
            "{quarter}"
        );
    }
}
