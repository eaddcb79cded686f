//! [`Quat::slerp_slice`]: slerp of many pairs by one `alpha`, for animation
//! systems that blend many bones at once, equal to [`Quat::slerp`] element
//! by element, bit for bit.

use super::Quat;

impl Quat {
    /// Slerps every pair `(starts[i], ends[i])` by the same `alpha` into
    /// `out[i]`: element by element, bit for bit, what
    /// [`slerp`](Self::slerp) returns for the pair, whatever the inputs
    /// (where that is NaN, a NaN: Rust leaves the sign and payload of a NaN
    /// result unspecified).
    ///
    /// Slices of different lengths: the first
    /// `min(starts.len(), ends.len(), out.len())` elements are written, and
    /// the rest of `out` is left as it was (never a panic).
    ///
    /// # How it is evaluated
    ///
    /// On x86-64 and AArch64 (without `fast-math`), for `alpha` in (0, 1],
    /// the pairs go through the evaluation `slerp` itself takes there (its
    /// angle and sines in f64), written without a branch, blocks of 64
    /// pairs at a time, which the compiler vectorizes (the square root
    /// included: the crate's square root is the processor's instruction,
    /// through an intrinsic the vectorizer sees). Every operation is the
    /// single call's, in its order, so the results agree bit for bit where
    /// that evaluation is the one `slerp` takes; the pairs where it is not (not
    /// finite or not within 2^16 per component, 2^-12 rad apart or less,
    /// norms more than 1e-6 apart, a wedge small enough to underflow) are
    /// then done again by `slerp` itself. Every other `alpha`, and every
    /// other target, is a loop of `slerp`.
    ///
    /// # Preconditions
    ///
    /// Those of [`slerp`](Self::slerp), element by element.
    ///
    /// # Accuracy
    ///
    /// That of [`slerp`](Self::slerp): the results are its results.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let starts = [Quat::from_rotation_x(0.1), Quat::from_rotation_y(0.2)];
    /// let ends = [Quat::from_rotation_x(0.9), -Quat::from_rotation_z(1.0)];
    /// let mut out = [Quat::IDENTITY; 2];
    /// Quat::slerp_slice(&starts, &ends, 0.25, &mut out);
    /// assert_eq!(out[0], starts[0].slerp(ends[0], 0.25));
    /// assert_eq!(out[1], starts[1].slerp(ends[1], 0.25));
    /// ```
    #[doc(alias = "slerp_many")]
    pub fn slerp_slice(starts: &[Quat], ends: &[Quat], alpha: f32, out: &mut [Quat]) {
        slerp_slice_by(starts, ends, alpha, out, |q| q, |_, _, q| q);
    }
}

/// For every pair `(starts[i], ends[i])`, `out[i] = finish(starts[i],
/// ends[i], rotation(starts[i]).slerp(rotation(ends[i]), alpha))`, with
/// the slerps evaluated as [`Quat::slerp_slice`] says: the rotations of
/// values that hold one (`RigTForm`'s), slerped in place, without copying
/// them out first.
#[inline(always)]
pub(crate) fn slerp_slice_by<T: Copy>(
    starts: &[T],
    ends: &[T],
    alpha: f32,
    out: &mut [T],
    rotation: impl Fn(T) -> Quat,
    finish: impl Fn(T, T, Quat) -> T,
) {
    #[cfg(all(
        any(target_arch = "x86_64", target_arch = "aarch64"),
        not(feature = "fast-math")
    ))]
    if alpha > 0.0 && alpha <= 1.0 {
        return lanes::slerp_in_blocks(starts, ends, alpha, out, rotation, finish);
    }
    for ((&a, &b), o) in starts.iter().zip(ends).zip(out.iter_mut()) {
        *o = finish(a, b, rotation(a).slerp(rotation(b), alpha));
    }
}

/// The branch-free evaluation of the slice, in blocks.
#[cfg(all(
    any(target_arch = "x86_64", target_arch = "aarch64"),
    not(feature = "fast-math")
))]
mod lanes {
    use super::super::slerp_f64::{Pair, NORM_SQUARED_LIMIT, SMALL_ANGLE_F64};
    use super::Quat;
    use crate::float::select;

    /// Pairs per block: the flags of a block live on the stack.
    const BLOCK: usize = 64;

    /// [`slerp_slice_by`](super::slerp_slice_by) for `alpha` in (0, 1].
    #[inline(always)]
    pub(super) fn slerp_in_blocks<T: Copy>(
        starts: &[T],
        ends: &[T],
        alpha: f32,
        out: &mut [T],
        rotation: impl Fn(T) -> Quat,
        finish: impl Fn(T, T, Quat) -> T,
    ) {
        let blocks = starts
            .chunks(BLOCK)
            .zip(ends.chunks(BLOCK))
            .zip(out.chunks_mut(BLOCK));
        for ((starts, ends), out) in blocks {
            let mut done = [false; BLOCK];
            for (((&a, &b), o), d) in starts.iter().zip(ends).zip(out.iter_mut()).zip(&mut done) {
                let (q, in_plane_done) = in_plane(rotation(a), rotation(b), alpha);
                (*o, *d) = (finish(a, b, q), in_plane_done);
            }
            let rest = starts.iter().zip(ends).zip(out.iter_mut()).zip(&done);
            for (((&a, &b), o), &d) in rest {
                if !d {
                    *o = finish(a, b, rotation(a).slerp(rotation(b), alpha));
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
        // (squared norms within NORM_SQUARED_LIMIT: infinities and NaN
        // among them), the arithmetic below may make infinities and NaN
        // (inf - inf in the minors) in that lane, and the lane is not done:
        // its value is replaced by `slerp`'s. Replacing such inputs by
        // finite ones first, select by select, cost a tenth of the time of
        // every lane. No Kani harness runs this path.
        let (n2, on2) = (a.norm_squared(), b.norm_squared());
        let mut pair = Pair::of(a, b);
        // `applies` checks the bounds too; checked here as well, from the
        // norms summed first, the compiler schedules the lane about 3 %
        // faster (11.85 against 12.24 ns per pair, one process).
        let bounded = (n2 <= NORM_SQUARED_LIMIT) & (on2 <= NORM_SQUARED_LIMIT);
        let applies = bounded & pair.applies();
        // A positive squared wedge where the evaluation does not apply
        // (it may be zero or lost to underflow there): no division by zero.
        pair.wedge = select(applies, pair.wedge, 1.0);
        let phi = pair.angle();
        let done = applies & (phi > SMALL_ANGLE_F64);
        (pair.slerp(a, b, phi, alpha), done)
    }

    #[cfg(test)]
    mod tests {
        use super::super::super::slerp_f64::tests::{just_past_the_small_angles, rare_pairs, unit};
        use super::*;
        use rand::{Rng, SeedableRng};

        /// A lane is done exactly where `slerp_f64` takes the pair, with
        /// its result, bit for bit: random unit pairs, and each class of
        /// input it leaves to the f32 evaluation.
        #[test]
        fn lanes_take_exactly_the_pairs_slerp_f64_takes() {
            let mut rng = rand::rngs::StdRng::seed_from_u64(14);
            let mut pairs: std::vec::Vec<(Quat, Quat)> = (0..10_000)
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
            assert_eq!(done_count, 10_001);
        }
    }
}
