//! [`PairLanes`] as two plain `f64`, for every target without SSE2's
//! registers (AArch64, whose compiler pairs the two lanes where it can;
//! x86-64 without SSE; Kani, which reads no intrinsic).

use super::{Lanes, PairLanes};
use crate::Quat;

/// Two f64 lanes, `[low, high]`, each operation IEEE 754's on each.
#[derive(Clone, Copy)]
pub(in crate::quat::slerp) struct F64x2([f64; 2]);

impl F64x2 {
    /// `f` on each lane.
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Self(self.0.map(f))
    }
    /// `f` on each pair of lanes.
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Self([f(self.0[0], o.0[0]), f(self.0[1], o.0[1])])
    }
    /// `f` on each pair of lanes, lane `k`'s flag in bit `k`.
    #[inline(always)]
    fn flags(self, o: Self, f: impl Fn(f64, f64) -> bool) -> u32 {
        u32::from(f(self.0[0], o.0[0])) | (u32::from(f(self.0[1], o.0[1])) << 1)
    }
}

impl Lanes for F64x2 {
    type Mask = u32;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self([x, x])
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self.zip(o, Lanes::add)
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self.zip(o, Lanes::sub)
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self.zip(o, Lanes::mul)
    }
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        self.zip(o, Lanes::div)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        self.map(f64::abs)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        self.zip(o, Lanes::max)
    }
    #[inline(always)]
    fn le(self, o: Self) -> u32 {
        self.flags(o, Lanes::le)
    }
    #[inline(always)]
    fn gt(self, o: Self) -> u32 {
        self.flags(o, Lanes::gt)
    }
    #[inline(always)]
    fn not_gt(self, o: Self) -> u32 {
        self.flags(o, Lanes::not_gt)
    }
}

impl PairLanes for F64x2 {
    #[inline(always)]
    fn new(low: f64, high: f64) -> Self {
        Self([low, high])
    }
    #[inline(always)]
    fn lanes(self) -> [f64; 2] {
        self.0
    }
    #[inline(always)]
    fn halves(q: &Quat) -> [Self; 2] {
        [
            Self([f64::from(q.x), f64::from(q.y)]),
            Self([f64::from(q.z), f64::from(q.w)]),
        ]
    }
    #[inline(always)]
    fn sums(p: Self, q: Self) -> Self {
        Self([p.0[0] + p.0[1], q.0[0] + q.0[1]])
    }
    #[inline(always)]
    fn weigh(a: &Quat, b: &Quat, c: Self, toward: f64) -> Quat {
        let [c0, c1] = c.0;
        a.weighted_sum(c0 as f32, *b, c1.copysign(toward) as f32)
    }
}
