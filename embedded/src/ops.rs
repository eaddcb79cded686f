//! The operations that `bin/bench.rs` counts instructions of and
//! `bin/size.rs` measures the flash of: rigtform's, and the same operation
//! of glam (built with libm), nalgebra (libm) and micromath, where each has
//! it. Every operation has one signature, so that the bench can walk a
//! table and the size binary can name one.

use rigtform::animation::{Interpolation, Sampler};
use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};

#[cfg(feature = "attitude-peers")]
mod attitude;
#[cfg(feature = "attitude-peers")]
pub use attitude::*;

/// The inputs of every operation: two unit quaternions, two vectors (also
/// the translations of two rigid body transforms) and a parameter in [0, 1].
#[derive(Clone, Copy, Debug)]
pub struct Input {
    /// First unit quaternion, `[w, x, y, z]`.
    pub a: [f32; 4],
    /// Second unit quaternion.
    pub b: [f32; 4],
    /// First vector.
    pub u: [f32; 3],
    /// Second vector.
    pub v: [f32; 3],
    /// Interpolation parameter.
    pub t: f32,
}

/// Room for any result (a quaternion, a vector, a transform, a matrix);
/// each operation writes only the entries its result needs.
pub type Output = [f32; 16];

/// One operation of one library: reads the input, writes the result.
pub type Op = fn(&Input, &mut Output);

fn put(o: &mut Output, r: &[f32]) {
    for (slot, &x) in o.iter_mut().zip(r) {
        *slot = x;
    }
}

fn quat(q: [f32; 4]) -> Quat {
    Quat::from_wxyz(q[0], q[1], q[2], q[3])
}
fn vec3(v: [f32; 3]) -> Cvec3 {
    Cvec3::new(v[0], v[1], v[2])
}
fn rig(x: &Input) -> (RigTForm, RigTForm) {
    (
        RigTForm::new(vec3(x.u), quat(x.a)),
        RigTForm::new(vec3(x.v), quat(x.b)),
    )
}
fn rig_out(o: &mut Output, r: RigTForm) {
    put(o, &[r.t.x, r.t.y, r.t.z, r.r.w, r.r.x, r.r.y, r.r.z]);
}
fn q_out(o: &mut Output, q: Quat) {
    put(o, &[q.w, q.x, q.y, q.z]);
}

/// The calibration: no operation, the input's first quaternion copied out.
pub fn empty(x: &Input, o: &mut Output) {
    put(o, &x.a);
}

pub fn rigtform_mul(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a) * quat(x.b));
}
pub fn rigtform_rotate(x: &Input, o: &mut Output) {
    let v = quat(x.a) * vec3(x.u);
    put(o, &[v.x, v.y, v.z]);
}
pub fn rigtform_normalize(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a).normalize());
}
pub fn rigtform_pow(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a).pow(x.t));
}
pub fn rigtform_slerp(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a).slerp(quat(x.b), x.t));
}
pub fn rigtform_nlerp(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a).nlerp(quat(x.b), x.t));
}
pub fn rigtform_mul_renormalized(x: &Input, o: &mut Output) {
    q_out(o, quat(x.a).mul_renormalized(quat(x.b)));
}
pub fn rigtform_rig_mul(x: &Input, o: &mut Output) {
    let (a, b) = rig(x);
    rig_out(o, a * b);
}
pub fn rigtform_rig_inv(x: &Input, o: &mut Output) {
    rig_out(o, rig(x).0.inv());
}
pub fn rigtform_rig_apply(x: &Input, o: &mut Output) {
    let p = rig(x).0 * Cvec4::from_point(vec3(x.v));
    put(o, &[p.x, p.y, p.z, p.w]);
}
pub fn rigtform_interpolate(x: &Input, o: &mut Output) {
    let (a, b) = rig(x);
    rig_out(o, a.interpolate(b, x.t));
}
/// Four keys from the input, for the splines: `a`, `b` and the same two
/// with their components rotated (still unit, other rotations), so that a
/// segment between the middle keys has four distinct neighbours. Moves
/// only: no arithmetic beyond the spline's own.
fn keys(x: &Input) -> [Quat; 4] {
    let [aw, ax, ay, az] = x.a;
    let [bw, bx, by, bz] = x.b;
    [
        quat(x.a),
        quat(x.b),
        Quat::from_wxyz(ax, ay, az, aw),
        Quat::from_wxyz(by, bz, bw, bx),
    ]
}
/// One evaluation inside the middle segment of four keys.
pub fn rigtform_catmull_rom(x: &Input, o: &mut Output) {
    q_out(o, Quat::catmull_rom(&keys(x), 1.0 + x.t));
}
/// The same for rigid body transforms, the translations `u`, `v`, `v`
/// and `u` swizzled alike.
pub fn rigtform_rig_catmull_rom(x: &Input, o: &mut Output) {
    let r = keys(x);
    let ([ux, uy, uz], [vx, vy, vz]) = (x.u, x.v);
    let t = [
        vec3(x.u),
        vec3(x.v),
        Cvec3::new(uy, uz, ux),
        Cvec3::new(vz, vx, vy),
    ];
    let frames: [RigTForm; 4] = core::array::from_fn(|i| RigTForm::new(t[i], r[i]));
    rig_out(o, RigTForm::catmull_rom(&frames, 1.0 + x.t));
}
/// A glTF rotation channel of eight keys (turns about one axis, 0.35 rad
/// apart as quaternions), at times 0.5 to 0.9 s apart.
const GLTF_TIMES: [f32; 8] = [0.0, 0.6, 1.5, 2.1, 3.0, 3.9, 4.4, 5.2];
const GLTF_KEYS: [Quat; 8] = [
    Quat {
        w: 1.0,
        x: 0.0,
        y: 0.0,
        z: 0.0,
    },
    Quat {
        w: 0.939_372_7,
        x: 0.205_738_7,
        y: 0.0,
        z: 0.274_318_25,
    },
    Quat {
        w: 0.764_842_2,
        x: 0.386_530_6,
        y: 0.0,
        z: 0.515_374_1,
    },
    Quat {
        w: 0.497_571_05,
        x: 0.520_453_94,
        y: 0.0,
        z: 0.693_938_6,
    },
    Quat {
        w: 0.169_967_14,
        x: 0.591_269_84,
        y: 0.0,
        z: 0.788_359_8,
    },
    Quat {
        w: -0.178_246_06,
        x: 0.590_391_6,
        y: 0.0,
        z: 0.787_188_8,
    },
    Quat {
        w: -0.504_846_1,
        x: 0.517_925_6,
        y: 0.0,
        z: 0.690_567_5,
    },
    Quat {
        w: -0.770_231_25,
        x: 0.382_658_8,
        y: 0.0,
        z: 0.510_211_8,
    },
];
/// The same keys as CUBICSPLINE values, each between an in- and an
/// out-tangent (the same small one).
const GLTF_CUBIC: [Quat; 24] = {
    const T: Quat = Quat {
        w: -0.2,
        x: 0.1,
        y: 0.05,
        z: 0.15,
    };
    let mut v = [T; 24];
    let mut k = 0;
    while k < 8 {
        v[3 * k + 1] = GLTF_KEYS[k];
        k += 1;
    }
    v
};
/// Checking the channel alone (`Sampler::new`: eight times, eight keys).
pub fn rigtform_gltf_new(_x: &Input, o: &mut Output) {
    let ok = Sampler::new(
        Interpolation::Linear,
        channel(&GLTF_TIMES),
        channel(&GLTF_KEYS),
    )
    .is_ok();
    o[0] = f32::from(u8::from(ok));
}
/// Checking the CUBICSPLINE channel alone (eight times, 24 values).
pub fn rigtform_gltf_new_cubic(_x: &Input, o: &mut Output) {
    let ok = Sampler::new(
        Interpolation::CubicSpline,
        channel(&GLTF_TIMES),
        channel(&GLTF_CUBIC),
    )
    .is_ok();
    o[0] = f32::from(u8::from(ok));
}
/// Checking the LINEAR channel and sampling it once, at a time from `t`.
pub fn rigtform_gltf_linear(x: &Input, o: &mut Output) {
    if let Ok(s) = Sampler::new(
        Interpolation::Linear,
        channel(&GLTF_TIMES),
        channel(&GLTF_KEYS),
    ) {
        q_out(o, s.sample(5.2 * x.t));
    }
}
/// Checking the CUBICSPLINE channel and sampling it once.
pub fn rigtform_gltf_cubic(x: &Input, o: &mut Output) {
    if let Ok(s) = Sampler::new(
        Interpolation::CubicSpline,
        channel(&GLTF_TIMES),
        channel(&GLTF_CUBIC),
    ) {
        q_out(o, s.sample(5.2 * x.t));
    }
}
/// A channel's times or values as a firmware reads them from memory: the
/// compiler cannot check them once at build time (at opt-level 3 it did,
/// and left the checking code out of the firmware).
fn channel<T>(values: &[T]) -> &[T] {
    core::hint::black_box(values)
}
pub fn rigtform_matrix(x: &Input, o: &mut Output) {
    put(o, &Matrix4::from(rig(x).0).to_cols_array());
}

fn glam_quat(q: [f32; 4]) -> glam::Quat {
    glam::Quat::from_xyzw(q[1], q[2], q[3], q[0])
}
fn glam_out(o: &mut Output, q: glam::Quat) {
    put(o, &[q.w, q.x, q.y, q.z]);
}
pub fn glam_mul(x: &Input, o: &mut Output) {
    glam_out(o, glam_quat(x.a) * glam_quat(x.b));
}
pub fn glam_rotate(x: &Input, o: &mut Output) {
    let v = glam_quat(x.a) * glam::Vec3::from_array(x.u);
    put(o, &[v.x, v.y, v.z]);
}
pub fn glam_normalize(x: &Input, o: &mut Output) {
    glam_out(o, glam_quat(x.a).normalize());
}
pub fn glam_slerp(x: &Input, o: &mut Output) {
    glam_out(o, glam_quat(x.a).slerp(glam_quat(x.b), x.t));
}
pub fn glam_nlerp(x: &Input, o: &mut Output) {
    glam_out(o, glam_quat(x.a).lerp(glam_quat(x.b), x.t));
}
/// A rigid body transform as glam users write it: (translation, rotation).
pub fn glam_interpolate(x: &Input, o: &mut Output) {
    let (t0, t1) = (glam::Vec3::from_array(x.u), glam::Vec3::from_array(x.v));
    let (r0, r1) = (glam_quat(x.a), glam_quat(x.b));
    let (t, r) = (t0.lerp(t1, x.t), r0.slerp(r1, x.t));
    put(o, &[t.x, t.y, t.z, r.w, r.x, r.y, r.z]);
}
/// glam has no spline: its nearest equivalent is the evaluation alone,
/// de Casteljau's six slerps over four rotations given as control points
/// (the keys of `rigtform_catmull_rom`), without the two powers that make
/// control points from keys.
pub fn glam_six_slerps(x: &Input, o: &mut Output) {
    let [p0, p1, p2, p3] = keys(x).map(|q| glam_quat([q.w, q.x, q.y, q.z]));
    let u = x.t;
    let (a, b, c) = (p0.slerp(p1, u), p1.slerp(p2, u), p2.slerp(p3, u));
    glam_out(o, a.slerp(b, u).slerp(b.slerp(c, u), u));
}
pub fn glam_matrix(x: &Input, o: &mut Output) {
    let m = glam::Mat4::from_rotation_translation(glam_quat(x.a), glam::Vec3::from_array(x.u));
    put(o, &m.to_cols_array());
}

fn na_quat(q: [f32; 4]) -> nalgebra::UnitQuaternion<f32> {
    nalgebra::UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]))
}
fn na_out(o: &mut Output, q: nalgebra::UnitQuaternion<f32>) {
    put(o, &[q.w, q.i, q.j, q.k]);
}
fn na_iso(t: [f32; 3], r: [f32; 4]) -> nalgebra::Isometry3<f32> {
    nalgebra::Isometry3::from_parts(nalgebra::Translation3::new(t[0], t[1], t[2]), na_quat(r))
}
fn na_iso_out(o: &mut Output, a: nalgebra::Isometry3<f32>) {
    let (t, r) = (a.translation.vector, a.rotation);
    put(o, &[t.x, t.y, t.z, r.w, r.i, r.j, r.k]);
}
pub fn nalgebra_mul(x: &Input, o: &mut Output) {
    na_out(o, na_quat(x.a) * na_quat(x.b));
}
pub fn nalgebra_rotate(x: &Input, o: &mut Output) {
    let v = na_quat(x.a) * nalgebra::Vector3::new(x.u[0], x.u[1], x.u[2]);
    put(o, &[v.x, v.y, v.z]);
}
pub fn nalgebra_normalize(x: &Input, o: &mut Output) {
    let q = na_quat(x.a).into_inner().normalize();
    put(o, &[q.w, q.i, q.j, q.k]);
}
pub fn nalgebra_pow(x: &Input, o: &mut Output) {
    na_out(o, na_quat(x.a).powf(x.t));
}
pub fn nalgebra_slerp(x: &Input, o: &mut Output) {
    na_out(o, na_quat(x.a).slerp(&na_quat(x.b), x.t));
}
pub fn nalgebra_nlerp(x: &Input, o: &mut Output) {
    na_out(o, na_quat(x.a).nlerp(&na_quat(x.b), x.t));
}
pub fn nalgebra_rig_mul(x: &Input, o: &mut Output) {
    na_iso_out(o, na_iso(x.u, x.a) * na_iso(x.v, x.b));
}
pub fn nalgebra_rig_inv(x: &Input, o: &mut Output) {
    na_iso_out(o, na_iso(x.u, x.a).inverse());
}
pub fn nalgebra_rig_apply(x: &Input, o: &mut Output) {
    let p = na_iso(x.u, x.a) * nalgebra::Point3::new(x.v[0], x.v[1], x.v[2]);
    put(o, &[p.x, p.y, p.z, 1.0]);
}
pub fn nalgebra_interpolate(x: &Input, o: &mut Output) {
    na_iso_out(o, na_iso(x.u, x.a).lerp_slerp(&na_iso(x.v, x.b), x.t));
}
pub fn nalgebra_matrix(x: &Input, o: &mut Output) {
    put(o, na_iso(x.u, x.a).to_homogeneous().as_slice());
}

fn mm_quat(q: [f32; 4]) -> micromath::Quaternion {
    micromath::Quaternion::new(q[0], q[1], q[2], q[3])
}
pub fn micromath_mul(x: &Input, o: &mut Output) {
    put(o, &(mm_quat(x.a) * mm_quat(x.b)).to_array());
}
pub fn micromath_rotate(x: &Input, o: &mut Output) {
    let v = mm_quat(x.a).rotate(micromath::vector::F32x3 {
        x: x.u[0],
        y: x.u[1],
        z: x.u[2],
    });
    put(o, &[v.x, v.y, v.z]);
}
pub fn micromath_normalize(x: &Input, o: &mut Output) {
    put(o, &mm_quat(x.a).normalize().to_array());
}

/// One operation of one library: the table's names for it, and the
/// function of this module that runs it.
pub struct Entry {
    /// The operation, as the README's table names it.
    pub operation: &'static str,
    /// The library.
    pub library: &'static str,
    /// The name of the function (what `RIGTFORM_SIZE_OP` names for
    /// `bin/size.rs`).
    pub function: &'static str,
    /// The function.
    pub op: Op,
}

/// An [`Entry`] of `function`, its name spelled once.
macro_rules! entry {
    ($operation:literal, $library:literal, $function:ident) => {
        Entry {
            operation: $operation,
            library: $library,
            function: stringify!($function),
            op: $function,
        }
    };
}

/// Every operation. `bin/bench.rs` walks this table in order and announces
/// each entry (`operation|library|function`); `cargo xtask` takes the rows
/// of its table, and the functions it builds `bin/size.rs` with, from
/// that announcement.
pub const OPS: &[Entry] = &[
    entry!("q * q", "rigtform", rigtform_mul),
    entry!("q * q", "glam", glam_mul),
    entry!("q * q", "nalgebra", nalgebra_mul),
    entry!("q * q", "micromath", micromath_mul),
    entry!("rotate Cvec3", "rigtform", rigtform_rotate),
    entry!("rotate Cvec3", "glam", glam_rotate),
    entry!("rotate Cvec3", "nalgebra", nalgebra_rotate),
    entry!("rotate Cvec3", "micromath", micromath_rotate),
    entry!("normalize", "rigtform", rigtform_normalize),
    entry!("normalize", "glam", glam_normalize),
    entry!("normalize", "nalgebra", nalgebra_normalize),
    entry!("normalize", "micromath", micromath_normalize),
    entry!("pow", "rigtform", rigtform_pow),
    entry!("pow", "nalgebra", nalgebra_pow),
    entry!("slerp", "rigtform", rigtform_slerp),
    entry!("slerp", "glam", glam_slerp),
    entry!("slerp", "nalgebra", nalgebra_slerp),
    entry!("nlerp", "rigtform", rigtform_nlerp),
    entry!("nlerp", "glam", glam_nlerp),
    entry!("nlerp", "nalgebra", nalgebra_nlerp),
    entry!("q * q renormalized", "rigtform", rigtform_mul_renormalized),
    entry!("glTF sampler new, 8 keys", "rigtform", rigtform_gltf_new),
    entry!(
        "glTF sampler new, 8 keys of CUBICSPLINE",
        "rigtform",
        rigtform_gltf_new_cubic
    ),
    entry!(
        "glTF LINEAR rotation (new + sample)",
        "rigtform",
        rigtform_gltf_linear
    ),
    entry!(
        "glTF CUBICSPLINE rotation (new + sample)",
        "rigtform",
        rigtform_gltf_cubic
    ),
    entry!("RigTForm * RigTForm", "rigtform", rigtform_rig_mul),
    entry!("RigTForm * RigTForm", "nalgebra", nalgebra_rig_mul),
    entry!("RigTForm inv", "rigtform", rigtform_rig_inv),
    entry!("RigTForm inv", "nalgebra", nalgebra_rig_inv),
    entry!("RigTForm * point", "rigtform", rigtform_rig_apply),
    entry!("RigTForm * point", "nalgebra", nalgebra_rig_apply),
    entry!("RigTForm interpolate", "rigtform", rigtform_interpolate),
    entry!("RigTForm interpolate", "glam", glam_interpolate),
    entry!("RigTForm interpolate", "nalgebra", nalgebra_interpolate),
    entry!("catmull_rom", "rigtform", rigtform_catmull_rom),
    entry!("catmull_rom", "glam", glam_six_slerps),
    entry!("RigTForm catmull_rom", "rigtform", rigtform_rig_catmull_rom),
    entry!("Matrix4 from RigTForm", "rigtform", rigtform_matrix),
    entry!("Matrix4 from RigTForm", "glam", glam_matrix),
    entry!("Matrix4 from RigTForm", "nalgebra", nalgebra_matrix),
];
