//! [`Quat`]: rotation quaternions, as in the notes' sections "the
//! representation" and "Operations". This file holds the type and what
//! defines it as a rotation: the dot product and norms, the inverse `inv`,
//! the conditional negation `cn` and the angle between two rotations; the
//! rest is one file a role or a concept, declared below in the order the
//! documentation lists their methods:
//!
//! - `quat/construction.rs` (from components, axis and angle, a coordinate
//!   axis) and `quat/conversion.rs` (arrays, tuples, `Cvec4`, axis-angle);
//! - `quat/ops.rs`, the core products: the Hamilton product `a * b` and the
//!   rotation of a vector `q * v`;
//! - `quat/power.rs` (the notes' "Power": the polar form and `pow`),
//!   `quat/interpolate.rs` (`nlerp`, `blend`), `quat/slerp.rs` (the notes'
//!   "to interpolate"), `quat/towards.rs` (`slerp_long`,
//!   `rotate_towards`), `quat/exp_log.rs` (the exponential and logarithm
//!   maps, and gyro integration), `quat/euler.rs` (Euler angles),
//!   `quat/from_basis.rs` (the rotation of an orthonormal basis, which
//!   `Quat::from_matrix` in `matrix/quat_conversions.rs` takes from a
//!   matrix), `quat/rotation_arc.rs` (the shortest rotation between two
//!   directions), `quat/catmull_rom.rs` (splines through many keyframes);
//! - `quat/other_names.rs`: glam's and nalgebra's names for these methods;
//! - `quat/vec_rotations.rs`: glam's `Vec3` helpers that turn a vector
//!   (`rotate_x`, `rotate_axis`, `rotate_towards`, `slerp`), methods of
//!   `Cvec3` that take their turns from quaternions.
//!
//! As a 4-vector (sums, scaling, norms), a `Quat` shares the code of the
//! vector types (`vec/template.rs`).

use crate::vec::euclidean;

#[cfg(all(kernels_exported, desktop64))]
pub use slerp::in_f64::{slerp_arc, slerp_coefficients, slerp_pair, slerp_sinc};
#[cfg(kernels_exported)]
pub use slerp::slerp_in_f32;
pub(crate) use slerp::slice::{slerp_slice_by, Slerped};
pub(crate) use slerp::WithRotation;

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
/// `*`; rotate a [`Cvec3`](crate::Cvec3) with `q * v`; interpolate with
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

impl Quat {
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
    /// the norm is within
    /// [`accuracy::RENORMALIZED_CHAIN_NORM_ERROR`](crate::accuracy::RENORMALIZED_CHAIN_NORM_ERROR)
    /// of 1 for inputs whose squared norms are within 2^-20 of 1 (proven),
    /// so a chain of products started within it stays within it for every
    /// length.
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

    /// `a self + b other`, component-wise: the sum under slerp, nlerp and
    /// blend.
    #[inline]
    pub(crate) fn weighted_sum(self, a: f32, other: Self, b: f32) -> Self {
        Self::from_wxyz(
            a * self.w + b * other.w,
            a * self.x + b * other.x,
            a * self.y + b * other.y,
            a * self.z + b * other.z,
        )
    }

    /// `f` of each component: the one place a `Quat`'s components are
    /// scaled one by one.
    #[inline(always)]
    pub(super) fn map(self, f: impl Fn(f32) -> f32) -> Self {
        Self::from_wxyz(f(self.w), f(self.x), f(self.y), f(self.z))
    }
}

euclidean!(Quat { x, y, z, w }, unit IDENTITY, contract(normalize_requires, normalize_ensures));

// The further concepts, in the order the documentation lists their
// methods: construction and conversion first, then the products,
// interpolation, glam's and nalgebra's names last.

mod construction;

mod conversion;

mod ops;

mod power;

mod interpolate;

mod slerp;

mod towards;

mod euler;

mod rotation_arc;

mod from_basis;

mod exp_log;

pub(crate) mod catmull_rom;

mod other_names;

mod vec_rotations;

/// The backend of the evaluations that keep a quaternion's components
/// together (the Hamilton product, `nlerp`): SSE registers on x86-64,
/// plain f32 elsewhere; the same functions in both, with the same bits.
#[cfg(x86_sse_lanes)]
mod sse2;
#[cfg(x86_sse_lanes)]
use sse2 as backend;
#[cfg(any(test, not(x86_sse_lanes)))]
mod scalar;
#[cfg(not(x86_sse_lanes))]
use scalar as backend;

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn norm_squared_is_the_sum_of_the_four_squares() {
        assert_eq!(Quat::from_wxyz(1.0, -2.0, 3.0, 0.5).norm_squared(), 14.25);
        assert_eq!(Quat::from_wxyz(0.0, 3.0, 0.0, 4.0).norm(), 5.0);
    }

    /// Each operator against glam's on the same components, bit for bit:
    /// both are one IEEE 754 operation per component.
    #[test]
    fn operators_agree_with_glam_bit_for_bit() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(26);
        let bits = |q: Quat| q.to_array().map(f32::to_bits);
        let g = |q: Quat| glam::Quat::from_array(q.to_array());
        let r = |q: glam::Quat| Quat::from_array(q.to_array());
        for _ in 0..10_000 {
            let mut draw =
                || Quat::from_array(core::array::from_fn(|_| rng.random_range(-4.0..4.0)));
            let (a, b) = (draw(), draw());
            let s = rng.random_range(-3.0f32..3.0);
            assert_eq!(bits(a + b), bits(r(g(a) + g(b))));
            assert_eq!(bits(a - b), bits(r(g(a) - g(b))));
            assert_eq!(bits(a * s), bits(r(g(a) * s)));
            assert_eq!(bits(s * a), bits(r(g(a) * s)));
            assert_eq!(bits(a / s), bits(r(g(a) / s)));
            let sum: Quat = [a, b, a].iter().sum();
            assert_eq!(bits(sum), bits(r([g(a), g(b), g(a)].iter().sum())));
            let (mut c, mut d) = (a, a);
            c += b;
            d -= b;
            assert_eq!((c, d), (a + b, a - b));
            c *= s;
            d /= s;
            assert_eq!((c, d), ((a + b) * s, (a - b) / s));
        }
    }
}
