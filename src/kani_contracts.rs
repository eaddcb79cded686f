//! Kani, for firmware that runs `cargo kani` on its own code: under
//! `cfg(kani)`, `kani::Arbitrary` for [`Quat`] (unit), [`Cvec3`] and
//! [`RigTForm`], and the proof harnesses of the contracts on the core
//! operations; in every build with Kani or the `kernel-contracts` feature,
//! the contracts themselves, one function per condition, which the
//! operations' `kani::requires` and `kani::ensures` call and which
//! `rigtform-proofs`' `tests/library_contracts.rs` checks on random and
//! edge inputs. `docs/kani.md` is the guide.
//!
//! The bounds the postconditions state are the ones Gappa proves
//! (`proofs/gappa/`, `cargo xtask prove`), not the measured maxima of
//! [`accuracy`](crate::accuracy), so that a contract holds by a checked
//! proof and not only on the draws that measured it; the test above
//! reads each from its model. Every condition is computed in f64 from the
//! f32 components (their squares are exact there) without a square root,
//! and makes no NaN from numbers, which Kani would report.
//!
//! Not part of the API (hidden): the
//! contracts change with the proofs.

use crate::{Cvec3, Quat, RigTForm};

/// `| |normalize(q)| - 1 |` for every finite non-zero `q`:
/// `proofs/coq/normalize_norm.v`, on the certificate of
/// `proofs/gappa/normalize.g` (and `normalize_scale.g` for the rescaled
/// branches, which scale exactly or within 2^-150 and then compute the
/// same).
pub const NORMALIZE_NORM_PROVEN: f64 = 2.391e-7;
/// The length of the error vector of the product of two quaternions with
/// components in [-1, 1] and squared norms within 2^-20 of 1 against the
/// exact product of the same f32 inputs: `proofs/gappa/mul.g`.
pub const MUL_ERROR_PROVEN: f64 = 7.16e-7;
/// `| |a * b| / (|a| |b|) - 1 |` for the same inputs:
/// `proofs/coq/mul_norm.v` (squared norms within 2^-20 of 1, any components).
pub const MUL_NORM_PROVEN: f64 = 2.84e-7;
/// The length of the error vector of `q * v` against the exact value of
/// the same formula, relative to `|v|`, for `q` with components in
/// [-1, 1] and `|q|^2` within 2^-20 of 1, and `v` with components in
/// [-1, 1] and `|v| >= 1/2`: `proofs/coq/rotate_error.v`, on the terms of
/// `proofs/gappa/rotate.g`.
pub const ROTATE_ERROR_PROVEN: f64 = 6.5e-7;

/// How far from 1 the norm of a quaternion that the contracts call unit
/// may be: what [`Quat::normalize`] guarantees ([`NORMALIZE_NORM_PROVEN`]),
/// so that its results are unit.
pub const UNIT_TOL: f64 = NORMALIZE_NORM_PROVEN;
/// `| |a * b| - 1 |` for unit `a`, `b` (norms within [`UNIT_TOL`] of 1):
/// `|a| |b|` is within `2 UNIT_TOL + UNIT_TOL^2` of 1, and the computed
/// product's norm within [`MUL_NORM_PROVEN`] of it, relative.
pub const MUL_OF_UNITS_TOL: f64 =
    2.0 * UNIT_TOL + UNIT_TOL * UNIT_TOL + MUL_NORM_PROVEN * (1.0 + UNIT_TOL) * (1.0 + UNIT_TOL);
/// `| |q * v| - |v| |`, relative to `|v|`, for unit `q` and `v` in
/// `rotate.g`'s domain: the formula `v + 2 w (u x v) + 2 u x (u x v)` is
/// the rotation plus `(1 - |q|^2) v`, so it is off the length of `v` by at
/// most `2 (2 UNIT_TOL + UNIT_TOL^2)` relative, and the computed value
/// within [`ROTATE_ERROR_PROVEN`] of it.
pub const ROTATE_BY_UNIT_TOL: f64 =
    ROTATE_ERROR_PROVEN + 4.0 * UNIT_TOL + 2.0 * UNIT_TOL * UNIT_TOL;
/// The largest component of a vector the contracts take, 2^60: large
/// enough for any measurement, small enough that a rotation (at most 13
/// times the largest component through its intermediate terms) and a
/// translation stay finite.
pub const VEC_BOUND: f32 = 1_152_921_504_606_846_976.0;

/// Relative slack on the f64 comparisons below for their own rounding
/// (each sum of four exact squares rounds by at most 2^-51 relative).
const SLACK: f64 = 1.0 / 281_474_976_710_656.0; // 2^-48

/// Whether `s` (a sum of squares in f64) is between `lo^2` and `hi^2`,
/// with the slack above.
fn squares_between(s: f64, lo: f64, hi: f64) -> bool {
    s >= lo * lo * (1.0 - SLACK) && s <= hi * hi * (1.0 + SLACK)
}

/// `|q|^2` in f64.
fn quat_squares(q: Quat) -> f64 {
    let (x, y, z, w) = (
        f64::from(q.x),
        f64::from(q.y),
        f64::from(q.z),
        f64::from(q.w),
    );
    x * x + y * y + z * z + w * w
}

/// `|v|^2` in f64.
fn vec_squares(v: Cvec3) -> f64 {
    let (x, y, z) = (f64::from(v.x), f64::from(v.y), f64::from(v.z));
    x * x + y * y + z * z
}

/// Every component of `q` in [-1, 1] (the domain of the Gappa models),
/// none NaN.
#[must_use]
pub fn in_unit_box(q: Quat) -> bool {
    q.x.abs() <= 1.0 && q.y.abs() <= 1.0 && q.z.abs() <= 1.0 && q.w.abs() <= 1.0
}

/// Whether `| |q| - 1 | <= tol`.
#[must_use]
pub fn norm_within(q: Quat, tol: f64) -> bool {
    squares_between(quat_squares(q), 1.0 - tol, 1.0 + tol)
}

/// A unit quaternion, as the contracts and `Quat`'s `kani::Arbitrary`
/// mean it: every component in [-1, 1] and the norm within [`UNIT_TOL`]
/// of 1 (every result of [`Quat::normalize`]).
#[must_use]
pub fn is_unit(q: Quat) -> bool {
    in_unit_box(q) && norm_within(q, UNIT_TOL)
}

/// Every component of `v` within +-[`VEC_BOUND`], none NaN.
#[must_use]
pub fn is_bounded(v: Cvec3) -> bool {
    v.x.abs() <= VEC_BOUND && v.y.abs() <= VEC_BOUND && v.z.abs() <= VEC_BOUND
}

/// `r` is the conjugate of `q` bit for bit: `w` kept, `x`, `y`, `z`
/// negated (sign bit flipped, NaN payloads and zeros included).
#[must_use]
pub fn is_conjugate(q: Quat, r: Quat) -> bool {
    const SIGN: u32 = 0x8000_0000;
    r.w.to_bits() == q.w.to_bits()
        && r.x.to_bits() == q.x.to_bits() ^ SIGN
        && r.y.to_bits() == q.y.to_bits() ^ SIGN
        && r.z.to_bits() == q.z.to_bits() ^ SIGN
}

/// `a * b` requires: every component of both in [-1, 1] (the domain of
/// `mul.g`; every unit quaternion).
#[must_use]
pub fn quat_mul_requires(a: Quat, b: Quat) -> bool {
    in_unit_box(a) && in_unit_box(b)
}

/// `a * b = r` ensures: `r` finite; for unit `a` and `b`, `|r|` within
/// [`MUL_OF_UNITS_TOL`] of 1.
#[must_use]
pub fn quat_mul_ensures(a: Quat, b: Quat, r: Quat) -> bool {
    r.is_finite() && (!(is_unit(a) && is_unit(b)) || norm_within(r, MUL_OF_UNITS_TOL))
}

/// `q.normalize()` requires: `q` finite (a zero `q` is allowed).
#[must_use]
pub fn normalize_requires(q: Quat) -> bool {
    q.is_finite()
}

/// `q.normalize() = r` ensures: [`Quat::NAN`] for zero `q`; otherwise `r`
/// unit ([`is_unit`]: components in [-1, 1], norm within
/// [`NORMALIZE_NORM_PROVEN`] of 1).
#[must_use]
pub fn normalize_ensures(q: Quat, r: Quat) -> bool {
    let zero = q.x == 0.0 && q.y == 0.0 && q.z == 0.0 && q.w == 0.0;
    if zero {
        r.x.is_nan() && r.y.is_nan() && r.z.is_nan() && r.w.is_nan()
    } else {
        is_unit(r)
    }
}

/// `q * v` requires: `q`'s components in [-1, 1], `v` [bounded](is_bounded).
#[must_use]
pub fn rotate_requires(q: Quat, v: Cvec3) -> bool {
    in_unit_box(q) && is_bounded(v)
}

/// `q * v = r` ensures: `r` finite; for unit `q` and `v` in `rotate.g`'s
/// domain (components in [-1, 1], `|v| >= 1/2`), `|r|` within
/// [`ROTATE_BY_UNIT_TOL`] `|v|` of `|v|`.
#[must_use]
pub fn rotate_ensures(q: Quat, v: Cvec3, r: Cvec3) -> bool {
    let v2 = vec_squares(v);
    let in_domain =
        is_unit(q) && v.x.abs() <= 1.0 && v.y.abs() <= 1.0 && v.z.abs() <= 1.0 && v2 >= 0.25;
    r.is_finite()
        && (!in_domain || {
            let r2 = vec_squares(r);
            let (lo, hi) = (1.0 - ROTATE_BY_UNIT_TOL, 1.0 + ROTATE_BY_UNIT_TOL);
            r2 >= lo * lo * v2 * (1.0 - SLACK) && r2 <= hi * hi * v2 * (1.0 + SLACK)
        })
}

/// `a.slerp(b, alpha)` requires: `a` and `b` unit, `alpha` in [0, 1].
#[must_use]
pub fn slerp_requires(a: Quat, b: Quat, alpha: f32) -> bool {
    is_unit(a) && is_unit(b) && (0.0..=1.0).contains(&alpha)
}

/// `a.slerp(b, alpha) = r` ensures: `r` finite, and `r == a` bit for bit
/// at `alpha = 0`. (No norm bound: slerp has no Gappa model yet; its
/// measured bound is [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR).)
#[must_use]
pub fn slerp_ensures(a: Quat, alpha: f32, r: Quat) -> bool {
    let same = r.x.to_bits() == a.x.to_bits()
        && r.y.to_bits() == a.y.to_bits()
        && r.z.to_bits() == a.z.to_bits()
        && r.w.to_bits() == a.w.to_bits();
    r.is_finite() && (alpha != 0.0 || same)
}

/// A transform the contracts take: its rotation's components in [-1, 1],
/// its translation [bounded](is_bounded).
#[must_use]
pub fn is_rigid_bounded(a: RigTForm) -> bool {
    in_unit_box(a.r) && is_bounded(a.t)
}

/// `a.inv()` requires: [`is_rigid_bounded`].
#[must_use]
pub fn rigtform_inv_requires(a: RigTForm) -> bool {
    is_rigid_bounded(a)
}

/// `a.inv() = r` ensures: `r.t` finite and `r.r` the conjugate of `a.r`.
#[must_use]
pub fn rigtform_inv_ensures(a: RigTForm, r: RigTForm) -> bool {
    r.t.is_finite() && is_conjugate(a.r, r.r)
}

/// `a * b` of transforms requires: both [`is_rigid_bounded`].
#[must_use]
pub fn rigtform_mul_requires(a: RigTForm, b: RigTForm) -> bool {
    is_rigid_bounded(a) && is_rigid_bounded(b)
}

/// `a * b = r` of transforms ensures: `r.t` finite, and `r.r` what the
/// quaternion product ensures of `a.r * b.r` ([`quat_mul_ensures`]: unit
/// for unit rotations, within the proven bound).
#[must_use]
pub fn rigtform_mul_ensures(a: RigTForm, b: RigTForm, r: RigTForm) -> bool {
    r.t.is_finite() && quat_mul_ensures(a.r, b.r, r.r)
}

/// `a.transform_point(p)` requires: `a` [`is_rigid_bounded`], `p`
/// [bounded](is_bounded).
#[must_use]
pub fn transform_point_requires(a: RigTForm, p: Cvec3) -> bool {
    is_rigid_bounded(a) && is_bounded(p)
}

/// `a.transform_point(p) = r` ensures: `r` finite.
#[must_use]
pub fn transform_point_ensures(r: Cvec3) -> bool {
    r.is_finite()
}

/// Any unit quaternion ([`is_unit`]): four f32 components, each assumed in
/// [-1, 1] and their norm within [`UNIT_TOL`] of 1. Assumed, not made
/// by dividing by the norm, so that no NaN is made on the way and the
/// solver's problem stays small; every result of [`Quat::normalize`] is
/// one of them.
#[cfg(kani)]
impl kani::Arbitrary for Quat {
    fn any() -> Self {
        let q = Quat::from_xyzw(kani::any(), kani::any(), kani::any(), kani::any());
        kani::assume(is_unit(q));
        q
    }
}

/// Any vector with components within +-[`VEC_BOUND`] (2^60): every
/// measurement, and nothing that a rotation or a translation overflows.
#[cfg(kani)]
impl kani::Arbitrary for Cvec3 {
    fn any() -> Self {
        let v = Cvec3::new(kani::any(), kani::any(), kani::any());
        kani::assume(is_bounded(v));
        v
    }
}

/// Any transform with a unit rotation (`Quat`'s `Arbitrary`) and a
/// translation as `Cvec3`'s.
#[cfg(kani)]
impl kani::Arbitrary for RigTForm {
    fn any() -> Self {
        RigTForm::new(kani::any(), kani::any())
    }
}

/// Any value of `T` as its bits may lie, NaN, infinite and subnormal
/// components included: `kani::any::<RawBits<Quat>>().0` is any four f32
/// bit patterns, unit or not. For firmware that must reason about corrupted
/// state (a quaternion read back from flash, a message off a bus), beside
/// `Quat`'s own `Arbitrary`, which is unit.
#[cfg(kani)]
#[derive(Clone, Copy, Debug)]
pub struct RawBits<T>(pub T);

#[cfg(kani)]
fn any_bits() -> f32 {
    f32::from_bits(kani::any())
}

#[cfg(kani)]
impl kani::Arbitrary for RawBits<Quat> {
    fn any() -> Self {
        Self(Quat::from_xyzw(
            any_bits(),
            any_bits(),
            any_bits(),
            any_bits(),
        ))
    }
}

#[cfg(kani)]
impl kani::Arbitrary for RawBits<Cvec3> {
    fn any() -> Self {
        Self(Cvec3::new(any_bits(), any_bits(), any_bits()))
    }
}

#[cfg(kani)]
impl kani::Arbitrary for RawBits<RigTForm> {
    fn any() -> Self {
        let (t, r): (RawBits<Cvec3>, RawBits<Quat>) = (kani::any(), kani::any());
        Self(RigTForm::new(t.0, r.0))
    }
}

/// The harnesses of the contracts: each calls its operation on inputs
/// that the contract's `requires` restricts (Kani assumes it), and Kani
/// checks its `ensures`, and that nothing on the way panics or makes a NaN.
/// Then `#[kani::stub_verified(..)]` may replace the operation by its
/// contract in a firmware's harness.
///
/// As the project's own harnesses (`proofs/src/harnesses.rs`), each is
/// split by exponent range: every symbolic component is built from a sign,
/// a mantissa and an exponent in a fixed range, so that the solver meets
/// one range of binades at a time (a fully symbolic f32 product is
/// several thousand clauses per bit of the exponent's spread). The ranges
/// of a contract's harnesses together cover every input its `requires`
/// admits: for quaternions in the unit box, exponents -127 (zero and the
/// subnormals) to 0; for vectors within 2^60, -127 to 60; for `normalize`,
/// its three branches (scaled up, unscaled, scaled down).
///
/// Written for `cargo kani -p rigtform -Z function-contracts`; not run
/// here (Kani is not installable on the machines this crate is developed
/// on), so nothing here is proven until it has been.
#[cfg(kani)]
mod contract_harnesses {
    use crate::{Cvec3, Quat, RigTForm};

    /// Any f32 of either sign with magnitude in `[2^lo, 2^(hi + 1))`,
    /// built from bits (a biased exponent of 0, `lo = -127`, gives zero
    /// and the subnormals).
    fn any_with_exponent_in(lo: i32, hi: i32) -> f32 {
        let sign_and_mantissa: u32 = kani::any::<u32>() & 0x807f_ffff;
        let span = u32::try_from(hi - lo + 1).unwrap_or(1);
        let biased = u32::try_from(lo + 127).unwrap_or(0) + kani::any::<u32>() % span;
        f32::from_bits(sign_and_mantissa | (biased << 23))
    }

    fn quat_in(lo: i32, hi: i32) -> Quat {
        let c = || any_with_exponent_in(lo, hi);
        Quat::from_xyzw(c(), c(), c(), c())
    }

    fn vec_in(lo: i32, hi: i32) -> Cvec3 {
        let c = || any_with_exponent_in(lo, hi);
        Cvec3::new(c(), c(), c())
    }

    /// The exponent ranges of a quaternion in the unit box: tiny
    /// components (where products go subnormal), and the rest.
    const UNIT_BOX: [(i32, i32); 2] = [(-127, -21), (-20, 0)];
    /// The exponent ranges of a vector within 2^60.
    const BOUNDED: [(i32, i32); 3] = [(-127, -21), (-20, 20), (21, 60)];

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::mul_quat)]
    fn quat_product_small() {
        let _ = quat_in(UNIT_BOX[0].0, UNIT_BOX[0].1).mul_quat(quat_in(-127, 0));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::mul_quat)]
    fn quat_product_moderate() {
        let _ = quat_in(UNIT_BOX[1].0, UNIT_BOX[1].1).mul_quat(quat_in(-127, 0));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::normalize)]
    fn quat_normalize_scaled_up() {
        let _ = quat_in(-127, -51).normalize();
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::normalize)]
    fn quat_normalize_unscaled() {
        let _ = quat_in(-50, 62).normalize();
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::normalize)]
    fn quat_normalize_scaled_down() {
        let _ = quat_in(63, 127).normalize();
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::inv)]
    fn quat_inv() {
        let q: super::RawBits<Quat> = kani::any();
        let _ = q.0.inv();
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::mul_vec3)]
    fn quat_rotates_a_small_vector() {
        let _ = quat_in(-127, 0).mul_vec3(vec_in(BOUNDED[0].0, BOUNDED[0].1));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::mul_vec3)]
    fn quat_rotates_a_moderate_vector() {
        let _ = quat_in(-127, 0).mul_vec3(vec_in(BOUNDED[1].0, BOUNDED[1].1));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::mul_vec3)]
    fn quat_rotates_a_large_vector() {
        let _ = quat_in(-127, 0).mul_vec3(vec_in(BOUNDED[2].0, BOUNDED[2].1));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(Quat::slerp)]
    fn quat_slerp() {
        let _ = quat_in(-127, 0).slerp(quat_in(-127, 0), any_with_exponent_in(-127, 0));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(RigTForm::inv)]
    fn rig_tform_inv() {
        let _ = RigTForm::new(vec_in(-127, 60), quat_in(-127, 0)).inv();
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(RigTForm::mul_rig_tform)]
    fn rig_tform_product() {
        let a = RigTForm::new(vec_in(-127, 60), quat_in(-127, 0));
        let _ = a.mul_rig_tform(RigTForm::new(vec_in(-127, 60), quat_in(-127, 0)));
    }

    #[kani::solver(cadical)]
    #[kani::proof_for_contract(RigTForm::transform_point)]
    fn rig_tform_transform_point() {
        let a = RigTForm::new(vec_in(-127, 60), quat_in(-127, 0));
        let _ = a.transform_point(vec_in(-127, 60));
    }

    /// `RawBits` reaches NaN components (a cover, not a proof).
    #[kani::proof]
    fn raw_bits_reach_nan() {
        let q: super::RawBits<Quat> = kani::any();
        kani::cover!(q.0.x.is_nan(), "a NaN component");
    }
}
