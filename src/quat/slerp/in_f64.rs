//! Slerp's in-plane formula in f64, on x86-64 and AArch64: what
//! [`Quat::slerp`] returns there for `alpha` in (0, 1], and what the
//! vectorized lanes of [`Quat::slerp_slice`] compute, one set of functions
//! for both, so that the two agree bit for bit.
//!
//! The arc comes from the squared lengths of the difference and the sum
//! of the two inputs, not from a rotation between them: for unit `a` and
//! `b` an angle `phi` apart, `|a - b| = 2 sin(phi / 2)` and `|a + b| =
//! 2 cos(phi / 2)`, so `|a - cn(b)|^2 / |a + cn(b)|^2` is `tan^2(phi / 2)`
//! (`b` negated when the dot product is negative, the notes' `cn`). Both
//! are `|a|^2 + |b|^2 -+ 2 |a . b|`, taken in f64 from the f32 components,
//! where every product is exact and only the sums round, so that the
//! cancellation of the nearer one costs at most about 2^-26 of it where
//! slerp uses it, far under an f32 ulp of the result: the quotient has
//! the accuracy of the inputs
//! themselves. From that one quotient two polynomials give
//! `phi^2` and `phi / sin(phi)` ([`Pair::arc`]), without a square root;
//! the result is `sin((1 - alpha) phi) / sin(phi) a + sin(alpha phi) /
//! sin(phi) cn(b)`, each coefficient `s phi / sin(phi)` times the
//! `sin(x) / x` of its share `s` of the arc, which is a polynomial in
//! `x^2 = s^2 phi^2` ([`Pair::slerp`]). One division, no square root and
//! no select on the way from the inputs to the result: the chain of
//! dependent operations that bounds a call's time is short, and only the
//! checks that ordinary inputs pass branch. On x86-64, `in_f64/sse2.rs`
//! gives the pair and the weighted sum in vector registers, the same
//! operations in the same order.

use super::kernels_f64::{ATAN, SIN};
use super::{NEARLY_UNIT, SMALL_ANGLE};
use crate::Quat;

#[cfg(x86_sse_lanes)]
mod sse2;
#[cfg(x86_sse_lanes)]
use sse2::blend;

/// `c0 a + c1 b` for slerp's coefficients `[c0, c1]` of `arc` and `alpha`
/// ([`Arc::coefficients`]), each rounded to f32, `c1` with the sign of
/// `toward` (the notes' `cn`).
#[cfg(not(x86_sse_lanes))]
#[inline(always)]
fn blend(a: Quat, b: Quat, arc: Arc, alpha: f32, toward: f64) -> Quat {
    let [c0, c1] = arc.coefficients(alpha);
    a.weighted_sum(c0 as f32, b, c1.copysign(toward) as f32)
}

/// 2^32, the largest squared norm the evaluation takes: components below
/// 2^16, far from where an f32 weighted sum could overflow.
pub(super) const NORM_SQUARED_LIMIT: f64 = 4_294_967_296.0;

/// A quaternion's components in f64 (exactly), in the pairs the sums below
/// take them: `[x, y]` and `[z, w]`.
// The portable evaluation, which the SSE2 one (`in_f64/sse2.rs`) matches
// bit for bit and is tested against.
#[cfg_attr(x86_sse_lanes, allow(dead_code))]
#[inline(always)]
fn wide(q: Quat) -> [[f64; 2]; 2] {
    [
        [f64::from(q.x), f64::from(q.y)],
        [f64::from(q.z), f64::from(q.w)],
    ]
}

/// `|v|^2` of four f64 components given as `[x, y]` and `[z, w]`, summed
/// as `(x^2 + z^2) + (y^2 + w^2)`: the order of the two-lane vector
/// registers, so that the vectorized evaluations round as this one does.
// The portable evaluation, which the SSE2 one (`in_f64/sse2.rs`) matches
// bit for bit and is tested against.
#[cfg_attr(x86_sse_lanes, allow(dead_code))]
#[inline(always)]
fn squares([low, high]: [[f64; 2]; 2]) -> f64 {
    let lanes = [
        low[0] * low[0] + high[0] * high[0],
        low[1] * low[1] + high[1] * high[1],
    ];
    lanes[0] + lanes[1]
}

/// The squared norms of `a` and `b` in f64, as [`Pair::of`] sums them.
// The portable evaluation, which the SSE2 one (`in_f64/sse2.rs`) matches
// bit for bit and is tested against.
#[cfg_attr(x86_sse_lanes, allow(dead_code))]
#[inline(always)]
pub(super) fn norms(a: Quat, b: Quat) -> [f64; 2] {
    [squares(wide(a)), squares(wide(b))]
}

/// `p . q` of four f64 components each, given as `[x, y]` and `[z, w]`,
/// summed as `(x x' + z z') + (y y' + w w')`: the order of the two-lane
/// vector registers, so that the vectorized evaluations round as this one
/// does.
// The portable evaluation, which the SSE2 one (`in_f64/sse2.rs`) matches
// bit for bit and is tested against.
#[cfg_attr(x86_sse_lanes, allow(dead_code))]
#[inline(always)]
fn dot([pl, ph]: [[f64; 2]; 2], [ql, qh]: [[f64; 2]; 2]) -> f64 {
    let lanes = [pl[0] * ql[0] + ph[0] * qh[0], pl[1] * ql[1] + ph[1] * qh[1]];
    lanes[0] + lanes[1]
}

/// Whether both squared norms are at most [`NORM_SQUARED_LIMIT`] (false
/// for NaN): the inputs are finite, and the products of [`Pair::of`]
/// make no infinity and no NaN.
#[inline(always)]
pub(super) fn bounded([n2, on2]: [f64; 2]) -> bool {
    (n2 <= NORM_SQUARED_LIMIT) & (on2 <= NORM_SQUARED_LIMIT)
}

/// What the evaluation needs of a pair `(a, b)`, in f64 from the f32
/// components: the squared norms and the dot product. Each product of two
/// f32 is exact in f64, so only the sums round, each by at most 2^-53 of
/// its size.
#[derive(Clone, Copy)]
pub(super) struct Pair {
    /// `|a|^2`.
    pub(super) n2: f64,
    /// `|b|^2`.
    pub(super) on2: f64,
    /// `a . b`.
    pub(super) dot: f64,
}

impl Pair {
    /// The squared norms and the dot product of `a` and `b`, in f64.
    ///
    /// # Preconditions
    ///
    /// None for the arithmetic (f64 products of f32 values cannot
    /// overflow); infinite components make NaN in the dot product
    /// (`inf * 0`), so [`Quat::slerp_f64`] checks [`bounded`] first.
    #[cfg_attr(x86_sse_lanes, allow(dead_code))]
    #[inline(always)]
    pub(super) fn of(a: Quat, b: Quat) -> Self {
        let [n2, on2] = norms(a, b);
        Self {
            n2,
            on2,
            dot: dot(wide(a), wide(b)),
        }
    }

    /// [`Pair::of`] for inputs that are [`bounded`], `None` for the others,
    /// checked on the squared norms first: they make no NaN from
    /// infinities (the dot product would: inf * 0).
    #[cfg(not(x86_sse_lanes))]
    #[inline(always)]
    pub(super) fn checked(a: Quat, b: Quat) -> Option<Self> {
        bounded(norms(a, b)).then(|| Self::of(a, b))
    }

    /// `|a - cn(b)|^2 = |a|^2 + |b|^2 - 2 |a . b|`, `b` negated when
    /// `a . b < 0` (the notes' `cn`). The subtraction cancels as the angle
    /// shrinks, but its operands carry only f64 rounding: against the
    /// squared length of the difference itself, 8.5e-9 relative at most on
    /// 50,000 unit pairs 2^-12 to 2^-6 rad apart (the smallest angles slerp
    /// takes this evaluation for), 7.7e-14 on 50,000 random ones.
    #[inline(always)]
    pub(super) fn near(&self) -> f64 {
        (self.n2 + self.on2) - 2.0 * self.dot.abs()
    }

    /// `|a + cn(b)|^2 = |a|^2 + |b|^2 + 2 |a . b|`.
    #[inline(always)]
    pub(super) fn far(&self) -> f64 {
        (self.n2 + self.on2) + 2.0 * self.dot.abs()
    }

    /// Whether the evaluation gives slerp's result for this pair, as far
    /// as that is known before the angle: squared norms within
    /// [`NORM_SQUARED_LIMIT`] and within 1e-6 of each other (relatively),
    /// and [`near`](Self::near) below [`far`](Self::far), so that the
    /// shorter of `b` and `-b` is known (the sign of the dot product, which
    /// turns exactly when `b` does) and their quotient below 1 is defined.
    /// Pairs at a right angle to f64's precision (and zero quaternions) are
    /// left to the f32 evaluation, whose dot product picks one way. Written
    /// to be false for NaN.
    #[inline(always)]
    pub(super) fn applies(&self) -> bool {
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let near_unit = !((self.n2 - self.on2).abs() > f64::from(NEARLY_UNIT) * self.on2);
        near_unit & bounded([self.n2, self.on2]) & (self.near() < self.far())
    }

    /// The arc from `a` to `cn(b)`: the square of the notes' `phi` in
    /// [0, pi/2] and `phi / sin(phi)`, in f64, from the tangent of the half
    /// angle, without a square root and with one division.
    ///
    /// `tan^2(phi / 2)` is `|a - cn(b)|^2 / |a + cn(b)|^2`: exactly for
    /// unit inputs, and for inputs whose squared norms differ,
    /// `(m - |a . b|) / (m + |a . b|)` with `m` the mean of the squared
    /// norms in place of `|a| |b|` (where the evaluation
    /// applies they are within 1e-6 of each other, relatively, and the two
    /// differ by less than 1.3e-13 of either). With `t^2` that quotient
    /// (in [0, 1)) and `atan(t) = t h(t^2)` (`h = 1 + t^2 P(t^2)`, the
    /// polynomial [`ATAN`]), `phi = 2 t h`, so that `phi^2 = 4 t^2 h^2`
    /// and, as `sin(phi) = 2 t / (1 + t^2)`, `phi / sin(phi) =
    /// h (1 + t^2)`: both functions of `t^2` alone.
    ///
    /// # Preconditions
    ///
    /// [`applies`](Self::applies) (or, in vectorized lanes, lengths put in
    /// their place whose larger is positive).
    ///
    /// # Accuracy
    ///
    /// Against the f64 arccosine of the same f32 inputs, on 10^6 random
    /// unit pairs: `phi / sin(phi)` within 4.0e-8 relative; `phi` within
    /// 1.3e-7 relative for `phi` in (0.5, 1.5) and 1.5e-7 down to 0.01 rad
    /// (the reference takes the inputs' norms as 1, which f32 unit
    /// quaternions are only to about 6e-8; the unit tests hold the first
    /// to 2e-7 and `phi` to 1e-6, on 10,000 pairs).
    #[inline(always)]
    pub(super) fn arc(&self) -> Arc {
        Arc::from_lengths(self.near(), self.far())
    }

    /// Slerp of `a` to `b` by `alpha` in (0, 1], for this pair's `arc`:
    /// `sin((1 - alpha) phi) / sin(phi) a + sin(alpha phi) / sin(phi)
    /// cn(b)`, each coefficient `s phi / sin(phi) sinc(s phi)` for its
    /// share `s` of the arc, `sinc(x) = sin(x) / x = 1 + x^2 Q(x^2)` with
    /// the polynomial [`SIN`] (of `x^2 = s^2 phi^2`), rounded to f32 once
    /// ([`Arc::coefficients`]).
    ///
    /// # Preconditions
    ///
    /// `phi > SMALL_ANGLE` for the result to be slerp's; those of
    /// [`arc`](Self::arc).
    #[inline(always)]
    pub(super) fn slerp(&self, a: Quat, b: Quat, arc: Arc, alpha: f32) -> Quat {
        blend(a, b, arc, alpha, self.dot)
    }
}

/// What slerp's coefficients need of the arc between a pair.
#[derive(Clone, Copy)]
pub(super) struct Arc {
    /// `phi^2`, the square of the notes' `phi`.
    pub(super) phi_squared: f64,
    /// `phi / sin(phi)`.
    pub(super) phi_over_sine: f64,
}

impl Arc {
    /// The arc whose `tan^2(phi / 2)` is `near / far` ([`Pair::arc`]).
    ///
    /// # Preconditions
    ///
    /// `far` positive; `near` at most `far`.
    #[inline(always)]
    pub(super) fn from_lengths(near: f64, far: f64) -> Self {
        let t2 = near / far;
        let h = 1.0 + t2 * atan_polynomial(t2);
        Arc {
            phi_squared: (4.0 * t2) * (h * h),
            phi_over_sine: h * (1.0 + t2),
        }
    }

    /// Slerp's coefficients `sin((1 - alpha) phi) / sin(phi)` and
    /// `sin(alpha phi) / sin(phi)` for `alpha` in (0, 1], before their
    /// rounding to f32: each `s phi / sin(phi) sinc(s^2 phi^2)` for its
    /// share `s` of the arc.
    #[cfg_attr(x86_sse_lanes, allow(dead_code))]
    #[inline(always)]
    pub(super) fn coefficients(self, alpha: f32) -> [f64; 2] {
        let alpha = f64::from(alpha);
        let rest = 1.0 - alpha;
        let c0 = (rest * self.phi_over_sine) * sinc((rest * rest) * self.phi_squared);
        let c1 = (alpha * self.phi_over_sine) * sinc((alpha * alpha) * self.phi_squared);
        [c0, c1]
    }
}

/// `(atan(u) - u) / u^3` as a polynomial in `s = u^2` ([`ATAN`]), by
/// Estrin's scheme (`proofs/gappa/arc_f64.g` models it).
#[inline(always)]
fn atan_polynomial(s: f64) -> f64 {
    let c = ATAN;
    let s2 = s * s;
    let s4 = s2 * s2;
    let low = (c[0] + s * c[1]) + s2 * (c[2] + s * c[3]);
    let high = (c[4] + s * c[5]) + s2 * (c[6] + s * c[7]);
    low + s4 * high
}

/// `sin(x) / x` from `s = x^2`, for `x` in [0, pi/2]: `1 + s Q(s)` with
/// the polynomial [`SIN`] in pairs (`proofs/gappa/sinc_f64.g` models it).
#[inline(always)]
pub(super) fn sinc(s: f64) -> f64 {
    let q = (SIN[0] + s * SIN[1]) + (s * s) * (SIN[2] + s * SIN[3]);
    1.0 + s * q
}

/// The square of the angle above which a pair's evaluation is slerp's, in
/// f64 (exact: 2^-24).
pub(super) const SMALL_ANGLE_SQUARED_F64: f64 = (SMALL_ANGLE as f64) * (SMALL_ANGLE as f64);

impl Quat {
    /// [`slerp`](Self::slerp) by the f64 evaluation, where it applies
    /// (`alpha` in (0, 1], finite inputs within 2^16, norms within 1e-6 of
    /// each other, more than 2^-12 rad apart); `None` elsewhere. The checks
    /// are branches that ordinary inputs always pass, so the processor
    /// predicts them and they cost no wait.
    #[inline(always)]
    pub(super) fn slerp_f64(self, other: Self, alpha: f32) -> Option<Self> {
        if !(alpha > 0.0 && alpha <= 1.0) {
            return None;
        }
        let pair = Pair::checked(self, other)?;
        if !pair.applies() {
            return None;
        }
        // Never NaN here: the pair applies.
        let arc = pair.arc();
        if arc.phi_squared <= SMALL_ANGLE_SQUARED_F64 {
            return None;
        }
        Some(pair.slerp(self, other, arc, alpha))
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    pub(in crate::quat) use crate::test_draws::unit_quat as unit;

    /// Ordinary pairs, random unit quaternions with `alpha` in (0, 1], are
    /// the f64 evaluation's, and `slerp` returns its result.
    #[test]
    fn takes_ordinary_pairs() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(12);
        for _ in 0..10_000 {
            let (a, b) = (unit(&mut rng), unit(&mut rng));
            let alpha: f32 = rng.random_range(0.0..=1.0);
            if alpha == 0.0 {
                continue;
            }
            let q = a.slerp_f64(b, alpha).expect("an ordinary pair");
            assert_eq!(q, a.slerp(b, alpha));
        }
    }

    /// Inputs off unit norm are taken while their squared norms are within
    /// 1e-6 of each other relative to the second's, whatever its size.
    #[test]
    fn takes_pairs_of_equal_norms_off_unit() {
        let a = Quat::from_rotation_x(0.3).map(|c| c * 2.0);
        let b = Quat::from_rotation_y(0.7).map(|c| c * 2.0);
        assert!(a.slerp_f64(b, 0.5).is_some());
        // Each component two ulps of 1 larger: |a|^2 is about 4 (1 + 4.8e-7),
        // 1.9e-6 above |b|^2 and within 1e-6 of 4.
        let a = a.map(|c| c * (1.0 + 2.0 * f32::EPSILON));
        assert!((a.norm_squared() - b.norm_squared()).abs() < 4e-6);
        assert!(a.slerp_f64(b, 0.5).is_some());
        assert!(a.map(|c| c * 1.01).slerp_f64(b, 0.5).is_none());
    }

    /// Two ordinary unit quaternions, 1.37 rad apart.
    pub(in crate::quat) fn ordinary_pair() -> (Quat, Quat) {
        (Quat::from_rotation_x(0.3), Quat::from_rotation_y(0.7))
    }

    /// Pairs the evaluation leaves to the f32 one: norms more than 1e-6
    /// apart, components beyond 2^16, non-finite input, pairs 2^-12 rad
    /// apart or less (identical ones included).
    pub(in crate::quat) fn rare_pairs() -> [(Quat, Quat); 8] {
        let (a, b) = ordinary_pair();
        let near = a * Quat::from_rotation_z(2.0 * SMALL_ANGLE * 0.9);
        let huge = Quat::from_wxyz(1e5, 0.0, 0.0, 0.0);
        [
            (a, a),
            (a, -a),
            (a, near),
            (a.map(|c| c * 1.01), b),
            (huge, huge * Quat::from_rotation_x(1.0)),
            (huge, b),
            (Quat::NAN, b),
            (a, Quat::from_wxyz(f32::INFINITY, 0.0, 0.0, 0.0)),
        ]
    }

    /// The pair just past the small angles, which the evaluation takes.
    pub(in crate::quat) fn just_past_the_small_angles() -> (Quat, Quat) {
        let (a, _) = ordinary_pair();
        (a, a * Quat::from_rotation_z(2.0 * SMALL_ANGLE * 1.1))
    }

    /// What the evaluation leaves to the f32 one: `alpha` outside (0, 1],
    /// and the rare pairs.
    #[test]
    fn leaves_the_rare_inputs_to_the_f32_evaluation() {
        let (a, b) = ordinary_pair();
        for alpha in [0.0, -0.25, 1.5, f32::NAN, f32::INFINITY] {
            assert!(a.slerp_f64(b, alpha).is_none(), "alpha {alpha}");
        }
        for (p, q) in rare_pairs() {
            assert!(p.slerp_f64(q, 0.5).is_none(), "{p:?} {q:?}");
        }
        let (a, past) = just_past_the_small_angles();
        assert!(a.slerp_f64(past, 0.5).is_some());
    }

    /// Pairs at an exact right angle (a zero dot product, `near == far`),
    /// where neither sign of `b` is shorter, are left to the f32
    /// evaluation, so that `slerp(a, b)` and `slerp(a, -b)` choose alike.
    #[test]
    fn pairs_at_a_right_angle_are_left_to_the_f32_evaluation() {
        let a = Quat::from_xyzw(1.0, 0.0, 0.0, 0.0);
        for b in [
            Quat::from_xyzw(0.0, 1.0, 0.0, 0.0),
            Quat::from_xyzw(0.0, 0.0, 0.6, 0.8),
        ] {
            let pair = Pair::of(a, b);
            assert_eq!(pair.near(), pair.far());
            assert!(!pair.applies());
            assert!(a.slerp_f64(b, 0.5).is_none() && a.slerp_f64(-b, 0.5).is_none());
        }
    }

    /// The pair is not formed (no dot product, which would make NaN of
    /// `inf * 0`) when either input's squared norm is beyond the bound,
    /// infinite or NaN, whichever of the two it is.
    #[test]
    fn pairs_beyond_the_bound_are_not_formed() {
        let (a, _) = ordinary_pair();
        let beyond = [
            Quat::from_wxyz(f32::INFINITY, 0.0, 0.0, 0.0),
            Quat::from_wxyz(0.0, 7e4, 0.0, 0.0),
            Quat::NAN,
        ];
        for q in beyond {
            assert!(Pair::checked(a, q).is_none(), "{q:?}");
            assert!(Pair::checked(q, a).is_none(), "{q:?}");
        }
        assert!(Pair::checked(a, a.map(|c| c * 6e4)).is_some());
    }

    /// `near` and `far` are `|a - cn(b)|^2` and `|a + cn(b)|^2`, against
    /// the sums of the squared f64 differences and sums of the components
    /// (exact but for the last bits), relatively: `far` within 2^-50,
    /// `near` within 1e-12 for random unit pairs and, where its subtraction
    /// cancels, for pairs a small angle apart (2^-12 to 2^-6 rad, where
    /// slerp takes the evaluation), within 2^-25.
    #[test]
    fn near_and_far_are_the_squared_lengths_of_difference_and_sum() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(17);
        let mut worst = [0.0f64; 3];
        // Fewer under Miri, which interprets every instruction.
        let draws = if cfg!(miri) { 100 } else { 100_000 };
        for i in 0..draws {
            let a = unit(&mut rng);
            let small = i % 2 == 0;
            let b = if small {
                let angle = 2f32.powf(rng.random_range(-12.0..-6.0f32));
                let b = a * Quat::from_axis_angle(unit(&mut rng).xyz().normalize(), 2.0 * angle);
                if i % 4 == 0 {
                    -b
                } else {
                    b
                }
            } else {
                unit(&mut rng)
            };
            let pair = Pair::of(a, b);
            let (p, q) = (a.to_array().map(f64::from), b.to_array().map(f64::from));
            let sign = pair.dot.signum();
            let length =
                |s: f64| -> f64 { p.iter().zip(&q).map(|(x, y)| (x + s * y).powi(2)).sum() };
            let (near, far) = (length(-sign), length(sign));
            let errors = [
                (pair.near() - near).abs() / near,
                (pair.far() - far).abs() / far,
            ];
            let k = usize::from(small);
            worst[k] = worst[k].max(errors[0]);
            worst[2] = worst[2].max(errors[1]);
        }
        assert!(worst[0] <= 1e-12, "{worst:?}");
        assert!(worst[1] <= 2f64.powi(-25), "{worst:?}");
        assert!(worst[2] <= 2f64.powi(-50), "{worst:?}");
    }

    /// The pair's arc is that between `a` and `cn(b)` (half the rotation
    /// angle between them): its `phi^2` and `phi / sin(phi)` against f64
    /// arithmetic on the same f32 inputs.
    #[test]
    fn arc_is_the_arc_between_the_pair() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(13);
        for _ in 0..10_000 {
            let (a, b) = (unit(&mut rng), unit(&mut rng));
            let wide = |q: Quat| q.to_array().map(f64::from);
            let (p, q) = (wide(a), wide(b));
            let dot: f64 = p.iter().zip(&q).map(|(x, y)| x * y).sum();
            let along: f64 = q
                .iter()
                .zip(&p)
                .map(|(y, x)| (y - dot * x).powi(2))
                .sum::<f64>();
            let exact = along.sqrt().atan2(dot.abs());
            let arc = Pair::of(a, b).arc();
            let phi = arc.phi_squared.sqrt();
            assert!((phi - exact).abs() <= 1e-6 * exact + 1e-7, "{phi} {exact}");
            let ratio = exact / exact.sin();
            let error = (arc.phi_over_sine - ratio).abs();
            assert!(error <= 2e-7 * ratio, "{} {ratio}", arc.phi_over_sine);
        }
    }
}
