//! The slice on x86-64 with AVX: sixteen pairs at a time, in AVX
//! registers written by hand.
//!
//! The pairs go through the operations of `Quat::slerp_f64`'s evaluation
//! ([`Pair::of`], [`Pair::applies`], `atan2_of_root`, [`Pair::slerp`] and
//! `sin_to_quarter_turn`), the same ones in the same order: the f32 part in
//! registers of eight lanes, the f64 part in registers of four. No fused
//! multiply-add is used (it rounds once where the single call rounds
//! twice), so every lane's result is the single call's, bit for bit; the
//! unit tests below check it against `slerp_f64` on random pairs and on
//! each class of pair it leaves to the f32 evaluation, in every lane.
//! Lanes whose pair that evaluation does not take are done again by
//! `slerp`, as in the portable lanes.
//!
//! The evaluation of one pair is a long chain of dependent operations (two
//! divisions and two square roots among them), longer than the processor
//! can look ahead past; two blocks of eight pairs go through it together,
//! stage by stage, so that while one block's lanes wait for a result the
//! other's have work. The compiler vectorizes the portable lanes too, but
//! one block at a time, and it moves the quaternions between their layout
//! (`w, x, y, z` of one, then the next) and one register per component with
//! about three times the shuffles of the transpose here. Medians of one
//! process, 1,024 random unit pairs, `-C target-cpu=x86-64-v3`, on an AMD
//! EPYC (Zen 3): 4.9 ns per pair here against 8.7 for the portable lanes
//! (`slerp_slice`), 5.7 against 9.3 (`RigTForm::interpolate_slice`).
//!
//! [`Pair::of`]: super::super::slerp_f64::Pair::of
//! [`Pair::applies`]: super::super::slerp_f64::Pair::applies
//! [`Pair::slerp`]: super::super::slerp_f64::Pair::slerp

use super::super::interpolate::NEARLY_UNIT;
use super::super::slerp_f64::{INVERSE_SINE_SQUARED_LIMIT, NORM_SQUARED_LIMIT, SMALL_ANGLE_F64};
use super::{Quat, Slerped};
use crate::float::{ATAN_F64, SIN_F64, SQUARES_UNDERFLOW};
use crate::RigTForm;
use core::arch::x86_64::{
    __m128, __m256, __m256d, _mm256_add_pd, _mm256_add_ps, _mm256_and_pd, _mm256_and_ps,
    _mm256_andnot_ps, _mm256_blendv_pd, _mm256_castpd_ps, _mm256_castps128_ps256,
    _mm256_castps256_ps128, _mm256_castps_pd, _mm256_cmp_pd, _mm256_cmp_ps, _mm256_cvtpd_ps,
    _mm256_cvtps_pd, _mm256_div_pd, _mm256_extractf128_ps, _mm256_insertf128_ps, _mm256_loadu_ps,
    _mm256_min_pd, _mm256_movemask_pd, _mm256_movemask_ps, _mm256_mul_pd, _mm256_mul_ps,
    _mm256_or_pd, _mm256_or_ps, _mm256_set1_pd, _mm256_set1_ps, _mm256_setzero_pd,
    _mm256_setzero_ps, _mm256_storeu_ps, _mm256_sub_pd, _mm256_sub_ps, _mm256_unpackhi_pd,
    _mm256_unpackhi_ps, _mm256_unpacklo_pd, _mm256_unpacklo_ps, _mm256_xor_pd, _mm_loadu_ps,
    _mm_sqrt_ps, _mm_storeu_ps, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_NGT_UQ,
};

/// Pairs per register of f32 lanes.
const LANES: usize = 8;

/// Blocks of [`LANES`] pairs evaluated together.
const BLOCKS: usize = 2;

/// Pairs per step.
pub(crate) const PAIRS: usize = LANES * BLOCKS;

/// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1]: steps
/// of [`PAIRS`] pairs, and the last pairs (fewer) in a step of their own,
/// padded with copies of the first of them.
#[inline(always)]
pub(super) fn slerp_in_steps<T: Slerped>(starts: &[T], ends: &[T], alpha: f32, out: &mut [T]) {
    let steps = starts
        .chunks_exact(PAIRS)
        .zip(ends.chunks_exact(PAIRS))
        .zip(out.chunks_exact_mut(PAIRS));
    let mut whole = 0;
    for ((s, e), o) in steps {
        let (Ok(s), Ok(e), Ok(o)) = (
            <&[T; PAIRS]>::try_from(s),
            <&[T; PAIRS]>::try_from(e),
            <&mut [T; PAIRS]>::try_from(o),
        ) else {
            break;
        };
        step(s, e, alpha, o);
        whole += PAIRS;
    }
    let left = starts
        .len()
        .min(ends.len())
        .min(out.len())
        .saturating_sub(whole);
    if let (Some(&s0), Some(&e0), true) = (starts.get(whole), ends.get(whole), left > 0) {
        let (mut s, mut e, mut o) = ([s0; PAIRS], [e0; PAIRS], [s0; PAIRS]);
        let pairs = starts.iter().zip(ends).skip(whole);
        for ((a, b), (s, e)) in pairs.zip(s.iter_mut().zip(e.iter_mut())) {
            (*s, *e) = (*a, *b);
        }
        step(&s, &e, alpha, &mut o);
        for (to, from) in out.iter_mut().skip(whole).take(left).zip(&o) {
            *to = *from;
        }
    }
}

/// One step: [`Slerped::lerp_rest_of`] the pairs, then their rotations by
/// [`evaluate`], and `slerp` for the pairs it leaves.
#[inline(always)]
fn step<T: Slerped>(s: &[T; PAIRS], e: &[T; PAIRS], alpha: f32, o: &mut [T; PAIRS]) {
    T::lerp_rest_of(s, e, alpha, o);
    let done = evaluate(s, e, alpha, o);
    if done != (1 << PAIRS) - 1 {
        for i in 0..PAIRS {
            if done & (1 << i) == 0 {
                *o[i].rotation_mut() = s[i].rotation().slerp(*e[i].rotation(), alpha);
            }
        }
    }
}

/// `slerp_f64`'s evaluation of the rotations of [`PAIRS`] pairs, without a
/// branch, written to the rotations of `o`; returned, a bit for each pair
/// (bit `i` for pair `i`) set where that result is `slerp`'s (where it is
/// not, the value is some quaternion, NaN or infinite components possible,
/// to be replaced).
///
/// Lanes: block `j` holds pairs `8j` to `8j + 7` in the order 0, 2, 4, 6,
/// 1, 3, 5, 7 (plus `8j`), which is the order the transpose by unpacking
/// within 128-bit halves gives; the low half of its f32 registers (pairs
/// 0, 2, 4, 6) goes to f64 register `2j`, the high half to `2j + 1`.
///
/// One of the crate's six `unsafe` blocks.
#[allow(unsafe_code)]
#[inline(always)]
fn evaluate<T: Slerped>(s: &[T; PAIRS], e: &[T; PAIRS], alpha: f32, o: &mut [T; PAIRS]) -> u32 {
    // SAFETY: every intrinsic here needs AVX, which this module is compiled
    // only with (`target_feature = "avx"`). The loads read, and the stores
    // write, 16 bytes at the address of a `Quat` (`rotation` and
    // `rotation_mut` of an element of `s`, `e` or `o`), which is `repr(C)`
    // of four f32 (16 bytes; `loadu` and `storeu` need no alignment). The
    // rest works on registers only, and AVX arithmetic cannot fault with
    // the default MXCSR (exceptions masked).
    unsafe {
        let (pd, ps) = (_mm256_castps_pd, _mm256_castpd_ps);
        let (add, sub, mul) = (_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps);
        let (addd, subd, muld, divd) = (_mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd, _mm256_div_pd);
        let splat = _mm256_set1_pd;
        let (sign32, sign64) = (_mm256_set1_ps(-0.0), splat(-0.0));
        let load = |q: &Quat| _mm_loadu_ps((q as *const Quat).cast::<f32>());
        let pair =
            |lo: __m128, hi: __m128| _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(lo), hi);
        // f32 lanes to f64, in two halves of four lanes, and back.
        let halves = |v: __m256| {
            [
                _mm256_cvtps_pd(_mm256_castps256_ps128(v)),
                _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v)),
            ]
        };
        let join = |lo: __m256d, hi: __m256d| pair(_mm256_cvtpd_ps(lo), _mm256_cvtpd_ps(hi));
        // The f32 square root of four f64 lanes.
        let root = |v: __m256d| _mm256_cvtps_pd(_mm_sqrt_ps(_mm256_cvtpd_ps(v)));

        // Four registers of two quaternions each, [q0 | q1], [q2 | q3],
        // [q4 | q5], [q6 | q7], to one register per component, lanes
        // [0 2 4 6 | 1 3 5 7].
        let transpose = |x: &[T; PAIRS], j: usize| {
            let q = |i: usize| load(x[LANES * j + i].rotation());
            let r = [
                pair(q(0), q(1)),
                pair(q(2), q(3)),
                pair(q(4), q(5)),
                pair(q(6), q(7)),
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
        let dot = |p: [__m256; 4], q: [__m256; 4]| {
            add(
                add(add(mul(p[0], q[0]), mul(p[1], q[1])), mul(p[2], q[2])),
                mul(p[3], q[3]),
            )
        };
        let minor = |p, q, r, s| sub(mul(p, s), mul(q, r));
        let sq = |x| mul(x, x);

        // Pair::of and Pair::applies, block by block: the squared norms,
        // the dot product, the six minors and the squared wedge; the bounds
        // on the squared norms are checked once (slerp_f64 checks them
        // twice, with the same result).
        let zero32 = _mm256_setzero_ps();
        let (mut a, mut b) = ([[zero32; 4]; BLOCKS], [[zero32; 4]; BLOCKS]);
        let (mut dots, mut wedges, mut applies) = ([zero32; BLOCKS], [zero32; BLOCKS], [0; BLOCKS]);
        for j in 0..BLOCKS {
            let ([aw, ax, ay, az], [bw, bx, by, bz]) = (transpose(s, j), transpose(e, j));
            let n2 = dot([aw, ax, ay, az], [aw, ax, ay, az]);
            let on2 = dot([bw, bx, by, bz], [bw, bx, by, bz]);
            let m = [
                minor(aw, ax, bw, bx),
                minor(aw, ay, bw, by),
                minor(aw, az, bw, bz),
                minor(ax, ay, bx, by),
                minor(ax, az, bx, bz),
                minor(ay, az, by, bz),
            ];
            let wedge = add(
                add(add(sq(m[0]), sq(m[1])), add(sq(m[2]), sq(m[3]))),
                add(sq(m[4]), sq(m[5])),
            );
            let limit = _mm256_set1_ps(NORM_SQUARED_LIMIT);
            let bounded = _mm256_and_ps(
                _mm256_cmp_ps::<_CMP_LE_OQ>(n2, limit),
                _mm256_cmp_ps::<_CMP_LE_OQ>(on2, limit),
            );
            let spread = _mm256_andnot_ps(sign32, sub(n2, on2));
            // `!(spread > NEARLY_UNIT * on2)`: "not greater", true for NaN.
            let near_unit =
                _mm256_cmp_ps::<_CMP_NGT_UQ>(spread, mul(_mm256_set1_ps(NEARLY_UNIT), on2));
            let resolved = _mm256_cmp_ps::<_CMP_GE_OQ>(wedge, _mm256_set1_ps(SQUARES_UNDERFLOW));
            applies[j] =
                _mm256_movemask_ps(_mm256_and_ps(_mm256_and_ps(bounded, near_unit), resolved));
            (a[j], b[j]) = ([aw, ax, ay, az], [bw, bx, by, bz]);
            (dots[j], wedges[j]) = (dot([aw, ax, ay, az], [bw, bx, by, bz]), wedge);
        }
        // Where the evaluation does not apply, the squared wedge may be zero
        // and the divisions below make infinities or NaN in that lane (the
        // processor does not trap: exceptions are masked), whose value is
        // replaced. Putting a positive wedge there first would add a blend
        // to every lane's chain of dependent operations.

        // The f64 part, four lanes a register, register by register at
        // each stage: w, x and x * x (of |x| in atan2_of_root and of x in
        // Pair::slerp: the same).
        let zero64 = _mm256_setzero_pd();
        let (mut w, mut x2) = ([zero64; 2 * BLOCKS], [zero64; 2 * BLOCKS]);
        for j in 0..BLOCKS {
            let (wedge, dot) = (halves(wedges[j]), halves(dots[j]));
            for h in 0..2 {
                (w[2 * j + h], x2[2 * j + h]) = (wedge[h], muld(dot[h], dot[h]));
            }
        }
        // atan2_of_root(w, |x|): the smaller of w and x^2 over the larger,
        // its square root in f32 (each register on its own, so that none
        // waits for another's division), the polynomial, the quarter turn.
        let mut z = [zero64; 2 * BLOCKS];
        for k in 0..2 * BLOCKS {
            let below = _mm256_cmp_pd::<_CMP_LT_OQ>(w[k], x2[k]);
            z[k] = divd(
                _mm256_blendv_pd(x2[k], w[k], below),
                _mm256_blendv_pd(w[k], x2[k], below),
            );
        }
        let mut phi = [zero64; 2 * BLOCKS];
        for k in 0..2 * BLOCKS {
            let (z, u) = (z[k], root(z[k]));
            let c = ATAN_F64;
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
            phi[k] = addd(muld(quarter, splat(core::f64::consts::FRAC_PI_2)), flipped);
        }
        // Pair::slerp: r = 1 / sin(phi) from the wedge and the dot product
        // (its square root in f32), the two sines.
        let mut r = [zero64; 2 * BLOCKS];
        for k in 0..2 * BLOCKS {
            let limit = splat(INVERSE_SINE_SQUARED_LIMIT);
            r[k] = root(_mm256_min_pd(divd(addd(w[k], x2[k]), w[k]), limit));
        }
        let sine = |x: __m256d| {
            let s = SIN_F64;
            let s2 = muld(x, x);
            let p = addd(
                addd(splat(s[0]), muld(s2, splat(s[1]))),
                muld(muld(s2, s2), addd(splat(s[2]), muld(s2, splat(s[3])))),
            );
            addd(x, muld(muld(x, s2), p))
        };
        let alpha = splat(f64::from(alpha));
        let rest = subd(splat(1.0), alpha);
        let (mut c0, mut c1) = ([zero64; 2 * BLOCKS], [zero64; 2 * BLOCKS]);
        for k in 0..2 * BLOCKS {
            c0[k] = muld(sine(muld(rest, phi[k])), r[k]);
            c1[k] = muld(sine(muld(alpha, phi[k])), r[k]);
        }

        // The weighted sums, back to four registers of two quaternions
        // each, and to the rotations of `o`; the done bits.
        let mut done = 0;
        for j in 0..BLOCKS {
            let c0 = join(c0[2 * j], c0[2 * j + 1]);
            let c1 = join(c1[2 * j], c1[2 * j + 1]);
            // (c1 as f32).copysign(dot)
            let c1 = _mm256_or_ps(_mm256_andnot_ps(sign32, c1), _mm256_and_ps(sign32, dots[j]));
            let weigh = |i: usize| add(mul(c0, a[j][i]), mul(c1, b[j][i]));
            let (qw, qx, qy, qz) = (weigh(0), weigh(1), weigh(2), weigh(3));
            let u0 = _mm256_unpacklo_ps(qw, qx);
            let u1 = _mm256_unpackhi_ps(qw, qx);
            let v0 = _mm256_unpacklo_ps(qy, qz);
            let v1 = _mm256_unpackhi_ps(qy, qz);
            let q = [
                ps(_mm256_unpacklo_pd(pd(u0), pd(v0))),
                ps(_mm256_unpackhi_pd(pd(u0), pd(v0))),
                ps(_mm256_unpacklo_pd(pd(u1), pd(v1))),
                ps(_mm256_unpackhi_pd(pd(u1), pd(v1))),
            ];
            for (k, q) in q.into_iter().enumerate() {
                let mut store = |i: usize, v: __m128| {
                    let to: *mut Quat = o[LANES * j + i].rotation_mut();
                    _mm_storeu_ps(to.cast::<f32>(), v);
                };
                store(2 * k, _mm256_castps256_ps128(q));
                store(2 * k + 1, _mm256_extractf128_ps::<1>(q));
            }
            let small = splat(SMALL_ANGLE_F64);
            let past_small = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(phi[2 * j], small))
                | (_mm256_movemask_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(phi[2 * j + 1], small)) << 4);
            let lanes_done = (applies[j] & past_small) as u32;
            // Lane k holds pair 2k (k < 4) or pair 2(k - 4) + 1.
            for (lane, pair) in [0, 2, 4, 6, 1, 3, 5, 7].into_iter().enumerate() {
                done |= ((lanes_done >> lane) & 1) << (LANES * j + pair);
            }
        }
        done
    }
}

/// `out[i].t = starts[i].t.lerp(ends[i].t, alpha)` for [`PAIRS`]
/// RigTForms at once: every one of their f32 components (rotations too,
/// which are written again afterwards) as `x (1 - alpha) + y alpha`, the
/// operations of `Cvec3::lerp`, eight at a time. One of the crate's six
/// `unsafe` blocks.
#[allow(unsafe_code)]
#[inline(always)]
pub(crate) fn lerp_rig_tforms(
    starts: &[RigTForm; PAIRS],
    ends: &[RigTForm; PAIRS],
    alpha: f32,
    out: &mut [RigTForm; PAIRS],
) {
    /// The f32 components of [`PAIRS`] RigTForms.
    const FLOATS: usize = PAIRS * 7;
    const _: () = assert!(core::mem::size_of::<[RigTForm; PAIRS]>() == 4 * FLOATS);
    const _: () = assert!(FLOATS % LANES == 0);
    let (x, y) = (starts.as_ptr().cast::<f32>(), ends.as_ptr().cast::<f32>());
    let to = out.as_mut_ptr().cast::<f32>();
    // SAFETY: AVX, as in `evaluate`. `RigTForm` is `repr(C)` of a `Cvec3`
    // and a `Quat`, each `repr(C)` of f32s: an array of PAIRS of them is
    // 7 PAIRS f32 with no padding (checked above, at compile time), every
    // bit pattern of which is a valid value. The loads and stores read and
    // write eight of those f32 at offsets below 7 PAIRS, through pointers
    // to the whole arrays.
    unsafe {
        let (keep, take) = (_mm256_set1_ps(1.0 - alpha), _mm256_set1_ps(alpha));
        for k in (0..FLOATS).step_by(LANES) {
            let (p, q) = (_mm256_loadu_ps(x.add(k)), _mm256_loadu_ps(y.add(k)));
            let lerped = _mm256_add_ps(_mm256_mul_ps(p, keep), _mm256_mul_ps(q, take));
            _mm256_storeu_ps(to.add(k), lerped);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::slerp_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
    use super::*;
    use crate::Cvec3;
    use rand::{Rng, SeedableRng};

    fn bits(q: Quat) -> [u32; 4] {
        q.to_array().map(f32::to_bits)
    }

    /// A pair is done exactly where `slerp_f64` takes it, with its result,
    /// bit for bit, in whichever lane of a step it is: random unit pairs,
    /// and each class of input it leaves to the f32 evaluation, every one
    /// in every lane among random pairs.
    #[test]
    fn lanes_take_exactly_the_pairs_slerp_f64_takes() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(15);
        let mut specials = std::vec::Vec::from(rare_pairs());
        specials.push(just_past_the_small_angles());
        let mut steps: std::vec::Vec<[(Quat, Quat); PAIRS]> = (0..1_000)
            .map(|_| core::array::from_fn(|_| (unit(&mut rng), unit(&mut rng))))
            .collect();
        for &special in &specials {
            for lane in 0..PAIRS {
                let mut step: [(Quat, Quat); PAIRS] =
                    core::array::from_fn(|_| (unit(&mut rng), unit(&mut rng)));
                step[lane] = special;
                steps.push(step);
            }
        }
        let (mut done_count, mut left_count) = (0, 0);
        for step in &steps {
            let alpha = rng.random_range(0.0..=1.0f32).max(f32::MIN_POSITIVE);
            let (s, e) = (step.map(|p| p.0), step.map(|p| p.1));
            let mut o = [Quat::NAN; PAIRS];
            let done = evaluate(&s, &e, alpha, &mut o);
            for (i, &(a, b)) in step.iter().enumerate() {
                let expected = a.slerp_f64(b, alpha);
                assert_eq!(done & (1 << i) != 0, expected.is_some(), "{a:?} {b:?}");
                match expected {
                    Some(q) => {
                        assert_eq!(bits(o[i]), bits(q), "{a:?} {b:?} {alpha}");
                        done_count += 1;
                    }
                    None => left_count += 1,
                }
            }
        }
        // Every pair but the eight rare ones, each in each lane.
        assert_eq!(left_count, 8 * PAIRS);
        assert_eq!(done_count, steps.len() * PAIRS - left_count);
    }

    /// Steps, the pairs left to `slerp` in them, and the last pairs, of
    /// slices of every length up to three steps and a bit, of quaternions
    /// and of RigTForms: each element the single call's result, bit for
    /// bit, and the rest of a longer `out` untouched.
    #[test]
    fn slices_of_every_length_are_the_single_calls_bit_for_bit() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(16);
        let rare = rare_pairs();
        let pairs: std::vec::Vec<(Quat, Quat)> = (0..3 * PAIRS + 5)
            .map(|i| match i % 5 {
                3 => rare[i % rare.len()],
                _ => (unit(&mut rng), unit(&mut rng)),
            })
            .collect();
        let (starts, ends): (std::vec::Vec<Quat>, std::vec::Vec<Quat>) =
            pairs.iter().copied().unzip();
        let mut shift = || {
            let mut c = || rng.random_range(-10.0..10.0f32);
            Cvec3::new(c(), c(), c())
        };
        let rig = |q: &[Quat], shift: &mut dyn FnMut() -> Cvec3| -> std::vec::Vec<RigTForm> {
            q.iter().map(|&r| RigTForm::new(shift(), r)).collect()
        };
        let (rig_starts, rig_ends) = (rig(&starts, &mut shift), rig(&ends, &mut shift));
        let same = |p: Quat, q: Quat| bits(p) == bits(q) || (p.is_nan() && q.is_nan());
        for len in 0..=pairs.len() {
            let mut out = std::vec![Quat::IDENTITY; len + 1];
            Quat::slerp_slice(&starts[..len], &ends[..len], 0.3, &mut out);
            for (i, &q) in out[..len].iter().enumerate() {
                let expected = starts[i].slerp(ends[i], 0.3);
                assert!(same(q, expected), "{len} {i}: {q:?} {expected:?}");
            }
            assert_eq!(out[len], Quat::IDENTITY);
            let mut out = std::vec![RigTForm::IDENTITY; len + 1];
            RigTForm::interpolate_slice(&rig_starts[..len], &rig_ends[..len], 0.3, &mut out);
            for (i, x) in out[..len].iter().enumerate() {
                let expected = rig_starts[i].interpolate(rig_ends[i], 0.3);
                assert!(same(x.r, expected.r), "{len} {i}: {x:?} {expected:?}");
                assert_eq!(
                    x.t.to_array().map(f32::to_bits),
                    expected.t.to_array().map(f32::to_bits)
                );
            }
            assert_eq!(out[len], RigTForm::IDENTITY);
        }
    }
}
