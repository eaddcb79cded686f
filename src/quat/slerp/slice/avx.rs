//! [`Isa`] for x86-64 with AVX: eight f32 lanes to a register, four f64.
//! Each operation is one intrinsic of `core::arch` (a few for the loads,
//! stores and conversions).

use super::steps::Isa;
use super::Slerped;
use crate::Quat;
use core::arch::x86_64::{
    __m128, __m256, __m256d, _mm256_add_pd, _mm256_add_ps, _mm256_and_ps, _mm256_andnot_ps,
    _mm256_castpd_ps, _mm256_castps128_ps256, _mm256_castps256_ps128, _mm256_castps_pd,
    _mm256_cmp_pd, _mm256_cvtpd_ps, _mm256_cvtps_pd, _mm256_div_pd, _mm256_extractf128_ps,
    _mm256_insertf128_ps, _mm256_max_pd, _mm256_movemask_pd, _mm256_mul_pd, _mm256_mul_ps,
    _mm256_or_ps, _mm256_set1_pd, _mm256_set1_ps, _mm256_setzero_ps, _mm256_sub_pd,
    _mm256_unpackhi_pd, _mm256_unpackhi_ps, _mm256_unpacklo_pd, _mm256_unpacklo_ps, _mm_loadu_ps,
    _mm_storeu_ps, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_NGT_UQ,
};

/// x86-64 with AVX (compiled only where `target_feature = "avx"`).
pub(super) struct Avx;

/// Two quaternions' registers, the first in the low half.
#[allow(unsafe_code)]
#[inline(always)]
fn pair(low: __m128, high: __m128) -> __m256 {
    // SAFETY: AVX, which this module is compiled only with; registers only.
    unsafe { _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(low), high) }
}

/// The quaternion at `q` in a register, `x` in lane 0.
#[allow(unsafe_code)]
#[inline(always)]
fn load_quat(q: &Quat) -> __m128 {
    // SAFETY: SSE, which every AVX target has; `Quat` is `repr(C)` of four
    // f32, 16 bytes at `q` (`loadu` needs no alignment).
    unsafe { _mm_loadu_ps((q as *const Quat).cast::<f32>()) }
}

/// The register's lanes to the quaternion at `q`, lane 0 to `x`.
#[allow(unsafe_code)]
#[inline(always)]
fn store_quat(v: __m128, q: &mut Quat) {
    // SAFETY: as in `load_quat`; the 16 bytes are `q`'s, borrowed mutably.
    unsafe { _mm_storeu_ps((q as *mut Quat).cast::<f32>(), v) }
}

/// The operations, each one of the AVX intrinsics (SAFETY of every
/// `unsafe` block below: AVX, which this module is compiled only with;
/// registers only; AVX arithmetic cannot fault with the default MXCSR,
/// exceptions masked).
#[allow(unsafe_code)]
impl Isa for Avx {
    type F = __m256;
    type D = __m256d;
    const LANES: usize = 8;
    // Unpacking within 128-bit halves: pairs 0, 2, 4, 6 in the low half.
    const PAIR_OF_LANE: [usize; 8] = [0, 2, 4, 6, 1, 3, 5, 7];

    #[inline(always)]
    fn splat(x: f32) -> __m256 {
        unsafe { _mm256_set1_ps(x) }
    }
    #[inline(always)]
    fn splat_d(x: f64) -> __m256d {
        unsafe { _mm256_set1_pd(x) }
    }
    #[inline(always)]
    fn add(a: __m256, b: __m256) -> __m256 {
        unsafe { _mm256_add_ps(a, b) }
    }
    #[inline(always)]
    fn mul(a: __m256, b: __m256) -> __m256 {
        unsafe { _mm256_mul_ps(a, b) }
    }
    #[inline(always)]
    fn and(a: __m256, b: __m256) -> __m256 {
        unsafe { _mm256_and_ps(a, b) }
    }
    #[inline(always)]
    fn and_not(a: __m256, b: __m256) -> __m256 {
        unsafe { _mm256_andnot_ps(a, b) }
    }
    #[inline(always)]
    fn or(a: __m256, b: __m256) -> __m256 {
        unsafe { _mm256_or_ps(a, b) }
    }
    #[inline(always)]
    fn add_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_add_pd(a, b) }
    }
    #[inline(always)]
    fn sub_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_sub_pd(a, b) }
    }
    #[inline(always)]
    fn mul_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_mul_pd(a, b) }
    }
    #[inline(always)]
    fn div_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_div_pd(a, b) }
    }
    #[inline(always)]
    fn gt_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_cmp_pd::<_CMP_GT_OQ>(a, b) }
    }
    #[inline(always)]
    fn le_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_cmp_pd::<_CMP_LE_OQ>(a, b) }
    }
    #[inline(always)]
    fn not_gt_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_cmp_pd::<_CMP_NGT_UQ>(a, b) }
    }
    #[inline(always)]
    fn max_d(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_max_pd(a, b) }
    }
    #[inline(always)]
    fn bits_d(a: __m256d) -> u32 {
        unsafe { _mm256_movemask_pd(a) as u32 }
    }
    #[inline(always)]
    fn halves(a: __m256) -> [__m256d; 2] {
        unsafe {
            [
                _mm256_cvtps_pd(_mm256_castps256_ps128(a)),
                _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(a)),
            ]
        }
    }
    #[inline(always)]
    fn join(low: __m256d, high: __m256d) -> __m256 {
        unsafe { pair(_mm256_cvtpd_ps(low), _mm256_cvtpd_ps(high)) }
    }
    #[inline(always)]
    fn load<T: Slerped>(values: &[T]) -> [__m256; 4] {
        // [q0 | q1], [q2 | q3], [q4 | q5], [q6 | q7] to one register per
        // component, lanes [0 2 4 6 | 1 3 5 7].
        let mut r = [unsafe { _mm256_setzero_ps() }; 4];
        for (r, two) in r.iter_mut().zip(values.chunks_exact(2)) {
            if let [p, q] = two {
                *r = pair(load_quat(p.rotation()), load_quat(q.rotation()));
            }
        }
        unsafe {
            let (pd, ps) = (_mm256_castps_pd, _mm256_castpd_ps);
            let t0 = _mm256_unpacklo_ps(r[0], r[1]);
            let t1 = _mm256_unpackhi_ps(r[0], r[1]);
            let t2 = _mm256_unpacklo_ps(r[2], r[3]);
            let t3 = _mm256_unpackhi_ps(r[2], r[3]);
            // x, y, z, w in memory; returned w first.
            [
                ps(_mm256_unpackhi_pd(pd(t1), pd(t3))),
                ps(_mm256_unpacklo_pd(pd(t0), pd(t2))),
                ps(_mm256_unpackhi_pd(pd(t0), pd(t2))),
                ps(_mm256_unpacklo_pd(pd(t1), pd(t3))),
            ]
        }
    }
    #[inline(always)]
    fn store<T: Slerped>([w, x, y, z]: [__m256; 4], values: &mut [T]) {
        let q = unsafe {
            let (pd, ps) = (_mm256_castps_pd, _mm256_castpd_ps);
            let u0 = _mm256_unpacklo_ps(x, y);
            let u1 = _mm256_unpackhi_ps(x, y);
            let v0 = _mm256_unpacklo_ps(z, w);
            let v1 = _mm256_unpackhi_ps(z, w);
            [
                ps(_mm256_unpacklo_pd(pd(u0), pd(v0))),
                ps(_mm256_unpackhi_pd(pd(u0), pd(v0))),
                ps(_mm256_unpacklo_pd(pd(u1), pd(v1))),
                ps(_mm256_unpackhi_pd(pd(u1), pd(v1))),
            ]
        };
        for (q, two) in q.into_iter().zip(values.chunks_exact_mut(2)) {
            if let [p, r] = two {
                let (low, high) =
                    unsafe { (_mm256_castps256_ps128(q), _mm256_extractf128_ps::<1>(q)) };
                store_quat(low, p.rotation_mut());
                store_quat(high, r.rotation_mut());
            }
        }
    }
}
