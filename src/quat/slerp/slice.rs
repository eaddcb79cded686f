//! [`Quat::slerp_slice`]: slerp of many pairs by one `alpha`, for animation
//! systems that blend many bones at once, equal to [`Quat::slerp`] element
//! by element, bit for bit.

use super::WithRotation;
use crate::Quat;

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
    /// On x86-64 and AArch64, for `alpha` in (0, 1],
    /// the pairs go through the evaluation `slerp` itself takes there (its
    /// angle and sines in f64), written without a branch, many pairs at a
    /// time in vector registers:
    ///
    /// - on x86-64, eight (SSE2) or sixteen (AVX) pairs a step, in vector
    ///   registers written by hand: SSE2's on every target with SSE, AVX's
    ///   where AVX is enabled at compile time (`-C target-cpu=x86-64-v3`,
    ///   `-C target-cpu=native` on a processor with AVX, or
    ///   `-C target-feature=+avx`); the performance page
    ///   (`docs/performance.md`, `slerp slice`) has the times beside a loop
    ///   of each peer's single slerp;
    /// - on AArch64, blocks of 64 pairs that the compiler vectorizes (the
    ///   square root included: the crate's square root is the processor's
    ///   instruction, through an intrinsic the vectorizer sees), and on
    ///   x86-64 targets without SSE the same blocks in scalar code.
    ///
    /// Every operation is the single call's, in its order (no fused
    /// multiply-add), so the results agree bit for bit where that
    /// evaluation is the one `slerp` takes; the pairs where it is not (not
    /// finite or not within 2^16 per component, 2^-12 rad apart or less,
    /// norms more than 1e-6 apart, at a right angle to f64's precision) are
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
    /// # Floating-point exceptions
    ///
    /// Programs that unmask exceptions (`feenableexcept`, a SIGFPE for
    /// each one raised) see none from the slices on pairs of finite,
    /// nearly unit quaternions that [`slerp`](Self::slerp) itself does not
    /// raise: identical, opposite and nearby pairs included, every length
    /// (`tests/fp_exceptions.rs`, with divide-by-zero and invalid-operation
    /// unmasked). On NaN or infinite input, or components beyond 2^16, the
    /// x86-64 vector steps compare and divide values that `slerp` leaves
    /// alone, and may raise the invalid-operation exception where it does
    /// not; with exceptions masked (the default) that only sets a flag.
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
        slerp_slice_by(starts, ends, alpha, out);
    }
}

/// What [`slerp_slice_by`] interpolates: a value that holds a rotation,
/// slerped, and maybe more, lerped (`RigTForm`'s translation).
pub(crate) trait Slerped: WithRotation {
    /// Writes into `out` all but the rotation of the interpolation of
    /// `start` and `end` by `alpha`.
    fn lerp_rest(start: &Self, end: &Self, alpha: f32, out: &mut Self);
    /// [`lerp_rest`](Self::lerp_rest) of every pair of the slices (the
    /// first `min(starts.len(), ends.len(), out.len())`) at once, for the
    /// steps of the x86-64 lanes; it may write the rotations of `out` too
    /// (they are written again afterwards).
    #[cfg(x86_sse_lanes)]
    fn lerp_rest_of(starts: &[Self], ends: &[Self], alpha: f32, out: &mut [Self]);
}

impl Slerped for Quat {
    #[inline(always)]
    fn lerp_rest(_: &Self, _: &Self, _: f32, _: &mut Self) {}
    #[cfg(x86_sse_lanes)]
    #[inline(always)]
    fn lerp_rest_of(_: &[Self], _: &[Self], _: f32, _: &mut [Self]) {}
}

/// For every pair `(starts[i], ends[i])`, the rotation of `out[i]` is
/// `starts[i].rotation().slerp(*ends[i].rotation(), alpha)` and the rest
/// [`Slerped::lerp_rest`]'s, with the slerps evaluated as
/// [`Quat::slerp_slice`] says: the rotations of values that hold one
/// (`RigTForm`'s), read and written in place.
#[inline(always)]
pub(crate) fn slerp_slice_by<T: Slerped>(starts: &[T], ends: &[T], alpha: f32, out: &mut [T]) {
    #[cfg(x86_avx_lanes)]
    if alpha > 0.0 && alpha <= 1.0 {
        return steps::slerp_in_steps::<Avx, T, 2, 4, 16>(starts, ends, alpha, out);
    }
    #[cfg(all(x86_sse_lanes, not(x86_avx_lanes)))]
    if alpha > 0.0 && alpha <= 1.0 {
        return steps::slerp_in_steps::<Sse2, T, 2, 4, 8>(starts, ends, alpha, out);
    }
    #[cfg(portable_lanes)]
    if alpha > 0.0 && alpha <= 1.0 {
        return blocks::slerp_in_blocks(starts, ends, alpha, out);
    }
    for ((a, b), o) in starts.iter().zip(ends).zip(out.iter_mut()) {
        *o.rotation_mut() = a.rotation().slerp(*b.rotation(), alpha);
        T::lerp_rest(a, b, alpha, o);
    }
}

/// Steps of pairs in the vector registers of x86-64.
#[cfg(x86_sse_lanes)]
mod steps;
#[cfg(x86_avx_lanes)]
use super::lanes::Avx;
#[cfg(all(x86_sse_lanes, not(x86_avx_lanes)))]
use super::lanes::Sse2;

/// The branch-free evaluation of the slice, in blocks the compiler
/// vectorizes (also compiled for the tests on x86-64, which check it).
#[cfg(any(portable_lanes, all(test, desktop64)))]
mod blocks;

/// What the tests of every evaluation of the slice in lanes share.
#[cfg(all(test, desktop64))]
mod tests {
    use super::super::in_f64::tests::{rare_pairs, unit};
    use crate::Quat;
    use crate::{Cvec3, RigTForm};
    use rand::{Rng, SeedableRng};

    /// The bits of the components, to compare results bit for bit.
    pub(super) fn bits(q: Quat) -> [u32; 4] {
        q.to_array().map(f32::to_bits)
    }

    /// Checks an evaluation of the slice (`quats` for quaternions, `rigs`
    /// for RigTForms, `alpha` 0.3) on slices of every length up to `max`,
    /// of random unit pairs with a rare pair (`rare_pairs`) every fifth:
    /// each element the single call's result, bit for bit (NaN for NaN),
    /// and the element past the slice in a longer `out` untouched.
    pub(super) fn every_length_is_the_single_calls_bit_for_bit(
        max: usize,
        quats: impl Fn(&[Quat], &[Quat], f32, &mut [Quat]),
        rigs: impl Fn(&[RigTForm], &[RigTForm], f32, &mut [RigTForm]),
    ) {
        let mut rng = rand::rngs::StdRng::seed_from_u64(16);
        let rare = rare_pairs();
        let pairs: std::vec::Vec<(Quat, Quat)> = (0..max)
            .map(|i| match i % 5 {
                3 => rare[i % rare.len()],
                _ => (unit(&mut rng), unit(&mut rng)),
            })
            .collect();
        let mut rig = |r: Quat| {
            let mut c = || rng.random_range(-10.0..10.0f32);
            RigTForm::new(Cvec3::new(c(), c(), c()), r)
        };
        let rig_pairs: std::vec::Vec<(RigTForm, RigTForm)> =
            pairs.iter().map(|&(a, b)| (rig(a), rig(b))).collect();
        let same = |p: Quat, q: Quat| bits(p) == bits(q) || (p.is_nan() && q.is_nan());
        let same_t =
            |p: Cvec3, q: Cvec3| p.to_array().map(f32::to_bits) == q.to_array().map(f32::to_bits);
        for len in 0..=max {
            let (starts, ends): (std::vec::Vec<Quat>, std::vec::Vec<Quat>) =
                pairs[..len].iter().copied().unzip();
            let mut out = std::vec![Quat::IDENTITY; len + 1];
            quats(&starts, &ends, 0.3, &mut out);
            for (i, &q) in out[..len].iter().enumerate() {
                let expected = starts[i].slerp(ends[i], 0.3);
                assert!(same(q, expected), "{len} {i}: {q:?} {expected:?}");
            }
            assert_eq!(out[len], Quat::IDENTITY);
            let (starts, ends): (std::vec::Vec<RigTForm>, std::vec::Vec<RigTForm>) =
                rig_pairs[..len].iter().copied().unzip();
            let mut out = std::vec![RigTForm::IDENTITY; len + 1];
            rigs(&starts, &ends, 0.3, &mut out);
            for (i, x) in out[..len].iter().enumerate() {
                let expected = starts[i].interpolate(ends[i], 0.3);
                assert!(
                    same(x.r, expected.r) && same_t(x.t, expected.t),
                    "{len} {i}: {x:?} {expected:?}"
                );
            }
            assert_eq!(out[len], RigTForm::IDENTITY);
        }
    }
}
