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
//!
//! [`mint::IntoMint`] names each type's mint counterpart, for code that is
//! generic over math libraries: `Cvec3` is a `mint::Vector3` (a point
//! converts to `mint::Point3` with `From` only), `Cvec4` a `mint::Vector4`,
//! `Quat` a `mint::Quaternion` and `Matrix4` a `mint::ColumnMatrix4`.
//! `RigTForm` has no mint counterpart.
//!
//! ```
//! use mint::IntoMint;
//! fn to_mint<T: IntoMint>(value: T) -> T::MintType {
//!     value.into()
//! }
//! let m = to_mint(rigtform::Quat::IDENTITY);
//! assert_eq!((m.s, m.v.z), (1.0, 0.0));
//! ```

use crate::{Cvec3, Cvec4, Matrix3, Matrix4, Quat};

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
        Self::from_wxyz(q.s, q.v.x, q.v.y, q.v.z)
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

impl From<mint::ColumnMatrix3<f32>> for Matrix3 {
    fn from(m: mint::ColumnMatrix3<f32>) -> Self {
        Self::from_cols(m.x.into(), m.y.into(), m.z.into())
    }
}

impl From<Matrix3> for mint::ColumnMatrix3<f32> {
    fn from(m: Matrix3) -> Self {
        let [x, y, z] = m.cols;
        Self {
            x: x.into(),
            y: y.into(),
            z: z.into(),
        }
    }
}

impl mint::IntoMint for Matrix3 {
    type MintType = mint::ColumnMatrix3<f32>;
}

impl mint::IntoMint for Cvec3 {
    type MintType = mint::Vector3<f32>;
}

impl mint::IntoMint for Cvec4 {
    type MintType = mint::Vector4<f32>;
}

impl mint::IntoMint for Quat {
    type MintType = mint::Quaternion<f32>;
}

impl mint::IntoMint for Matrix4 {
    type MintType = mint::ColumnMatrix4<f32>;
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

    /// Fails to compile if a type loses `IntoMint`, or names another mint
    /// type; the conversion it names is the exact one.
    #[test]
    fn into_mint_names_each_types_counterpart() {
        fn via<T: mint::IntoMint>(value: T) -> T::MintType {
            value.into()
        }
        let v: mint::Vector3<f32> = via(Cvec3::new(1.0, 2.0, 3.0));
        assert_eq!((v.x, v.y, v.z), (1.0, 2.0, 3.0));
        let v4: mint::Vector4<f32> = via(Cvec4::new(1.0, 2.0, 3.0, 4.0));
        assert_eq!(v4.w, 4.0);
        let q: mint::Quaternion<f32> = via(Quat::from_wxyz(1.0, 2.0, 3.0, 4.0));
        assert_eq!((q.s, q.v.x, q.v.z), (1.0, 2.0, 4.0));
        let m: mint::ColumnMatrix4<f32> = via(Matrix4::from_translation(Cvec3::X));
        assert_eq!(m.w.x, 1.0);
    }
}
