//! Kani proof harnesses over the laws of [`crate::laws`].
//!
//! Under `cargo kani -p rigtform-proofs` (where Kani is installed) each
//! harness is a proof over every input its assumptions allow. Everywhere
//! else (`cargo test`), the same body runs as an ordinary test through the
//! stand-in in `src/kani_stand_in.rs`, on 50,000 random draws: that is testing, not
//! proof. Kani is not installable on the machines this crate is developed
//! on, so none of these harnesses has been proven there, and no proof time
//! is recorded beside them: a harness gets its measured time once
//! `cargo kani` has proven it.
//!
//! Every assumption is marked **precondition** (the law's own, from its
//! docs) or **solver bound** (narrower than the law allows, only to keep the
//! model checker's float arithmetic tractable and every product finite:
//! Kani fails any float operation that makes a NaN from numbers, such as
//! `inf - inf`, whatever its result is used for).
//!
//! The square root is stubbed by its contract everywhere (`src/stubs.rs`:
//! it is inline assembly, which Kani cannot read). `pow` also gets its
//! sine, cosine and atan2 stubbed: its unit norm needs only the Pythagorean
//! identity, whatever the angle, so the proof then covers every kernel that
//! meets the contracts (which `src/float.rs` checks the crate's kernels
//! meet), and nothing about the angle. `slerp`'s unit norm needs accurate
//! angles, so its harnesses keep the real kernels: polynomials (on
//! x86-64, where Kani runs, the f64 arc and `sin(x) / x` of `quat/slerp/in_f64.rs`
//! for `alpha` in (0, 1]), and for extrapolation beyond 3 pi/4 an argument
//! reduction in integers that branches.
//!
//! Tractability: the harnesses of exact, bit-level laws (`inv`, `cn`, NaN
//! out for NaN in, exactness at `alpha = 0`, `None` or finite for the
//! matrix inverse) take paths of comparisons, sign operations and early
//! returns, with symbolic arithmetic only where a matrix is invertible.
//! Three error-bound laws are split for the solver, one harness per
//! exponent range (`quat_product_multiplies_norms_*`,
//! `normalize_is_unit_*`, `quat_times_inverse_is_real_*`): one or two
//! symbolic components built from bits in a fixed exponent range, the
//! others concrete, nothing assumed, and a comment on each saying what
//! keeps it small; their full-range versions stay as random tests here.
//! None of them has been run under Kani, so their tractability is a design
//! argument, not a measured time. The other harnesses that bound an error
//! hand the solver several symbolic divisions, square roots and
//! polynomials at once; each says in one line why, as written, it is a
//! random test and not a proof target.
//!
//! `kani::cover!` marks the branches a law is about; the stand-in fails a
//! harness whose cover no kept draw met, and prints how many met each.

#[cfg(not(kani))]
use crate::kani_stand_in as kani;
use crate::laws::{self, assert_holds};
use core::f32::consts::{FRAC_PI_2, PI};
use rigtform::{Cvec3, Cvec4, EulerRot, Matrix4, Quat, RigTForm};

/// Runs `body` once under Kani (symbolically: once is all inputs), or on
/// many random draws under the stand-in.
fn check(name: &str, body: impl Fn()) {
    #[cfg(kani)]
    {
        let _ = name;
        body();
    }
    #[cfg(not(kani))]
    crate::kani_stand_in::run(name, body);
}

/// Any finite `f32`.
fn any_finite() -> f32 {
    kani::any_where(|x: &f32| x.is_finite())
}

/// Any `f32` of magnitude at most `limit` (NaN excluded).
fn any_within(limit: f32) -> f32 {
    kani::any_where(move |x: &f32| x.abs() <= limit)
}

/// Any quaternion with components of magnitude at most `limit`.
fn any_quat_within(limit: f32) -> Quat {
    Quat::from_wxyz(
        any_within(limit),
        any_within(limit),
        any_within(limit),
        any_within(limit),
    )
}

/// Any vector with components of magnitude at most `limit`.
fn any_vec_within(limit: f32) -> Cvec3 {
    Cvec3::new(any_within(limit), any_within(limit), any_within(limit))
}

/// Any quaternion: every bit pattern of every component.
fn any_quat_bits() -> Quat {
    Quat::from_wxyz(kani::any(), kani::any(), kani::any(), kani::any())
}

/// Any finite quaternion.
fn any_finite_quat() -> Quat {
    Quat::from_wxyz(any_finite(), any_finite(), any_finite(), any_finite())
}

/// A unit quaternion as the laws' preconditions mean it: any finite
/// non-zero quaternion, normalized (which [`normalize_is_unit`] checks
/// lands within the laws' tolerance).
fn any_unit_quat() -> Quat {
    let q = any_finite_quat();
    // Precondition of normalize_is_unit: not zero.
    kani::assume(q != Quat::from_wxyz(0.0, 0.0, 0.0, 0.0));
    q.normalize()
}

/// 2^20: a solver bound on translations and vectors, far inside the laws'
/// 2^40, and beyond any scene or sensor value in metres.
const MILLION: f32 = 1_048_576.0;

/// 2^60: the laws' precondition where a product must stay finite.
const TWO_TO_60: f32 = 1.152_921_5e18;

/// Any `f32` of either sign with magnitude in `[2^lo, 2^(hi + 1))`: a
/// symbolic sign and mantissa and an exponent among `hi - lo + 1`, built
/// from bits, so no draw is rejected and no NaN or infinity can appear
/// (for `-126 <= lo <= hi <= 127`). A biased exponent of 0 (`lo = -127`)
/// gives zero and the subnormals. The split harnesses below give each
/// exponent range a harness of its own, so that the solver meets one
/// binade range at a time.
fn any_with_exponent_in(lo: i32, hi: i32) -> f32 {
    let sign_and_mantissa: u32 = kani::any::<u32>() & 0x807f_ffff;
    let span = u32::try_from(hi - lo + 1).unwrap_or(1);
    let biased = u32::try_from(lo + 127).unwrap_or(0) + kani::any::<u32>() % span;
    f32::from_bits(sign_and_mantissa | (biased << 23))
}

/// Random test, not a proof target: eight unconstrained components, 32
/// symbolic products and the f64 norms at once. The three harnesses after
/// it are the law's proof targets.
#[cfg(all(test, not(kani)))]
#[test]
fn quat_product_multiplies_norms() {
    check("quat_product_multiplies_norms", || {
        // Solver bound: components within 2^20 (the law allows 2^40).
        let (a, b) = (any_quat_within(MILLION), any_quat_within(MILLION));
        // Precondition: squared norms in [2^-40, 2^40] (no underflow).
        let n = |q: Quat| f64::from(q.norm_squared());
        kani::assume((9.1e-13..=1.1e12).contains(&n(a)) && (9.1e-13..=1.1e12).contains(&n(b)));
        assert_holds(laws::product_norm_is_multiplicative(a, b));
    });
}

/// `|a b| = |a| |b|` with one symbolic component in each factor, its
/// exponent in `[lo, hi]`, beside three concrete ones. Tractable by
/// design (not measured: Kani does not run here): of the 16 products in
/// `a b`, one multiplies two symbolic numbers, the other 15 multiply a
/// symbolic number by a constant or two constants (which CBMC folds); the
/// f64 norms square one symbolic number each. The precondition (squared
/// norms in `[2^-40, 2^80]`) holds by construction, so nothing is assumed.
fn product_norm_with_exponents_in(name: &str, lo: i32, hi: i32) {
    check(name, || {
        let a = Quat::from_wxyz(any_with_exponent_in(lo, hi), 0.75, -0.5, 0.25);
        let b = Quat::from_wxyz(0.5, any_with_exponent_in(lo, hi), 0.25, -0.75);
        assert_holds(laws::product_norm_is_multiplicative(a, b));
    });
}

/// Symbolic components in `[2^-30, 2^-10)`: small beside the constants.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_product_multiplies_norms_small() {
    product_norm_with_exponents_in("quat_product_multiplies_norms_small", -30, -11);
}

/// Symbolic components in `[2^-10, 2^10)`: as large as the constants, where
/// the products' roundings meet.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_product_multiplies_norms_moderate() {
    product_norm_with_exponents_in("quat_product_multiplies_norms_moderate", -10, 9);
}

/// Symbolic components in `[2^10, 2^30)`: they dominate the norms.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_product_multiplies_norms_large() {
    product_norm_with_exponents_in("quat_product_multiplies_norms_large", 10, 29);
}

/// Random test, not a proof target as written: four unconstrained
/// components normalized (four symbolic divisions) and a symbolic vector
/// rotated through 18 products.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn quat_rotation_preserves_length() {
    check("quat_rotation_preserves_length", || {
        let q = any_unit_quat();
        // Solver bound: components within 2^20 (the law allows 2^40).
        let v = any_vec_within(MILLION);
        assert_holds(laws::rotation_preserves_length(q, v));
    });
}

/// Random test, not a proof target: four unconstrained components, four
/// symbolic divisions and both rescalings at once. The three harnesses
/// after it are the law's proof targets, one per branch's range.
#[cfg(all(test, not(kani)))]
#[test]
fn normalize_is_unit_from_subnormal_to_max() {
    check("normalize_is_unit_from_subnormal_to_max", || {
        // Precondition: finite and not zero. No solver bound: normalize's
        // exact power-of-two rescaling is the point.
        let q = any_finite_quat();
        kani::assume(q != Quat::from_wxyz(0.0, 0.0, 0.0, 0.0));
        // The branches of scale_for_squares: the sum of squares underflows
        // (components below 2^-75 or so) or overflows (beyond 2^63).
        let largest = [q.w, q.x, q.y, q.z]
            .iter()
            .fold(0.0f32, |m, c| m.max(c.abs()));
        kani::cover!(largest < 1e-25, "scaled up");
        kani::cover!(largest > 1e20, "scaled down");
        assert_holds(laws::normalize_is_unit(q));
    });
}

/// `normalize` of `(w, x, 0, 0)`: `w` non-zero with its exponent in
/// `[lo, hi]`, `x` anything from zero up to `w`'s range. Tractable by
/// design (not measured): two symbolic components, two concrete zeros
/// (their squares and quotients fold), the square root stubbed by its
/// contract, and an exponent range that fixes which branch of
/// `scale_for_squares` runs, up to the rounding of one sum at its edge.
/// Zero and non-zero are decided by construction: nothing is assumed.
fn normalize_with_exponents_in(name: &str, lo: i32, hi: i32) {
    check(name, || {
        let q = Quat::from_wxyz(
            any_with_exponent_in(lo, hi),
            any_with_exponent_in(-127, hi),
            0.0,
            0.0,
        );
        kani::cover!(q.x.abs() < f32::MIN_POSITIVE, "x zero or subnormal");
        assert_holds(laws::normalize_is_unit(q));
    });
}

/// `w` in `[2^-126, 2^-50)`: the squares underflow and the components are
/// scaled up by 2^100 (a sum just below 2^-100 may round up to it and
/// take the common path).
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn normalize_is_unit_scaled_up() {
    normalize_with_exponents_in("normalize_is_unit_scaled_up", -126, -51);
}

/// `w` in `[2^-50, 2^63)`, `x` below 2^63: the common path, no scaling.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn normalize_is_unit_unscaled() {
    normalize_with_exponents_in("normalize_is_unit_unscaled", -50, 62);
}

/// `w` in `[2^63, f32::MAX]`: the squares overflow and the components are
/// scaled down by 2^-66.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn normalize_is_unit_scaled_down() {
    normalize_with_exponents_in("normalize_is_unit_scaled_down", 63, 127);
}

/// The norm of `pow` on every finite input: zero, subnormal and huge vector
/// parts, `w = +-1`, `w = 0`, non-unit inputs, any finite `alpha`. With
/// atan2, sine and cosine stubbed by contracts that ignore their argument's
/// value, this covers no atan2 edge case and says nothing about the angle:
/// only that any kernels meeting the contracts give a unit result. The
/// angle is `pow_turns_as_the_notes_define`'s (stand-in and fuzz target).
///
/// Random test, not a proof target as written: four unconstrained
/// components, the scaled sum of squares, divisions and the stubbed
/// kernels' contracts (f64 polynomials of symbolic outputs) at once.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // scaled sums of squares over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::atan2, crate::stubs::atan2))]
#[cfg_attr(
    kani,
    kani::stub(rigtform::kani_kernels::sin_cos, crate::stubs::sin_cos)
)]
#[cfg_attr(not(kani), test)]
fn pow_is_unit_for_every_finite_input() {
    check("pow_is_unit_for_every_finite_input", || {
        // Preconditions: finite quaternion and exponent. No solver bound.
        // A choice Kani explores both ways anyway; for the stand-in, half
        // the draws are pure real, whose path random bits almost never take.
        let q = if kani::any() {
            any_finite_quat()
        } else {
            Quat::from_wxyz(any_finite(), 0.0, 0.0, 0.0)
        };
        let alpha = any_finite();
        kani::cover!(q.x == 0.0 && q.y == 0.0 && q.z == 0.0, "pure real");
        kani::cover!(alpha.abs() > f32::MAX / 4.0, "fourth power");
        assert_holds(laws::pow_is_unit(q, alpha));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::atan2, crate::stubs::atan2))]
#[cfg_attr(
    kani,
    kani::stub(rigtform::kani_kernels::sin_cos, crate::stubs::sin_cos)
)]
#[cfg_attr(not(kani), test)]
fn pow_of_non_finite_input_is_nan() {
    check("pow_of_non_finite_input_is_nan", || {
        let q = any_quat_bits();
        let alpha: f32 = kani::any();
        // Precondition: something is NaN or infinite.
        kani::assume(!(q.is_finite() && alpha.is_finite()));
        assert_holds(laws::pow_of_non_finite_is_nan(q, alpha));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn slerp_of_non_finite_input_is_nan() {
    check("slerp_of_non_finite_input_is_nan", || {
        let a = any_quat_bits();
        let b = any_quat_bits();
        let alpha: f32 = kani::any();
        // Precondition: something is NaN or infinite.
        kani::assume(!(a.is_finite() && b.is_finite() && alpha.is_finite()));
        assert_holds(laws::slerp_of_non_finite_is_nan(a, b, alpha));
    });
}

/// Identical, nearly identical, antipodal and opposite pairs are all among
/// the inputs. The real sine and atan2 kernels: the norm depends on their
/// accuracy.
///
/// Random test, not a proof target as written: two normalized symbolic
/// quaternions, the real atan2 and sine polynomials and, beyond 3 pi/4, a
/// branching reduction in integers.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn slerp_is_unit_for_every_finite_alpha() {
    check("slerp_is_unit_for_every_finite_alpha", || {
        // Preconditions: unit inputs, finite alpha. No solver bound.
        let a = any_unit_quat();
        // Half the pairs within 2^-11 rad of each other (a turned about
        // x), so that the small-angle branch is reached.
        let b = if kani::any() {
            any_unit_quat()
        } else {
            (a * Quat::from_rotation_x(any_within(4.9e-4))).normalize()
        };
        let alpha = any_finite();
        let in_plane = (0.0..=1.0).contains(&alpha) && alpha != 0.0;
        // slerp's phi is half the rotation angle: below 2^-12, the
        // small-angle branch (at 0, the early return).
        let angle = a.angle_to(b);
        let close = angle > 0.0 && angle < 4.8e-4;
        kani::cover!(in_plane && !close, "in plane");
        kani::cover!(in_plane && close, "small angle");
        kani::cover!(!(0.0..=1.0).contains(&alpha), "extrapolating");
        assert_holds(laws::slerp_is_unit(a, b, alpha));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn slerp_is_exact_at_zero() {
    check("slerp_is_exact_at_zero", || {
        // Precondition: components within 2^60, so that b a^-1 is finite.
        let (a, b) = (any_quat_within(TWO_TO_60), any_quat_within(TWO_TO_60));
        assert_holds(laws::slerp_is_exact_at_zero(a, b));
    });
}

/// The short way: `b` and `-b` give one path. Heavy for a solver (two
/// slerps of symbolic unit inputs, real atan2 and sines); its point is
/// `cn`, which is exact sign arithmetic.
///
/// Random test, not a proof target as written: two slerps of two normalized
/// symbolic quaternions with the real kernels.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn slerp_takes_the_short_way() {
    check("slerp_takes_the_short_way", || {
        // Preconditions: unit inputs, finite alpha.
        let (a, b) = (any_unit_quat(), any_unit_quat());
        let alpha = any_finite();
        kani::cover!(a.dot(b) < 0.0, "b on the far side");
        assert_holds(laws::slerp_takes_the_short_way(a, b, alpha));
    });
}

/// Constant angular velocity: the turn from `a` is `alpha` times the angle
/// to `b`. Heavy for a solver (three angles through atan2 and square
/// roots of symbolic unit inputs): a stand-in test until it is split.
///
/// Random test, not a proof target as written: three angles through the
/// real atan2 and stubbed square roots of two normalized symbolic
/// quaternions.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn slerp_turns_by_alpha_times_the_angle() {
    check("slerp_turns_by_alpha_times_the_angle", || {
        // Preconditions: unit inputs, alpha in [0, 1].
        let (a, b) = (any_unit_quat(), any_unit_quat());
        let alpha = kani::any_where(|t: &f32| (0.0..=1.0).contains(t));
        assert_holds(laws::slerp_turns_by_alpha_times_the_angle(a, b, alpha));
    });
}

/// `pow` turns as the notes define it, against the notes' formula in
/// `f64` (libm's sines and arctangent): not a proof target (Kani would
/// have to reason through libm's f64 kernels), a stand-in test only; the
/// `pow` fuzz target checks the same law.
#[cfg(all(test, not(kani)))]
#[test]
fn pow_turns_as_the_notes_define() {
    check("pow_turns_as_the_notes_define", || {
        // Preconditions: finite quaternion, alpha in [-4, 4].
        let q = any_finite_quat();
        let alpha = any_within(4.0);
        kani::cover!(q.w < 0.0, "w < 0");
        assert_holds(laws::pow_turns_as_the_notes_define(q, alpha));
    });
}

/// Random test, not a proof target as written: two normalized symbolic
/// quaternions, their weighted sum and a third normalization.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn nlerp_is_unit() {
    check("nlerp_is_unit", || {
        // Preconditions: unit inputs, alpha in [0, 1].
        let (a, b) = (any_unit_quat(), any_unit_quat());
        let alpha = kani::any_where(|t: &f32| (0.0..=1.0).contains(t));
        assert_holds(laws::nlerp_is_unit(a, b, alpha));
    });
}

/// Random test, not a proof target as written: three normalized symbolic
/// quaternions, three symbolic weights and a normalization of their sum.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // three entries, and normalize's four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn blend_of_three_is_unit_or_identity() {
    check("blend_of_three_is_unit_or_identity", || {
        // Preconditions: unit quaternions, finite weights within 2^60;
        // solver bound: three entries, weights within 2^20.
        let entries = [
            (any_unit_quat(), any_within(MILLION)),
            (any_unit_quat(), any_within(MILLION)),
            (any_unit_quat(), any_within(MILLION)),
        ];
        kani::cover!(Quat::blend(&entries) == Quat::IDENTITY, "identity");
        assert_holds(laws::blend_is_unit_or_identity(&entries));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(not(kani), test)]
fn quat_inverse_is_an_involution() {
    check("quat_inverse_is_an_involution", || {
        // No assumption: every bit pattern, NaN payloads included.
        let q = any_quat_bits();
        assert_holds(laws::inverse_is_an_involution(q));
    });
}

/// Random test, not a proof target: four unconstrained components within
/// 2^60 and their 16 products at once. The three harnesses after it are
/// the law's proof targets.
#[cfg(all(test, not(kani)))]
#[test]
fn quat_times_inverse_is_real() {
    check("quat_times_inverse_is_real", || {
        // Precondition: components within 2^60 (no overflow).
        let q = any_quat_within(TWO_TO_60);
        assert_holds(laws::product_with_inverse_is_real(q));
    });
}

/// `q q^-1` for `q = (w, x, 0.375, -1.25)`, `w` and `x` with exponents in
/// `[lo, hi]`. Tractable by design (not measured): two symbolic
/// components; `q^-1` only flips signs (exact); of the 16 products in
/// `q q^-1`, four multiply two symbolic numbers and the rest a symbolic
/// number by a constant or two constants; the law squares in f64 what
/// comes out, with no division and no square root. The precondition
/// (components within 2^60) holds by construction.
fn product_with_inverse_with_exponents_in(name: &str, lo: i32, hi: i32) {
    check(name, || {
        let q = Quat::from_wxyz(
            any_with_exponent_in(lo, hi),
            any_with_exponent_in(lo, hi),
            0.375,
            -1.25,
        );
        assert_holds(laws::product_with_inverse_is_real(q));
    });
}

/// `w`, `x` in `[2^-60, 2^-20)`: the constants carry the norm.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_times_inverse_is_real_small() {
    product_with_inverse_with_exponents_in("quat_times_inverse_is_real_small", -60, -21);
}

/// `w`, `x` in `[2^-20, 2^20)`: every component counts.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_times_inverse_is_real_moderate() {
    product_with_inverse_with_exponents_in("quat_times_inverse_is_real_moderate", -20, 19);
}

/// `w`, `x` in `[2^20, 2^60)`: the constants round away.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::solver(kissat))]
#[cfg_attr(not(kani), test)]
fn quat_times_inverse_is_real_large() {
    product_with_inverse_with_exponents_in("quat_times_inverse_is_real_large", 20, 59);
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(not(kani), test)]
fn cn_gives_non_negative_w_and_the_same_rotation() {
    check("cn_gives_non_negative_w_and_the_same_rotation", || {
        // No assumption: every bit pattern.
        let q = any_quat_bits();
        assert_holds(laws::cn_gives_non_negative_w_and_the_same_rotation(q));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(not(kani), test)]
fn catmull_rom_is_the_key_at_and_beyond_each_key() {
    check("catmull_rom_is_the_key_at_and_beyond_each_key", || {
        // No assumption on the keys: every bit pattern. What keeps this
        // tractable: on this path the spline computes nothing from the
        // keys (it only picks one), so the solver meets no slerp, power or
        // kernel, only comparisons of t, its cast to an index and one
        // exact subtraction (t minus its own whole part); twelve symbolic
        // components are merely copied.
        let keys = [any_quat_bits(), any_quat_bits(), any_quat_bits()];
        // Solver bound: up to three keys, none included.
        let n = kani::any::<u32>() % 4;
        let keys = keys.get(..n as usize).unwrap_or(&keys);
        let t: f32 = kani::any();
        // Precondition: t NaN, a whole number, or outside (0, n - 1). With
        // at most three keys, the whole numbers inside are 1 alone.
        kani::assume(t.is_nan() || t == 1.0 || !(0.0 < t && t < n as f32 - 1.0));
        assert_holds(laws::catmull_rom_is_the_key_at_and_beyond_each_key(keys, t));
    });
}

/// A rigid body transform with a unit rotation and a translation within
/// 2^20 (solver bound; the laws allow 2^40 or 2^20).
fn any_rig_tform() -> RigTForm {
    RigTForm::new(any_vec_within(MILLION), any_unit_quat())
}

/// Random test, not a proof target as written: a normalized symbolic
/// rotation and a symbolic translation rotated twice.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rigtform_times_inverse_is_identity() {
    check("rigtform_times_inverse_is_identity", || {
        assert_holds(laws::rigid_product_with_inverse_is_identity(any_rig_tform()));
    });
}

/// Random test, not a proof target as written: a normalized symbolic
/// rotation and a symbolic translation rotated twice.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rigtform_inverse_is_an_involution() {
    check("rigtform_inverse_is_an_involution", || {
        assert_holds(laws::rigid_inverse_is_an_involution(any_rig_tform()));
    });
}

/// Random test, not a proof target as written: a normalized symbolic
/// rotation, its matrix and the general matrix inverse (cofactors and a
/// division).
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(17))] // the law compares 16 matrix entries
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rigtform_inverse_agrees_with_matrix_inverse() {
    check("rigtform_inverse_agrees_with_matrix_inverse", || {
        assert_holds(laws::rigid_inverse_matches_matrix_inverse(any_rig_tform()));
    });
}

/// Random test, not a proof target as written: a normalized symbolic
/// rotation, its matrix and a symbolic vector moved both ways.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rigtform_matrix_moves_points_as_the_transform() {
    check("rigtform_matrix_moves_points_as_the_transform", || {
        let a = any_rig_tform();
        // Precondition: w is 0 (a vector) or 1 (a point).
        let w = if kani::any::<bool>() { 1.0 } else { 0.0 };
        let v = any_vec_within(MILLION);
        let c = Cvec4::new(v.x, v.y, v.z, w);
        assert_holds(laws::rigid_matrix_moves_points_as_the_transform(a, c));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rigtform_interpolate_is_exact_at_zero() {
    check("rigtform_interpolate_is_exact_at_zero", || {
        // Precondition: components within 2^60.
        let a = RigTForm::new(any_vec_within(TWO_TO_60), any_quat_within(TWO_TO_60));
        let b = RigTForm::new(any_vec_within(TWO_TO_60), any_quat_within(TWO_TO_60));
        assert_holds(laws::interpolate_is_exact_at_zero(a, b));
    });
}

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(17))] // sixteen entries drawn, four columns checked
#[cfg_attr(not(kani), test)]
fn matrix_inverse_is_none_or_finite() {
    check("matrix_inverse_is_none_or_finite", || {
        // No assumption: every bit pattern of every entry.
        let m = Matrix4::from_cols_array(&core::array::from_fn(|_| kani::any()));
        kani::cover!(m.inverse().is_some(), "Some");
        kani::cover!(m.inverse().is_none(), "None");
        assert_holds(laws::matrix_inverse_is_none_or_finite(m));
    });
}

/// Any of the 24 orders of Euler angles.
fn any_euler_order() -> EulerRot {
    let i = kani::any::<u32>() % EulerRot::ALL.len() as u32;
    EulerRot::ALL[i as usize]
}

/// Random test, not a proof target as written: a normalized symbolic
/// quaternion, two `hypotf`s and three atan2 polynomials one way, and the
/// sines and cosines of three symbolic angles back.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // the scaled sum of squares over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn euler_angles_give_back_the_rotation() {
    check("euler_angles_give_back_the_rotation", || {
        let order = any_euler_order();
        // Precondition: unit. Half the draws at gimbal lock (b = +-pi/2,
        // any a and c), which random unit quaternions all but never meet.
        let q = if kani::any() {
            any_unit_quat()
        } else {
            let lock = if kani::any() { FRAC_PI_2 } else { -FRAC_PI_2 };
            Quat::from_euler(order, any_within(PI), lock, any_within(PI))
        };
        let (_, b, c) = q.to_euler(order);
        // At the lock to_euler puts the whole turn in a and returns c = 0.
        kani::cover!(b.abs() == FRAC_PI_2 && c == 0.0, "gimbal lock");
        kani::cover!(b.abs() < 1.5, "away from the lock");
        kani::cover!(q.w < 0.0, "w < 0 (cn first)");
        assert_holds(laws::euler_angles_give_back_the_rotation(q, order));
    });
}

/// Random test, not a proof target as written: a normalized symbolic
/// quaternion, its matrix (products of symbolic components) and Shepperd's
/// four-way branch and normalization back.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over four components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn from_matrix_inverts_from_quat() {
    check("from_matrix_inverts_from_quat", || {
        // Precondition: unit. Half the draws are half turns (w = 0), whose
        // trace is -1, so that x, y or z is the largest of Shepperd's four.
        let q = if kani::any() {
            any_unit_quat()
        } else {
            let v = any_vec_within(MILLION);
            // Precondition of normalize_is_unit: not zero.
            kani::assume(v != Cvec3::ZERO);
            Quat::from_wxyz(0.0, v.x, v.y, v.z).normalize()
        };
        // The branch from_matrix takes: the largest of four times the
        // squares of w, x, y and z, read from the matrix as it reads them.
        let m = Matrix4::from_quat(q).to_cols_array();
        let (m00, m11, m22) = (m[0], m[5], m[10]);
        let w4 = 1.0 + m00 + m11 + m22;
        let x4 = 1.0 + m00 - m11 - m22;
        let y4 = 1.0 - m00 + m11 - m22;
        let z4 = 1.0 - m00 - m11 + m22;
        let w_branch = w4 >= x4 && w4 >= y4 && w4 >= z4;
        let x_branch = !w_branch && x4 >= y4 && x4 >= z4;
        let y_branch = !w_branch && !x_branch && y4 >= z4;
        let z_branch = !w_branch && !x_branch && !y_branch;
        kani::cover!(w_branch, "w largest");
        kani::cover!(x_branch && q.w == 0.0, "x largest, half turn");
        kani::cover!(y_branch && q.w == 0.0, "y largest, half turn");
        kani::cover!(z_branch && q.w == 0.0, "z largest, half turn");
        assert_holds(laws::from_matrix_inverts_from_quat(q));
    });
}

/// Random test, not a proof target as written: two symbolic directions
/// normalized (six symbolic divisions), their cross product, and a
/// normalization or a perpendicular built by another cross product.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))] // normalize maps over the components
#[cfg_attr(kani, kani::stub(rigtform::kani_kernels::sqrt, crate::stubs::sqrt))]
#[cfg_attr(not(kani), test)]
fn rotation_arc_takes_from_to_to() {
    check("rotation_arc_takes_from_to_to", || {
        // Solver bound: components within 2^20 (the law allows squared
        // lengths up to 2^80).
        let from = any_vec_within(MILLION);
        // A third of the draws exactly opposite (-2 from, an exact
        // scaling: the cross product of the two is exactly zero and the
        // unit directions are negatives of each other to rounding, the
        // branch of a half turn about a perpendicular axis), a third
        // nearly opposite (one component nudged), which random directions
        // all but never are.
        let to = match kani::any::<u32>() % 3 {
            0 => any_vec_within(MILLION),
            1 => from * -2.0,
            _ => from * -2.0 + Cvec3::new(any_within(1e-3), 0.0, 0.0),
        };
        // Precondition: squared lengths in [2^-40, 2^80].
        let moderate = |v: Cvec3| (9.094_947e-13..=1.208_925_8e24).contains(&v.norm_squared());
        kani::assume(moderate(from) && moderate(to));
        let dot = from.dot(to);
        kani::cover!(from.cross(to) == Cvec3::ZERO && dot < 0.0, "opposite");
        kani::cover!(from.cross(to) != Cvec3::ZERO && dot < 0.0, "far side");
        kani::cover!(dot >= 0.0, "near side");
        assert_holds(laws::rotation_arc_takes_from_to_to(from, to));
    });
}

/// STEP samplers only pick keys: at each key's time, between keys and
/// beyond both ends, a key bit for bit. Every finite bit pattern of up to
/// three keys, every strictly increasing finite key times, every time but
/// NaN. What keeps it tractable: on STEP's path the sampler compares times
/// and computes one subtraction and one division of finite times (the
/// segment's `u`, unused), and copies a key.
#[cfg_attr(kani, kani::proof)]
#[cfg_attr(kani, kani::unwind(5))]
#[cfg_attr(not(kani), test)]
fn step_sampler_copies_its_keys() {
    use rigtform::animation::{Interpolation, Sampler};
    check("step_sampler_copies_its_keys", || {
        let keys = [any_quat_bits(), any_quat_bits(), any_quat_bits()];
        let times: [f32; 3] = [kani::any(), kani::any(), kani::any()];
        // Solver bound: one to three keys.
        let n = (kani::any::<u32>() % 3 + 1) as usize;
        let (times, keys) = (&times[..n], &keys[..n]);
        // Precondition: a channel Sampler::new accepts.
        kani::assume(Sampler::new(Interpolation::Step, times, keys).is_ok());
        let t: f32 = kani::any();
        // Precondition: a time that is not NaN.
        kani::assume(!t.is_nan());
        kani::cover!(
            n == 3 && times[0] < t && t < times[2] && t != times[1],
            "between keys"
        );
        kani::cover!(t < times[0], "before the first key");
        kani::cover!(t > times[n - 1], "after the last key");
        assert_holds(laws::sampler_hits_its_keys(
            Interpolation::Step,
            times,
            keys,
        ));
        assert_holds(laws::step_sampler_is_constant_between_keys(times, keys, t));
    });
}
