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
//! The square root is stubbed by its contract wherever a harness reaches
//! it (`src/stubs.rs`): a weaker statement than the library's own square
//! root under `cfg(kani)` (the correctly rounded one, described exactly),
//! so each proof covers any root within the contract. `pow` also gets its
//! sine, cosine and atan2 stubbed: its non-finite input gives NaN whatever
//! the kernels return within their contracts (which
//! `tests/kernel_contracts.rs` checks the crate's kernels meet).
//!
//! Only harnesses Kani is likely to finish are here. The harnesses of
//! exact, bit-level laws (`inv`, `cn`, NaN out for NaN in, exactness at
//! `alpha = 0`, `None` or finite for the matrix inverse, the spline's and
//! the STEP sampler's keys) take paths of comparisons, sign operations and
//! early returns, with symbolic arithmetic only where a matrix is
//! invertible. Three error-bound laws are split for the solver, one
//! harness per exponent range (`quat_product_multiplies_norms_*`,
//! `normalize_is_unit_*`, `quat_times_inverse_is_real_*`): one or two
//! symbolic components built from bits in a fixed exponent range, the
//! others concrete, nothing assumed, and a comment on each saying what
//! keeps it small. None of them has been run under Kani, so their
//! tractability is a design argument, not a measured time. The laws whose
//! harnesses would hand the solver several symbolic divisions, square
//! roots and polynomials at once (the norms of `pow`, `slerp`, `nlerp`
//! and `blend`, rotation, the rigid-body identities, Euler angles,
//! `from_matrix`, `from_rotation_arc`, and the full ranges of the split
//! laws) are proptest properties of the library's `tests/properties.rs`
//! instead, on the same kinds of draws (edge values, components from
//! subnormal to huge normalized, the rare branches); two random tests stay
//! here because no property repeats them (`normalize_is_unit_from_subnormal_to_max`
//! and `pow_turns_as_the_notes_define`).
//!
//! `kani::cover!` marks the branches a law is about; the stand-in fails a
//! harness whose cover no kept draw met, and prints how many met each.

#[cfg(not(kani))]
use crate::kani_stand_in as kani;
use crate::laws::{self, assert_holds};
use rigtform::{Cvec3, Matrix4, Quat, RigTForm};

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

/// Any finite `f32` (for the stand-in tests only).
#[cfg(not(kani))]
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

/// Any finite quaternion (for the stand-in tests only).
#[cfg(not(kani))]
fn any_finite_quat() -> Quat {
    Quat::from_wxyz(any_finite(), any_finite(), any_finite(), any_finite())
}

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

#[cfg_attr(kani, kani::proof)]
#[cfg_attr(not(kani), test)]
fn quat_inverse_is_an_involution() {
    check("quat_inverse_is_an_involution", || {
        // No assumption: every bit pattern, NaN payloads included.
        let q = any_quat_bits();
        assert_holds(laws::inverse_is_an_involution(q));
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
