//! Coordinate vectors: [`Cvec3`] (a point or a direction) and [`Cvec4`]
//! (homogeneous coordinates: `w = 1` for a point, `w = 0` for a vector).

use core::ops::{
    Add, AddAssign, Div, DivAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign,
};

use crate::float::scale_for_squares;

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
    #[doc(alias = "length_squared")]
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
    #[doc(alias = "length")]
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
}

impl Cvec4 {
    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0, 0.0);
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
    #[doc(alias = "length_squared")]
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
    #[doc(alias = "length")]
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

componentwise_ops!(Cvec3 { x, y, z });
componentwise_ops!(Cvec4 { x, y, z, w });
indexing!(Cvec3, 3, { 0 => x, 1 => y }, z);
indexing!(Cvec4, 4, { 0 => x, 1 => y, 2 => z }, w);

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
}
