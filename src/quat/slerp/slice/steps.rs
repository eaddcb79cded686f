//! The slice on x86-64: steps of pairs in vector registers, through an
//! instruction set's operations written by hand ([`Isa`]: SSE2 on every
//! x86-64 target with SSE, AVX where it is enabled at compile time).
//!
//! The pairs go through the operations of `Quat::slerp_f64`'s evaluation
//! ([`Pair::of`], [`Pair::applies`], [`Pair::arc`] and [`Pair::slerp`]),
//! the same ones in the same order: the f32 part in
//! registers of [`Isa::LANES`] lanes, the f64 part in registers of half as
//! many. No fused multiply-add is used (it rounds once where the single
//! call rounds twice), so every lane's result is the single call's, bit for
//! bit; the unit tests below check it against `slerp_f64` on random pairs
//! and on each class of pair it leaves to the f32 evaluation, in every
//! lane. Lanes whose pair that evaluation does not take are done again by
//! `slerp`, as in the portable lanes.
//!
//! The evaluation of one pair is a long chain of dependent operations (a
//! division and three polynomials among them), longer than the processor
//! can look ahead past; several blocks of [`Isa::LANES`] pairs go through
//! it together, stage by stage, so that while one block's lanes wait for a
//! result the others' have work. The compiler vectorizes the portable lanes
//! too, but one block at a time, and it moves the quaternions between their
//! layout (`x, y, z, w` of one, then the next) and one register per
//! component with more shuffles, blends and permutes than the transposes
//! here: 48 per 4 pairs in its SSE2 loop against 95 per 16 here, about 85
//! per 8 pairs in its AVX2 loop against 60 per 16 here (counted in the
//! compiled loops of `Quat::slerp_slice` when SSE2 took four blocks a step
//! and the arc came from f32 minors, as were the times below).
//! Medians of one process, 1,024 random unit pairs, on an AMD EPYC (Zen 3):
//! on the default target (SSE2) 9.2 ns per pair here against 12.1 for the
//! portable lanes (`slerp_slice`) and 10.1 against 13.4
//! (`RigTForm::interpolate_slice`); with `-C target-cpu=x86-64-v3` (AVX)
//! 4.9 against 8.7 and 5.7 against 9.3. Two blocks a step suit both AVX's
//! sixteen registers of eight lanes and SSE2's of four: with the squared
//! norms and dot products in f64, more blocks make the compiler keep
//! registers on the stack (SSE2 with four blocks 7.3 against 5.6 ns per
//! pair, three 5.9, one 7.3; AVX with one 4.0 against 3.3).
//!
//! [`Pair::of`]: super::super::in_f64::Pair::of
//! [`Pair::applies`]: super::super::in_f64::Pair::applies
//! [`Pair::arc`]: super::super::in_f64::Pair::arc
//! [`Pair::slerp`]: super::super::in_f64::Pair::slerp

use super::super::in_f64::{NORM_SQUARED_LIMIT, SMALL_ANGLE_SQUARED_F64};
use super::super::kernels_f64::{ATAN as ATAN_F64, SIN as SIN_F64};
use super::super::NEARLY_UNIT;
use super::Slerped;

/// An instruction set's registers and the operations the evaluation
/// takes, each one instruction (or a fixed few), IEEE 754's operation on
/// every lane.
pub(super) trait Isa {
    /// A register of f32 lanes.
    type F: Copy;
    /// A register of f64 lanes, half as many.
    type D: Copy;
    /// f32 lanes per register: pairs per block.
    const LANES: usize;
    /// The pair of its block that each lane holds, after [`load`](Self::load).
    const PAIR_OF_LANE: [usize; 8];

    /// `x` in every f32 lane.
    fn splat(x: f32) -> Self::F;
    /// `x` in every f64 lane.
    fn splat_d(x: f64) -> Self::D;
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
    /// `a + b` in f64.
    fn add_d(a: Self::D, b: Self::D) -> Self::D;
    /// `a - b` in f64.
    fn sub_d(a: Self::D, b: Self::D) -> Self::D;
    /// `a * b` in f64.
    fn mul_d(a: Self::D, b: Self::D) -> Self::D;
    /// `a / b` in f64.
    fn div_d(a: Self::D, b: Self::D) -> Self::D;
    /// All ones where `a > b`, else zeros (false for NaN).
    fn gt_d(a: Self::D, b: Self::D) -> Self::D;
    /// All ones where `a <= b`, else zeros (false for NaN).
    fn le_d(a: Self::D, b: Self::D) -> Self::D;
    /// All ones where `!(a > b)`, else zeros (true for NaN).
    fn not_gt_d(a: Self::D, b: Self::D) -> Self::D;
    /// `if a > b { a } else { b }` in f64 (`b` where either is NaN).
    fn max_d(a: Self::D, b: Self::D) -> Self::D;
    /// The sign bits of the f64 lanes, lane `k` in bit `k`.
    fn bits_d(a: Self::D) -> u32;
    /// The low and the high half of the f32 lanes, each widened to f64.
    fn halves(a: Self::F) -> [Self::D; 2];
    /// Two registers of f64 lanes rounded to f32, the first the low half.
    fn join(low: Self::D, high: Self::D) -> Self::F;
    /// The rotations of [`LANES`](Self::LANES) values, one register per
    /// component (`w`, `x`, `y`, `z`), lanes in the order
    /// [`PAIR_OF_LANE`](Self::PAIR_OF_LANE) gives.
    fn load<T: Slerped>(values: &[T]) -> [Self::F; 4];
    /// The inverse of [`load`](Self::load): the quaternions in the four
    /// component registers to the rotations of `values`.
    fn store<T: Slerped>(components: [Self::F; 4], values: &mut [T]);
}

/// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1]: steps
/// of `PAIRS` pairs (`BLOCKS` blocks of `I::LANES`, with `CHAINS = 2
/// BLOCKS` registers of f64 lanes), and the last pairs (fewer) in a step
/// of their own, padded with copies of the first of them.
#[inline(always)]
pub(super) fn slerp_in_steps<
    I: Isa,
    T: Slerped,
    const BLOCKS: usize,
    const CHAINS: usize,
    const PAIRS: usize,
>(
    starts: &[T],
    ends: &[T],
    alpha: f32,
    out: &mut [T],
) {
    const { assert!(CHAINS == 2 * BLOCKS && PAIRS == I::LANES * BLOCKS && PAIRS < 32) };
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
        step::<I, T, BLOCKS, CHAINS, PAIRS>(s, e, alpha, o);
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
        step::<I, T, BLOCKS, CHAINS, PAIRS>(&s, &e, alpha, &mut o);
        for (to, from) in out.iter_mut().skip(whole).take(left).zip(&o) {
            *to = *from;
        }
    }
}

/// One step of `I::LANES * BLOCKS` pairs: [`Slerped::lerp_rest_of`] them,
/// then their rotations by [`evaluate`], and `slerp` for the pairs it
/// leaves.
#[inline(always)]
fn step<I: Isa, T: Slerped, const BLOCKS: usize, const CHAINS: usize, const PAIRS: usize>(
    s: &[T; PAIRS],
    e: &[T; PAIRS],
    alpha: f32,
    o: &mut [T; PAIRS],
) {
    T::lerp_rest_of(s, e, alpha, o);
    let done = evaluate::<I, T, BLOCKS, CHAINS, PAIRS>(s, e, alpha, o);
    if done != (1 << PAIRS) - 1 {
        let rest = s.iter().zip(e).zip(o.iter_mut()).enumerate();
        for (i, ((s, e), o)) in rest {
            if done & (1 << i) == 0 {
                *o.rotation_mut() = s.rotation().slerp(*e.rotation(), alpha);
            }
        }
    }
}

/// `slerp_f64`'s evaluation of the rotations of the pairs of a step
/// (`I::LANES * BLOCKS` of them), without a branch, written to the
/// rotations of `o`; returned, a bit for each pair (bit `i` for pair `i`)
/// set where that result is `slerp`'s (where it is not, the value is some
/// quaternion, NaN or infinite components possible, to be replaced).
///
/// Block `j` holds pairs `LANES j` to `LANES (j + 1) - 1`; the low half of
/// its f32 registers goes to f64 register `2j`, the high half to `2j + 1`.
#[inline(always)]
fn evaluate<I: Isa, T: Slerped, const BLOCKS: usize, const CHAINS: usize, const PAIRS: usize>(
    s: &[T; PAIRS],
    e: &[T; PAIRS],
    alpha: f32,
    o: &mut [T; PAIRS],
) -> u32 {
    let (add, mul) = (I::add, I::mul);
    let (add_d, sub_d, mul_d, div_d) = (I::add_d, I::sub_d, I::mul_d, I::div_d);
    let splat = I::splat_d;
    let sign32 = I::splat(-0.0);
    // `(x x' + z z') + (y y' + w w')` of f64 components `[w, x, y, z]`.
    let dot = |p: [I::D; 4], q: [I::D; 4]| {
        add_d(
            add_d(mul_d(p[1], q[1]), mul_d(p[3], q[3])),
            add_d(mul_d(p[2], q[2]), mul_d(p[0], q[0])),
        )
    };

    // Pair::of and Pair::applies, register by register: the quaternions
    // widened to f64 (the low half of block `j`'s f32 registers to f64
    // register `2j`, the high half to `2j + 1`), their squared norms and
    // dot product, the squared lengths of their difference and sum (as
    // `Pair::near` and `Pair::far`), and the checks.
    let zero = I::splat(0.0);
    let (mut a, mut b) = ([[zero; 4]; BLOCKS], [[zero; 4]; BLOCKS]);
    let zero = splat(0.0);
    let (mut wa, mut wb) = ([[zero; 4]; CHAINS], [[zero; 4]; CHAINS]);
    let lanes = |j: usize| I::LANES * j..I::LANES * (j + 1);
    for j in 0..BLOCKS {
        (a[j], b[j]) = (I::load(&s[lanes(j)]), I::load(&e[lanes(j)]));
        for i in 0..4 {
            let ([al, ah], [bl, bh]) = (I::halves(a[j][i]), I::halves(b[j][i]));
            (wa[2 * j][i], wa[2 * j + 1][i]) = (al, ah);
            (wb[2 * j][i], wb[2 * j + 1][i]) = (bl, bh);
        }
    }
    let (mut applies, mut near, mut far, mut toward) =
        ([0; CHAINS], [zero; CHAINS], [zero; CHAINS], [zero; CHAINS]);
    for k in 0..CHAINS {
        let (p, q) = (wa[k], wb[k]);
        let (n2, on2, pq) = (dot(p, p), dot(q, q), dot(p, q));
        let limit = splat(NORM_SQUARED_LIMIT);
        let bounded = I::bits_d(I::le_d(n2, limit)) & I::bits_d(I::le_d(on2, limit));
        // `!(|n2 - on2| > NEARLY_UNIT * on2)`, one sign at a time: "not
        // greater", true for NaN.
        let allowed = mul_d(splat(f64::from(NEARLY_UNIT)), on2);
        let near_unit = I::bits_d(I::not_gt_d(sub_d(n2, on2), allowed))
            & I::bits_d(I::not_gt_d(sub_d(on2, n2), allowed));
        // `2 |a . b|`, exact: the larger of `2 a . b` and `-2 a . b`.
        let twice = I::max_d(mul_d(splat(2.0), pq), mul_d(splat(-2.0), pq));
        let sum = add_d(n2, on2);
        near[k] = sub_d(sum, twice);
        let larger = add_d(sum, twice);
        let unequal = I::bits_d(I::gt_d(larger, near[k]));
        applies[k] = bounded & near_unit & unequal;
        // Where the evaluation does not apply, the larger length may be
        // zero (a zero quaternion) or NaN: the smallest normal f64 in its
        // place (`max` takes it for NaN), so that the division below never
        // divides by zero (which would raise the divide-by-zero exception
        // that slerp itself does not, a SIGFPE where a program unmasks
        // it). Where it applies, it is above the smaller length, so
        // positive, and stays as it is.
        far[k] = I::max_d(larger, splat(f64::MIN_POSITIVE));
        toward[k] = pq;
    }

    // Pair::arc, register by register at each stage: the tangent of the
    // half angle squared (one division, each register on its own, so that
    // none waits for another's), the polynomial, phi^2 and phi / sin(phi).
    let mut t2 = [zero; CHAINS];
    for k in 0..CHAINS {
        t2[k] = div_d(near[k], far[k]);
    }
    let (mut phi2, mut ratio) = ([zero; CHAINS], [zero; CHAINS]);
    for k in 0..CHAINS {
        let s = t2[k];
        let c = ATAN_F64;
        let s2 = mul_d(s, s);
        let s4 = mul_d(s2, s2);
        let low = add_d(
            add_d(splat(c[0]), mul_d(s, splat(c[1]))),
            mul_d(s2, add_d(splat(c[2]), mul_d(s, splat(c[3])))),
        );
        let high = add_d(
            add_d(splat(c[4]), mul_d(s, splat(c[5]))),
            mul_d(s2, add_d(splat(c[6]), mul_d(s, splat(c[7])))),
        );
        let p = add_d(low, mul_d(s4, high));
        let h = add_d(splat(1.0), mul_d(s, p));
        phi2[k] = mul_d(mul_d(splat(4.0), s), mul_d(h, h));
        ratio[k] = mul_d(h, add_d(splat(1.0), s));
    }
    // Pair::slerp: each share of the arc times phi / sin(phi) times the
    // sinc of its angle.
    let sinc = |s| {
        let c = SIN_F64;
        let q = add_d(
            add_d(splat(c[0]), mul_d(s, splat(c[1]))),
            mul_d(mul_d(s, s), add_d(splat(c[2]), mul_d(s, splat(c[3])))),
        );
        add_d(splat(1.0), mul_d(s, q))
    };
    let alpha = splat(f64::from(alpha));
    let rest = sub_d(splat(1.0), alpha);
    let (alpha2, rest2) = (mul_d(alpha, alpha), mul_d(rest, rest));
    let (mut c0, mut c1) = ([zero; CHAINS], [zero; CHAINS]);
    for k in 0..CHAINS {
        c0[k] = mul_d(mul_d(rest, ratio[k]), sinc(mul_d(rest2, phi2[k])));
        c1[k] = mul_d(mul_d(alpha, ratio[k]), sinc(mul_d(alpha2, phi2[k])));
    }

    // The weighted sums, to the rotations of `o`; the done bits.
    let mut done = 0;
    let small = splat(SMALL_ANGLE_SQUARED_F64);
    let half = I::LANES / 2;
    for j in 0..BLOCKS {
        let c0 = I::join(c0[2 * j], c0[2 * j + 1]);
        let c1 = I::join(c1[2 * j], c1[2 * j + 1]);
        // (c1.copysign(dot)) as f32: the sign of the dot product is that
        // of its rounding to f32.
        let toward = I::join(toward[2 * j], toward[2 * j + 1]);
        let c1 = I::or(I::and_not(sign32, c1), I::and(sign32, toward));
        let weigh = |i: usize| add(mul(c0, a[j][i]), mul(c1, b[j][i]));
        I::store([weigh(0), weigh(1), weigh(2), weigh(3)], &mut o[lanes(j)]);
        let past_small = I::bits_d(I::gt_d(phi2[2 * j], small))
            | (I::bits_d(I::gt_d(phi2[2 * j + 1], small)) << half);
        let applies = applies[2 * j] | (applies[2 * j + 1] << half);
        let lanes_done = applies & past_small;
        for (lane, pair) in I::PAIR_OF_LANE.into_iter().enumerate().take(I::LANES) {
            done |= ((lanes_done >> lane) & 1) << (I::LANES * j + pair);
        }
    }
    done
}

#[cfg(test)]
mod tests {
    use super::super::super::in_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
    use super::super::sse2::Sse2;
    use super::super::tests::bits;
    use super::*;
    use crate::{Quat, RigTForm};
    use rand::{Rng, SeedableRng};

    /// A pair is done exactly where `slerp_f64` takes it, with its result,
    /// bit for bit, in whichever lane of a step it is: random unit pairs,
    /// and each class of input it leaves to the f32 evaluation, every one
    /// in every lane among random pairs.
    fn lanes_take_exactly_the_pairs_slerp_f64_takes<
        I: Isa,
        const BLOCKS: usize,
        const CHAINS: usize,
        const PAIRS: usize,
    >() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(15);
        let mut specials = std::vec::Vec::from(rare_pairs());
        specials.push(just_past_the_small_angles());
        // Fewer random steps under Miri, which interprets every instruction.
        let random_steps = if cfg!(miri) { 10 } else { 1_000 };
        let mut steps: std::vec::Vec<[(Quat, Quat); PAIRS]> = (0..random_steps)
            .map(|_| core::array::from_fn(|_| (unit(&mut rng), unit(&mut rng))))
            .collect();
        // Under Miri every fifth lane (the first and the last among them).
        let lanes: std::vec::Vec<usize> =
            (0..PAIRS).step_by(if cfg!(miri) { 5 } else { 1 }).collect();
        for &special in &specials {
            for &lane in &lanes {
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
            let done = evaluate::<I, Quat, BLOCKS, CHAINS, PAIRS>(&s, &e, alpha, &mut o);
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
        // Every pair but the eight rare ones, each in each lane tried.
        assert_eq!(left_count, 8 * lanes.len());
        assert_eq!(done_count, steps.len() * PAIRS - left_count);
    }

    #[test]
    fn sse2_lanes_take_exactly_the_pairs_slerp_f64_takes() {
        lanes_take_exactly_the_pairs_slerp_f64_takes::<Sse2, 2, 4, 8>();
    }

    #[cfg(x86_avx_lanes)]
    #[test]
    fn avx_lanes_take_exactly_the_pairs_slerp_f64_takes() {
        lanes_take_exactly_the_pairs_slerp_f64_takes::<super::super::avx::Avx, 2, 4, 16>();
    }

    /// Steps, the pairs left to `slerp` in them, and the last pairs, of
    /// slices of every length up to three steps and a bit, of quaternions
    /// and of RigTForms: each element the single call's result, bit for
    /// bit.
    fn slices_of_every_length_are_the_single_calls<
        I: Isa,
        const BLOCKS: usize,
        const CHAINS: usize,
        const PAIRS: usize,
    >() {
        super::super::tests::every_length_is_the_single_calls_bit_for_bit(
            3 * PAIRS + 5,
            slerp_in_steps::<I, Quat, BLOCKS, CHAINS, PAIRS>,
            slerp_in_steps::<I, RigTForm, BLOCKS, CHAINS, PAIRS>,
        );
    }

    #[test]
    fn sse2_slices_of_every_length_are_the_single_calls_bit_for_bit() {
        slices_of_every_length_are_the_single_calls::<Sse2, 2, 4, 8>();
    }

    #[cfg(x86_avx_lanes)]
    #[test]
    fn avx_slices_of_every_length_are_the_single_calls_bit_for_bit() {
        slices_of_every_length_are_the_single_calls::<super::super::avx::Avx, 2, 4, 16>();
    }
}
