//! Laws of the ways to build a rotation from something else: Euler angles,
//! a rotation matrix, two directions.
//!
//! Angles between rotations are measured without a square root (which Kani
//! cannot read on x86): for unit `q` and `r`, the rotation between them
//! turns by `theta` with `sin^2(theta / 2) = 1 - (q . r)^2`, computed in
//! f64, where `q . r` of f32 components is exact.

use super::{norm2, within, yes_or_no, Verdict, ONE_STEP_NORM_TOL};
use rigtform::accuracy::{
    EULER_MAX_ANGLE_ERROR, FROM_MATRIX_MAX_ANGLE_ERROR, MATRIX_ENTRY_ERROR, ROTATION_ARC_MAX_ERROR,
};
use rigtform::{Cvec3, EulerRot, Matrix4, Quat};

fn dot64(a: Quat, b: Quat) -> f64 {
    let [ax, ay, az, aw] = a.to_array().map(f64::from);
    let [bx, by, bz, bw] = b.to_array().map(f64::from);
    aw * bw + ax * bx + ay * by + az * bz
}

/// `sin^2` of half the angle of the rotation between `q` and `r`, for any
/// non-zero scales of them.
fn half_angle_sin2(q: Quat, r: Quat) -> f64 {
    let d = dot64(q, r);
    1.0 - d * d / (norm2(q) * norm2(r))
}

/// The largest `sin^2(theta / 2)` for an angle of `theta` radians: the
/// square of `theta / 2`, an upper bound of the sine.
fn half_angle_sin2_bound(theta: f64) -> f64 {
    (theta / 2.0) * (theta / 2.0)
}

/// `from_euler` of the angles that `to_euler` returns is the rotation it
/// was given, and the angles are in their documented ranges: `a` and `c`
/// in [-pi, pi], `b` in the order's `middle_angle_range`. The angle between the two rotations
/// stays within twice [`EULER_MAX_ANGLE_ERROR`] (one way and back) plus the
/// input's distance from unit norm.
///
/// Preconditions: `q` unit to [`ONE_STEP_NORM_TOL`].
pub fn euler_angles_give_back_the_rotation(q: Quat, order: EulerRot) -> Verdict {
    use core::f32::consts::PI;
    let (a, b, c) = q.to_euler(order);
    let (lo, hi) = order.middle_angle_range();
    yes_or_no(
        "euler_angles_give_back_the_rotation (ranges)",
        (-PI..=PI).contains(&a) && (lo..=hi).contains(&b) && (-PI..=PI).contains(&c),
    )?;
    let back = Quat::from_euler(order, a, b, c);
    within(
        "euler_angles_give_back_the_rotation",
        half_angle_sin2(q, back),
        half_angle_sin2_bound(2.0 * f64::from(EULER_MAX_ANGLE_ERROR) + ONE_STEP_NORM_TOL),
    )
}

/// `Quat::from_matrix` inverts `Matrix4::from_quat`: the same rotation (up
/// to sign), with `w >= 0` and unit norm. The angle allowed is
/// [`FROM_MATRIX_MAX_ANGLE_ERROR`] plus what the f32 matrix entries (each
/// within [`MATRIX_ENTRY_ERROR`]) can move it, doubled for the worst case.
///
/// Preconditions: `q` unit to [`ONE_STEP_NORM_TOL`].
pub fn from_matrix_inverts_from_quat(q: Quat) -> Verdict {
    let r = Quat::from_matrix(Matrix4::from_quat(q));
    yes_or_no("from_matrix_inverts_from_quat (w >= 0)", r.w >= 0.0)?;
    within(
        "from_matrix_inverts_from_quat (norm)",
        (norm2(r) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )?;
    let tol = 2.0 * f64::from(FROM_MATRIX_MAX_ANGLE_ERROR + 4.0 * MATRIX_ENTRY_ERROR);
    within(
        "from_matrix_inverts_from_quat",
        half_angle_sin2(q, r),
        half_angle_sin2_bound(tol + ONE_STEP_NORM_TOL),
    )
}

fn to64(v: Cvec3) -> [f64; 3] {
    v.to_array().map(f64::from)
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `q v q^-1` in f64, for a unit `q` (the vector part of the notes' triple
/// product, as `v + 2 w (u x v) + 2 u x (u x v)`).
fn rotate64(q: Quat, v: [f64; 3]) -> [f64; 3] {
    let w = f64::from(q.w);
    let u = to64(q.vector());
    let t = cross3(u, v).map(|c| 2.0 * c);
    let ut = cross3(u, t);
    [
        v[0] + w * t[0] + ut[0],
        v[1] + w * t[1] + ut[1],
        v[2] + w * t[2] + ut[2],
    ]
}

/// `Quat::from_rotation_arc(from, to)` is unit and takes the direction of
/// `from` to the direction of `to` (the sine of the angle left between
/// them within twice [`ROTATION_ARC_MAX_ERROR`], plus the norm's error),
/// the short way: its axis is perpendicular to `from` and its `w` is not
/// negative.
///
/// Preconditions: `from` and `to` finite, with squared lengths in
/// `[2^-40, 2^80]`.
pub fn rotation_arc_takes_from_to_to(from: Cvec3, to: Cvec3) -> Verdict {
    let q = Quat::from_rotation_arc(from, to);
    within(
        "rotation_arc_takes_from_to_to (norm)",
        (norm2(q) - 1.0).abs(),
        ONE_STEP_NORM_TOL,
    )?;
    yes_or_no("rotation_arc_takes_from_to_to (w >= 0)", q.w >= 0.0)?;
    let (a, b) = (to64(from), to64(to));
    let (a2, b2) = (dot3(a, a), dot3(b, b));
    let moved = rotate64(q, a);
    // Parallel and the same way: the cross product vanishes and the dot
    // product is positive.
    let sin2 = dot3(cross3(moved, b), cross3(moved, b)) / (dot3(moved, moved) * b2);
    let tol = 2.0 * f64::from(ROTATION_ARC_MAX_ERROR) + ONE_STEP_NORM_TOL;
    within("rotation_arc_takes_from_to_to", sin2, tol * tol)?;
    yes_or_no(
        "rotation_arc_takes_from_to_to (same way)",
        dot3(moved, b) > 0.0,
    )?;
    // The axis of the shortest rotation is perpendicular to `from`: the
    // vector part of the unit `q`, `sin(theta / 2)` times the axis, has no
    // component along `from` beyond the error allowed.
    let along = dot3(to64(q.vector()), a);
    within(
        "rotation_arc_takes_from_to_to (axis perpendicular to from)",
        along * along,
        tol * tol * a2,
    )
}
