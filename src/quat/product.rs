//! The Hamilton product `a * b`: the notes' formula, and on x86-64 the
//! same sums four lanes at a time.
//!
//! Both evaluate every component as `a.w b_i ± a.x b_j ± a.y b_k ±
//! a.z b_l`, left to right, so they give the same bits: changing the sign
//! of a product is exact, and `s - p` is `s + (-p)` in IEEE 754, NaN and
//! signed zeros included (`by_lanes_is_by_formula_bit_for_bit`).

use super::Quat;

/// `a * b`: [`by_lanes`] on x86-64 with SSE, [`by_formula`] elsewhere and
/// under Kani (whose harnesses then need no model of the intrinsics).
#[inline(always)]
pub(super) fn hamilton(a: Quat, b: Quat) -> Quat {
    #[cfg(x86_sse_lanes)]
    return by_lanes(a, b);
    #[cfg(not(x86_sse_lanes))]
    return by_formula(a, b);
}

/// The notes' `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`, written out one
/// component at a time, the terms in the order of `a`'s components.
#[cfg(any(test, not(x86_sse_lanes)))]
#[inline(always)]
fn by_formula(a: Quat, b: Quat) -> Quat {
    Quat::from_wxyz(
        a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
        a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
        a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
        a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
    )
}

/// [`by_formula`] by columns in SSE registers, lanes in the order of the
/// memory layout, `x, y, z, w`: `a.w [bx by bz bw]`, plus
/// `a.x [bw -bz by -bx]`, plus `a.y [bz bw -bx -by]`, plus
/// `a.z [-by bx bw -bz]`, each column a shuffle of `b` with sign bits
/// flipped by an exclusive or. One of the few places of the crate's
/// `unsafe` code (src/lib.rs lists them).
///
/// The compiler does vectorize [`by_formula`] too, but it folds each
/// negated term into a subtraction and builds the sign pattern from
/// additions, subtractions and lane blends, about ten instructions more
/// per product than these columns.
#[cfg(x86_sse_lanes)]
#[allow(unsafe_code)]
#[inline(always)]
fn by_lanes(a: Quat, b: Quat) -> Quat {
    use core::arch::x86_64::{
        _mm_add_ps, _mm_cvtss_f32, _mm_mul_ps, _mm_set1_ps, _mm_set_ps, _mm_shuffle_ps, _mm_xor_ps,
    };
    // SAFETY: every intrinsic here needs SSE, which this function is
    // compiled only with (`target_feature = "sse"`, enabled on every
    // x86-64 target but the soft-float kernel ones). They work on
    // registers only, reading and writing no memory, and SSE arithmetic
    // cannot fault with the default MXCSR (exceptions masked).
    unsafe {
        // `_mm_set_ps` takes the lanes from the highest: lane 0 is `x`, as
        // in memory.
        let b_xyzw = _mm_set_ps(b.w, b.z, b.y, b.x);
        // `_mm_shuffle_ps::<imm>`: lane i takes lane (imm >> 2i) & 3.
        let b_wzyx = _mm_shuffle_ps::<0b00_01_10_11>(b_xyzw, b_xyzw);
        let b_zwxy = _mm_shuffle_ps::<0b01_00_11_10>(b_xyzw, b_xyzw);
        let b_yxwz = _mm_shuffle_ps::<0b10_11_00_01>(b_xyzw, b_xyzw);
        // -0.0 in a lane flips that lane's sign bit.
        let signs_x = _mm_set_ps(-0.0, 0.0, -0.0, 0.0);
        let signs_y = _mm_set_ps(-0.0, -0.0, 0.0, 0.0);
        let signs_z = _mm_set_ps(-0.0, 0.0, 0.0, -0.0);
        let mut r = _mm_mul_ps(_mm_set1_ps(a.w), b_xyzw);
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.x), _mm_xor_ps(b_wzyx, signs_x)));
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.y), _mm_xor_ps(b_zwxy, signs_y)));
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.z), _mm_xor_ps(b_yxwz, signs_z)));
        Quat::from_xyzw(
            _mm_cvtss_f32(r),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(r, r)),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b10_10_10_10>(r, r)),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b11_11_11_11>(r, r)),
        )
    }
}

#[cfg(all(test, x86_sse_lanes))]
mod tests {
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
    fn by_lanes_is_by_formula_bit_for_bit() {
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
            let (lanes, formula) = (by_lanes(a, b), by_formula(a, b));
            assert!(
                same(lanes, formula),
                "{a:?} * {b:?}: {lanes:?} against {formula:?}"
            );
        }
    }
}
