//! The registers of x86-64 with AVX, for the slices' steps: eight f32
//! lanes to an `__m256`, four f64 to an `__m256d`. Each operation is one
//! intrinsic of `core::arch` (a few for the loads, stores and
//! conversions).
//!
//! SAFETY, for every `unsafe` block of this file: AVX, which this module
//! is compiled only with; registers only, but for the loads and stores,
//! which read and write the 16 bytes of a `Quat`, `repr(C)` of four f32,
//! through a reference to it (`loadu` and `storeu` need no alignment); AVX
//! arithmetic cannot fault with the default MXCSR (exceptions masked).

#![allow(unsafe_code)]

use super::super::WithRotation;
use super::{Lanes, Steps};
use crate::Quat;
use core::arch::x86_64::{
    __m128, __m256, __m256d, _mm256_add_pd, _mm256_add_ps, _mm256_and_ps, _mm256_andnot_pd,
    _mm256_andnot_ps, _mm256_castpd_ps, _mm256_castps128_ps256, _mm256_castps256_ps128,
    _mm256_castps_pd, _mm256_cmp_pd, _mm256_cvtpd_ps, _mm256_cvtps_pd, _mm256_div_pd,
    _mm256_extractf128_ps, _mm256_insertf128_ps, _mm256_max_pd, _mm256_movemask_pd, _mm256_mul_pd,
    _mm256_mul_ps, _mm256_or_ps, _mm256_set1_pd, _mm256_set1_ps, _mm256_setzero_ps, _mm256_sub_pd,
    _mm256_unpackhi_pd, _mm256_unpackhi_ps, _mm256_unpacklo_pd, _mm256_unpacklo_ps, _mm_loadu_ps,
    _mm_storeu_ps, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_NGT_UQ,
};

/// Two quaternions' registers, the first in the low half.
#[inline(always)]
fn pair(low: __m128, high: __m128) -> __m256 {
    unsafe { _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(low), high) }
}

/// The quaternion at `q` in a register, `x` in lane 0.
#[inline(always)]
fn load_quat(q: &Quat) -> __m128 {
    unsafe { _mm_loadu_ps(core::ptr::from_ref(q).cast()) }
}

/// The register's lanes to the quaternion at `q`, lane 0 to `x`.
#[inline(always)]
fn store_quat(v: __m128, q: &mut Quat) {
    unsafe { _mm_storeu_ps(core::ptr::from_mut(q).cast(), v) }
}

impl Lanes for __m256d {
    type Mask = u32;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        unsafe { _mm256_set1_pd(x) }
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        unsafe { _mm256_add_pd(self, o) }
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        unsafe { _mm256_sub_pd(self, o) }
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        unsafe { _mm256_mul_pd(self, o) }
    }
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        unsafe { _mm256_div_pd(self, o) }
    }
    #[inline(always)]
    fn abs(self) -> Self {
        unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self) }
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        unsafe { _mm256_max_pd(self, o) }
    }
    #[inline(always)]
    fn le(self, o: Self) -> u32 {
        unsafe { _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(self, o)) as u32 }
    }
    #[inline(always)]
    fn gt(self, o: Self) -> u32 {
        unsafe { _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(self, o)) as u32 }
    }
    #[inline(always)]
    fn not_gt(self, o: Self) -> u32 {
        unsafe { _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NGT_UQ>(self, o)) as u32 }
    }
}

/// The slices' steps with AVX: eight pairs a register.
pub(in crate::quat::slerp) struct Avx;

impl Steps for Avx {
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
    fn load<T: WithRotation>(values: &[T]) -> [__m256; 4] {
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
    fn store<T: WithRotation>([w, x, y, z]: [__m256; 4], values: &mut [T]) {
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
