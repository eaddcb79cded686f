//! [`Pair::checked`] and [`blend`] in SSE2's registers, on x86-64: one
//! load per quaternion, its components widened to f64 two at a time, the
//! sums of products taken in the lanes, in the order of the portable
//! functions (`(x x' + z z') + (y y' + w w')`), and both coefficients in
//! the two lanes of one register, so that both give the same bits.
//! Written out because the compiler, left to the portable code, loads each
//! quaternion in two halves and moves its components through the general
//! registers one by one; with these, a call in a loop compiles to about
//! 130 instructions on the default target.

use super::{bounded, Arc, Pair, SIN};
use crate::Quat;
use core::arch::x86_64::{
    __m128, __m128d, _mm_add_pd, _mm_add_ps, _mm_and_pd, _mm_andnot_pd, _mm_cvtpd_ps, _mm_cvtps_pd,
    _mm_cvtsd_f64, _mm_loadu_ps, _mm_movehl_ps, _mm_mul_pd, _mm_mul_ps, _mm_or_pd, _mm_set1_pd,
    _mm_set_pd, _mm_shuffle_ps, _mm_storeu_ps, _mm_unpackhi_pd, _mm_unpacklo_pd,
};

/// The four lanes of a quaternion, `x, y, z, w`.
#[inline(always)]
#[allow(unsafe_code)]
fn lanes(q: &Quat) -> __m128 {
    // SAFETY: SSE2, which this module is compiled only with; reads the 16
    // bytes of a `Quat`, `repr(C)` of four f32, through a reference to it
    // (`loadu` needs no alignment).
    unsafe { _mm_loadu_ps(core::ptr::from_ref(q).cast()) }
}

impl Pair {
    /// [`Pair::of`] for inputs that are [`bounded`], `None` for the others,
    /// checked on the squared norms first: they make no NaN from
    /// infinities (the dot product would: inf * 0, raising the
    /// invalid-operation flag, a SIGFPE where a program unmasks it).
    #[inline(always)]
    #[allow(unsafe_code)]
    pub(in crate::quat::slerp) fn checked(a: Quat, b: Quat) -> Option<Self> {
        // SAFETY: SSE2 arithmetic on registers, which cannot fault with
        // the default MXCSR (exceptions masked).
        unsafe {
            let (va, vb) = (lanes(&a), lanes(&b));
            let (al, ah) = (_mm_cvtps_pd(va), _mm_cvtps_pd(_mm_movehl_ps(va, va)));
            let (bl, bh) = (_mm_cvtps_pd(vb), _mm_cvtps_pd(_mm_movehl_ps(vb, vb)));
            // [x^2 + z^2, y^2 + w^2]
            let squares = |l: __m128d, h: __m128d| _mm_add_pd(_mm_mul_pd(l, l), _mm_mul_pd(h, h));
            // [p0 + p1, q0 + q1]
            let sums =
                |p: __m128d, q: __m128d| _mm_add_pd(_mm_unpacklo_pd(p, q), _mm_unpackhi_pd(p, q));
            let high = |v: __m128d| _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
            let norms = sums(squares(al, ah), squares(bl, bh));
            let (n2, on2) = (_mm_cvtsd_f64(norms), high(norms));
            if !bounded([n2, on2]) {
                return None;
            }
            // [x x' + z z', y y' + w w']
            let products = _mm_add_pd(_mm_mul_pd(al, bl), _mm_mul_pd(ah, bh));
            let dot = _mm_add_pd(products, _mm_unpackhi_pd(products, products));
            Some(Self {
                n2,
                on2,
                dot: _mm_cvtsd_f64(dot),
            })
        }
    }
}

/// The portable `blend`: slerp's coefficients `[c0, c1]` of `arc` and
/// `alpha` ([`Arc::coefficients`], both in the two f64 lanes of one
/// register, each lane the portable function's operations), `c1` with the
/// sign of `toward`, rounded to f32, and `c0 a + c1 b` as
/// [`Quat::weighted_sum`] rounds it.
#[inline(always)]
#[allow(unsafe_code)]
pub(in crate::quat::slerp) fn blend(a: Quat, b: Quat, arc: Arc, alpha: f32, toward: f64) -> Quat {
    let mut out = Quat::NAN;
    // SAFETY: SSE2 arithmetic on registers; writes the 16 bytes of a
    // `Quat` through a mutable reference to it (`storeu` needs no
    // alignment).
    unsafe {
        let alpha = f64::from(alpha);
        // [1 - alpha, alpha]
        let shares = _mm_set_pd(alpha, 1.0 - alpha);
        let s = _mm_mul_pd(_mm_mul_pd(shares, shares), _mm_set1_pd(arc.phi_squared));
        let k = |c: f64| _mm_set1_pd(c);
        let q = _mm_add_pd(
            _mm_add_pd(k(SIN[0]), _mm_mul_pd(s, k(SIN[1]))),
            _mm_mul_pd(
                _mm_mul_pd(s, s),
                _mm_add_pd(k(SIN[2]), _mm_mul_pd(s, k(SIN[3]))),
            ),
        );
        let sinc = _mm_add_pd(k(1.0), _mm_mul_pd(s, q));
        let c = _mm_mul_pd(_mm_mul_pd(shares, k(arc.phi_over_sine)), sinc);
        // copysign of the high lane.
        let sign = _mm_set_pd(-0.0, 0.0);
        let c = _mm_or_pd(_mm_andnot_pd(sign, c), _mm_and_pd(sign, k(toward)));
        let c = _mm_cvtpd_ps(c);
        let (c0, c1) = (_mm_shuffle_ps::<0x00>(c, c), _mm_shuffle_ps::<0x55>(c, c));
        let r = _mm_add_ps(_mm_mul_ps(lanes(&a), c0), _mm_mul_ps(lanes(&b), c1));
        _mm_storeu_ps(core::ptr::from_mut(&mut out).cast(), r);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::tests::{rare_pairs, unit};
    use super::super::{Arc, Pair};
    use super::blend;
    use crate::Quat;
    use rand::{Rng, SeedableRng};

    fn bits(q: Quat) -> [u32; 4] {
        q.to_array().map(f32::to_bits)
    }

    /// The registers' pair and blend are the portable functions', bit for
    /// bit: on random unit pairs, pairs off unit norm, and the rare pairs
    /// (where the pair's values may be NaN, and `applies` is false in both).
    #[test]
    fn registers_give_the_portable_bits() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(41);
        let mut pairs: std::vec::Vec<(Quat, Quat)> = rare_pairs().to_vec();
        // Fewer under Miri, which interprets every instruction.
        let draws = if cfg!(miri) { 100 } else { 100_000 };
        for i in 0..draws {
            let (a, b) = (unit(&mut rng), unit(&mut rng));
            let scale = if i % 4 == 0 {
                rng.random_range(1e-3..1e3f32)
            } else {
                1.0
            };
            pairs.push((a.map(|c| c * scale), b.map(|c| c * scale)));
        }
        for (a, b) in pairs {
            let portable = Pair::of(a, b);
            let Some(fast) = Pair::checked(a, b) else {
                assert!(!portable.applies(), "{a:?} {b:?}");
                continue;
            };
            assert_eq!(fast.applies(), portable.applies(), "{a:?} {b:?}");
            if !portable.applies() {
                continue;
            }
            let lengths = |p: Pair| [p.n2, p.on2, p.dot].map(f64::to_bits);
            assert_eq!(lengths(fast), lengths(portable), "{a:?} {b:?}");
            let arc = portable.arc();
            let alpha = rng.random_range(0.0..=1.0f32).max(f32::MIN_POSITIVE);
            let toward = portable.dot;
            let [c0, c1] = arc.coefficients(alpha);
            let expected = a.weighted_sum(c0 as f32, b, c1.copysign(toward) as f32);
            let got = blend(a, b, arc, alpha, toward);
            assert_eq!(bits(got), bits(expected), "{a:?} {b:?} {alpha}");
        }
        // Both signs of `toward`, and an arc given outright.
        let arc = Arc {
            phi_squared: 0.25,
            phi_over_sine: 1.04,
        };
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        for toward in [1.0, -1.0, 0.0, -0.0] {
            let [c0, c1] = arc.coefficients(0.3);
            let expected = a.weighted_sum(c0 as f32, b, c1.copysign(toward) as f32);
            assert_eq!(bits(blend(a, b, arc, 0.3, toward)), bits(expected));
        }
    }
}
