//! The evaluations that keep a quaternion's four components together, in
//! x86-64's SSE registers, lanes in the order of the memory layout,
//! `x, y, z, w`: the same operations in the same order as
//! `quat/scalar.rs`, four lanes at a time, so the same bits (the tests
//! below hold the two together). The backend is chosen where `quat.rs`
//! declares it; both files have the same functions. One of the few places
//! of the crate's `unsafe` code (src/lib.rs lists them).
//!
//! SAFETY, for every `unsafe` block of this file: every intrinsic here
//! needs SSE, which this module is compiled only with (`target_feature =
//! "sse"`, enabled on every x86-64 target but the soft-float kernel ones);
//! the loads and stores read and write the 16 bytes of a `Quat`,
//! `repr(C)` of four f32, through a reference to it (`loadu` and `storeu`
//! need no alignment); SSE arithmetic cannot fault with the default MXCSR
//! (exceptions masked).

#![allow(unsafe_code)]

use super::Quat;
use crate::float;
use core::arch::x86_64::{
    __m128, _mm_add_ps, _mm_add_ss, _mm_and_ps, _mm_cvtss_f32, _mm_div_ps, _mm_loadu_ps,
    _mm_movehl_ps, _mm_mul_ps, _mm_set1_ps, _mm_set_ps, _mm_shuffle_ps, _mm_sqrt_ps, _mm_storeu_ps,
    _mm_xor_ps,
};

/// The quaternion in one register, `x` in lane 0.
#[inline(always)]
fn load(q: &Quat) -> __m128 {
    unsafe { _mm_loadu_ps(core::ptr::from_ref(q).cast()) }
}

/// The quaternion of the register's lanes, lane 0 its `x`.
#[inline(always)]
fn store(v: __m128) -> Quat {
    let mut q = Quat::NAN;
    unsafe { _mm_storeu_ps(core::ptr::from_mut(&mut q).cast(), v) };
    q
}

/// `a * b` by columns, lanes `x, y, z, w`: `a.w [bx by bz bw]`, plus
/// `a.x [bw -bz by -bx]`, plus `a.y [bz bw -bx -by]`, plus
/// `a.z [-by bx bw -bz]`, each column a shuffle of `b` with sign bits
/// flipped by an exclusive or: every component `a.w b_i ± a.x b_j ±
/// a.y b_k ± a.z b_l`, left to right, as `quat/scalar.rs` sums it
/// (changing the sign of a product is exact, and `s - p` is `s + (-p)` in
/// IEEE 754, NaN and signed zeros included). The compiler vectorizes the
/// scalar formula too, but it folds each negated term into a subtraction
/// and builds the sign pattern from additions, subtractions and lane
/// blends, about ten instructions more per product than these columns.
#[inline(always)]
pub(super) fn hamilton(a: Quat, b: Quat) -> Quat {
    let (a, b_xyzw) = (load(&a), load(&b));
    unsafe {
        // `_mm_shuffle_ps::<imm>`: lane i takes lane (imm >> 2i) & 3.
        let b_wzyx = _mm_shuffle_ps::<0b00_01_10_11>(b_xyzw, b_xyzw);
        let b_zwxy = _mm_shuffle_ps::<0b01_00_11_10>(b_xyzw, b_xyzw);
        let b_yxwz = _mm_shuffle_ps::<0b10_11_00_01>(b_xyzw, b_xyzw);
        // -0.0 in a lane flips that lane's sign bit.
        let signs_x = _mm_set_ps(-0.0, 0.0, -0.0, 0.0);
        let signs_y = _mm_set_ps(-0.0, -0.0, 0.0, 0.0);
        let signs_z = _mm_set_ps(-0.0, 0.0, 0.0, -0.0);
        let mut r = _mm_mul_ps(_mm_shuffle_ps::<0b11_11_11_11>(a, a), b_xyzw);
        let x = _mm_shuffle_ps::<0b00_00_00_00>(a, a);
        r = _mm_add_ps(r, _mm_mul_ps(x, _mm_xor_ps(b_wzyx, signs_x)));
        let y = _mm_shuffle_ps::<0b01_01_01_01>(a, a);
        r = _mm_add_ps(r, _mm_mul_ps(y, _mm_xor_ps(b_zwxy, signs_y)));
        let z = _mm_shuffle_ps::<0b10_10_10_10>(a, a);
        r = _mm_add_ps(r, _mm_mul_ps(z, _mm_xor_ps(b_yxwz, signs_z)));
        store(r)
    }
}

/// `p . q` summed in pairs, `(x x' + z z') + (y y' + w w')`, in lane 0.
#[inline(always)]
fn dot_in_pairs(p: __m128, q: __m128) -> __m128 {
    unsafe {
        let products = _mm_mul_ps(p, q);
        // [x x' + z z', y y' + w w', ...]
        let halves = _mm_add_ps(products, _mm_movehl_ps(products, products));
        _mm_add_ss(halves, _mm_shuffle_ps::<0b01_01_01_01>(halves, halves))
    }
}

/// [`Quat::nlerp`], as `quat/scalar.rs` evaluates it: the sign of the dot
/// product on every lane of `b`, the lerp, and the division by the norm.
#[inline(always)]
pub(super) fn nlerp(a: Quat, b: Quat, alpha: f32) -> Quat {
    let (a, b) = (load(&a), load(&b));
    unsafe {
        let dot = dot_in_pairs(a, b);
        let sign = _mm_and_ps(_mm_shuffle_ps::<0>(dot, dot), _mm_set1_ps(-0.0));
        let b = _mm_xor_ps(b, sign);
        let lerp = _mm_add_ps(
            _mm_mul_ps(_mm_set1_ps(1.0 - alpha), a),
            _mm_mul_ps(_mm_set1_ps(alpha), b),
        );
        let sum = _mm_cvtss_f32(dot_in_pairs(lerp, lerp));
        if float::needs_no_rescaling(sum) {
            return store(_mm_div_ps(lerp, _mm_sqrt_ps(_mm_set1_ps(sum))));
        }
        store(lerp).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::super::scalar;
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Both NaN, or the same bits.
    fn same(p: Quat, q: Quat) -> bool {
        p.to_array()
            .iter()
            .zip(q.to_array())
            .all(|(a, b)| (a.is_nan() && b.is_nan()) || a.to_bits() == b.to_bits())
    }

    #[test]
    fn the_product_in_lanes_is_the_formulas_bit_for_bit() {
        let q = Quat::from_wxyz(0.0, 1.0, 2.0, 3.0);
        assert!(same(q, q) && same(Quat::NAN, Quat::NAN));
        assert!(!same(q, Quat::from_wxyz(-0.0, 1.0, 2.0, 3.0)));
        assert!(!same(
            Quat::NAN,
            Quat::from_wxyz(f32::NAN, 1.0, f32::NAN, f32::NAN)
        ));
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f32::MIN_POSITIVE,
            -1e-40,
            f32::MAX,
            -f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let component = |rng: &mut rand::rngs::StdRng| match rng.random_range(0..4) {
            0 => special[rng.random_range(0..special.len())],
            1 => f32::from_bits(rng.random()),
            _ => rng.random_range(-1.0f32..1.0),
        };
        // Fewer draws under Miri, which interprets every instruction.
        let draws = if cfg!(miri) { 500 } else { 200_000 };
        for _ in 0..draws {
            let mut q = || {
                Quat::from_wxyz(
                    component(&mut rng),
                    component(&mut rng),
                    component(&mut rng),
                    component(&mut rng),
                )
            };
            let (a, b) = (q(), q());
            let (lanes, formula) = (hamilton(a, b), scalar::hamilton(a, b));
            assert!(
                same(lanes, formula),
                "{a:?} * {b:?}: {lanes:?} against {formula:?}"
            );
        }
    }

    /// nlerp in lanes is the scalar evaluation's, bit for bit: random unit
    /// pairs (both signs of the dot product), pairs off unit norm, pairs
    /// whose lerp needs rescaling, and NaN.
    #[test]
    fn nlerp_in_lanes_is_the_scalar_ones_bit_for_bit() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(8);
        let draws = if cfg!(miri) { 200 } else { 200_000 };
        for i in 0..draws {
            let (a, b) = (
                crate::test_draws::unit_quat(&mut rng),
                crate::test_draws::unit_quat(&mut rng),
            );
            let scale = match i % 5 {
                0 => 1e-30,
                1 => 1e25,
                2 => rng.random_range(0.5..2.0f32),
                _ => 1.0,
            };
            let b = b.map(|c| c * scale);
            let alpha = match i % 7 {
                0 => rng.random_range(-3.0..4.0f32),
                1 => f32::NAN,
                _ => rng.random_range(0.0..=1.0f32),
            };
            let (lanes, plain) = (nlerp(a, b, alpha), scalar::nlerp(a, b, alpha));
            assert!(
                same(lanes, plain),
                "{a:?} {b:?} {alpha}: {lanes:?} against {plain:?}"
            );
        }
    }
}
