//! Conversions to and from [nalgebra](https://docs.rs/nalgebra) 0.35
//! (feature `nalgebra`, without nalgebra's default `std`): `From` both
//! ways for [`Quat`] (`Quaternion<f32>` and `UnitQuaternion<f32>`),
//! [`Cvec3`] (`Vector3<f32>` and `Point3<f32>`), [`Cvec4`]
//! (`Vector4<f32>`), [`Matrix3`] (`Matrix3<f32>`), [`Matrix4`]
//! (`Matrix4<f32>`) and [`RigTForm`]
//! (`Isometry3<f32>`), each exact, component by component; and a
//! `RigTForm` from a `Matrix4<f32>` with `TryFrom`, which checks that the
//! matrix is rigid.
//!
//! nalgebra 0.35 needs Rust 1.89; the rest of the crate builds with 1.84.
//!
//! nalgebra's `Quaternion::new(w, i, j, k)` takes the scalar first, as
//! [`Quat::from_wxyz`]; its storage, like this crate's, is `i, j, k, w`.
//! A `Quat` becomes a `UnitQuaternion` as it is, without normalizing
//! (`new_unchecked`): the crate's rotations are unit already, and the
//! round trip stays exact.
//!
//! ```
//! use nalgebra as na;
//! use rigtform::{Cvec3, Quat, RigTForm};
//! let q = Quat::from_rotation_z(0.5);
//! let u: na::UnitQuaternion<f32> = q.into();
//! assert!((u.angle() - 0.5).abs() < 1e-6);
//! assert_eq!(Quat::from(u), q);
//!
//! let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), q);
//! let iso: na::Isometry3<f32> = a.into();
//! assert_eq!(RigTForm::from(iso), a);
//! ```

use nalgebra as na;

use crate::{Cvec3, Cvec4, Matrix3, Matrix4, Quat, RigTForm};

impl From<na::Quaternion<f32>> for Quat {
    /// `Quaternion::new(w, i, j, k)` to `Quat::from_wxyz(w, i, j, k)`, exact.
    #[inline]
    fn from(q: na::Quaternion<f32>) -> Self {
        Self::from_wxyz(q.w, q.i, q.j, q.k)
    }
}

impl From<Quat> for na::Quaternion<f32> {
    /// Exact, component by component.
    #[inline]
    fn from(q: Quat) -> Self {
        na::Quaternion::new(q.w, q.x, q.y, q.z)
    }
}

impl From<na::UnitQuaternion<f32>> for Quat {
    /// Exact, component by component.
    #[inline]
    fn from(q: na::UnitQuaternion<f32>) -> Self {
        q.into_inner().into()
    }
}

impl From<Quat> for na::UnitQuaternion<f32> {
    /// Exact, without normalizing (nalgebra's `new_unchecked`).
    ///
    /// # Preconditions
    ///
    /// `q` is a unit quaternion, as every rotation of this crate is;
    /// [`Quat::normalize`] one that has drifted.
    #[inline]
    fn from(q: Quat) -> Self {
        na::UnitQuaternion::new_unchecked(q.into())
    }
}

impl From<na::Vector3<f32>> for Cvec3 {
    #[inline]
    fn from(v: na::Vector3<f32>) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Cvec3> for na::Vector3<f32> {
    #[inline]
    fn from(v: Cvec3) -> Self {
        na::Vector3::new(v.x, v.y, v.z)
    }
}

impl From<na::Point3<f32>> for Cvec3 {
    #[inline]
    fn from(p: na::Point3<f32>) -> Self {
        Self::new(p.x, p.y, p.z)
    }
}

impl From<Cvec3> for na::Point3<f32> {
    #[inline]
    fn from(p: Cvec3) -> Self {
        na::Point3::new(p.x, p.y, p.z)
    }
}

impl From<na::Vector4<f32>> for Cvec4 {
    #[inline]
    fn from(v: na::Vector4<f32>) -> Self {
        Self::new(v.x, v.y, v.z, v.w)
    }
}

impl From<Cvec4> for na::Vector4<f32> {
    #[inline]
    fn from(v: Cvec4) -> Self {
        na::Vector4::new(v.x, v.y, v.z, v.w)
    }
}

impl From<na::Matrix4<f32>> for Matrix4 {
    /// Column by column (both store column-major), exact.
    #[inline]
    fn from(m: na::Matrix4<f32>) -> Self {
        let mut cols = [0.0; 16];
        cols.copy_from_slice(m.as_slice());
        Self::from_cols_array(&cols)
    }
}

impl From<Matrix4> for na::Matrix4<f32> {
    /// Column by column, exact.
    #[inline]
    fn from(m: Matrix4) -> Self {
        na::Matrix4::from_column_slice(&m.to_cols_array())
    }
}

impl From<na::Matrix3<f32>> for Matrix3 {
    /// Column by column (both store column-major), exact.
    #[inline]
    fn from(m: na::Matrix3<f32>) -> Self {
        let mut cols = [0.0; 9];
        cols.copy_from_slice(m.as_slice());
        Self::from_cols_array(&cols)
    }
}

impl From<Matrix3> for na::Matrix3<f32> {
    /// Column by column, exact.
    #[inline]
    fn from(m: Matrix3) -> Self {
        na::Matrix3::from_column_slice(&m.to_cols_array())
    }
}

impl TryFrom<na::Matrix4<f32>> for RigTForm {
    type Error = crate::NotRigid;

    /// The rigid body transform of a homogeneous matrix that holds one, as
    /// [`RigTForm::try_from`] a [`Matrix4`] (nalgebra's
    /// `na::try_convert::<_, Isometry3<f32>>(m)`): [`NotRigid`](crate::NotRigid)
    /// for a scale, a shear, a mirror or a projection.
    fn try_from(m: na::Matrix4<f32>) -> Result<Self, crate::NotRigid> {
        RigTForm::try_from(Matrix4::from(m))
    }
}

impl From<na::Isometry3<f32>> for RigTForm {
    /// The translation and the rotation, exact: an `Isometry3` is a
    /// `RigTForm { t, r }` by another name.
    #[inline]
    fn from(iso: na::Isometry3<f32>) -> Self {
        Self::new(iso.translation.vector.into(), iso.rotation.into())
    }
}

impl From<RigTForm> for na::Isometry3<f32> {
    /// The translation and the rotation, exact.
    ///
    /// # Preconditions
    ///
    /// `a.r` is a unit quaternion.
    #[inline]
    fn from(a: RigTForm) -> Self {
        na::Isometry3 {
            rotation: a.r.into(),
            translation: na::Translation3::from(na::Vector3::from(a.t)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn bits<const N: usize>(a: [f32; N]) -> [u32; N] {
        a.map(f32::to_bits)
    }

    #[test]
    fn round_trips_are_exact() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(32);
        for _ in 0..10_000 {
            let c: [f32; 16] = core::array::from_fn(|_| f32::from_bits(rng.random()));
            let q = Quat::from_array([c[0], c[1], c[2], c[3]]);
            assert_eq!(
                bits(Quat::from(na::Quaternion::from(q)).to_array()),
                bits(q.to_array())
            );
            assert_eq!(
                bits(Quat::from(na::UnitQuaternion::from(q)).to_array()),
                bits(q.to_array())
            );
            let v = Cvec3::new(c[4], c[5], c[6]);
            assert_eq!(
                bits(Cvec3::from(na::Vector3::from(v)).to_array()),
                bits(v.to_array())
            );
            assert_eq!(
                bits(Cvec3::from(na::Point3::from(v)).to_array()),
                bits(v.to_array())
            );
            let p = Cvec4::new(c[7], c[8], c[9], c[10]);
            assert_eq!(
                bits(Cvec4::from(na::Vector4::from(p)).to_array()),
                bits(p.to_array())
            );
            let m = Matrix4::from_cols_array(&c);
            assert_eq!(
                bits(Matrix4::from(na::Matrix4::from(m)).to_cols_array()),
                bits(c)
            );
            let c9: [f32; 9] = core::array::from_fn(|i| c[i]);
            let m3 = Matrix3::from_cols_array(&c9);
            assert_eq!(
                bits(Matrix3::from(na::Matrix3::from(m3)).to_cols_array()),
                bits(c9)
            );
            let a = RigTForm::new(v, q);
            let back = RigTForm::from(na::Isometry3::from(a));
            assert_eq!(bits(back.t.to_array()), bits(a.t.to_array()));
            assert_eq!(bits(back.r.to_array()), bits(a.r.to_array()));
        }
    }

    /// nalgebra's own constructors and operations on the converted values
    /// give this crate's results.
    #[test]
    fn operations_agree_with_nalgebra() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(33);
        for _ in 0..10_000 {
            let mut c = || rng.random_range(-3.0f32..3.0);
            let (axis, angle) = (Cvec3::new(c(), c(), c()), c());
            let ours = Quat::from_axis_angle(axis, angle);
            let theirs = na::UnitQuaternion::from_axis_angle(
                &na::Unit::new_normalize(na::Vector3::from(axis)),
                angle,
            );
            assert!(ours.angle_to(theirs.into()) < 1e-6);
            // The storage orders agree: nalgebra's coords are i, j, k, w.
            assert_eq!(theirs.coords.as_slice(), &Quat::from(theirs).to_array());
            let t = Cvec3::new(c(), c(), c());
            let a = RigTForm::new(t, ours);
            let iso = na::Isometry3::from(a);
            let p = Cvec3::new(c(), c(), c());
            let mapped = Cvec3::from(iso * na::Point3::from(p));
            assert!((mapped - a.transform_point(p)).norm() < 1e-5);
            let m = na::Matrix4::from(Matrix4::from(a));
            let theirs_m = iso.to_homogeneous();
            assert!((m - theirs_m).abs().max() < 1e-6);
            let inv = RigTForm::from(iso.inverse());
            assert!((inv.t - a.inv().t).norm() < 1e-5 && inv.r.angle_to(a.inv().r) < 1e-6);
            // A matrix that holds a rigid transform comes back where
            // nalgebra's try_convert finds its isometry, and one that
            // scales does not, in either crate.
            let back = RigTForm::try_from(theirs_m).expect("rigid");
            let iso_back: na::Isometry3<f32> = na::try_convert(theirs_m).expect("rigid");
            assert!((back.t - Cvec3::from(iso_back.translation.vector)).norm() < 1e-6);
            assert!(back.r.angle_to(iso_back.rotation.into()) < 1e-6);
            let scaled = theirs_m * na::Matrix4::new_scaling(1.5);
            assert!(RigTForm::try_from(scaled).is_err());
            assert!(na::try_convert::<_, na::Isometry3<f32>>(scaled).is_none());
        }
    }
}
