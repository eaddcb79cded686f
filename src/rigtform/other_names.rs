//! glam's (`Affine3A`) and nalgebra's (`Isometry3`) names for
//! [`RigTForm`]'s operations, and the few operations of theirs the notes
//! do not name: `RigTForm * Cvec3`, the inverse transforms of points and
//! vectors and `is_finite` (the rigid transform of a `Matrix4` is with the
//! matrices, in `matrix/rig_tform_conversions.rs`). Where the notes have a name of their
//! own (`inv`, `interpolate`), the other name is a deprecated method whose
//! warning names the notes' one.

use core::ops::Mul;

use super::RigTForm;
use crate::other_names::renamed;
use crate::quat::Quat;
use crate::vec::Cvec3;

impl RigTForm {
    /// `self * other`, the composition (the notes' "rbt * rbt"): glam's
    /// way of naming a product (`mul_quat`, `mul_mat4`).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::X, Quat::from_rotation_z(0.3));
    /// let b = RigTForm::new(Cvec3::Y, Quat::from_rotation_x(0.2));
    /// assert_eq!(a.mul_rig_tform(b), a * b);
    /// ```
    ///
    /// `*` calls this method, so its Kani contract (`docs/kani.md`) covers
    /// both spellings.
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::rigtform_mul_requires(self, other))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &RigTForm| crate::kani_contracts::rigtform_mul_ensures(self, other, *r)))]
    #[inline]
    #[must_use]
    pub fn mul_rig_tform(self, other: Self) -> Self {
        Self::new(self.t + self.r * other.t, self.r * other.r)
    }

    /// The transform that rotates by `r`, then translates by `t`, glam's
    /// `Affine3A::from_rotation_translation` (arguments in that order): the
    /// same as [`RigTForm::new(t, r)`](Self::new).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let r = Quat::from_rotation_z(0.5);
    /// assert_eq!(RigTForm::from_rotation_translation(r, Cvec3::X), RigTForm::new(Cvec3::X, r));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_rotation_translation(r: Quat, t: Cvec3) -> Self {
        Self::new(t, r)
    }

    /// The point `p` taken back through the transform, `r^-1 (p - t)`:
    /// nalgebra's `inverse_transform_point`, the same as
    /// `self.inv().transform_point(p)` without composing the inverse.
    ///
    /// # Preconditions
    ///
    /// `r` is a unit quaternion.
    ///
    /// # Accuracy
    ///
    /// One rounding of the difference, then the rotation's error, at most
    /// [`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|p - t|`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::from_rotation_y(0.7));
    /// let p = Cvec3::new(-4.0, 0.5, 2.0);
    /// assert!((a.inverse_transform_point(a.transform_point(p)) - p).norm() < 1e-5);
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse_transform_point(self, p: Cvec3) -> Cvec3 {
        self.r.inv() * (p - self.t)
    }

    /// The vector `v` taken back through the rotation, `r^-1 v`:
    /// nalgebra's `inverse_transform_vector`.
    ///
    /// # Preconditions
    ///
    /// `r` is a unit quaternion.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(9.0, 0.0, 0.0), Quat::from_rotation_z(0.7));
    /// let v = Cvec3::new(1.0, 2.0, 0.0);
    /// assert!((a.inverse_transform_vector(a.transform_vector(v)) - v).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn inverse_transform_vector(self, v: Cvec3) -> Cvec3 {
        self.r.inv() * v
    }

    /// `true` if every component of `t` and `r` is finite.
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// assert!(RigTForm::IDENTITY.is_finite());
    /// assert!(!RigTForm::from_translation(Cvec3::new(f32::INFINITY, 0.0, 0.0)).is_finite());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.t.is_finite() && self.r.is_finite()
    }

    /// `true` if any component of `t` or `r` is NaN.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// assert!(RigTForm::from_rotation(Quat::NAN).is_nan());
    /// assert!(!RigTForm::IDENTITY.is_nan());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_nan(self) -> bool {
        let Cvec3 { x, y, z } = self.t;
        x.is_nan() || y.is_nan() || z.is_nan() || self.r.is_nan()
    }

    /// nalgebra's `Isometry3::face_towards`: the frame of an observer at
    /// `eye` whose +z axis points at `target`, its y axis towards `up`.
    /// That is [`look_at`](Self::look_at) turned half way round about its y
    /// axis, since the notes' eye looks down -z: use `look_at` for a camera,
    /// this for an object that faces what it looks at along +z.
    ///
    /// # Preconditions and accuracy
    ///
    /// Those of [`look_at`](Self::look_at); the half turn is exact.
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// let a = RigTForm::face_towards(Cvec3::ZERO, Cvec3::new(3.0, 0.0, 0.0), Cvec3::Y);
    /// assert!((a.transform_vector(Cvec3::Z) - Cvec3::X).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn face_towards(eye: Cvec3, target: Cvec3, up: Cvec3) -> Self {
        let frame = Self::look_at(eye, target, up);
        // A half turn about y, `[0, 0, 1, 0]` scalar last: `(x, y, z, w) *
        // (0, 1, 0, 0)` with every product exact but for signs.
        let r = frame.r;
        Self::new(frame.t, Quat::from_xyzw(-r.z, r.w, r.x, -r.y))
    }

    /// nalgebra's `Isometry3::look_at_rh`: the view transform of an eye at
    /// `eye` looking at `target`, world to eye, which takes `eye` to the
    /// origin and `target` onto the -z axis. The inverse of the eye frame
    /// [`look_at`](Self::look_at) returns; `Matrix4::from` of it is glam's
    /// `Mat4::look_at_rh`.
    ///
    /// # Preconditions and accuracy
    ///
    /// Those of [`look_at`](Self::look_at) and [`inv`](Self::inv).
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// let view = RigTForm::look_at_rh(Cvec3::new(0.0, 0.0, 5.0), Cvec3::ZERO, Cvec3::Y);
    /// assert!((view.transform_point(Cvec3::ZERO) - Cvec3::new(0.0, 0.0, -5.0)).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn look_at_rh(eye: Cvec3, target: Cvec3, up: Cvec3) -> Self {
        Self::look_at(eye, target, up).inv()
    }

    /// The rotation by `angle` radians about `axis`, without translation
    /// (glam's `Affine3A::from_axis_angle`): the rotation of
    /// [`Quat::from_axis_angle`], with its preconditions (any non-zero
    /// axis) and accuracy.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::from_axis_angle(Cvec3::Y, 0.5);
    /// assert_eq!(a, RigTForm::from_rotation(Quat::from_axis_angle(Cvec3::Y, 0.5)));
    /// ```
    #[must_use]
    pub fn from_axis_angle(axis: Cvec3, angle: f32) -> Self {
        Self::from_rotation(Quat::from_axis_angle(axis, angle))
    }

    renamed! {
        /// nalgebra's `Isometry3::from_parts(translation, rotation)`: here
        /// [`RigTForm::new(t, r)`](Self::new).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Quat, RigTForm};
        /// assert_eq!(RigTForm::from_parts(Cvec3::X, Quat::IDENTITY), RigTForm::new(Cvec3::X, Quat::IDENTITY));
        /// ```
        note "use `RigTForm::new(t, r)`";
        pub const fn from_parts(t: Cvec3, r: Quat) -> Self {
            Self::new(t, r)
        }

        /// glam's `Affine3A::from_quat(rotation)`: here
        /// [`RigTForm::from_rotation`].
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Quat, RigTForm};
        /// let q = Quat::from_rotation_z(0.4);
        /// assert_eq!(RigTForm::from_quat(q), RigTForm::from_rotation(q));
        /// ```
        note "use `RigTForm::from_rotation(r)`";
        pub const fn from_quat(r: Quat) -> Self {
            Self::from_rotation(r)
        }

        /// glam's and nalgebra's `inverse`: the notes call it `inv`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Quat, RigTForm};
        /// let a = RigTForm::new(Cvec3::X, Quat::from_rotation_y(0.3));
        /// assert_eq!(a.inverse(), a.inv());
        /// ```
        note "the notes' name is `inv`: use `RigTForm::inv`";
        pub fn inverse(self) -> Self {
            self.inv()
        }

        /// A `lerp` of two frames: here [`interpolate`](Self::interpolate)
        /// (the translation lerped, the rotation slerped), as nalgebra's
        /// `Isometry3::lerp_slerp`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Quat, RigTForm};
        /// let (a, b) = (RigTForm::IDENTITY, RigTForm::new(Cvec3::X, Quat::from_rotation_z(1.0)));
        /// assert_eq!(a.lerp(b, 0.5), a.interpolate(b, 0.5));
        /// ```
        note "the notes' name is `interpolate`: use `RigTForm::interpolate` (lerp of t, slerp of r)";
        pub fn lerp(self, other: Self, alpha: f32) -> Self {
            self.interpolate(other, alpha)
        }

        /// nalgebra's `lerp_slerp`: here [`interpolate`](Self::interpolate).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Quat, RigTForm};
        /// let (a, b) = (RigTForm::IDENTITY, RigTForm::new(Cvec3::X, Quat::from_rotation_z(1.0)));
        /// assert_eq!(a.lerp_slerp(b, 0.5), a.interpolate(b, 0.5));
        /// ```
        note "the notes' name is `interpolate`: use `RigTForm::interpolate`";
        pub fn lerp_slerp(self, other: Self, alpha: f32) -> Self {
            self.interpolate(other, alpha)
        }

        /// glam's `Affine3A::transform_point3`: here
        /// [`transform_point`](Self::transform_point).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, RigTForm};
        /// let a = RigTForm::from_translation(Cvec3::X);
        /// assert_eq!(a.transform_point3(Cvec3::Y), a.transform_point(Cvec3::Y));
        /// ```
        note "use `RigTForm::transform_point`";
        pub fn transform_point3(self, p: Cvec3) -> Cvec3 {
            self.transform_point(p)
        }

        /// glam's `Affine3A::transform_vector3`: here
        /// [`transform_vector`](Self::transform_vector).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, RigTForm};
        /// let a = RigTForm::from_translation(Cvec3::X);
        /// assert_eq!(a.transform_vector3(Cvec3::Y), Cvec3::Y);
        /// ```
        note "use `RigTForm::transform_vector`";
        pub fn transform_vector3(self, v: Cvec3) -> Cvec3 {
            self.transform_vector(v)
        }

        /// nalgebra's `Isometry3::identity()`: the constant
        /// [`RigTForm::IDENTITY`].
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// assert_eq!(rigtform::RigTForm::identity(), rigtform::RigTForm::IDENTITY);
        /// ```
        note "use the constant `RigTForm::IDENTITY`";
        pub const fn identity() -> Self {
            Self::IDENTITY
        }
    }
}

impl Mul<Cvec3> for RigTForm {
    type Output = Cvec3;

    /// Applies the transform to a point: [`transform_point`](RigTForm::transform_point),
    /// as nalgebra's `Isometry3 * Point3` and glam's
    /// `Affine3A::transform_point3`. A direction is not translated: use
    /// [`transform_vector`](RigTForm::transform_vector) for it (or a
    /// [`Cvec4`](crate::Cvec4) with `w = 0`).
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// let a = RigTForm::from_translation(Cvec3::new(5.0, 0.0, 0.0));
    /// assert_eq!(a * Cvec3::X, Cvec3::new(6.0, 0.0, 0.0));
    /// assert_eq!(a.transform_vector(Cvec3::X), Cvec3::X);
    /// ```
    #[inline]
    fn mul(self, p: Cvec3) -> Cvec3 {
        self.transform_point(p)
    }
}

#[cfg(test)]
#[allow(deprecated)]
mod tests {
    use super::*;
    use crate::test_draws::rig_tform;
    use nalgebra as na;
    use rand::{Rng, SeedableRng};

    fn na_iso(a: RigTForm) -> na::Isometry3<f32> {
        na::Isometry3::from_parts(
            na::Translation3::new(a.t.x, a.t.y, a.t.z),
            na::UnitQuaternion::new_unchecked(na::Quaternion::new(a.r.w, a.r.x, a.r.y, a.r.z)),
        )
    }

    /// Each name means what it means in nalgebra's `Isometry3`.
    /// The product is the notes' "rbt * rbt" (translation `t1 + r1 t2`,
    /// rotation `r1 r2`), nalgebra's `Isometry3 * Isometry3`, and `*`.
    #[test]
    fn mul_rig_tform_composes_as_nalgebra_and_is_the_operator() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(36);
        for _ in 0..10_000 {
            let (a, b) = (rig_tform(&mut rng), rig_tform(&mut rng));
            let ab = a.mul_rig_tform(b);
            assert_eq!(ab, a * b);
            let theirs = na_iso(a) * na_iso(b);
            let t = theirs.translation.vector;
            assert!((ab.t - Cvec3::new(t.x, t.y, t.z)).norm() < 1e-4 * (1.0 + ab.t.norm()));
            let q = theirs.rotation.quaternion();
            let r = Quat::from_wxyz(q.w, q.i, q.j, q.k);
            assert!(ab.r.angle_to(r) < 1e-5, "{a:?} {b:?}");
        }
    }

    #[test]
    fn other_names_agree_with_nalgebra() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(30);
        for _ in 0..10_000 {
            let (a, b) = (rig_tform(&mut rng), rig_tform(&mut rng));
            let iso = na_iso(a);
            let p = Cvec3::new(3.0, -1.0, 0.25);
            let np = na::Point3::new(p.x, p.y, p.z);
            let close =
                |u: Cvec3, v: [f32; 3]| (u - Cvec3::from_array(v)).norm() < 1e-4 * (1.0 + u.norm());
            assert!(close(a * p, (iso * np).coords.into()));
            assert!(close(
                a.inverse_transform_point(p),
                iso.inverse_transform_point(&np).coords.into()
            ));
            let nv = na::Vector3::new(p.x, p.y, p.z);
            assert!(close(
                a.inverse_transform_vector(p),
                iso.inverse_transform_vector(&nv).into()
            ));
            let t = rng.random_range(0.0..1.0);
            let theirs = iso.lerp_slerp(&na_iso(b), t);
            let ours = a.lerp(b, t);
            assert!(close(ours.t, theirs.translation.vector.into()));
            assert_eq!(a.lerp_slerp(b, t), a.interpolate(b, t));
            assert_eq!(a.inverse(), a.inv());
            assert_eq!(a.transform_point3(p), a.transform_point(p));
            assert_eq!(a.transform_vector3(p), a.transform_vector(p));
            assert_eq!(RigTForm::from_rotation_translation(a.r, a.t), a);
        }
        assert_eq!(RigTForm::identity(), RigTForm::IDENTITY);
    }

    /// glam's `Affine3A::from_axis_angle` and `from_quat` map points as
    /// glam's do.
    #[test]
    fn glams_affine_constructors_agree_with_glam() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(45);
        for _ in 0..10_000 {
            let mut c = || rng.random_range(-1.0f32..1.0);
            let axis = Cvec3::new(c(), c(), c()).normalize();
            let (angle, p) = (3.0 * c(), Cvec3::new(c(), c(), c()) * 10.0);
            let g = |v: Cvec3| glam::Vec3::from_array(v.to_array());
            let theirs = glam::Affine3A::from_axis_angle(g(axis), angle).transform_point3(g(p));
            let ours = RigTForm::from_axis_angle(axis, angle);
            assert!((ours * p - Cvec3::from_array(theirs.to_array())).norm() < 1e-5);
            let q = ours.r;
            let theirs = glam::Affine3A::from_quat(glam::Quat::from_array(q.to_array()));
            let theirs = theirs.transform_point3(g(p));
            assert_eq!(RigTForm::from_quat(q), RigTForm::from_rotation(q));
            assert!(
                (RigTForm::from_quat(q) * p - Cvec3::from_array(theirs.to_array())).norm() < 1e-5
            );
        }
    }

    /// `face_towards` and `look_at_rh` mean what they mean in nalgebra:
    /// +z towards the target, and the view transform.
    #[test]
    fn face_towards_and_look_at_rh_agree_with_nalgebra() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(35);
        for _ in 0..10_000 {
            let mut c = || rng.random_range(-10.0f32..10.0);
            let (eye, target) = (Cvec3::new(c(), c(), c()), Cvec3::new(c(), c(), c()));
            let up = Cvec3::new(c(), c(), c());
            let sight = target - eye;
            if sight.norm() < 1e-2 || up.normalize().cross(sight.normalize()).norm() < 0.1 {
                continue;
            }
            let (ne, nt, nu) = (
                na::Point3::new(eye.x, eye.y, eye.z),
                na::Point3::new(target.x, target.y, target.z),
                na::Vector3::new(up.x, up.y, up.z),
            );
            let iso = |i: na::Isometry3<f32>| {
                let q = i.rotation.into_inner();
                let t = i.translation.vector;
                RigTForm::new(
                    Cvec3::new(t.x, t.y, t.z),
                    Quat::from_wxyz(q.w, q.i, q.j, q.k),
                )
            };
            let theirs = iso(na::Isometry3::face_towards(&ne, &nt, &nu));
            let ours = RigTForm::face_towards(eye, target, up);
            assert!(ours.r.angle_to(theirs.r) < 1e-5, "{ours:?} {theirs:?}");
            assert_eq!(ours.t, eye);
            let theirs = iso(na::Isometry3::look_at_rh(&ne, &nt, &nu));
            let ours = RigTForm::look_at_rh(eye, target, up);
            assert!(ours.r.angle_to(theirs.r) < 1e-5);
            assert!((ours.t - theirs.t).norm() < 1e-4 * (1.0 + eye.norm()));
        }
    }
}
