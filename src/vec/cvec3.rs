//! [`Cvec3`], the notes' coordinate 3-vector: a point or a direction.
//! Its own methods here (the cross product, reflection, the angle between
//! two directions, perpendiculars and orthonormal pairs); what it shares
//! with [`Cvec4`] and [`Quat`](crate::Quat) is written once in
//! `vec/template.rs` and instanced at the bottom. Its turns by angles
//! (`rotate_x`, `slerp`) are with the quaternions, in `quat/vec_rotations.rs`.

use super::template::{coordinates, euclidean};
use super::Cvec4;
use crate::float;
use crate::other_names::renamed;

/// A coordinate 3-vector `[x, y, z]`, the `cvec3` of the notes.
///
/// # Examples
///
/// ```
/// use rigtform::Cvec3;
/// let a = Cvec3::new(1.0, 0.0, 0.0);
/// let b = Cvec3::new(0.0, 1.0, 0.0);
/// assert_eq!(a.cross(b), Cvec3::new(0.0, 0.0, 1.0));
/// assert_eq!(a + b, Cvec3::new(1.0, 1.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Cvec3 {
    /// First coordinate.
    pub x: f32,
    /// Second coordinate.
    pub y: f32,
    /// Third coordinate.
    pub z: f32,
}

impl Cvec3 {
    /// The unit vector along x.
    pub const X: Self = Self::new(1.0, 0.0, 0.0);
    /// The unit vector along y.
    pub const Y: Self = Self::new(0.0, 1.0, 0.0);
    /// The unit vector along z.
    pub const Z: Self = Self::new(0.0, 0.0, 1.0);
    /// The unit vector along -x.
    pub const NEG_X: Self = Self::new(-1.0, 0.0, 0.0);
    /// The unit vector along -y.
    pub const NEG_Y: Self = Self::new(0.0, -1.0, 0.0);
    /// The unit vector along -z.
    pub const NEG_Z: Self = Self::new(0.0, 0.0, -1.0);
    /// Builds a vector from its coordinates.
    ///
    /// ```
    /// let v = rigtform::Cvec3::new(1.0, 2.0, 3.0);
    /// assert_eq!((v.x, v.y, v.z), (1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(x: f32, y: f32, z: f32) -> Self {
        Self { x, y, z }
    }

    /// Dot product `x1 x2 + y1 y2 + z1 z2`.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::new(1.0, 2.0, 3.0).dot(Cvec3::new(4.0, 5.0, 6.0)), 32.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn dot(self, other: Self) -> f32 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Cross product (right-handed: `X.cross(Y) == Z`).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::Y.cross(Cvec3::Z), Cvec3::X);
    /// ```
    #[inline]
    #[must_use]
    pub fn cross(self, other: Self) -> Self {
        Self::new(
            self.y * other.z - self.z * other.y,
            self.z * other.x - self.x * other.z,
            self.x * other.y - self.y * other.x,
        )
    }

    /// `self` mirrored in the plane through the origin with unit normal
    /// `normal`: `self - 2 (self . normal) normal` (glam's `reflect`).
    ///
    /// # Preconditions
    ///
    /// `normal` is of unit length (otherwise the result is not a mirror
    /// image).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::new(1.0, -1.0, 0.0).reflect(Cvec3::Y), Cvec3::new(1.0, 1.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn reflect(self, normal: Self) -> Self {
        self - normal * (2.0 * self.dot(normal))
    }

    /// `self` with `x` replaced (glam's `with_x`).
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec3::ONE.with_x(5.0).x, 5.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_x(self, x: f32) -> Self {
        Self::new(x, self.y, self.z)
    }

    /// `self` with `y` replaced (glam's `with_y`).
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec3::ONE.with_y(5.0).y, 5.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_y(self, y: f32) -> Self {
        Self::new(self.x, y, self.z)
    }

    /// `self` with `z` replaced (glam's `with_z`).
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec3::ONE.with_z(5.0).z, 5.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_z(self, z: f32) -> Self {
        Self::new(self.x, self.y, z)
    }

    /// The homogeneous 4-vector `[x, y, z, w]` (glam's `Vec3::extend`):
    /// `w = 1` for a point ([`Cvec4::from_point`]), `w = 0` for a vector
    /// ([`Cvec4::from_vector`]).
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec3::X.extend(1.0), Cvec4::from_point(Cvec3::X));
    /// ```
    #[inline]
    #[must_use]
    pub const fn extend(self, w: f32) -> Cvec4 {
        Cvec4::new(self.x, self.y, self.z, w)
    }

    /// The angle between `self` and `other`, in radians, in [0, pi]:
    /// `atan2(|u x v|, u . v)` of the two directions `u`, `v` (glam's
    /// `Vec3::angle_between`, nalgebra's `Vector3::angle`), which stays
    /// accurate for nearly parallel and nearly opposite vectors, where the
    /// arccosine of the dot product loses half the digits.
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are finite and non-zero. Otherwise the angle is
    /// undefined and the result is NaN (never a panic).
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::ANGLE_BETWEEN_MAX_ERROR`](crate::accuracy::ANGLE_BETWEEN_MAX_ERROR)
    /// radians of the exact angle between the f32 inputs, at every scale
    /// (the directions are normalized first), 1e-30 and pi - 1e-6 included.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::Cvec3;
    /// assert!((Cvec3::X.angle_between(Cvec3::new(0.0, 5.0, 0.0)) - FRAC_PI_2).abs() < 1e-6);
    /// // Accurate at small angles, where acos(dot) would give 0.
    /// let tilted = Cvec3::new(1.0, 1e-5, 0.0);
    /// assert!((Cvec3::X.angle_between(tilted) - 1e-5).abs() < 1e-11);
    /// assert!(Cvec3::ZERO.angle_between(Cvec3::X).is_nan());
    /// ```
    #[doc(alias = "angle")]
    #[must_use]
    pub fn angle_between(self, other: Self) -> f32 {
        match (self.try_normalize(), other.try_normalize()) {
            (Some(u), Some(v)) => float::atan2(u.cross(v).norm(), u.dot(v)),
            _ => f32::NAN,
        }
    }

    /// A vector perpendicular to `self`, of no particular length (glam's
    /// `any_orthogonal_vector`, the same formula): `self x Y` or
    /// `self x X`, whichever is the longer, so it is zero only for the
    /// zero vector.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(1.0, 2.0, 3.0);
    /// assert_eq!(v.any_orthogonal_vector().dot(v), 0.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn any_orthogonal_vector(self) -> Self {
        if self.x.abs() > self.y.abs() {
            Self::new(-self.z, 0.0, self.x)
        } else {
            Self::new(0.0, self.z, -self.y)
        }
    }

    /// A unit vector perpendicular to the unit vector `self` (glam's
    /// `any_orthonormal_vector`): the second vector of
    /// [`any_orthonormal_pair`](Self::any_orthonormal_pair).
    ///
    /// # Preconditions
    ///
    /// As [`any_orthonormal_pair`](Self::any_orthonormal_pair).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(1.0, 2.0, 3.0).normalize();
    /// let u = v.any_orthonormal_vector();
    /// assert!(u.dot(v).abs() < 1e-6 && (u.norm() - 1.0).abs() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn any_orthonormal_vector(self) -> Self {
        self.any_orthonormal_pair().1
    }

    /// Two unit vectors that make a right-handed orthonormal basis with
    /// the unit vector `self`, `(a, b)` with `a x b = self` (glam's
    /// `any_orthonormal_pair`, the same formula: J. R. Frisvad's, as
    /// revised by T. Duff et al., "Building an Orthonormal Basis,
    /// Revisited", *Journal of Computer Graphics Techniques* 6(1), 2017).
    ///
    /// # Preconditions
    ///
    /// `self` is of unit length (glam asserts it); for any other the pair
    /// is not orthonormal. NaN in, NaN out.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let n = Cvec3::new(-2.0, 0.5, 1.0).normalize();
    /// let (a, b) = n.any_orthonormal_pair();
    /// assert!((a.cross(b) - n).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn any_orthonormal_pair(self) -> (Self, Self) {
        let sign = self.z.signum();
        let a = -1.0 / (sign + self.z);
        let b = self.x * self.y * a;
        (
            Self::new(1.0 + sign * self.x * self.x * a, sign * b, -sign * self.x),
            Self::new(b, sign + self.y * self.y * a, -self.y),
        )
    }

    renamed! {
        /// glam's `Vec3::to_homogeneous`, the point `[x, y, z, 1]`: here
        /// [`Cvec4::from_point`] (nalgebra's `Vector3::to_homogeneous`
        /// gives the vector `[x, y, z, 0]`, [`Cvec4::from_vector`]).
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Cvec4};
        /// assert_eq!(Cvec3::X.to_homogeneous(), Cvec4::from_point(Cvec3::X));
        /// ```
        note "use `Cvec4::from_point(p)` (w = 1, glam's meaning) or `Cvec4::from_vector(v)` (w = 0, nalgebra's `Vector3::to_homogeneous`)";
        pub const fn to_homogeneous(self) -> Cvec4 {
            Cvec4::from_point(self)
        }

        /// glam's `Vec3::from_homogeneous(v)`, the point of homogeneous
        /// coordinates `v`: here [`v.project()`](Cvec4::project), the
        /// perspective divide.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Cvec3, Cvec4};
        /// let v = Cvec4::new(2.0, 4.0, 6.0, 2.0);
        /// assert_eq!(Cvec3::from_homogeneous(v), v.project());
        /// ```
        note "use `v.project()`, the perspective divide";
        pub fn from_homogeneous(v: Cvec4) -> Self {
            v.project()
        }
    }
}

euclidean!(Cvec3 { x, y, z } pad 0.0, unit X);
coordinates!(Cvec3, 3, [x, y, z], index { 0 => x, 1 => y } last z);
