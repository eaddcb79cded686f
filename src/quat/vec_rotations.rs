//! glam's `Vec3` helpers that turn a vector: [`Cvec3::rotate_x`] (`_y`,
//! `_z`), [`Cvec3::rotate_axis`], [`Cvec3::rotate_towards`] and
//! [`Cvec3::slerp`]. They take their turns from the quaternions, so they
//! live with them: the vectors do not know of quaternions.

use super::Quat;
use crate::float;
use crate::vec::Cvec3;

impl Cvec3 {
    /// `self` turned by `angle` radians about the x axis, by the
    /// right-hand rule (glam's `rotate_x`, the same formula:
    /// `y cos - z sin`, `y sin + z cos`).
    ///
    /// # Accuracy
    ///
    /// `x` exactly; `y` and `z` each within
    /// `(2` [`accuracy::SIN_COS_MAX_ABS_ERROR`](crate::accuracy::SIN_COS_MAX_ABS_ERROR)
    /// `+ 2 f32::EPSILON) |v|` of the exact rotation, from the sine and
    /// cosine and the roundings of two products and a sum.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// assert!((Cvec3::Y.rotate_x(FRAC_PI_2) - Cvec3::Z).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn rotate_x(self, angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle);
        Self::new(self.x, self.y * c - self.z * s, self.y * s + self.z * c)
    }

    /// `self` turned by `angle` radians about the y axis (glam's
    /// `rotate_y`), as [`rotate_x`](Self::rotate_x) about x, with its
    /// accuracy (`y` exact).
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// assert!((Cvec3::Z.rotate_y(FRAC_PI_2) - Cvec3::X).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn rotate_y(self, angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle);
        Self::new(self.x * c + self.z * s, self.y, self.z * c - self.x * s)
    }

    /// `self` turned by `angle` radians about the z axis (glam's
    /// `rotate_z`), as [`rotate_x`](Self::rotate_x) about x, with its
    /// accuracy (`z` exact).
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// assert!((Cvec3::X.rotate_z(FRAC_PI_2) - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn rotate_z(self, angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle);
        Self::new(self.x * c - self.y * s, self.x * s + self.y * c, self.z)
    }

    /// `self` turned by `angle` radians about `axis` (glam's
    /// `rotate_axis`, the same definition):
    /// `Quat::from_axis_angle(axis, angle) * self`, with the preconditions
    /// of [`Quat::from_axis_angle`] (any non-zero axis) and the accuracy
    /// of `q * v`.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// assert!((Cvec3::X.rotate_axis(Cvec3::Z * 3.0, FRAC_PI_2) - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn rotate_axis(self, axis: Self, angle: f32) -> Self {
        Quat::from_axis_angle(axis, angle) * self
    }

    /// `self` turned towards the direction of `rhs` by at most `max_angle`
    /// radians, in the plane of the two (glam's `rotate_towards`): all
    /// the way where they are less than `max_angle` apart. A negative
    /// `max_angle` turns away, no further than opposite `rhs`. The length
    /// is kept.
    ///
    /// # Preconditions
    ///
    /// `self` and `rhs` are finite and non-zero; otherwise the result is
    /// NaN (glam asserts), as for a NaN `max_angle`. Opposite directions have no plane: the turn is
    /// about [`any_orthogonal_vector`](Self::any_orthogonal_vector), as
    /// glam's.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// let v = Cvec3::X.rotate_towards(Cvec3::Y * 5.0, FRAC_PI_2 / 2.0);
    /// assert!((v - Cvec3::new(1.0, 1.0, 0.0).normalize()).norm() < 1e-6);
    /// assert!((Cvec3::X.rotate_towards(Cvec3::Y, 4.0) - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn rotate_towards(self, rhs: Self, max_angle: f32) -> Self {
        let between = self.angle_between(rhs);
        if between.is_nan() {
            return Self::NAN;
        }
        // max_angle clamped to [between - pi, between], NaN kept.
        let angle = if max_angle < between - core::f32::consts::PI {
            between - core::f32::consts::PI
        } else if max_angle > between {
            between
        } else {
            max_angle
        };
        let axis = self
            .cross(rhs)
            .try_normalize()
            .unwrap_or_else(|| self.any_orthogonal_vector());
        Quat::from_axis_angle(axis, angle) * self
    }

    /// The spherical interpolation of two vectors (glam's `Vec3::slerp`):
    /// the direction of `self` turned towards that of `rhs` by the
    /// fraction `s` of the angle between them, about their common
    /// perpendicular, and the length lerped from `|self|` to `|rhs|`. `s`
    /// may lie outside [0, 1] (extrapolation).
    ///
    /// The turn is `Quat::from_rotation_arc(self, rhs).pow(s)`: for
    /// opposite directions, a half turn about the axis
    /// [`Quat::from_rotation_arc`] picks.
    ///
    /// # Preconditions
    ///
    /// `self` and `rhs` are finite and non-zero; otherwise the result is
    /// NaN (glam asserts).
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_4;
    /// use rigtform::Cvec3;
    /// let v = Cvec3::X.slerp(Cvec3::Y * 3.0, 0.5);
    /// assert!((v - Cvec3::new(FRAC_PI_4.cos(), FRAC_PI_4.sin(), 0.0) * 2.0).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn slerp(self, rhs: Self, s: f32) -> Self {
        let (Some(u), Some(v)) = (self.try_normalize(), rhs.try_normalize()) else {
            return Self::NAN;
        };
        let (from, to) = (self.norm(), rhs.norm());
        Quat::from_rotation_arc(u, v).pow(s) * u * (from + (to - from) * s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::SIN_COS_MAX_ABS_ERROR;
    use rand::{Rng, SeedableRng};

    fn g(v: Cvec3) -> glam::Vec3 {
        glam::Vec3::from_array(v.to_array())
    }

    fn close(v: Cvec3, w: glam::Vec3, tolerance: f32) -> bool {
        (v - Cvec3::from_array(w.to_array())).norm() <= tolerance
    }

    /// Each turns as glam's of that name, and `rotate_x/y/z` within their
    /// bound of the exact turn (f64).
    #[test]
    fn turns_agree_with_glams_and_the_exact_turn() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(46);
        let bound = 2.0 * SIN_COS_MAX_ABS_ERROR + 2.0 * f32::EPSILON;
        for _ in 0..100_000 {
            let mut c = || rng.random_range(-10.0f32..10.0);
            let (v, w, axis) = (
                Cvec3::new(c(), c(), c()),
                Cvec3::new(c(), c(), c()),
                Cvec3::new(c(), c(), c()),
            );
            let angle = c();
            let size = v.norm();
            assert!(close(v.rotate_x(angle), g(v).rotate_x(angle), 1e-6 * size));
            assert!(close(v.rotate_y(angle), g(v).rotate_y(angle), 1e-6 * size));
            assert!(close(v.rotate_z(angle), g(v).rotate_z(angle), 1e-6 * size));
            let (s, co) = (f64::from(angle).sin(), f64::from(angle).cos());
            let [x, y, z] = v.to_array().map(f64::from);
            let exact = [
                (v.rotate_x(angle), [x, y * co - z * s, y * s + z * co]),
                (v.rotate_y(angle), [x * co + z * s, y, z * co - x * s]),
                (v.rotate_z(angle), [x * co - y * s, x * s + y * co, z]),
            ];
            for (ours, [ex, ey, ez]) in exact {
                let error = [ours.x, ours.y, ours.z]
                    .iter()
                    .zip([ex, ey, ez])
                    .fold(0f64, |e, (a, b)| e.max((f64::from(*a) - b).abs()));
                assert!(error <= f64::from(bound * size), "{v:?} {angle}: {error:e}");
            }
            assert_eq!(v.rotate_x(angle).x, v.x);
            assert_eq!(v.rotate_y(angle).y, v.y);
            assert_eq!(v.rotate_z(angle).z, v.z);
            let unit = axis.normalize();
            let theirs = g(v).rotate_axis(g(unit), angle);
            assert!(close(v.rotate_axis(axis, angle), theirs, 1e-5 * size));
            let max_angle = rng.random_range(-4.0f32..4.0);
            let theirs = g(v).rotate_towards(g(w), max_angle);
            assert!(close(v.rotate_towards(w, max_angle), theirs, 1e-5 * size));
            let t = rng.random_range(-0.5f32..1.5);
            let theirs = g(v).slerp(g(w), t);
            let between = v.angle_between(w);
            if between > 1e-2 && between < 3.1 {
                let ours = v.slerp(w, t);
                assert!(
                    close(ours, theirs, 1e-4 * (size + w.norm())),
                    "{v:?} {w:?} {t}"
                );
                let length = size + (w.norm() - size) * t;
                assert!((ours.norm() - length.abs()).abs() <= 1e-5 * (size + w.norm()));
            }
        }
        assert!(Cvec3::ZERO.slerp(Cvec3::X, 0.5).is_nan());
        assert!(Cvec3::X.rotate_towards(Cvec3::ZERO, 0.5).is_nan());
        assert!(Cvec3::X.rotate_towards(Cvec3::Y, f32::NAN).is_nan());
        // Opposite directions turn about a perpendicular axis, keeping the
        // length.
        let v = Cvec3::X.rotate_towards(-Cvec3::X, core::f32::consts::FRAC_PI_2);
        assert!(v.dot(Cvec3::X).abs() < 1e-6 && (v.norm() - 1.0).abs() < 1e-6);
        let v = Cvec3::X.slerp(-Cvec3::X * 3.0, 0.5);
        assert!(v.dot(Cvec3::X).abs() < 1e-5 && (v.norm() - 2.0).abs() < 1e-5);
    }
}
