//! The registers of x86-64 with SSE2 (every x86-64 target with SSE): two
//! f64 lanes to an `__m128d`, four f32 lanes to an `__m128`. Each operation
//! is one intrinsic of `core::arch` (a few for the loads, stores and
//! conversions).
//!
//! SAFETY, for every `unsafe` block of this file: SSE2, which this module
//! is compiled only with; registers only, but for the loads and stores,
//! which read and write the 16 bytes of a `Quat`, `repr(C)` of four f32,
//! through a reference to it (`loadu` and `storeu` need no alignment); SSE
//! arithmetic cannot fault with the default MXCSR (exceptions masked).
//!
//! For the single call ([`PairLanes`]) the compiler, left to two plain
//! `f64`, loads each quaternion in two halves and moves its components
//! through the general registers one by one: these keep a quaternion in
//! one register from its load to its store.

#![allow(unsafe_code)]

use super::{Lanes, PairLanes};
use crate::Quat;
use core::arch::x86_64::{
    __m128, __m128d, _mm_add_pd, _mm_add_ps, _mm_and_pd, _mm_andnot_pd, _mm_cmpgt_pd, _mm_cmple_pd,
    _mm_cmpngt_pd, _mm_cvtpd_ps, _mm_cvtps_pd, _mm_cvtsd_f64, _mm_div_pd, _mm_loadu_ps, _mm_max_pd,
    _mm_movehl_ps, _mm_movemask_pd, _mm_mul_pd, _mm_mul_ps, _mm_or_pd, _mm_set1_pd, _mm_set_pd,
    _mm_shuffle_ps, _mm_storeu_ps, _mm_sub_pd, _mm_unpackhi_pd, _mm_unpacklo_pd,
};

/// The slices' steps with SSE2, four pairs a register (also compiled for
/// the tests of AVX builds, which check both).
#[cfg(any(test, not(x86_avx_lanes)))]
mod steps;
#[cfg(any(test, not(x86_avx_lanes)))]
pub(in crate::quat::slerp) use steps::Sse2;

/// The four lanes of a quaternion, `x, y, z, w`.
#[inline(always)]
pub(super) fn load_quat(q: &Quat) -> __m128 {
    unsafe { _mm_loadu_ps(core::ptr::from_ref(q).cast()) }
}

/// The four lanes, `x, y, z, w`, to the quaternion at `q`.
#[inline(always)]
pub(super) fn store_quat(v: __m128, q: &mut Quat) {
    unsafe { _mm_storeu_ps(core::ptr::from_mut(q).cast(), v) }
}

impl Lanes for __m128d {
    type Mask = u32;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        unsafe { _mm_set1_pd(x) }
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        unsafe { _mm_add_pd(self, o) }
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        unsafe { _mm_sub_pd(self, o) }
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        unsafe { _mm_mul_pd(self, o) }
    }
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        unsafe { _mm_div_pd(self, o) }
    }
    #[inline(always)]
    fn abs(self) -> Self {
        unsafe { _mm_andnot_pd(_mm_set1_pd(-0.0), self) }
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        unsafe { _mm_max_pd(self, o) }
    }
    #[inline(always)]
    fn le(self, o: Self) -> u32 {
        unsafe { _mm_movemask_pd(_mm_cmple_pd(self, o)) as u32 }
    }
    #[inline(always)]
    fn gt(self, o: Self) -> u32 {
        unsafe { _mm_movemask_pd(_mm_cmpgt_pd(self, o)) as u32 }
    }
    #[inline(always)]
    fn not_gt(self, o: Self) -> u32 {
        unsafe { _mm_movemask_pd(_mm_cmpngt_pd(self, o)) as u32 }
    }
}

impl PairLanes for __m128d {
    #[inline(always)]
    fn new(low: f64, high: f64) -> Self {
        unsafe { _mm_set_pd(high, low) }
    }
    #[inline(always)]
    fn lanes(self) -> [f64; 2] {
        unsafe {
            [
                _mm_cvtsd_f64(self),
                _mm_cvtsd_f64(_mm_unpackhi_pd(self, self)),
            ]
        }
    }
    #[inline(always)]
    fn halves(q: &Quat) -> [Self; 2] {
        let v = load_quat(q);
        unsafe { [_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v))] }
    }
    #[inline(always)]
    fn sums(p: Self, q: Self) -> Self {
        unsafe { _mm_add_pd(_mm_unpacklo_pd(p, q), _mm_unpackhi_pd(p, q)) }
    }
    #[inline(always)]
    fn weigh(a: &Quat, b: &Quat, c: Self, toward: f64) -> Quat {
        let mut out = Quat::NAN;
        unsafe {
            // copysign of the high lane.
            let sign = _mm_set_pd(-0.0, 0.0);
            let c = _mm_or_pd(
                _mm_andnot_pd(sign, c),
                _mm_and_pd(sign, _mm_set1_pd(toward)),
            );
            let c = _mm_cvtpd_ps(c);
            let (c0, c1) = (_mm_shuffle_ps::<0x00>(c, c), _mm_shuffle_ps::<0x55>(c, c));
            let r = _mm_add_ps(_mm_mul_ps(load_quat(a), c0), _mm_mul_ps(load_quat(b), c1));
            store_quat(r, &mut out);
        }
        out
    }
}
