//! Coordinate vectors: [`Cvec3`] (a point or a direction) and [`Cvec4`]
//! (homogeneous coordinates: `w = 1` for a point, `w = 0` for a vector).

use core::iter::Sum;
use core::ops::{
    Add, AddAssign, Div, DivAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign,
};

use crate::float::{self, scale_for_squares};

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

/// A coordinate 4-vector `[x, y, z, w]`: homogeneous coordinates, with
/// `w = 1` for a point and `w = 0` for a vector (which translations leave
/// alone).
///
/// # Examples
///
/// ```
/// use rigtform::{Cvec3, Cvec4};
/// let p = Cvec4::from_point(Cvec3::new(1.0, 2.0, 3.0));
/// assert_eq!(p, Cvec4::new(1.0, 2.0, 3.0, 1.0));
/// assert_eq!(p.xyz(), Cvec3::new(1.0, 2.0, 3.0));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Cvec4 {
    /// First coordinate.
    pub x: f32,
    /// Second coordinate.
    pub y: f32,
    /// Third coordinate.
    pub z: f32,
    /// Fourth (homogeneous) coordinate: 1 for points, 0 for vectors.
    pub w: f32,
}

impl Cvec3 {
    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0);
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
    /// All components NaN: what the crate returns for undefined results.
    pub const NAN: Self = Self::new(f32::NAN, f32::NAN, f32::NAN);

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

    /// The coordinates as an array `[x, y, z]`.
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec3::new(1.0, 2.0, 3.0).to_array(), [1.0, 2.0, 3.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f32; 3] {
        [self.x, self.y, self.z]
    }

    /// Builds a vector from an array `[x, y, z]`.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::from_array([1.0, 2.0, 3.0]), Cvec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_array([x, y, z]: [f32; 3]) -> Self {
        Self::new(x, y, z)
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

    /// Squared length `dot(self, self)`. Overflows to infinity for
    /// components beyond about 1.8e19; use [`norm`](Self::norm) for lengths.
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec3::new(1.0, 2.0, 2.0).norm_squared(), 9.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn norm_squared(self) -> f32 {
        self.dot(self)
    }

    /// Euclidean length, without intermediate overflow or underflow.
    ///
    /// # Accuracy
    ///
    /// Within 2 ulp of the exact length for every finite input, from
    /// subnormal components (down to 1e-45) to `f32::MAX` (exact power-of-two
    /// rescaling, as C's `hypot`). Lengths above `f32::MAX` round to
    /// infinity. NaN in, NaN out.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::new(3.0, 4.0, 0.0).norm(), 5.0);
    /// assert_eq!(Cvec3::new(3e30, 4e30, 0.0).norm(), 5e30); // no overflow
    /// ```
    #[inline]
    #[must_use]
    pub fn norm(self) -> f32 {
        scale_for_squares([self.x, self.y, self.z, 0.0]).norm()
    }

    /// The unit vector in the direction of `self`, or `None` if `self` is
    /// zero or has a NaN or infinite component.
    ///
    /// # Accuracy
    ///
    /// The result's norm is within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of 1, for every finite non-zero input, subnormal or huge.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::new(0.0, 1e-40, 0.0).try_normalize(), Some(Cvec3::Y));
    /// assert_eq!(Cvec3::ZERO.try_normalize(), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        let [x, y, z, _] = scale_for_squares([self.x, self.y, self.z, 0.0]).unit()?;
        Some(Self::new(x, y, z))
    }

    /// The unit vector in the direction of `self`.
    ///
    /// # Preconditions
    ///
    /// `self` is finite and non-zero. Otherwise the result is [`Cvec3::NAN`]
    /// (never a panic); use [`try_normalize`](Self::try_normalize) to get an
    /// `Option` instead.
    ///
    /// # Accuracy
    ///
    /// As [`try_normalize`](Self::try_normalize).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// assert_eq!(Cvec3::new(0.0, 0.0, -7.0).normalize(), -Cvec3::Z);
    /// assert!(Cvec3::ZERO.normalize().x.is_nan());
    /// ```
    #[inline]
    #[must_use]
    pub fn normalize(self) -> Self {
        self.try_normalize().unwrap_or(Self::NAN)
    }

    /// Linear interpolation `(1 - alpha) self + alpha other`: exactly `self`
    /// at `alpha = 0` and exactly `other` at `alpha = 1`; extrapolates outside
    /// [0, 1].
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let a = Cvec3::new(0.0, 0.0, 0.0);
    /// let b = Cvec3::new(2.0, 4.0, 6.0);
    /// assert_eq!(a.lerp(b, 0.5), Cvec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(a.lerp(b, 1.0), b);
    /// ```
    #[inline]
    #[must_use]
    pub fn lerp(self, other: Self, alpha: f32) -> Self {
        self * (1.0 - alpha) + other * alpha
    }

    /// `true` if every component is finite (neither NaN nor infinite).
    ///
    /// ```
    /// assert!(!rigtform::Cvec3::new(1.0, f32::NAN, 0.0).is_finite());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
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

    /// The vector projection of `self` onto the line of `rhs`:
    /// `(self . u) u` with `u` the direction of `rhs` (glam's
    /// `Vec3::project_onto`).
    ///
    /// # Preconditions
    ///
    /// `rhs` is finite and non-zero, and `self` finite; otherwise the
    /// result is [`Cvec3::NAN`] (never a panic). `rhs` need not be of unit
    /// length: it is normalized first, without overflow or underflow.
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
    /// times `|self|` of the exact projection of the f32 inputs.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(2.0, 3.0, 4.0);
    /// assert_eq!(v.project_onto(Cvec3::new(0.0, 10.0, 0.0)), Cvec3::new(0.0, 3.0, 0.0));
    /// assert!(v.project_onto(Cvec3::ZERO).is_nan());
    /// ```
    #[doc(alias = "project")]
    #[must_use]
    pub fn project_onto(self, rhs: Self) -> Self {
        match rhs.try_normalize() {
            Some(u) => u * self.dot(u),
            None => Self::NAN,
        }
    }

    /// The part of `self` perpendicular to `rhs`: `self` minus its
    /// [`project_onto`](Self::project_onto) `rhs` (glam's `Vec3::reject_from`).
    ///
    /// # Preconditions
    ///
    /// As [`project_onto`](Self::project_onto): NaN for a zero or
    /// non-finite `rhs`.
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
    /// times `|self|` of the exact rejection (the error of the projection,
    /// and one rounding of the difference).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(2.0, 3.0, 4.0);
    /// assert_eq!(v.reject_from(Cvec3::Y), Cvec3::new(2.0, 0.0, 4.0));
    /// ```
    #[doc(alias = "reject")]
    #[must_use]
    pub fn reject_from(self, rhs: Self) -> Self {
        self - self.project_onto(rhs)
    }
}

impl Cvec4 {
    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0, 0.0);
    /// The unit vector along x.
    pub const X: Self = Self::new(1.0, 0.0, 0.0, 0.0);
    /// The unit vector along y.
    pub const Y: Self = Self::new(0.0, 1.0, 0.0, 0.0);
    /// The unit vector along z.
    pub const Z: Self = Self::new(0.0, 0.0, 1.0, 0.0);
    /// The unit vector along w.
    pub const W: Self = Self::new(0.0, 0.0, 0.0, 1.0);
    /// The unit vector along -x.
    pub const NEG_X: Self = Self::new(-1.0, 0.0, 0.0, 0.0);
    /// The unit vector along -y.
    pub const NEG_Y: Self = Self::new(0.0, -1.0, 0.0, 0.0);
    /// The unit vector along -z.
    pub const NEG_Z: Self = Self::new(0.0, 0.0, -1.0, 0.0);
    /// The unit vector along -w.
    pub const NEG_W: Self = Self::new(0.0, 0.0, 0.0, -1.0);
    /// All components NaN: what the crate returns for undefined results.
    pub const NAN: Self = Self::new(f32::NAN, f32::NAN, f32::NAN, f32::NAN);

    /// Builds a vector from its coordinates.
    ///
    /// ```
    /// let v = rigtform::Cvec4::new(1.0, 2.0, 3.0, 0.0);
    /// assert_eq!(v.w, 0.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(x: f32, y: f32, z: f32, w: f32) -> Self {
        Self { x, y, z, w }
    }

    /// The homogeneous coordinates of a point: `[p, 1]`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::from_point(Cvec3::X).w, 1.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_point(p: Cvec3) -> Self {
        Self::new(p.x, p.y, p.z, 1.0)
    }

    /// The homogeneous coordinates of a vector (a direction, which
    /// translations leave alone): `[v, 0]`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::from_vector(Cvec3::X).w, 0.0);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_vector(v: Cvec3) -> Self {
        Self::new(v.x, v.y, v.z, 0.0)
    }

    /// The first three coordinates.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::new(1.0, 2.0, 3.0, 4.0).xyz(), Cvec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn xyz(self) -> Cvec3 {
        Cvec3::new(self.x, self.y, self.z)
    }

    /// The point of homogeneous coordinates `self`: `[x, y, z] / w`, the
    /// perspective divide (glam's `Vec4::project`).
    ///
    /// # Preconditions
    ///
    /// None. `w = 0` (a direction, not a point) gives infinite or NaN
    /// coordinates, never a panic.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::new(2.0, 4.0, 6.0, 2.0).project(), Cvec3::new(1.0, 2.0, 3.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn project(self) -> Cvec3 {
        self.xyz() / self.w
    }

    /// The vector projection of `self` onto the line of `rhs`, all four
    /// coordinates (glam's `Vec4::project_onto`); see
    /// [`Cvec3::project_onto`].
    ///
    /// # Preconditions
    ///
    /// `rhs` finite and non-zero, `self` finite; otherwise [`Cvec4::NAN`].
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
    /// times `|self|` of the exact projection of the f32 inputs.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// let v = Cvec4::new(2.0, 3.0, 4.0, 5.0);
    /// assert_eq!(v.project_onto(Cvec4::W * 10.0), Cvec4::W * 5.0);
    /// ```
    #[must_use]
    pub fn project_onto(self, rhs: Self) -> Self {
        match rhs.try_normalize() {
            Some(u) => u * self.dot(u),
            None => Self::NAN,
        }
    }

    /// The part of `self` perpendicular to `rhs` (glam's
    /// `Vec4::reject_from`): `self` minus its
    /// [`project_onto`](Self::project_onto) `rhs`.
    ///
    /// # Preconditions
    ///
    /// As [`project_onto`](Self::project_onto).
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
    /// times `|self|` of the exact rejection.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// let v = Cvec4::new(2.0, 3.0, 4.0, 5.0);
    /// assert_eq!(v.reject_from(Cvec4::W), Cvec4::new(2.0, 3.0, 4.0, 0.0));
    /// ```
    #[must_use]
    pub fn reject_from(self, rhs: Self) -> Self {
        self - self.project_onto(rhs)
    }

    /// glam's `Vec4::truncate`: the first three coordinates, which the
    /// crate (and glam's swizzle) calls [`xyz`](Self::xyz).
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::new(1.0, 2.0, 3.0, 4.0).truncate(), Cvec3::new(1.0, 2.0, 3.0));
    /// ```
    #[deprecated(note = "use `Cvec4::xyz`")]
    #[inline]
    #[must_use]
    pub const fn truncate(self) -> Cvec3 {
        self.xyz()
    }

    /// The coordinates as an array `[x, y, z, w]`.
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec4::new(1.0, 2.0, 3.0, 4.0).to_array(), [1.0, 2.0, 3.0, 4.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f32; 4] {
        [self.x, self.y, self.z, self.w]
    }

    /// Builds a vector from an array `[x, y, z, w]`.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// assert_eq!(Cvec4::from_array([1.0, 2.0, 3.0, 4.0]), Cvec4::new(1.0, 2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_array([x, y, z, w]: [f32; 4]) -> Self {
        Self::new(x, y, z, w)
    }

    /// Dot product of all four coordinates.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// assert_eq!(Cvec4::new(1.0, 2.0, 3.0, 4.0).dot(Cvec4::new(1.0, 1.0, 1.0, 1.0)), 10.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn dot(self, other: Self) -> f32 {
        self.x * other.x + self.y * other.y + self.z * other.z + self.w * other.w
    }

    /// Squared length of all four coordinates.
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec4::new(1.0, 1.0, 1.0, 1.0).norm_squared(), 4.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn norm_squared(self) -> f32 {
        self.dot(self)
    }

    /// Euclidean length of all four coordinates, without intermediate
    /// overflow or underflow (see [`Cvec3::norm`]).
    ///
    /// ```
    /// assert_eq!(rigtform::Cvec4::new(1e30, 1e30, 1e30, 1e30).norm(), 2e30);
    /// ```
    #[inline]
    #[must_use]
    pub fn norm(self) -> f32 {
        scale_for_squares(self.to_array()).norm()
    }

    /// The unit vector in the direction of `self` (all four coordinates), or
    /// `None` if `self` is zero or not finite.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// assert_eq!(Cvec4::new(0.0, 0.0, 0.0, 2.0).try_normalize(), Some(Cvec4::new(0.0, 0.0, 0.0, 1.0)));
    /// assert_eq!(Cvec4::ZERO.try_normalize(), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        scale_for_squares(self.to_array())
            .unit()
            .map(Self::from_array)
    }

    /// The unit vector in the direction of `self`.
    ///
    /// # Preconditions
    ///
    /// `self` is finite and non-zero; otherwise every component is NaN.
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// assert_eq!(Cvec4::new(0.0, 3.0, 0.0, 0.0).normalize(), Cvec4::new(0.0, 1.0, 0.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn normalize(self) -> Self {
        self.try_normalize().unwrap_or(Self::NAN)
    }

    /// Linear interpolation `(1 - alpha) self + alpha other` of all four
    /// coordinates (exact at `alpha = 0` and `1`).
    ///
    /// ```
    /// use rigtform::Cvec4;
    /// let a = Cvec4::new(0.0, 0.0, 0.0, 1.0);
    /// let b = Cvec4::new(2.0, 0.0, 0.0, 1.0);
    /// assert_eq!(a.lerp(b, 0.25), Cvec4::new(0.5, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn lerp(self, other: Self, alpha: f32) -> Self {
        self * (1.0 - alpha) + other * alpha
    }

    /// `true` if every component is finite.
    ///
    /// ```
    /// assert!(rigtform::Cvec4::new(1.0, 2.0, 3.0, 1.0).is_finite());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite() && self.w.is_finite()
    }
}

/// Component-wise operators, written once for both vector types.
macro_rules! componentwise_ops {
    ($t:ident { $($f:ident),+ }) => {
        impl Add for $t {
            type Output = Self;
            #[inline]
            fn add(self, o: Self) -> Self {
                Self { $($f: self.$f + o.$f),+ }
            }
        }
        impl Sub for $t {
            type Output = Self;
            #[inline]
            fn sub(self, o: Self) -> Self {
                Self { $($f: self.$f - o.$f),+ }
            }
        }
        impl Neg for $t {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self {
                Self { $($f: -self.$f),+ }
            }
        }
        impl Mul<f32> for $t {
            type Output = Self;
            #[inline]
            fn mul(self, s: f32) -> Self {
                Self { $($f: self.$f * s),+ }
            }
        }
        impl Mul<$t> for f32 {
            type Output = $t;
            #[inline]
            fn mul(self, v: $t) -> $t {
                v * self
            }
        }
        impl Div<f32> for $t {
            type Output = Self;
            #[inline]
            fn div(self, s: f32) -> Self {
                Self { $($f: self.$f / s),+ }
            }
        }
        impl AddAssign for $t {
            #[inline]
            fn add_assign(&mut self, o: Self) {
                *self = *self + o;
            }
        }
        impl SubAssign for $t {
            #[inline]
            fn sub_assign(&mut self, o: Self) {
                *self = *self - o;
            }
        }
        impl MulAssign<f32> for $t {
            #[inline]
            fn mul_assign(&mut self, s: f32) {
                *self = *self * s;
            }
        }
        impl DivAssign<f32> for $t {
            #[inline]
            fn div_assign(&mut self, s: f32) {
                *self = *self / s;
            }
        }
    };
}

/// Indexing and array conversions, written once for both vector types.
/// The last field takes every index past the end, so indexing never
/// panics.
macro_rules! indexing {
    ($t:ident, $n:literal, { $($i:literal => $f:ident),+ }, $last:ident) => {
        impl Index<usize> for $t {
            type Output = f32;
            /// The coordinate at `i`, in the order of the fields. Every
            /// index past the end gives the last coordinate (never a panic).
            #[inline]
            fn index(&self, i: usize) -> &f32 {
                match i {
                    $($i => &self.$f,)+
                    _ => &self.$last,
                }
            }
        }
        impl IndexMut<usize> for $t {
            /// The coordinate at `i`, in the order of the fields. Every
            /// index past the end gives the last coordinate (never a panic).
            #[inline]
            fn index_mut(&mut self, i: usize) -> &mut f32 {
                match i {
                    $($i => &mut self.$f,)+
                    _ => &mut self.$last,
                }
            }
        }
        impl From<[f32; $n]> for $t {
            /// Same as `from_array`.
            #[inline]
            fn from(a: [f32; $n]) -> Self {
                Self::from_array(a)
            }
        }
        impl From<$t> for [f32; $n] {
            /// Same as `to_array`.
            #[inline]
            fn from(v: $t) -> Self {
                v.to_array()
            }
        }
    };
}

/// The smaller of `a` and `b`, NaN if either is NaN.
#[inline]
fn min_or_nan(a: f32, b: f32) -> f32 {
    if a < b {
        a
    } else if a >= b {
        b
    } else {
        f32::NAN
    }
}

/// The larger of `a` and `b`, NaN if either is NaN.
#[inline]
fn max_or_nan(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else if a <= b {
        b
    } else {
        f32::NAN
    }
}

/// glam's everyday vector methods, written once for both vector types.
/// `$first` and `$rest` name the fields; the examples use `$t::ONE` and
/// `splat`, which both types have.
macro_rules! everyday {
    ($t:ident, $tuple:ty, { $first:ident $(, $rest:ident)* }) => {
        impl $t {
            /// Every component 1.
            pub const ONE: Self = Self { $first: 1.0 $(, $rest: 1.0)* };

            /// The sum of the components, left to right (glam's
            /// `element_sum`).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ONE.element_sum(), ", stringify!($t), "::ONE.dot(", stringify!($t), "::ONE));")]
            /// ```
            #[inline]
            #[must_use]
            pub fn element_sum(self) -> f32 {
                self.$first $(+ self.$rest)*
            }

            /// The product of the components, left to right (glam's
            /// `element_product`).
            ///
            /// ```
            #[doc = concat!("assert_eq!(rigtform::", stringify!($t), "::splat(2.0).element_product(), 2f32.powi(rigtform::", stringify!($t), "::ONE.element_sum() as i32));")]
            /// ```
            #[inline]
            #[must_use]
            pub fn element_product(self) -> f32 {
                self.$first $(* self.$rest)*
            }

            /// The point half way, `(self + other) / 2` evaluated as
            /// `self * 0.5 + other * 0.5`, which cannot overflow for finite
            /// inputs (glam's `midpoint`).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ZERO.midpoint(", stringify!($t), "::splat(2.0)), ", stringify!($t), "::ONE);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn midpoint(self, other: Self) -> Self {
                self * 0.5 + other * 0.5
            }

            /// `1 / |self|` (glam's `length_recip`): infinite for the zero
            /// vector, NaN for a NaN component.
            ///
            /// ```
            #[doc = concat!("assert_eq!(rigtform::", stringify!($t), "::splat(0.5).length_recip() , 2.0 / rigtform::", stringify!($t), "::ONE.norm());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn length_recip(self) -> f32 {
                1.0 / self.norm()
            }

            /// `true` if the norm is within
            /// [`accuracy::IS_NORMALIZED_TOLERANCE`](crate::accuracy::IS_NORMALIZED_TOLERANCE)
            /// of 1, as [`Quat::is_normalized`](crate::Quat::is_normalized)
            /// (glam's `is_normalized`); `false` for NaN or infinite
            /// components.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert!(", stringify!($t), "::X.is_normalized());")]
            #[doc = concat!("assert!(!", stringify!($t), "::ONE.is_normalized());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn is_normalized(self) -> bool {
                (self.norm_squared() - 1.0).abs() <= 2.0 * crate::accuracy::IS_NORMALIZED_TOLERANCE
            }

            /// The vector with every component `v` (glam's `splat`).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::splat(2.0), ", stringify!($t), "::ONE * 2.0);")]
            /// ```
            #[inline]
            #[must_use]
            pub const fn splat(v: f32) -> Self {
                Self { $first: v $(, $rest: v)* }
            }

            /// The component-wise minimum. A NaN in either operand gives
            /// NaN in that component (glam and `f32::min` return the other
            /// operand instead); of `0.0` and `-0.0` either may come back.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let a = ", stringify!($t), "::splat(2.0);")]
            #[doc = concat!("assert_eq!(a.min(", stringify!($t), "::ONE), ", stringify!($t), "::ONE);")]
            #[doc = concat!("assert!(a.min(", stringify!($t), "::NAN).is_nan());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn min(self, other: Self) -> Self {
                Self {
                    $first: min_or_nan(self.$first, other.$first)
                    $(, $rest: min_or_nan(self.$rest, other.$rest))*
                }
            }

            /// The component-wise maximum. A NaN in either operand gives
            /// NaN in that component (glam and `f32::max` return the other
            /// operand instead); of `0.0` and `-0.0` either may come back.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let a = ", stringify!($t), "::splat(2.0);")]
            #[doc = concat!("assert_eq!(a.max(", stringify!($t), "::ONE), a);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn max(self, other: Self) -> Self {
                Self {
                    $first: max_or_nan(self.$first, other.$first)
                    $(, $rest: max_or_nan(self.$rest, other.$rest))*
                }
            }

            /// The component-wise absolute value.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!((-", stringify!($t), "::ONE).abs(), ", stringify!($t), "::ONE);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn abs(self) -> Self {
                Self { $first: self.$first.abs() $(, $rest: self.$rest.abs())* }
            }

            /// The smallest component; NaN if any component is NaN.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let mut v = ", stringify!($t), "::splat(3.0);")]
            /// v.y = -1.0;
            /// assert_eq!(v.min_element(), -1.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn min_element(self) -> f32 {
                let m = self.$first;
                $(let m = min_or_nan(m, self.$rest);)*
                m
            }

            /// The largest component; NaN if any component is NaN.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let mut v = ", stringify!($t), "::splat(3.0);")]
            /// v.y = 7.0;
            /// assert_eq!(v.max_element(), 7.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn max_element(self) -> f32 {
                let m = self.$first;
                $(let m = max_or_nan(m, self.$rest);)*
                m
            }

            /// glam's name for [`norm`](Self::norm): the Euclidean length,
            /// without intermediate overflow or underflow.
            ///
            /// # Accuracy
            ///
            /// As [`norm`](Self::norm).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::splat(2.0).length(), ", stringify!($t), "::splat(2.0).norm());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn length(self) -> f32 {
                self.norm()
            }

            /// glam's name for [`norm_squared`](Self::norm_squared).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::splat(2.0).length_squared(), ", stringify!($t), "::splat(2.0).norm_squared());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn length_squared(self) -> f32 {
                self.norm_squared()
            }

            /// The Euclidean distance `|self - other|`.
            ///
            /// # Accuracy
            ///
            /// [`norm`](Self::norm) of `self - other`, whose components are
            /// each rounded once (half an ulp): within 2 ulp of the length
            /// of that rounded difference. Infinite where a component of the
            /// difference overflows.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let (a, b) = (", stringify!($t), "::ONE, ", stringify!($t), "::splat(4.0));")]
            #[doc = concat!("assert_eq!(a.distance(b), (b - a).norm());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn distance(self, other: Self) -> f32 {
                (self - other).norm()
            }

            /// The squared distance `|self - other|^2` (overflows beyond about
            /// 1.8e19, as [`norm_squared`](Self::norm_squared)).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let (a, b) = (", stringify!($t), "::ONE, ", stringify!($t), "::splat(3.0));")]
            #[doc = concat!("assert_eq!(a.distance_squared(b), (b - a).norm_squared());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn distance_squared(self, other: Self) -> f32 {
                (self - other).norm_squared()
            }

            /// The unit vector in the direction of `self`, or the zero
            /// vector where there is none (zero, NaN or infinite input).
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ZERO.normalize_or_zero(), ", stringify!($t), "::ZERO);")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::NAN.normalize_or_zero(), ", stringify!($t), "::ZERO);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize_or_zero(self) -> Self {
                self.normalize_or(Self::ZERO)
            }

            /// The unit vector in the direction of `self`, or `fallback`
            /// where there is none (zero, NaN or infinite input).
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ZERO.normalize_or(", stringify!($t), "::ONE), ", stringify!($t), "::ONE);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize_or(self, fallback: Self) -> Self {
                self.try_normalize().unwrap_or(fallback)
            }

            /// `true` if any component is NaN.
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert!(", stringify!($t), "::NAN.is_nan() && !", stringify!($t), "::ONE.is_nan());")]
            /// ```
            #[inline]
            #[must_use]
            pub fn is_nan(self) -> bool {
                self.$first.is_nan() $(|| self.$rest.is_nan())*
            }

            /// Each component clamped to `[lo, hi]` (of the same component):
            /// `self.max(lo).min(hi)`, so a NaN in any operand gives NaN in
            /// that component, and where `lo > hi` the result is `hi`
            /// (glam asserts `lo <= hi`; this never panics).
            ///
            /// ```
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("let v = ", stringify!($t), "::splat(5.0);")]
            #[doc = concat!("assert_eq!(v.clamp(", stringify!($t), "::ZERO, ", stringify!($t), "::ONE), ", stringify!($t), "::ONE);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn clamp(self, lo: Self, hi: Self) -> Self {
                self.max(lo).min(hi)
            }

            /// nalgebra's name for the crate's [`norm`](Self::norm) (glam's
            /// [`length`](Self::length)).
            ///
            /// ```
            /// # #![allow(deprecated)]
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ONE.magnitude(), ", stringify!($t), "::ONE.norm());")]
            /// ```
            #[deprecated(note = "use `norm` (the notes' name) or `length` (glam's)")]
            #[inline]
            #[must_use]
            pub fn magnitude(self) -> f32 {
                self.norm()
            }

            /// nalgebra's name for the crate's [`norm_squared`](Self::norm_squared).
            ///
            /// ```
            /// # #![allow(deprecated)]
            #[doc = concat!("use rigtform::", stringify!($t), ";")]
            #[doc = concat!("assert_eq!(", stringify!($t), "::ONE.magnitude_squared(), ", stringify!($t), "::ONE.norm_squared());")]
            /// ```
            #[deprecated(note = "use `norm_squared` (the notes' name) or `length_squared` (glam's)")]
            #[inline]
            #[must_use]
            pub fn magnitude_squared(self) -> f32 {
                self.norm_squared()
            }
        }

        impl Mul for $t {
            type Output = Self;
            /// The component-wise product (glam's `Vec3 * Vec3`).
            #[inline]
            fn mul(self, o: Self) -> Self {
                Self { $first: self.$first * o.$first $(, $rest: self.$rest * o.$rest)* }
            }
        }
        impl Div for $t {
            type Output = Self;
            /// The component-wise quotient (glam's `Vec3 / Vec3`).
            #[inline]
            fn div(self, o: Self) -> Self {
                Self { $first: self.$first / o.$first $(, $rest: self.$rest / o.$rest)* }
            }
        }
        impl MulAssign for $t {
            /// `*self = *self * o`, component-wise.
            #[inline]
            fn mul_assign(&mut self, o: Self) {
                *self = *self * o;
            }
        }
        impl DivAssign for $t {
            /// `*self = *self / o`, component-wise.
            #[inline]
            fn div_assign(&mut self, o: Self) {
                *self = *self / o;
            }
        }
        impl Sum for $t {
            /// The sum of the vectors, from the zero vector, left to right.
            #[inline]
            fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
                iter.fold(Self::ZERO, |a, b| a + b)
            }
        }
        impl<'a> Sum<&'a $t> for $t {
            /// The sum of the vectors, from the zero vector, left to right.
            #[inline]
            fn sum<I: Iterator<Item = &'a Self>>(iter: I) -> Self {
                iter.fold(Self::ZERO, |a, b| a + *b)
            }
        }
        impl From<$tuple> for $t {
            /// The components in the order of the fields, as glam's.
            #[inline]
            fn from(($first $(, $rest)*): $tuple) -> Self {
                Self { $first $(, $rest)* }
            }
        }
        impl From<$t> for $tuple {
            /// The components in the order of the fields, as glam's.
            #[inline]
            fn from(v: $t) -> Self {
                (v.$first $(, v.$rest)*)
            }
        }
    };
}

componentwise_ops!(Cvec3 { x, y, z });
componentwise_ops!(Cvec4 { x, y, z, w });
indexing!(Cvec3, 3, { 0 => x, 1 => y }, z);
indexing!(Cvec4, 4, { 0 => x, 1 => y, 2 => z }, w);
everyday!(Cvec3, (f32, f32, f32), { x, y, z });
everyday!(Cvec4, (f32, f32, f32, f32), { x, y, z, w });

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indexing_follows_the_fields_and_clamps_past_the_end() {
        let mut v = Cvec3::new(1.0, 2.0, 3.0);
        assert_eq!(
            [v[0], v[1], v[2], v[3], v[usize::MAX]],
            [1.0, 2.0, 3.0, 3.0, 3.0]
        );
        v[1] = 5.0;
        v[9] = 7.0;
        assert_eq!(v, Cvec3::new(1.0, 5.0, 7.0));
        let mut c = Cvec4::new(1.0, 2.0, 3.0, 4.0);
        c[2] = -1.0;
        c[4] = 0.0;
        assert_eq!(c, Cvec4::new(1.0, 2.0, -1.0, 0.0));
        assert_eq!((c[0], c[1], c[7]), (1.0, 2.0, 0.0));
    }

    #[test]
    fn compound_assignment_matches_the_operators_and_arrays_round_trip() {
        let v = Cvec4::new(1.0, -2.0, 3.0, 0.5);
        let mut m = v;
        m *= 3.0;
        assert_eq!(m, v * 3.0);
        m /= 7.0;
        assert_eq!(m, v * 3.0 / 7.0);
        let mut u = Cvec3::new(1.0, 2.0, 4.0);
        u *= 0.5;
        u /= 0.25;
        assert_eq!(u, Cvec3::new(2.0, 4.0, 8.0));
        let a: [f32; 3] = u.into();
        assert_eq!(Cvec3::from(a), u);
        let b: [f32; 4] = v.into();
        assert_eq!((b, Cvec4::from(b)), ([1.0, -2.0, 3.0, 0.5], v));
    }

    #[test]
    fn cross_is_right_handed_and_anticommutative() {
        assert_eq!(Cvec3::X.cross(Cvec3::Y), Cvec3::Z);
        assert_eq!(Cvec3::Z.cross(Cvec3::X), Cvec3::Y);
        let a = Cvec3::new(1.0, -2.0, 0.5);
        let b = Cvec3::new(0.25, 3.0, -1.0);
        assert_eq!(a.cross(b), -b.cross(a));
        assert_eq!(a.cross(b).dot(a), 0.0);
    }

    #[test]
    fn operators_act_per_component() {
        let a = Cvec4::new(1.0, 2.0, 3.0, 4.0);
        let b = Cvec4::new(0.5, -1.0, 2.0, 0.0);
        assert_eq!(a + b, Cvec4::new(1.5, 1.0, 5.0, 4.0));
        assert_eq!(a - b, Cvec4::new(0.5, 3.0, 1.0, 4.0));
        assert_eq!(2.0 * a, a * 2.0);
        assert_eq!(a / 2.0, Cvec4::new(0.5, 1.0, 1.5, 2.0));
        let mut c = a;
        c += b;
        c -= b;
        assert_eq!(c, a);
    }

    #[test]
    fn normalize_of_degenerate_vectors_is_nan_not_a_panic() {
        assert!(Cvec3::ZERO.normalize().x.is_nan());
        assert!(Cvec3::new(f32::INFINITY, 0.0, 0.0).normalize().y.is_nan());
        assert!(Cvec4::ZERO.normalize().w.is_nan());
        assert_eq!(Cvec3::new(f32::MAX, 0.0, 0.0).normalize(), Cvec3::X);
        // As documented for norm: lengths beyond f32::MAX round to infinity.
        assert_eq!(Cvec3::new(f32::MAX, f32::MAX, 0.0).norm(), f32::INFINITY);
        assert_eq!(Cvec4::new(f32::MAX, 0.0, 0.0, 0.0).norm(), f32::MAX);
    }

    #[test]
    fn arrays_hold_the_coordinates_in_order() {
        assert_eq!(Cvec3::new(1.0, 2.0, 3.0).to_array(), [1.0, 2.0, 3.0]);
        let v = Cvec4::new(1.0, 2.0, 3.0, 4.0);
        assert_eq!(Cvec4::from_array(v.to_array()), v);
        assert_eq!(v.norm_squared(), 30.0);
        assert_eq!(Cvec3::new(2.0, 3.0, 6.0).norm_squared(), 49.0);
    }

    #[test]
    fn cvec4_products_norms_and_lerp_use_all_four_coordinates() {
        let a = Cvec4::new(1.0, 2.0, 3.0, 4.0);
        let b = Cvec4::new(-2.0, 0.5, 4.0, -1.5);
        assert_eq!(a.dot(b), -2.0 + 1.0 + 12.0 - 6.0);
        assert_eq!(Cvec4::new(1.0, 1.0, 1.0, 1.0).norm(), 2.0);
        assert_eq!(Cvec4::new(0.0, 0.0, 0.0, 5.0).norm(), 5.0);
        assert_eq!(
            Cvec4::new(0.0, 0.0, 3.0, 4.0).try_normalize(),
            Some(Cvec4::new(0.0, 0.0, 0.6, 0.8))
        );
        assert_eq!(a.lerp(b, 0.0), a);
        assert_eq!(a.lerp(b, 1.0), b);
        assert_eq!(a.lerp(b, 0.5), Cvec4::new(-0.5, 1.25, 3.5, 1.25));
        assert_eq!(a.lerp(b, -1.0), Cvec4::new(4.0, 3.5, 2.0, 9.5));
    }

    #[test]
    fn lerp_is_exact_at_both_ends() {
        let a = Cvec3::new(0.1, 0.2, 0.3);
        let b = Cvec3::new(-7.0, 1e-3, 5.0);
        assert_eq!(a.lerp(b, 0.0), a);
        assert_eq!(a.lerp(b, 1.0), b);
        assert_eq!(a.lerp(b, 2.0), Cvec3::new(-14.1, -0.198, 9.7));
    }
    /// glam's `Vec3` of the same components.
    fn g3(v: Cvec3) -> glam::Vec3 {
        glam::Vec3::new(v.x, v.y, v.z)
    }

    /// nalgebra's f64 vector of the same components.
    fn n3(v: Cvec3) -> nalgebra::Vector3<f64> {
        nalgebra::Vector3::new(v.x.into(), v.y.into(), v.z.into())
    }

    /// A random vector with components in [-1, 1] times 2^e, e in
    /// [-40, 40], so that the draws cover tiny and huge scales.
    fn draw(rng: &mut impl rand::Rng) -> Cvec3 {
        let scale = 2f32.powi(rng.random_range(-40..=40));
        Cvec3::new(
            rng.random_range(-1.0..=1.0),
            rng.random_range(-1.0..=1.0),
            rng.random_range(-1.0..=1.0),
        ) * scale
    }

    use crate::test_draws::count as draws;

    #[test]
    fn everyday_methods_agree_with_glam() {
        use rand::SeedableRng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(23);
        for _ in 0..draws() {
            let (a, b) = (draw(&mut rng), draw(&mut rng));
            let (ga, gb) = (g3(a), g3(b));
            assert_eq!(g3(a.min(b)), ga.min(gb));
            assert_eq!(g3(a.max(b)), ga.max(gb));
            assert_eq!(g3(a.abs()), ga.abs());
            assert_eq!(a.min_element(), ga.min_element());
            assert_eq!(a.max_element(), ga.max_element());
            assert_eq!(g3(a * b), ga * gb);
            if b.x * b.y * b.z != 0.0 {
                assert_eq!(g3(a / b), ga / gb);
            }
            assert_eq!(a.distance_squared(b), ga.distance_squared(gb));
            assert_eq!(a.length_squared(), ga.length_squared());
            assert_eq!(g3(Cvec3::splat(a.x)), glam::Vec3::splat(a.x));
            assert_eq!(<(f32, f32, f32)>::from(a), <(f32, f32, f32)>::from(ga));
            assert_eq!(Cvec3::from(<(f32, f32, f32)>::from(ga)), a);
            // glam's length squares without rescaling: compare where its
            // squares neither overflow nor underflow.
            if a.norm_squared().is_normal() && ga.length_squared() < 1e30 {
                let (ours, theirs) = (a.length(), ga.length());
                assert!((ours - theirs).abs() <= 4.0 * f32::EPSILON * theirs);
            }
            let d = (a - b).norm_squared();
            if d.is_normal() && d < 1e30 {
                let (ours, theirs) = (a.distance(b), ga.distance(gb));
                assert!((ours - theirs).abs() <= 4.0 * f32::EPSILON * theirs);
            }
            let unit = a.normalize_or_zero();
            let theirs = ga.normalize_or_zero();
            assert!(
                (g3(unit) - theirs).length() < 4.0 * f32::EPSILON || theirs == glam::Vec3::ZERO
            );
            let mut c = a;
            c *= b;
            c /= b;
            let same = |x: f32, y: f32| x == y || (x.is_nan() && y.is_nan());
            let theirs = (ga * gb / gb).to_array();
            assert!((0..3).all(|i| same(c[i], theirs[i])), "{c:?} vs {theirs:?}");
        }
        assert_eq!(g3(Cvec3::ONE), glam::Vec3::ONE);
        assert_eq!(
            [Cvec3::NEG_X, Cvec3::NEG_Y, Cvec3::NEG_Z].map(g3),
            [glam::Vec3::NEG_X, glam::Vec3::NEG_Y, glam::Vec3::NEG_Z]
        );
        let v = Cvec4::new(1.0, -2.0, 3.0, -4.0);
        let gv = glam::Vec4::new(1.0, -2.0, 3.0, -4.0);
        let g4 = |c: Cvec4| glam::Vec4::from_array(c.to_array());
        assert_eq!(g4(v.abs()), gv.abs());
        assert_eq!(g4(v * v / Cvec4::splat(2.0)), gv * gv / 2.0);
        assert_eq!(g4(v.min(Cvec4::ONE)), gv.min(glam::Vec4::ONE));
        assert_eq!(g4(v.max(Cvec4::ONE)), gv.max(glam::Vec4::ONE));
        assert_eq!(
            (v.min_element(), v.max_element()),
            (gv.min_element(), gv.max_element())
        );
        assert_eq!(v.length(), gv.length());
        assert_eq!(v.distance(Cvec4::ONE), gv.distance(glam::Vec4::ONE));
        assert!((g4(v.normalize_or_zero()) - gv.normalize_or_zero()).length() < 4.0 * f32::EPSILON);
        assert_eq!(
            [Cvec4::X, Cvec4::Y, Cvec4::Z, Cvec4::W, Cvec4::NEG_W].map(g4),
            [
                glam::Vec4::X,
                glam::Vec4::Y,
                glam::Vec4::Z,
                glam::Vec4::W,
                glam::Vec4::NEG_W
            ]
        );
        assert_eq!(
            Cvec4::from((1.0, 2.0, 3.0, 4.0)),
            Cvec4::new(1.0, 2.0, 3.0, 4.0)
        );
    }

    /// The exact angle between the f32 inputs, in f64, by nalgebra.
    fn angle64(a: Cvec3, b: Cvec3) -> f64 {
        let (a, b) = (n3(a).normalize(), n3(b).normalize());
        a.cross(&b).norm().atan2(a.dot(&b))
    }

    #[test]
    fn angle_between_is_within_its_bound_of_nalgebra_in_f64_and_near_glam() {
        use crate::accuracy::ANGLE_BETWEEN_MAX_ERROR;
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(24);
        let mut worst = 0f64;
        for i in 0..draws() {
            let a = draw(&mut rng);
            // A third random, a third nearly parallel, a third nearly
            // opposite, 1e-7 to 1e-1 rad apart.
            let tilt = 10f32.powf(rng.random_range(-7.0..-1.0));
            let b = match i % 3 {
                0 => draw(&mut rng),
                k => {
                    let off = draw(&mut rng).reject_from(a).normalize_or_zero() * a.norm() * tilt;
                    let b = a + off;
                    if k == 1 {
                        b * 3.0
                    } else {
                        -b * 0.25
                    }
                }
            };
            if !b.is_finite() || b == Cvec3::ZERO {
                continue;
            }
            let got = a.angle_between(b);
            let err = (f64::from(got) - angle64(a, b)).abs();
            worst = worst.max(err);
            assert!(
                err <= f64::from(ANGLE_BETWEEN_MAX_ERROR),
                "{a:?} {b:?}: {got} err {err:e}"
            );
            if i % 3 == 0 && (a.norm_squared() * b.norm_squared()).is_normal() {
                // glam's arccosine loses digits near 0 and pi only.
                let theirs = g3(a).angle_between(g3(b));
                assert!(
                    (got - theirs).abs() < 2e-3 + ANGLE_BETWEEN_MAX_ERROR,
                    "{got} vs glam {theirs}"
                );
            }
        }
        std::println!(
            "angle_between: worst error {worst:.3e} rad over {} draws",
            draws()
        );
        assert!(Cvec3::ZERO.angle_between(Cvec3::X).is_nan());
        assert!(Cvec3::X.angle_between(Cvec3::NAN).is_nan());
        assert!(Cvec3::X
            .angle_between(Cvec3::new(f32::INFINITY, 0.0, 0.0))
            .is_nan());
        assert_eq!(Cvec3::X.angle_between(-Cvec3::X), core::f32::consts::PI);
        assert_eq!(
            Cvec3::new(1e-30, 0.0, 0.0).angle_between(Cvec3::X * 1e30),
            0.0
        );
    }

    #[test]
    fn project_onto_and_reject_from_are_within_their_bound_of_nalgebra_in_f64() {
        use crate::accuracy::PROJECT_MAX_REL_ERROR;
        use rand::SeedableRng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(25);
        let (mut worst_p, mut worst_r) = (0f64, 0f64);
        for _ in 0..draws() {
            let (a, b) = (draw(&mut rng), draw(&mut rng));
            let (na, nb) = (n3(a), n3(b));
            let p64 = nb * (na.dot(&nb) / nb.dot(&nb));
            let r64 = na - p64;
            let size = na.norm();
            let ep = (n3(a.project_onto(b)) - p64).norm() / size;
            let er = (n3(a.reject_from(b)) - r64).norm() / size;
            worst_p = worst_p.max(ep);
            worst_r = worst_r.max(er);
            assert!(
                ep.max(er) <= f64::from(PROJECT_MAX_REL_ERROR),
                "{a:?} {b:?}: {ep:e} {er:e}"
            );
            if a.norm_squared().is_normal() && b.norm_squared().is_normal() {
                let scale = a.norm();
                let theirs = g3(a).project_onto(g3(b));
                assert!((g3(a.project_onto(b)) - theirs).length() < 1e-6 * scale);
                let theirs = g3(a).reject_from(g3(b));
                assert!((g3(a.reject_from(b)) - theirs).length() < 1e-6 * scale);
            }
        }
        std::println!("project_onto {worst_p:.3e}, reject_from {worst_r:.3e} (relative to |self|) over {} draws", draws());
        assert!(Cvec3::X.project_onto(Cvec3::ZERO).is_nan());
        assert!(Cvec3::X.reject_from(Cvec3::NAN).is_nan());
    }

    #[test]
    fn cvec4_project_onto_reject_from_and_project_agree_with_nalgebra_and_glam() {
        use crate::accuracy::PROJECT_MAX_REL_ERROR;
        use rand::SeedableRng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(33);
        let n4 = |v: Cvec4| nalgebra::Vector4::from(v.to_array().map(f64::from));
        let g4 = |v: Cvec4| glam::Vec4::from_array(v.to_array());
        let mut worst = 0f64;
        for _ in 0..draws() {
            let (a3, b3) = (draw(&mut rng), draw(&mut rng));
            let a = a3.extend(a3.y * 0.5 - a3.x);
            let b = b3.extend(b3.z * 2.0 + b3.x);
            let (na, nb) = (n4(a), n4(b));
            let p64 = nb * (na.dot(&nb) / nb.dot(&nb));
            let size = na.norm();
            let ep = (n4(a.project_onto(b)) - p64).norm() / size;
            let er = (n4(a.reject_from(b)) - (na - p64)).norm() / size;
            worst = worst.max(ep).max(er);
            assert!(
                ep.max(er) <= f64::from(PROJECT_MAX_REL_ERROR),
                "{a:?} {b:?}: {ep:e} {er:e}"
            );
            if a.norm_squared().is_normal() && b.norm_squared().is_normal() {
                let scale = a.norm();
                assert!(
                    (g4(a.project_onto(b)) - g4(a).project_onto(g4(b))).length() < 1e-6 * scale
                );
                assert!((g4(a.reject_from(b)) - g4(a).reject_from(g4(b))).length() < 1e-6 * scale);
                assert_eq!(g3(a.project()), g4(a).project());
            }
        }
        std::println!(
            "Cvec4 project_onto / reject_from: {worst:.3e} (relative to |self|) over {} draws",
            draws()
        );
        assert!(Cvec4::X.project_onto(Cvec4::ZERO).is_nan());
        assert!(!Cvec4::X.project().is_finite());
    }

    #[test]
    fn sums_clamp_and_nan_in_agree_with_glam_or_give_nan() {
        let vs = [Cvec3::X, Cvec3::Y * 2.0, Cvec3::Z * 3.0];
        assert_eq!(vs.iter().sum::<Cvec3>(), Cvec3::new(1.0, 2.0, 3.0));
        assert_eq!(vs.into_iter().sum::<Cvec3>(), Cvec3::new(1.0, 2.0, 3.0));
        assert_eq!(core::iter::empty::<Cvec4>().sum::<Cvec4>(), Cvec4::ZERO);
        let g: glam::Vec3 = vs.iter().map(|v| g3(*v)).sum();
        assert_eq!(g3(vs.iter().sum()), g);
        let n = Cvec3::new(f32::NAN, 1.0, 2.0);
        assert!(n.is_nan() && !Cvec3::ONE.is_nan());
        for v in [n, Cvec3::ONE, Cvec3::new(1.0, 2.0, f32::NAN), Cvec3::ZERO] {
            assert_eq!(v.is_nan(), g3(v).is_nan());
            assert_eq!(
                g3(v.normalize_or(Cvec3::Z)),
                g3(v).normalize_or(glam::Vec3::Z)
            );
        }
        assert!(n.min(Cvec3::ONE).x.is_nan() && Cvec3::ONE.max(n).x.is_nan());
        assert!(n.min_element().is_nan() && n.max_element().is_nan());
        assert_eq!(n.normalize_or(Cvec3::X), Cvec3::X);
        assert_eq!(
            Cvec3::new(f32::INFINITY, 0.0, 0.0).normalize_or_zero(),
            Cvec3::ZERO
        );
        assert_eq!(Cvec3::new(0.0, 1e-40, 0.0).normalize_or_zero(), Cvec3::Y);
        assert_eq!(2.0 * Cvec3::ONE, Cvec3::splat(2.0));
        let v = Cvec3::new(-2.0, 0.5, 9.0);
        let g = g3(v).clamp(glam::Vec3::ZERO, glam::Vec3::ONE);
        assert_eq!(g3(v.clamp(Cvec3::ZERO, Cvec3::ONE)), g);
        assert!(n.clamp(Cvec3::ZERO, Cvec3::ONE).x.is_nan());
        assert_eq!(Cvec3::ONE.clamp(Cvec3::ONE, Cvec3::ZERO), Cvec3::ZERO);
        assert_eq!(
            Cvec4::from_array(g3(v).extend(2.0).to_array()),
            v.extend(2.0)
        );
        #[allow(deprecated)]
        {
            assert_eq!(v.extend(1.0).truncate(), v);
            assert_eq!(
                (v.magnitude(), v.magnitude_squared()),
                (v.norm(), v.norm_squared())
            );
            let w = Cvec4::new(1.0, 2.0, 2.0, 4.0);
            assert_eq!((w.magnitude(), w.magnitude_squared()), (5.0, 25.0));
        }
    }

    /// glam's spellings give glam's results: bit for bit where the
    /// operations are the same, within a few ulps where glam orders them
    /// otherwise.
    #[test]
    fn element_sum_product_midpoint_reflect_and_with_as_glam() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(36);
        for _ in 0..10_000 {
            let mut c = || rng.random_range(-10.0f32..10.0);
            let (a, b) = (Cvec3::new(c(), c(), c()), Cvec3::new(c(), c(), c()));
            let (ga, gb) = (
                glam::Vec3::from_array(a.to_array()),
                glam::Vec3::from_array(b.to_array()),
            );
            assert_eq!(a.element_sum(), ga.element_sum());
            assert_eq!(a.element_product(), ga.element_product());
            assert!((a.midpoint(b) - Cvec3::from_array(ga.midpoint(gb).to_array())).norm() <= 1e-5);
            let n = b.normalize();
            let gn = glam::Vec3::from_array(n.to_array());
            assert!((a.reflect(n) - Cvec3::from_array(ga.reflect(gn).to_array())).norm() <= 1e-5);
            assert!((a.length_recip() - ga.length_recip()).abs() <= 1e-6 * ga.length_recip());
            assert_eq!(n.is_normalized(), gn.is_normalized());
            assert_eq!(a.with_x(1.5).to_array(), ga.with_x(1.5).to_array());
            assert_eq!(a.with_y(1.5).to_array(), ga.with_y(1.5).to_array());
            assert_eq!(a.with_z(1.5).to_array(), ga.with_z(1.5).to_array());
            let (p, q) = (
                Cvec4::new(c(), c(), c(), c()),
                Cvec4::new(c(), c(), c(), c()),
            );
            let (gp, gq) = (
                glam::Vec4::from_array(p.to_array()),
                glam::Vec4::from_array(q.to_array()),
            );
            // glam's Vec4 adds and multiplies its lanes pairwise.
            let scale = p.abs().element_sum();
            assert!((p.element_sum() - gp.element_sum()).abs() <= 4.0 * f32::EPSILON * scale);
            let product = p.element_product();
            assert!((product - gp.element_product()).abs() <= 4.0 * f32::EPSILON * product.abs());
            assert!((p.midpoint(q) - Cvec4::from_array(gp.midpoint(gq).to_array())).norm() <= 1e-5);
        }
        assert!(!Cvec3::NAN.is_normalized());
        assert_eq!(Cvec3::ZERO.length_recip(), f32::INFINITY);
    }
}
