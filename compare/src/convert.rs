//! Conversions from plain arrays (quaternions `[w, x, y, z]`, vectors
//! `[x, y, z]`) into each library's types, so that every library gets the
//! same numbers.

pub fn rig_quat(q: [f32; 4]) -> rigtform::Quat {
    let [w, x, y, z] = q;
    rigtform::Quat::from_wxyz(w, x, y, z)
}
pub fn rig_vec(v: [f32; 3]) -> rigtform::Cvec3 {
    rigtform::Cvec3::from_array(v)
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
