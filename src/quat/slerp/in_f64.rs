//! Slerp's in-plane formula in f64, on x86-64 and AArch64, written once
//! for every register it runs in ([`Lanes`]): what [`Quat::slerp`]
//! returns there for `alpha` in (0, 1] (one pair, its arc in one lane and
//! its two coefficients side by side in two), and what the slices compute
//! many pairs at a time (`slice/steps.rs`, `slice/blocks.rs`), so that the
//! two agree bit for bit.
//!
//! The arc comes from the squared lengths of the difference and the sum
//! of the two inputs, not from a rotation between them: for unit `a` and
//! `b` an angle `phi` apart, `|a - b| = 2 sin(phi / 2)` and `|a + b| =
//! 2 cos(phi / 2)`, so `|a - cn(b)|^2 / |a + cn(b)|^2` is `tan^2(phi / 2)`
//! (`b` negated when the dot product is negative, the notes' `cn`). Both
//! are `|a|^2 + |b|^2 -+ 2 |a . b|`, taken in f64 from the f32 components,
//! where every product is exact and only the sums round, so that the
//! cancellation of the nearer one costs at most about 2^-26 of it where
//! slerp uses it, far under an f32 ulp of the result. From that one
//! quotient the arctangent polynomial ([`ATAN`]) gives `phi^2` and
//! `phi / sin(phi)` ([`Arc::from_quotient`]), without a square root; the
//! result is `sin((1 - alpha) phi) / sin(phi) a + sin(alpha phi) /
//! sin(phi) cn(b)`, each coefficient `s phi / sin(phi)` times the
//! `sin(x) / x` of its share `s` of the arc, a polynomial in
//! `x^2 = s^2 phi^2` ([`SIN`], [`Arc::coefficient`]). One division, no
//! square root and no select on the way from the inputs to the result:
//! the chain of dependent operations that bounds a call's time is short,
//! and only the checks that ordinary inputs pass branch.
//!
//! Both polynomials are this file's own: their coefficients, from
//! `tools/minimax.py` (Remez exchange in multiple precision), beside their
//! evaluation. Never compiled for the microcontrollers, whose FPUs have no
//! f64 (the f32 evaluation serves them).

use super::lanes::{Lanes, PairLanes, Two};
use super::{NEARLY_UNIT, SMALL_ANGLE};
use crate::Quat;

/// Minimax coefficients of `(atan(u) - u) / u^3` as a polynomial in `u^2`
/// on [0, 1], for relative error (`tools/minimax.py atan_f64`): the
/// approximation error is 1.7e-8 of the result.
pub(crate) const ATAN: [f64; 8] = [
    -0.333_331_527_378_383_06,
    0.199_937_728_817_470_77,
    -0.142_110_557_110_242_54,
    0.106_660_062_753_114_79,
    -0.075_522_178_037_118_6,
    0.043_211_902_355_727_805,
    -0.016_367_953_412_402_284,
    0.002_920_698_523_972_636,
];

/// `(atan(u) - u) / u^3` as a polynomial in `s = u^2` ([`ATAN`]), by
/// Estrin's scheme (`proofs/gappa/arc_f64.g` models it).
#[inline(always)]
fn atan_polynomial<L: Lanes>(s: L) -> L {
    let c = ATAN.map(L::splat);
    let s2 = s.mul(s);
    let s4 = s2.mul(s2);
    let low = c[0].add(s.mul(c[1])).add(s2.mul(c[2].add(s.mul(c[3]))));
    let high = c[4].add(s.mul(c[5])).add(s2.mul(c[6].add(s.mul(c[7]))));
    low.add(s4.mul(high))
}

/// Minimax coefficients of `(sin(x) - x) / x^3` as a polynomial in `x^2`
/// on [0, pi/2], for relative error (`tools/minimax.py sin_f64`): the
/// approximation error is 6.1e-9 of the result.
pub(crate) const SIN: [f64; 4] = [
    -0.166_666_595_504_268_43,
    0.008_333_066_246_154_522,
    -0.000_198_096_029_100_214_08,
    2.605_780_657_782_845e-6,
];

/// `sin(x) / x` from `s = x^2`, for `x` in [0, pi/2]: `1 + s Q(s)` with
/// the polynomial [`SIN`] in pairs (`proofs/gappa/sinc_f64.g` models it).
///
/// # Accuracy
///
/// Within [`SINC_F64_MAX_REL_ERROR`](crate::accuracy::SINC_F64_MAX_REL_ERROR).
#[inline(always)]
pub(super) fn sinc<L: Lanes>(s: L) -> L {
    let c = SIN.map(L::splat);
    let q = c[0]
        .add(s.mul(c[1]))
        .add(s.mul(s).mul(c[2].add(s.mul(c[3]))));
    L::splat(1.0).add(s.mul(q))
}

/// 2^32, the largest squared norm the evaluation takes: components below
/// 2^16, far from where an f32 weighted sum could overflow.
pub(super) const NORM_SQUARED_LIMIT: f64 = 4_294_967_296.0;

/// The square of the angle above which a pair's evaluation is slerp's, in
/// f64 (exact: 2^-24).
pub(super) const SMALL_ANGLE_SQUARED_F64: f64 = (SMALL_ANGLE as f64) * (SMALL_ANGLE as f64);

/// What the evaluation needs of a pair `(a, b)` (in each lane), in f64
/// from the f32 components: the squared norms and the dot product. Each
/// product of two f32 is exact in f64, so only the sums round, each by at
/// most 2^-53 of its size.
#[derive(Clone, Copy)]
pub(super) struct Pair<L> {
    /// `|a|^2`.
    pub(super) n2: L,
    /// `|b|^2`.
    pub(super) on2: L,
    /// `a . b`.
    pub(super) dot: L,
}

/// `p . q` of the components `[w, x, y, z]`, summed as
/// `(x x' + z z') + (y y' + w w')`: the order of a single call's two-lane
/// registers ([`Pair::checked`]), which every evaluation keeps.
#[inline(always)]
fn dot<L: Lanes>(p: [L; 4], q: [L; 4]) -> L {
    let [w, x, y, z] = [0, 1, 2, 3].map(|i| p[i].mul(q[i]));
    x.add(z).add(y.add(w))
}

impl<L: Lanes> Pair<L> {
    /// The squared norms and the dot product of the components
    /// `[w, x, y, z]` of `a` and `b`, widened to f64.
    ///
    /// # Preconditions
    ///
    /// None for the arithmetic (f64 products of f32 values cannot
    /// overflow); infinite components make NaN in the dot product
    /// (`inf * 0`): the single call checks the norms first
    /// ([`Pair::checked`]).
    #[inline(always)]
    pub(super) fn of(a: [L; 4], b: [L; 4]) -> Self {
        Self {
            n2: dot(a, a),
            on2: dot(b, b),
            dot: dot(a, b),
        }
    }

    /// `|a - cn(b)|^2 = |a|^2 + |b|^2 - 2 |a . b|`, `b` negated when
    /// `a . b < 0` (the notes' `cn`). The subtraction cancels as the angle
    /// shrinks, but its operands carry only f64 rounding: against the
    /// squared length of the difference itself, 8.5e-9 relative at most on
    /// 50,000 unit pairs 2^-12 to 2^-6 rad apart (the smallest angles slerp
    /// takes this evaluation for), 7.7e-14 on 50,000 random ones.
    #[inline(always)]
    pub(super) fn near(&self) -> L {
        self.n2.add(self.on2).sub(L::splat(2.0).mul(self.dot.abs()))
    }

    /// `|a + cn(b)|^2 = |a|^2 + |b|^2 + 2 |a . b|`.
    #[inline(always)]
    pub(super) fn far(&self) -> L {
        self.n2.add(self.on2).add(L::splat(2.0).mul(self.dot.abs()))
    }

    /// Where the evaluation gives slerp's result for the pair, as far as
    /// that is known before the angle: squared norms within
    /// [`NORM_SQUARED_LIMIT`] and within 1e-6 of each other (relatively),
    /// and [`near`](Self::near) below [`far`](Self::far), so that the
    /// shorter of `b` and `-b` is known (the sign of the dot product, which
    /// turns exactly when `b` does) and their quotient below 1 is defined.
    /// Pairs at a right angle to f64's precision (and zero quaternions) are
    /// left to the f32 evaluation, whose dot product picks one way. False
    /// for NaN.
    #[inline(always)]
    pub(super) fn applies(&self) -> L::Mask {
        let allowed = L::splat(f64::from(NEARLY_UNIT)).mul(self.on2);
        let near_unit = self.n2.sub(self.on2).abs().not_gt(allowed);
        let limit = L::splat(NORM_SQUARED_LIMIT);
        near_unit & self.n2.le(limit) & self.on2.le(limit) & self.far().gt(self.near())
    }

    /// `tan^2(phi / 2)` of the arc from `a` to `cn(b)`, in [0, 1):
    /// `|a - cn(b)|^2 / |a + cn(b)|^2`, exactly so for unit inputs. For
    /// inputs whose squared norms differ it is `(m - |a . b|) /
    /// (m + |a . b|)` with `m` the mean of the squared norms in place of
    /// `|a| |b|` (where the evaluation applies they are within 1e-6 of each
    /// other, relatively, and the two differ by less than 1.3e-13 of
    /// either).
    ///
    /// # Preconditions
    ///
    /// [`applies`](Self::applies).
    #[inline(always)]
    pub(super) fn quotient(&self) -> L {
        self.near().div(self.far())
    }

    /// The two lengths whose quotient is [`quotient`](Self::quotient),
    /// `(near, far)`, in every lane, whether the evaluation applies there
    /// or not: where it does not, the larger length may be zero (a zero
    /// quaternion) or NaN, and the smallest normal f64 takes its place
    /// (`max` takes it for NaN), so that no lane divides by zero (which
    /// would raise the divide-by-zero exception that slerp itself does not,
    /// a SIGFPE where a program unmasks it). Where the evaluation applies,
    /// the larger length is above the smaller, so positive, and stays as
    /// it is.
    #[inline(always)]
    pub(super) fn lengths_in_every_lane(&self) -> (L, L) {
        (self.near(), self.far().max(L::splat(f64::MIN_POSITIVE)))
    }
}

impl Pair<f64> {
    /// The pair of a single call, in the two-lane registers `T` (`[x, y]`
    /// and `[z, w]` of each input), `None` for inputs whose squared norms
    /// are beyond [`NORM_SQUARED_LIMIT`], infinite or NaN, checked before
    /// the dot product, which would make NaN of infinities (`inf * 0`,
    /// raising the invalid-operation flag, a SIGFPE where a program
    /// unmasks it). The sums are [`Pair::of`]'s, in its order.
    #[inline(always)]
    pub(super) fn checked<T: PairLanes>(a: &Quat, b: &Quat) -> Option<Self> {
        let ([al, ah], [bl, bh]) = (T::halves(a), T::halves(b));
        // [x^2 + z^2, y^2 + w^2]
        let squares = |l: T, h: T| l.mul(l).add(h.mul(h));
        let [n2, on2] = T::sums(squares(al, ah), squares(bl, bh)).lanes();
        let limit = NORM_SQUARED_LIMIT;
        if !(n2.le(limit) & on2.le(limit)) {
            return None;
        }
        // [x x' + z z', y y' + w w']
        let products = al.mul(bl).add(ah.mul(bh));
        Some(Self {
            n2,
            on2,
            dot: T::sums(products, products).lanes()[0],
        })
    }

    /// The pair of quaternions, with [`Pair::of`] on their components:
    /// the slices' portable blocks, and the tests.
    #[cfg(any(portable_lanes, test))]
    #[inline(always)]
    pub(super) fn of_quats(a: &Quat, b: &Quat) -> Self {
        let wide = |q: &Quat| q.to_wxyz().map(f64::from);
        Self::of(wide(a), wide(b))
    }
}

/// What slerp's coefficients need of the arc between a pair (in each
/// lane).
#[derive(Clone, Copy)]
pub(super) struct Arc<L> {
    /// `phi^2`, the square of the notes' `phi`, in [0, pi^2/4].
    pub(super) phi_squared: L,
    /// `phi / sin(phi)`.
    pub(super) phi_over_sine: L,
}

impl<L: Lanes> Arc<L> {
    /// The arc whose `tan^2(phi / 2)` is `t2` ([`Pair::quotient`]), without
    /// a square root: with `atan(t) = t h(t^2)` (`h = 1 + t^2 P(t^2)`, the
    /// polynomial [`ATAN`]), `phi = 2 t h`, so that `phi^2 = 4 t^2 h^2`
    /// and, as `sin(phi) = 2 t / (1 + t^2)`, `phi / sin(phi) =
    /// h (1 + t^2)`: both functions of `t^2` alone.
    ///
    /// # Preconditions
    ///
    /// `t2` in [0, 1].
    ///
    /// # Accuracy
    ///
    /// Against the f64 arccosine of the same f32 inputs, on 10^6 random
    /// unit pairs: `phi / sin(phi)` within 4.0e-8 relative; `phi` within
    /// 1.3e-7 relative for `phi` in (0.5, 1.5) and 1.5e-7 down to 0.01 rad
    /// (the reference takes the inputs' norms as 1, which f32 unit
    /// quaternions are only to about 6e-8). Against `t2` itself, within
    /// [`PHI_SQUARED_F64_MAX_REL_ERROR`](crate::accuracy::PHI_SQUARED_F64_MAX_REL_ERROR)
    /// and [`PHI_OVER_SINE_F64_MAX_REL_ERROR`](crate::accuracy::PHI_OVER_SINE_F64_MAX_REL_ERROR).
    #[inline(always)]
    pub(super) fn from_quotient(t2: L) -> Self {
        let one = L::splat(1.0);
        let h = one.add(t2.mul(atan_polynomial(t2)));
        Arc {
            phi_squared: L::splat(4.0).mul(t2).mul(h.mul(h)),
            phi_over_sine: h.mul(one.add(t2)),
        }
    }

    /// Where the arc is longer than the small angles (`phi` above 2^-12
    /// rad), below which the f32 evaluation takes the pair. False for NaN.
    #[inline(always)]
    pub(super) fn past_small_angles(&self) -> L::Mask {
        self.phi_squared.gt(L::splat(SMALL_ANGLE_SQUARED_F64))
    }

    /// The coefficient `sin(s phi) / sin(phi)` of the share `s` of the arc
    /// (`1 - alpha` for `a`, `alpha` for `b`), before its rounding to f32:
    /// `s phi / sin(phi)` times [`sinc`] of `s^2 phi^2`.
    ///
    /// # Preconditions
    ///
    /// `s` in [0, 1].
    ///
    /// # Accuracy
    ///
    /// Within [`SLERP_COEFFICIENT_F64_MAX_REL_ERROR`](crate::accuracy::SLERP_COEFFICIENT_F64_MAX_REL_ERROR)
    /// where `phi^2` is above 2^-24.
    #[inline(always)]
    pub(super) fn coefficient(&self, s: L) -> L {
        s.mul(self.phi_over_sine)
            .mul(sinc(s.mul(s).mul(self.phi_squared)))
    }
}

impl Arc<f64> {
    /// The arc in every lane of `L`.
    #[inline(always)]
    pub(super) fn splat<L: Lanes>(self) -> Arc<L> {
        Arc {
            phi_squared: L::splat(self.phi_squared),
            phi_over_sine: L::splat(self.phi_over_sine),
        }
    }

    /// Slerp's coefficients of `a` and `b`, `1 - alpha` and `alpha` of the
    /// arc, side by side in the two lanes of `T`.
    #[inline(always)]
    pub(super) fn coefficients<T: PairLanes>(self, alpha: f32) -> T {
        let alpha = f64::from(alpha);
        self.splat::<T>().coefficient(T::new(1.0 - alpha, alpha))
    }
}

/// [`Quat::slerp_f64`] in the two-lane registers `T`.
#[inline(always)]
pub(super) fn slerp_in<T: PairLanes>(a: Quat, b: Quat, alpha: f32) -> Option<Quat> {
    if !(alpha > 0.0 && alpha <= 1.0) {
        return None;
    }
    let pair = Pair::checked::<T>(&a, &b)?;
    if !pair.applies() {
        return None;
    }
    // Never NaN here: the pair applies.
    let arc = Arc::from_quotient(pair.quotient());
    if !arc.past_small_angles() {
        return None;
    }
    Some(T::weigh(&a, &b, arc.coefficients(alpha), pair.dot))
}

impl Quat {
    /// [`slerp`](Self::slerp) by the f64 evaluation, where it applies
    /// (`alpha` in (0, 1], finite inputs within 2^16, norms within 1e-6 of
    /// each other, more than 2^-12 rad apart); `None` elsewhere. The checks
    /// are branches that ordinary inputs always pass, so the processor
    /// predicts them and they cost no wait.
    #[inline(always)]
    pub(super) fn slerp_f64(self, other: Self, alpha: f32) -> Option<Self> {
        slerp_in::<Two>(self, other, alpha)
    }
}

/// slerp's pair as a single call computes it: `[near, far, t2]`, the
/// squared lengths `|a - cn(b)|^2` and `|a + cn(b)|^2` and their quotient,
/// which `proofs/gappa/slerp_angle_f64.g` models; `None` where the squared
/// norms are beyond 2^32, infinite or NaN.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_pair(a: Quat, b: Quat) -> Option<[f64; 3]> {
    let pair = Pair::checked::<Two>(&a, &b)?;
    Some([pair.near(), pair.far(), pair.quotient()])
}

/// slerp's arc: `(phi^2, phi / sin(phi))` from the squared lengths
/// `near = |a - cn(b)|^2` and `far = |a + cn(b)|^2` of a pair, which
/// `proofs/gappa/arc_quotient_f64.g` (their quotient) and `arc_f64.g` (the
/// rest) model.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_arc(near: f64, far: f64) -> (f64, f64) {
    let arc = Arc::from_quotient(near / far);
    (arc.phi_squared, arc.phi_over_sine)
}

/// slerp's `sin(x) / x` from `s = x^2`, which `proofs/gappa/sinc_f64.g`
/// models.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_sinc(s: f64) -> f64 {
    sinc(s)
}

/// slerp's coefficients before their rounding to f32, `[c0, c1]`, from
/// the arc's `phi^2` and `phi / sin(phi)`, which
/// `proofs/gappa/coefficient_rest_f64.g` (`c0`) and `coefficient_f64.g`
/// (`c1`) model.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_coefficients(phi_squared: f64, phi_over_sine: f64, alpha: f32) -> [f64; 2] {
    let arc = Arc {
        phi_squared,
        phi_over_sine,
    };
    let alpha = f64::from(alpha);
    [arc.coefficient(1.0 - alpha), arc.coefficient(alpha)]
}

#[cfg(test)]
pub(super) mod tests;
