//! `rigtform`: f32 rotation quaternions and rigid body transforms for
//! microcontroller IMU firmware and for renderers. `#![no_std]`, no heap, no
//! panics, one required dependency (`libm`), and no `unsafe` code but
//! for the processor's square root instruction (on Arm hard-float targets,
//! x86-64 and AArch64) and, on x86-64, the quaternion product in SSE
//! registers and the slice APIs' vector lanes.
//!
//! It implements the quaternion lecture notes of CS175 (Gortler,
//! *Foundations of 3D Computer Graphics*, chapters 7 and 8): [`Quat`] with
//! the power operator `pow` (atan2 and conditional negation `cn`), `slerp`,
//! [`RigTForm`] (translation plus rotation quaternion, with its product,
//! inverse and interpolation) and the few [`Matrix4`]s a renderer still
//! needs (projection, model-view, normal matrix).
//!
//! # Conventions
//!
//! - Quaternions are scalar first: `Quat { w, x, y, z }`, `Quat::new(w, x, y, z)`.
//!   A rotation by `theta` about the unit axis `k` is `[cos(theta/2), sin(theta/2) k]`.
//! - `*` is the Hamilton product (`i j = k`), and `a * b` applies `b`
//!   first, then `a`, as rotation matrices and [`RigTForm`]s do.
//! - `q` and `-q` are the same rotation. Compare rotations with
//!   [`Quat::angle_to`], never component by component.
//! - Right-handed coordinates, right-hand rule for positive angles, angles
//!   in radians.
//! - Column vectors (`m * v`); [`Matrix4`] is stored column-major (OpenGL).
//! - [`Cvec4`] is homogeneous: `w = 1` for a point, `w = 0` for a vector,
//!   which translations leave alone.
//!
//! # Numerics contract
//!
//! 1. No function panics, for any input bits: there is no `unwrap`, no
//!    fallible indexing and no integer arithmetic that can overflow. The
//!    tests call every function on all quaternions made of 24 edge values and
//!    on 100,000 random bit patterns, in debug and release builds
//!    (`tests/edge_cases.rs`); that is testing, not proof.
//! 2. Bad input gets a documented result: NaN out for NaN or infinite in,
//!    `None` for a singular matrix, [`Quat::IDENTITY`] where there is no
//!    rotation to speak of (each method says which).
//! 3. [`Quat::pow`] returns a unit quaternion for every finite non-zero
//!    input (unit or not, subnormal or huge), and [`Quat::slerp`] always
//!    takes the short way, with finite unit results for identical, nearly
//!    identical, antipodal and opposite inputs.
//! 4. Products and slerps of unit quaternions stay unit within
//!    [`accuracy::UNIT_NORM_ERROR`]; [`Quat::normalize`] removes drift.
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
//! | (default) | f32 atan2, sine and cosine kernels, each within 1 to 1.6 ulp (no f64 arithmetic, so no soft-float code on a Cortex-M4F); on x86-64 and AArch64 only, where f64 costs what f32 does, slerp's angle and sines in f64 (one polynomial each, below a tenth of an f32 ulp but the angle's square root); the processor's square root instruction on Arm hard-float targets, x86-64 and AArch64; libm for the rest |
//! | `fast-math` | `micromath`'s atan2, sine, cosine and tangent where they hold (the default sine and cosine kernel beyond 2^9 rad): far less accurate (see [`accuracy`]). On the Cortex-M4F a few percent faster where atan2 or the sines dominate (slerp 354 instructions instead of 357, `Smoother::update` 327 instead of 375), but not smaller: a firmware with the filter, slerp and `RigTForm` takes 12,828 bytes of flash instead of 12,700, and on the Cortex-M0 14,588 instead of 13,672 |
//! | `defmt` | `defmt::Format` for every public type, for logging on target |
//! | `mint` | `From` conversions to and from `mint` types (interop with glam, nalgebra, cgmath), and `mint::IntoMint` |
//! | `serde` | `Serialize` and `Deserialize` for every public type, the attitude filter's state included |
//! | `bytemuck` | `Pod` and `Zeroable` for the vectors, `Quat`, `RigTForm`, `Matrix4`, `Smoother`, `FilterParams`, `InertialCalibration` and `MagneticCalibration` (GPU uploads, wire formats) |
//! | `approx` | `AbsDiffEq`, `RelativeEq` and `UlpsEq`, component by component (compare rotations with [`Quat::angle_to`]) |
//!
//! The library never needs `std`. It builds with Rust 1.84 or newer, with
//! every feature (`rust-version`, checked in CI).

#![cfg_attr(not(test), no_std)]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![deny(missing_docs)]
// No unsafe code, except the square root instruction in src/float/sqrt.rs:
// `vsqrt.f32` (`fpu_sqrt`) on Arm hard-float targets, `sqrtss` and `fsqrt`
// (`vector_unit_sqrt`) on x86-64 with SSE and AArch64 with NEON; and on
// x86-64 with SSE the quaternion product in SSE registers
// (`product::by_lanes` in src/quat/product.rs) and the slice APIs' vector
// lanes (the `Isa` implementations of src/quat/slerp_slice/sse2.rs and,
// with AVX, avx.rs: one intrinsic per operation; and `lerp_rig_tforms` in
// src/quat/slerp_slice/steps.rs, which sees RigTForms as f32s). There the
// lint is `deny` and those items allow it; elsewhere it is `forbid`.
// With the `bytemuck` feature, bytemuck's derive macros write `unsafe impl
// Pod` and `Zeroable` for the plain-f32 types after checking them (`repr(C)`,
// no padding, `Pod` fields); the lint does not fire on that generated code
// (src/features/impl_bytemuck.rs).
#![cfg_attr(
    not(any(
        all(target_arch = "arm", target_abi = "eabihf"),
        all(target_arch = "x86_64", target_feature = "sse"),
        all(target_arch = "aarch64", target_feature = "neon")
    )),
    forbid(unsafe_code)
)]
#![cfg_attr(
    any(
        all(target_arch = "arm", target_abi = "eabihf"),
        all(target_arch = "x86_64", target_feature = "sse"),
        all(target_arch = "aarch64", target_feature = "neon")
    ),
    deny(unsafe_code)
)]

pub mod accuracy;
pub mod attitude;
mod display;
mod features;
mod float;
mod matrix;
mod quat;
mod rigtform;
mod vec;

/// The float kernels that every transcendental call goes through,
/// re-exported only under Kani (`cfg(kani)`), so that the proof harnesses
/// of `rigtform-proofs` can replace them by their contracts, and with the
/// `kernel-contracts` feature, so that its tests can check that the
/// kernels meet those contracts. Not part of the API: ordinary builds do
/// not have this module.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[doc(hidden)]
pub mod kani_kernels {
    pub use crate::float::{atan2, sin_cos, sqrt};
    /// slerp's f64 angle and sine, which `proofs/gappa/angle_f64.g`,
    /// `angle_f64_above.g` and `sin_f64.g` model.
    #[cfg(all(
        any(target_arch = "x86_64", target_arch = "aarch64"),
        not(feature = "fast-math")
    ))]
    pub use crate::float::{atan2_of_root, sin_to_quarter_turn};
}

pub use matrix::Matrix4;
pub use quat::{EulerRot, Quat};
pub use rigtform::RigTForm;
pub use vec::{Cvec3, Cvec4};

/// The README's Rust example, compiled and run as a doc test.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
