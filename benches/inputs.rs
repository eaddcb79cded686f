//! The pre-generated inputs every library is timed on, and their
//! conversions into each library's types. `benches/ops.rs` times every
//! library on these inputs; `examples/accuracy.rs` uses the conversions.
//! The inputs come from `tests/common`'s `Draws`, as the tests' and the
//! accuracy report's do (each includer declares `mod common`).
#![allow(dead_code)] // each user needs a different part

/// One set of random inputs, drawn once from a fixed seed.
pub struct Inputs {
    /// Uniformly distributed unit quaternions `[w, x, y, z]`.
    pub a: Vec<[f32; 4]>,
    /// A second, independent set of them.
    pub b: Vec<[f32; 4]>,
    /// Vectors with components in [-10, 10] (also the translations).
    pub v: Vec<[f32; 3]>,
    /// A second set of vectors.
    pub u: Vec<[f32; 3]>,
    /// Interpolation parameters in [0, 1].
    pub alpha: Vec<f32>,
}

impl Inputs {
    /// `n` of each input, from the seed `seed`.
    pub fn new(n: usize, seed: u64) -> Self {
        let mut d = crate::common::Draws::new(seed);
        let quats = |d: &mut crate::common::Draws| -> Vec<[f32; 4]> {
            (0..n)
                .map(|_| {
                    let q = d.unit_quat();
                    [q.w, q.x, q.y, q.z]
                })
                .collect()
        };
        let (a, b) = (quats(&mut d), quats(&mut d));
        let vec3s = |d: &mut crate::common::Draws| -> Vec<[f32; 3]> {
            (0..n)
                .map(|_| core::array::from_fn(|_| d.uniform(-10.0, 10.0) as f32))
                .collect()
        };
        let (v, u) = (vec3s(&mut d), vec3s(&mut d));
        let alpha = (0..n).map(|_| d.uniform(0.0, 1.0) as f32).collect();
        Self { a, b, v, u, alpha }
    }
}

pub fn rig_quat([w, x, y, z]: [f32; 4]) -> rigtform::Quat {
    rigtform::Quat::new(w, x, y, z)
}
pub fn rig_vec([x, y, z]: [f32; 3]) -> rigtform::Cvec3 {
    rigtform::Cvec3::new(x, y, z)
}
pub fn rig_tform(t: [f32; 3], r: [f32; 4]) -> rigtform::RigTForm {
    rigtform::RigTForm::new(rig_vec(t), rig_quat(r))
}

pub fn glam_quat([w, x, y, z]: [f32; 4]) -> glam::Quat {
    glam::Quat::from_xyzw(x, y, z, w)
}
pub fn glam_vec(v: [f32; 3]) -> glam::Vec3 {
    glam::Vec3::from_array(v)
}
pub fn glam_scalar_quat([w, x, y, z]: [f32; 4]) -> glam_scalar::Quat {
    glam_scalar::Quat::from_xyzw(x, y, z, w)
}
pub fn glam_scalar_vec(v: [f32; 3]) -> glam_scalar::Vec3 {
    glam_scalar::Vec3::from_array(v)
}

pub fn na_quat([w, x, y, z]: [f32; 4]) -> nalgebra::UnitQuaternion<f32> {
    nalgebra::UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(w, x, y, z))
}
pub fn na_vec([x, y, z]: [f32; 3]) -> nalgebra::Vector3<f32> {
    nalgebra::Vector3::new(x, y, z)
}
pub fn na_iso(t: [f32; 3], r: [f32; 4]) -> nalgebra::Isometry3<f32> {
    nalgebra::Isometry3::from_parts(na_vec(t).into(), na_quat(r))
}

pub fn mm_quat([w, x, y, z]: [f32; 4]) -> micromath::Quaternion {
    micromath::Quaternion::new(w, x, y, z)
}
pub fn mm_vec([x, y, z]: [f32; 3]) -> micromath::vector::F32x3 {
    micromath::vector::F32x3 { x, y, z }
}

pub fn cg_quat([w, x, y, z]: [f32; 4]) -> cgmath::Quaternion<f32> {
    cgmath::Quaternion::new(w, x, y, z)
}
pub fn cg_vec([x, y, z]: [f32; 3]) -> cgmath::Vector3<f32> {
    cgmath::Vector3::new(x, y, z)
}
pub fn cg_decomposed(
    t: [f32; 3],
    r: [f32; 4],
) -> cgmath::Decomposed<cgmath::Vector3<f32>, cgmath::Quaternion<f32>> {
    cgmath::Decomposed {
        scale: 1.0,
        rot: cg_quat(r),
        disp: cg_vec(t),
    }
}
