//! Interpolation by the notes' "4D lerp and renormalization":
//! [`Quat::nlerp`] between two rotations and the n-way [`Quat::blend`].
//! Slerp has a folder of its own, `quat/slerp/`.

use super::Quat;

impl Quat {
    /// Normalized linear interpolation: aligns the sign of `other` with
    /// `self` (negating it if `self.dot(other)` is negative or -0, so it
    /// goes the short way), lerps the four components as `(1 - alpha) self + alpha other`,
    /// and normalizes (the notes' "4D lerp and renormalization" hack).
    ///
    /// Cheaper than [`slerp`](Self::slerp), with the same path but not
    /// constant angular velocity (it is faster in the middle). For `alpha`
    /// in [0, 1] the result is written on the side of `self`
    /// (`result.dot(self) >= 0`).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions. The lerp can only vanish
    /// when they are not (or for extreme extrapolation of non-unit inputs);
    /// then, as for NaN or infinite input, the result is [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_y(0.2);
    /// let b = Quat::from_rotation_y(0.6);
    /// assert!(a.nlerp(b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// assert!(a.nlerp(-b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// ```
    // Inlined across crates on 64-bit desktop targets, where the call
    // costs as much as a share of the work; one out-of-line copy elsewhere
    // (flash on a Cortex-M4F).
    #[cfg_attr(desktop64, inline)]
    #[must_use]
    pub fn nlerp(self, other: Self, alpha: f32) -> Self {
        super::backend::nlerp(self, other, alpha)
    }

    /// N-way weighted blend: the normalized sum of `weight * q` over the
    /// entries, each `q` first sign-aligned to the first entry's (negated if
    /// its dot product with it is negative). No allocation; the slice may be
    /// of any length. This is the notes' "4D lerp and renormalization",
    /// useful for n-way blends; for two entries with weights `1 - t` and `t`
    /// it equals [`nlerp`](Self::nlerp).
    ///
    /// The result is written on the side of the first entry (`dot >= 0`
    /// with it) when the weights are positive. Weights need not sum to one
    /// (the result is normalized). Mind that
    /// sign alignment to the first entry is only a good choice when all
    /// rotations lie within a quarter turn (pi/2) of it.
    ///
    /// # Preconditions
    ///
    /// Unit quaternions and finite weights, of any size: they are scaled by
    /// a power of two first, so that weights near `f32::MAX` or subnormal
    /// ones blend as the same weights near 1 do. An empty slice, or weights
    /// that cancel to an exactly zero sum, give [`Quat::IDENTITY`] (no
    /// rotation information). A NaN or infinite quaternion or weight gives
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_z(0.3);
    /// let b = Quat::from_rotation_z(0.9);
    /// let blended = Quat::blend(&[(a, 1.0), (-b, 1.0)]); // -b is b
    /// assert!(blended.angle_to(Quat::from_rotation_z(0.6)) < 1e-6);
    /// assert_eq!(Quat::blend(&[]), Quat::IDENTITY);
    /// ```
    #[must_use]
    pub fn blend(entries: &[(Quat, f32)]) -> Self {
        let first = entries.first().map_or(Self::IDENTITY, |&(q, _)| q);
        // The weights scaled by a power of two (exactly, and the result does
        // not depend on their scale) so that the largest is about 1: the sum
        // neither overflows for weights near f32::MAX nor loses tiny ones.
        let largest = entries.iter().fold(0.0f32, |m, &(_, w)| m.max(w.abs()));
        let scale = weight_scale(largest);
        let mut sum = Self {
            w: 0.0,
            x: 0.0,
            y: 0.0,
            z: 0.0,
        };
        for &(q, weight) in entries {
            let weight = weight * scale;
            let weight = if q.dot(first) < 0.0 { -weight } else { weight };
            sum = sum.weighted_sum(1.0, q, weight);
        }
        // An empty slice, or weights that cancel: no rotation information.
        if sum.w == 0.0 && sum.x == 0.0 && sum.y == 0.0 && sum.z == 0.0 {
            return Self::IDENTITY;
        }
        sum.normalize()
    }
}

/// The power of two that brings `largest`, the largest magnitude of finite
/// weights, into [1, 4): 2^-e for `largest` in [2^e, 2^(e + 1)), e from -126
/// to 126, and 2^-126 above (2^127 and more); 2^126 for subnormal `largest`,
/// and 1 for zero, infinite or NaN `largest` (whose blend is the identity
/// or NaN whatever the scale). Built from the bits, so exact.
fn weight_scale(largest: f32) -> f32 {
    // The biased exponent: 0 for zero and subnormals, 255 for infinity
    // and NaN.
    let biased = (largest.to_bits() >> 23) & 0xff;
    match biased {
        0 if largest == 0.0 => 1.0,
        0 => f32::from_bits((126 + 127) << 23),
        255 => 1.0,
        // 2^(127 - biased), at least 2^-126: the biased exponent of the
        // scale is 254 - biased, at least 1.
        _ => f32::from_bits((254 - biased).max(1) << 23),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weight_scale_is_a_power_of_two_bringing_the_largest_weight_near_one() {
        for largest in [
            f32::MIN_POSITIVE,
            1e-30,
            0.3,
            1.0,
            1.5,
            7.0,
            1e30,
            2.0f32.powi(126),
            2.0f32.powi(127),
            f32::MAX,
        ] {
            let scale = weight_scale(largest);
            assert_eq!(scale.to_bits() & 0x007f_ffff, 0, "{largest}: {scale}");
            let scaled = largest * scale;
            assert!((1.0..4.0).contains(&scaled), "{largest}: {scaled}");
        }
        let tiny = f32::from_bits(1);
        assert!(tiny * weight_scale(tiny) > 0.0);
        for odd in [0.0, f32::INFINITY, f32::NAN] {
            assert_eq!(weight_scale(odd), 1.0);
        }
    }

    #[test]
    fn blend_is_unit_for_weights_near_the_largest_float() {
        let q = Quat::from_rotation_z(0.3);
        let r = Quat::from_rotation_x(0.5);
        let unit = |b: Quat| (b.norm() - 1.0).abs() <= crate::accuracy::NORMALIZE_MAX_NORM_ERROR;
        for big in [f32::MAX, -f32::MAX, 0.75 * f32::MAX, 2.0f32.powi(127), 1e38] {
            let both = Quat::blend(&[(q, big), (q, big)]);
            assert!(unit(both), "{big}: {both:?}");
            assert!(both.angle_to(q) < 1e-6, "{big}: {both:?}");
            let many = [(q, big), (r, big), (q, big), (r, f32::MAX)];
            assert!(unit(Quat::blend(&many)), "{big}");
        }
        // The scale does not change the answer: the same blend with the
        // weights divided by 2^100 and by 2^-100.
        let entries = [(q, 0.75), (r, 0.25)];
        let want = Quat::blend(&entries);
        for k in [-100, 100] {
            let scaled = entries.map(|(e, w)| (e, w * 2.0f32.powi(k)));
            assert_eq!(Quat::blend(&scaled), want, "2^{k}");
        }
        // Subnormal weights alone still blend, where their products with
        // the components underflowed.
        let tiny = f32::from_bits(3);
        let blended = Quat::blend(&[(q, tiny), (r, tiny)]);
        assert!(unit(blended), "{blended:?}");
        assert!(blended.angle_to(Quat::blend(&[(q, 1.0), (r, 1.0)])) < 1e-6);
        // Weights that are not finite still give NaN.
        assert!(Quat::blend(&[(q, f32::MAX), (r, f32::INFINITY)]).w.is_nan());
        assert!(Quat::blend(&[(q, f32::NAN), (r, f32::MAX)]).w.is_nan());
    }

    #[test]
    fn blend_and_nlerp_answer_on_the_side_of_their_first_input() {
        let a = Quat::from_rotation_x(0.4);
        let b = -Quat::from_rotation_y(0.9); // w < 0, the far side of a
        assert!(Quat::blend(&[(a, 1.0), (b, 1.0)]).dot(a) > 0.0);
        assert!(Quat::blend(&[(b, 1.0), (a, 3.0)]).dot(b) > 0.0);
        assert!(a.nlerp(b, 0.9).dot(a) > 0.0);
        assert!(b.nlerp(a, 0.9).dot(b) > 0.0);
    }

    #[test]
    fn blend_of_cancelling_weights_is_identity_and_nan_stays_nan() {
        let q = Quat::from_rotation_x(0.3);
        assert_eq!(Quat::blend(&[(q, 1.0), (q, -1.0)]), Quat::IDENTITY);
        assert!(!Quat::blend(&[(q, 1.0), (q, f32::NAN)]).w.is_finite());
        assert!(!Quat::blend(&[(q, f32::INFINITY)]).w.is_finite());
    }
}
