//! The slices' steps with SSE2 ([`Steps`]): four pairs to a register of
//! four f32 lanes, one register per component. SAFETY, for every `unsafe`
//! block: as in `lanes/sse2.rs`.

#![allow(unsafe_code)]

use super::super::super::WithRotation;
use super::super::Steps;
use super::{load_quat, store_quat};
use core::arch::x86_64::{
    __m128, __m128d, _mm_add_ps, _mm_and_ps, _mm_andnot_ps, _mm_cvtpd_ps, _mm_cvtps_pd,
    _mm_movehl_ps, _mm_movelh_ps, _mm_mul_ps, _mm_or_ps, _mm_set1_ps, _mm_setzero_ps,
    _mm_unpackhi_ps, _mm_unpacklo_ps,
};

/// The slices' steps with SSE2: four pairs a register.
pub(in crate::quat::slerp) struct Sse2;

impl Steps for Sse2 {
    type F = __m128;
    type D = __m128d;
    const LANES: usize = 4;
    const PAIR_OF_LANE: [usize; 8] = [0, 1, 2, 3, 4, 5, 6, 7];

    #[inline(always)]
    fn splat(x: f32) -> __m128 {
        unsafe { _mm_set1_ps(x) }
    }
    #[inline(always)]
    fn add(a: __m128, b: __m128) -> __m128 {
        unsafe { _mm_add_ps(a, b) }
    }
    #[inline(always)]
    fn mul(a: __m128, b: __m128) -> __m128 {
        unsafe { _mm_mul_ps(a, b) }
    }
    #[inline(always)]
    fn and(a: __m128, b: __m128) -> __m128 {
        unsafe { _mm_and_ps(a, b) }
    }
    #[inline(always)]
    fn and_not(a: __m128, b: __m128) -> __m128 {
        unsafe { _mm_andnot_ps(a, b) }
    }
    #[inline(always)]
    fn or(a: __m128, b: __m128) -> __m128 {
        unsafe { _mm_or_ps(a, b) }
    }
    #[inline(always)]
    fn halves(a: __m128) -> [__m128d; 2] {
        unsafe { [_mm_cvtps_pd(a), _mm_cvtps_pd(_mm_movehl_ps(a, a))] }
    }
    #[inline(always)]
    fn join(low: __m128d, high: __m128d) -> __m128 {
        unsafe { _mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high)) }
    }
    #[inline(always)]
    fn load<T: WithRotation>(values: &[T]) -> [__m128; 4] {
        let mut r = [unsafe { _mm_setzero_ps() }; 4];
        for (r, value) in r.iter_mut().zip(values) {
            *r = load_quat(value.rotation());
        }
        // The four quaternions (x, y, z, w in memory) to one register per
        // component, lanes in their order, returned w first.
        unsafe {
            let t0 = _mm_unpacklo_ps(r[0], r[1]);
            let t1 = _mm_unpackhi_ps(r[0], r[1]);
            let t2 = _mm_unpacklo_ps(r[2], r[3]);
            let t3 = _mm_unpackhi_ps(r[2], r[3]);
            [
                _mm_movehl_ps(t3, t1),
                _mm_movelh_ps(t0, t2),
                _mm_movehl_ps(t2, t0),
                _mm_movelh_ps(t1, t3),
            ]
        }
    }
    #[inline(always)]
    fn store<T: WithRotation>([w, x, y, z]: [__m128; 4], values: &mut [T]) {
        let q = unsafe {
            let u0 = _mm_unpacklo_ps(x, y);
            let u1 = _mm_unpackhi_ps(x, y);
            let v0 = _mm_unpacklo_ps(z, w);
            let v1 = _mm_unpackhi_ps(z, w);
            [
                _mm_movelh_ps(u0, v0),
                _mm_movehl_ps(v0, u0),
                _mm_movelh_ps(u1, v1),
                _mm_movehl_ps(v1, u1),
            ]
        };
        for (q, value) in q.into_iter().zip(values) {
            store_quat(q, value.rotation_mut());
        }
    }
}
