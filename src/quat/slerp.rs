//! [`Quat::slerp`], the notes' "to interpolate", and everything that
//! evaluates it, read top-down:
//!
//! - this file: `slerp` itself, which picks the evaluation for the target;
//! - `slerp/in_f64.rs` (x86-64, AArch64): the in-plane formula in f64 for
//!   the ordinary pairs, with its two polynomials, written once for every
//!   register it runs in: the single call's, and the slices' many pairs;
//! - `slerp/lanes.rs`: those registers, one set of signatures, the backend
//!   chosen at its module declaration (`lanes/sse2.rs`, `lanes/avx.rs`,
//!   `lanes/portable.rs`);
//! - `slerp/in_f32.rs`: the whole of slerp in f32 (every input, every
//!   `alpha`), on every other target, and on x86-64 and AArch64 for what
//!   the f64 evaluation leaves;
//! - `slerp/slice.rs`: [`Quat::slerp_slice`] and the slerp of many
//!   `RigTForm`s' rotations: `slice/steps.rs` on x86-64, `slice/blocks.rs`
//!   in blocks the compiler vectorizes.

use super::Quat;

mod in_f32;
#[cfg(kernels_exported)]
pub use in_f32::slerp_in_f32;
#[cfg(desktop64)]
pub(super) mod in_f64;
#[cfg(desktop64)]
mod lanes;
pub(super) mod slice;

/// How far the ratio of two squared norms may be from 1 for slerp to treat
/// the inputs as unit: well above the rounding of f32 unit quaternions
/// (a few 1e-7), well below any real drift.
pub(super) const NEARLY_UNIT: f32 = 1e-6;
/// 2^-12 rad: below this, `sin(x) / sin(phi)` is `x / phi` to f32's
/// precision (the two differ by less than `phi^2 / 6`, 2^-26).
pub(super) const SMALL_ANGLE: f32 = 1.0 / 4096.0;

/// A value that holds a rotation, as the slices read and write it: a
/// [`Quat`], or a `RigTForm`'s `r`.
pub(crate) trait WithRotation: Copy {
    /// The rotation.
    fn rotation(&self) -> &Quat;
    /// The rotation, to be written.
    fn rotation_mut(&mut self) -> &mut Quat;
}

impl WithRotation for Quat {
    #[inline(always)]
    fn rotation(&self) -> &Quat {
        self
    }
    #[inline(always)]
    fn rotation_mut(&mut self) -> &mut Quat {
        self
    }
}

impl Quat {
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
    /// and each endpoint is reached exactly (`slerp_in_plane`). Like `pow`,
    /// this is scale-free: inputs a little off unit norm still give the
    /// rotation between them. On x86-64 and AArch64, where an f64
    /// operation costs what an f32 one does, `alpha` in (0, 1] takes the
    /// same formula in f64 (`quat/slerp/in_f64.rs`), with `phi^2` and
    /// `phi / sin(phi)` from the tangent of the half angle (the shorter of
    /// `self - other` and `self + other` over the longer, squared, from
    /// the norms and the dot product in f64, where every product of the f32
    /// components is exact) and each coefficient
    /// `sin(s phi) / sin(phi)` as `s phi / sin(phi)` times a polynomial in
    /// `(s phi)^2`: one division, no square root, no branch that random
    /// inputs mispredict, and coefficients rounded to f32 once; inputs it
    /// does not take (norms more than 1e-6 apart, components beyond 2^16,
    /// angles of 2^-12 rad or less, pairs at a right angle to f64's
    /// precision) go the way described here. For
    /// extrapolation (where the two coefficients
    /// grow and their rounding would show in the norm) the notes' formula itself is evaluated as a turn by
    /// `alpha phi` from `self` (`slerp_extrapolated`; it rounds `alpha phi`,
    /// so its error grows with the turn).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions, or nearly so (the result has
    /// the norm of `self`, up to rounding). NaN or infinite inputs give
    /// [`Quat::NAN`], as do inputs whose squared norms overflow
    /// (components of order 1e19 and beyond). Every finite `alpha` gives a
    /// unit result; beyond
    /// 2^125 in magnitude, where an ulp of `alpha phi` is many turns, it is
    /// taken as +-2^125.
    ///
    /// # Accuracy
    ///
    /// Rotation error at most [`accuracy::SLERP_MAX_ANGLE_ERROR`](crate::accuracy::SLERP_MAX_ANGLE_ERROR)
    /// `* max(1, |alpha| theta)` radians against an f64 reference, with
    /// `theta = self.angle_to(other)`; norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of
    /// the norm of `self`, relative: `| |r| / |self| - 1 |`, for every
    /// finite `alpha` (a unit `self` of f32 is 1 only up to its own
    /// rounding, which the result keeps: 2.6e-7 relative but 3.0e-7 from 1
    /// at worst in 200,000 pairs one ulp apart extrapolated by up to
    /// `f32::MAX`, `far_extrapolation_of_nearby_inputs_keeps_the_norm_of_self`).
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
    // Inlined across crates on 64-bit desktop targets, where the call
    // costs as much as a share of the work; one out-of-line copy elsewhere
    // (flash on a Cortex-M4F).
    #[cfg_attr(desktop64, inline)]
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::slerp_requires(self, other, alpha))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &Quat| crate::kani_contracts::slerp_ensures(self, alpha, *r)))]
    #[must_use]
    pub fn slerp(self, other: Self, alpha: f32) -> Self {
        #[cfg(desktop64)]
        {
            if let Some(q) = self.slerp_f64(other, alpha) {
                return q;
            }
            slerp_f32_in_registers(self, other, alpha)
        }
        #[cfg(not(desktop64))]
        self.slerp_f32(other, alpha)
    }
}

/// [`Quat::slerp_f32`] out of line, for the inputs the f64 evaluation
/// leaves, on x86-64 and AArch64.
///
/// Out of line, so that the inlined `slerp` is that evaluation and one
/// call: with the rare cases' code inlined too, `slerp` is too large for
/// the compiler to inline into `RigTForm::interpolate` and callers' loops,
/// which then pay for a call every time. Through the C calling convention,
/// which passes the two quaternions and returns the result in registers:
/// the Rust one passes them through memory, so that every `slerp` stores
/// its inputs on the stack and loads them back on its critical path, in
/// case this call comes (31.0 against 29.5 ns per call on x86-64). Chains
/// of dependent slerps pay a little for the registers instead (about 5 %
/// in `catmull_rom`).
#[cfg(desktop64)]
#[inline(never)]
extern "C" fn slerp_f32_in_registers(a: Quat, b: Quat, alpha: f32) -> Quat {
    a.slerp_f32(b, alpha)
}
