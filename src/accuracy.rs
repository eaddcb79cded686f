//! The accuracy bounds of the crate, in one place.
//!
//! Every bound a doc comment quotes is one of these constants, and the tests
//! that measure it (`tests/differential.rs` against an f64 reference,
//! `tests/edge_cases.rs`, `tests/attitude.rs`, `tests/broad.rs`, the
//! smoother's unit test and the kernel sweeps in `src/float/`) assert
//! against the same constant, so the docs cannot promise a tolerance the
//! tests do not check. Unless its doc says otherwise (a fixed chain of
//! products, a recorded trial), each value is the largest error measured over
//! 10,000,000 random draws per operation (2,500,000 per slerp edge class),
//! rounded up by about a quarter; the measured maxima are in comments beside
//! the values. Reproduce with
//! `RIGTFORM_DRAWS=10000000 cargo test --release --test differential -- --nocapture`;
//! CI re-checks every bound on 100,000 draws per operation.
//!
//! How each bound is known, the last line of its doc says:
//!
//! - **proven**: a Gappa model of the code's arithmetic (`proofs/gappa/`,
//!   with Sollya for a polynomial's approximation error) proves it over the
//!   bound's whole domain, Coq checks Gappa's certificate, and a test checks
//!   that the model computes the code's bits (`cargo xtask prove` runs all
//!   three; `docs/verification-proofs.md` describes the models);
//! - **swept**: an exhaustive test tries every f32 of the bound's domain
//!   (for atan2's two arguments, every f32 quotient its branches compute,
//!   which stands for every pair);
//! - **measured**: the largest error over random draws, rounded up. Where a
//!   model proves a looser bound for the same quantity, the doc gives it.
//!
//! Four constants are not error bounds and are counted apart:
//! [`IS_NORMALIZED_TOLERANCE`] and [`RIGID_TOLERANCE`] are **tolerances**
//! (chosen from measured errors), and the two BROAD RMSE figures are
//! **benchmark** figures (the filter on one recording).
//!
//! Angles are radians; "angle error" is the angle of the rotation between the
//! computed and the exact result (compared up to sign, as rotations).
//!
//! | bound | value |
//! | --- | --- |
//! | [`MUL_MAX_ANGLE_ERROR`] | 1.2e-6 |
//! | [`ROTATE_MAX_REL_ERROR`] | 6.5e-7 |
//! | [`MATRIX_ENTRY_ERROR`] | 6.6e-7 |
//! | [`INVERSE_MAX_REL_ERROR`] | 5.4e-7 |
//! | [`NORMALIZE_MAX_NORM_ERROR`] | 2.4e-7 |
//! | [`UNIT_NORM_ERROR`] | 3.5e-7 |
//! | [`POW_MAX_ANGLE_ERROR`] | 3.4e-7 |
//! | [`SLERP_MAX_ANGLE_ERROR`] | 5.2e-7 |
//! | [`ATAN2_MAX_ABS_ERROR`] | 3.2e-7 |
//! | [`SIN_COS_MAX_ABS_ERROR`] | 6.4e-8 |
//! | [`TAN_MAX_REL_ERROR`] | 1.2e-7 |
//! | [`FROM_SCALED_AXIS_MAX_REL_ERROR`] | 3.0e-7 |
//! | [`TO_SCALED_AXIS_MAX_REL_ERROR`] | 3.2e-7 |
//! | [`EXP_LOG_POW_MAX_ANGLE_ERROR`] | 4.5e-7 |
//! | [`INTEGRATE_STEP_MAX_ANGLE_ERROR`] | 4.0e-7 |
//! | [`SMOOTHER_DECAY_MAX_ERROR`] | 1.0e-5 |
//! | [`RENORMALIZED_CHAIN_NORM_ERROR`] | 1.95e-7 |
//! | [`EULER_MAX_ANGLE_ERROR`] | 8.4e-7 |
//! | [`FROM_MATRIX_MAX_ANGLE_ERROR`] | 4.3e-7 |
//! | [`ROTATION_ARC_MAX_ERROR`] | 4.6e-7 |
//! | [`LOOK_AT_MAX_ANGLE_ERROR`] | 1.1e-6 |
//! | [`DETERMINANT_MAX_REL_ERROR`] | 4.8e-7 |
//! | [`CATMULL_ROM_MAX_ANGLE_ERROR`] | 4.8e-7 |
//! | [`SAMPLER_LINEAR_MAX_ANGLE_ERROR`] | 5.6e-7 |
//! | [`SAMPLER_CUBIC_MAX_ANGLE_ERROR`] | 1.0e-6 |
//! | [`SAMPLER_VEC3_MAX_REL_ERROR`] | 2.5e-6 |
//! | [`ANGLE_BETWEEN_MAX_ERROR`] | 4.2e-7 |
//! | [`PROJECT_MAX_REL_ERROR`] | 7.83e-7 |
//! | [`MATRIX3_INVERSE_MAX_REL_ERROR`] | 3.6e-7 |
//! | [`MATRIX3_DETERMINANT_MAX_REL_ERROR`] | 3.0e-7 |
//! | [`LOOK_AT_RH_MAX_TRANSLATION_ERROR`] | 1.1e-6 |
//! | [`SRT_ROTATION_MAX_ANGLE_ERROR`] | 9.0e-7 |
//! | [`SRT_SCALE_MAX_REL_ERROR`] | 9.5e-7 |

/// The bounds that depend on the f32 kernels of `src/float/`: measured
/// maxima over 10^7 draws in the comments, rounded up by about 25 %.
mod backend {
    pub const ATAN2_MAX_ABS_ERROR: f32 = 3.2e-7; // 2.667e-7 (every f32 quotient, near pi; the kernel is within 1.6 ulp); 3.16e-7 proven
    pub const SIN_COS_MAX_ABS_ERROR: f32 = 6.4e-8; // 5.760e-8 at 2.359356 (every f32 of [-10, 10])
    pub const TAN_MAX_REL_ERROR: f32 = 1.2e-7; // 7.745e-8 at 0.12439033 (every f32 of [0.0087, 1.5621])
    pub const UNIT_NORM_ERROR: f32 = 3.5e-7; // 2.572e-7 (slerp, random pairs); 2.6220e-7 (slerp's f32 path in the plane, by search); 1.9720e-7 (a product, relative to |a| |b|, by search; 2.84e-7 proven); 2.4337e-7 (from_axis_angle, by search; 3.483e-7 proven)
    pub const POW_MAX_ANGLE_ERROR: f32 = 3.4e-7; // 2.580e-7 (pow), 2.725e-7 (to_axis_angle), 2.968e-7 (pow, search); 1.03e-6 proven given swept kernels
    pub const SLERP_MAX_ANGLE_ERROR: f32 = 5.2e-7; // 4.106e-7 (random pairs, alpha in [-1, 2])
    pub const FROM_SCALED_AXIS_MAX_REL_ERROR: f32 = 3.0e-7; // 2.426e-7
    pub const TO_SCALED_AXIS_MAX_REL_ERROR: f32 = 3.2e-7; // 2.624e-7 (f32 kernels; 2.495e-7 with libm), 2.612e-7 (search); 6.6912e-7 proven given the swept atan2 kernel
    pub const EXP_LOG_POW_MAX_ANGLE_ERROR: f32 = 4.5e-7; // 3.250e-7 (f32 kernels; 3.612e-7 with libm)
    pub const INTEGRATE_STEP_MAX_ANGLE_ERROR: f32 = 4.0e-7; // 3.206e-7
    pub const SMOOTHER_DECAY_MAX_ERROR: f32 = 1.0e-5; // 7.480e-6 (100 Hz and 1 kHz, 2 s)
    pub const IS_NORMALIZED_TOLERANCE: f32 = 1.0e-4;
    pub const EULER_MAX_ANGLE_ERROR: f32 = 8.4e-7; // 6.794e-7 (to_euler), 3.314e-7 (from_euler), 24 orders
    pub const CATMULL_ROM_MAX_ANGLE_ERROR: f32 = 4.8e-7; // 3.849e-7 (5 keys, t over all of them)
    pub const SAMPLER_LINEAR_MAX_ANGLE_ERROR: f32 = 5.6e-7; // 4.432e-7 (4,000,000 samples)
    pub const ANGLE_BETWEEN_MAX_ERROR: f32 = 4.2e-7; // 3.333e-7
}

/// Relative error of the square root kernel (`src/float/sqrt.rs`, `sweep_sqrt`).
///
/// Known: proven: `proofs/gappa/sqrt.g` proves 2^-24 (5.9605e-8) for every
/// positive f32, given a correctly rounded square root (IEEE 754's, which every
/// backend's instruction or `sqrtf` is).
pub const SQRT_MAX_REL_ERROR: f32 = 5.97e-8; // 5.960e-8 measured, 2^-24 = 5.9605e-8 proven

// The default backend's f32 kernels (`src/float/`), in ulps of the exact
// result. Each bound is the largest error over every f32 of the kernel's
// range (`cargo test --release --lib -- --ignored exhaustive_kernel_sweep`;
// the maximum and where it occurs in the comment), rounded up; every test
// run checks every 997th f32 against the same bound.

/// The atan2 kernel, in ulps, for every pair of finite arguments.
///
/// Known: swept: every f32 quotient `u` of each of the kernel's three
/// branches (`quotient_sweep` in `src/float/atan2.rs`, which
/// `exhaustive_kernel_sweep` runs; every test run takes every 997th): the
/// result depends on the arguments only through the branch, `u` and the
/// signs, and the sweep takes the exact angle anywhere in the interval of
/// ratios that compute to `u`, so it bounds every pair. The families
/// `(t, +-1)`, `(1, +-t)` and `(1 + t, 1)` reach 1.291 at t = 0.54892975.
pub const ATAN2_MAX_ULP: f32 = 1.6; // 1.597 at u = 0.5049959 (every quotient, the exact ratio anywhere it rounds from)
/// The arctangent polynomial inside the atan2 kernel, in ulps, on
/// [0, tan(1/2)].
///
/// Known: swept: every f32 of [0, tan(1/2)] (`exhaustive_kernel_sweep`). Not
/// proven in ulps: that needs the result's binade, which a Gappa model would
/// split by. Relative to atan(u), Gappa (certificates checked by coqc) proves
/// 8.8e-8 for every f32 u from 2^-149 to the f32 above tan(1/2) (`atan_poly.g`,
/// `atan_poly_tiny.g`, with Sollya's bound of the approximation error,
/// `atan_poly.sollya`); negative u by symmetry, u = 0 exact. The largest
/// over every f32 of [0, tan(1/2)] is 6.3852e-8 (`worst_cases.rs`). The
/// proof of [`ATAN2_MAX_ABS_ERROR`] takes that relative bound.
pub const ATAN_POLY_MAX_ULP: f32 = 1.0; // 0.821 at 0.5461395
/// The sine and cosine polynomials inside the sine and cosine kernel, in
/// ulps, on [0, pi/4].
///
/// Known: swept: every f32 of [0, pi/4] (`exhaustive_kernel_sweep`).
/// `proofs/gappa/cos_poly.g` proves 0.834 ulp for the cosine polynomial on
/// all of it, and `sin_poly_hi.g`, `sin_poly_mid.g` and `sin_poly_low.g`
/// 0.85 ulp for the sine polynomial on [2^-9, pi/4] (with Sollya's bounds of
/// the approximation errors, `cos_poly.sollya`, `sin_poly.sollya`); below
/// 2^-9 the sine has no model (one per binade would be needed, for the
/// reason of [`ATAN_POLY_MAX_ULP`]). Relative to the sine and cosine of
/// `r + t`, with the tail, Gappa (certificates checked by coqc) proves
/// 1.0e-7 (`sin_poly_tail.g`, `r` in [2^-149, 0.7854]) and 8e-8
/// (`cos_poly_tail.g`, `r` in [0, 0.7854]) for `|t| <= 2^-24 |r|`; that
/// every `(r, t)` the kernel evaluates lies there is argued from the code
/// (`docs/verification-proofs.md`) and checked by the sweep, negative `r`
/// by the polynomials' symmetry, and `r = 0` is exact.
pub const SIN_COS_POLY_MAX_ULP: f32 = 1.0; // sin 0.805 at 0.7828049, cos 0.749 at 0.7086515
/// The sine and cosine kernel, in ulps, on [-3 pi/4, 3 pi/4]: every angle
/// `slerp` hands it for `alpha` in [0, 1].
///
/// Known: swept: every f32 of [0, 3 pi/4] (`exhaustive_kernel_sweep`).
pub const SIN_COS_NARROW_MAX_ULP: f32 = 1.0; // 0.858 at 2.3555665
/// The sine and cosine kernel, in ulps, for every finite argument beyond
/// 3 pi/4 (exact argument reduction).
///
/// Known: swept: every finite f32 beyond 3 pi/4 (`exhaustive_kernel_sweep`).
pub const SIN_COS_MAX_ULP: f32 = 1.25; // 0.985 at 2.3279488e23
/// Relative error of `phi^2` from the arc of slerp's f64 evaluation on
/// x86-64 and AArch64 (`quat/slerp/in_f64.rs`, `Arc::from_quotient`), against the
/// exact `phi^2 = 4 atan^2(sqrt(t2))` of the quotient `t2 = tan^2(phi / 2)`
/// that the evaluation computes in f64, for `t2` in [2^-170, 1.0001]. The
/// error of `t2` itself (the rounding of the f64 sums of squares of the
/// inputs' difference and sum, and the inputs' own) is not part of it.
///
/// Known: proven: `proofs/gappa/arc_f64.g` proves 3.392e-8: Sollya bounds
/// the approximation error of `1 + t2 P(t2)` against `atan(t) / t` by
/// 1.6959e-8 (`atan_f64.sollya`), which `phi^2` takes twice, and Gappa the
/// f64 rounding. Swept: every f32 `t2` of [2^-30, 1]
/// (`exhaustive_kernel_sweep_f64` in `quat/slerp/in_f64/tests.rs`).
pub const PHI_SQUARED_F64_MAX_REL_ERROR: f32 = 3.4e-8; // 3.340e-8 at t2 = 0.8781245 swept, 3.392e-8 proven
/// Relative error of `phi / sin(phi)` from the arc of slerp's f64
/// evaluation (`Arc::from_quotient`), on the domain of
/// [`PHI_SQUARED_F64_MAX_REL_ERROR`] and against the exact value for the
/// same `t2`.
///
/// Known: proven: `proofs/gappa/arc_f64.g` proves 1.696e-8, the
/// approximation error of `1 + t2 P(t2)` (Sollya, 1.6959e-8) and the f64
/// rounding. Swept as [`PHI_SQUARED_F64_MAX_REL_ERROR`].
pub const PHI_OVER_SINE_F64_MAX_REL_ERROR: f32 = 1.7e-8; // 1.670e-8 at t2 = 0.87812424 swept, 1.696e-8 proven
/// Relative error of `sin(x) / x` as slerp's f64 evaluation takes it
/// (`quat/slerp/in_f64.rs`, `sinc`, `1 + s Q(s)` of `s = x^2`), for every
/// f64 `s` in [0, 2.4676] (`x` up to pi/2 and a little beyond).
///
/// Known: proven: `proofs/gappa/sinc_f64.g` proves 6.0967e-9: Sollya bounds
/// the approximation error by 6.0966e-9 (`sinc_f64.sollya`), Gappa the f64
/// evaluation by 2.7e-16. Swept: every f32 `x` of [2^-30, pi/2]
/// (`exhaustive_kernel_sweep_f64`).
pub const SINC_F64_MAX_REL_ERROR: f32 = 6.1e-9; // 6.054e-9 at x = 1.4982078 swept, 6.0967e-9 proven
/// Relative error of slerp's coefficients `sin((1 - alpha) phi) / sin(phi)`
/// and `sin(alpha phi) / sin(phi)` in its f64 evaluation
/// (`quat/slerp/in_f64.rs`, `Arc::coefficient`) before their rounding to
/// f32, for every f32 `alpha` in (0, 1] and the `phi` of the arc's `t2`
/// (on the domain of [`PHI_SQUARED_F64_MAX_REL_ERROR`], `phi^2` above
/// 2^-24, where the evaluation applies): the arc's errors, `sin(x) / x`'s
/// and the rounding of the coefficients' own operations.
///
/// Known: proven: `proofs/gappa/coefficient_f64.g` (`c1`) and
/// `coefficient_rest_f64.g` (`c0`) prove 4.09e-8 each, taking
/// `arc_f64.g`'s proven bounds and `sinc_f64.sollya`'s approximation error
/// as hypotheses (and `phi^2` at most 2.4676, which follows from the arc's
/// domain by a calculation). Sampled: every 15,952nd f32 `t2` of
/// [2^-25, 1] with 13 values of `alpha` (`coefficient_sweep`; every 64th f32
/// `t2` in `exhaustive_kernel_sweep_f64`).
pub const SLERP_COEFFICIENT_F64_MAX_REL_ERROR: f32 = 4.1e-8; // 2.169e-8 at t2 = 0.57344437, alpha = 1/3 sampled, 4.09e-8 proven
/// Absolute error, in radians, of the atan2 kernel, for every pair of
/// finite arguments.
///
/// Known: proven: `proofs/gappa/atan2_outer.g` (the lower and upper
/// branches) and `atan2_middle.g` prove 3.16e-7 against the angle of the
/// exact arguments, every sign, given the polynomial's error relative to
/// atan(u) that `atan_poly.g` and `atan_poly_tiny.g` prove (8.8e-8), and
/// steps argued on paper in the models' headers (the mean value theorem
/// for the quotient's rounding, the branches' ranges, one rounding on the
/// grid of its argument, the arguments at the ends of the ranges). The
/// sweep of every f32 quotient of each branch, as [`ATAN2_MAX_ULP`], finds
/// 2.667e-7 at u = -0.54528743 (a result near pi), a search of argument
/// pairs 2.6299e-7.
pub const ATAN2_MAX_ABS_ERROR: f32 = backend::ATAN2_MAX_ABS_ERROR;
/// Absolute error of the sine and cosine kernel on [-10, 10].
///
/// Known: swept: every f32 of [-10, 10] (`exhaustive_kernel_sweep` in
/// `src/float.rs`; every test run takes every 997th), the largest error
/// rounded up.
pub const SIN_COS_MAX_ABS_ERROR: f32 = backend::SIN_COS_MAX_ABS_ERROR;
/// Relative error of the tangent kernel over half fields of view, [0.0087,
/// 1.5621] (1 to 179 degrees).
///
/// Known: swept: every f32 of [0.0087, 1.5621] (`exhaustive_kernel_sweep`
/// in `src/float.rs`; every test run takes every 997th), the largest error
/// rounded up.
pub const TAN_MAX_REL_ERROR: f32 = backend::TAN_MAX_REL_ERROR;
/// `|norm - 1|` after `normalize`, `nlerp` or `blend`, for any finite non-zero
/// input, subnormal to `f32::MAX`.
///
/// Known: proven: `proofs/coq/normalize_norm.v` proves 2.391e-7 (Coq, on
/// the certificate of `proofs/gappa/normalize.g`; `normalize_scale.g` proves
/// that the rescaled branches scale exactly or within 2^-150). A search
/// found 1.8335e-7 (`proofs/tests/worst_cases.rs`).
pub const NORMALIZE_MAX_NORM_ERROR: f32 = 2.4e-7; // 2.391e-7 proven; 1.723e-7 (random), 1.8335e-7 (by search)
/// The norm error an operation adds: `|norm - 1|` of the result of `pow`
/// and `from_axis_angle` (on any finite input); for `slerp` on unit
/// inputs, relative to the nearest norm between its inputs' (`|r| / n -
/// 1` with `n` the nearest value of `[min(|a|, |b|), max(|a|, |b|)]` to
/// `|r|`: the result's norm moves from `|a|` to `|b|`, whose ratio for two
/// results of `normalize` is 1 only within twice its error); for `*`,
/// relative to the product of the inputs' norms, `| |a * b| / (|a| |b|) -
/// 1 |`. The inputs' own distance from unit norm
/// carries through a product: for two results of `normalize`, `|a * b|`
/// is within `(1 + NORMALIZE_MAX_NORM_ERROR)^2 (1 + UNIT_NORM_ERROR) - 1`
/// (8.3e-7) of 1, and a search found 4.6884e-7 (`proofs/tests/worst_cases.rs`).
///
/// Known: measured. For products, `proofs/coq/mul_norm.v` proves 2.84e-7
/// (Coq, from the rounding of each term and partial sum, relative to `|a| |b|`
/// for inputs within 2^-20 of unit norm, whatever their components), and a search found 1.9720e-7
/// (`proofs/tests/worst_cases.rs`); for `from_axis_angle` and for `pow`
/// with `|alpha| <= f32::MAX / 4` (beyond, `pow` ends with `normalize`),
/// `proofs/coq/axis_angle_norm.v` proves 3.483e-7 (Coq, on the terms of
/// `proofs/gappa/axis_angle.g`), given the sine polynomial's relative
/// error within 1.0e-7 (`sin_poly_tail.g`) and the cosine polynomial's
/// within 8e-8 (`cos_poly_tail.g`), as the kernel pairs them (the libm
/// backend is outside it), and a search found
/// 2.4337e-7 (`from_axis_angle`) and 2.2764e-7 (`pow`). For
/// `slerp`'s f32 evaluation (every target without the f64 one, and the
/// inputs that one leaves) `proofs/coq/slerp_endpoint_norm_f32.v` proves,
/// at `alpha = 1` (angles above 2^-12; its hypothesis that the computed
/// sine lies in [2^-13, 1] follows, by a calculation in its header, from
/// the polynomials' relative errors `sin_poly_tail.g` and `cos_poly_tail.g`
/// prove), 1.193e-7 relative
/// to `|b|` (a search: 1.0744e-7); the rest of `slerp` has no proof. For
/// its main branch in the plane (`alpha` in (0, 1), angles above 2^-12),
/// `proofs/coq/slerp_plane_f32.v` proves two pieces: the computed shares
/// of the angle add up to it within 5.961e-8, relative (exactly wherever
/// `far >= phi / 2`), and the exact combination at the angle they make has
/// a squared norm off 1 by at most that angle's error; the law joining
/// them to the kernels' errors is not proven. A
/// search of the f32 evaluation (`deep_slerp_f32_search`) finds 2.5020e-7
/// (`alpha` in [0, 1]) and 2.9384e-7 (extrapolating) against the range of
/// the inputs' norms, and one of that branch alone
/// (`deep_slerp_f32_plane_search`) 2.6220e-7. For `slerp`'s f64 path
/// (x86-64 and AArch64, `alpha` in (0, 1]), `proofs/coq/slerp_norm_f64.v`
/// proves 2.2e-7 relative to the mean of the inputs' norms that the exact
/// coefficients weigh (Coq; the angle from `proofs/gappa/slerp_angle_f64.g`,
/// the coefficients from `coefficient_f64.g` and `coefficient_rest_f64.g`),
/// which lies in their range, and the search found 1.5033e-7 against that
/// mean (ratio 1.46; a looser bound of this constant on that path) and 1.5332e-7
/// against the range (`deep_slerp_f64_norm_search`). The largest over
/// random draws is 2.572e-7.
pub const UNIT_NORM_ERROR: f32 = backend::UNIT_NORM_ERROR;
/// `|norm - 1|` of [`Quat::mul_renormalized`](crate::Quat::mul_renormalized)'s
/// result, one step and so every chain: for `a` and `b` with `|a|^2` and
/// `|b|^2` within 2^-20 of 1 (whatever their components), the exact
/// norm of the f32 result of `a.mul_renormalized(b)` is within this of 1,
/// whatever the inputs' norms in that domain (the Newton step takes them
/// away to second order; what is left is the step's own rounding). By
/// induction, a chain started within this of unit norm (the identity
/// included) whose steps are within 2.391e-7 of it (every result of
/// `normalize`) stays within it for every length (a component of
/// 1 + 2^-23, which such a chain can reach, is inside the domain). A chain of 1,000,000
/// products cycling through 1,000 random rotations of up to 0.1 rad
/// reached 1.192e-7 (`renormalized_product_chain_stays_unit` in
/// `tests/edge_cases.rs`); plain products of the same steps drifted by
/// 1.7e-2 in that run.
///
/// Known: proven: `proofs/coq/renormalized_norm.v` proves 1.947e-7 (Coq,
/// on the certificate of `proofs/gappa/renormalize.g` for the scale
/// `(3 - n2) * 0.5` and on `mul_norm.v` for the product). A search
/// (`deep_renormalized_search` in `proofs/tests/worst_cases.rs`) finds
/// 1.6240e-7 on that domain (ratio 1.20) and 1.5701e-7 with `|a|` within
/// 1.947e-7 of 1 and `|b|` within 2.391e-7, the invariant's (ratio 1.24).
pub const RENORMALIZED_CHAIN_NORM_ERROR: f32 = 1.95e-7; // 1.6240e-7 searched, 1.947e-7 proven (a chain of 10^6 products: 1.192e-7)
/// How far from 1 the norm of a quaternion may be for
/// [`Quat::is_normalized`](crate::Quat::is_normalized): the drift of about
/// 300 chained products at [`UNIT_NORM_ERROR`] each (plain products without
/// [`Quat::normalize`](crate::Quat::normalize)), and still small enough that
/// rotating by such a quaternion scales vectors by less than 0.02 %. The check compares the squared norm with 1 within
/// twice this value.
///
/// Known: tolerance: chosen from the measured [`UNIT_NORM_ERROR`], not
/// itself an error bound.
pub const IS_NORMALIZED_TOLERANCE: f32 = backend::IS_NORMALIZED_TOLERANCE;
/// How far from rigid a matrix may be for
/// [`RigTForm::try_from`](crate::RigTForm#impl-TryFrom%3CMatrix4%3E-for-RigTForm)
/// to take it: the largest entry of `|M^T M - I|` of its 3x3 block and of
/// its last row's distance from `[0, 0, 0, 1]`. A chosen tolerance, not a
/// measured error: several hundred times the orthonormality error of the
/// f32 rotation matrices [`Matrix4::from_quat`](crate::Matrix4::from_quat)
/// makes, so that products of a few such matrices pass, while a scale of
/// 1.001 or a shear of 0.001 is refused.
///
/// Known: tolerance: chosen from the measured orthonormality error of the
/// matrices above, not an error bound.
pub const RIGID_TOLERANCE: f32 = 1e-4;
/// Angle error of [`Quat::from_matrix`](crate::Quat::from_matrix) for the
/// f32 rotation matrices of random unit quaternions, against the exact
/// rotation of the same f32 entries, half turns included.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const FROM_MATRIX_MAX_ANGLE_ERROR: f32 = 4.3e-7; // 3.433e-7
/// `|q * a - b|` for `q = Quat::from_rotation_arc(a, b)` and unit `a`, `b`
/// (random, nearly the same, nearly opposite and opposite pairs), and the
/// angle error of `q` against the shortest rotation for directions at most
/// 90 degrees apart.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const ROTATION_ARC_MAX_ERROR: f32 = 4.6e-7; // 3.666e-7 (|q a - b|), 3.419e-7 (angle)
/// Angle error of the rotation of
/// [`RigTForm::look_at`](crate::RigTForm::look_at), against the exact eye
/// frame of the same f32 points, for random eyes, targets and up vectors
/// at least 0.1 rad (about 6 degrees) off the line of sight. Closer, the
/// roll is ill-conditioned and the error grows as 1 / sin of that angle.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const LOOK_AT_MAX_ANGLE_ERROR: f32 = 1.1e-6; // 8.830e-7
/// Error of [`Matrix4::determinant`](crate::Matrix4::determinant)
/// relative to the sum `T` of the magnitudes of the 24 products of four
/// entries of the determinant's expansion: `|det - exact| <= DETERMINANT_MAX_REL_ERROR
/// T`, for every matrix where nothing overflows, and besides at most
/// `112 2^-150 (1 + M^2)` (`M` the largest entry) where products round
/// near underflow. `T` is `|det|` where the terms do not cancel; the
/// relative error of the determinant itself is at most this times
/// `T / |det|`, large for a nearly singular matrix.
///
/// Known: proven: `proofs/coq/matrix4_determinant_bound.v` proves
/// (1 + 2^-24)^8 - 1 (4.7684e-7): each product passes through eight
/// roundings, each relative to what it rounds (Coq, on the rounded terms
/// of `proofs/gappa/matrix4_determinant.g`, which computes the code's
/// bits). A search (`deep_determinant_search` in
/// `proofs/tests/worst_cases.rs`) finds 2.7633e-7: the bound is 1.73
/// times that.
pub const DETERMINANT_MAX_REL_ERROR: f32 = 4.8e-7; // 2.7633e-7 (search), 4.7684e-7 proven
/// Angle error of the Hamilton product `a * b` of unit quaternions: every
/// component in [-1, 1] and `|a|^2`, `|b|^2` within 2^-20 of 1 (f32
/// roundings of unit quaternions, and every result of `normalize`).
///
/// Known: proven: `proofs/gappa/mul_angle.g` proves 1.1922e-6 (the error
/// vector's length, within 10 2^-24, over `|a| |b|` less it, twice: the
/// whole error taken as turning the product, where only its part across
/// the exact product does). A search (`deep_product_angle_search` in
/// `proofs/tests/worst_cases.rs`) finds 3.324e-7: the bound is 3.6 times
/// that.
pub const MUL_MAX_ANGLE_ERROR: f32 = 1.2e-6; // 2.988e-7 (random), 3.324e-7 (search), 1.1922e-6 proven
/// Error of `q * v` (rotating a vector by a unit quaternion), relative to
/// `|v|`, against the exact value of the formula it evaluates,
/// `F(v) = v + 2 w (u x v) + 2 u x (u x v)`, which is the rotation by `q`
/// for `|q| = 1`. For `|q|^2 = 1 + e`, `F(v) = |q|^2 R(v) + (1 - |q|^2) v`
/// with `R` the rotation by `q / |q|`: off `R(v)` by at most `2 |e| |v|`
/// besides, which for a result of `normalize` (`|e|` up to 4.4e-7) a search
/// reaches, 9.5991e-7 against `R` (`proofs/tests/worst_cases.rs`); for the f32
/// rounding of a unit quaternion (`|e|` below 1.2e-7) the error against `R`
/// measured 4.710e-7.
///
/// Known: proven: `proofs/coq/rotate_error.v` proves 6.5e-7 (Coq, on
/// Flocq's rounding, for `|q|^2` within 2^-20 of 1; the model is
/// `proofs/gappa/rotate.g`). A search found 4.7482e-7
/// (`proofs/tests/worst_cases.rs`, with `q` a result of `normalize`).
pub const ROTATE_MAX_REL_ERROR: f32 = 6.5e-7; // 6.5e-7 proven; 4.7482e-7 (by search)
/// Angle error of `q.pow(alpha)` for unit `q`, per radian of the rotation
/// it returns and never less than this many radians: the error is at most
/// `POW_MAX_ANGLE_ERROR * max(1, |alpha| theta)`, with `theta` the angle of
/// `q` (`2 atan2(|v|, w)`, up to 2 pi). It grows with the turn because the
/// f32 product `alpha phi` handed to sin and cos is itself rounded. Also the
/// error of the angle returned by `to_axis_angle` (at most pi), per
/// `max(1, theta)`.
///
/// Known: measured: the largest error over the draws in its doc, rounded
/// up; a search (`deep_polar_search` in `proofs/tests/worst_cases.rs`)
/// finds 2.968e-7 for `pow`. `proofs/gappa/polar_angle.g` proves a looser
/// 1.03e-6 for `pow` and 3.7016e-7 per radian for `to_axis_angle`, given
/// [`ATAN2_MAX_ULP`] and [`SIN_COS_MAX_ABS_ERROR`] (swept, not proven) and
/// the length's rounding that `normalize.g` proves, with the last step,
/// from the model's goals to the rotation's angle, on paper in the model.
pub const POW_MAX_ANGLE_ERROR: f32 = backend::POW_MAX_ANGLE_ERROR;
/// Angle error of [`Quat::from_euler`](crate::Quat::from_euler) for angles
/// in [-pi, pi], and of the rotation (evaluated exactly) of the angles that
/// [`Quat::to_euler`](crate::Quat::to_euler) returns for a unit quaternion,
/// every one of the 24 orders, gimbal lock included. `from_euler`'s result is also within
/// this much of unit norm (2.029e-7 measured).
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const EULER_MAX_ANGLE_ERROR: f32 = backend::EULER_MAX_ANGLE_ERROR;
/// Angle error of `Quat::from_scaled_axis(v)`, relative to the angle `|v|`:
/// at most `FROM_SCALED_AXIS_MAX_REL_ERROR * |v|` radians, for angles from
/// 1e-38 (f32's normal range) to 1000 rad (`tests/attitude.rs`). Below,
/// `v`'s components are subnormal and their products round absolutely,
/// by up to 2^-150 each: 1.4e-3 of the angle at 1.4e-42 rad.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const FROM_SCALED_AXIS_MAX_REL_ERROR: f32 = backend::FROM_SCALED_AXIS_MAX_REL_ERROR;
/// Error of `q.to_scaled_axis()` for unit `q`, relative to the length of
/// the exact rotation vector, for angles from 2^-99 to 2 pi. Below, the
/// result's components are near or below f32's normal range and round
/// absolutely (6.4e-6 relative at 3.1e-40 rad).
///
/// Known: measured: the largest error over the draws in its doc, rounded
/// up; a search (`deep_polar_search` in `proofs/tests/worst_cases.rs`)
/// finds 2.612e-7. `proofs/gappa/polar_angle.g` proves a looser 6.6912e-7
/// (each component, relative), given [`ATAN2_MAX_ULP`] (swept, not
/// proven) and the length's rounding that `normalize.g` proves.
pub const TO_SCALED_AXIS_MAX_REL_ERROR: f32 = backend::TO_SCALED_AXIS_MAX_REL_ERROR;
/// Angle between `Quat::from_scaled_axis(a * q.to_scaled_axis())` and
/// `q.pow(a)`, in the form of [`POW_MAX_ANGLE_ERROR`]: at most
/// `EXP_LOG_POW_MAX_ANGLE_ERROR * max(1, |a| theta)` radians.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const EXP_LOG_POW_MAX_ANGLE_ERROR: f32 = backend::EXP_LOG_POW_MAX_ANGLE_ERROR;
/// Angle error, in radians, of one `q.integrate(omega, dt)` step for unit
/// `q` and `|omega dt|` up to 1 rad; `n` steps are within `n` times this.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const INTEGRATE_STEP_MAX_ANGLE_ERROR: f32 = backend::INTEGRATE_STEP_MAX_ANGLE_ERROR;
/// Largest difference, in radians, between the angle an
/// `attitude::Smoother` has left to a constant measurement and the exact
/// `theta_0 exp(-t / tau)`, over up to 2,000 updates at 100 Hz and 1 kHz
/// (`step_response_has_the_time_constant_at_100_hz_and_1_khz`).
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const SMOOTHER_DECAY_MAX_ERROR: f32 = backend::SMOOTHER_DECAY_MAX_ERROR;
/// Bound on the 6D inclination RMSE, in degrees, of
/// `attitude::OrientationFilter` with `FilterParams::DEFAULT` on BROAD trial
/// 16 (fast translation), shipped in `testkit/data/` and run by
/// `tests/broad.rs`: the measured RMSE rounded up.
///
/// Known: benchmark: measured on the recorded trial, rounded up; a figure
/// of the filter on one recording, not an error bound of the arithmetic.
pub const FILTER_BROAD_16_INCLINATION_RMSE_DEG: f32 = 0.6; // 0.516 6D and 9D
/// Bound on the 9D total RMSE, in degrees, of the same run with the
/// magnetometer.
///
/// Known: benchmark: measured on the recorded trial, rounded up.
pub const FILTER_BROAD_16_TOTAL_RMSE_DEG: f32 = 0.8; // 0.727
/// Angle error of `a.slerp(b, alpha)` for unit inputs, in the same form as
/// [`POW_MAX_ANGLE_ERROR`]: at most `SLERP_MAX_ANGLE_ERROR * max(1, |alpha| theta)`
/// with `theta = a.angle_to(b)` (at most pi). So for `alpha` in [0, 1] it is
/// at most `pi * SLERP_MAX_ANGLE_ERROR`, and at most `SLERP_MAX_ANGLE_ERROR`
/// when the two are less than a radian apart. Measured over random pairs and
/// `alpha` in [-1, 2], and on each edge class: identical, 1e-6 and 1e-3 rad
/// apart, pi - 1e-4 apart, antipodal (`q`, `-q`), exactly pi apart.
/// Outside [-1, 2], for inputs less than about 1e-5 rad apart, the error
/// can instead reach `|alpha| 2^-22` rad, the resolution of their f32
/// difference (`slerp_extrapolated_from_inputs_ulps_apart_turns_by_no_more_than_their_resolution`
/// in `tests/edge_cases.rs`, default backend).
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const SLERP_MAX_ANGLE_ERROR: f32 = backend::SLERP_MAX_ANGLE_ERROR;
/// Angle error, in radians, of `Quat::catmull_rom` (and of the rotation of
/// `RigTForm::catmull_rom`) against the same construction in f64
/// (`testkit::catmull_rom`), over five unit keys on a random walk whose
/// neighbours are up to 1.5 rad apart (so keys two apart, whose transition
/// the control points take the power of, are up to 3 rad apart) and `t`
/// uniform over the keys. Six slerps and two powers stand between keys
/// and result; most of the error is that of the last slerps.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const CATMULL_ROM_MAX_ANGLE_ERROR: f32 = backend::CATMULL_ROM_MAX_ANGLE_ERROR;
/// Angle error, in radians, of a LINEAR rotation [`Sampler`](crate::animation::Sampler)
/// against the same evaluation in f64 (the segment's `u` and the notes'
/// slerp, from the same f32 keys and time): five unit keys uniform over
/// the rotations (so neighbours up to pi apart), times with intervals in
/// [0.01, 2] s from a start in [0, 10] s, `t` uniform over the keys. The
/// error is slerp's plus that of `u`, rounded in f32, times the angle
/// between the keys.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const SAMPLER_LINEAR_MAX_ANGLE_ERROR: f32 = backend::SAMPLER_LINEAR_MAX_ANGLE_ERROR;
/// Angle error, in radians, of a CUBICSPLINE rotation
/// [`Sampler`](crate::animation::Sampler) against the same Hermite sum in f64,
/// normalized, from the same f32 keys, tangents and time (keys as for
/// [`SAMPLER_LINEAR_MAX_ANGLE_ERROR`], tangents with components in [-1, 1]),
/// per unit of the sum's condition: the sum of the norms of its four terms
/// over the norm of the sum, 1 where the terms do not cancel and large
/// where they nearly do (keys and tangents that point opposite ways). No
/// transcendental function: the same for every backend.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const SAMPLER_CUBIC_MAX_ANGLE_ERROR: f32 = 1.0e-6; // 8.091e-7 (4,000,000 samples)
/// Error of a LINEAR or CUBICSPLINE translation or scale
/// [`Sampler`](crate::animation::Sampler) against the same evaluation in f64,
/// relative to the largest component magnitude among the segment's two
/// values and its two tangents times the interval (values and tangents with
/// components in [-100, 100], times as for
/// [`SAMPLER_LINEAR_MAX_ANGLE_ERROR`], and for any values and times where
/// nothing underflows or overflows and `t - t0` is at least 2^-126).
///
/// Known: proven: `proofs/gappa/sampler_linear.g` proves 5.12e-7 for
/// LINEAR and `sampler_cubic.g` 2.48e-6 for CUBICSPLINE (the Hermite
/// weights' errors, up to 6.04e-7 each, add where the two values are
/// opposite), given the relative error of the segment's `u` (three
/// roundings, at most 1.7882e-7, on paper). A search
/// (`deep_vector_sampler_search` in `proofs/tests/worst_cases.rs`) finds
/// 6.628e-7, so the bound is 3.7 times what is found.
pub const SAMPLER_VEC3_MAX_REL_ERROR: f32 = 2.5e-6; // 5.774e-7 (4,000,000 samples of each), 6.628e-7 (search), 2.48e-6 proven
/// Error of an entry of [`Matrix4::inverse`](crate::Matrix4::inverse),
/// `|entry - C / D|` with `C` the entry's cofactor (the signed
/// determinant of the 3x3 matrix left without one row and one column)
/// and `D` the determinant, relative to `(Ac + |C| T / |D|) / |D|`: `Ac`
/// the sum of the magnitudes of the cofactor's six products, `T` that of
/// the 24 products of the determinant's expansion (as
/// [`DETERMINANT_MAX_REL_ERROR`]). The first part is the cofactor's own
/// rounding, the second the determinant's error carried into every entry
/// through `1 / det`; `T / |D|` is how much the expansion cancels, which
/// grows with the condition number. For every matrix whose expansion
/// cancels by at most 2^12 (`T <= 4096 |D|`), where nothing underflows or
/// overflows (after scaling the largest entry to 1, `|D|` at least
/// 2^-100; besides that, `20 2^-150 (1 + 1 / |D|)` near underflow).
///
/// Known: proven: `proofs/coq/matrix4_inverse_bound.v` proves 5.376e-7
/// (Coq, on the rounded terms of `proofs/gappa/matrix4_inverse.g`, which
/// computes the code's bits): each product of the cofactor rounds six
/// times (its minor's three, the product with `1 / det`, the product
/// with the entry, the sums), and `1 / det` is within `2^-24 + 4.7684e-7`
/// (its rounding and the determinant's, relative to `T / |D|`) of `1 /
/// D`. A search (`deep_matrix4_inverse_search` in
/// `proofs/tests/worst_cases.rs`) finds 2.0199e-7: the bound is 2.7 times
/// that.
pub const INVERSE_MAX_REL_ERROR: f32 = 5.4e-7; // 2.0199e-7 (search), 5.376e-7 proven
/// Error of the translation of [`Matrix4::look_at_rh`](crate::Matrix4::look_at_rh),
/// relative to `|eye|`, against nalgebra's f64 `Matrix4::look_at_rh` of the
/// same f32 points (eyes and targets in a cube of half-side 100, `up` at
/// least 0.1 rad off the line of sight).
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const LOOK_AT_RH_MAX_TRANSLATION_ERROR: f32 = 1.1e-6; // 8.405e-7
/// Angle error, in radians, of the rotation of
/// [`Matrix4::to_scale_rotation_translation`](crate::Matrix4::to_scale_rotation_translation)
/// for `Matrix4::from_scale_rotation_translation(s, r, t)` with random unit
/// `r` and scales of magnitude 1e-3 to 1e3 (the x scale of either sign),
/// against `r`.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const SRT_ROTATION_MAX_ANGLE_ERROR: f32 = 9.0e-7; // 7.084e-7
/// Error of the scale of the same, relative to each input scale, for `r`
/// an f32 rounding of a unit quaternion (`|r|^2` within 1.2e-7 of 1). For
/// any other `r` the scale also carries `r`'s distance from unit norm:
/// the exact column of `from_quat(r)` has squared length `1 + 4 (y^2 +
/// z^2) (|r|^2 - 1)`, so up to `2 ||r|^2 - 1|` more (for a result of
/// [`Quat::normalize`](crate::Quat::normalize), `|r|^2` up to 4.8e-7 from 1).
///
/// Known: proven: `proofs/coq/srt_scale_bound.v` proves 7.92e-7 (Coq, on
/// the rounded terms of `proofs/gappa/srt_scale.g`, which computes the
/// code's bits) for every f32 `r` with `|r|^2` within 1.2e-7 of 1 (every
/// f32 rounding of a unit quaternion) and every f32 scale of magnitude at
/// least 1e-3 (to 1e3, where the norm takes no rescaling): the computed
/// column of `from_quat(r)` is within 3.4241e-7 of the exact column of
/// `r`'s formula, whose length is within 2.4001e-7 of 1, and the products
/// by the scale, the sum of squares and the root add 3.5 roundings. A
/// search (`deep_srt_scale_search` in `proofs/tests/worst_cases.rs`)
/// finds 5.0071e-7 on that domain: the bound is 1.58 times that.
/// `trs_round_trips_within_its_bounds_and_agrees_with_glam` checks it on
/// random draws, and results of `normalize` against it plus `2 ||r|^2 -
/// 1|`.
pub const SRT_SCALE_MAX_REL_ERROR: f32 = 9.5e-7; // 5.0071e-7 (search), 7.92e-7 proven
/// Error of an entry of [`Matrix3::inverse`](crate::Matrix3::inverse),
/// `|entry - M / D|` with `M` the entry's minor (a component of a cross
/// product of two columns) and `D` the determinant, relative to
/// `(Am + |M| T / |D|) / |D|`: `Am` the sum of the magnitudes of the
/// minor's two products, `T` that of the six products of the
/// determinant's expansion (as [`MATRIX3_DETERMINANT_MAX_REL_ERROR`]).
/// The first part is the minor's own rounding, the second the
/// determinant's error carried into every entry through `1 / det`; `T /
/// |D|` is how much the expansion cancels, which grows with the
/// condition number. For every matrix whose expansion cancels by at most
/// 2^12 (`T <= 4096 |D|`), where nothing underflows or overflows (after
/// scaling the largest entry to 1, `|D|` at least 2^-100; besides that,
/// `4 2^-150 (1 + 1 / |D|)` near underflow).
///
/// Known: proven: `proofs/coq/matrix3_inverse_bound.v` proves 3.585e-7
/// (Coq, on the rounded terms of `proofs/gappa/matrix3_inverse.g`, which
/// computes the code's bits): the minor and its product with `1 / det`
/// round three times, and `1 / det` is within `2^-24 + 2.9803e-7` (its
/// rounding and the determinant's, relative to `T / |D|`) of `1 / D`. A
/// search (`deep_matrix3_inverse_search` in `proofs/tests/worst_cases.rs`)
/// finds 1.8827e-7: the bound is 1.9 times that.
pub const MATRIX3_INVERSE_MAX_REL_ERROR: f32 = 3.6e-7; // 1.8827e-7 (search), 3.585e-7 proven
/// Error of [`Matrix3::determinant`](crate::Matrix3::determinant)
/// relative to the sum `T` of the magnitudes of the six products of its
/// expansion (`|a_x b_y c_z|` and the five others): `|det - exact| <=
/// MATRIX3_DETERMINANT_MAX_REL_ERROR T`, for every matrix where nothing
/// overflows, and besides at most `8 2^-150 (1 + |a|_1)` (`a` the first
/// column) where products round near underflow.
///
/// Known: proven: `proofs/coq/matrix3_determinant_bound.v` proves
/// (1 + 2^-24)^5 - 1 (2.9803e-7): each product passes through five
/// roundings, each relative to what it rounds (Coq, on the rounded terms
/// of `proofs/gappa/matrix3_determinant.g`, which computes the code's
/// bits). A search (`deep_determinant_search` in
/// `proofs/tests/worst_cases.rs`) finds 2.4171e-7: the bound is 1.23
/// times that.
pub const MATRIX3_DETERMINANT_MAX_REL_ERROR: f32 = 3.0e-7; // 2.4171e-7 (search), 2.9803e-7 proven
/// Largest entry difference between `Matrix4::from_quat(q)`, for unit `q`,
/// and the exact rotation matrix of `q / |q|`: "unit" is an f32 rounding
/// of a unit quaternion, every component in [-1, 1] and `|q|^2` within
/// 1.2e-7 of 1 (2^-23, and 2 |1 - |q|^2| of the bound is that distance).
///
/// Known: proven: `proofs/gappa/matrix_entry.g` proves 6.58e-7 for the
/// diagonal and 4.19e-7 for the other entries.
pub const MATRIX_ENTRY_ERROR: f32 = 6.6e-7; // 3.000e-7 measured (random), 6.58e-7 proven
/// Angle error, in radians, of
/// [`Cvec3::angle_between`](crate::Cvec3::angle_between) against the exact
/// angle between the same f32 vectors (nalgebra in f64, `src/vec/tests.rs`'s
/// tests): random pairs, and pairs 1e-7 to 1e-1 rad from parallel and
/// from opposite, at scales 2^-40 to 2^40.
///
/// Known: measured: the largest error over the draws in its doc, rounded up.
pub const ANGLE_BETWEEN_MAX_ERROR: f32 = backend::ANGLE_BETWEEN_MAX_ERROR;
/// Error of [`Cvec3::project_onto`](crate::Cvec3::project_onto) and
/// [`Cvec3::reject_from`](crate::Cvec3::reject_from) (and of `Cvec4`'s),
/// relative to `|self|`, against the exact projection of the same f32
/// vectors, for every finite `self` with `|self|` from 2^-100 (below,
/// each rounding near underflow may add 2^-150) and every finite non-zero
/// `rhs`, where the result is finite (a dot product beyond `f32::MAX`
/// overflows to infinity).
///
/// Known: proven: `proofs/coq/project4_bound.v` (`Cvec4`) and
/// `proofs/coq/project3_bound.v` (`Cvec3`) prove 7.83e-7 for both
/// (their lemmas: 7.7584e-7 for `project_onto` and 7.8175e-7 for
/// `reject_from`; Coq, on the rounded
/// terms of `proofs/gappa/project4.g` and `project3.g`, which compute the
/// code's bits, and on the certificate of `normalize.g` for the norm of
/// `rhs`; `normalize_scale.g` proves that the rescaled branches scale
/// exactly or within 2^-150). A search (`deep_projection_search` in
/// `proofs/tests/worst_cases.rs`, from random, near-parallel and
/// near-orthogonal pairs) finds 5.4611e-7 (`Cvec4::reject_from`): the
/// bound is 1.43 times that. Random draws reach 3.619e-7.
pub const PROJECT_MAX_REL_ERROR: f32 = 7.83e-7; // 7.83e-7 proven; 5.4611e-7 (by search), 3.619e-7 (random)

#[cfg(test)]
mod tests {
    /// The tables in the module docs and in the README quote every constant
    /// (but the two filter RMSE bounds); this keeps them equal to the code.
    #[test]
    fn docs_table_matches_the_constants() {
        let column = 1;
        let constants = [
            ("MUL_MAX_ANGLE_ERROR", super::MUL_MAX_ANGLE_ERROR),
            ("ROTATE_MAX_REL_ERROR", super::ROTATE_MAX_REL_ERROR),
            ("MATRIX_ENTRY_ERROR", super::MATRIX_ENTRY_ERROR),
            ("INVERSE_MAX_REL_ERROR", super::INVERSE_MAX_REL_ERROR),
            ("NORMALIZE_MAX_NORM_ERROR", super::NORMALIZE_MAX_NORM_ERROR),
            ("UNIT_NORM_ERROR", super::UNIT_NORM_ERROR),
            ("POW_MAX_ANGLE_ERROR", super::POW_MAX_ANGLE_ERROR),
            ("SLERP_MAX_ANGLE_ERROR", super::SLERP_MAX_ANGLE_ERROR),
            ("ATAN2_MAX_ABS_ERROR", super::ATAN2_MAX_ABS_ERROR),
            ("SIN_COS_MAX_ABS_ERROR", super::SIN_COS_MAX_ABS_ERROR),
            ("TAN_MAX_REL_ERROR", super::TAN_MAX_REL_ERROR),
            (
                "FROM_SCALED_AXIS_MAX_REL_ERROR",
                super::FROM_SCALED_AXIS_MAX_REL_ERROR,
            ),
            (
                "TO_SCALED_AXIS_MAX_REL_ERROR",
                super::TO_SCALED_AXIS_MAX_REL_ERROR,
            ),
            (
                "EXP_LOG_POW_MAX_ANGLE_ERROR",
                super::EXP_LOG_POW_MAX_ANGLE_ERROR,
            ),
            (
                "INTEGRATE_STEP_MAX_ANGLE_ERROR",
                super::INTEGRATE_STEP_MAX_ANGLE_ERROR,
            ),
            ("SMOOTHER_DECAY_MAX_ERROR", super::SMOOTHER_DECAY_MAX_ERROR),
            (
                "RENORMALIZED_CHAIN_NORM_ERROR",
                super::RENORMALIZED_CHAIN_NORM_ERROR,
            ),
            ("EULER_MAX_ANGLE_ERROR", super::EULER_MAX_ANGLE_ERROR),
            (
                "FROM_MATRIX_MAX_ANGLE_ERROR",
                super::FROM_MATRIX_MAX_ANGLE_ERROR,
            ),
            ("ROTATION_ARC_MAX_ERROR", super::ROTATION_ARC_MAX_ERROR),
            ("LOOK_AT_MAX_ANGLE_ERROR", super::LOOK_AT_MAX_ANGLE_ERROR),
            (
                "DETERMINANT_MAX_REL_ERROR",
                super::DETERMINANT_MAX_REL_ERROR,
            ),
            (
                "CATMULL_ROM_MAX_ANGLE_ERROR",
                super::CATMULL_ROM_MAX_ANGLE_ERROR,
            ),
            ("PROJECT_MAX_REL_ERROR", super::PROJECT_MAX_REL_ERROR),
        ];
        // Quoted in this module's table only (not in the README's).
        let module_only = [
            (
                "SAMPLER_LINEAR_MAX_ANGLE_ERROR",
                super::SAMPLER_LINEAR_MAX_ANGLE_ERROR,
            ),
            (
                "SAMPLER_CUBIC_MAX_ANGLE_ERROR",
                super::SAMPLER_CUBIC_MAX_ANGLE_ERROR,
            ),
            (
                "SAMPLER_VEC3_MAX_REL_ERROR",
                super::SAMPLER_VEC3_MAX_REL_ERROR,
            ),
            ("ANGLE_BETWEEN_MAX_ERROR", super::ANGLE_BETWEEN_MAX_ERROR),
            (
                "MATRIX3_INVERSE_MAX_REL_ERROR",
                super::MATRIX3_INVERSE_MAX_REL_ERROR,
            ),
            (
                "MATRIX3_DETERMINANT_MAX_REL_ERROR",
                super::MATRIX3_DETERMINANT_MAX_REL_ERROR,
            ),
            (
                "LOOK_AT_RH_MAX_TRANSLATION_ERROR",
                super::LOOK_AT_RH_MAX_TRANSLATION_ERROR,
            ),
            (
                "SRT_ROTATION_MAX_ANGLE_ERROR",
                super::SRT_ROTATION_MAX_ANGLE_ERROR,
            ),
            ("SRT_SCALE_MAX_REL_ERROR", super::SRT_SCALE_MAX_REL_ERROR),
        ];
        let text = include_str!("accuracy.rs");
        for (name, value) in module_only {
            let row = text
                .lines()
                .find(|l| l.starts_with(&std::format!("//! | [`{name}`")))
                .unwrap_or_else(|| panic!("{name} is missing from the table in src/accuracy.rs"));
            let cell = row.split('|').nth(column + 1).unwrap_or_default().trim();
            assert_eq!(
                cell.parse(),
                Ok(value),
                "src/accuracy.rs: table row for {name}"
            );
        }
        let tables = [
            ("src/accuracy.rs", include_str!("accuracy.rs"), "//! | [`"),
            ("README.md", include_str!("../README.md"), "| `"),
        ];
        for (file, text, row_start) in tables {
            for (name, value) in constants {
                let row = text
                    .lines()
                    .find(|l| l.starts_with(&std::format!("{row_start}{name}`")))
                    .unwrap_or_else(|| panic!("{name} is missing from the table in {file}"));
                let cell = row.split('|').nth(column + 1).unwrap_or_default().trim();
                assert_eq!(cell.parse(), Ok(value), "{file}: table row for {name}");
            }
        }
    }
}
