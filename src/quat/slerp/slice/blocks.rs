//! The branch-free evaluation of the slice, in blocks the compiler
//! vectorizes.

use super::super::in_f64::{Arc, Pair};
use super::super::lanes::{PairLanes, Two};
use super::{Quat, Slerped};

/// Pairs per block: the flags of a block live on the stack.
const BLOCK: usize = 64;

/// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1].
#[inline(always)]
pub(super) fn slerp_in_blocks<T: Slerped>(starts: &[T], ends: &[T], alpha: f32, out: &mut [T]) {
    let blocks = starts
        .chunks(BLOCK)
        .zip(ends.chunks(BLOCK))
        .zip(out.chunks_mut(BLOCK));
    for ((starts, ends), out) in blocks {
        let mut done = [false; BLOCK];
        for (((a, b), o), d) in starts.iter().zip(ends).zip(out.iter_mut()).zip(&mut done) {
            let (q, in_plane_done) = in_plane(*a.rotation(), *b.rotation(), alpha);
            (*o.rotation_mut(), *d) = (q, in_plane_done);
            T::lerp_rest(a, b, alpha, o);
        }
        let rest = starts.iter().zip(ends).zip(out.iter_mut()).zip(&done);
        for (((a, b), o), &d) in rest {
            if !d {
                *o.rotation_mut() = a.rotation().slerp(*b.rotation(), alpha);
            }
        }
    }
}

/// `Quat::slerp_f64` without a branch: the same functions on the same
/// numbers, and whether its result is what `slerp` returns (when it is
/// not, the value is some quaternion, NaN or infinite components
/// possible, to be replaced).
#[inline(always)]
fn in_plane(a: Quat, b: Quat, alpha: f32) -> (Quat, bool) {
    // Where the inputs are beyond the check `slerp_f64` makes first
    // (squared norms within NORM_SQUARED_LIMIT: infinities and NaN among
    // them), the products make NaN in that lane (inf * 0), and the
    // lane is not done: its value is replaced by `slerp`'s. Replacing such
    // inputs by finite ones first, select by select, cost a tenth of the
    // time of every lane. No Kani harness runs this path.
    let pair = Pair::of_quats(&a, &b);
    let (near, far) = pair.lengths_in_every_lane();
    let arc = Arc::from_quotient(near / far);
    let done = pair.applies() & arc.past_small_angles();
    (Two::weigh(&a, &b, arc.coefficients(alpha), pair.dot), done)
}

#[cfg(test)]
mod tests {
    use super::super::super::in_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
    use super::*;
    use rand::{Rng, SeedableRng};

    /// A lane is done exactly where `slerp_f64` takes the pair, with
    /// its result, bit for bit: random unit pairs, and each class of
    /// input it leaves to the f32 evaluation.
    #[test]
    fn lanes_take_exactly_the_pairs_slerp_f64_takes() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(14);
        // Fewer random pairs under Miri, which interprets every instruction.
        let random = if cfg!(miri) { 100 } else { 10_000 };
        let mut pairs: std::vec::Vec<(Quat, Quat)> = (0..random)
            .map(|_| (unit(&mut rng), unit(&mut rng)))
            .collect();
        pairs.extend(rare_pairs());
        pairs.push(just_past_the_small_angles());
        let mut done_count = 0;
        for (a, b) in pairs {
            let alpha = rng.random_range(0.0..=1.0f32).max(f32::MIN_POSITIVE);
            let (q, done) = in_plane(a, b, alpha);
            let expected = a.slerp_f64(b, alpha);
            assert_eq!(done, expected.is_some(), "{a:?} {b:?}");
            if let Some(e) = expected {
                assert_eq!(q, e, "{a:?} {b:?} {alpha}");
                done_count += 1;
            }
        }
        // Every random pair and the one just past the small angles.
        assert_eq!(done_count, random + 1);
    }

    /// Blocks, the pairs left to `slerp` in them and the last block, of
    /// slices of every length up to two blocks and a bit, of quaternions
    /// and of RigTForms: each element the single call's result, bit for
    /// bit.
    #[test]
    fn slices_of_every_length_are_the_single_calls_bit_for_bit() {
        // One block and a bit under Miri, which interprets every instruction.
        let max = if cfg!(miri) { BLOCK + 5 } else { 2 * BLOCK + 5 };
        super::super::tests::every_length_is_the_single_calls_bit_for_bit(
            max,
            slerp_in_blocks::<Quat>,
            slerp_in_blocks::<crate::RigTForm>,
        );
    }
}
