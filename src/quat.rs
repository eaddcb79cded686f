//! [`Quat`]: rotation quaternions, their power operator and slerp, as in the
//! notes' sections "the representation", "Operations", "Power",
//! "power antipodes and cycle" and "to interpolate".

use core::ops::{Mul, Neg};

use crate::float::{self, scale_for_squares};
use crate::vec::{Cvec3, Cvec4};

/// A quaternion `[w, x, y, z]`, scalar first as in the notes. A rotation of
/// `theta` radians about the unit axis `k` is `[cos(theta/2), sin(theta/2) k]`.
///
/// `q` and `-q` are the same rotation. `a * b` is the Hamilton product,
/// which applies `b` first, then `a` (as rotation matrices do).
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
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[repr(C)]
pub struct Quat {
    /// Scalar part, `cos(theta / 2)` for a rotation by `theta`.
    pub w: f32,
    /// First coordinate of the vector part, `sin(theta / 2) k.x`.
    pub x: f32,
    /// Second coordinate of the vector part, `sin(theta / 2) k.y`.
    pub y: f32,
    /// Third coordinate of the vector part, `sin(theta / 2) k.z`.
    pub z: f32,
}

impl Default for Quat {
    /// The identity rotation.
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// The unit axis and the angle `phi = atan2(beta, w)` of the notes' "Power"
/// section: `self = |self| (cos phi, sin phi axis)`.
pub(crate) struct Polar {
    pub(crate) axis: Cvec3,
    pub(crate) phi: f32,
}

/// 2^-21 (four ulps of 1): the cosine between a unit direction and the
/// quaternion it must be orthogonal to, below which slerp's extrapolation
/// takes the direction as orthogonal (a larger one would show in the norm
/// of the result, by up to that much).
const ORTHOGONAL_TO_ULPS: f32 = 4.768_371_6e-7;

/// 2^-63: the smallest length of the direction of slerp's extrapolation (in
/// the scaled units of `scale_for_squares`, where the difference it comes
/// from is at least 2^-50 long) whose squares are still normal, so that it
/// normalizes to full precision; shorter, it is rounding.
const MIN_ORTHOGONAL: f32 = 1.084_202_2e-19;

/// The bits of 2^125, the largest |alpha| slerp's extrapolation uses (an
/// immediate operand on Arm, where f32::MAX / 4 would be a load).
const ALPHA_LIMIT_BITS: u32 = 0x7e00_0000;

/// How far the ratio of two squared norms may be from 1 for slerp to treat
/// the inputs as unit: well above the rounding of f32 unit quaternions
/// (a few 1e-7), well below any real drift.
const NEARLY_UNIT: f32 = 1e-6;
/// 2^-12 rad: below this, `sin(x) / sin(phi)` is `x / phi` to f32's
/// precision (the two differ by less than `phi^2 / 6`, 2^-26).
const SMALL_ANGLE: f32 = 1.0 / 4096.0;

impl Quat {
    /// The identity rotation `[1, 0, 0, 0]`.
    pub const IDENTITY: Self = Self::new(1.0, 0.0, 0.0, 0.0);
    /// All components NaN: the documented result for NaN or infinite input.
    pub const NAN: Self = Self::new(f32::NAN, f32::NAN, f32::NAN, f32::NAN);

    /// Builds a quaternion from its components, scalar first.
    ///
    /// # Preconditions
    ///
    /// None here; the rotation methods expect a unit quaternion and say so.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::new(1.0, 0.0, 0.0, 0.0), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(w: f32, x: f32, y: f32, z: f32) -> Self {
        Self { w, x, y, z }
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
        Self::new(c, s, 0.0, 0.0)
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
        Self::new(c, 0.0, s, 0.0)
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
        Self::new(c, 0.0, 0.0, s)
    }

    /// The vector part `[x, y, z]`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// assert_eq!(Quat::new(1.0, 2.0, 3.0, 4.0).vector(), Cvec3::new(2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn vector(self) -> Cvec3 {
        Cvec3::new(self.x, self.y, self.z)
    }

    #[inline]
    pub(crate) const fn from_scalar_vector(w: f32, v: Cvec3) -> Self {
        Self::new(w, v.x, v.y, v.z)
    }

    #[inline]
    const fn to_array(self) -> [f32; 4] {
        [self.w, self.x, self.y, self.z]
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
    #[inline]
    #[must_use]
    pub fn inv(self) -> Self {
        Self::new(self.w, -self.x, -self.y, -self.z)
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
    /// assert_eq!(rigtform::Quat::new(1.0, 1.0, 1.0, 1.0).norm_squared(), 4.0);
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
    /// assert_eq!(Quat::new(0.0, 3.0, 0.0, 4.0).norm(), 5.0);
    /// assert_eq!(Quat::new(f32::MAX, 0.0, 0.0, 0.0).norm(), f32::MAX);
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
    /// assert_eq!(Quat::new(2.0, 0.0, 0.0, 0.0).try_normalize(), Some(Quat::IDENTITY));
    /// assert_eq!(Quat::new(0.0, 0.0, 0.0, 0.0).try_normalize(), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        let [w, x, y, z] = scale_for_squares(self.to_array()).unit()?;
        Some(Self::new(w, x, y, z))
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
    /// let q = Quat::new(1e-40, 0.0, 1e-40, 0.0).normalize(); // subnormal input
    /// assert!((q.norm() - 1.0).abs() < 1e-6);
    /// ```
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
    /// assert_eq!(Quat::new(-0.6, 0.8, 0.0, 0.0).cn(), Quat::new(0.6, -0.8, 0.0, 0.0));
    /// assert_eq!(Quat::new(0.6, 0.8, 0.0, 0.0).cn(), Quat::new(0.6, 0.8, 0.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn cn(self) -> Self {
        if self.w < 0.0 {
            -self
        } else {
            self
        }
    }

    /// The notes' decomposition `self = |self| (cos phi, sin phi k)`, with `k`
    /// the normalized vector part and `phi = atan2(beta, w)` in [0, pi].
    /// Scale-free: the vector part is normalized by exact power-of-two
    /// scaling, and `w` is scaled by the same power, so neither subnormal nor
    /// huge components lose precision or overflow. A pure real quaternion
    /// has no axis: it gets the x axis, with `phi = pi` if `w < 0` (a turn
    /// by 2 pi) and `phi = 0` otherwise (including zero).
    ///
    /// The caller has checked that every component is finite.
    pub(crate) fn polar(self) -> Polar {
        let v = scale_for_squares([self.x, self.y, self.z, 0.0]);
        if v.sum == 0.0 {
            let phi = if self.w < 0.0 {
                core::f32::consts::PI
            } else {
                0.0
            };
            return Polar {
                axis: Cvec3::X,
                phi,
            };
        }
        let beta = float::sqrt(v.sum);
        let [x, y, z, _] = v.v;
        Polar {
            axis: Cvec3::new(x / beta, y / beta, z / beta),
            // w * scale may overflow to infinity (when the vector part was
            // scaled up because it is tiny beside w) or go subnormal (when it
            // was scaled down because it is huge): atan2 then gives 0 or pi,
            // or pi/2, which are the correctly rounded angles in those cases.
            phi: float::atan2(beta, self.w * v.scale),
        }
    }

    /// The power operator of the notes: with `self = |self| (cos phi, sin phi k)`,
    /// `phi = atan2(beta, w)`, returns `(cos(alpha phi), sin(alpha phi) k)`, the
    /// rotation about the same axis by `alpha` times the angle.
    ///
    /// No conditional negation happens here (the notes put it in
    /// [`slerp`](Self::slerp)): for `w < 0` the angle `2 phi` exceeds pi, so
    /// `q.pow(alpha)` and `(-q).pow(alpha)` turn different ways.
    ///
    /// # Preconditions
    ///
    /// None beyond finiteness. `self` need not be a unit quaternion: atan2 is
    /// scale-free, and the axis is normalized by exact scaling, so non-unit,
    /// subnormal and huge inputs (up to `f32::MAX`) all give a unit result.
    ///
    /// - A pure real `self` (zero vector part) has no axis. `w > 0` (and the
    ///   zero quaternion) gives [`Quat::IDENTITY`]. `w < 0` is a turn by
    ///   2 pi about every axis; it is taken about the x axis:
    ///   `(cos(alpha pi), sin(alpha pi), 0, 0)`.
    /// - NaN or infinite `self` or `alpha` gives [`Quat::NAN`].
    /// - Every finite `alpha` works. For `|alpha| > f32::MAX / 4`, where
    ///   `alpha phi` could overflow, the result is computed as the fourth
    ///   power (two squarings) of `self.pow(alpha / 4)`.
    ///
    /// # Accuracy
    ///
    /// Against an f64 reference over random unit inputs and `alpha` in
    /// [-2, 3]: rotation error at most
    /// [`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR)
    /// `* max(1, |alpha| theta)` radians, `theta` being the angle of `self`
    /// (the rounding of `alpha phi` grows with the turn). Norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1
    /// for every finite non-zero input and finite `alpha`
    /// (`tests/differential.rs`, `tests/edge_cases.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_x(1.2);
    /// assert!(q.pow(0.5).angle_to(Quat::from_rotation_x(0.6)) < 1e-6);
    /// assert_eq!(q.pow(0.0), Quat::IDENTITY);
    /// // Not unit, still a unit result:
    /// assert!((Quat::new(0.0, 5.0, 0.0, 0.0).pow(0.3).norm() - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn pow(self, alpha: f32) -> Self {
        if !(self.is_finite() && alpha.is_finite()) {
            return Self::NAN;
        }
        // |alpha| <= f32::MAX / 4 and |phi| <= pi < 4 keep alpha * phi finite.
        let (alpha, square_twice) = if alpha.abs() > f32::MAX / 4.0 {
            (alpha * 0.25, true)
        } else {
            (alpha, false)
        };
        let Polar { axis, phi } = self.polar();
        let (s, c) = float::sin_cos(alpha * phi);
        let result = Self::from_scalar_vector(c, axis * s);
        if !square_twice {
            return result;
        }
        let square = result * result;
        // Two rounded products roughly triple the norm error: renormalize.
        (square * square).normalize()
    }

    /// Spherical linear interpolation, as the notes define it:
    /// `cn(other * self.inv()).pow(alpha) * self`.
    ///
    /// The rotation `other * self.inv()` that takes `self` to `other` is
    /// conditionally negated so it goes the short way (at most pi), then
    /// scaled by `alpha`. The result moves from `self` to `other` about one
    /// fixed axis with constant angular velocity, and is left invariant:
    /// `(g * a).slerp(g * b, t) == g * a.slerp(b, t)` up to sign.
    ///
    /// - `alpha = 0` gives exactly `self`; `alpha = 1` gives the rotation of
    ///   `other` (possibly written as `-other`).
    /// - `alpha` outside [0, 1] extrapolates along the same great circle.
    /// - Identical, nearly identical, antipodal (`other == -self`) and
    ///   opposite (pi apart) inputs all give finite unit results; for
    ///   rotations exactly pi apart both ways are equally short, and the sign
    ///   of the rounded dot product picks one.
    ///
    /// # How it is evaluated
    ///
    /// `pow(alpha) * self` of the notes traces the great circle of the unit
    /// 4-sphere through `self` and `other`, so for `alpha` in [0, 1] it is
    /// evaluated in that plane, without the two f32 products (each of which
    /// rounds by up to 2.5e-7 rad): the `w` of `other * self.inv()` is
    /// `self.dot(other)` (its sign is the `cn`), its vector part has the
    /// length of the part of `other` orthogonal to `self`, so the notes'
    /// `phi` is the atan2 of the two, and the result is
    /// `(sin((1 - alpha) phi) self + sin(alpha phi) other) / sin(phi)`.
    /// Rounding errors common to both coefficients only scale the result,
    /// and each endpoint is reached exactly. Like `pow`, this is
    /// scale-free: inputs a little off unit norm still give the rotation
    /// between them. For extrapolation (where the two coefficients grow
    /// and their rounding would show in the norm), and with the `fast-math`
    /// feature (whose sines have absolute, not relative, errors), the notes'
    /// formula itself is evaluated (it rounds `alpha phi`, so its error grows
    /// with the turn).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions, or nearly so (the result has
    /// the norm of `self`, up to rounding). NaN or infinite inputs give
    /// [`Quat::NAN`]. Every finite `alpha` gives a unit result; beyond
    /// 2^125 in magnitude, where an ulp of `alpha phi` is many turns, it is
    /// taken as +-2^125.
    ///
    /// # Accuracy
    ///
    /// Rotation error at most [`accuracy::SLERP_MAX_ANGLE_ERROR`](crate::accuracy::SLERP_MAX_ANGLE_ERROR)
    /// `* max(1, |alpha| theta)` radians against an f64 reference, with
    /// `theta = self.angle_to(other)`; norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1.
    /// Measured on random pairs and on every edge class above
    /// (`tests/differential.rs`). Extrapolating far (outside [-1, 2]) from
    /// inputs less than about 1e-5 rad apart, the error can instead reach
    /// `|alpha| 2^-22` rad, the resolution of their f32 difference.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_z(0.0);
    /// let b = Quat::from_rotation_z(PI / 2.0);
    /// assert!(a.slerp(b, 0.5).angle_to(Quat::from_rotation_z(PI / 4.0)) < 1e-6);
    /// assert_eq!(a.slerp(b, 0.0), a);
    /// // The short way: -b is the same rotation as b.
    /// assert!(a.slerp(-b, 0.5).angle_to(Quat::from_rotation_z(PI / 4.0)) < 1e-6);
    /// ```
    #[must_use]
    pub fn slerp(self, other: Self, alpha: f32) -> Self {
        // Zero times the sum of all inputs is NaN exactly when one of them
        // is NaN or infinite, or when they are so huge that the sum
        // overflows (where the squared norms below would overflow anyway):
        // one test instead of nine, for flash.
        let sum = self.w + self.x + self.y + self.z + other.w + other.x + other.y + other.z;
        if ((sum + alpha) * 0.0).is_nan() {
            return Self::NAN;
        }
        // The w of other * self.inv(); cn flips other when it is negative
        // (multiplying by the sign, exactly, rather than branching on it).
        let dot = self.dot(other);
        let flip = 1.0f32.copysign(dot);
        let other = Self::new(
            other.w * flip,
            other.x * flip,
            other.y * flip,
            other.z * flip,
        );
        let dot = dot * flip;
        // The part of other orthogonal to self, times |self|^2 (exactly
        // orthogonal for any norm of self, in exact arithmetic), scaled by
        // a power of two if its squares would underflow.
        let n2 = self.norm_squared();
        let u = scale_for_squares(other.weighted_sum(n2, self, -dot).to_array());
        if u.sum == 0.0 || alpha == 0.0 {
            // Identical or antipodal (or a zero input): the transition is
            // the identity, and so is its every power. And alpha = 0.
            return self;
        }
        // |u| = |self|^2 |other| sin(phi) and |self| dot = |self|^2 |other|
        // cos(phi), both times u.scale: the notes' phi in [0, pi/2].
        let n = float::sqrt(n2);
        let beta = float::sqrt(u.sum);
        let phi = float::atan2(beta, n * dot * u.scale);
        // Extrapolating (where the two coefficients below would grow and
        // their rounding show in the norm), and with fast-math (whose sines
        // are off by about 1e-3 absolute, too much to divide by a small
        // sin(phi)): the point at angle alpha phi on the circle through self
        // in the direction of u, made orthogonal to self once more (its
        // rounding leaves a component along self of an ulp over |u|, a lot
        // when self and other are nearly the same), then normalized.
        if cfg!(feature = "fast-math") || !(0.0..=1.0).contains(&alpha) {
            let [w, x, y, z] = u.v;
            let dir = Self::new(w, x, y, z);
            let dir = dir.weighted_sum(1.0, self, -dir.dot(self) / n2);
            // When the inputs are one rotation to within ulps, u is mostly
            // rounding along self, and what the projection leaves is
            // rounding too: it may vanish, or be no more orthogonal to self
            // than u was. There is then no direction to turn in, and no turn
            // worth the name (found by the slerp fuzz target: such inputs
            // extrapolated by -4e-18, -2.7e7 and -1.5e21 gave infinities,
            // and norms 1 + 2e-6 and 1.9). Within a few ulps of orthogonal,
            // the norm of the result is off by no more than that.
            let m = float::sqrt(dir.norm_squared());
            // Written to be true for a NaN m too. The negated comparison is
            // 12 bytes smaller on the Cortex-M4F than `m.is_nan() || m < ..`,
            // which slerp's 2 KiB of flash needs (`cargo xtask budget`).
            #[allow(clippy::neg_cmp_op_on_partial_ord)]
            let no_direction = !(m >= MIN_ORTHOGONAL);
            if no_direction {
                return self;
            }
            let dir = Self::new(dir.w / m, dir.x / m, dir.y / m, dir.z / m);
            if dir.dot(self).abs() > ORTHOGONAL_TO_ULPS * n {
                return self;
            }
            // The angle of the part of u orthogonal to self, the part the
            // turn goes along, rather than of all of u, whose rounding alpha
            // would blow up into a turn. Where the two differ, the angle is
            // tiny and atan2 linear: the ratio of the lengths scales it.
            let phi = if phi < SMALL_ANGLE {
                phi * (m / beta)
            } else {
                phi
            };
            // |alpha| <= 2^125 and phi <= pi/2 keep alpha * phi finite.
            // Beyond, an ulp of alpha phi is far more than a turn (any angle
            // is as right as any other), so |alpha| is clamped, on its bits:
            // one comparison of integers, 14 bytes smaller on the Cortex-M4F
            // than the two of floats that `clamp` makes.
            let sign = alpha.to_bits() & float::SIGN;
            let magnitude = (alpha.to_bits() & !float::SIGN).min(ALPHA_LIMIT_BITS);
            let alpha = f32::from_bits(magnitude | sign);
            let (s, c) = float::sin_cos(alpha * phi);
            return self.weighted_sum(c, dir, s * n);
        }
        // alpha phi and (1 - alpha) phi add up to phi exactly where f32
        // allows (Sterbenz), so that the result stays on the arc.
        let far = alpha * phi;
        let near = phi - far;
        let (c0, c1) = if phi > SMALL_ANGLE {
            // near, far and phi lie in [0, pi/2]. The rounding error of
            // 1 / sin(phi) is common to both coefficients: it changes the
            // norm, not the rotation.
            let (s0, s1, sin_phi) = float::sin3(near, far, phi);
            let r = 1.0 / sin_phi;
            (s0 * r, s1 * r)
        } else {
            // sin(x) / sin(phi) is x / phi within 2^-26 here.
            (near / phi, far / phi)
        };
        // For inputs off unit norm, other / |other| * |self| is the endpoint
        // on self's sphere. Within rounding of unit norm the factor is taken
        // as 1: computed, it would be off by as much as it corrects.
        let on2 = other.norm_squared();
        let c1 = if (n2 - on2).abs() > NEARLY_UNIT * on2 {
            c1 * float::sqrt(n2 / on2)
        } else {
            c1
        };
        self.weighted_sum(c0, other, c1)
    }

    /// Normalized linear interpolation: aligns the sign of `other` with
    /// `self` (negating it if `self.dot(other) < 0`, so it goes the short
    /// way), lerps the four components as `(1 - alpha) self + alpha other`,
    /// and normalizes (the notes' "4D lerp and renormalization" hack).
    ///
    /// Cheaper than [`slerp`](Self::slerp), with the same path but not
    /// constant angular velocity (it is faster in the middle). For `alpha`
    /// in [0, 1] the result is written on the side of `self`
    /// (`result.dot(self) >= 0`).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions. The lerp can only vanish
    /// when they are not (or for extreme extrapolation of non-unit inputs);
    /// then, as for NaN or infinite input, the result is [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_y(0.2);
    /// let b = Quat::from_rotation_y(0.6);
    /// assert!(a.nlerp(b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// assert!(a.nlerp(-b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// ```
    #[must_use]
    pub fn nlerp(self, other: Self, alpha: f32) -> Self {
        let other = if self.dot(other) < 0.0 { -other } else { other };
        self.weighted_sum(1.0 - alpha, other, alpha).normalize()
    }

    /// `a self + b other`, component-wise.
    #[inline]
    fn weighted_sum(self, a: f32, other: Self, b: f32) -> Self {
        Self::new(
            a * self.w + b * other.w,
            a * self.x + b * other.x,
            a * self.y + b * other.y,
            a * self.z + b * other.z,
        )
    }

    /// N-way weighted blend: the normalized sum of `weight * q` over the
    /// entries, each `q` first sign-aligned to the first entry's (negated if
    /// its dot product with it is negative). No allocation; the slice may be
    /// of any length. This is the notes' "4D lerp and renormalization",
    /// useful for n-way blends; for two entries with weights `1 - t` and `t`
    /// it equals [`nlerp`](Self::nlerp).
    ///
    /// The result is written on the side of the first entry (`dot >= 0`
    /// with it) when the weights are positive. Weights need not sum to one
    /// (the result is normalized). Mind that
    /// sign alignment to the first entry is only a good choice when all
    /// rotations lie within a quarter turn (pi/2) of it.
    ///
    /// # Preconditions
    ///
    /// Unit quaternions and finite weights. An empty slice, or weights that
    /// cancel to an exactly zero sum, give [`Quat::IDENTITY`] (no rotation
    /// information). A NaN or infinite quaternion or weight gives
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_z(0.3);
    /// let b = Quat::from_rotation_z(0.9);
    /// let blended = Quat::blend(&[(a, 1.0), (-b, 1.0)]); // -b is b
    /// assert!(blended.angle_to(Quat::from_rotation_z(0.6)) < 1e-6);
    /// assert_eq!(Quat::blend(&[]), Quat::IDENTITY);
    /// ```
    #[must_use]
    pub fn blend(entries: &[(Quat, f32)]) -> Self {
        let first = entries.first().map_or(Self::IDENTITY, |&(q, _)| q);
        let mut sum = Self::new(0.0, 0.0, 0.0, 0.0);
        for &(q, weight) in entries {
            let weight = if q.dot(first) < 0.0 { -weight } else { weight };
            sum = sum.weighted_sum(1.0, q, weight);
        }
        // An empty slice, or weights that cancel: no rotation information.
        if sum == Self::new(0.0, 0.0, 0.0, 0.0) {
            return Self::IDENTITY;
        }
        sum.normalize()
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
        Self::new(p.w * s, p.x * s, p.y * s, p.z * s)
    }
}

impl Mul<Quat> for Quat {
    type Output = Quat;

    /// The Hamilton product of the notes' "Operations":
    /// `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`. As rotations, `a * b`
    /// applies `b` first, then `a`.
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
        Quat::new(
            self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        )
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
        let u = self.vector();
        let t = u.cross(v) * 2.0;
        v + t * self.w + u.cross(t)
    }
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
        Quat::new(-self.w, -self.x, -self.y, -self.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::PI;

    #[test]
    fn product_of_axis_rotations_matches_the_notes_formula() {
        // i j = k, j k = i, k i = j (Hamilton).
        let i = Quat::new(0.0, 1.0, 0.0, 0.0);
        let j = Quat::new(0.0, 0.0, 1.0, 0.0);
        let k = Quat::new(0.0, 0.0, 0.0, 1.0);
        assert_eq!(i * j, k);
        assert_eq!(j * k, i);
        assert_eq!(k * i, j);
        assert_eq!(i * i, Quat::new(-1.0, 0.0, 0.0, 0.0));
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
        assert_eq!(Quat::new(1.0, -2.0, 3.0, 0.5).norm_squared(), 14.25);
        assert_eq!(Quat::new(0.0, 3.0, 0.0, 4.0).norm(), 5.0);
    }

    #[test]
    fn blend_and_nlerp_answer_on_the_side_of_their_first_input() {
        let a = Quat::from_rotation_x(0.4);
        let b = -Quat::from_rotation_y(0.9); // w < 0, the far side of a
        assert!(Quat::blend(&[(a, 1.0), (b, 1.0)]).dot(a) > 0.0);
        assert!(Quat::blend(&[(b, 1.0), (a, 3.0)]).dot(b) > 0.0);
        assert!(a.nlerp(b, 0.9).dot(a) > 0.0);
        assert!(b.nlerp(a, 0.9).dot(b) > 0.0);
    }

    #[test]
    fn pow_of_pure_real_negative_turns_about_x() {
        let q = Quat::new(-1.0, 0.0, 0.0, 0.0).pow(0.5);
        assert!((q.w).abs() < 1e-7);
        assert_eq!((q.x, q.y, q.z), (1.0, 0.0, 0.0));
    }

    #[test]
    fn pow_with_huge_alpha_stays_unit_and_matches_the_squaring_identity() {
        let q = Quat::from_rotation_z(1e-30);
        for alpha in [f32::MAX, -f32::MAX, f32::MAX / 3.0] {
            let r = q.pow(alpha);
            assert!(r.is_finite());
            assert!((r.norm() - 1.0).abs() < 1e-5, "{alpha}: {r:?}");
        }
        // Just above the split, pow(alpha) == pow(alpha / 4)^4.
        let alpha = f32::MAX / 3.0;
        let quarter = Quat::from_rotation_z(0.5).pow(alpha * 0.25);
        let fourth = (quarter * quarter) * (quarter * quarter);
        assert!(Quat::from_rotation_z(0.5).pow(alpha).angle_to(fourth) < 1e-5);
    }

    #[test]
    fn to_axis_angle_of_a_half_turn_is_pi() {
        let (axis, angle) = Quat::new(0.0, 0.0, 0.0, -1.0).to_axis_angle();
        assert_eq!(axis, -Cvec3::Z);
        assert_eq!(angle, PI);
    }

    #[test]
    fn blend_of_cancelling_weights_is_identity_and_nan_stays_nan() {
        let q = Quat::from_rotation_x(0.3);
        assert_eq!(Quat::blend(&[(q, 1.0), (q, -1.0)]), Quat::IDENTITY);
        assert!(!Quat::blend(&[(q, 1.0), (q, f32::NAN)]).w.is_finite());
        assert!(!Quat::blend(&[(q, f32::INFINITY)]).w.is_finite());
    }
}
