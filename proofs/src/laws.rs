//! The laws of the numerics contract, each written once.
//!
//! Every law is a function that takes inputs meeting its stated
//! preconditions and returns a [`Verdict`]. The same function is called by
//! the Kani harnesses (`src/harnesses.rs`), by the proptest properties
//! (`tests/properties.rs` of the `rigtform` crate), by the fuzz targets
//! (`fuzz/`) and by the on-target tests (`embedded/`), so that the four
//! layers cannot drift apart.
//!
//! The checks are computed in `f64`: squares and sums of `f32` values are
//! then (nearly) exact, so a law measures the error of the `f32` code under
//! test, not of its own arithmetic.
//!
//! The tolerances are worst-case bounds, looser than the measured maxima of
//! `rigtform::accuracy` (which come from random draws): a law must hold for
//! every input a model checker may choose, and a real bug (a sign, a swapped
//! component, a missing negation) breaks it by orders of magnitude.

use rigtform::accuracy::{INVERSE_MAX_REL_ERROR, ROTATE_MAX_REL_ERROR, UNIT_NORM_ERROR};
use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};

mod animation;
mod constructors;
pub mod registry;
pub use animation::{
    sampler_hits_its_keys, sampler_is_unit, step_sampler_is_constant_between_keys,
};
pub use constructors::{
    euler_angles_give_back_the_rotation, from_matrix_inverts_from_quat,
    rotation_arc_takes_from_to_to,
};

/// A law that did not hold: its name, the measured quantity and its bound
/// (both `NaN`-free unless the result itself was `NaN`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Violation {
    /// The law's function name.
    pub law: &'static str,
    /// What was measured (an error, or 1.0 for a failed yes-or-no check).
    pub measured: f64,
    /// The bound it had to stay within (0.0 for a yes-or-no check).
    pub bound: f64,
}

/// The outcome of checking a law on one input.
pub type Verdict = Result<(), Violation>;

/// Panics with the [`Violation`] if `verdict` is one. Every layer asserts a
/// law this one way: the Kani harnesses (where the panic fails the proof),
/// the proptest properties (where proptest catches it and shrinks the
/// input) and the fuzz targets (where it is the crash libFuzzer reports).
///
/// ```should_panic
/// use rigtform::Quat;
/// use rigtform_proofs::laws::{assert_holds, pow_is_unit};
/// assert_holds(pow_is_unit(Quat::from_rotation_x(1.0), 0.5)); // holds
/// assert_holds(Err(rigtform_proofs::laws::Violation { law: "example", measured: 1.0, bound: 0.0 }));
/// ```
#[track_caller]
pub fn assert_holds(verdict: Verdict) {
    if let Err(v) = verdict {
        panic!("{v:?}");
    }
}

/// `|norm^2 - 1|` allowed after one rounded operation on unit inputs
/// (a product, `normalize`, `pow`, `nlerp`): four times the measured
/// [`UNIT_NORM_ERROR`] (which is about `|norm - 1|`, so half of
/// `|norm^2 - 1|`).
///
/// Worst case, default backend: a product's norm is off by at most
/// `2 gamma_4 = 8u` (u = 2^-24; each component is a sum of four rounded
/// products, and the vector of their absolute sums has norm at most
/// `2 |a| |b|`), so `|norm^2 - 1| <= 16u = 9.5e-7`; `pow` adds sine and
/// cosine errors (`3 SIN_COS_MAX_ABS_ERROR`) to the normalized axis (`8u`):
/// 6.6e-7. Both are below 4 x 4.7e-7 = 1.9e-6, and so is `pow` under the
/// Kani stubs, whose sines may be off the unit circle by the whole
/// [`PYTHAGORAS_TOL`](crate::contracts::PYTHAGORAS_TOL) (4.5e-7, from the
/// kernel's ulp bound): 9.3e-7.
pub const ONE_STEP_NORM_TOL: f64 = 4.0 * UNIT_NORM_ERROR as f64;

/// `|norm^2 - 1|` allowed after two rounded operations (`slerp` is a `pow`
/// and a product): twice [`ONE_STEP_NORM_TOL`].
pub const TWO_STEP_NORM_TOL: f64 = 2.0 * ONE_STEP_NORM_TOL;

/// Relative error allowed in a translation that went through a rotation
/// and back (`a * a.inv()`, `a.inv().inv()`): two rotations, each within
/// [`ROTATE_MAX_REL_ERROR`] (measured), times four for the worst case, plus
/// what a rotation quaternion off unit by [`ONE_STEP_NORM_TOL`] does to
/// lengths (`2 |norm^2 - 1|` per rotation).
pub const TRANSLATION_REL_TOL: f64 = 4.0 * ONE_STEP_NORM_TOL + 8.0 * ROTATE_MAX_REL_ERROR as f64;

/// Absolute slack for results that should be zero or equal, in units of the
/// inputs' magnitude: below this, products of tiny components underflow.
const UNDERFLOW_SLACK: f64 = 1e-36;

/// A relative tolerance applied to a magnitude, plus the underflow slack.
fn relative(tol: f64, magnitude: f64) -> f64 {
    tol * magnitude + UNDERFLOW_SLACK
}

fn norm2(q: Quat) -> f64 {
    let [w, x, y, z] = [q.w, q.x, q.y, q.z].map(f64::from);
    w * w + x * x + y * y + z * z
}

/// Squared length, in f64. The laws compare squares rather than take
/// square roots: libm's `sqrt` is inline assembly on x86, which Kani
/// cannot read.
fn vnorm2(v: Cvec3) -> f64 {
    let [x, y, z] = [v.x, v.y, v.z].map(f64::from);
    x * x + y * y + z * z
}

/// The 1-norm, in f64: an upper bound of the length without a square root.
fn vnorm1(v: Cvec3) -> f64 {
    f64::from(v.x).abs() + f64::from(v.y).abs() + f64::from(v.z).abs()
}

/// The slerp angle error allowed for a turn of `theta` radians: the
/// documented bound per radian turned (at least one radian), doubled for
/// the error of measuring angles with `angle_to`.
fn slerp_angle_tol(theta: f64) -> f64 {
    2.0 * f64::from(rigtform::accuracy::SLERP_MAX_ANGLE_ERROR) * theta.max(1.0)
}

fn within(law: &'static str, measured: f64, bound: f64) -> Verdict {
    // Written so that a NaN measurement fails.
    if measured <= bound {
        Ok(())
    } else {
        Err(Violation {
            law,
            measured,
            bound,
        })
    }
}

fn yes_or_no(law: &'static str, condition: bool) -> Verdict {
    within(law, if condition { 0.0 } else { 1.0 }, 0.0)
}

fn is_nan_quat(q: Quat) -> bool {
    q.w.is_nan() && q.x.is_nan() && q.y.is_nan() && q.z.is_nan()
}

/// The same bits, or both NaN, component by component.
fn same_floats<const N: usize>(a: [f32; N], b: [f32; N]) -> bool {
    a.iter()
        .zip(&b)
        .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
}

fn same_bits(a: Quat, b: Quat) -> bool {
    [a.w, a.x, a.y, a.z].map(f32::to_bits) == [b.w, b.x, b.y, b.z].map(f32::to_bits)
}

/// `|a b| = |a| |b|`: the Hamilton product multiplies norms, so it keeps
/// unit quaternions unit.
///
/// Preconditions: `a` and `b` finite, with `|a|^2` and `|b|^2` in
/// `[2^-40, 2^80]` (no overflow; underflow then costs nothing relative).
pub fn product_norm_is_multiplicative(a: Quat, b: Quat) -> Verdict {
    let want = norm2(a) * norm2(b);
    let got = norm2(a * b);
    within(
        "product_norm_is_multiplicative",
        (got - want).abs(),
        // No underflow slack: the precondition keeps the norms normal.
        ONE_STEP_NORM_TOL * want,
    )
}

/// `|q v| = |v|` for a unit `q`: rotations keep lengths (compared as
/// squares: `|q v|^2` within `2b + b^2` of `|v|^2` for a length bound `b`).
///
/// Preconditions: `q` unit to [`ONE_STEP_NORM_TOL`] (as `normalize` gives),
/// `v` finite with `|v| <= 2^40`.
pub fn rotation_preserves_length(q: Quat, v: Cvec3) -> Verdict {
    let len2 = vnorm2(v);
    // A q off unit by d scales part of v by 1 + d: up to 2 d |v| in all.
    let b = 2.0 * ONE_STEP_NORM_TOL + 4.0 * ROTATE_MAX_REL_ERROR as f64;
    within(
        "rotation_preserves_length",
        (vnorm2(q * v) - len2).abs(),
        relative(2.0 * b + b * b, len2),
    )
}

/// `normalize` gives a unit quaternion for every finite non-zero input,
/// from subnormal to `f32::MAX` components.
///
/// Preconditions: `q` finite and not zero.
pub fn normalize_is_unit(q: Quat) -> Verdict {
    within(
        "normalize_is_unit",
        (norm2(q.normalize()) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )
}

/// `pow` gives a finite unit quaternion for every finite input and every
/// finite exponent (the contract's item 3): zero, subnormal or huge vector
/// parts, `w = +-1`, `w = 0`, non-unit inputs, any `alpha`.
///
/// Preconditions: `q` and `alpha` finite.
pub fn pow_is_unit(q: Quat, alpha: f32) -> Verdict {
    let r = q.pow(alpha);
    yes_or_no("pow_is_unit (finite)", r.is_finite())?;
    within("pow_is_unit", (norm2(r) - 1.0).abs(), ONE_STEP_NORM_TOL)
}

/// `pow` turns as the notes define it: the rotation of `q.pow(alpha)` is
/// that of the notes' formula evaluated in `f64` from the same inputs
/// ([`Quat64::pow`](crate::reference::Quat64::pow): `phi = atan2(|v|, w)`,
/// no conditional negation), to within twice the documented
/// [`POW_MAX_ANGLE_ERROR`](rigtform::accuracy::POW_MAX_ANGLE_ERROR) per
/// radian turned (at least one). A norm check cannot see a wrong angle:
/// `(-q).pow(alpha)` is unit too, but turns the other way for `w < 0`.
///
/// Preconditions: `q` finite, `alpha` in `[-4, 4]` (the documented
/// accuracy's range, with a margin; beyond it, where `w` times the scaling
/// of a tiny vector part overflows, `phi` is rounded to 0 and a huge
/// `alpha` multiplies that). Uses `f64` sines and arctangents (libm's): a
/// law for the tests and the fuzz targets, not for Kani.
pub fn pow_turns_as_the_notes_define(q: Quat, alpha: f32) -> Verdict {
    use crate::reference::Quat64;
    let q64 = Quat64::from(q);
    let want = q64.pow(alpha.into());
    let got = Quat64::from(q.pow(alpha));
    let beta = libm::sqrt(q64.x * q64.x + q64.y * q64.y + q64.z * q64.z);
    let theta = 2.0 * libm::atan2(beta, q64.w);
    let turned = (f64::from(alpha) * theta).abs();
    within(
        "pow_turns_as_the_notes_define",
        Quat64::angle_between(got, want),
        2.0 * f64::from(rigtform::accuracy::POW_MAX_ANGLE_ERROR) * turned.max(1.0),
    )
}

/// NaN or infinity in, NaN out: `pow` of a non-finite quaternion or with a
/// non-finite exponent is [`Quat::NAN`].
///
/// Preconditions: `q` or `alpha` not finite.
pub fn pow_of_non_finite_is_nan(q: Quat, alpha: f32) -> Verdict {
    yes_or_no("pow_of_non_finite_is_nan", is_nan_quat(q.pow(alpha)))
}

/// `slerp` of unit quaternions gives a finite unit quaternion for every
/// finite `alpha`: identical, nearly identical, antipodal and opposite
/// inputs included.
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], `alpha` finite.
pub fn slerp_is_unit(a: Quat, b: Quat, alpha: f32) -> Verdict {
    let r = a.slerp(b, alpha);
    yes_or_no("slerp_is_unit (finite)", r.is_finite())?;
    within("slerp_is_unit", (norm2(r) - 1.0).abs(), TWO_STEP_NORM_TOL)
}

/// NaN or infinity in, NaN out: `slerp` with a non-finite input or
/// exponent is [`Quat::NAN`] (the NaN of `pow` spreads through the product).
///
/// Preconditions: `a`, `b` or `alpha` not finite.
pub fn slerp_of_non_finite_is_nan(a: Quat, b: Quat, alpha: f32) -> Verdict {
    yes_or_no("slerp_of_non_finite_is_nan", is_nan_quat(a.slerp(b, alpha)))
}

/// `slerp(a, b, 0) == a`, exactly (up to the sign of zero components).
///
/// Preconditions: `a` and `b` finite, components at most 2^60 in magnitude
/// (so that `b a^-1` is finite).
pub fn slerp_is_exact_at_zero(a: Quat, b: Quat) -> Verdict {
    yes_or_no("slerp_is_exact_at_zero", a.slerp(b, 0.0) == a)
}

/// Slerp takes the short way at constant angular velocity: for `alpha` in
/// `[0, 1]`, the rotation from `a` to `slerp(a, b, alpha)` is `alpha` times
/// the rotation from `a` to `b` (at most pi), to within the documented
/// slerp error, doubled for the error of measuring the angles themselves.
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], `alpha` in `[0, 1]`.
pub fn slerp_turns_by_alpha_times_the_angle(a: Quat, b: Quat, alpha: f32) -> Verdict {
    let theta = a.angle_to(b);
    let turned = a.angle_to(a.slerp(b, alpha));
    within(
        "slerp_turns_by_alpha_times_the_angle",
        (f64::from(turned) - f64::from(alpha) * f64::from(theta)).abs(),
        slerp_angle_tol(theta.into()),
    )
}

/// `slerp` is the notes' `cn(b a^-1)^alpha a`: its rotation is that of the
/// formula evaluated in `f64` from the same inputs
/// ([`Quat64::slerp`](crate::reference::Quat64::slerp)), to within twice
/// the documented [`SLERP_MAX_ANGLE_ERROR`](rigtform::accuracy::SLERP_MAX_ANGLE_ERROR)
/// per radian turned (at least one).
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], `alpha` in
/// `[-1, 2]` (farther out, extrapolating from nearly identical inputs has a
/// documented error of its own). Uses libm's `f64` functions: a law for the
/// tests and the fuzz targets, not for Kani.
pub fn slerp_matches_the_notes(a: Quat, b: Quat, alpha: f32) -> Verdict {
    use crate::reference::Quat64;
    let (a64, b64) = (Quat64::from(a), Quat64::from(b));
    let got = Quat64::from(a.slerp(b, alpha));
    let theta = Quat64::angle_between(a64, b64);
    // The transition b a^-1 and its negation: cn picks the one with w >= 0.
    // Within rounding of w = 0 (rotations pi apart) both ways are short,
    // and the sign of slerp's f32 dot product picks one: either is right.
    let d = b64 * a64.conj();
    let minus_d = Quat64 {
        w: -d.w,
        x: -d.x,
        y: -d.y,
        z: -d.z,
    };
    let error = |d: Quat64| Quat64::angle_between(got, d.pow(alpha.into()) * a64);
    let measured = if d.w.abs() <= PI_APART_DOT {
        error(d).min(error(minus_d))
    } else {
        error(if d.w < 0.0 { minus_d } else { d })
    };
    within(
        "slerp_matches_the_notes",
        measured,
        slerp_angle_tol(f64::from(alpha).abs() * theta),
    )
}

/// `|a . b|` below which two unit quaternions count as rotations pi apart
/// for [`slerp_matches_the_notes`]: several f32 roundings of a dot product
/// of unit inputs (a few 1e-8).
const PI_APART_DOT: f64 = 1e-6;

/// Slerp takes the short way: `b` and `-b` are one rotation, so they give
/// one path (the rounding is the same: `cn` flips `-b` back to `b`
/// exactly). Only rotations exactly pi apart (`a.dot(b) == 0`) have two
/// short ways, and the sign of the rounded dot product picks one.
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], `alpha` finite.
pub fn slerp_takes_the_short_way(a: Quat, b: Quat, alpha: f32) -> Verdict {
    if a.dot(b) == 0.0 {
        return Ok(());
    }
    let (p, q) = (a.slerp(b, alpha), a.slerp(-b, alpha));
    yes_or_no("slerp_takes_the_short_way", p == q || p == -q)
}

/// `slerp(a, b, 1)` is the rotation of `b` (possibly as `-b`), to within
/// the documented slerp error, doubled for the error of measuring the angle.
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`].
pub fn slerp_reaches_the_rotation_of_b_at_one(a: Quat, b: Quat) -> Verdict {
    within(
        "slerp_reaches_the_rotation_of_b_at_one",
        f64::from(a.slerp(b, 1.0).angle_to(b)),
        slerp_angle_tol(a.angle_to(b).into()),
    )
}

/// `nlerp` of unit quaternions is unit, for `alpha` in `[0, 1]` (it blends
/// on one hemisphere, so the sum never comes near zero).
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], `alpha` in `[0, 1]`.
pub fn nlerp_is_unit(a: Quat, b: Quat, alpha: f32) -> Verdict {
    within(
        "nlerp_is_unit",
        (norm2(a.nlerp(b, alpha)) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )
}

/// `blend` of finite entries is unit, or [`Quat::IDENTITY`] when the
/// weights cancel (the documented result for "no rotation information").
///
/// Preconditions: every quaternion unit to [`ONE_STEP_NORM_TOL`], every
/// weight finite with magnitude at most 2^60.
pub fn blend_is_unit_or_identity(entries: &[(Quat, f32)]) -> Verdict {
    let r = Quat::blend(entries);
    if r == Quat::IDENTITY {
        return Ok(());
    }
    within(
        "blend_is_unit_or_identity",
        (norm2(r) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )
}

/// `q.inv().inv() == q`, bit for bit, for every input (NaN payloads and
/// signed zeros included).
///
/// Preconditions: none.
pub fn inverse_is_an_involution(q: Quat) -> Verdict {
    yes_or_no("inverse_is_an_involution", same_bits(q.inv().inv(), q))
}

/// `q q^-1 = (|q|^2, 0)`: the real part is the rounded sum of squares and
/// the vector part cancels to rounding (its terms meet their own negations,
/// though not always in an order that makes the cancellation exact), so a
/// unit `q` gives the identity.
///
/// Preconditions: `q` finite, components at most 2^60 in magnitude.
pub fn product_with_inverse_is_real(q: Quat) -> Verdict {
    let r = q * q.inv();
    let n2 = norm2(q);
    let tol = relative(ONE_STEP_NORM_TOL, n2);
    within(
        "product_with_inverse_is_real (vector part, squared)",
        vnorm2(r.vector()),
        tol * tol,
    )?;
    within(
        "product_with_inverse_is_real",
        (f64::from(r.w) - n2).abs(),
        tol,
    )
}

/// `cn(q)` has `w >= 0` and is `q` or `-q`, bit for bit: the same rotation,
/// on the near hemisphere (a NaN `w` is left alone).
///
/// Preconditions: none.
pub fn cn_gives_non_negative_w_and_the_same_rotation(q: Quat) -> Verdict {
    let r = q.cn();
    yes_or_no(
        "cn_gives_non_negative_w_and_the_same_rotation",
        (r.w >= 0.0 || r.w.is_nan()) && (same_bits(r, q) || same_bits(r, -q)),
    )
}

/// `a a^-1 = IDENTITY`: the rotation part as
/// [`product_with_inverse_is_real`] says, and the translation back to zero
/// within [`TRANSLATION_REL_TOL`] `|t|`.
///
/// Preconditions: `a.r` unit to [`ONE_STEP_NORM_TOL`], `a.t` finite with
/// `|a.t| <= 2^40`.
pub fn rigid_product_with_inverse_is_identity(a: RigTForm) -> Verdict {
    let p = a * a.inv();
    product_with_inverse_is_real(a.r)?;
    within(
        "rigid_product_with_inverse_is_identity (rotation, squared)",
        norm2(Quat::from_wxyz(p.r.w - 1.0, p.r.x, p.r.y, p.r.z)),
        4.0 * ONE_STEP_NORM_TOL * ONE_STEP_NORM_TOL,
    )?;
    within(
        "rigid_product_with_inverse_is_identity (squared)",
        vnorm2(p.t),
        relative(TRANSLATION_REL_TOL * TRANSLATION_REL_TOL, vnorm2(a.t)),
    )
}

/// `a.inv().inv() = a`: the rotation bit for bit, the translation within
/// [`TRANSLATION_REL_TOL`] `|t|`.
///
/// Preconditions: `a.r` unit to [`ONE_STEP_NORM_TOL`], `a.t` finite with
/// `|a.t| <= 2^40`.
pub fn rigid_inverse_is_an_involution(a: RigTForm) -> Verdict {
    let b = a.inv().inv();
    yes_or_no(
        "rigid_inverse_is_an_involution (rotation)",
        same_bits(b.r, a.r),
    )?;
    within(
        "rigid_inverse_is_an_involution (squared)",
        vnorm2(b.t - a.t),
        relative(TRANSLATION_REL_TOL * TRANSLATION_REL_TOL, vnorm2(a.t)),
    )
}

/// `RigTForm::inv` agrees with `Matrix4::inverse`: the matrix of `a.inv()`
/// equals the inverse of the matrix of `a`, entry by entry, within
/// `(8 INVERSE_MAX_REL_ERROR + 4 ONE_STEP_NORM_TOL) (1 + |t|_1)` (the cofactor inverse of a rigid
/// matrix has a unit determinant whose expansion's magnitudes `T` sum to
/// at most `3 sqrt 3` for unit rows; a rotation entry's cofactor is a 2x2
/// minor, its products' magnitudes at most 2, and a translation entry's is
/// a triple product with `t`, at most `|t|` and its products' magnitudes
/// at most `2 |t|_1`: each entry within `(2 + 3 sqrt 3)
/// INVERSE_MAX_REL_ERROR` or `(2 |t|_1 + 3 sqrt 3 |t|)
/// INVERSE_MAX_REL_ERROR` of the exact one).
///
/// Preconditions: `a.r` unit to [`ONE_STEP_NORM_TOL`], `a.t` finite with
/// `|a.t| <= 2^20`.
pub fn rigid_inverse_matches_matrix_inverse(a: RigTForm) -> Verdict {
    let Some(m) = Matrix4::from(a).inverse() else {
        return yes_or_no("rigid_inverse_matches_matrix_inverse (invertible)", false);
    };
    let want = Matrix4::from(a.inv()).to_cols_array();
    let worst = m
        .to_cols_array()
        .iter()
        .zip(want)
        .map(|(&x, y)| (f64::from(x) - f64::from(y)).abs())
        .fold(0.0, f64::max);
    // Plus what a rotation off unit does: its matrix is then no longer
    // orthogonal, and the conjugate no longer its exact inverse.
    let tol =
        (8.0 * f64::from(INVERSE_MAX_REL_ERROR) + 4.0 * ONE_STEP_NORM_TOL) * (1.0 + vnorm1(a.t));
    within("rigid_inverse_matches_matrix_inverse", worst, tol)
}

/// The matrix of a rigid transform moves points and vectors as the
/// transform does: `Matrix4::from(a) * c` equals `a * c` within the
/// rotation error, relative to `|t|_1 + |c|_1`.
///
/// Preconditions: `a.r` unit to [`ONE_STEP_NORM_TOL`]; `a.t` and `c` finite,
/// magnitudes at most 2^40; `c.w` 0 or 1.
pub fn rigid_matrix_moves_points_as_the_transform(a: RigTForm, c: Cvec4) -> Verdict {
    let by_matrix = Matrix4::from(a) * c;
    let by_rbt = a * c;
    let d = by_matrix - by_rbt;
    let scale = vnorm1(a.t) + vnorm1(c.xyz());
    // The matrix entries carry MATRIX_ENTRY_ERROR; both paths round.
    let tol = 8.0 * f64::from(rigtform::accuracy::MATRIX_ENTRY_ERROR);
    let worst = [d.x, d.y, d.z, d.w]
        .iter()
        .map(|&e| f64::from(e).abs())
        .fold(0.0, f64::max);
    within(
        "rigid_matrix_moves_points_as_the_transform",
        worst,
        relative(tol, scale),
    )
}

/// `interpolate(a, b, 0) == a`, exactly: `lerp` and `slerp` are both exact
/// at `alpha = 0`.
///
/// Preconditions: `a` and `b` finite, components at most 2^60.
pub fn interpolate_is_exact_at_zero(a: RigTForm, b: RigTForm) -> Verdict {
    yes_or_no("interpolate_is_exact_at_zero", a.interpolate(b, 0.0) == a)
}

/// `Quat::slerp_slice` is `slerp` element by element, bit for bit (a NaN
/// where slerp's is NaN: Rust leaves the sign and payload of a NaN result
/// unspecified, and the compiler may swap a product's operands), for any
/// input bits and any `alpha`; and slices of different lengths write the
/// shortest length, leaving the rest of `out` as it was.
///
/// Preconditions: none.
pub fn slerp_slice_is_slerp_bit_for_bit<const N: usize>(
    starts: &[Quat; N],
    ends: &[Quat; N],
    alpha: f32,
) -> Verdict {
    let mut out = [Quat::NAN; N];
    Quat::slerp_slice(starts, ends, alpha, &mut out);
    let floats = |q: Quat| [q.w, q.x, q.y, q.z];
    let same = starts
        .iter()
        .zip(ends)
        .zip(&out)
        .all(|((&a, &b), &o)| same_floats(floats(o), floats(a.slerp(b, alpha))));
    yes_or_no("slerp_slice_is_slerp_bit_for_bit", same)?;
    // One start fewer: the last element of out is not written.
    let mut short = [Quat::NAN; N];
    let fewer = starts.split_last().map_or(&[][..], |(_, rest)| rest);
    Quat::slerp_slice(fewer, ends, alpha, &mut short);
    let kept = short.last().is_none_or(|&q| same_bits(q, Quat::NAN));
    let mut written = fewer.iter().zip(&out).zip(&short);
    let same = written.all(|((_, &o), &s)| same_floats(floats(o), floats(s)));
    yes_or_no("slerp_slice_is_slerp_bit_for_bit (shorter)", same && kept)
}

/// `RigTForm::interpolate_slice` is `interpolate` element by element, bit
/// for bit (a NaN where interpolate's is NaN, as for
/// [`slerp_slice_is_slerp_bit_for_bit`]), for any input bits and any
/// `alpha`.
///
/// Preconditions: none.
pub fn interpolate_slice_is_interpolate_bit_for_bit<const N: usize>(
    starts: &[RigTForm; N],
    ends: &[RigTForm; N],
    alpha: f32,
) -> Verdict {
    let mut out = [RigTForm::IDENTITY; N];
    RigTForm::interpolate_slice(starts, ends, alpha, &mut out);
    let floats = |a: RigTForm| [a.t.x, a.t.y, a.t.z, a.r.w, a.r.x, a.r.y, a.r.z];
    let same = starts
        .iter()
        .zip(ends)
        .zip(&out)
        .all(|((&a, &b), &o)| same_floats(floats(o), floats(a.interpolate(b, alpha))));
    yes_or_no("interpolate_slice_is_interpolate_bit_for_bit", same)
}

/// `Matrix4::inverse` and `normal_matrix` give `None` or finite entries,
/// for any input bits, never a panic; a normal matrix has no translation.
///
/// Preconditions: none.
pub fn matrix_inverse_is_none_or_finite(m: Matrix4) -> Verdict {
    let inverse_ok = m.inverse().is_none_or(Matrix4::is_finite);
    let normal_ok = m
        .normal_matrix()
        .is_none_or(|n| n.is_finite() && n.cols[3] == Cvec4::new(0.0, 0.0, 0.0, 1.0));
    yes_or_no("matrix_inverse_is_none_or_finite", inverse_ok && normal_ok)
}

/// The Catmull-Rom spline is each key at that key, bit for bit, and the
/// end keys beyond the ends; a NaN `t` gives [`Quat::NAN`], no keys
/// [`Quat::IDENTITY`]. Nothing is computed on this path but the place of
/// `t`, so it holds for any bits of the keys.
///
/// Preconditions: `t` NaN, a whole number, or outside `(0, keys.len() - 1)`.
pub fn catmull_rom_is_the_key_at_and_beyond_each_key(keys: &[Quat], t: f32) -> Verdict {
    let law = "catmull_rom_is_the_key_at_and_beyond_each_key";
    let got = Quat::catmull_rom(keys, t);
    let Some(last) = keys.len().checked_sub(1) else {
        return yes_or_no(law, same_bits(got, Quat::IDENTITY));
    };
    if t.is_nan() {
        return yes_or_no(law, is_nan_quat(got));
    }
    let i = if t <= 0.0 {
        0
    } else if t >= last as f32 {
        last
    } else {
        t as usize
    };
    yes_or_no(law, keys.get(i).is_some_and(|&k| same_bits(got, k)))
}

/// The Catmull-Rom spline of unit keys is a finite unit quaternion for
/// every `t` but NaN (it is normalized at the end; at a key it is the
/// key).
///
/// Preconditions: every key unit to [`ONE_STEP_NORM_TOL`], `t` not NaN.
pub fn catmull_rom_is_unit(keys: &[Quat], t: f32) -> Verdict {
    let r = Quat::catmull_rom(keys, t);
    yes_or_no("catmull_rom_is_unit (finite)", r.is_finite())?;
    within(
        "catmull_rom_is_unit",
        (norm2(r) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )
}

/// The angle error allowed between two evaluations of the spline that
/// differ by a rounded product with each key and with the result: four
/// times the measured spline error (two evaluations, each doubled for the
/// worst case) and four products.
fn catmull_rom_tol() -> f64 {
    4.0 * f64::from(rigtform::accuracy::CATMULL_ROM_MAX_ANGLE_ERROR)
        + 4.0 * f64::from(rigtform::accuracy::MUL_MAX_ANGLE_ERROR)
}

/// Left invariance: `catmull_rom(w * keys, t)` is the rotation of
/// `w * catmull_rom(keys, t)`, for any rotation `w` (the power of a
/// conjugate is the conjugate of the power, and slerp is left invariant).
///
/// Preconditions: `w` and the keys unit to [`ONE_STEP_NORM_TOL`],
/// neighbouring keys at most 1.5 rad apart (so that no transition the
/// construction takes the power of is near its conditional negation's
/// switch at pi), `t` finite.
pub fn catmull_rom_is_left_invariant<const N: usize>(w: Quat, keys: [Quat; N], t: f32) -> Verdict {
    let turned = Quat::catmull_rom(&keys.map(|k| w * k), t);
    let then_turned = w * Quat::catmull_rom(&keys, t);
    within(
        "catmull_rom_is_left_invariant",
        f64::from(turned.angle_to(then_turned)),
        catmull_rom_tol(),
    )
}

/// With two keys the spline follows slerp's path between them (its
/// control points lie on that great circle), though not at slerp's
/// constant rate: at each `t` it is `a.slerp(b, s)` for the `s` of the
/// angle it has turned from `a`.
///
/// Preconditions: `a` and `b` unit to [`ONE_STEP_NORM_TOL`], at most 3 rad
/// apart (away from the tie between the two ways at pi), `t` finite.
pub fn catmull_rom_of_two_keys_follows_the_slerp_path(a: Quat, b: Quat, t: f32) -> Verdict {
    let r = Quat::catmull_rom(&[a, b], t);
    let theta = a.angle_to(b);
    let s = if theta > 0.0 {
        a.angle_to(r) / theta
    } else {
        0.0
    };
    within(
        "catmull_rom_of_two_keys_follows_the_slerp_path",
        f64::from(r.angle_to(a.slerp(b, s))),
        catmull_rom_tol() + slerp_angle_tol(theta.into()),
    )
}

/// The translation of `RigTForm::catmull_rom` is the cubic Bezier segment
/// of the Catmull-Rom control points `c_i + (c_{i+1} - c_{i-1}) / 6` and
/// `c_{i+1} - (c_{i+2} - c_i) / 6`, evaluated here in f64 in its Bernstein
/// form: equal to 2^-18 of the largest translation component (a few
/// roundings in each of the six lerps and the control points).
///
/// Preconditions: at least two keys, translations finite with components
/// at most 2^100 in magnitude, `t` finite.
pub fn catmull_rom_translation_is_the_cubic(keys: &[RigTForm], t: f32) -> Verdict {
    let law = "catmull_rom_translation_is_the_cubic";
    let n = keys.len();
    let got = RigTForm::catmull_rom(keys, t).t;
    let last = n.saturating_sub(1);
    // The segment and the parameter along it, as the spline places t.
    let t = f64::from(t).clamp(0.0, last as f64);
    let i = (t as usize).min(last.saturating_sub(1));
    let u = t - i as f64;
    let at = |j: usize| {
        let c = keys.get(j.min(last)).map_or(Cvec3::ZERO, |k| k.t);
        [c.x, c.y, c.z].map(f64::from)
    };
    let (before, from, to, after) = (at(i.saturating_sub(1)), at(i), at(i + 1), at(i + 2));
    let v = 1.0 - u;
    let mut largest = 0.0f64;
    let mut error = 0.0f64;
    // Once NaN, error stays NaN: `e > NaN` is false.
    for (k, got) in [got.x, got.y, got.z].into_iter().enumerate() {
        let p1 = from[k] + (to[k] - before[k]) / 6.0;
        let p2 = to[k] - (after[k] - from[k]) / 6.0;
        let want =
            from[k] * v * v * v + 3.0 * p1 * v * v * u + 3.0 * p2 * v * u * u + to[k] * u * u * u;
        let e = (f64::from(got) - want).abs();
        // A NaN is kept (max would drop it), so that it fails.
        if e.is_nan() || e > error {
            error = e;
        }
        for c in [before[k], from[k], to[k], after[k]] {
            largest = largest.max(c.abs());
        }
    }
    within(law, error, relative(3.814_697_265_625e-6, largest))
}

#[cfg(test)]
mod tests {
    //! Each law must be able to fail: a deliberately wrong input breaks it.
    use super::*;

    #[test]
    fn laws_hold_on_plain_inputs() {
        let a = Quat::from_rotation_x(0.7);
        let b = Quat::from_axis_angle(Cvec3::new(1.0, 2.0, 3.0), 2.5);
        let f = RigTForm::new(Cvec3::new(3.0, -4.0, 12.0), b);
        let v = Cvec3::new(1.0, -2.0, 0.5);
        assert_eq!(product_norm_is_multiplicative(a, b), Ok(()));
        assert_eq!(rotation_preserves_length(b, v), Ok(()));
        assert_eq!(
            normalize_is_unit(Quat::from_wxyz(1e-40, 3e-41, 0.0, 0.0)),
            Ok(())
        );
        assert_eq!(
            pow_is_unit(Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0), 0.3),
            Ok(())
        );
        assert_eq!(pow_of_non_finite_is_nan(a, f32::NAN), Ok(()));
        assert_eq!(slerp_of_non_finite_is_nan(a, Quat::NAN, 0.5), Ok(()));
        assert_eq!(slerp_of_non_finite_is_nan(a, b, f32::INFINITY), Ok(()));
        assert_eq!(slerp_is_unit(a, -a, 0.5), Ok(()));
        assert_eq!(slerp_is_exact_at_zero(a, b), Ok(()));
        assert_eq!(slerp_turns_by_alpha_times_the_angle(a, b, 0.25), Ok(()));
        assert_eq!(slerp_reaches_the_rotation_of_b_at_one(a, -b), Ok(()));
        assert_eq!(nlerp_is_unit(a, -b, 0.5), Ok(()));
        assert_eq!(blend_is_unit_or_identity(&[(a, 1.0), (b, 2.0)]), Ok(()));
        assert_eq!(blend_is_unit_or_identity(&[(a, 1.0), (a, -1.0)]), Ok(()));
        assert_eq!(inverse_is_an_involution(Quat::NAN), Ok(()));
        assert_eq!(product_with_inverse_is_real(b), Ok(()));
        assert_eq!(cn_gives_non_negative_w_and_the_same_rotation(-a), Ok(()));
        assert_eq!(rigid_product_with_inverse_is_identity(f), Ok(()));
        assert_eq!(rigid_inverse_is_an_involution(f), Ok(()));
        assert_eq!(rigid_inverse_matches_matrix_inverse(f), Ok(()));
        assert_eq!(
            rigid_matrix_moves_points_as_the_transform(f, Cvec4::from_point(v)),
            Ok(())
        );
        assert_eq!(interpolate_is_exact_at_zero(f, RigTForm::IDENTITY), Ok(()));
        assert_eq!(matrix_inverse_is_none_or_finite(Matrix4::IDENTITY), Ok(()));
        let keys = [a, b, -a, Quat::from_rotation_z(1.0)];
        for t in [-1.0, 0.0, 1.0, 3.0, 9.0, f32::NAN, f32::INFINITY] {
            assert_eq!(
                catmull_rom_is_the_key_at_and_beyond_each_key(&keys, t),
                Ok(())
            );
        }
        assert_eq!(
            catmull_rom_is_the_key_at_and_beyond_each_key(&[], 0.5),
            Ok(())
        );
        let walk = [
            a,
            Quat::from_rotation_y(1.0) * a,
            Quat::from_rotation_z(1.2) * a,
        ];
        assert_eq!(catmull_rom_is_unit(&walk, 1.3), Ok(()));
        assert_eq!(catmull_rom_is_left_invariant(b, walk, 0.7), Ok(()));
        assert_eq!(
            catmull_rom_of_two_keys_follows_the_slerp_path(a, -b, 0.3),
            Ok(())
        );
        let frames = walk.map(|r| RigTForm::new(Cvec3::new(r.x, 2.0, -r.w), r));
        assert_eq!(catmull_rom_translation_is_the_cubic(&frames, 1.4), Ok(()));
    }

    #[test]
    fn laws_fail_on_inputs_that_break_them() {
        // Inputs outside the preconditions, where the law is false.
        let a = Quat::from_rotation_x(0.7);
        let scaled = Quat::from_wxyz(2.0, 0.0, 0.0, 0.0);
        assert!(rotation_preserves_length(Quat::from_wxyz(0.0, 2.0, 0.0, 0.0), Cvec3::Y).is_err());
        assert!(normalize_is_unit(Quat::from_wxyz(0.0, 0.0, 0.0, 0.0)).is_err());
        assert!(pow_is_unit(Quat::NAN, 0.5).is_err());
        assert!(pow_of_non_finite_is_nan(a, 0.5).is_err());
        assert!(slerp_of_non_finite_is_nan(a, a, 0.5).is_err());
        assert!(slerp_is_unit(scaled, a, 0.5).is_err());
        assert!(slerp_turns_by_alpha_times_the_angle(a, -a.inv(), 3.0).is_err());
        assert!(slerp_reaches_the_rotation_of_b_at_one(a, Quat::NAN).is_err());
        assert!(nlerp_is_unit(Quat::NAN, a, 0.5).is_err());
        assert!(blend_is_unit_or_identity(&[(scaled, 1.0)]).is_ok()); // normalized
        assert!(blend_is_unit_or_identity(&[(a, f32::NAN)]).is_err());
        assert!(product_with_inverse_is_real(Quat::from_wxyz(1e30, 1e30, 0.0, 0.0)).is_err());
        let off = RigTForm::new(
            Cvec3::new(1.0, 2.0, 3.0),
            Quat::from_wxyz(0.0, 2.0, 0.0, 0.0),
        );
        assert!(rigid_product_with_inverse_is_identity(off).is_err());
        assert!(rigid_inverse_is_an_involution(off).is_err());
        assert!(rigid_inverse_matches_matrix_inverse(off).is_err());
        let singular = Matrix4::from_scale(Cvec3::new(1.0, 0.0, 1.0));
        assert_eq!(matrix_inverse_is_none_or_finite(singular), Ok(()));
        let b = Quat::from_rotation_y(1.0);
        assert!(catmull_rom_is_the_key_at_and_beyond_each_key(&[a, b], 0.5).is_err());
        assert!(catmull_rom_is_unit(&[scaled, scaled], 0.0).is_err());
        assert!(catmull_rom_is_left_invariant(Quat::NAN, [a, b], 0.5).is_err());
        assert!(catmull_rom_of_two_keys_follows_the_slerp_path(a, Quat::NAN, 0.5).is_err());
        let far = [
            Cvec3::new(f32::MAX, 0.0, 0.0),
            Cvec3::new(-f32::MAX, 0.0, 0.0),
        ];
        let far = far.map(|t| RigTForm::new(t, a));
        assert!(catmull_rom_translation_is_the_cubic(&far, 0.5).is_err());
        let err = product_norm_is_multiplicative(a, Quat::NAN).unwrap_err();
        assert_eq!(err.law, "product_norm_is_multiplicative");
        assert!(err.measured.is_nan());
    }

    #[test]
    fn tolerances_follow_their_derivation() {
        let u = 1.0 / 16_777_216.0; // 2^-24
        let unit = f64::from(UNIT_NORM_ERROR);
        let rotate = f64::from(ROTATE_MAX_REL_ERROR);
        assert_eq!(ONE_STEP_NORM_TOL, 4.0 * unit);
        assert_eq!(TWO_STEP_NORM_TOL, 8.0 * unit);
        assert_eq!(TRANSLATION_REL_TOL, 16.0 * unit + 8.0 * rotate);
        // The worst case of a product's squared norm, 16u, fits under the
        // one-step tolerance, and the tolerance is not much looser.
        assert!((16.0 * u..=32.0 * u).contains(&ONE_STEP_NORM_TOL));
        let s = f64::from(rigtform::accuracy::SLERP_MAX_ANGLE_ERROR);
        assert_eq!(slerp_angle_tol(0.5), 2.0 * s);
        assert_eq!(slerp_angle_tol(3.0), 6.0 * s);
        assert_eq!(relative(2.0, 3.0), 6.0 + UNDERFLOW_SLACK);
    }

    #[test]
    fn the_length_law_fails_just_beyond_its_bound() {
        // A half turn about x scaled by s acts on y as 1 - 2 s^2: with
        // s^2 = 1 + d, the squared length grows by about 4 d.
        let b = 2.0 * ONE_STEP_NORM_TOL + 4.0 * f64::from(ROTATE_MAX_REL_ERROR);
        let at = |d: f64| {
            let s = (1.0 + d).sqrt() as f32;
            rotation_preserves_length(Quat::from_wxyz(0.0, s, 0.0, 0.0), Cvec3::Y)
        };
        assert_eq!(at(0.2 * b), Ok(()));
        assert!(at(1.0 * b).is_err());
    }

    #[test]
    fn the_product_law_fails_where_products_underflow() {
        // Outside the precondition: the product of two 1e-30 quaternions
        // underflows to zero, and its norm is no longer the product of norms.
        let tiny = Quat::from_wxyz(1e-30, 1e-30, 0.0, 0.0);
        assert!(product_norm_is_multiplicative(tiny, tiny).is_err());
    }

    #[test]
    fn helpers_compare_every_component() {
        assert!(is_nan_quat(Quat::NAN));
        for k in 0..4 {
            let mut c = [f32::NAN; 4];
            c[k] = 0.0;
            assert!(!is_nan_quat(Quat::from_wxyz(c[0], c[1], c[2], c[3])));
            let mut d = [1.0f32; 4];
            d[k] = -1.0;
            let q = Quat::from_wxyz(d[0], d[1], d[2], d[3]);
            assert!(!same_bits(q, Quat::from_wxyz(1.0, 1.0, 1.0, 1.0)));
        }
        assert!(!same_bits(
            Quat::from_wxyz(0.0, 0.0, 0.0, 0.0),
            Quat::from_wxyz(-0.0, 0.0, 0.0, 0.0)
        ));
        assert!(same_bits(Quat::NAN, Quat::NAN));
    }
}
