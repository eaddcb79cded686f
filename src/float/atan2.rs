//! The default backend's arctangent: [`atan2_kernel`], one division onto
//! [-tan(1/2), tan(1/2)] and a degree-13 odd minimax polynomial, f32 only.

use super::bits::{select, SIGN};
use super::head_tail::{PIO2_HI, PIO2_LO, PIO4_HI, PIO4_LO, PI_HI, PI_LO};

/// tan(1/2), rounded to f32: the bound of [`atan_poly`]'s range.
pub(super) const TAN_HALF: f32 = 0.546_302_5;

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
/// the exact angle (the sweeps take every f32 `t` in [0, 1] as `(t, 1)`,
/// `(1, t)`, `(t, -1)`, `(1, -t)` and `(1 + t, 1)`;
/// `atan2_kernel_is_within_its_bound_on_random_pairs` takes pairs at every
/// scale).
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
    // within a factor 2 of each other (and b + a can only overflow if b is
    // huge, where a quarter of each is exact). Selected by bit masks, which
    // compile to no branch.
    let (low, high) = (b <= a * TAN_HALF, a <= b * TAN_HALF);
    let quarter = select(b > 1e37, 0.25, 1.0);
    let (qb, qa) = (b * quarter, a * quarter);
    let num = select(low, b, select(high, -a, qb - qa));
    let den = select(low, a, select(high, b, qb + qa));
    let hi = select(low, 0.0, select(high, PIO2_HI, PIO4_HI));
    let lo = select(low, 0.0, select(high, PIO2_LO, PIO4_LO));
    let phi = hi + (atan_poly(num / den) + lo);
    let phi = select(x.is_sign_negative(), PI_HI - (phi - PI_LO), phi);
    // phi >= 0: the sign of y is the sign of the result.
    f32::from_bits(phi.to_bits() | (y.to_bits() & SIGN))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{ATAN2_MAX_ULP, ATAN_POLY_MAX_ULP};
    use crate::float::sweep::{floats, ulps, Worst};

    /// The largest ulp errors of `atan_poly` and `atan2_kernel` over every
    /// `step`-th f32 of their ranges.
    fn kernel_sweep(step: usize) {
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
