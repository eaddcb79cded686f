//! The notes' power operator, [`Quat::pow`], and the polar decomposition
//! it rests on (the notes' section "Power").

use super::Quat;
use crate::float::{self, scale_for_squares};
use crate::vec::Cvec3;

/// The unit axis and the angle `phi = atan2(beta, w)` of the notes' "Power"
/// section: `q = |q| (cos phi, sin phi axis)`.
pub(super) struct Polar {
    pub(super) axis: Cvec3,
    pub(super) phi: f32,
}

impl Quat {
    /// The notes' decomposition `self = |self| (cos phi, sin phi k)`, with `k`
    /// the normalized vector part and `phi = atan2(beta, w)` in [0, pi].
    /// Scale-free: the vector part is normalized by exact power-of-two
    /// scaling, and `w` is scaled by the same power, so neither subnormal nor
    /// huge components lose precision or overflow. A pure real quaternion
    /// has no axis: it gets the x axis, with `phi = pi` if `w < 0` (a turn
    /// by 2 pi) and `phi = 0` otherwise (including zero).
    ///
    /// The caller has checked that every component is finite.
    pub(super) fn polar(self) -> Polar {
        let v = scale_for_squares([self.x, self.y, self.z, 0.0]);
        if v.sum == 0.0 {
            let phi = if self.w < 0.0 {
                core::f32::consts::PI
            } else {
                0.0
            };
            return Polar {
                axis: Cvec3::X,
                phi,
            };
        }
        let beta = float::sqrt(v.sum);
        let [x, y, z, _] = v.v;
        Polar {
            axis: Cvec3::new(x / beta, y / beta, z / beta),
            // w * scale may overflow to infinity (when the vector part was
            // scaled up because it is tiny beside w) or go subnormal (when it
            // was scaled down because it is huge): atan2 then gives 0 or pi,
            // or pi/2, which are the correctly rounded angles in those cases.
            phi: float::atan2(beta, self.w * v.scale),
        }
    }

    /// The power operator of the notes: with `self = |self| (cos phi, sin phi k)`,
    /// `phi = atan2(beta, w)`, returns `(cos(alpha phi), sin(alpha phi) k)`, the
    /// rotation about the same axis by `alpha` times the angle.
    ///
    /// No conditional negation happens here (the notes put it in
    /// [`slerp`](Self::slerp)): for `w < 0` the angle `2 phi` exceeds pi, so
    /// `q.pow(alpha)` and `(-q).pow(alpha)` turn different ways.
    ///
    /// # Preconditions
    ///
    /// None beyond finiteness. `self` need not be a unit quaternion: atan2 is
    /// scale-free, and the axis is normalized by exact scaling, so non-unit,
    /// subnormal and huge inputs (up to `f32::MAX`) all give a unit result.
    ///
    /// - A pure real `self` (zero vector part) has no axis. `w > 0` (and the
    ///   zero quaternion) gives [`Quat::IDENTITY`]. `w < 0` is a turn by
    ///   2 pi about every axis; it is taken about the x axis:
    ///   `(cos(alpha pi), sin(alpha pi), 0, 0)`.
    /// - NaN or infinite `self` or `alpha` gives [`Quat::NAN`].
    /// - Every finite `alpha` works. For `|alpha| > f32::MAX / 4`, where
    ///   `alpha phi` could overflow, the result is computed as the fourth
    ///   power (two squarings) of `self.pow(alpha / 4)`.
    ///
    /// # Accuracy
    ///
    /// Against an f64 reference over random unit inputs and `alpha` in
    /// [-2, 3]: rotation error at most
    /// [`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR)
    /// `* max(1, |alpha| theta)` radians, `theta` being the angle of `self`
    /// (the rounding of `alpha phi` grows with the turn). Norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1
    /// for every finite non-zero input and finite `alpha`
    /// (`tests/differential.rs`, `tests/edge_cases.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_x(1.2);
    /// assert!(q.pow(0.5).angle_to(Quat::from_rotation_x(0.6)) < 1e-6);
    /// assert_eq!(q.pow(0.0), Quat::IDENTITY);
    /// // Not unit, still a unit result:
    /// assert!((Quat::from_wxyz(0.0, 5.0, 0.0, 0.0).pow(0.3).norm() - 1.0).abs() < 1e-6);
    /// ```
    // Inlined across crates on 64-bit desktop targets, where the call
    // costs as much as a share of the work; one out-of-line copy elsewhere
    // (flash on a Cortex-M4F).
    #[cfg_attr(desktop64, inline)]
    #[must_use]
    pub fn pow(self, alpha: f32) -> Self {
        if !(self.is_finite() && alpha.is_finite()) {
            return Self::NAN;
        }
        // |alpha| <= f32::MAX / 4 and |phi| <= pi < 4 keep alpha * phi finite.
        let (alpha, square_twice) = if alpha.abs() > f32::MAX / 4.0 {
            (alpha * 0.25, true)
        } else {
            (alpha, false)
        };
        let Polar { axis, phi } = self.polar();
        let (s, c) = float::sin_cos(alpha * phi);
        let result = Self::from_scalar_vector(c, axis * s);
        if !square_twice {
            return result;
        }
        let square = result * result;
        // Two rounded products roughly triple the norm error: renormalize.
        (square * square).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pow_of_pure_real_negative_turns_about_x() {
        let q = Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0).pow(0.5);
        assert!((q.w).abs() < 1e-7);
        assert_eq!((q.x, q.y, q.z), (1.0, 0.0, 0.0));
    }

    #[test]
    fn pow_with_huge_alpha_stays_unit_and_matches_the_squaring_identity() {
        let q = Quat::from_rotation_z(1e-30);
        for alpha in [f32::MAX, -f32::MAX, f32::MAX / 3.0] {
            let r = q.pow(alpha);
            assert!(r.is_finite());
            assert!((r.norm() - 1.0).abs() < 1e-5, "{alpha}: {r:?}");
        }
        // Just above the split, pow(alpha) == pow(alpha / 4)^4.
        let alpha = f32::MAX / 3.0;
        let quarter = Quat::from_rotation_z(0.5).pow(alpha * 0.25);
        let fourth = (quarter * quarter) * (quarter * quarter);
        assert!(Quat::from_rotation_z(0.5).pow(alpha).angle_to(fourth) < 1e-5);
    }
}
