//! The slice on x86-64: steps of pairs in vector registers ([`Steps`]:
//! SSE2's on every x86-64 target with SSE, AVX's where it is enabled at
//! compile time), through the f64 evaluation of `in_f64.rs`, the same
//! operations in the same order: the f32 part in registers of
//! [`Steps::LANES`] lanes, the f64 part in registers of half as many. No
//! fused multiply-add is used (it rounds once where the single call rounds
//! twice), so every lane's result is the single call's, bit for bit; the
//! unit tests below check it against `slerp_f64` on random pairs and on
//! each class of pair it leaves to the f32 evaluation, in every lane.
//! Lanes whose pair that evaluation does not take are done again by
//! `slerp`, as in the portable blocks.
//!
//! The evaluation of one pair is a long chain of dependent operations (a
//! division and three polynomials among them), longer than the processor
//! can look ahead past: two blocks of [`Steps::LANES`] pairs go through it
//! together, stage by stage, so that while one block's lanes wait for a
//! result the other's have work. Two suit both AVX's sixteen registers of
//! eight lanes and SSE2's of four: with the squared norms and dot products
//! in f64, more blocks make the compiler keep registers on the stack.

use super::super::in_f64::{Arc, Pair};
use super::super::lanes::{Lanes, Steps};
use super::super::WithRotation;
use super::Slerped;

/// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1]: steps
/// of `PAIRS` pairs (`BLOCKS` blocks of `I::LANES`, with `CHAINS = 2
/// BLOCKS` registers of f64 lanes), and the last pairs (fewer) in a step
/// of their own, padded with copies of the first of them.
#[inline(always)]
pub(super) fn slerp_in_steps<
    I: Steps,
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
fn step<I: Steps, T: Slerped, const BLOCKS: usize, const CHAINS: usize, const PAIRS: usize>(
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
fn evaluate<
    I: Steps,
    T: WithRotation,
    const BLOCKS: usize,
    const CHAINS: usize,
    const PAIRS: usize,
>(
    s: &[T; PAIRS],
    e: &[T; PAIRS],
    alpha: f32,
    o: &mut [T; PAIRS],
) -> u32 {
    // The quaternions, one f32 register per component `[w, x, y, z]`, and
    // widened to f64: the low half of block `j`'s registers to f64
    // register `2j`, the high half to `2j + 1`.
    let zero = I::splat(0.0);
    let (mut a, mut b) = ([[zero; 4]; BLOCKS], [[zero; 4]; BLOCKS]);
    let zero = I::D::splat(0.0);
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
    // Each stage register by register, so that no register waits for
    // another's: the pairs and their checks, the quotients (one division
    // each), the arcs, the coefficients.
    let (mut applies, mut near, mut far, mut toward) =
        ([0; CHAINS], [zero; CHAINS], [zero; CHAINS], [zero; CHAINS]);
    for k in 0..CHAINS {
        let pair = Pair::of(wa[k], wb[k]);
        applies[k] = pair.applies();
        (near[k], far[k]) = pair.lengths_in_every_lane();
        toward[k] = pair.dot;
    }
    let mut t2 = [zero; CHAINS];
    for k in 0..CHAINS {
        t2[k] = near[k].div(far[k]);
    }
    let mut arcs = [Arc {
        phi_squared: zero,
        phi_over_sine: zero,
    }; CHAINS];
    for k in 0..CHAINS {
        arcs[k] = Arc::from_quotient(t2[k]);
    }
    let (rest, alpha) = (
        I::D::splat(1.0 - f64::from(alpha)),
        I::D::splat(f64::from(alpha)),
    );
    let (mut c0, mut c1) = ([zero; CHAINS], [zero; CHAINS]);
    for k in 0..CHAINS {
        c0[k] = arcs[k].coefficient(rest);
        c1[k] = arcs[k].coefficient(alpha);
    }

    // The weighted sums, to the rotations of `o`; the done bits.
    let sign = I::splat(-0.0);
    let half = I::LANES / 2;
    let mut done = 0;
    for j in 0..BLOCKS {
        let (low, high) = (2 * j, 2 * j + 1);
        let c0 = I::join(c0[low], c0[high]);
        // (c1.copysign(dot)) as f32: the sign of the dot product is that
        // of its rounding to f32.
        let toward = I::join(toward[low], toward[high]);
        let c1 = I::or(
            I::and_not(sign, I::join(c1[low], c1[high])),
            I::and(sign, toward),
        );
        let weigh = |i: usize| I::add(I::mul(c0, a[j][i]), I::mul(c1, b[j][i]));
        I::store([weigh(0), weigh(1), weigh(2), weigh(3)], &mut o[lanes(j)]);
        let taken = |k: usize| applies[k] & arcs[k].past_small_angles();
        let lanes_done = taken(low) | (taken(high) << half);
        for (lane, pair) in I::PAIR_OF_LANE.into_iter().enumerate().take(I::LANES) {
            done |= ((lanes_done >> lane) & 1) << (I::LANES * j + pair);
        }
    }
    done
}

#[cfg(test)]
mod tests {
    use super::super::super::in_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
    use super::super::super::lanes::Sse2;
    use super::super::tests::bits;
    use super::*;
    use crate::{Quat, RigTForm};
    use rand::{Rng, SeedableRng};

    /// A pair is done exactly where `slerp_f64` takes it, with its result,
    /// bit for bit, in whichever lane of a step it is: random unit pairs,
    /// and each class of input it leaves to the f32 evaluation, every one
    /// in every lane among random pairs.
    fn lanes_take_exactly_the_pairs_slerp_f64_takes<
        I: Steps,
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
        lanes_take_exactly_the_pairs_slerp_f64_takes::<super::super::super::lanes::Avx, 2, 4, 16>();
    }

    /// Steps, the pairs left to `slerp` in them, and the last pairs, of
    /// slices of every length up to three steps and a bit, of quaternions
    /// and of RigTForms: each element the single call's result, bit for
    /// bit.
    fn slices_of_every_length_are_the_single_calls<
        I: Steps,
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
        slices_of_every_length_are_the_single_calls::<super::super::super::lanes::Avx, 2, 4, 16>();
    }
}
