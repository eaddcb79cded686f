//! The registers slerp's f64 evaluation (`in_f64.rs`) is written for: one
//! set of signatures, and a backend for each target, chosen at its module
//! declaration below, as glam chooses its SIMD or scalar files.
//!
//! - [`Lanes`]: f64 lanes and the IEEE 754 operations the evaluation
//!   takes on them, lane by lane. `f64` is one lane: the single call's arc,
//!   and the slices' portable blocks, which the compiler vectorizes.
//! - [`PairLanes`]: the single call's registers, two f64 lanes: a
//!   quaternion's components two at a time (`[x, y]` and `[z, w]`), and
//!   slerp's two coefficients side by side.
//! - [`Steps`]: the slices' registers on x86-64, one register per
//!   component of several pairs.
//!
//! The backends: `lanes/sse2.rs` (x86-64 with SSE2: `__m128d`, and the
//! slices' steps of four pairs a register), `lanes/avx.rs` (x86-64 with
//! AVX, the slices' steps of eight pairs a register), `lanes/portable.rs`
//! (every other target: [`PairLanes`] as two plain `f64`). Each operation
//! is IEEE 754's, with no fused multiply-add, so every backend gives the
//! same bits as `f64` itself.

use crate::Quat;
use core::ops::BitAnd;

#[cfg(x86_sse_lanes)]
use super::WithRotation;

/// f64 lanes: IEEE 754's operations on each lane, rounded as `f64`'s.
pub(super) trait Lanes: Copy {
    /// The result of a comparison, a flag per lane.
    type Mask: Copy + BitAnd<Output = Self::Mask>;
    /// `x` in every lane.
    fn splat(x: f64) -> Self;
    /// `self + o`.
    fn add(self, o: Self) -> Self;
    /// `self - o`.
    fn sub(self, o: Self) -> Self;
    /// `self * o`.
    fn mul(self, o: Self) -> Self;
    /// `self / o`.
    fn div(self, o: Self) -> Self;
    /// `|self|` (exact: the sign bit cleared).
    fn abs(self) -> Self;
    /// `if self > o { self } else { o }` (`o` where either is NaN).
    fn max(self, o: Self) -> Self;
    /// Where `self <= o` (false for NaN).
    fn le(self, o: Self) -> Self::Mask;
    /// Where `self > o` (false for NaN).
    fn gt(self, o: Self) -> Self::Mask;
    /// Where `!(self > o)` (true for NaN).
    fn not_gt(self, o: Self) -> Self::Mask;
}

/// One lane.
impl Lanes for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        self / o
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        if self > o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn le(self, o: Self) -> bool {
        self <= o
    }
    #[inline(always)]
    fn gt(self, o: Self) -> bool {
        self > o
    }
    #[inline(always)]
    fn not_gt(self, o: Self) -> bool {
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let not_greater = !(self > o);
        not_greater
    }
}

/// The single call's registers: two f64 lanes, `low` and `high`.
pub(super) trait PairLanes: Lanes {
    /// The lanes `low` and `high`.
    fn new(low: f64, high: f64) -> Self;
    /// The two lanes, `[low, high]`.
    fn lanes(self) -> [f64; 2];
    /// `q`'s components in f64 (exactly), two at a time: `[x, y]` and
    /// `[z, w]`.
    fn halves(q: &Quat) -> [Self; 2];
    /// `[p.low + p.high, q.low + q.high]`.
    fn sums(p: Self, q: Self) -> Self;
    /// `c.low a + c.high b` with `c.high` given the sign of `toward`, both
    /// coefficients rounded to f32 and the sum as
    /// [`Quat::weighted_sum`] rounds it.
    fn weigh(a: &Quat, b: &Quat, c: Self, toward: f64) -> Quat;
}

/// The slices' registers on x86-64: `LANES` f32 lanes to a register of
/// [`F`](Self::F) (pairs per block), half as many f64 lanes to one of
/// [`D`](Self::D).
#[cfg(x86_sse_lanes)]
pub(super) trait Steps {
    /// A register of f32 lanes.
    type F: Copy;
    /// A register of f64 lanes, half as many; its masks are bit sets,
    /// lane `k` in bit `k`.
    type D: Lanes<Mask = u32>;
    /// f32 lanes per register: pairs per block.
    const LANES: usize;
    /// The pair of its block that each lane holds, after
    /// [`load`](Self::load).
    const PAIR_OF_LANE: [usize; 8];

    /// `x` in every f32 lane.
    fn splat(x: f32) -> Self::F;
    /// `a + b`.
    fn add(a: Self::F, b: Self::F) -> Self::F;
    /// `a * b`.
    fn mul(a: Self::F, b: Self::F) -> Self::F;
    /// Bitwise `a & b`.
    fn and(a: Self::F, b: Self::F) -> Self::F;
    /// Bitwise `!a & b`.
    fn and_not(a: Self::F, b: Self::F) -> Self::F;
    /// Bitwise `a | b`.
    fn or(a: Self::F, b: Self::F) -> Self::F;
    /// The low and the high half of the f32 lanes, each widened to f64.
    fn halves(a: Self::F) -> [Self::D; 2];
    /// Two registers of f64 lanes rounded to f32, the first the low half.
    fn join(low: Self::D, high: Self::D) -> Self::F;
    /// The rotations of [`LANES`](Self::LANES) values, one register per
    /// component (`w`, `x`, `y`, `z`), lanes in the order
    /// [`PAIR_OF_LANE`](Self::PAIR_OF_LANE) gives.
    fn load<T: WithRotation>(values: &[T]) -> [Self::F; 4];
    /// The inverse of [`load`](Self::load): the quaternions in the four
    /// component registers to the rotations of `values`.
    fn store<T: WithRotation>(components: [Self::F; 4], values: &mut [T]);
}

/// x86-64 with SSE2: the single call's pair and coefficients in `__m128d`,
/// the slices' steps of four pairs a register.
#[cfg(x86_sse_lanes)]
mod sse2;
#[cfg(all(x86_sse_lanes, any(test, not(x86_avx_lanes))))]
pub(super) use sse2::Sse2;
/// The single call's registers on this target.
#[cfg(x86_sse_lanes)]
pub(super) type Two = core::arch::x86_64::__m128d;

/// x86-64 with AVX: the slices' steps of eight pairs a register.
#[cfg(x86_avx_lanes)]
mod avx;
#[cfg(x86_avx_lanes)]
pub(super) use avx::Avx;

/// Every other target: two plain `f64` (also compiled for the tests on
/// x86-64, which hold it to SSE2's bits).
#[cfg(any(test, not(x86_sse_lanes)))]
mod portable;
/// The single call's registers on this target.
#[cfg(not(x86_sse_lanes))]
pub(super) type Two = portable::F64x2;
#[cfg(all(test, x86_sse_lanes))]
pub(super) use portable::F64x2;
