//! The default backend's sine and cosine: [`sin_cos_kernel`], a degree-7
//! and a degree-8 minimax polynomial on [-pi/4, pi/4]; arguments up to
//! 3 pi/4 (all that slerp produces for `alpha` in [0, 1]) need one
//! subtraction, every other finite argument the exact integer reduction of
//! [`reduce`](super::reduce). f32 only.

use super::bits::SIGN;
use super::head_tail::{sum_and_tail, PIO2_HI, PIO2_LO};
use super::reduce::reduce_by_quarter_turns;

/// 3 pi/4 rounded down to f32: up to here, [`sin_cos_kernel`] reduces by
/// one subtraction of pi/2 at most.
pub(super) const THREE_PI_4: f32 = 2.356_194_3;

/// `(sin(r) - r) / r^3` as a polynomial in `r^2` on |r| <= pi/4, relative
/// error 3.8e-9 (`tools/minimax.py sin`).
const SIN: [f32; 3] = [-0.166_666_55, 0.008_332_161, -0.000_195_152_83];
/// `(cos(r) - 1 + r^2 / 2) / r^4` as a polynomial in `r^2` on |r| <= pi/4,
/// absolute error 1.2e-10 (`tools/minimax.py cos`).
const COS: [f32; 3] = [0.041_666_646, -0.001_388_731_6, 2.443_315_7e-5];

/// `sin(r + t)` for `|r| <= pi/4` (a little beyond is fine) and a tail
/// `t` below an ulp of `r`: `r + (t + r^3 P(r^2))` with `P` the degree-2
/// minimax polynomial [`SIN`]. Within 1 ulp for `t = 0`
/// ([`accuracy::SIN_COS_POLY_MAX_ULP`](crate::accuracy::SIN_COS_POLY_MAX_ULP);
/// 0.805 at worst); the tail carries the bits of a reduced argument that do
/// not fit in `r`.
#[inline]
fn sin_poly(r: f32, t: f32) -> f32 {
    let s = r * r;
    r + (t + r * (s * (SIN[0] + s * (SIN[1] + s * SIN[2]))))
}

/// `cos(r + t)` for `|r| <= pi/4` and a tail `t` below an ulp of `r`:
/// `1 - r^2/2 - r t + r^4 P(r^2)` with `P` the degree-2 minimax polynomial
/// [`COS`]. `1 - r^2/2` is rounded once, and its rounding error is
/// recovered (as in FreeBSD's `k_cos.c`), so the result is within 1 ulp
/// for `t = 0`
/// ([`accuracy::SIN_COS_POLY_MAX_ULP`](crate::accuracy::SIN_COS_POLY_MAX_ULP);
/// 0.749 at worst).
#[inline]
fn cos_poly(r: f32, t: f32) -> f32 {
    let s = r * r;
    let half = 0.5 * s;
    let w = 1.0 - half;
    w + ((((1.0 - w) - half) - r * t) + s * s * (COS[0] + s * (COS[1] + s * COS[2])))
}

/// The f32-only sine and cosine of the default backend (see
/// [`float::sin_cos`](super::sin_cos)).
///
/// - `|x| <= pi/4`: the polynomials directly.
/// - `|x| <= 3 pi/4` (every argument slerp produces for `alpha` in [0, 1],
///   since the half angle after `cn` is at most pi/2): `r = pi/2 - |x|`,
///   exact in its head (Sterbenz) and rounded once with the tail of pi/2,
///   then `sin x = cos r`, `cos x = sin r`.
/// - beyond: [`reduce_by_quarter_turns`], exact for every finite f32.
///
/// Within [`accuracy::SIN_COS_NARROW_MAX_ULP`](crate::accuracy::SIN_COS_NARROW_MAX_ULP)
/// for `|x| <= 3 pi/4` and [`accuracy::SIN_COS_MAX_ULP`](crate::accuracy::SIN_COS_MAX_ULP)
/// beyond; NaN for NaN and infinite `x`.
#[must_use]
pub(crate) fn sin_cos_kernel(x: f32) -> (f32, f32) {
    let a = x.abs();
    if a > THREE_PI_4 || a.is_nan() {
        return sin_cos_reduced(x);
    }
    let (s, c) = sin_cos_quarter(a);
    // s >= 0 here: the sign of x is the sign of the sine.
    (f32::from_bits(s.to_bits() | (x.to_bits() & SIGN)), c)
}

/// Sine and cosine of `0 <= a <= 3 pi/4`, without a branch (so that
/// random arguments cost no mispredicted branch, and two calls side by side
/// can share vector instructions). Within a quarter turn of 0: `r + t` is
/// `a` itself, or `pi/2 - a` with sine and cosine swapped, whose head's
/// difference is exact (Sterbenz: `a` lies within a factor 2 of `PIO2_HI`)
/// and whose tail is kept. Within
/// [`accuracy::SIN_COS_NARROW_MAX_ULP`](crate::accuracy::SIN_COS_NARROW_MAX_ULP).
///
/// Inlined on 64-bit desktop targets, where the three calls of [`sin3`]
/// then share vector instructions; elsewhere one out-of-line copy keeps
/// flash small (a Cortex-M4F has no vector unit to gain from copies).
#[cfg_attr(desktop64, inline(always))]
fn sin_cos_quarter(a: f32) -> (f32, f32) {
    let swap = a > core::f32::consts::FRAC_PI_4;
    let (r, t) = if swap {
        sum_and_tail(PIO2_HI - a, PIO2_LO)
    } else {
        (a, 0.0)
    };
    let (s, c) = sin_cos_poly(r, t);
    if swap {
        (c, s)
    } else {
        (s, c)
    }
}

/// `(sin(r + t), cos(r + t))` for `|r| <= pi/4`: both polynomials, in one
/// function that the narrow and the reduced paths share.
#[cfg_attr(desktop64, inline(always))]
fn sin_cos_poly(r: f32, t: f32) -> (f32, f32) {
    (sin_poly(r, t), cos_poly(r, t))
}

/// Sines of three angles, each in [0, 3 pi/4]: the three that slerp
/// needs, side by side (on x86-64 the compiler evaluates them together in
/// vector registers; on a Cortex-M4F they are three calls of one body),
/// with the accuracy of [`float::sin_cos`](super::sin_cos) (default
/// backend: within
/// [`accuracy::SIN_COS_NARROW_MAX_ULP`](crate::accuracy::SIN_COS_NARROW_MAX_ULP)).
/// Arguments outside the range get no reduction: the caller guarantees the
/// range.
#[inline(always)]
#[must_use]
pub(crate) fn sin3(a: f32, b: f32, c: f32) -> (f32, f32, f32) {
    (
        sin_cos_quarter(a).0,
        sin_cos_quarter(b).0,
        sin_cos_quarter(c).0,
    )
}

/// [`sin_cos_kernel`] beyond 3 pi/4, by [`reduce_by_quarter_turns`]; NaN
/// for NaN and infinities.
#[cold]
fn sin_cos_reduced(x: f32) -> (f32, f32) {
    let a = x.abs();
    if !a.is_finite() {
        return (f32::NAN, f32::NAN);
    }
    let (quadrant, r, t) = reduce_by_quarter_turns(a);
    let (s, c) = sin_cos_poly(r, t);
    // Quadrants 0 to 3 map (s, c) to (s, c), (c, -s), (-s, -c), (-c, s):
    // swapped in the odd ones, the sine negated in 2 and 3, the cosine in 1
    // and 2, by flipping sign bits. sin(-x) = -sin(x): the sine's sign bit
    // flips with x's too.
    let (s, c) = if quadrant & 1 == 0 { (s, c) } else { (c, s) };
    let sin_flip = (quadrant >> 1) << 31;
    let cos_flip = ((quadrant + 1) >> 1 & 1) << 31;
    (
        f32::from_bits(s.to_bits() ^ sin_flip ^ (x.to_bits() & SIGN)),
        f32::from_bits(c.to_bits() ^ cos_flip),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{SIN_COS_MAX_ULP, SIN_COS_NARROW_MAX_ULP, SIN_COS_POLY_MAX_ULP};
    use crate::float::sweep::{floats, ulps, Worst};
    use core::f32::consts::FRAC_PI_4;

    /// The largest ulp errors of the polynomials and of `sin_cos_kernel`
    /// over every `step`-th f32 of their ranges.
    fn kernel_sweep(step: usize) {
        let mut sin = Worst::new("sin_poly, [0, pi/4]", SIN_COS_POLY_MAX_ULP);
        let mut cos = Worst::new("cos_poly, [0, pi/4]", SIN_COS_POLY_MAX_ULP);
        for r in floats(0.0, FRAC_PI_4, step) {
            sin.see(ulps(sin_poly(r, 0.0), (r as f64).sin()), r);
            cos.see(ulps(cos_poly(r, 0.0), (r as f64).cos()), r);
        }
        let mut narrow = Worst::new("sin_cos_kernel, [0, 3 pi/4]", SIN_COS_NARROW_MAX_ULP);
        for x in floats(0.0, THREE_PI_4, step) {
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            narrow.see(ulps(s, x64.sin()).max(ulps(c, x64.cos())), x);
        }
        let mut general = Worst::new("sin_cos_kernel, [3 pi/4, f32::MAX]", SIN_COS_MAX_ULP);
        for x in floats(THREE_PI_4, f32::MAX, step) {
            crate::float::reduce::check_reduced_range(x);
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            general.see(ulps(s, x64.sin()).max(ulps(c, x64.cos())), x);
        }
        for worst in [sin, cos, narrow, general] {
            worst.check();
        }
    }

    crate::float::sweep::sweep_tests!(kernel_sweep);

    /// sin is odd and cos even, bit for bit, on both paths; and the
    /// quadrant of the reduced path is right on either side of zero.
    #[test]
    fn sin_cos_of_negative_arguments_mirrors_the_positive_ones() {
        let sweep = (0x3f80_0000..0x7f80_0000u32)
            .step_by(9973)
            .map(f32::from_bits);
        for x in sweep.chain([THREE_PI_4, 2.5, 4.0, 5.5, 7.0, 1e3, f32::MAX]) {
            let (s, c) = sin_cos_kernel(x);
            let (ns, nc) = sin_cos_kernel(-x);
            assert_eq!(ns.to_bits(), (-s).to_bits(), "sin(-{x:e})");
            assert_eq!(nc.to_bits(), c.to_bits(), "cos(-{x:e})");
            let x64 = -(x as f64);
            assert!(
                ulps(ns, x64.sin()).max(ulps(nc, x64.cos())) <= SIN_COS_MAX_ULP as f64,
                "{x:e}"
            );
        }
    }

    /// Arguments whose reduced value is tiny (they lie close to a multiple
    /// of pi/2), where the reduction must keep its low bits: without them,
    /// 7.729179e28 is off by 9.3 ulp.
    #[test]
    fn sin_cos_keeps_the_low_bits_of_tiny_reduced_arguments() {
        for x in [7.729_179e28_f32, 2.327_948_8e23, 5.544_331_8e23] {
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            let err = ulps(s, x64.sin()).max(ulps(c, x64.cos()));
            assert!(err <= SIN_COS_MAX_ULP as f64, "{x:e}: {err} ulp");
        }
    }
}
