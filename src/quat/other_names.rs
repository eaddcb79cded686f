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
    }
}

#[cfg(test)]
#[allow(deprecated)]
mod tests {
    use super::*;
    use nalgebra as na;
    use rand::{Rng, SeedableRng};

    fn na_quat(q: Quat) -> na::UnitQuaternion<f32> {
        na::UnitQuaternion::new_unchecked(na::Quaternion::new(q.w, q.x, q.y, q.z))
    }

    fn from_na(q: na::UnitQuaternion<f32>) -> Quat {
        Quat::from_wxyz(q.w, q.i, q.j, q.k)
    }

    fn glam_quat(q: Quat) -> glam::Quat {
        glam::Quat::from_array(q.to_array())
    }

    /// Each of glam's and nalgebra's names gives what it gives there.
    #[test]
    fn other_names_mean_what_they_mean_in_glam_and_nalgebra() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(29);
        for _ in 0..10_000 {
            let mut draw = || {
                Quat::from_axis_angle(
                    Cvec3::new(
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                    ),
                    rng.random_range(-3.0..3.0),
                )
            };
            let (a, b) = (draw(), draw());
            let (ga, gb) = (glam_quat(a), glam_quat(b));
            let (na_a, na_b) = (na_quat(a), na_quat(b));
            assert_eq!(a.conjugate().to_array(), ga.conjugate().to_array());
            assert_eq!(a.inverse().to_array(), ga.inverse().to_array());
            assert!((a.length() - ga.length()).abs() < 1e-6);
            assert!((a.length_squared() - ga.length_squared()).abs() < 1e-6);
            assert!((a.angle_between(b) - ga.angle_between(gb)).abs() < 2e-3);
            assert!((a.angle() - na_a.angle()).abs() < 1e-5);
            assert!(a.rotation_to(b).angle_to(from_na(na_a.rotation_to(&na_b))) < 1e-5);
            assert_eq!(a.xyz().to_array(), ga.xyz().to_array());
            let v = Cvec3::new(1.0, -2.0, 0.5);
            let gv = ga.mul_vec3(glam::Vec3::from_array(v.to_array()));
            assert!((a.mul_vec3(v) - Cvec3::from_array(gv.to_array())).norm() < 1e-5);
            assert!(
                a.mul_quat(b)
                    .angle_to(Quat::from_array(ga.mul_quat(gb).to_array()))
                    < 1e-6
            );
            let t = rng.random_range(0.0..1.0);
            assert!(
                a.lerp(b, t)
                    .angle_to(Quat::from_array(ga.lerp(gb, t).to_array()))
                    < 1e-5
            );
            assert!(a.powf(t).angle_to(from_na(na_a.powf(t))) < 1e-5);
            let (roll, pitch, yaw) = (
                rng.random_range(-3.0..3.0),
                rng.random_range(-1.5..1.5),
                rng.random_range(-3.0..3.0),
            );
            let ours = Quat::from_euler_angles(roll, pitch, yaw);
            let theirs = na::UnitQuaternion::from_euler_angles(roll, pitch, yaw);
            assert!(ours.angle_to(from_na(theirs)) < 1e-5);
            let (r, p, y) = ours.euler_angles();
            let (nr, np, ny) = theirs.euler_angles();
            assert!((r - nr).abs() < 1e-3 && (p - np).abs() < 1e-3 && (y - ny).abs() < 1e-3);
            let w = Cvec3::new(-0.5, 2.0, 0.25);
            let nw = na::Vector3::new(w.x, w.y, w.z);
            let close =
                |u: Cvec3, v: na::Vector3<f32>| (u - Cvec3::new(v.x, v.y, v.z)).norm() < 1e-5;
            assert!(close(a.transform_vector(w), na_a.transform_vector(&nw)));
            assert!(close(
                a.inverse_transform_vector(w),
                na_a.inverse_transform_vector(&nw)
            ));
            let np = na::Point3::new(w.x, w.y, w.z);
            assert!(close(
                a.transform_point(w),
                na_a.transform_point(&np).coords
            ));
            assert!(close(
                a.inverse_transform_point(w),
                na_a.inverse_transform_point(&np).coords
            ));
            let up = Cvec3::new(0.1, 1.0, -0.2);
            if v.normalize().cross(up.normalize()).norm() > 0.1 {
                let (nv, nu) = (
                    na::Vector3::new(v.x, v.y, v.z),
                    na::Vector3::new(up.x, up.y, up.z),
                );
                let theirs = from_na(na::UnitQuaternion::face_towards(&nv, &nu));
                assert!(Quat::face_towards(v, up).angle_to(theirs) < 1e-5);
                let theirs = from_na(na::UnitQuaternion::look_at_rh(&nv, &nu));
                assert!(Quat::look_at_rh(v, up).angle_to(theirs) < 1e-5);
            }
            assert_eq!(a.scaled_axis(), a.to_scaled_axis());
            assert!(close(a.scaled_axis(), na_a.scaled_axis()));
        }
        assert_eq!(Quat::identity().to_array(), glam::Quat::IDENTITY.to_array());
        let mut rng = rand::rngs::StdRng::seed_from_u64(34);
        for _ in 0..10_000 {
            let mut v = || {
                Cvec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                )
                .normalize()
            };
            let (from, to) = (v(), v());
            let ours = Quat::from_rotation_arc_colinear(from, to);
            let theirs = glam::Quat::from_rotation_arc_colinear(
                glam::Vec3::from_array(from.to_array()),
                glam::Vec3::from_array(to.to_array()),
            );
            assert!(ours.angle_to(Quat::from_array(theirs.to_array())) < 1e-4);
            assert!(ours.angle() <= core::f32::consts::FRAC_PI_2 + 1e-6);
            let angle = rng.random_range(0.0..0.01f32);
            let q = Quat::from_axis_angle(from, angle);
            let g = glam::Quat::from_array(q.to_array());
            if (angle - 0.002_847_144_6).abs() > 1e-4 {
                assert_eq!(q.is_near_identity(), g.is_near_identity(), "{angle}");
            }
            assert!((q.length_recip() - g.length_recip()).abs() < 1e-6);
        }
    }
}
