//! The slice on x86-64 with AVX: eight pairs at a time, in AVX registers
//! written by hand.
//!
//! Each block of eight pairs goes through the operations of
//! `Quat::slerp_f64`'s evaluation ([`Pair::of`], [`Pair::applies`],
//! `atan2_of_root`, [`Pair::slerp`] and `sin_to_quarter_turn`), the same
//! ones in the same order: the f32 part in eight lanes, the f64 part in
//! two halves of four. No fused multiply-add is used (it rounds once where
//! the single call rounds twice), so every lane's result is the single
//! call's, bit for bit; the unit test below checks it against
//! `slerp_f64` on random pairs and on each class of pair it leaves to the
//! f32 evaluation. Lanes whose pair that evaluation does not take are done
//! again by `slerp`, as in the portable lanes.
//!
//! Why by hand: the compiler vectorizes the portable lanes too, but moves
//! the quaternions between their layout (`w, x, y, z` of one, then the
//! next) and one register per component with about three times the
//! shuffles of the transpose below, and spills more; by hand the slice
//! takes about two thirds of the time.
//!
//! [`Pair::of`]: super::super::slerp_f64::Pair::of
//! [`Pair::applies`]: super::super::slerp_f64::Pair::applies
//! [`Pair::slerp`]: super::super::slerp_f64::Pair::slerp

use super::super::interpolate::NEARLY_UNIT;
use super::super::slerp_f64::{INVERSE_SINE_SQUARED_LIMIT, NORM_SQUARED_LIMIT, SMALL_ANGLE_F64};
use super::Quat;
use crate::float::{ATAN_F64, SIN_F64, SQUARES_UNDERFLOW};
use core::arch::x86_64::{
    __m128, __m256, __m256d, _mm256_add_pd, _mm256_add_ps, _mm256_and_pd, _mm256_and_ps,
    _mm256_andnot_ps, _mm256_blendv_pd, _mm256_blendv_ps, _mm256_castpd_ps, _mm256_castps128_ps256,
    _mm256_castps256_ps128, _mm256_castps_pd, _mm256_cmp_pd, _mm256_cmp_ps, _mm256_cvtpd_ps,
    _mm256_cvtps_pd, _mm256_div_pd, _mm256_extractf128_ps, _mm256_insertf128_ps, _mm256_min_pd,
    _mm256_movemask_pd, _mm256_movemask_ps, _mm256_mul_pd, _mm256_mul_ps, _mm256_or_pd,
    _mm256_or_ps, _mm256_set1_pd, _mm256_set1_ps, _mm256_sqrt_ps, _mm256_sub_pd, _mm256_sub_ps,
    _mm256_unpackhi_pd, _mm256_unpackhi_ps, _mm256_unpacklo_pd, _mm256_unpacklo_ps, _mm256_xor_pd,
    _mm_loadu_ps, _mm_storeu_ps, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_NGT_UQ,
};

/// Pairs per block.
const LANES: usize = 8;

/// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1].
#[inline(always)]
pub(super) fn slerp_in_blocks<T: Copy>(
    starts: &[T],
    ends: &[T],
    alpha: f32,
    out: &mut [T],
    rotation: impl Fn(&T) -> &Quat,
    finish: impl Fn(&T, &T, Quat) -> T,
) {
    let blocks = starts
        .chunks_exact(LANES)
        .zip(ends.chunks_exact(LANES))
        .zip(out.chunks_exact_mut(LANES));
    let mut whole = 0;
    for ((s, e), o) in blocks {
        let (Ok(s), Ok(e), Ok(o)) = (
            <&[T; LANES]>::try_from(s),
            <&[T; LANES]>::try_from(e),
            <&mut [T; LANES]>::try_from(o),
        ) else {
            break;
        };
        let [s0, s1, s2, s3, s4, s5, s6, s7] = s;
        let [e0, e1, e2, e3, e4, e5, e6, e7] = e;
        let r = &rotation;
        let (q, done) = eight(
            [r(s0), r(s1), r(s2), r(s3), r(s4), r(s5), r(s6), r(s7)],
            [r(e0), r(e1), r(e2), r(e3), r(e4), r(e5), r(e6), r(e7)],
            alpha,
        );
        for i in 0..LANES {
            o[i] = finish(&s[i], &e[i], q[i]);
        }
        if done != 0xff {
            for i in 0..LANES {
                if done & (1 << i) == 0 {
                    o[i] = finish(&s[i], &e[i], rotation(&s[i]).slerp(*rotation(&e[i]), alpha));
                }
            }
        }
        whole += LANES;
    }
    let rest = starts.iter().zip(ends).zip(out.iter_mut()).skip(whole);
    for ((a, b), o) in rest {
        *o = finish(a, b, rotation(a).slerp(*rotation(b), alpha));
    }
}

/// `slerp_f64`'s evaluation of eight pairs, without a branch: the results,
/// and a bit for each pair (bit `i` for pair `i`) set where that result is
/// `slerp`'s (where it is not, the value is some quaternion, NaN or
/// infinite components possible, to be replaced).
///
/// Lanes: the pairs in the order 0, 2, 4, 6, 1, 3, 5, 7, which is the
/// order the transpose by unpacking within 128-bit halves gives; the low
/// half of an f32 register (pairs 0, 2, 4, 6) is the first f64 register,
/// the high half the second.
#[allow(unsafe_code)]
#[inline(always)]
fn eight(a: [&Quat; LANES], b: [&Quat; LANES], alpha: f32) -> ([Quat; LANES], u32) {
    // SAFETY: every intrinsic here needs AVX, which this module is compiled
    // only with (`target_feature = "avx"`). The loads read, and the stores
    // write, 16 bytes at the address of a `Quat`, which is `repr(C)` of
    // four f32 (16 bytes; `loadu` and `storeu` need no alignment), inside
    // the arrays `a`, `b` and `out`. The rest works on registers only, and
    // AVX arithmetic cannot fault with the default MXCSR (exceptions
    // masked).
    unsafe {
        let load = |q: &Quat| _mm_loadu_ps((q as *const Quat).cast::<f32>());
        let pair =
            |lo: __m128, hi: __m128| _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(lo), hi);
        let (pd, ps) = (_mm256_castps_pd, _mm256_castpd_ps);
        // Four registers of two quaternions each, [q0 | q1], [q2 | q3],
        // [q4 | q5], [q6 | q7], to one register per component, lanes
        // [0 2 4 6 | 1 3 5 7].
        let transpose = |q: [&Quat; LANES]| {
            let r = [
                pair(load(q[0]), load(q[1])),
                pair(load(q[2]), load(q[3])),
                pair(load(q[4]), load(q[5])),
                pair(load(q[6]), load(q[7])),
            ];
            let t0 = _mm256_unpacklo_ps(r[0], r[1]);
            let t1 = _mm256_unpackhi_ps(r[0], r[1]);
            let t2 = _mm256_unpacklo_ps(r[2], r[3]);
            let t3 = _mm256_unpackhi_ps(r[2], r[3]);
            [
                ps(_mm256_unpacklo_pd(pd(t0), pd(t2))),
                ps(_mm256_unpackhi_pd(pd(t0), pd(t2))),
                ps(_mm256_unpacklo_pd(pd(t1), pd(t3))),
                ps(_mm256_unpackhi_pd(pd(t1), pd(t3))),
            ]
        };
        let [aw, ax, ay, az] = transpose(a);
        let [bw, bx, by, bz] = transpose(b);
        let (add, sub, mul) = (_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps);
        let dot4 = |p: [__m256; 4], q: [__m256; 4]| {
            add(
                add(add(mul(p[0], q[0]), mul(p[1], q[1])), mul(p[2], q[2])),
                mul(p[3], q[3]),
            )
        };

        // Pair::of: squared norms, dot product, the six minors and the
        // squared wedge.
        let n2 = dot4([aw, ax, ay, az], [aw, ax, ay, az]);
        let on2 = dot4([bw, bx, by, bz], [bw, bx, by, bz]);
        let dot = dot4([aw, ax, ay, az], [bw, bx, by, bz]);
        let minor = |p, q, r, s| sub(mul(p, s), mul(q, r));
        let m = [
            minor(aw, ax, bw, bx),
            minor(aw, ay, bw, by),
            minor(aw, az, bw, bz),
            minor(ax, ay, bx, by),
            minor(ax, az, bx, bz),
            minor(ay, az, by, bz),
        ];
        let sq = |x| mul(x, x);
        let wedge = add(
            add(add(sq(m[0]), sq(m[1])), add(sq(m[2]), sq(m[3]))),
            add(sq(m[4]), sq(m[5])),
        );

        // Pair::applies (the bounds on the squared norms are checked once:
        // slerp_f64 checks them twice, with the same result).
        let limit = _mm256_set1_ps(NORM_SQUARED_LIMIT);
        let bounded = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_LE_OQ>(n2, limit),
            _mm256_cmp_ps::<_CMP_LE_OQ>(on2, limit),
        );
        let sign32 = _mm256_set1_ps(-0.0);
        let spread = _mm256_andnot_ps(sign32, sub(n2, on2));
        // `!(spread > NEARLY_UNIT * on2)`: "not greater", true for NaN.
        let near_unit = _mm256_cmp_ps::<_CMP_NGT_UQ>(spread, mul(_mm256_set1_ps(NEARLY_UNIT), on2));
        let resolved = _mm256_cmp_ps::<_CMP_GE_OQ>(wedge, _mm256_set1_ps(SQUARES_UNDERFLOW));
        let applies = _mm256_and_ps(_mm256_and_ps(bounded, near_unit), resolved);
        // As in the portable lanes: a positive squared wedge where the
        // evaluation does not apply, so that nothing divides by zero.
        let wedge = _mm256_blendv_ps(_mm256_set1_ps(1.0), wedge, applies);

        // To f64, in two halves of four lanes, and back.
        let halves = |v: __m256| {
            [
                _mm256_cvtps_pd(_mm256_castps256_ps128(v)),
                _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v)),
            ]
        };
        let join = |lo: __m256d, hi: __m256d| pair(_mm256_cvtpd_ps(lo), _mm256_cvtpd_ps(hi));
        let (addd, subd, muld, divd) = (_mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd, _mm256_div_pd);
        let splat = _mm256_set1_pd;
        let sign64 = splat(-0.0);
        let w = halves(wedge);
        let x = halves(dot);
        // x * x, of |x| in atan2_of_root and of x in Pair::slerp: the same.
        let x2 = [muld(x[0], x[0]), muld(x[1], x[1])];

        // atan2_of_root(w, |x|): the smaller of w and x^2 over the larger,
        // its square root in f32, the polynomial, the quarter turn.
        let ratio = |k: usize| {
            let below = _mm256_cmp_pd::<_CMP_LT_OQ>(w[k], x2[k]);
            divd(
                _mm256_blendv_pd(x2[k], w[k], below),
                _mm256_blendv_pd(w[k], x2[k], below),
            )
        };
        let z = [ratio(0), ratio(1)];
        let roots = halves(_mm256_sqrt_ps(join(z[0], z[1])));
        let c = ATAN_F64;
        let angle = |k: usize| {
            let (z, u) = (z[k], roots[k]);
            let z2 = muld(z, z);
            let z4 = muld(z2, z2);
            let low = addd(
                addd(splat(c[0]), muld(z, splat(c[1]))),
                muld(z2, addd(splat(c[2]), muld(z, splat(c[3])))),
            );
            let high = addd(
                addd(splat(c[4]), muld(z, splat(c[5]))),
                muld(z2, addd(splat(c[6]), muld(z, splat(c[7])))),
            );
            let p = addd(low, muld(z4, high));
            let a = addd(u, muld(u, muld(z, p)));
            let d = subd(x2[k], w[k]);
            let half = splat(0.5);
            let quarter = subd(half, _mm256_or_pd(half, _mm256_and_pd(d, sign64)));
            let flipped = _mm256_xor_pd(a, _mm256_and_pd(d, sign64));
            addd(muld(quarter, splat(core::f64::consts::FRAC_PI_2)), flipped)
        };
        let phi = [angle(0), angle(1)];
        let small = splat(SMALL_ANGLE_F64);
        let past_small = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(phi[0], small))
            | (_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(phi[1], small)) << 4);
        let lanes_done = (_mm256_movemask_ps(applies) & past_small) as u32;

        // Pair::slerp: r = 1 / sin(phi) from the wedge and the dot product
        // (its square root in f32), the two sines, the weighted sum.
        let inverse_sine_squared = |k: usize| {
            let limit = splat(INVERSE_SINE_SQUARED_LIMIT);
            _mm256_min_pd(divd(addd(w[k], x2[k]), w[k]), limit)
        };
        let r = halves(_mm256_sqrt_ps(join(
            inverse_sine_squared(0),
            inverse_sine_squared(1),
        )));
        let s = SIN_F64;
        let sine = |x: __m256d| {
            let s2 = muld(x, x);
            let p = addd(
                addd(splat(s[0]), muld(s2, splat(s[1]))),
                muld(muld(s2, s2), addd(splat(s[2]), muld(s2, splat(s[3])))),
            );
            addd(x, muld(muld(x, s2), p))
        };
        let alpha = splat(f64::from(alpha));
        let rest = subd(splat(1.0), alpha);
        let c0 = join(
            muld(sine(muld(rest, phi[0])), r[0]),
            muld(sine(muld(rest, phi[1])), r[1]),
        );
        let c1 = join(
            muld(sine(muld(alpha, phi[0])), r[0]),
            muld(sine(muld(alpha, phi[1])), r[1]),
        );
        // (c1 as f32).copysign(dot)
        let c1 = _mm256_or_ps(_mm256_andnot_ps(sign32, c1), _mm256_and_ps(sign32, dot));
        let weigh = |p, q| add(mul(c0, p), mul(c1, q));
        let (qw, qx, qy, qz) = (weigh(aw, bw), weigh(ax, bx), weigh(ay, by), weigh(az, bz));

        // Back to four registers of two quaternions each.
        let u0 = _mm256_unpacklo_ps(qw, qx);
        let u1 = _mm256_unpackhi_ps(qw, qx);
        let v0 = _mm256_unpacklo_ps(qy, qz);
        let v1 = _mm256_unpackhi_ps(qy, qz);
        let r = [
            ps(_mm256_unpacklo_pd(pd(u0), pd(v0))),
            ps(_mm256_unpackhi_pd(pd(u0), pd(v0))),
            ps(_mm256_unpacklo_pd(pd(u1), pd(v1))),
            ps(_mm256_unpackhi_pd(pd(u1), pd(v1))),
        ];
        let mut out = [Quat::IDENTITY; LANES];
        let mut store = |i: usize, v: __m128| {
            _mm_storeu_ps((&mut out[i] as *mut Quat).cast::<f32>(), v);
        };
        for (k, &v) in r.iter().enumerate() {
            store(2 * k, _mm256_castps256_ps128(v));
            store(2 * k + 1, _mm256_extractf128_ps::<1>(v));
        }
        // Lane k holds pair 2k (k < 4) or pair 2(k - 4) + 1.
        let mut done = 0;
        for (lane, pair) in [0, 2, 4, 6, 1, 3, 5, 7].into_iter().enumerate() {
            done |= ((lanes_done >> lane) & 1) << pair;
        }
        (out, done)
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::slerp_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
    use super::*;
    use rand::{Rng, SeedableRng};

    /// A pair is done exactly where `slerp_f64` takes it, with its result,
    /// bit for bit, in whichever of the eight lanes it is: random unit
    /// pairs, and each class of input it leaves to the f32 evaluation,
    /// every one in every lane among random pairs.
    #[test]
    fn lanes_take_exactly_the_pairs_slerp_f64_takes() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(15);
        let mut specials = std::vec::Vec::from(rare_pairs());
        specials.push(just_past_the_small_angles());
        let mut blocks: std::vec::Vec<[(Quat, Quat); LANES]> = (0..2_000)
            .map(|_| core::array::from_fn(|_| (unit(&mut rng), unit(&mut rng))))
            .collect();
        for &special in &specials {
            for lane in 0..LANES {
                let mut block: [(Quat, Quat); LANES] =
                    core::array::from_fn(|_| (unit(&mut rng), unit(&mut rng)));
                block[lane] = special;
                blocks.push(block);
            }
        }
        let (mut done_count, mut left_count) = (0, 0);
        for block in blocks {
            let alpha = rng.random_range(0.0..=1.0f32).max(f32::MIN_POSITIVE);
            let (q, done) = eight(
                block.each_ref().map(|p| &p.0),
                block.each_ref().map(|p| &p.1),
                alpha,
            );
            for (i, &(a, b)) in block.iter().enumerate() {
                let expected = a.slerp_f64(b, alpha);
                assert_eq!(done & (1 << i) != 0, expected.is_some(), "{a:?} {b:?}");
                match expected {
                    Some(e) => {
                        assert_eq!(
                            q[i].to_array().map(f32::to_bits),
                            e.to_array().map(f32::to_bits),
                            "{a:?} {b:?} {alpha}"
                        );
                        done_count += 1;
                    }
                    None => left_count += 1,
                }
            }
        }
        // Every pair but the eight rare ones, each in each lane.
        assert_eq!(left_count, 8 * LANES);
        assert_eq!(
            done_count,
            2_000 * LANES + specials.len() * LANES * LANES - left_count
        );
    }

    /// Blocks, the pairs left to `slerp` in them, and the tail: slices of
    /// every length up to three blocks and a bit, each pair `slerp`'s
    /// result, bit for bit.
    #[test]
    fn slices_of_every_length_are_slerps_bit_for_bit() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(16);
        let rare = rare_pairs();
        let pairs: std::vec::Vec<(Quat, Quat)> = (0..3 * LANES + 5)
            .map(|i| match i % 5 {
                3 => rare[i % rare.len()],
                _ => (unit(&mut rng), unit(&mut rng)),
            })
            .collect();
        let (starts, ends): (std::vec::Vec<Quat>, std::vec::Vec<Quat>) =
            pairs.iter().copied().unzip();
        for len in 0..=pairs.len() {
            let mut out = std::vec![Quat::NAN; len];
            super::super::super::Quat::slerp_slice(&starts[..len], &ends[..len], 0.3, &mut out);
            for (i, q) in out.iter().enumerate() {
                let e = starts[i].slerp(ends[i], 0.3);
                assert!(
                    q.to_array().map(f32::to_bits) == e.to_array().map(f32::to_bits)
                        || (q.is_nan() && e.is_nan()),
                    "{len} {i}: {q:?} {e:?}"
                );
            }
        }
    }
}
