//! The measured accuracy bounds of the crate, in one place.
//!
//! Every bound a doc comment quotes is one of these constants, and the tests
//! that measure it (`tests/differential.rs` against an f64 reference,
//! `tests/edge_cases.rs`, and the kernel sweeps in `src/float.rs`) assert
//! against the same constant, so the docs cannot promise a tolerance the
//! tests do not check. Each value is the largest error measured over the
//! test's inputs, rounded up by about a quarter (the measured maxima are in
//! comments beside the values).
//!
//! Angles are radians; "angle error" is the angle of the rotation between the
//! computed and the exact result (compared up to sign, as rotations).
//!
//! With the `fast-math` feature, micromath's approximations are far less
//! accurate; the constants then take the values measured for that backend
//! (run `cargo test --features fast-math -- --nocapture` to see them).

#[cfg(not(feature = "fast-math"))]
mod values {
    // Measured (cargo test -- --nocapture), then rounded up by about 25 %:
    pub const SQRT_MAX_REL_ERROR: f32 = 6.0e-8; // 5.960e-8 (correctly rounded)
    pub const ATAN2_MAX_ABS_ERROR: f32 = 2.5e-7; // 2.395e-7 (1 ulp of pi)
    pub const SIN_COS_MAX_ABS_ERROR: f32 = 6.0e-8; // 2.985e-8
    pub const TAN_MAX_REL_ERROR: f32 = 1.2e-7; // 7.609e-8
    pub const NORMALIZE_MAX_NORM_ERROR: f32 = 2.0e-7; // 1.427e-7
    pub const UNIT_NORM_ERROR: f32 = 2.5e-7; // 1.966e-7 (slerp)
    pub const MUL_MAX_ANGLE_ERROR: f32 = 3.0e-7; // 2.374e-7
    pub const ROTATE_MAX_REL_ERROR: f32 = 5.0e-7; // 4.166e-7
    pub const POW_MAX_ANGLE_ERROR: f32 = 2.5e-7; // 1.936e-7 (pow), 2.269e-7 (to_axis_angle)
    pub const SLERP_MAX_ANGLE_ERROR: f32 = 4.0e-7; // 3.209e-7 (pi apart)
    pub const MATRIX_ENTRY_ERROR: f32 = 3.5e-7; // 2.683e-7
}

#[cfg(feature = "fast-math")]
mod values {
    pub const SQRT_MAX_REL_ERROR: f32 = 1.0e-3;
    pub const ATAN2_MAX_ABS_ERROR: f32 = 5.0e-3;
    pub const SIN_COS_MAX_ABS_ERROR: f32 = 5.0e-3;
    pub const TAN_MAX_REL_ERROR: f32 = 5.0e-2;
    pub const NORMALIZE_MAX_NORM_ERROR: f32 = 2.0e-3;
    pub const UNIT_NORM_ERROR: f32 = 1.0e-2;
    pub const MUL_MAX_ANGLE_ERROR: f32 = 5.0e-7;
    pub const ROTATE_MAX_REL_ERROR: f32 = 5.0e-7;
    pub const POW_MAX_ANGLE_ERROR: f32 = 1.0e-2;
    pub const SLERP_MAX_ANGLE_ERROR: f32 = 1.0e-2;
    pub const MATRIX_ENTRY_ERROR: f32 = 5.0e-7;
}

/// Relative error of the square root kernel (`src/float.rs`, `sweep_sqrt`).
pub const SQRT_MAX_REL_ERROR: f32 = values::SQRT_MAX_REL_ERROR;
/// Absolute error, in radians, of the atan2 kernel (`sweep_atan2`).
pub const ATAN2_MAX_ABS_ERROR: f32 = values::ATAN2_MAX_ABS_ERROR;
/// Absolute error of the sine and cosine kernel on [-10, 10] (`sweep_sin_cos`).
pub const SIN_COS_MAX_ABS_ERROR: f32 = values::SIN_COS_MAX_ABS_ERROR;
/// Relative error of the tangent kernel over half fields of view (`sweep_tan`).
pub const TAN_MAX_REL_ERROR: f32 = values::TAN_MAX_REL_ERROR;
/// `|norm - 1|` after `normalize`, `nlerp` or `blend`, for any finite non-zero
/// input, subnormal to `f32::MAX`.
pub const NORMALIZE_MAX_NORM_ERROR: f32 = values::NORMALIZE_MAX_NORM_ERROR;
/// `|norm - 1|` of the result of `*`, `pow`, `slerp` and `from_axis_angle`
/// on unit inputs (and of `pow` on any finite non-zero input).
pub const UNIT_NORM_ERROR: f32 = values::UNIT_NORM_ERROR;
/// Angle error of the Hamilton product `a * b` of unit quaternions.
pub const MUL_MAX_ANGLE_ERROR: f32 = values::MUL_MAX_ANGLE_ERROR;
/// Error of `q * v` (rotating a vector by a unit quaternion), relative to `|v|`.
pub const ROTATE_MAX_REL_ERROR: f32 = values::ROTATE_MAX_REL_ERROR;
/// Angle error of `q.pow(alpha)` for unit `q`, per radian of the rotation
/// it returns and never less than this many radians: the error is at most
/// `POW_MAX_ANGLE_ERROR * max(1, |alpha| theta)`, with `theta` the angle of
/// `q` (`2 atan2(|v|, w)`, up to 2 pi). It grows with the turn because the
/// f32 product `alpha phi` handed to sin and cos is itself rounded. Also the
/// error of the angle returned by `to_axis_angle` (at most pi).
pub const POW_MAX_ANGLE_ERROR: f32 = values::POW_MAX_ANGLE_ERROR;
/// Angle error of `a.slerp(b, alpha)` for unit inputs, in the same form as
/// [`POW_MAX_ANGLE_ERROR`]: at most `SLERP_MAX_ANGLE_ERROR * max(1, |alpha| theta)`
/// with `theta = a.angle_to(b)` (at most pi). So for `alpha` in [0, 1] it is
/// at most `pi * SLERP_MAX_ANGLE_ERROR`, and at most `SLERP_MAX_ANGLE_ERROR`
/// when the two are less than a radian apart. Measured over random pairs and
/// `alpha` in [-1, 2], and on each edge class: identical, 1e-6 and 1e-3 rad
/// apart, pi - 1e-4 apart, antipodal (`q`, `-q`), exactly pi apart.
pub const SLERP_MAX_ANGLE_ERROR: f32 = values::SLERP_MAX_ANGLE_ERROR;
/// Largest entry difference between `Matrix4::from_quat(q)`, for unit `q`,
/// and the exact rotation matrix of `q`.
pub const MATRIX_ENTRY_ERROR: f32 = values::MATRIX_ENTRY_ERROR;
