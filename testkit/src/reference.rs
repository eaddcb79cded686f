//! The f64 side of every accuracy measurement: conversions to nalgebra's
//! types, rotation angles between quaternions, and the notes' power
//! operator and slerp in f64 (`rigtform_proofs::reference`, which the
//! on-target tests use too).

use nalgebra as na;
use rigtform::{Cvec3, EulerRot, Quat};
use rigtform_proofs::reference::Quat64;

/// `q` in f64, exactly.
pub fn to_f64(q: Quat) -> na::Quaternion<f64> {
    na::Quaternion::new(q.w as f64, q.x as f64, q.y as f64, q.z as f64)
}

/// `q` rounded to f32.
pub fn to_f32(q: na::Quaternion<f64>) -> Quat {
    Quat::from_wxyz(q.w as f32, q.i as f32, q.j as f32, q.k as f32)
}

/// `v` in f64, exactly.
pub fn vec_to_f64(v: Cvec3) -> na::Vector3<f64> {
    na::Vector3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// The angle of the rotation between two quaternions, up to sign and
/// scale, in f64: `2 atan2(|v|, |w|)` of `b^-1 a` (accurate near 0 and pi).
///
/// ```
/// use rigtform::Quat;
/// use rigtform_testkit::{rotation_angle64, to_f64};
/// let (a, b) = (Quat::from_rotation_x(0.25), Quat::from_rotation_x(1.0));
/// assert!((rotation_angle64(to_f64(a), to_f64(-b)) - 0.75).abs() < 1e-6);
/// ```
pub fn rotation_angle64(a: na::Quaternion<f64>, b: na::Quaternion<f64>) -> f64 {
    Quat64::angle_between(to_reference(a), to_reference(b))
}

/// The angle between a computed f32 rotation and an f64 reference.
pub fn angle_error(got: Quat, want: na::Quaternion<f64>) -> f64 {
    rotation_angle64(to_f64(got), want)
}

fn to_reference(q: na::Quaternion<f64>) -> Quat64 {
    Quat64 {
        w: q.w,
        x: q.i,
        y: q.j,
        z: q.k,
    }
}

fn from_reference(q: Quat64) -> na::Quaternion<f64> {
    na::Quaternion::new(q.w, q.x, q.y, q.z)
}

/// The notes' power operator in f64: `phi = atan2(|v|, w)`,
/// `(cos(alpha phi), sin(alpha phi) v/|v|)`; a pure real negative `q`
/// turns about x.
pub fn pow64(q: na::Quaternion<f64>, alpha: f64) -> na::Quaternion<f64> {
    from_reference(to_reference(q).pow(alpha))
}

/// `pow(cn(q1 q0^-1), alpha) q0` in f64, on the normalized inputs.
pub fn slerp64(
    q0: na::Quaternion<f64>,
    q1: na::Quaternion<f64>,
    alpha: f64,
) -> na::Quaternion<f64> {
    from_reference(Quat64::slerp(
        to_reference(q0.normalize()),
        to_reference(q1.normalize()),
        alpha,
    ))
}

/// The rotation of the Euler angles `(a, b, c)` in f64: the product of the
/// three axis rotations of `order`, read from its name: `R_i(a) R_j(b) R_k(c)`
/// for an intrinsic order `IJK`, `R_k(c) R_j(b) R_i(a)` for an extrinsic
/// `IJKEx` (each about the fixed axes, first axis first).
///
/// ```
/// use rigtform::{EulerRot, Quat};
/// use rigtform_testkit::{angle_error, euler64};
/// let q = Quat::from_euler(EulerRot::ZYX, 0.1, 0.2, 0.3);
/// assert!(angle_error(q, euler64(EulerRot::ZYX, 0.1, 0.2, 0.3)) < 1e-6);
/// let q = Quat::from_euler(EulerRot::XYXEx, 0.1, 0.2, 0.3);
/// assert!(angle_error(q, euler64(EulerRot::XYXEx, 0.1, 0.2, 0.3)) < 1e-6);
/// ```
pub fn euler64(order: EulerRot, a: f64, b: f64, c: f64) -> na::Quaternion<f64> {
    let axis = |letter: u8| match letter {
        b'X' => na::Vector3::x_axis(),
        b'Y' => na::Vector3::y_axis(),
        _ => na::Vector3::z_axis(),
    };
    let name = format!("{order:?}");
    let n = name.as_bytes();
    let r = |letter, angle| na::UnitQuaternion::from_axis_angle(&axis(letter), angle);
    let (ra, rb, rc) = (r(n[0], a), r(n[1], b), r(n[2], c));
    if name.ends_with("Ex") {
        (rc * rb * ra).into_inner()
    } else {
        (ra * rb * rc).into_inner()
    }
}
