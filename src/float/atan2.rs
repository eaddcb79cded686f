//! The default backend's arctangent: [`atan2_kernel`], one division onto
//! [-tan(1/2), tan(1/2)] and a degree-13 odd minimax polynomial, f32 only.

use super::bits::{select, SIGN};
use super::head_tail::{PIO2_HI, PIO2_LO, PIO4_HI, PIO4_LO, PI_HI, PI_LO};

/// tan(1/2), rounded to f32: the bound of [`atan_poly`]'s range.
pub(super) const TAN_HALF: f32 = 0.546_302_5;

/// 2^60: how much [`atan2_kernel`] scales its arguments for its branch
/// tests where `|y| <= 1`.
const TINY_SCALE: f32 = f32::from_bits((127 + 60) << 23);

/// Minimax coefficients of `(atan(u) - u) / u^3` as a polynomial in `u^2`,
/// on |u| <= tan(1/2), for relative error (`tools/minimax.py atan`):
/// the approximation error is 7.7e-10 of the result, 1 % of an ulp.
const ATAN: [f32; 6] = [
    -0.333_333_16,
    0.199_989_1,
    -0.142_611_64,
    0.108_522_59,
    -0.076_592_16,
    0.034_324_907,
];

/// `atan(u)` for `|u| <= tan(1/2)`: `u + u^3 P(u^2)`, with `P` the degree-5
/// minimax polynomial [`ATAN`]. Within
/// [`accuracy::ATAN_POLY_MAX_ULP`](crate::accuracy::ATAN_POLY_MAX_ULP) over
/// the whole range; odd, exactly: `atan_poly(-u) == -atan_poly(u)`.
#[inline]
fn atan_poly(u: f32) -> f32 {
    let s = u * u;
    // Estrin's scheme: three independent pairs, then two steps in s^2
    // (a shorter chain of dependent operations than Horner's).
    let s2 = s * s;
    let p = (ATAN[0] + s * ATAN[1]) + s2 * ((ATAN[2] + s * ATAN[3]) + s2 * (ATAN[4] + s * ATAN[5]));
    u + u * (s * p)
}

/// The f32-only arctangent of the default backend (see
/// [`float::atan2`](super::atan2)).
///
/// With `a = |x|` and `b = |y|`, the angle `phi` of the point `(a, b)` in
/// [0, pi/2] comes from one division and [`atan_poly`]:
/// `atan(b / a)` up to 1/2 rad, `pi/2 - atan(a / b)` from pi/2 - 1/2 on,
/// and `pi/4 + atan((b - a) / (b + a))` between (the identity
/// `atan(t) = pi/4 + atan((t - 1) / (t + 1))`, with the division done
/// once, and `|u| <= tan(pi/4 - 1/2)`, small enough that the rounding of
/// `b - a` and `b + a` costs less than an ulp of `phi`). Then `pi - phi`
/// for a negative `x`, and the sign of `y`. Constants are added as a head
/// and a tail, so that their rounding does not count.
///
/// Within [`accuracy::ATAN2_MAX_ULP`](crate::accuracy::ATAN2_MAX_ULP) of
/// the exact angle for every pair of finite arguments (the sweep takes
/// every f32 quotient of each branch, with the exact ratio anywhere it
/// rounds from; others take every f32 `t` in [0, 1] as `(t, 1)`, `(1, t)`,
/// `(t, -1)`, `(1, -t)` and `(1 + t, 1)`, and pairs at every scale).
#[inline]
#[must_use]
pub(crate) fn atan2_kernel(y: f32, x: f32) -> f32 {
    let (b, a) = (y.abs(), x.abs());
    // IEEE 754's limits, by substitution rather than a separate path: two
    // infinities count as (1, 1), two zeros as (0, 1). One infinity needs
    // nothing (the division below gives 0 for it), and NaN stays NaN.
    let infinite = a == f32::INFINITY && b == f32::INFINITY;
    let (b, a) = (select(infinite, 1.0, b), select(infinite, 1.0, a));
    let a = select(a == 0.0 && b == 0.0, 1.0, a);
    // The angle of (a, b) in [0, pi/2] as hi + atan(num / den) + lo: at
    // most 1/2 rad, at least pi/2 - 1/2, or between, where a and b are
    // within a factor 2 of each other. Selected by bit masks, which
    // compile to no branch. The branch tests and the middle branch take
    // both scaled, exactly where it matters: by 2^60 for `b` up to 1, so
    // that the tests' products by tan(1/2) are never subnormal (two equal
    // subnormals would otherwise pass for a ratio below tan(1/2)), and by
    // 1/4 above, so that `b + a` cannot overflow. Where a scaled `a`
    // overflows or loses bits, it is far from `b` and the tests' outcome
    // is the same.
    let scale = select(b > 1.0, 0.25, TINY_SCALE);
    let (qb, qa) = (b * scale, a * scale);
    let (low, high) = (qb <= qa * TAN_HALF, qa <= qb * TAN_HALF);
    let num = select(low, b, select(high, -a, qb - qa));
    let den = select(low, a, select(high, b, qb + qa));
    let hi = select(low, 0.0, select(high, PIO2_HI, PIO4_HI));
    let lo = select(low, 0.0, select(high, PIO2_LO, PIO4_LO));
    let phi = angle_of_quotient(num / den, hi, lo, x.is_sign_negative());
    // phi >= 0: the sign of y is the sign of the result.
    f32::from_bits(phi.to_bits() | (y.to_bits() & SIGN))
}

/// The angle in [0, pi] of a branch of [`atan2_kernel`] from its quotient
/// `u`: `hi + atan(u) + lo`, or `pi` minus that for a negative `x`. The
/// kernel's result depends on its arguments only through the branch, this
/// quotient and the signs, which is what lets its tests try every f32
/// quotient (`quotient_sweep`).
#[inline]
fn angle_of_quotient(u: f32, hi: f32, lo: f32, negative_x: bool) -> f32 {
    let phi = hi + (atan_poly(u) + lo);
    select(negative_x, PI_HI - (phi - PI_LO), phi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{ATAN2_MAX_ABS_ERROR, ATAN2_MAX_ULP, ATAN_POLY_MAX_ULP};
    use crate::float::sweep::{floats, ulp, ulps, Worst};

    /// The step `proofs/gappa/atan2_outer.g` takes as a hypothesis for a
    /// negative x in the upper branch: `phi - PI_LO` rounds to `phi + 2^-23`
    /// for every f32 `phi` in [1, 2 - 2^-23].
    #[test]
    fn pi_lo_moves_every_phi_of_the_upper_branch_by_one_ulp() {
        let step = f32::EPSILON;
        for bits in 1.0f32.to_bits()..2.0f32.to_bits() {
            let phi = f32::from_bits(bits);
            assert_eq!(phi - PI_LO, phi + step, "{phi}");
        }
    }

    /// The real numbers that round to the f32 `t >= 0`: from the midpoint
    /// with the f32 below to the midpoint with the one above.
    fn rounding_interval(t: f32) -> (f64, f64) {
        let t64 = f64::from(t);
        let below = if t == 0.0 {
            t64
        } else {
            (t64 + f64::from(f32::from_bits(t.to_bits() - 1))) / 2.0
        };
        let above = (t64 + f64::from(f32::from_bits(t.to_bits() + 1))) / 2.0;
        (below, above)
    }

    /// The largest error of `got` against every exact angle between
    /// `ends.0` and `ends.1` (positive), in ulps of that angle and in
    /// radians. Within a binade the error in ulps is largest at an end of
    /// the interval; where the interval crosses a power of two, just below
    /// it (the ulp halves there) is a third candidate.
    fn error_over(got: f32, ends: (f64, f64)) -> (f64, f64) {
        let (lo, hi) = (ends.0.min(ends.1), ends.0.max(ends.1));
        let got = f64::from(got);
        let far = (got - lo).abs().max((got - hi).abs());
        let mut in_ulps = ulps_of(got, lo).max(ulps_of(got, hi));
        let power = 2f64.powi(hi.log2().floor() as i32);
        if lo < power {
            in_ulps = in_ulps.max((got - power).abs() / (ulp(power) / 2.0));
        }
        (in_ulps, far)
    }

    /// `|got - want| / ulp(want)`, in f64.
    fn ulps_of(got: f64, want: f64) -> f64 {
        (got - want).abs() / ulp(want)
    }

    /// The errors of `atan2_kernel` for every pair of finite arguments,
    /// through every `step`-th f32 quotient of each branch: the result
    /// depends on the arguments only through the branch, the quotient `u`
    /// and the signs (`angle_of_quotient`), so each f32 `u` stands for
    /// every pair whose quotient computes to it, and the exact angle of
    /// such a pair lies between those of the ends of `u`'s interval:
    ///
    /// - `b / a` (up to 1/2 rad) and `-(a / b)` (from pi/2 - 1/2 on) are
    ///   one correctly rounded division of the arguments, so the exact
    ///   ratio is any real that rounds to `t = |u|`, up to tan(1/2)
    ///   (1 + 2^-24) (the branch's test `b <= a tan(1/2)`, on the scaled
    ///   arguments, rounds its product once, never subnormal where the
    ///   outcome depends on it);
    /// - between, `a` and `b` (scaled exactly) lie within a factor 2 of
    ///   each other, `b - a` is exact (Sterbenz) and `b + a` and the
    ///   quotient round once each:
    ///   the exact `(b - a) / (b + a)` is within a factor `(1 + 2^-24) /
    ///   (1 - 2^-24)` of `u`, and at most that of the ratio
    ///   tan(1/2) (1 - 2^-24) in magnitude (0.2934).
    ///
    /// Each result is taken for a positive and a negative `x`; the sign of
    /// `y` is copied exactly. Returns the largest error in ulps and in
    /// radians, and the quotient of each.
    fn quotient_sweep(step: usize) -> ((f64, f32), (f64, f32)) {
        use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        let mut ulps_worst = (0.0, 0.0);
        let mut abs_worst = (0.0, 0.0);
        let mut see = |u: f32, hi: f32, lo: f32, exact: (f64, f64)| {
            for negative_x in [false, true] {
                let got = angle_of_quotient(u, hi, lo, negative_x);
                let ends = if negative_x {
                    (PI - exact.0, PI - exact.1)
                } else {
                    exact
                };
                let (in_ulps, in_radians) = error_over(got, ends);
                if in_ulps > ulps_worst.0 || in_ulps.is_nan() {
                    ulps_worst = (in_ulps, u);
                }
                if in_radians > abs_worst.0 || in_radians.is_nan() {
                    abs_worst = (in_radians, u);
                }
            }
        };
        let eps = 2f64.powi(-24);
        // The outer branches take ratios up to tan(1/2) (1 + 2^-24), the
        // middle one from tan(1/2) (1 - 2^-24) on: the branch's test rounds
        // its product once.
        let outer = f64::from(TAN_HALF) * (1.0 + eps);
        let beyond_half = f32::from_bits(TAN_HALF.to_bits() + 1);
        for t in floats(0.0, beyond_half, step) {
            let (below, above) = rounding_interval(t);
            if below > outer {
                continue;
            }
            let ends = (below.atan(), above.min(outer).atan());
            see(t, 0.0, 0.0, ends);
            see(
                -t,
                PIO2_HI,
                PIO2_LO,
                (FRAC_PI_2 - ends.0, FRAC_PI_2 - ends.1),
            );
        }
        let (shrink, grow) = ((1.0 - eps) / (1.0 + eps), (1.0 + eps) / (1.0 - eps));
        // |(b - a) / (b + a)| is at most (1 - r) / (1 + r) for the ratio
        // r = tan(1/2) (1 - 2^-24) at the branch's edge.
        let r = f64::from(TAN_HALF) * (1.0 - eps);
        let edge = (1.0 - r) / (1.0 + r);
        for t in floats(
            0.0,
            f32::from_bits(((edge * grow) as f32).to_bits() + 1),
            step,
        ) {
            let t64 = f64::from(t);
            if t64 * shrink > edge {
                continue;
            }
            let ends = ((t64 * shrink).atan(), (t64 * grow).min(edge).atan());
            see(
                t,
                PIO4_HI,
                PIO4_LO,
                (FRAC_PI_4 + ends.0, FRAC_PI_4 + ends.1),
            );
            see(
                -t,
                PIO4_HI,
                PIO4_LO,
                (FRAC_PI_4 - ends.0, FRAC_PI_4 - ends.1),
            );
        }
        (ulps_worst, abs_worst)
    }

    /// The largest ulp errors of `atan_poly` and `atan2_kernel` over every
    /// `step`-th f32 of their ranges, and of `atan2_kernel` over every
    /// `step`-th f32 quotient of its branches (`quotient_sweep`), in ulps
    /// and in radians.
    fn kernel_sweep(step: usize) {
        let ((in_ulps, u), (in_radians, v)) = quotient_sweep(step);
        std::println!(
            "atan2_kernel, every quotient: max {in_ulps:.3} ulp at u = {u:e}, {in_radians:.4e} rad at u = {v:e}"
        );
        assert!(
            in_ulps <= f64::from(ATAN2_MAX_ULP),
            "{in_ulps} ulp at {u:e}"
        );
        assert!(
            in_radians <= f64::from(ATAN2_MAX_ABS_ERROR),
            "{in_radians} rad at {v:e}"
        );
        let mut atan = Worst::new("atan_poly, [0, tan(1/2)]", ATAN_POLY_MAX_ULP);
        for u in floats(0.0, TAN_HALF, step) {
            atan.see(ulps(atan_poly(u), (u as f64).atan()), u);
        }
        let mut atan2 = Worst::new("atan2_kernel, t in [0, 1] against +-1", ATAN2_MAX_ULP);
        for t in floats(0.0, 1.0, step) {
            for (y, x) in [(t, 1.0), (1.0, t), (t, -1.0), (1.0, -t)] {
                atan2.see(ulps(atan2_kernel(y, x), (y as f64).atan2(x as f64)), t);
            }
            // The middle branch with a real division: (1 + t, 1).
            let y = 1.0 + t;
            atan2.see(ulps(atan2_kernel(y, 1.0), (y as f64).atan2(1.0)), t);
        }
        atan.check();
        atan2.check();
    }

    crate::float::sweep::sweep_tests!(kernel_sweep);

    /// Pairs of subnormals, where the branch tests' products underflow
    /// unless the arguments are scaled first: every pair of the 300
    /// smallest positive f32.
    #[test]
    fn atan2_kernel_is_within_its_bound_on_subnormal_pairs() {
        for i in 1..=300 {
            for j in 1..=300 {
                let (y, x) = (f32::from_bits(j), f32::from_bits(i));
                let err = ulps(atan2_kernel(y, x), (y as f64).atan2(x as f64));
                assert!(err <= f64::from(ATAN2_MAX_ULP), "{y:e}, {x:e}: {err}");
            }
        }
    }

    /// `atan2_kernel` on random pairs with exponents from subnormal to huge,
    /// every sign, against f64.
    #[test]
    fn atan2_kernel_is_within_its_bound_on_random_pairs() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(5);
        let mut worst: (f64, f32, f32) = (0.0, 0.0, 0.0);
        for _ in 0..1_000_000 {
            // Any finite bit pattern: uniform in the exponent, not the value.
            let mut any = || loop {
                let x = f32::from_bits(rng.random());
                if x.is_finite() {
                    return x;
                }
            };
            let (y, x) = (any(), any());
            let err = ulps(atan2_kernel(y, x), (y as f64).atan2(x as f64));
            if err > worst.0 {
                worst = (err, y, x);
            }
        }
        std::println!(
            "atan2_kernel, random pairs: max {:.3} ulp at {:e}, {:e}",
            worst.0,
            worst.1,
            worst.2
        );
        assert!(worst.0 <= ATAN2_MAX_ULP as f64, "{worst:?}");
    }
}
