//! [`RigTForm::look_at`]: the frame of an eye at one point looking at
//! another, as the notes' eye frame (`eyeRbt`): the eye looks down its own
//! -z axis, with its y axis up, as in OpenGL; and nalgebra's rotations
//! that look along a direction, `Quat::face_towards` and `Quat::look_at_rh`,
//! which are the rotations of such frames.

use super::RigTForm;
use crate::quat::Quat;
use crate::vec::Cvec3;

impl RigTForm {
    /// The frame of an eye at `eye` looking at `target`: its -z axis points
    /// at `target`, its y axis is as close to `up` as that allows, and its
    /// x axis is `y x z` (right-handed: x to the right of the view).
    ///
    /// This is the eye frame itself (camera to world); the view matrix a
    /// renderer needs is its inverse, `Matrix4::from(eye.inv())` (glam's
    /// `Mat4::look_at_rh`).
    ///
    /// # Preconditions
    ///
    /// `up` need not be of unit length. Where `up` is zero or parallel to
    /// the line of sight it cannot fix the roll: the rotation is then the
    /// shortest one taking -z to the line of sight
    /// ([`Quat::from_rotation_arc`]). Where `eye == target` there is no line
    /// of sight: the rotation is [`Quat::IDENTITY`] (looking down -z). NaN or
    /// infinite input gives a NaN rotation.
    ///
    /// # Accuracy
    ///
    /// The rotation is within
    /// [`accuracy::LOOK_AT_MAX_ANGLE_ERROR`](crate::accuracy::LOOK_AT_MAX_ANGLE_ERROR)
    /// radians of the exact one while `up` is at least 0.1 rad (about 6
    /// degrees) off the line of sight; closer, the roll is ill-conditioned
    /// and its error grows as 1 / sin of that angle. Unit to within
    /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, RigTForm};
    /// let eye = RigTForm::look_at(Cvec3::new(0.0, 3.0, 4.0), Cvec3::ZERO, Cvec3::Y);
    /// // Seen from the eye, the target is straight ahead, 5 away.
    /// let seen = eye.inv().transform_point(Cvec3::ZERO);
    /// assert!((seen - Cvec3::new(0.0, 0.0, -5.0)).norm() < 1e-5);
    /// // The eye's x axis stays horizontal.
    /// assert!(eye.transform_vector(Cvec3::X).y.abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn look_at(eye: Cvec3, target: Cvec3, up: Cvec3) -> Self {
        if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
            return Self::new(eye, Quat::NAN);
        }
        let Some(back) = (eye - target).try_normalize() else {
            return Self::new(eye, Quat::IDENTITY);
        };
        let side = up.try_normalize().map_or(Cvec3::ZERO, |u| u.cross(back));
        // Below 2^-22 the cross product of unit vectors is rounding noise:
        // `up` is along the line of sight as far as f32 can tell.
        let r = if side.norm() > 1.0 / (1u32 << 22) as f32 {
            let right = side.normalize();
            Quat::from_basis(right, back.cross(right), back)
        } else {
            Quat::from_rotation_arc(-Cvec3::Z, -back)
        };
        Self::new(eye, r)
    }
}

impl Quat {
    /// The rotation of a frame whose +z axis points along `dir` and whose y
    /// axis is as close to `up` as that allows: nalgebra's
    /// `UnitQuaternion::face_towards`, the rotation of
    /// [`RigTForm::face_towards`](RigTForm::face_towards) (with its
    /// preconditions and accuracy).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::face_towards(Cvec3::X, Cvec3::Y);
    /// assert!((q * Cvec3::Z - Cvec3::X).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn face_towards(dir: Cvec3, up: Cvec3) -> Self {
        RigTForm::face_towards(Cvec3::ZERO, dir, up).r
    }

    /// The rotation of the view from an eye looking along `dir`, with `up`
    /// up: nalgebra's `UnitQuaternion::look_at_rh`, which takes `dir` onto
    /// -z; the inverse of [`face_towards`](Self::face_towards) of `-dir`,
    /// and the rotation of [`RigTForm::look_at_rh`](RigTForm::look_at_rh).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::look_at_rh(Cvec3::X, Cvec3::Y);
    /// assert!((q * Cvec3::X + Cvec3::Z).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn look_at_rh(dir: Cvec3, up: Cvec3) -> Self {
        RigTForm::look_at(Cvec3::ZERO, dir, up).r.inv()
    }
}
