//! Conversions to and from [`mint`] types (feature `mint`), the
//! interchange types that glam, nalgebra and cgmath also convert to.
//!
//! `mint::Quaternion` stores the vector part `v` and the scalar `s`
//! separately, so no component order can be confused.
//!
//! ```
//! use rigtform::{Cvec3, Quat};
//! let q = Quat::from_rotation_x(0.5);
//! let m: mint::Quaternion<f32> = q.into();
//! assert_eq!((m.s, m.v.x), (q.w, q.x));
//! assert_eq!(Quat::from(m), q);
//! let v: mint::Vector3<f32> = Cvec3::new(1.0, 2.0, 3.0).into();
//! assert_eq!(Cvec3::from(v), Cvec3::new(1.0, 2.0, 3.0));
//! ```

use crate::{Cvec3, Cvec4, Matrix4, Quat};

impl From<mint::Vector3<f32>> for Cvec3 {
    fn from(v: mint::Vector3<f32>) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Cvec3> for mint::Vector3<f32> {
    fn from(v: Cvec3) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

impl From<mint::Point3<f32>> for Cvec3 {
    fn from(p: mint::Point3<f32>) -> Self {
        Self::new(p.x, p.y, p.z)
    }
}

impl From<Cvec3> for mint::Point3<f32> {
    fn from(p: Cvec3) -> Self {
        Self {
            x: p.x,
            y: p.y,
            z: p.z,
        }
    }
}

impl From<mint::Vector4<f32>> for Cvec4 {
    fn from(v: mint::Vector4<f32>) -> Self {
        Self::new(v.x, v.y, v.z, v.w)
    }
}

impl From<Cvec4> for mint::Vector4<f32> {
    fn from(v: Cvec4) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
            w: v.w,
        }
    }
}

impl From<mint::Quaternion<f32>> for Quat {
    fn from(q: mint::Quaternion<f32>) -> Self {
        Self::new(q.s, q.v.x, q.v.y, q.v.z)
    }
}

impl From<Quat> for mint::Quaternion<f32> {
    fn from(q: Quat) -> Self {
        Self {
            s: q.w,
            v: q.vector().into(),
        }
    }
}

impl From<mint::ColumnMatrix4<f32>> for Matrix4 {
    fn from(m: mint::ColumnMatrix4<f32>) -> Self {
        Self::from_cols(m.x.into(), m.y.into(), m.z.into(), m.w.into())
    }
}

impl From<Matrix4> for mint::ColumnMatrix4<f32> {
    fn from(m: Matrix4) -> Self {
        let [x, y, z, w] = m.cols;
        Self {
            x: x.into(),
            y: y.into(),
            z: z.into(),
            w: w.into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_are_exact() {
        let m = Matrix4::from_cols_array(&core::array::from_fn(|i| i as f32 - 7.5));
        let mm: mint::ColumnMatrix4<f32> = m.into();
        assert_eq!(mm.y.x, m.cols[1].x);
        assert_eq!(Matrix4::from(mm), m);
        let p: mint::Point3<f32> = Cvec3::new(1.0, -2.0, 3.0).into();
        assert_eq!(Cvec3::from(p), Cvec3::new(1.0, -2.0, 3.0));
        let v: mint::Vector4<f32> = Cvec4::new(1.0, 2.0, 3.0, 4.0).into();
        assert_eq!(Cvec4::from(v), Cvec4::new(1.0, 2.0, 3.0, 4.0));
    }
}
