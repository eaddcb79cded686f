//! Building a [`Quat`]: from its components in either order, from an
//! axis and an angle (the notes' "the representation"), and about a
//! coordinate axis.

use super::Quat;
use crate::float;
use crate::vec::Cvec3;

impl Quat {
    /// The identity rotation `[1, 0, 0, 0]`.
    pub const IDENTITY: Self = Self::from_wxyz(1.0, 0.0, 0.0, 0.0);

    /// All components NaN: the documented result for NaN or infinite input.
    pub const NAN: Self = Self::from_wxyz(f32::NAN, f32::NAN, f32::NAN, f32::NAN);

    /// Builds a quaternion from its components in glam's order, scalar
    /// last: `x, y, z` the vector part, `w` the scalar part. The same as
    /// glam's `Quat::from_xyzw`.
    ///
    /// # Preconditions
    ///
    /// None here; the rotation methods expect a unit quaternion and say so.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_xyzw(0.0, 0.0, 0.0, 1.0), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_xyzw(x: f32, y: f32, z: f32, w: f32) -> Self {
        Self { x, y, z, w }
    }

    /// Builds a quaternion from its components scalar first, as the notes
    /// write `[w, c]` and as nalgebra's `Quaternion::new(w, i, j, k)` takes
    /// them.
    ///
    /// # Preconditions
    ///
    /// None here; the rotation methods expect a unit quaternion and say so.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_wxyz(1.0, 0.0, 0.0, 0.0), Quat::IDENTITY);
    /// assert_eq!(Quat::from_wxyz(4.0, 1.0, 2.0, 3.0), Quat::from_xyzw(1.0, 2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_wxyz(w: f32, x: f32, y: f32, z: f32) -> Self {
        Self { x, y, z, w }
    }

    /// Scalar first, as [`from_wxyz`](Self::from_wxyz). Its order is not
    /// in its name, and glam's users expect scalar last: call
    /// [`from_wxyz`](Self::from_wxyz) or [`from_xyzw`](Self::from_xyzw).
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::Quat;
    /// assert_eq!(Quat::new(1.0, 0.0, 0.0, 0.0), Quat::from_wxyz(1.0, 0.0, 0.0, 0.0));
    /// ```
    #[deprecated(
        since = "0.1.0",
        note = "the order is not in the name: use `Quat::from_wxyz(w, x, y, z)` (scalar first, \
                as here and in nalgebra's `Quaternion::new`) or `Quat::from_xyzw(x, y, z, w)` (glam's)"
    )]
    #[inline]
    #[must_use]
    pub const fn new(w: f32, x: f32, y: f32, z: f32) -> Self {
        Self::from_wxyz(w, x, y, z)
    }

    /// The rotation by `angle` radians about `axis`, by the right-hand rule:
    /// `[cos(angle/2), sin(angle/2) k]` with `k = axis / |axis|` (the notes'
    /// "the representation").
    ///
    /// # Preconditions
    ///
    /// `axis` need not be of unit length: it is normalized here (exactly
    /// scaled, so subnormal and huge axes work). A zero axis gives
    /// [`Quat::IDENTITY`] (no direction, no rotation); a NaN or infinite axis
    /// or angle gives [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// The result's norm is within [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_axis_angle(Cvec3::new(0.0, 0.0, 2.0), PI);
    /// assert!((q * Cvec3::X + Cvec3::X).norm() < 1e-6); // half a turn about z
    /// assert_eq!(Quat::from_axis_angle(Cvec3::ZERO, 1.0), Quat::IDENTITY);
    /// ```
    #[must_use]
    pub fn from_axis_angle(axis: Cvec3, angle: f32) -> Self {
        if !(axis.is_finite() && angle.is_finite()) {
            return Self::NAN;
        }
        match axis.try_normalize() {
            Some(k) => {
                let (s, c) = float::sin_cos(angle * 0.5);
                Self::from_scalar_vector(c, k * s)
            }
            None => Self::IDENTITY,
        }
    }

    /// The rotation by `angle` radians about the x axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_x(FRAC_PI_2) * Cvec3::Y;
    /// assert!((v - Cvec3::Z).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_x(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, s, 0.0, 0.0)
    }

    /// The rotation by `angle` radians about the y axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_y(FRAC_PI_2) * Cvec3::Z;
    /// assert!((v - Cvec3::X).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_y(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, 0.0, s, 0.0)
    }

    /// The rotation by `angle` radians about the z axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_z(FRAC_PI_2) * Cvec3::X;
    /// assert!((v - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_z(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, 0.0, 0.0, s)
    }

    #[inline]
    pub(crate) const fn from_scalar_vector(w: f32, v: Cvec3) -> Self {
        Self::from_wxyz(w, v.x, v.y, v.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_about_the_axes_follow_the_right_hand_rule() {
        let quarter = core::f32::consts::FRAC_PI_2;
        let cases = [
            (Quat::from_rotation_x(quarter), Cvec3::X, Cvec3::Y, Cvec3::Z),
            (Quat::from_rotation_y(quarter), Cvec3::Y, Cvec3::Z, Cvec3::X),
            (Quat::from_rotation_z(quarter), Cvec3::Z, Cvec3::X, Cvec3::Y),
        ];
        // The kernel's sine and cosine errors, doubled by the rotation.
        let tol = 4.0 * crate::accuracy::SIN_COS_MAX_ABS_ERROR;
        for (q, axis, from, to) in cases {
            assert!((q * from - to).norm() <= tol, "{q:?}");
            assert!((q * axis - axis).norm() <= tol, "{q:?}");
            for angle in [-2.5f32, 0.3, 3.0] {
                let about = Quat::from_axis_angle(axis, angle);
                let named = match axis {
                    Cvec3::X => Quat::from_rotation_x(angle),
                    Cvec3::Y => Quat::from_rotation_y(angle),
                    _ => Quat::from_rotation_z(angle),
                };
                assert_eq!(named, about);
            }
        }
    }
}
