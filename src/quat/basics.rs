//! The methods of [`Quat`] itself, as the notes' "the representation" and
//! "Operations" have them: construction (by components, axis and angle,
//! about a coordinate axis), the components and arrays, norms and
//! normalization, the inverse, `cn`, and the axis-angle form.

use super::power::Polar;
use super::Quat;
use crate::float::{self, scale_for_squares};
use crate::vec::Cvec3;

impl Quat {
    /// The identity rotation `[1, 0, 0, 0]`.
    pub const IDENTITY: Self = Self::from_wxyz(1.0, 0.0, 0.0, 0.0);
    /// All components NaN: the documented result for NaN or infinite input.
    pub const NAN: Self = Self::from_wxyz(f32::NAN, f32::NAN, f32::NAN, f32::NAN);

    /// Builds a quaternion from its components in glam's order, scalar
    /// last: `x, y, z` the vector part, `w` the scalar part. The same as
    /// glam's `Quat::from_xyzw`.
    ///
    /// # Preconditions
    ///
    /// None here; the rotation methods expect a unit quaternion and say so.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_xyzw(0.0, 0.0, 0.0, 1.0), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_xyzw(x: f32, y: f32, z: f32, w: f32) -> Self {
        Self { x, y, z, w }
    }

    /// Builds a quaternion from its components scalar first, as the notes
    /// write `[w, c]` and as nalgebra's `Quaternion::new(w, i, j, k)` takes
    /// them.
    ///
    /// # Preconditions
    ///
    /// None here; the rotation methods expect a unit quaternion and say so.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_wxyz(1.0, 0.0, 0.0, 0.0), Quat::IDENTITY);
    /// assert_eq!(Quat::from_wxyz(4.0, 1.0, 2.0, 3.0), Quat::from_xyzw(1.0, 2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_wxyz(w: f32, x: f32, y: f32, z: f32) -> Self {
        Self { x, y, z, w }
    }

    /// Scalar first, as [`from_wxyz`](Self::from_wxyz). Its order is not
    /// in its name, and glam's users expect scalar last: call
    /// [`from_wxyz`](Self::from_wxyz) or [`from_xyzw`](Self::from_xyzw).
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::Quat;
    /// assert_eq!(Quat::new(1.0, 0.0, 0.0, 0.0), Quat::from_wxyz(1.0, 0.0, 0.0, 0.0));
    /// ```
    #[deprecated(
        since = "0.1.0",
        note = "the order is not in the name: use `Quat::from_wxyz(w, x, y, z)` (scalar first, \
                as here and in nalgebra's `Quaternion::new`) or `Quat::from_xyzw(x, y, z, w)` (glam's)"
    )]
    #[inline]
    #[must_use]
    pub const fn new(w: f32, x: f32, y: f32, z: f32) -> Self {
        Self::from_wxyz(w, x, y, z)
    }

    /// The rotation by `angle` radians about `axis`, by the right-hand rule:
    /// `[cos(angle/2), sin(angle/2) k]` with `k = axis / |axis|` (the notes'
    /// "the representation").
    ///
    /// # Preconditions
    ///
    /// `axis` need not be of unit length: it is normalized here (exactly
    /// scaled, so subnormal and huge axes work). A zero axis gives
    /// [`Quat::IDENTITY`] (no direction, no rotation); a NaN or infinite axis
    /// or angle gives [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// The result's norm is within [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_axis_angle(Cvec3::new(0.0, 0.0, 2.0), PI);
    /// assert!((q * Cvec3::X + Cvec3::X).norm() < 1e-6); // half a turn about z
    /// assert_eq!(Quat::from_axis_angle(Cvec3::ZERO, 1.0), Quat::IDENTITY);
    /// ```
    #[must_use]
    pub fn from_axis_angle(axis: Cvec3, angle: f32) -> Self {
        if !(axis.is_finite() && angle.is_finite()) {
            return Self::NAN;
        }
        match axis.try_normalize() {
            Some(k) => {
                let (s, c) = float::sin_cos(angle * 0.5);
                Self::from_scalar_vector(c, k * s)
            }
            None => Self::IDENTITY,
        }
    }

    /// The rotation by `angle` radians about the x axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_x(FRAC_PI_2) * Cvec3::Y;
    /// assert!((v - Cvec3::Z).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_x(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, s, 0.0, 0.0)
    }

    /// The rotation by `angle` radians about the y axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_y(FRAC_PI_2) * Cvec3::Z;
    /// assert!((v - Cvec3::X).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_y(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, 0.0, s, 0.0)
    }

    /// The rotation by `angle` radians about the z axis.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_z(FRAC_PI_2) * Cvec3::X;
    /// assert!((v - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_rotation_z(angle: f32) -> Self {
        let (s, c) = float::sin_cos(angle * 0.5);
        Self::from_wxyz(c, 0.0, 0.0, s)
    }

    /// The vector part `[x, y, z]`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// assert_eq!(Quat::from_wxyz(1.0, 2.0, 3.0, 4.0).vector(), Cvec3::new(2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn vector(self) -> Cvec3 {
        Cvec3::new(self.x, self.y, self.z)
    }

    #[inline]
    pub(crate) const fn from_scalar_vector(w: f32, v: Cvec3) -> Self {
        Self::from_wxyz(w, v.x, v.y, v.z)
    }

    /// The components as an array `[x, y, z, w]`, scalar last: the order
    /// of glam's `to_array`, of mint, glTF and GPU shaders, and of the
    /// memory layout.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_xyzw(1.0, 2.0, 3.0, 4.0);
    /// assert_eq!(q.to_array(), [1.0, 2.0, 3.0, 4.0]);
    /// assert_eq!(Quat::IDENTITY.to_array(), [0.0, 0.0, 0.0, 1.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f32; 4] {
        [self.x, self.y, self.z, self.w]
    }

    /// Builds a quaternion from an array `[x, y, z, w]`, scalar last, as
    /// glam's `from_array` and glTF's rotation accessors.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_array([0.0, 0.0, 0.0, 1.0]), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_array([x, y, z, w]: [f32; 4]) -> Self {
        Self { x, y, z, w }
    }

    /// The components scalar first, `[w, x, y, z]`, as the notes write
    /// them.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::IDENTITY.to_wxyz(), [1.0, 0.0, 0.0, 0.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_wxyz(self) -> [f32; 4] {
        [self.w, self.x, self.y, self.z]
    }

    /// `f` of each component: the one place a `Quat`'s components are
    /// scaled one by one.
    #[inline(always)]
    pub(super) fn map(self, f: impl Fn(f32) -> f32) -> Self {
        Self::from_wxyz(f(self.w), f(self.x), f(self.y), f(self.z))
    }

    /// `true` if every component is finite.
    ///
    /// ```
    /// assert!(!rigtform::Quat::NAN.is_finite());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.w.is_finite() && self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// `true` if any component is NaN.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert!(Quat::NAN.is_nan());
    /// assert!(!Quat::from_wxyz(f32::INFINITY, 0.0, 0.0, 0.0).is_nan());
    /// ```
    #[inline]
    #[must_use]
    pub fn is_nan(self) -> bool {
        self.w.is_nan() || self.x.is_nan() || self.y.is_nan() || self.z.is_nan()
    }

    /// `true` if the norm is within
    /// [`accuracy::IS_NORMALIZED_TOLERANCE`](crate::accuracy::IS_NORMALIZED_TOLERANCE)
    /// of 1: the quaternion can be handed to the methods that expect a
    /// unit one. `false` for NaN or infinite components.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert!(Quat::from_rotation_x(0.3).is_normalized());
    /// assert!(!Quat::from_wxyz(2.0, 0.0, 0.0, 0.0).is_normalized());
    /// assert!(!Quat::NAN.is_normalized());
    /// ```
    #[doc(alias = "is_unit")]
    #[inline]
    #[must_use]
    pub fn is_normalized(self) -> bool {
        (self.norm_squared() - 1.0).abs() <= 2.0 * crate::accuracy::IS_NORMALIZED_TOLERANCE
    }

    /// The inverse of a unit quaternion, its conjugate `[w, -x, -y, -z]`
    /// (the notes' "unit quat multiplicative inverse").
    ///
    /// # Preconditions
    ///
    /// `self` is a unit quaternion. For any other, this is still the
    /// conjugate, which is the inverse times `|self|^2`. Exact (sign flips
    /// only): `q.inv().inv() == q` bit for bit.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_y(0.7);
    /// assert!((q * q.inv()).angle_to(Quat::IDENTITY) < 1e-6);
    /// assert_eq!(q.inv().inv(), q);
    /// ```
    #[cfg_attr(kani, kani::ensures(|r: &Quat| crate::kani_contracts::is_conjugate(self, *r)))]
    #[inline]
    #[must_use]
    pub fn inv(self) -> Self {
        Self::from_wxyz(self.w, -self.x, -self.y, -self.z)
    }

    /// Dot product of the four components, `cos(angle/2)` of the rotation
    /// from `self` to `other` up to sign, for unit quaternions.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::IDENTITY.dot(-Quat::IDENTITY), -1.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn dot(self, other: Self) -> f32 {
        self.w * other.w + self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Squared norm, the sum of the four squares. Overflows for components
    /// beyond about 1.8e19; use [`norm`](Self::norm) for the norm itself.
    ///
    /// ```
    /// assert_eq!(rigtform::Quat::from_wxyz(1.0, 1.0, 1.0, 1.0).norm_squared(), 4.0);
    /// ```
    #[inline]
    #[must_use]
    pub fn norm_squared(self) -> f32 {
        self.dot(self)
    }

    /// Norm (length as a 4-vector), without intermediate overflow or
    /// underflow: within 2 ulp for every finite input.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_wxyz(0.0, 3.0, 0.0, 4.0).norm(), 5.0);
    /// assert_eq!(Quat::from_wxyz(f32::MAX, 0.0, 0.0, 0.0).norm(), f32::MAX);
    /// ```
    #[inline]
    #[must_use]
    pub fn norm(self) -> f32 {
        scale_for_squares(self.to_array()).norm()
    }

    /// `self / |self|`, or `None` if `self` is zero or has a NaN or infinite
    /// component.
    ///
    /// # Accuracy
    ///
    /// The result's norm is within
    /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of 1 for every finite non-zero input, including subnormal and huge ones.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_wxyz(2.0, 0.0, 0.0, 0.0).try_normalize(), Some(Quat::IDENTITY));
    /// assert_eq!(Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).try_normalize(), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        Some(Self::from_array(scale_for_squares(self.to_array()).unit()?))
    }

    /// `self / |self|`: pulls a quaternion that drifted off the unit sphere
    /// back onto it.
    ///
    /// # Preconditions
    ///
    /// `self` is finite and non-zero. Otherwise the result is [`Quat::NAN`]
    /// (never a panic); [`try_normalize`](Self::try_normalize) returns an
    /// `Option` instead.
    ///
    /// # Accuracy
    ///
    /// As [`try_normalize`](Self::try_normalize).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_wxyz(1e-40, 0.0, 1e-40, 0.0).normalize(); // subnormal input
    /// assert!((q.norm() - 1.0).abs() < 1e-6);
    /// ```
    #[cfg_attr(kani, kani::requires(crate::kani_contracts::normalize_requires(self)))]
    #[cfg_attr(kani, kani::ensures(|r: &Quat| crate::kani_contracts::normalize_ensures(self, *r)))]
    #[inline]
    #[must_use]
    pub fn normalize(self) -> Self {
        self.try_normalize().unwrap_or(Self::NAN)
    }

    /// Conditional negation, the notes' `cn`: `-self` if `w < 0`, otherwise
    /// `self`. The same rotation, written with `w >= 0`, so that its angle is
    /// at most pi (the short way). Exact.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_wxyz(-0.6, 0.8, 0.0, 0.0).cn(), Quat::from_wxyz(0.6, -0.8, 0.0, 0.0));
    /// assert_eq!(Quat::from_wxyz(0.6, 0.8, 0.0, 0.0).cn(), Quat::from_wxyz(0.6, 0.8, 0.0, 0.0));
    /// ```
    #[doc(alias = "conditional_negate")]
    #[inline]
    #[must_use]
    pub fn cn(self) -> Self {
        if self.w < 0.0 {
            -self
        } else {
            self
        }
    }

    /// The rotation as a unit axis and an angle in [0, pi] radians: the
    /// short way, whichever of `q` and `-q` is given.
    ///
    /// # Preconditions
    ///
    /// Any finite non-zero quaternion (the angle comes from atan2, which is
    /// scale-free). A pure real quaternion, or zero, is no rotation:
    /// `(Cvec3::X, 0.0)`. NaN or infinite input gives `(Cvec3::NAN, NaN)`.
    ///
    /// # Accuracy
    ///
    /// The angle is within [`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR)
    /// of the exact one for unit input (atan2 stays accurate near 0 and pi, where acos does not).
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let (axis, angle) = Quat::from_axis_angle(Cvec3::Y, 1.5 * PI).to_axis_angle();
    /// // 270 degrees about +y is 90 degrees about -y:
    /// assert!((axis + Cvec3::Y).norm() < 1e-6);
    /// assert!((angle - 0.5 * PI).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn to_axis_angle(self) -> (Cvec3, f32) {
        if !self.is_finite() {
            return (Cvec3::NAN, f32::NAN);
        }
        let Polar { axis, phi } = self.cn().polar();
        (axis, 2.0 * phi)
    }

    /// The angle in [0, pi] radians of the rotation that takes `self` to
    /// `other`: the angle of `other * self.inv()`, the short way. Zero, up
    /// to rounding, exactly when they are the same rotation (so
    /// `q.angle_to(-q)` is 0). This is the right way to compare two
    /// rotations (never component by component).
    ///
    /// # Preconditions
    ///
    /// Unit quaternions; NaN or infinite input gives NaN.
    ///
    /// # Accuracy
    ///
    /// The angle is computed with atan2 from the transition quaternion, so
    /// it stays accurate for tiny and for nearly pi angles; its error is
    /// that of one product plus [`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_x(0.25);
    /// let b = Quat::from_rotation_x(1.0);
    /// assert!((a.angle_to(b) - 0.75).abs() < 1e-6);
    /// assert_eq!(b.angle_to(-b), 0.0);
    /// ```
    #[must_use]
    pub fn angle_to(self, other: Self) -> f32 {
        (other * self.inv()).to_axis_angle().1
    }

    /// The Hamilton product `self * other`, pulled back towards unit norm by
    /// one Newton step for `1 / sqrt(n)`, `n` being the product's squared
    /// norm: the product times `(3 - n) / 2`. No square root, no division.
    ///
    /// For long integration chains (a gyro integrator multiplying millions
    /// of small rotations): plain products let the rounding errors of the
    /// norm add up, while here a product whose squared norm is `1 + e` comes
    /// out with a norm of `1 - 3 e^2 / 8` plus one rounding, so the drift
    /// cannot accumulate.
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions, or nearly so (the step
    /// converges towards 1 for squared norms in (0, 3), and fastest near 1).
    /// NaN or infinite input gives a NaN or infinite result.
    ///
    /// # Accuracy
    ///
    /// The rotation is that of `self * other` (the scale does not change it);
    /// the norm stays within
    /// [`accuracy::RENORMALIZED_CHAIN_NORM_ERROR`](crate::accuracy::RENORMALIZED_CHAIN_NORM_ERROR)
    /// of 1 over a chain of 1,000,000 products
    /// (`renormalized_product_chain_stays_unit` in `tests/edge_cases.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let step = Quat::from_rotation_z(1e-3).mul_renormalized(Quat::from_rotation_x(2e-3));
    /// let mut q = Quat::IDENTITY;
    /// for _ in 0..100_000 {
    ///     q = q.mul_renormalized(step);
    /// }
    /// assert!((q.norm() - 1.0).abs() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn mul_renormalized(self, other: Self) -> Self {
        let p = self * other;
        let s = (3.0 - p.norm_squared()) * 0.5;
        p.map(|c| c * s)
    }
}
