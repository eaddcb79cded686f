//! The renderer's matrices: [`Matrix4`] (the projection, the model-view
//! and normal matrices of the notes' "more code") and [`Matrix3`] (a
//! shader's `mat3`), one file each (`matrix/matrix4.rs`,
//! `matrix/matrix3.rs`), what they share written once
//! (`matrix/template.rs`), and one file a role beside them:
//! `matrix/transform.rs` (glam's `Mat4` API), `matrix/camera.rs` (view and
//! projection matrices), `matrix/quat_conversions.rs` and
//! `matrix/rig_tform_conversions.rs` (the rotations and rigid transforms
//! of matrices, which the quaternions and transforms do not know of).

mod template;

mod matrix3;
mod matrix4;

mod camera;
mod quat_conversions;
mod rig_tform_conversions;
mod transform;

#[cfg(test)]
mod tests;

pub use matrix3::Matrix3;
pub use matrix4::Matrix4;
pub use rig_tform_conversions::NotRigid;
