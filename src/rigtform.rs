//! [`RigTForm`]: a rigid body transform kept as a translation and a rotation
//! quaternion, as in the notes' "Rbt data structure", "rbt * rbt", "inv
//! operator" and "rbt Interpolation"; `rigtform/look_at.rs` builds an eye
//! frame from a point and a target, `rigtform/catmull_rom.rs` holds
//! the spline through many keyframes, and `rigtform/other_names.rs` glam's
//! and nalgebra's names, `RigTForm * Cvec3` and the rigid transform of a
//! matrix.

use core::ops::{Mul, MulAssign};

use crate::quat::Quat;
use crate::vec::{Cvec3, Cvec4};

mod catmull_rom;
mod look_at;
mod other_names;
mod slice;

/// A rigid body transform `A = T R`: first rotate by `r`, then translate by
/// `t`. As a matrix, `[[r, t], [0, 1]]`.
///
/// # Examples
///
/// ```
/// use core::f32::consts::FRAC_PI_2;
/// use rigtform::{Cvec3, Cvec4, Quat, RigTForm};
///
/// let a = RigTForm::new(Cvec3::new(1.0, 0.0, 0.0), Quat::from_rotation_z(FRAC_PI_2));
/// let p = a * Cvec4::from_point(Cvec3::X);   // rotated, then moved
/// let v = a * Cvec4::from_vector(Cvec3::X);  // rotated only
/// assert!((p - Cvec4::new(1.0, 1.0, 0.0, 1.0)).norm() < 1e-6);
/// assert!((v - Cvec4::new(0.0, 1.0, 0.0, 0.0)).norm() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct RigTForm {
    /// Translation, applied after the rotation.
    pub t: Cvec3,
    /// Rotation, a unit quaternion.
    pub r: Quat,
}

impl Default for RigTForm {
    /// The identity transform.
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl RigTForm {
    /// No translation, no rotation.
    pub const IDENTITY: Self = Self::new(Cvec3::ZERO, Quat::IDENTITY);

    /// The transform that rotates by `r`, then translates by `t`.
    ///
    /// # Preconditions
    ///
    /// `r` is a unit quaternion (not checked; [`Quat::normalize`] it if it
    /// may have drifted).
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::Z, Quat::IDENTITY);
    /// assert_eq!(a, RigTForm::from_translation(Cvec3::Z));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(t: Cvec3, r: Quat) -> Self {
        Self { t, r }
    }

    /// A pure translation.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, RigTForm};
    /// let p = RigTForm::from_translation(Cvec3::Y) * Cvec4::from_point(Cvec3::ZERO);
    /// assert_eq!(p, Cvec4::new(0.0, 1.0, 0.0, 1.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_translation(t: Cvec3) -> Self {
        Self::new(t, Quat::IDENTITY)
    }

    /// A pure rotation.
    ///
    /// # Preconditions
    ///
    /// `r` is a unit quaternion.
    ///
    /// ```
    /// use rigtform::{Quat, RigTForm};
    /// let a = RigTForm::from_rotation(Quat::from_rotation_x(0.1));
    /// assert_eq!(a, RigTForm::from_rotation_x(0.1));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_rotation(r: Quat) -> Self {
        Self::new(Cvec3::ZERO, r)
    }

    /// A pure rotation by `angle` radians about the x axis (the notes'
    /// `makeXRotation`).
    ///
    /// ```
    /// use rigtform::{Quat, RigTForm};
    /// assert_eq!(RigTForm::from_rotation_x(0.5).r, Quat::from_rotation_x(0.5));
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_x(angle: f32) -> Self {
        Self::from_rotation(Quat::from_rotation_x(angle))
    }

    /// A pure rotation by `angle` radians about the y axis.
    ///
    /// ```
    /// use rigtform::{Quat, RigTForm};
    /// assert_eq!(RigTForm::from_rotation_y(0.5).r, Quat::from_rotation_y(0.5));
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_y(angle: f32) -> Self {
        Self::from_rotation(Quat::from_rotation_y(angle))
    }

    /// A pure rotation by `angle` radians about the z axis.
    ///
    /// ```
    /// use rigtform::{Quat, RigTForm};
    /// assert_eq!(RigTForm::from_rotation_z(0.5).r, Quat::from_rotation_z(0.5));
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_z(angle: f32) -> Self {
        Self::from_rotation(Quat::from_rotation_z(angle))
    }

    /// The inverse transform, translation `-r^-1 t` and rotation `r^-1`
    /// (the notes' "inv operator").
    ///
    /// # Preconditions
    ///
    /// `r` is a unit quaternion. `a.inv().inv()` equals `a` up to the
    /// rounding of two rotations of `t` ([`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|t|` each); the rotation part is exact.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::from_rotation_y(0.3));
    /// let i = a * a.inv();
    /// assert!(i.t.norm() < 1e-6 && i.r.angle_to(Quat::IDENTITY) < 1e-6);
    /// ```
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::rigtform_inv_requires(self))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &RigTForm| crate::kani_contracts::rigtform_inv_ensures(self, *r)))]
    #[inline]
    #[must_use]
    pub fn inv(self) -> Self {
        let r = self.r.inv();
        Self::new(-(r * self.t), r)
    }

    /// Applies the transform to a point: rotated, then translated,
    /// `r p + t`. The same as `self * Cvec4::from_point(p)`, without the
    /// fourth coordinate.
    ///
    /// # Accuracy
    ///
    /// The rotation's error, at most
    /// [`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|p|`, plus one rounding of the sum.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(5.0, 0.0, 0.0), Quat::from_rotation_z(FRAC_PI_2));
    /// assert!((a.transform_point(Cvec3::X) - Cvec3::new(5.0, 1.0, 0.0)).norm() < 1e-6);
    /// ```
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::transform_point_requires(self, p))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &Cvec3| crate::kani_contracts::transform_point_ensures(*r)))]
    #[inline]
    #[must_use]
    pub fn transform_point(self, p: Cvec3) -> Cvec3 {
        self.r * p + self.t
    }

    /// Applies the transform to a vector (a direction or a displacement):
    /// rotated only, `r v`; translations leave vectors alone. The same as
    /// `self * Cvec4::from_vector(v)`, without the fourth coordinate.
    ///
    /// # Accuracy
    ///
    /// At most [`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|v|`.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(5.0, 0.0, 0.0), Quat::from_rotation_z(FRAC_PI_2));
    /// assert!((a.transform_vector(Cvec3::X) - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_vector(self, v: Cvec3) -> Cvec3 {
        self.r * v
    }

    /// Interpolates between two frames the notes' way: the translation by
    /// linear interpolation (the origin moves on a straight line at constant
    /// speed), the rotation by [`Quat::slerp`] (constant angular velocity
    /// about one axis, the short way).
    ///
    /// Exactly `self` at `alpha = 0`; `other` (its rotation possibly as
    /// `-r`) at `alpha = 1`; extrapolates outside [0, 1]. Left invariant,
    /// `(g * a).interpolate(g * b, t) == g * a.interpolate(b, t)`, but not
    /// right invariant: the origin plays a special role.
    ///
    /// # Preconditions
    ///
    /// Unit rotations. NaN or infinite input gives NaN components.
    ///
    /// # Accuracy
    ///
    /// Rotation as [`Quat::slerp`]; translation as [`Cvec3::lerp`].
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let a = RigTForm::IDENTITY;
    /// let b = RigTForm::new(Cvec3::new(2.0, 0.0, 0.0), Quat::from_rotation_z(PI / 2.0));
    /// let mid = a.interpolate(b, 0.5);
    /// assert_eq!(mid.t, Cvec3::new(1.0, 0.0, 0.0));
    /// assert!(mid.r.angle_to(Quat::from_rotation_z(PI / 4.0)) < 1e-6);
    /// ```
    #[doc(alias = "slerp")]
    // Always inlined on 64-bit desktop targets: with a plain `inline` hint
    // the compiler inlined `slerp` into this function and then judged the
    // whole too large to inline into callers' loops, which then passed the
    // two transforms and the result through memory and paid for a call,
    // whereas the same loop of `slerp` alone inlined it. One out-of-line
    // copy elsewhere (flash on a Cortex-M4F).
    #[cfg_attr(desktop64, inline(always))]
    #[must_use]
    pub fn interpolate(self, other: Self, alpha: f32) -> Self {
        Self::new(self.t.lerp(other.t, alpha), self.r.slerp(other.r, alpha))
    }

    /// Interpolates every pair `(starts[i], ends[i])` by the same `alpha`
    /// into `out[i]`: element by element, bit for bit, what
    /// [`interpolate`](Self::interpolate) returns for the pair, whatever
    /// the inputs (where that is NaN, a NaN: Rust leaves the sign and
    /// payload of a NaN result unspecified). The rotations are slerped
    /// where they lie, as [`Quat::slerp_slice`] slerps (vectorized on
    /// x86-64 and AArch64), the translations lerped beside them (on
    /// x86-64, sixteen transforms at a time).
    ///
    /// Slices of different lengths: the first
    /// `min(starts.len(), ends.len(), out.len())` elements are written, and
    /// the rest of `out` is left as it was (never a panic).
    ///
    /// # Preconditions
    ///
    /// Those of [`interpolate`](Self::interpolate), element by element.
    ///
    /// # Accuracy
    ///
    /// That of [`interpolate`](Self::interpolate): the results are its
    /// results. Floating-point exceptions: as the section of that name of
    /// [`Quat::slerp_slice`](crate::Quat::slerp_slice) says.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let starts = [RigTForm::IDENTITY; 3];
    /// let ends = [RigTForm::new(Cvec3::X, Quat::from_rotation_z(1.0)); 3];
    /// let mut out = [RigTForm::IDENTITY; 2]; // shorter: two are written
    /// RigTForm::interpolate_slice(&starts, &ends, 0.5, &mut out);
    /// assert_eq!(out[1], starts[1].interpolate(ends[1], 0.5));
    /// ```
    pub fn interpolate_slice(starts: &[Self], ends: &[Self], alpha: f32, out: &mut [Self]) {
        crate::quat::slerp_slice_by(starts, ends, alpha, out);
    }
}

impl Mul<RigTForm> for RigTForm {
    type Output = RigTForm;

    /// Composition: translation `t1 + r1 t2`, rotation `r1 r2` (the notes'
    /// "rbt * rbt"). `a * b` applies `b` first.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::X, Quat::from_rotation_z(0.3));
    /// let b = RigTForm::new(Cvec3::Y, Quat::from_rotation_x(0.2));
    /// let p = Cvec4::from_point(Cvec3::new(1.0, 2.0, 3.0));
    /// assert!(((a * b) * p - a * (b * p)).norm() < 1e-6);
    /// ```
    #[inline]
    fn mul(self, o: RigTForm) -> RigTForm {
        self.mul_rig_tform(o)
    }
}

impl MulAssign<RigTForm> for RigTForm {
    /// `*self = *self * other`: `other` applied first, then `self`.
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// let mut a = RigTForm::from_rotation_z(0.3);
    /// a *= RigTForm::from_translation(Cvec3::X);
    /// assert_eq!(a, RigTForm::from_rotation_z(0.3) * RigTForm::from_translation(Cvec3::X));
    /// ```
    #[inline]
    fn mul_assign(&mut self, other: RigTForm) {
        *self = *self * other;
    }
}

impl Mul<Cvec4> for RigTForm {
    type Output = Cvec4;

    /// Applies the transform to homogeneous coordinates: `r c + [t, 0] c.w`.
    /// A point (`w = 1`) is rotated and translated; a vector (`w = 0`) is
    /// only rotated; `w` is copied.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, RigTForm};
    /// let a = RigTForm::from_translation(Cvec3::new(5.0, 0.0, 0.0));
    /// assert_eq!(a * Cvec4::new(1.0, 0.0, 0.0, 0.0), Cvec4::new(1.0, 0.0, 0.0, 0.0));
    /// assert_eq!(a * Cvec4::new(1.0, 0.0, 0.0, 1.0), Cvec4::new(6.0, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    fn mul(self, c: Cvec4) -> Cvec4 {
        self.r * c + Cvec4::from_vector(self.t) * c.w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_of_a_pure_translation_is_exact() {
        let a = RigTForm::from_translation(Cvec3::new(1.5, -2.0, 3.25));
        assert_eq!(
            a.inv(),
            RigTForm::from_translation(Cvec3::new(-1.5, 2.0, -3.25))
        );
        assert_eq!(a * a.inv(), RigTForm::IDENTITY);
    }

    #[test]
    fn named_rotations_are_pure_rotations_about_their_axis() {
        let cases = [
            (RigTForm::from_rotation_x(0.7), Quat::from_rotation_x(0.7)),
            (RigTForm::from_rotation_y(0.7), Quat::from_rotation_y(0.7)),
            (RigTForm::from_rotation_z(0.7), Quat::from_rotation_z(0.7)),
        ];
        for (a, r) in cases {
            assert_eq!(a, RigTForm::new(Cvec3::ZERO, r));
        }
        assert_eq!(RigTForm::default(), RigTForm::IDENTITY);
    }

    #[test]
    fn points_move_with_the_frame_and_vectors_only_turn() {
        let a = RigTForm::new(Cvec3::new(0.5, -1.0, 2.0), Quat::from_rotation_x(0.9));
        let p = Cvec3::new(1.0, 2.0, 3.0);
        assert_eq!(a.transform_point(p), (a * Cvec4::from_point(p)).xyz());
        assert_eq!(a.transform_vector(p), (a * Cvec4::from_vector(p)).xyz());
        assert!((a.transform_point(p) - a.transform_vector(p) - a.t).norm() < 1e-6);
    }

    #[test]
    fn look_at_puts_the_target_on_minus_z_with_x_horizontal() {
        let (eye, target) = (Cvec3::new(3.0, -2.0, 7.0), Cvec3::new(-1.0, 0.5, 0.25));
        let e = RigTForm::look_at(eye, target, Cvec3::Y);
        let ahead = e.inv().transform_point(target);
        assert!((ahead - Cvec3::new(0.0, 0.0, -(target - eye).norm())).norm() < 1e-5);
        assert!(e.transform_vector(Cvec3::X).y.abs() < 1e-6);
        assert!(e.transform_vector(Cvec3::Y).y > 0.0);
        assert!((e.r.norm() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn look_at_along_up_or_at_itself_gives_documented_rotations() {
        let eye = Cvec3::new(0.0, 5.0, 0.0);
        let down = RigTForm::look_at(eye, Cvec3::ZERO, Cvec3::Y);
        assert!((down.transform_vector(-Cvec3::Z) + Cvec3::Y).norm() < 1e-6);
        assert_eq!(down.r, Quat::from_rotation_arc(-Cvec3::Z, -Cvec3::Y));
        assert_eq!(RigTForm::look_at(eye, Cvec3::ZERO, Cvec3::ZERO).r, down.r);
        assert_eq!(
            RigTForm::look_at(eye, eye, Cvec3::Y),
            RigTForm::from_translation(eye)
        );
        assert!(RigTForm::look_at(eye, Cvec3::NAN, Cvec3::Y).r.is_nan());
    }

    #[test]
    fn interpolate_is_exact_at_zero() {
        let a = RigTForm::new(Cvec3::new(0.1, 0.2, 0.3), Quat::from_rotation_y(0.4));
        let b = RigTForm::new(Cvec3::new(9.0, 8.0, 7.0), Quat::from_rotation_x(2.0));
        assert_eq!(a.interpolate(b, 0.0), a);
    }
}
