//! Slerp's in-plane formula in f64, on x86-64 and AArch64: what
//! [`Quat::slerp`] returns there for `alpha` in (0, 1], and what the
//! vectorized lanes of [`Quat::slerp_slice`] compute, one set of functions
//! for both, so that the two agree bit for bit.
//!
//! The arc comes from the wedge of the two inputs, not from a rotation
//! between them: `|a ^ b|^2`, the sum of the squares of the six 2x2 minors
//! of `a` and `b`, is `|a|^2 |b|^2 sin^2(phi)` and needs neither their dot
//! product nor their norms first, so it starts as soon as the inputs are
//! loaded. Over `(|a| |b| + |a . b|)^2` it is `tan^2(phi / 2)`, and from
//! that one quotient two polynomials give `phi^2` and `phi / sin(phi)`
//! ([`Pair::arc`]), without a square root; the result is
//! `sin((1 - alpha) phi) / sin(phi) a + sin(alpha phi) / sin(phi) b`,
//! `b` negated when the dot product is negative (the notes' `cn`), each
//! coefficient `s phi / sin(phi)` times the `sin(x) / x` of its share `s`
//! of the arc, which is a polynomial in `x^2 = s^2 phi^2` ([`Pair::slerp`]).
//! One division, no square root and no select on the way from the inputs
//! to the result: the chain of dependent operations that bounds a call's
//! time is short, and only the checks that ordinary inputs pass branch.

use super::kernels_f64::{ATAN, SIN};
use super::{NEARLY_UNIT, SMALL_ANGLE};
use crate::float::SQUARES_UNDERFLOW;
use crate::Quat;

/// 2^32, the largest squared norm the evaluation takes: components below
/// 2^16, whose products and sums of squares stay far from overflow (at
/// most 2^69), so that no operation makes an infinity, and none a NaN.
pub(super) const NORM_SQUARED_LIMIT: f32 = 4_294_967_296.0;

/// What the evaluation needs of a pair `(a, b)`: squared norms, dot
/// product and squared wedge.
#[derive(Clone, Copy)]
pub(super) struct Pair {
    /// `|a|^2`.
    pub(super) n2: f32,
    /// `|b|^2`.
    pub(super) on2: f32,
    /// `a . b`.
    pub(super) dot: f32,
    /// `|a ^ b|^2 = |a|^2 |b|^2 - (a . b)^2`, without the cancellation.
    pub(super) wedge: f32,
}

impl Pair {
    /// The squared norms, dot product and squared wedge of `a` and `b`.
    ///
    /// # Preconditions
    ///
    /// Components within 2^16 in magnitude (where nothing overflows);
    /// [`Quat::slerp`] checks the squared norms first.
    #[inline(always)]
    pub(super) fn of(a: Quat, b: Quat) -> Self {
        let minor = |p: f32, q: f32, r: f32, s: f32| p * s - q * r;
        let m = [
            minor(a.w, a.x, b.w, b.x),
            minor(a.w, a.y, b.w, b.y),
            minor(a.w, a.z, b.w, b.z),
            minor(a.x, a.y, b.x, b.y),
            minor(a.x, a.z, b.x, b.z),
            minor(a.y, a.z, b.y, b.z),
        ];
        let wedge = ((m[0] * m[0] + m[1] * m[1]) + (m[2] * m[2] + m[3] * m[3]))
            + (m[4] * m[4] + m[5] * m[5]);
        Self {
            n2: a.norm_squared(),
            on2: b.norm_squared(),
            dot: a.dot(b),
            wedge,
        }
    }

    /// Whether the evaluation gives slerp's result for this pair, as far
    /// as that is known before the angle: squared norms within
    /// [`NORM_SQUARED_LIMIT`] and within 1e-6 of each other (relatively),
    /// and a squared wedge large enough not to have lost precision to
    /// underflow. Written to be false for NaN.
    #[inline(always)]
    pub(super) fn applies(&self) -> bool {
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let near_unit = !((self.n2 - self.on2).abs() > NEARLY_UNIT * self.on2);
        near_unit
            & (self.n2 <= NORM_SQUARED_LIMIT)
            & (self.on2 <= NORM_SQUARED_LIMIT)
            & (self.wedge >= SQUARES_UNDERFLOW)
    }

    /// The arc from `a` to `cn(b)`: the square of the notes' `phi` in
    /// [0, pi/2] and `phi / sin(phi)`, in f64, from the tangent of the half
    /// angle, without a square root and with one division.
    ///
    /// `tan^2(phi / 2) = |a ^ b|^2 / (|a| |b| + |a . b|)^2`, with `|a| |b|`
    /// taken as `(|a|^2 + |b|^2) / 2`: the squared norms are within 1e-6 of
    /// each other (relatively) where the evaluation applies, where the two
    /// differ by less than 1.3e-13 of either. With `t^2` that quotient (in
    /// [0, 1]) and `atan(t) = t h(t^2)` (`h = 1 + t^2 P(t^2)`, the
    /// polynomial [`ATAN`]), `phi = 2 t h`, so that
    /// `phi^2 = 4 t^2 h^2` and, as `sin(phi) = 2 t / (1 + t^2)`,
    /// `phi / sin(phi) = h (1 + t^2)`: both functions of `t^2` alone.
    ///
    /// # Preconditions
    ///
    /// [`applies`](Self::applies) (or, in vectorized lanes, squared norms
    /// put in their place that are positive).
    ///
    /// # Accuracy
    ///
    /// Against the f64 arccosine of the same f32 inputs, on 10^6 random
    /// unit pairs: `phi / sin(phi)` within 1.1e-7 relative; `phi` within
    /// 1.9e-7 relative for `phi` in (0.5, 1.5) and 8.3e-7 down to 0.01 rad,
    /// where the f32 rounding of the minors dominates (the unit tests hold
    /// the first to 2e-7 and `phi` to 1e-6, on 10,000 pairs).
    #[inline(always)]
    pub(super) fn arc(&self) -> Arc {
        let m = 0.5 * (f64::from(self.n2) + f64::from(self.on2));
        let d = m + f64::from(self.dot.abs());
        let t2 = f64::from(self.wedge) / (d * d);
        let h = 1.0 + t2 * atan_polynomial(t2);
        Arc {
            phi_squared: (4.0 * t2) * (h * h),
            phi_over_sine: h * (1.0 + t2),
        }
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
        let [c0, c1] = arc.coefficients(alpha);
        a.weighted_sum(c0 as f32, b, (c1 as f32).copysign(self.dot))
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
    /// Slerp's coefficients `sin((1 - alpha) phi) / sin(phi)` and
    /// `sin(alpha phi) / sin(phi)` for `alpha` in (0, 1], before their
    /// rounding to f32: each `s phi / sin(phi) sinc(s^2 phi^2)` for its
    /// share `s` of the arc.
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
        // Squared norms first: they make no NaN from infinities (the
        // minors would: inf - inf).
        let bounded =
            self.norm_squared() <= NORM_SQUARED_LIMIT && other.norm_squared() <= NORM_SQUARED_LIMIT;
        if !bounded {
            return None;
        }
        let pair = Pair::of(self, other);
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
