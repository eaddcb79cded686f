//! `rigtform`: f32 rotation quaternions and rigid body transforms for
//! microcontroller IMU firmware and for renderers. `#![no_std]`, no heap, no
//! panics, one required dependency (`libm`), and no `unsafe` code but
//! for the processor's square root instruction (on Arm hard-float targets,
//! x86-64 and AArch64) and, on x86-64, the quaternion product and slerp's
//! f64 evaluation in SSE registers and the slice APIs' vector lanes.
//!
//! It implements the quaternion lecture notes of CS175 (Gortler,
//! *Foundations of 3D Computer Graphics*, chapters 7 and 8): [`Quat`] with
//! the power operator `pow` (atan2 and conditional negation `cn`), `slerp`,
//! [`RigTForm`] (translation plus rotation quaternion, with its product,
//! inverse and interpolation) and the few [`Matrix4`]s a renderer still
//! needs (projection, model-view, normal matrix), and the IMU attitude
//! filter of [`attitude`].
//!
//! - Firmware authors (Cortex-M4F, Cortex-M0): f32 only, no allocation, a
//!   documented result for every input bit pattern, `defmt` formatting;
//!   `thumbv7em-none-eabihf` and `thumbv6m-none-eabi` build in CI.
//! - Renderer authors: object and eye frames as [`RigTForm`]s, keyframe
//!   interpolation that is left invariant and takes the short way, and
//!   OpenGL matrices ([`Matrix4::to_cols_array`] goes straight to
//!   `glUniformMatrix4fv`).
//!
//! For renderers that play glTF 2.0 animations, [`animation`] has the
//! format's keyframe samplers (STEP, LINEAR through slerp, CUBICSPLINE) over
//! key times and rotation or translation and scale values.
//!
//! # Conventions
//!
//! - The notes write quaternions scalar first, `[w, c]`: a rotation by
//!   `theta` about the unit axis `k` is `[cos(theta/2), sin(theta/2) k]`. In
//!   memory, arrays, tuples and casts a [`Quat`] is `x, y, z, w`, as glam,
//!   nalgebra's storage, mint, glTF and shaders keep it. The constructors say
//!   their order: [`Quat::from_xyzw`] and [`Quat::from_wxyz`];
//!   [`Quat::to_array`] is `[x, y, z, w]` and [`Quat::to_wxyz`] the notes'
//!   order.
//! - `*` is the Hamilton product (`i j = k`), and `a * b` applies `b`
//!   first, then `a`, for [`Quat`], [`RigTForm`] and [`Matrix4`] alike.
//! - `q` and `-q` are the same rotation. Compare rotations with
//!   [`Quat::angle_to`], never component by component.
//! - Right-handed coordinates, right-hand rule for positive angles, angles
//!   in radians.
//! - Column vectors (`m * v`); [`Matrix4`] is stored column-major (OpenGL),
//!   and so are its arrays.
//! - [`Cvec4`] is homogeneous: `w = 1` for a point, `w = 0` for a vector,
//!   which translations leave alone (`RigTForm * Cvec4` does not translate a
//!   vector).
//! - [`Matrix4::perspective`]`(fovy, aspect, near, far)` takes positive
//!   distances and maps `z = -near` to NDC -1 and `z = -far` to +1, as
//!   `gluPerspective`.
//! - Euler angles ([`EulerRot`]) are intrinsic, first axis first, with
//!   glam's names: `EulerRot::ZYX` is yaw, pitch, roll.
//!
//! # The notes' words
//!
//! The docs and tests use the vocabulary of the CS175 notes, one sentence
//! each:
//!
//! - **[`Cvec3`], [`Cvec4`]**: coordinate vectors; a `Cvec4` with `w = 1` is
//!   a point and with `w = 0` a direction.
//! - **[`RigTForm`] `{ t, r }`**: a rigid body transform (rotation, then
//!   translation), kept as a translation `t` and a unit quaternion `r`
//!   rather than a matrix.
//! - **`inv`**: the inverse; for a unit quaternion, its conjugate (glam's
//!   `inverse`, nalgebra's `conjugate`).
//! - **`cn`** (conditional negation): `-q` when `w < 0`, else `q`: the same
//!   rotation written so that its angle is at most 180 degrees.
//! - **`pow`** (the power operator): `q^alpha`, the rotation about the same
//!   axis by `alpha` times the angle.
//! - **slerp**: spherical linear interpolation, `(cn(b a^-1))^alpha a`,
//!   turning at constant angular velocity the short way from `a` to `b`.
//! - **lerp, nlerp**: linear interpolation; nlerp is lerp followed by
//!   normalization (cheaper than slerp, but not at constant speed).
//! - **bad idea 1, bad idea 2**: the notes' two wrong ways to interpolate
//!   keyframes: lerping the 4x4 matrices (the body shears and shrinks) and
//!   lerping Euler angles (a path that depends on the axes).
//! - **left invariance**: interpolating `g a` and `g b` gives `g` times the
//!   interpolation of `a` and `b`, so the motion does not depend on where
//!   the world frame is. **Right invariance**, the same with `g` on the
//!   right, does not hold for `RigTForm` interpolation (the object's origin
//!   is special).
//! - **eye frame, object frame (`eyeRbt`, `objRbt`)**: the `RigTForm`s that
//!   place the camera and an object in the world; the model-view matrix
//!   (**MVM**) is `eyeRbt^-1 objRbt`, and the normal matrix (**NMVM**) its
//!   inverse transpose, which keeps normals perpendicular.
//! - **NDC**: normalized device coordinates, the cube [-1, 1]^3 a
//!   projection maps the view into.
//! - **ulp** (unit in the last place): the gap between an `f32` and the next
//!   one; an error of 1 ulp is the best an `f32` result can promise.
//! - **unit norm**: a quaternion of length 1, the only kind that is a
//!   rotation; rounding makes products drift off it by a few ulps.
//! - **6D, 9D**: an attitude filter fed a gyroscope and an accelerometer (6
//!   axes), or a magnetometer too (9).
//! - **BROAD, TAGP, RMSE**: the Berlin Robust Orientation Estimation
//!   Assessment Dataset of IMU recordings with optical ground truth; its name
//!   for a filter's one parameter set that is best over all its trials; the
//!   root mean square of the orientation error over a recording.
//! - **Kani**: a model checker for Rust; the harnesses of `rigtform-proofs`
//!   are written for it (and have not been run through it: they run as
//!   random tests). Under `cfg(kani)` the crate reads as Kani needs it (no
//!   intrinsic, no inline assembly), implements `kani::Arbitrary` for
//!   `Quat` (unit), `Cvec3` and `RigTForm`, and puts contracts on its core
//!   operations, for firmware that runs `cargo kani` on its own code
//!   (`docs/kani.md` in the repository).
//!
//! # Numerics contract
//!
//! 1. No function panics, for any input bits, in any build profile: there is
//!    no `unwrap`, no fallible indexing and no integer arithmetic that can
//!    overflow. The tests call every function on all 331,776 quaternions
//!    made of 24 edge values (zeros, subnormals, +-1, 1 +- ulp, 1e30,
//!    `f32::MAX`, infinities, NaN) and on 100,000 random bit patterns, in
//!    debug and release builds (`tests/edge_cases.rs`); that is testing, not
//!    proof.
//! 2. Bad input gets a documented result: NaN out for NaN or infinite in,
//!    `None` from [`Matrix4::inverse`] and [`Matrix4::normal_matrix`] for a
//!    singular matrix, [`Quat::IDENTITY`] where there is no rotation to speak
//!    of (zero axis, empty blend). Each method says which.
//! 3. [`Quat::pow`] returns a unit quaternion for every finite non-zero
//!    input (unit or not, subnormal or with components up to `f32::MAX`,
//!    `w = -1` exactly) and every finite exponent; [`Quat::slerp`] always
//!    takes the short way, is exact at `alpha = 0`, and gives finite unit
//!    results for identical, 1e-6 rad apart, antipodal and opposite inputs.
//! 4. Products and slerps of unit quaternions stay unit within
//!    [`accuracy::UNIT_NORM_ERROR`]; [`Quat::normalize`] (exactly rescaled,
//!    from subnormal to `f32::MAX`) removes drift. Rounding still
//!    accumulates: 100,000 chained products drifted by 2.550e-3 in
//!    `tests/edge_cases.rs`, so long-running integrators renormalize now and
//!    then, or chain [`Quat::mul_renormalized`], whose norm stays within
//!    [`accuracy::RENORMALIZED_CHAIN_NORM_ERROR`] of 1 over chains of
//!    every length (proven for one step from near-unit inputs).
//! 5. Every accuracy figure in these docs is a constant of [`accuracy`],
//!    which the tests assert against an f64 reference.
//!
//! # Example
//!
//! ```
//! use core::f32::consts::PI;
//! use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};
//!
//! // Two keyframes of an object, and the frame halfway between them.
//! let a = RigTForm::new(Cvec3::new(0.0, 0.0, 0.0), Quat::IDENTITY);
//! let b = RigTForm::new(Cvec3::new(4.0, 0.0, 0.0), Quat::from_rotation_y(PI / 2.0));
//! let mid = a.interpolate(b, 0.5);
//! assert_eq!(mid.t, Cvec3::new(2.0, 0.0, 0.0));
//! assert!(mid.r.angle_to(Quat::from_rotation_y(PI / 4.0)) < 1e-6);
//!
//! // Points move with the frame; vectors only turn.
//! let p = mid * Cvec4::from_point(Cvec3::Z);
//! let v = mid * Cvec4::from_vector(Cvec3::Z);
//! assert!((p.xyz() - v.xyz() - mid.t).norm() < 1e-6);
//!
//! // The renderer's model-view matrix, from eye and object frames.
//! let eye = RigTForm::from_translation(Cvec3::new(0.0, 1.0, 8.0));
//! let mvm = Matrix4::from(eye.inv() * mid);
//! let nmvm = mvm.normal_matrix().expect("a rigid motion is invertible");
//! assert!((nmvm.cols[0] - mvm.cols[0]).norm() < 1e-6); // rotation only
//! ```
//!
//! # Features
//!
//! | feature | what it adds |
//! | --- | --- |
//! | (default) | f32 atan2, sine and cosine kernels, each within 1 to 1.6 ulp (no f64 arithmetic, so no soft-float code on a Cortex-M4F); on x86-64 and AArch64 only, where f64 costs what f32 does, slerp's arc and coefficients in f64 (one polynomial each, the coefficients proven within 4.09e-8 before their rounding to f32); the processor's square root instruction on Arm hard-float targets, x86-64 and AArch64; libm for the rest |
//! | `defmt` | `defmt::Format` for every public type, for logging on target |
//! | `mint` | `From` conversions to and from `mint` types (interop with glam, nalgebra, cgmath through `mint`), and `mint::IntoMint` for generic code |
//! | `serde` | `Serialize` and `Deserialize` for every public type, as structs with the Rust field names (a `Quat` is `{x, y, z, w}`); the attitude filter with its whole state, so that a learned gyro bias can be saved and restored |
//! | `bytemuck` | `Pod` and `Zeroable` for the vectors, `Quat`, `RigTForm`, `Matrix4`, `Smoother`, `FilterParams`, `InertialCalibration` and `MagneticCalibration`: slices cast to bytes without a copy (GPU uploads, wire formats), each type its `f32`s in field order (`Quat` `x, y, z, w`; `Matrix4` column-major). bytemuck's derive writes the `unsafe impl`s after checking `repr(C)`, no padding and `Pod` fields |
//! | `approx` | `AbsDiffEq`, `RelativeEq` and `UlpsEq` for the vectors, `Quat`, `RigTForm` and `Matrix4`, component by component with `f32`'s defaults, as glam does (`q` and `-q` are one rotation but never component-wise equal: compare rotations with [`Quat::angle_to`]) |
//! | `convert-glam030` | `From` both ways, exact, between the vectors, `Quat`, `Matrix3`, `Matrix4` and glam 0.30's types (the glam of Bevy 0.17 and 0.18), `RigTForm` to `Affine3A` and back with `TryFrom` (rigid maps only); Rust 1.84 |
//! | `convert-glam032` | the same with glam 0.32 (Bevy 0.19); Rust 1.84 |
//! | `convert-glam033` | the same with glam 0.33 (Bevy 0.20); Rust 1.84 |
//! | `convert-glam034`, or `glam` | the same with glam 0.34; Rust 1.85 (glam 0.34's). `glam` is its first name and stays |
//! | `nalgebra` | `From` both ways with nalgebra 0.35's types, `RigTForm` to and from `Isometry3`; Rust 1.89 (nalgebra 0.35's) |
//!
//! There is no fast-math backend. micromath's approximations of atan2,
//! sine, cosine and tangent, measured in their place on the emulated
//! Cortex-M4F (`cargo xtask m4f`), saved at most 1 % of the instructions of
//! any operation but `Smoother::update` (327 against 375), cost more of
//! some (`catmull_rom` 2,805 against 2,689) and added flash to every
//! operation that used them (`pow` 2,224 bytes against 1,836); a firmware
//! with the filter, slerp and `RigTForm` took 12,828 bytes against 12,656
//! on the Cortex-M4F and 14,552 against 13,640 on the Cortex-M0, and the
//! kernels were four orders of magnitude less accurate. micromath stays a
//! measured peer on the performance page.
//!
//! The library never needs `std`. It builds with Rust 1.84 or newer, with
//! every feature but `convert-glam034` (alias `glam`: Rust 1.85, glam
//! 0.34's) and `nalgebra` (Rust 1.89, nalgebra 0.35's) (`rust-version`,
//! checked in CI, as are those two).

#![cfg_attr(not(test), no_std)]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![deny(missing_docs)]
// No unsafe code, except the square root instruction in src/float/sqrt.rs:
// `vsqrt.f32` (`fpu_sqrt`) on Arm hard-float targets, `sqrtss` and `fsqrt`
// (`vector_unit_sqrt`) on x86-64 with SSE and AArch64 with NEON; and on
// x86-64 with SSE the quaternion product in SSE registers
// (src/quat/sse2.rs: the Hamilton product and nlerp), the registers of slerp's f64
// evaluation (src/quat/slerp/lanes/: sse2.rs and sse2/steps.rs, and with
// AVX avx.rs: one intrinsic per operation) and `lerp_all_components` in
// src/rigtform/slice.rs, which sees RigTForms as f32s. There the
// lint is `deny` and those items allow it; elsewhere it is `forbid`.
// With the `bytemuck` feature, bytemuck's derive macros write `unsafe impl
// Pod` and `Zeroable` for the plain-f32 types after checking them (`repr(C)`,
// no padding, `Pod` fields); the lint does not fire on that generated code
// (src/features/impl_bytemuck.rs).
#![cfg_attr(not(any(arm_fpu_sqrt, vector_unit_sqrt)), forbid(unsafe_code))]
#![cfg_attr(any(arm_fpu_sqrt, vector_unit_sqrt), deny(unsafe_code))]

pub mod accuracy;
pub mod animation;
pub mod attitude;
mod constructors;
mod display;
mod features;
mod float;
mod matrix;
mod other_names;
mod quat;
mod rigtform;
#[cfg(test)]
mod test_draws;
mod vec;

/// The float kernels that every transcendental call goes through,
/// re-exported only under Kani (`cfg(kani)`), so that the proof harnesses
/// of `rigtform-proofs` can replace them by their contracts, and with the
/// `kernel-contracts` feature, so that its tests can check that the
/// kernels meet those contracts. Not part of the API: ordinary builds do
/// not have this module.
#[cfg(kernels_exported)]
#[doc(hidden)]
pub mod kani_kernels {
    /// What Kani's square root assumes of its result (`float/sqrt_kani.rs`).
    #[cfg(feature = "kernel-contracts")]
    pub use crate::float::is_correctly_rounded_sqrt;
    pub use crate::float::{atan2, sin_cos, sqrt};
    /// slerp's f32 evaluation, on every target.
    pub use crate::quat::slerp_in_f32;
    /// slerp's f64 pair, arc, `sin(x) / x` and coefficients, which
    /// `proofs/gappa/slerp_angle_f64.g`, `arc_f64.g`, `sinc_f64.g`,
    /// `coefficient_f64.g` and `coefficient_rest_f64.g` model.
    #[cfg(desktop64)]
    pub use crate::quat::{slerp_arc, slerp_coefficients, slerp_pair, slerp_sinc};
}

/// The conditions of the contracts on the core operations, under Kani and
/// with the `kernel-contracts` feature, for `rigtform-proofs`' check of
/// them. Not part of the API.
#[cfg(kernels_exported)]
#[doc(hidden)]
pub mod kani_contracts;

// glam's free constructors, deprecated: a user's import of one warns.
#[allow(deprecated)]
pub use constructors::{mat3, mat4, quat, vec3, vec4};
pub use matrix::{Matrix3, Matrix4, NotRigid};
pub use quat::{EulerRot, Quat};
pub use rigtform::RigTForm;
pub use vec::{Cvec3, Cvec4};

/// The README's Rust example, compiled and run as a doc test.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
