//! The contracts of the float kernels that the Kani harnesses stub.
//!
//! The crate's square root is an instruction (inline assembly or a
//! `core::arch` intrinsic) in ordinary builds and, under `cfg(kani)`, the
//! exact description of the correctly rounded root; its sine, cosine and
//! atan2 are f32 polynomials that a model checker can follow, but slowly.
//! So the harnesses replace the kernels they do not need exactly
//! (`src/stubs.rs`) by "any value that meets the contract". That is sound only if the real kernels meet the contracts:
//! `kernels_meet_the_contracts_the_proofs_stub_them_by` in this crate's
//! `tests/kernel_contracts.rs` checks them, with each backend, on edge values and a
//! sweep of every binade. The contracts are deliberately weak (ranges and
//! the Pythagorean identity, not accuracy): what the unit-norm laws need.
//!
//! Their tolerances follow from bounds that hold on every argument, not
//! from a maximum measured on samples: the square root's from correct
//! rounding, the sine and cosine's from the kernel's ulp bounds
//! ([`accuracy::SIN_COS_NARROW_MAX_ULP`](rigtform::accuracy::SIN_COS_NARROW_MAX_ULP),
//! [`accuracy::SIN_COS_MAX_ULP`](rigtform::accuracy::SIN_COS_MAX_ULP)), which the
//! exhaustive kernel sweep establishes over every f32.

use rigtform::accuracy::{SIN_COS_MAX_ULP, SIN_COS_NARROW_MAX_ULP};

/// The larger of two bounds, in a constant.
const fn max(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else {
        b
    }
}

/// How far the sine or cosine kernel may be from the truth, in absolute
/// terms, on every finite argument: its ulp bound (the larger of the two
/// ranges') times the largest ulp of a value in `[-1, 1]`, 2^-23 (the
/// spacing above 1, which the sweeps' ulp of a true value just below 1
/// rounds to).
pub const SIN_COS_ABS_BOUND: f64 =
    max(SIN_COS_NARROW_MAX_ULP, SIN_COS_MAX_ULP) as f64 / 8_388_608.0;

/// `sin^2 + cos^2` is within this of 1. With `s = sin x + e` and
/// `c = cos x + f`, `|e|, |f| <= d` ([`SIN_COS_ABS_BOUND`]):
/// `|s^2 + c^2 - 1| = |2 e sin x + 2 f cos x + e^2 + f^2|
/// <= 2 sqrt(2) d + 2 d^2 < 3 d` (for `d < 0.08`); the margin, about
/// `0.17 d`, covers the rounding of the f64 check.
pub const PYTHAGORAS_TOL: f64 = 3.0 * SIN_COS_ABS_BOUND;

/// `sqrt(x)^2` is within this relative error of `x`: a correctly rounded
/// square root is off by at most half an ulp, `u = 2^-24` relative, and
/// `(1 + u)^2 - 1 <= 2u + u^2`.
pub const SQRT_SQUARED_REL_TOL: f64 = 2.0 / 16_777_216.0 + 1.0 / 281_474_976_710_656.0;

/// What `sin_cos(x) = (s, c)` promises: NaN for NaN or infinite `x`;
/// exactly `(x, 1)` at `x = +-0`; otherwise both in `[-1, 1]` and
/// `|s^2 + c^2 - 1| <= PYTHAGORAS_TOL`.
///
/// ```
/// use rigtform_proofs::contracts::sin_cos;
/// assert!(sin_cos(0.5, libm::sinf(0.5), libm::cosf(0.5)));
/// assert!(!sin_cos(0.5, 0.5, 0.5));
/// ```
pub fn sin_cos(x: f32, s: f32, c: f32) -> bool {
    if !x.is_finite() {
        return s.is_nan() && c.is_nan();
    }
    if x == 0.0 {
        return s.to_bits() == x.to_bits() && c == 1.0;
    }
    let (s64, c64) = (f64::from(s), f64::from(c));
    s.abs() <= 1.0 && c.abs() <= 1.0 && (s64 * s64 + c64 * c64 - 1.0).abs() <= PYTHAGORAS_TOL
}

/// What `atan2(y, x) = phi` promises: NaN if either argument is NaN;
/// otherwise `phi` in `[-pi, pi]` (the `f32` nearest pi bounding it), with
/// the sign of `y` (atan2 is odd in `y`, signed zeros included).
///
/// ```
/// use rigtform_proofs::contracts::atan2;
/// assert!(atan2(1.0, -1.0, libm::atan2f(1.0, -1.0)));
/// assert!(!atan2(1.0, -1.0, -2.0));
/// ```
pub fn atan2(y: f32, x: f32, phi: f32) -> bool {
    if y.is_nan() || x.is_nan() {
        return phi.is_nan();
    }
    phi.abs() <= core::f32::consts::PI && phi.is_sign_negative() == y.is_sign_negative()
}

/// What `sqrt(x) = r` promises: NaN for NaN or negative `x` (but `-0`
/// gives `-0`); `r == x` at zero and infinity; otherwise `r > 0` with
/// `|r^2 - x| <= SQRT_SQUARED_REL_TOL x`.
///
/// ```
/// use rigtform_proofs::contracts::sqrt;
/// assert!(sqrt(2.0, libm::sqrtf(2.0)));
/// assert!(!sqrt(2.0, 1.5));
/// ```
pub fn sqrt(x: f32, r: f32) -> bool {
    if x.is_nan() || x < 0.0 {
        return r.is_nan();
    }
    if x == 0.0 || x == f32::INFINITY {
        return r.to_bits() == x.to_bits();
    }
    let (x64, r64) = (f64::from(x), f64::from(r));
    r > 0.0 && (r64 * r64 - x64).abs() <= SQRT_SQUARED_REL_TOL * x64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under the stubs, `pow`'s sines may be off the unit circle by the
    /// whole tolerance: with the normalized axis's `8u` that must stay
    /// within what `pow_is_unit` allows, or a proof of that law under the
    /// stubs would fail on kernels that meet the contract.
    #[test]
    fn the_sine_tolerance_fits_what_pow_is_unit_allows() {
        let eight_u = 8.0 / 16_777_216.0;
        assert!(PYTHAGORAS_TOL + eight_u <= crate::laws::ONE_STEP_NORM_TOL);
    }

    /// A contract that accepted anything would make every stubbed proof
    /// vacuous: each must reject what a kernel must not return.
    #[test]
    fn contracts_reject_what_the_kernels_must_not_return() {
        assert!(!sin_cos(1.0, 0.9, 0.9)); // off the unit circle
        assert!(!sin_cos(0.0, 0.0, 0.999)); // cos(0) is exactly 1
        assert!(!sin_cos(f32::INFINITY, 0.0, 1.0)); // must be NaN
        assert!(!atan2(-1.0, 1.0, 0.7)); // wrong sign
        assert!(!atan2(1.0, -1.0, 3.2)); // beyond pi
        assert!(!atan2(f32::NAN, 1.0, 0.0));
        assert!(!sqrt(4.0, 2.001));
        assert!(!sqrt(-1.0, 1.0));
        assert!(!sqrt(0.0, 1e-20));
    }
}
