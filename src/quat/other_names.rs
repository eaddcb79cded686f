//! glam's and nalgebra's names for [`Quat`]'s operations, so that their
//! users' first spellings compile or lead to the crate's. Where the other
//! crate's name is simply another word for the same thing (`length`,
//! `conjugate`, `angle_between`), it is a method here too; where the notes
//! have a name of their own (`inv`, `nlerp`, `pow`), the other name is a
//! deprecated method whose warning names the notes' one.
//!
//! Every method here means what it means in glam 0.34 or nalgebra 0.35
//! (tests below hold them against those crates).

use super::{EulerRot, Quat};
use crate::other_names::renamed;
use crate::vec::Cvec3;

impl Quat {
    /// The conjugate `[w, -x, -y, -z]`, glam's and nalgebra's name: the same
    /// as [`inv`](Self::inv), which is the inverse of a unit quaternion.
    /// Exact.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_x(0.3);
    /// assert_eq!(q.conjugate(), q.inv());
    /// ```
    #[inline]
    #[must_use]
    pub fn conjugate(self) -> Self {
        self.inv()
    }

    /// The norm, glam's name for [`norm`](Self::norm) (same accuracy).
    ///
    /// ```
    /// assert_eq!(rigtform::Quat::from_xyzw(0.0, 3.0, 0.0, 4.0).length(), 5.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn length(self) -> f32 {
        self.norm()
    }

    /// The squared norm, glam's name for [`norm_squared`](Self::norm_squared).
    ///
    /// ```
    /// assert_eq!(rigtform::Quat::IDENTITY.length_squared(), 1.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn length_squared(self) -> f32 {
        self.norm_squared()
    }

    /// The angle in [0, pi] between two rotations, glam's name for
    /// [`angle_to`](Self::angle_to) (same preconditions and accuracy).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::from_rotation_x(0.25), Quat::from_rotation_x(1.0));
    /// assert_eq!(a.angle_between(b), a.angle_to(b));
    /// ```
    #[inline]
    #[must_use]
    pub fn angle_between(self, other: Self) -> f32 {
        self.angle_to(other)
    }

    /// The rotation angle in [0, pi], nalgebra's `UnitQuaternion::angle`:
    /// the angle of [`to_axis_angle`](Self::to_axis_angle) (same
    /// preconditions and accuracy).
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert!((Quat::from_rotation_y(-2.0).angle() - 2.0).abs() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn angle(self) -> f32 {
        self.to_axis_angle().1
    }

    /// The rotation that takes `self` to `other`, `other * self.inv()`:
    /// nalgebra's `rotation_to`.
    ///
    /// # Preconditions
    ///
    /// Unit quaternions.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::from_rotation_x(0.2), Quat::from_rotation_y(0.7));
    /// assert!((a.rotation_to(b) * a).angle_to(b) < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn rotation_to(self, other: Self) -> Self {
        other * self.inv()
    }

    /// The vector part, glam's name for [`vector`](Self::vector).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// assert_eq!(Quat::from_xyzw(1.0, 2.0, 3.0, 4.0).xyz(), Cvec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn xyz(self) -> Cvec3 {
        self.vector()
    }

    /// `1 / |self|`, glam's `length_recip`.
    ///
    /// ```
    /// assert_eq!(rigtform::Quat::from_xyzw(0.0, 0.0, 0.0, 2.0).length_recip(), 0.5);
    /// ```
    #[inline]
    #[must_use]
    pub fn length_recip(self) -> f32 {
        1.0 / self.norm()
    }

    /// `true` if the rotation turns by less than 0.002 847 144 6 radians,
    /// the threshold of glam's `is_near_identity` (either sign of the
    /// quaternion; [`angle`](Self::angle) measures the turn). `false` for
    /// NaN.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert!(Quat::from_rotation_x(1e-3).is_near_identity());
    /// assert!(!Quat::from_rotation_x(1e-2).is_near_identity());
    /// assert!((-Quat::IDENTITY).is_near_identity());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_near_identity(self) -> bool {
        self.angle() < 0.002_847_144_6
    }

    /// The shortest rotation taking `from` to either `to` or `-to`,
    /// whichever is nearer: glam's `from_rotation_arc_colinear`, for
    /// directions whose sign does not matter (an axis, a line of sight).
    /// Otherwise as [`from_rotation_arc`](Self::from_rotation_arc), with
    /// its preconditions and accuracy; the turn is at most pi/2.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_arc_colinear(Cvec3::X, -Cvec3::X);
    /// assert!(q.angle() < 1e-6); // -X is already on the line of X
    /// ```
    #[must_use]
    pub fn from_rotation_arc_colinear(from: Cvec3, to: Cvec3) -> Self {
        if from.dot(to) < 0.0 {
            Self::from_rotation_arc(from, -to)
        } else {
            Self::from_rotation_arc(from, to)
        }
    }

    /// `v` rotated, nalgebra's `transform_vector` (which takes `&v`): the
    /// same as `self * v`, with its preconditions and accuracy.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_z(0.5);
    /// assert_eq!(q.transform_vector(Cvec3::X), q * Cvec3::X);
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_vector(self, v: Cvec3) -> Cvec3 {
        self * v
    }

    /// `p` rotated about the origin, nalgebra's `transform_point`: for a
    /// rotation, the same as [`transform_vector`](Self::transform_vector).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_z(0.5);
    /// assert_eq!(q.transform_point(Cvec3::Y), q * Cvec3::Y);
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_point(self, p: Cvec3) -> Cvec3 {
        self * p
    }

    /// `v` rotated back, `self.inv() * v`: nalgebra's
    /// `inverse_transform_vector`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_z(0.5);
    /// assert!((q.inverse_transform_vector(q * Cvec3::X) - Cvec3::X).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse_transform_vector(self, v: Cvec3) -> Cvec3 {
        self.inv() * v
    }

    /// `p` rotated back about the origin, nalgebra's
    /// `inverse_transform_point`: as
    /// [`inverse_transform_vector`](Self::inverse_transform_vector).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_y(1.0);
    /// assert!((q.inverse_transform_point(q * Cvec3::Z) - Cvec3::Z).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse_transform_point(self, p: Cvec3) -> Cvec3 {
        self.inv() * p
    }

    /// The rotation whose matrix has the columns `x_axis`, `y_axis` and
    /// `z_axis` (glam's `from_rotation_axes`): as
    /// [`from_mat3`](Self::from_mat3) of those columns, with its
    /// preconditions (an orthonormal, right-handed basis) and accuracy.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_axes(Cvec3::Y, -Cvec3::X, Cvec3::Z);
    /// assert!(q.angle_to(Quat::from_rotation_z(core::f32::consts::FRAC_PI_2)) < 1e-6);
    /// ```
    #[must_use]
    pub fn from_rotation_axes(x_axis: Cvec3, y_axis: Cvec3, z_axis: Cvec3) -> Self {
        Self::from_basis(x_axis, y_axis, z_axis)
    }

    /// The rotation's unit axis, nalgebra's `UnitQuaternion::axis`: the
    /// direction of the vector part of the quaternion written with
    /// `w >= 0` ([`cn`](Self::cn)), so that the angle about it is
    /// [`angle`](Self::angle), in [0, pi]. `None` where there is no axis:
    /// no rotation (a zero vector part), and NaN or infinite components.
    ///
    /// # Accuracy
    ///
    /// As [`try_normalize`](Self::try_normalize) of the vector part.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_axis_angle(Cvec3::new(0.0, 0.0, -2.0), 0.5);
    /// assert_eq!(q.axis(), Some(-Cvec3::Z));
    /// assert_eq!((-q).axis(), Some(-Cvec3::Z));
    /// assert_eq!(Quat::IDENTITY.axis(), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn axis(self) -> Option<Cvec3> {
        self.cn().vector().try_normalize()
    }

    /// nalgebra's `renormalize`: here `q = q.normalize()` (the notes'
    /// word). Like nalgebra's, it normalizes in place and returns the norm
    /// it had.
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::Quat;
    /// let mut q = Quat::from_xyzw(0.0, 0.0, 0.0, 2.0);
    /// assert_eq!(q.renormalize(), 2.0);
    /// assert_eq!(q, Quat::IDENTITY);
    /// ```
    #[deprecated(since = "0.1.0", note = "use `q = q.normalize()`")]
    #[inline]
    pub fn renormalize(&mut self) -> f32 {
        let norm = self.norm();
        *self = self.normalize();
        norm
    }

    renamed! {
        /// nalgebra's `scaled_axis`: here [`to_scaled_axis`](Self::to_scaled_axis).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// let q = rigtform::Quat::from_rotation_x(0.5);
        /// assert_eq!(q.scaled_axis(), q.to_scaled_axis());
        /// ```
        note "use `Quat::to_scaled_axis`";
        pub fn scaled_axis(self) -> Cvec3 {
            self.to_scaled_axis()
        }

        /// nalgebra's `axis_angle` (an `Option`): here
        /// [`to_axis_angle`](Self::to_axis_angle), which gives the x axis and 0
        /// for no rotation.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// let q = rigtform::Quat::from_rotation_x(0.5);
        /// assert_eq!(q.axis_angle(), q.to_axis_angle());
        /// ```
        note "use `Quat::to_axis_angle`, which returns (axis, angle)";
        pub fn axis_angle(self) -> (Cvec3, f32) {
            self.to_axis_angle()
        }

        /// nalgebra's `rotation_between(a, b)` (an `Option`): here
        /// [`from_rotation_arc`](Self::from_rotation_arc), which takes any two
        /// non-zero directions, opposite ones included.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Quat};
        /// assert_eq!(Quat::rotation_between(Cvec3::X, Cvec3::Y), Quat::from_rotation_arc(Cvec3::X, Cvec3::Y));
        /// ```
        note "use `Quat::from_rotation_arc(from, to)`";
        pub fn rotation_between(from: Cvec3, to: Cvec3) -> Self {
            Self::from_rotation_arc(from, to)
        }

        /// glam's and nalgebra's `inverse`: the notes call it `inv`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// let q = Quat::from_rotation_x(0.3);
        /// assert_eq!(q.inverse(), q.inv());
        /// ```
        note "the notes' name is `inv`: use `Quat::inv` (the conjugate, the inverse of a unit quaternion)";
        pub fn inverse(self) -> Self {
            self.inv()
        }

        /// glam's `lerp` (sign-aligned, normalized): here `nlerp`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// let (a, b) = (Quat::from_rotation_x(0.2), Quat::from_rotation_x(0.6));
        /// assert_eq!(a.lerp(b, 0.5), a.nlerp(b, 0.5));
        /// ```
        note "a normalized, sign-aligned lerp is `Quat::nlerp` here (and `Quat::slerp` the spherical one)";
        pub fn lerp(self, other: Self, alpha: f32) -> Self {
            self.nlerp(other, alpha)
        }

        /// nalgebra's `powf`: the notes' `pow`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// let q = Quat::from_rotation_x(1.2);
        /// assert_eq!(q.powf(0.5), q.pow(0.5));
        /// ```
        note "the notes' name is `pow`: use `Quat::pow`";
        pub fn powf(self, alpha: f32) -> Self {
            self.pow(alpha)
        }

        /// nalgebra's `UnitQuaternion::identity()`: the constant
        /// [`Quat::IDENTITY`].
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// assert_eq!(rigtform::Quat::identity(), rigtform::Quat::IDENTITY);
        /// ```
        note "use the constant `Quat::IDENTITY`";
        pub const fn identity() -> Self {
            Self::IDENTITY
        }

        /// nalgebra's `from_euler_angles(roll, pitch, yaw)`: the rotation
        /// `Rz(yaw) Ry(pitch) Rx(roll)`, which is
        /// `Quat::from_euler(EulerRot::ZYX, yaw, pitch, roll)` here.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{EulerRot, Quat};
        /// assert_eq!(
        ///     Quat::from_euler_angles(0.1, 0.2, 0.3),
        ///     Quat::from_euler(EulerRot::ZYX, 0.3, 0.2, 0.1)
        /// );
        /// ```
        note "use `Quat::from_euler(EulerRot::ZYX, yaw, pitch, roll)`: the order is in its first argument";
        pub fn from_euler_angles(roll: f32, pitch: f32, yaw: f32) -> Self {
            Self::from_euler(EulerRot::ZYX, yaw, pitch, roll)
        }

        /// nalgebra's `euler_angles()`: `(roll, pitch, yaw)`, which is
        /// `to_euler(EulerRot::ZYX)` in reverse here.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{EulerRot, Quat};
        /// let q = Quat::from_euler(EulerRot::ZYX, 0.3, 0.2, 0.1);
        /// let (roll, pitch, yaw) = q.euler_angles();
        /// assert_eq!((yaw, pitch, roll), q.to_euler(EulerRot::ZYX));
        /// ```
        note "use `q.to_euler(EulerRot::ZYX)`, which returns (yaw, pitch, roll)";
        pub fn euler_angles(self) -> (f32, f32, f32) {
            let (yaw, pitch, roll) = self.to_euler(EulerRot::ZYX);
            (roll, pitch, yaw)
        }

        /// nalgebra's `UnitQuaternion::new_normalize(q)`: here
        /// [`q.normalize()`](Self::normalize). A `Quat` has no unit
        /// wrapper; the methods that need a unit quaternion say so.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// let q = Quat::from_wxyz(2.0, 0.0, 0.0, 0.0);
        /// assert_eq!(Quat::new_normalize(q), q.normalize());
        /// ```
        note "use `q.normalize()`: a `Quat` has no unit wrapper";
        pub fn new_normalize(q: Self) -> Self {
            q.normalize()
        }

        /// nalgebra's `UnitQuaternion::new_unchecked(q)`: here `q` itself.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// assert_eq!(Quat::new_unchecked(Quat::IDENTITY), Quat::IDENTITY);
        /// ```
        note "a `Quat` has no unit wrapper: use `q` itself";
        pub const fn new_unchecked(q: Self) -> Self {
            q
        }

        /// nalgebra's `UnitQuaternion::quaternion()`: here the `Quat`
        /// itself.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// assert_eq!(Quat::IDENTITY.quaternion().w, 1.0);
        /// ```
        note "a `Quat` has no unit wrapper: use `q` itself";
        pub const fn quaternion(&self) -> &Self {
            self
        }

        /// nalgebra's `UnitQuaternion::into_inner()`: here the `Quat`
        /// itself.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// assert_eq!(Quat::IDENTITY.into_inner(), Quat::IDENTITY);
        /// ```
        note "a `Quat` has no unit wrapper: use `q` itself";
        pub const fn into_inner(self) -> Self {
            self
        }

        /// nalgebra's `imag()`, the vector part: here
        /// [`vector`](Self::vector) (or glam's [`xyz`](Self::xyz)).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// let q = Quat::from_xyzw(1.0, 2.0, 3.0, 4.0);
        /// assert_eq!(q.imag(), q.vector());
        /// ```
        note "use `q.vector()`, the vector part";
        pub const fn imag(&self) -> Cvec3 {
            self.vector()
        }

        /// nalgebra's `scalar()`, the scalar part: here the field `w`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::Quat;
        /// assert_eq!(Quat::IDENTITY.scalar(), Quat::IDENTITY.w);
        /// ```
        note "use the field `q.w`, the scalar part";
        pub const fn scalar(&self) -> f32 {
            self.w
        }
    }
}

#[cfg(test)]
mod tests;
