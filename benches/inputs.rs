//! The pre-generated inputs every library is timed on, and their
//! conversions into each library's types. Shared by `benches/ops.rs` and
//! `examples/accuracy.rs` (through `#[path]`), so that the two measure the
//! same things.
#![allow(dead_code)] // each user needs a different part

use rand::{Rng, SeedableRng};

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

/// A unit quaternion with a uniformly distributed rotation: a point of the
/// 4-ball, kept away from the origin, projected onto the sphere.
pub fn unit_quat(rng: &mut impl Rng) -> [f32; 4] {
    loop {
        let q: [f64; 4] = core::array::from_fn(|_| rng.random_range(-1.0..1.0));
        let n2: f64 = q.iter().map(|c| c * c).sum();
        if (0.01..=1.0).contains(&n2) {
            return q.map(|c| (c / n2.sqrt()) as f32);
        }
    }
}

impl Inputs {
    /// `n` of each input, from the seed `seed`.
    pub fn new(n: usize, seed: u64) -> Self {
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        let vec3 =
            |rng: &mut rand::rngs::StdRng| core::array::from_fn(|_| rng.random_range(-10.0..10.0));
        Self {
            a: (0..n).map(|_| unit_quat(&mut rng)).collect(),
            b: (0..n).map(|_| unit_quat(&mut rng)).collect(),
            v: (0..n).map(|_| vec3(&mut rng)).collect(),
            u: (0..n).map(|_| vec3(&mut rng)).collect(),
            alpha: (0..n).map(|_| rng.random_range(0.0..1.0)).collect(),
        }
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
