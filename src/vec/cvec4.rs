//! [`Cvec4`], the notes' homogeneous coordinate 4-vector: `w = 1` for a
//! point, `w = 0` for a direction. Its own methods here (the homogeneous
//! forms and the perspective divide); what it shares with [`Cvec3`] and
//! [`Quat`](crate::Quat) is written once in `vec/template.rs` and
//! instanced at the bottom.

use super::template::{coordinates, euclidean};
use super::Cvec3;

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

impl Cvec4 {
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
}

impl From<(Cvec3, f32)> for Cvec4 {
    /// `[v, w]`, glam's `Vec4::from((v, w))`: [`Cvec4::from_point`] for
    /// `w = 1`, [`Cvec4::from_vector`] for `w = 0`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// assert_eq!(Cvec4::from((Cvec3::X, 1.0)), Cvec4::from_point(Cvec3::X));
    /// ```
    #[inline]
    fn from((v, w): (Cvec3, f32)) -> Self {
        v.extend(w)
    }
}

euclidean!(Cvec4 { x, y, z, w }, unit X);
coordinates!(Cvec4, 4, [x, y, z, w], index { 0 => x, 1 => y, 2 => z } last w);
