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
    /// the pairs go through slerp's in-plane formula written without a
    /// branch, blocks of 64 pairs at a time, which the compiler vectorizes
    /// (4 pairs at once with SSE2, 8 with AVX2). Its square root is
    /// `float::sqrt_by_newton`, plain arithmetic, correctly rounded like
    /// the square root of the single call. Every operation is the single
    /// call's, in its order, so the results agree bit for bit where that
    /// formula is the one `slerp` takes; the pairs where it is not (not
    /// finite or not within 2^16 per component, 2^-12 rad apart or less,
    /// norms more than 1e-6 apart, a difference small enough to be
    /// rescaled) are then done again by `slerp` itself. Every other
    /// `alpha`, and every other target, is a loop of `slerp`.
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
        #[cfg(all(
            any(target_arch = "x86_64", target_arch = "aarch64"),
            not(feature = "fast-math")
        ))]
        if alpha > 0.0 && alpha <= 1.0 {
            return lanes::slerp_in_blocks(starts, ends, alpha, out);
        }
        for ((&a, &b), o) in starts.iter().zip(ends).zip(out.iter_mut()) {
            *o = a.slerp(b, alpha);
        }
    }
}

/// The branch-free evaluation of the slice, in blocks.
#[cfg(all(
    any(target_arch = "x86_64", target_arch = "aarch64"),
    not(feature = "fast-math")
))]
mod lanes {
    use super::super::interpolate::{NEARLY_UNIT, SMALL_ANGLE};
    use super::Quat;
    use crate::float::{self, select, sqrt_by_newton, sum_of_squares, SQUARES_UNDERFLOW};

    /// Pairs per block: the flags of a block live on the stack.
    const BLOCK: usize = 64;

    /// 2^16, the largest magnitude of a component the lanes
    /// take: the products and sums of squares below stay far from
    /// overflow (at most 2^104), so no operation makes an infinity, and
    /// none a NaN.
    const LANE_LIMIT: f32 = 65_536.0;

    /// [`Quat::slerp_slice`] for `alpha` in (0, 1].
    pub(super) fn slerp_in_blocks(starts: &[Quat], ends: &[Quat], alpha: f32, out: &mut [Quat]) {
        let blocks = starts
            .chunks(BLOCK)
            .zip(ends.chunks(BLOCK))
            .zip(out.chunks_mut(BLOCK));
        for ((starts, ends), out) in blocks {
            let mut done = [false; BLOCK];
            for (((&a, &b), o), d) in starts.iter().zip(ends).zip(out.iter_mut()).zip(&mut done) {
                (*o, *d) = in_plane(a, b, alpha);
            }
            let rest = starts.iter().zip(ends).zip(out.iter_mut()).zip(&done);
            for (((&a, &b), o), &d) in rest {
                if !d {
                    *o = a.slerp(b, alpha);
                }
            }
        }
    }

    /// Slerp's in-plane evaluation of `a` to `b` by `alpha` in (0, 1],
    /// without a branch, and whether it is what `slerp` returns (when it
    /// is not, the value is some finite quaternion, to be replaced).
    /// Operation for operation `Quat::slerp` and its `slerp_in_plane`, with
    /// `u.scale == 1` and with `sqrt_by_newton` for `float::sqrt`.
    #[inline(always)]
    fn in_plane(a: Quat, b: Quat, alpha: f32) -> (Quat, bool) {
        // Out-of-range components (NaN and infinities among them) are
        // replaced before any arithmetic; their pair goes to slerp.
        let within = |q: Quat| {
            (q.w.abs() <= LANE_LIMIT)
                & (q.x.abs() <= LANE_LIMIT)
                & (q.y.abs() <= LANE_LIMIT)
                & (q.z.abs() <= LANE_LIMIT)
        };
        let bounded = within(a) & within(b);
        let a = a.map(|c| select(bounded, c, 1.0));
        let b = b.map(|c| select(bounded, c, 1.0));

        let dot = a.dot(b);
        let flip = 1.0f32.copysign(dot);
        let b = b.map(|c| c * flip);
        let dot = dot * flip;
        let n2 = a.norm_squared();
        let u = b.weighted_sum(n2, a, -dot);
        let sum = sum_of_squares(u.to_array());
        let n = sqrt_by_newton(n2);
        let beta = sqrt_by_newton(sum);
        let phi = float::atan2(beta, n * dot * 1.0);

        let far = alpha * phi;
        let near = phi - far;
        let wide = phi > SMALL_ANGLE;
        let (s0, s1, sin_phi) = float::sin3(near, far, phi);
        // sin(phi) > 0 where phi > 2^-12; elsewhere 1, so that nothing
        // divides by zero.
        let r = 1.0 / select(wide, sin_phi, 1.0);
        let (c0, c1) = (s0 * r, s1 * r);
        let on2 = b.norm_squared();
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let near_unit = !((n2 - on2).abs() > NEARLY_UNIT * on2);
        let done = bounded & (sum >= SQUARES_UNDERFLOW) & wide & near_unit;
        (a.weighted_sum(c0, b, c1), done)
    }
}
