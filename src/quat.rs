//! [`Quat`]: rotation quaternions, as in the notes' sections "the
//! representation" and "Operations": the type, its products and rotation
//! of vectors; `quat/basics.rs` holds its own methods (construction,
//! components, norms, the inverse, conditional negation `cn` and the
//! axis-angle form).
//!
//! One file per further concept: `quat/power.rs` (the notes' "Power": the
//! polar form and `pow`), `quat/interpolate.rs` ("to interpolate": `slerp`,
//! `nlerp`, `blend`), `quat/exp_log.rs` (the exponential and logarithm
//! maps, and gyro integration built on them), `quat/euler.rs` (Euler
//! angles), `quat/from_basis.rs` (the rotation of an orthonormal basis, which
//! `Quat::from_matrix` in `matrix/quat_conversions.rs` takes from a matrix),
//! `quat/rotation_arc.rs` (the shortest rotation between two directions),
//! `quat/catmull_rom.rs` (splines through many keyframes),
//! `quat/arithmetic.rs` (sums and scaling, as a 4-vector),
//! `quat/towards.rs` (`slerp_long`, `rotate_towards`) and
//! `quat/other_names.rs` (glam's and nalgebra's names for these methods).

use core::ops::{Mul, MulAssign, Neg};

use crate::vec::{Cvec3, Cvec4};

#[cfg(all(kernels_exported, desktop64))]
pub(crate) use slerp::kernels_f64;
pub(crate) use slerp::{slerp_slice_by, Slerped};

pub use euler::EulerRot;

/// A rotation quaternion. The notes write it scalar first, `[w, c]`: a
/// rotation of `theta` radians about the unit axis `k` is
/// `[cos(theta/2), sin(theta/2) k]`. In memory, in arrays, tuples and casts
/// it is `x, y, z, w`, scalar last, as glam, nalgebra's storage, mint,
/// glTF and GPU shaders keep it: a `&[Quat]` uploads to a shader as it is.
///
/// `q` and `-q` are the same rotation. `a * b` is the Hamilton product,
/// which applies `b` first, then `a` (as rotation matrices do).
///
/// Start with [`from_axis_angle`](Self::from_axis_angle) or
/// [`from_rotation_x`](Self::from_rotation_x) (and `_y`, `_z`); compose with
/// `*`; rotate a [`Cvec3`] with `q * v`; interpolate with
/// [`slerp`](Self::slerp). Components come in and out by name:
/// [`from_xyzw`](Self::from_xyzw) (glam's order) and
/// [`from_wxyz`](Self::from_wxyz) (the notes' and nalgebra's
/// `Quaternion::new` order).
///
/// # Examples
///
/// ```
/// use core::f32::consts::FRAC_PI_2;
/// use rigtform::{Cvec3, Quat};
///
/// let q = Quat::from_rotation_z(FRAC_PI_2);
/// let v = q * Cvec3::X; // x turns into y
/// assert!((v - Cvec3::Y).norm() < 1e-6);
///
/// // Halfway from the identity to a quarter turn is an eighth of a turn.
/// let half = Quat::IDENTITY.slerp(q, 0.5);
/// assert!((half.angle_to(Quat::from_rotation_z(FRAC_PI_2 / 2.0))) < 1e-6);
///
/// // Arrays are x, y, z, w, as glam's.
/// assert_eq!(Quat::IDENTITY.to_array(), [0.0, 0.0, 0.0, 1.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Quat {
    /// First coordinate of the vector part, `sin(theta / 2) k.x`.
    pub x: f32,
    /// Second coordinate of the vector part, `sin(theta / 2) k.y`.
    pub y: f32,
    /// Third coordinate of the vector part, `sin(theta / 2) k.z`.
    pub z: f32,
    /// Scalar part, `cos(theta / 2)` for a rotation by `theta`.
    pub w: f32,
}

impl Default for Quat {
    /// The identity rotation.
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Mul<Quat> for Quat {
    type Output = Quat;

    /// The Hamilton product of the notes' "Operations":
    /// `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`. As rotations, `a * b`
    /// applies `b` first, then `a`. On x86-64 the four components are
    /// summed at once in SSE registers, with the same bits as the formula.
    ///
    /// Accuracy: for unit inputs the product is within
    /// [`accuracy::MUL_MAX_ANGLE_ERROR`](crate::accuracy::MUL_MAX_ANGLE_ERROR)
    /// radians of the exact rotation and within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of unit norm.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let (a, b) = (Quat::from_rotation_x(0.5), Quat::from_rotation_y(0.5));
    /// let v = Cvec3::new(1.0, 2.0, 3.0);
    /// assert!(((a * b) * v - a * (b * v)).norm() < 1e-5);
    /// ```
    #[inline]
    fn mul(self, o: Quat) -> Quat {
        // Through the inherent method, which carries the Kani contract.
        self.mul_quat(o)
    }
}

impl MulAssign<Quat> for Quat {
    /// `*self = *self * other`: `other` applied first, then `self`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::from_rotation_x(0.5);
    /// q *= Quat::from_rotation_y(0.5);
    /// assert_eq!(q, Quat::from_rotation_x(0.5) * Quat::from_rotation_y(0.5));
    /// ```
    #[inline]
    fn mul_assign(&mut self, other: Quat) {
        *self = *self * other;
    }
}

impl From<[f32; 4]> for Quat {
    /// Same as [`Quat::from_array`]: `[x, y, z, w]`, scalar last.
    #[inline]
    fn from(a: [f32; 4]) -> Self {
        Self::from_array(a)
    }
}

impl From<Quat> for [f32; 4] {
    /// Same as [`Quat::to_array`]: `[x, y, z, w]`, scalar last.
    #[inline]
    fn from(q: Quat) -> Self {
        q.to_array()
    }
}

impl From<Cvec4> for Quat {
    /// `x, y, z, w` as they are, glam's `Quat::from_vec4`.
    ///
    /// ```
    /// use rigtform::{Cvec4, Quat};
    /// assert_eq!(Quat::from(Cvec4::new(0.0, 0.0, 0.0, 1.0)), Quat::IDENTITY);
    /// ```
    #[inline]
    fn from(v: Cvec4) -> Self {
        Self::from_xyzw(v.x, v.y, v.z, v.w)
    }
}

impl From<Quat> for Cvec4 {
    /// `x, y, z, w` as they are, glam's `Vec4::from(Quat)`.
    ///
    /// ```
    /// use rigtform::{Cvec4, Quat};
    /// assert_eq!(Cvec4::from(Quat::IDENTITY), Cvec4::new(0.0, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    fn from(q: Quat) -> Self {
        Cvec4::new(q.x, q.y, q.z, q.w)
    }
}

impl From<(f32, f32, f32, f32)> for Quat {
    /// `(x, y, z, w)`, scalar last, as [`Quat::from_xyzw`].
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from((0.0, 0.0, 0.0, 1.0)), Quat::IDENTITY);
    /// ```
    #[inline]
    fn from((x, y, z, w): (f32, f32, f32, f32)) -> Self {
        Self::from_xyzw(x, y, z, w)
    }
}

impl From<Quat> for (f32, f32, f32, f32) {
    /// `(x, y, z, w)`, scalar last, as [`Quat::to_array`].
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (x, y, z, w) = Quat::IDENTITY.into();
    /// assert_eq!((x, y, z, w), (0.0, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    fn from(q: Quat) -> Self {
        (q.x, q.y, q.z, q.w)
    }
}

impl Mul<Cvec3> for Quat {
    type Output = Cvec3;

    /// Rotates `v`: the vector part of the notes' triple product
    /// `q [0, v] q^-1`, evaluated as `v + w t + u x t` with `u` the vector
    /// part of `q` and `t = 2 u x v` (the same value for a unit `q`, in 18
    /// multiplications instead of the triple product's 32).
    ///
    /// Preconditions: `self` is a unit quaternion (for another, the result
    /// is not a rotation). Accuracy: error at most
    /// [`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|v|`.
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_y(PI) * Cvec3::new(1.0, 2.0, 3.0);
    /// assert!((v - Cvec3::new(-1.0, 2.0, -3.0)).norm() < 1e-6);
    /// ```
    #[inline]
    fn mul(self, v: Cvec3) -> Cvec3 {
        // Through the inherent method, which carries the Kani contract.
        self.mul_vec3(v)
    }
}

/// `q * v`, the formula of `Mul<Cvec3> for Quat` (its doc).
#[inline]
fn rotate(q: Quat, v: Cvec3) -> Cvec3 {
    let u = q.vector();
    let t = u.cross(v) * 2.0;
    v + t * q.w + u.cross(t)
}

impl Mul<Cvec4> for Quat {
    type Output = Cvec4;

    /// Rotates the first three coordinates and copies the fourth, as the
    /// notes' `quat * cvec4` ("copy over the 0/1 fourth coordinate").
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec4, Quat};
    /// let c = Quat::from_rotation_z(FRAC_PI_2) * Cvec4::new(1.0, 0.0, 0.0, 1.0);
    /// assert!((c - Cvec4::new(0.0, 1.0, 0.0, 1.0)).norm() < 1e-6);
    /// assert_eq!(c.w, 1.0);
    /// ```
    #[inline]
    fn mul(self, c: Cvec4) -> Cvec4 {
        let r = self * c.xyz();
        Cvec4::new(r.x, r.y, r.z, c.w)
    }
}

impl Neg for Quat {
    type Output = Quat;

    /// The antipode `-q`: the same rotation.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_x(0.4);
    /// assert_eq!((-q).angle_to(q), 0.0);
    /// ```
    #[inline]
    fn neg(self) -> Quat {
        Quat::from_wxyz(-self.w, -self.x, -self.y, -self.z)
    }
}

// The further concepts, in the order the documentation lists their
// methods: the type's own first, then interpolation, glam's and nalgebra's
// names last.

mod basics;

mod power;

mod interpolate;

mod slerp;

mod towards;

mod euler;

mod rotation_arc;

mod from_basis;

mod exp_log;

pub(crate) mod catmull_rom;

mod arithmetic;

mod product;

mod other_names;

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::PI;

    #[test]
    fn product_of_axis_rotations_matches_the_notes_formula() {
        // i j = k, j k = i, k i = j (Hamilton).
        let i = Quat::from_wxyz(0.0, 1.0, 0.0, 0.0);
        let j = Quat::from_wxyz(0.0, 0.0, 1.0, 0.0);
        let k = Quat::from_wxyz(0.0, 0.0, 0.0, 1.0);
        assert_eq!(i * j, k);
        assert_eq!(j * k, i);
        assert_eq!(k * i, j);
        assert_eq!(i * i, Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0));
    }

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

    #[test]
    fn norm_squared_is_the_sum_of_the_four_squares() {
        assert_eq!(Quat::from_wxyz(1.0, -2.0, 3.0, 0.5).norm_squared(), 14.25);
        assert_eq!(Quat::from_wxyz(0.0, 3.0, 0.0, 4.0).norm(), 5.0);
    }

    #[test]
    fn to_axis_angle_of_a_half_turn_is_pi() {
        let (axis, angle) = Quat::from_wxyz(0.0, 0.0, 0.0, -1.0).to_axis_angle();
        assert_eq!(axis, -Cvec3::Z);
        assert_eq!(angle, PI);
    }
}
