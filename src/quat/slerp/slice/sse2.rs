//! [`Isa`] for x86-64 with SSE2 (every x86-64 target with SSE): four f32
//! lanes to a register, two f64. Each operation is one intrinsic of
//! `core::arch` (a few for the loads, stores, conversions and the f64
//! select, which SSE2 builds from bitwise operations).

use super::steps::Isa;
use super::Slerped;
use crate::Quat;
use core::arch::x86_64::{
    __m128, __m128d, _mm_add_pd, _mm_add_ps, _mm_and_ps, _mm_andnot_ps, _mm_cmpgt_pd, _mm_cmple_pd,
    _mm_cmpngt_pd, _mm_cvtpd_ps, _mm_cvtps_pd, _mm_div_pd, _mm_loadu_ps, _mm_max_pd, _mm_movehl_ps,
    _mm_movelh_ps, _mm_movemask_pd, _mm_mul_pd, _mm_mul_ps, _mm_or_ps, _mm_set1_pd, _mm_set1_ps,
    _mm_setzero_ps, _mm_storeu_ps, _mm_sub_pd, _mm_unpackhi_ps, _mm_unpacklo_ps,
};

/// x86-64 with SSE2 (compiled only where `target_feature = "sse2"`).
pub(super) struct Sse2;

/// The operations, each one of the SSE2 intrinsics (SAFETY of every
/// `unsafe` block below: SSE2, which this module is compiled only with;
/// registers only, but for `load` and `store`, which read and write the
/// 16 bytes of a `Quat`, `repr(C)` of four f32, through a reference to it
/// (`loadu` and `storeu` need no alignment); SSE arithmetic cannot fault
/// with the default MXCSR, exceptions masked).
#[allow(unsafe_code)]
impl Isa for Sse2 {
    type F = __m128;
    type D = __m128d;
    const LANES: usize = 4;
    const PAIR_OF_LANE: [usize; 8] = [0, 1, 2, 3, 4, 5, 6, 7];

    #[inline(always)]
    fn splat(x: f32) -> __m128 {
        unsafe { _mm_set1_ps(x) }
    }
    #[inline(always)]
    fn splat_d(x: f64) -> __m128d {
        unsafe { _mm_set1_pd(x) }
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
    fn add_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_add_pd(a, b) }
    }
    #[inline(always)]
    fn sub_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_sub_pd(a, b) }
    }
    #[inline(always)]
    fn mul_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_mul_pd(a, b) }
    }
    #[inline(always)]
    fn div_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_div_pd(a, b) }
    }
    #[inline(always)]
    fn gt_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_cmpgt_pd(a, b) }
    }
    #[inline(always)]
    fn le_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_cmple_pd(a, b) }
    }
    #[inline(always)]
    fn not_gt_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_cmpngt_pd(a, b) }
    }
    #[inline(always)]
    fn max_d(a: __m128d, b: __m128d) -> __m128d {
        unsafe { _mm_max_pd(a, b) }
    }
    #[inline(always)]
    fn bits_d(a: __m128d) -> u32 {
        unsafe { _mm_movemask_pd(a) as u32 }
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
    fn load<T: Slerped>(values: &[T]) -> [__m128; 4] {
        let mut r = [unsafe { _mm_setzero_ps() }; 4];
        for (r, value) in r.iter_mut().zip(values) {
            *r = unsafe { _mm_loadu_ps((value.rotation() as *const Quat).cast::<f32>()) };
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
    fn store<T: Slerped>([w, x, y, z]: [__m128; 4], values: &mut [T]) {
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
            let to: *mut Quat = value.rotation_mut();
            unsafe { _mm_storeu_ps(to.cast::<f32>(), q) };
        }
    }
}
