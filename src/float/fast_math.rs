//! The `fast-math` backend: micromath's approximations of atan2, sin, cos
//! and tan, guarded where micromath breaks down (rescaled arguments, Taylor
//! terms near zero, IEEE 754's limits of atan2 where an argument is zero
//! or infinite), and the default sine and cosine kernel where it must
//! answer instead (huge or non-finite arguments).

use super::bits::SIGN;
use super::head_tail::{PI_HI, PI_LO};
use super::sin_cos::sin_cos_kernel;

/// 2^-6: below this, the sine and cosine are Taylor polynomials.
const SIN_COS_TAYLOR: f32 = 0.015625;
/// 2^9: beyond this, micromath's f32 range reduction loses accuracy (its
/// absolute error grows from 1.1e-3 below 2^9 to 6.7e-3 near 2^16, and
/// `sin^2 + cos^2` drifts from 1 by up to 8e-3), so the default kernel,
/// with its exact reduction, takes over. The proof harness
/// `pow_is_unit_for_every_finite_input`, run with `fast-math`, checks the
/// unit norm this keeps.
const SIN_COS_LIMIT: f32 = 512.0;
/// 2^20 and 2^-20: the range in which micromath's atan2 squares its
/// arguments safely.
const ATAN2_HIGH: f32 = f32::from_bits((127 + 20) << 23);
const ATAN2_LOW: f32 = f32::from_bits((127 - 20) << 23);

/// micromath's atan2 for finite non-zero arguments, [`atan2_limits`] for
/// the others (see [`float::atan2`](super::atan2)). Never inlined: its
/// guards at each of the crate's call sites would cost more flash than a
/// call.
#[inline(never)]
pub(super) fn atan2(y: f32, x: f32) -> f32 {
    if y.is_finite() && x.is_finite() && y != 0.0 && x != 0.0 {
        let largest = y.abs().max(x.abs());
        let (y, x) = if (ATAN2_LOW..=ATAN2_HIGH).contains(&largest) {
            (y, x)
        } else {
            (y / largest, x / largest)
        };
        // The smaller argument may now be tiny beside the larger, or even
        // zero: its square then vanishes, which only rounds the angle to 0,
        // pi/2 or pi, as it should.
        return micromath::F32Ext::atan2(y, x).copysign(y);
    }
    atan2_limits(y, x)
}

/// atan2 where an argument is zero, infinite or NaN: IEEE 754's limits
/// (0, pi/4, pi/2, 3 pi/4 or pi, with the sign of `y`), bit for bit what
/// the default kernel gives there, without linking that kernel, so that
/// `fast-math` adds micromath's atan2 instead of keeping both. NaN for NaN.
#[inline]
fn atan2_limits(y: f32, x: f32) -> f32 {
    use core::f32::consts::{FRAC_PI_2, FRAC_PI_4};
    let (b, a) = (y.abs(), x.abs());
    // The angle of (a, b) in [0, pi/2]: one of them is 0 or infinite.
    let phi = if b == 0.0 {
        0.0
    } else if b == a {
        FRAC_PI_4 // both infinite
    } else if b > a {
        FRAC_PI_2 // b infinite, or a zero
    } else {
        0.0 // a infinite, b finite; or a NaN (then so is the sum below)
    };
    let phi = if y.is_nan() || x.is_nan() {
        f32::NAN
    } else if x.is_sign_negative() {
        // As the default kernel rounds pi - phi, from pi's head and tail.
        PI_HI - (phi - PI_LO)
    } else {
        phi
    };
    f32::from_bits(phi.to_bits() | (y.to_bits() & SIGN))
}

/// micromath's sine and cosine, Taylor terms below 2^-6, the default
/// kernel beyond 2^9 and for NaN (see [`float::sin_cos`](super::sin_cos)).
#[inline]
pub(super) fn sin_cos(x: f32) -> (f32, f32) {
    let a = x.abs();
    if a < SIN_COS_TAYLOR {
        let x2 = x * x;
        // The x^4 / 24 term of the cosine is below 2.5e-9, under half an
        // ulp of 1: f32 cannot hold it.
        // x (1 - x^2/6) rather than x - x^3/6 keeps the sign of -0.
        return (x * (1.0 - x2 * (1.0 / 6.0)), 1.0 - x2 * 0.5);
    }
    if a <= SIN_COS_LIMIT {
        return (micromath::F32Ext::sin(x), micromath::F32Ext::cos(x));
    }
    sin_cos_kernel(x)
}

/// micromath's tangent up to 2^9, libm's beyond and for NaN (see
/// [`float::tan`](super::tan)).
#[inline]
pub(super) fn tan(x: f32) -> f32 {
    if x.abs() <= SIN_COS_LIMIT {
        return micromath::F32Ext::tan(x);
    }
    libm::tanf(x)
}

#[cfg(test)]
mod tests {
    use super::super::{atan2, sin_cos, tan};
    use crate::float::atan2::atan2_kernel;
    use crate::float::sweep::spread;

    /// Where an argument is zero, infinite or NaN, `fast-math`'s atan2
    /// gives the default kernel's bits (NaN for NaN), for every pair of
    /// these and of finite values of every scale.
    #[test]
    fn atan2_limits_are_the_default_kernels_bits() {
        let limits = [0.0f32, -0.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN];
        let finite = [
            1e-45f32,
            -1e-45,
            1e-30,
            0.5,
            -1.0,
            3.0,
            -1e30,
            f32::MAX,
            -f32::MAX,
        ];
        for y in limits.into_iter().chain(finite) {
            for x in limits.into_iter().chain(finite) {
                if y.is_finite() && x.is_finite() && y != 0.0 && x != 0.0 {
                    continue;
                }
                let (got, want) = (atan2(y, x), atan2_kernel(y, x));
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "atan2({y:e}, {x:e}) = {got:e}, the default kernel {want:e}"
                );
            }
        }
    }

    /// The feature does what it says: inside their ranges the kernels are
    /// micromath's, bit for bit (the accuracy sweeps alone would also pass
    /// if everything had quietly fallen back to the default kernels).
    #[test]
    fn fast_math_kernels_are_micromaths_inside_their_ranges() {
        use micromath::F32Ext;
        for (y, x) in [(0.5f32, 0.7f32), (-3.0, 2.0), (1e5, -3e5), (-1e-3, -2e-3)] {
            assert_eq!(atan2(y, x), F32Ext::atan2(y, x), "atan2({y}, {x})");
        }
        for x in [0.5f32, -2.0, 300.0, -500.0] {
            assert_eq!(sin_cos(x), (F32Ext::sin(x), F32Ext::cos(x)), "sin_cos({x})");
        }
        for x in [0.3f32, 1.2] {
            assert_eq!(tan(x), F32Ext::tan(x), "tan({x})");
        }
    }

    /// Why fast-math keeps the accurate square root: micromath's (2.1) is
    /// off by several percent, as the `sqrt` doc says.
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
}
