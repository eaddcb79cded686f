//! The rigid body transform a [`Matrix4`] holds: `RigTForm::try_from`,
//! with [`NotRigid`] when it holds none, and glam's name for it
//! (`from_mat4`, deprecated: it leads to `try_from`); nalgebra's names for
//! the other way. They live with the matrices, which `RigTForm` does not
//! know of.

use core::fmt;

use crate::matrix::Matrix4;
use crate::other_names::renamed;
use crate::quat::Quat;
use crate::rigtform::RigTForm;

impl RigTForm {
    /// glam's `Affine3A::from_mat4(m)`, which keeps whatever the matrix
    /// holds: a `RigTForm` holds only a rotation and a translation, so here
    /// it is `RigTForm::try_from(m)`, which says when the matrix is not
    /// rigid ([`NotRigid`]).
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Cvec3, Matrix4, RigTForm};
    /// let m = Matrix4::from_translation(Cvec3::X);
    /// assert_eq!(RigTForm::from_mat4(m), RigTForm::try_from(m));
    /// assert!(RigTForm::from_mat4(Matrix4::from_scale(Cvec3::splat(2.0))).is_err());
    /// ```
    #[deprecated(
        since = "0.1.0",
        note = "a general matrix is not rigid: use `RigTForm::try_from(m)`, a `Result` whose \
                error `NotRigid` says how far from rigid it is (take a scale off first with \
                `Matrix4::to_scale_rotation_translation`)"
    )]
    #[inline]
    pub fn from_mat4(m: Matrix4) -> Result<Self, NotRigid> {
        Self::try_from(m)
    }

    renamed! {
        /// nalgebra's `Isometry3::to_matrix`: here `Matrix4::from(a)`.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Matrix4, RigTForm};
        /// let a = RigTForm::from_rotation_x(0.3);
        /// assert_eq!(a.to_matrix(), Matrix4::from(a));
        /// ```
        note "use `Matrix4::from(a)` (or `Matrix4::from_rig_tform`)";
        pub fn to_matrix(self) -> Matrix4 {
            Matrix4::from_rig_tform(self)
        }

        /// nalgebra's `Isometry3::to_homogeneous`, the same matrix as its
        /// `to_matrix`: here `Matrix4::from(a)` too.
        ///
        /// ```
        /// # #![allow(deprecated)]
        /// use rigtform::{Matrix4, RigTForm};
        /// let a = RigTForm::from_translation(rigtform::Cvec3::X);
        /// assert_eq!(a.to_homogeneous(), a.to_matrix());
        /// ```
        note "use `Matrix4::from(a)` (or `Matrix4::from_rig_tform`)";
        pub fn to_homogeneous(self) -> Matrix4 {
            Matrix4::from_rig_tform(self)
        }
    }
}

/// The error of [`RigTForm::try_from`] a matrix (or, with a glam feature,
/// a `glam::Affine3A` or `glam::Mat4`; with `nalgebra`, a
/// `nalgebra::Matrix4<f32>`) that is not a rigid body transform: it
/// scales, shears, mirrors or projects, or has a NaN or infinite entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NotRigid {
    /// How far the matrix is from rigid: the largest entry of
    /// `|M^T M - I|` over its upper-left 3x3 block `M`, and of the last
    /// row's distance from `[0, 0, 0, 1]`; infinite for a mirror (negative
    /// determinant), NaN for a NaN or infinite entry.
    pub deviation: f32,
}

impl fmt::Display for NotRigid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "not a rigid body transform: the matrix is {} from rotation and translation (at most {} allowed); \
             Matrix4::to_scale_rotation_translation takes a scale apart from the rotation",
            self.deviation,
            crate::accuracy::RIGID_TOLERANCE
        )
    }
}

impl core::error::Error for NotRigid {}

/// `|M^T M - I|`'s largest entry, and the last row's distance from
/// `[0, 0, 0, 1]`; infinite for a negative determinant, NaN for a
/// non-finite entry. Zero for an exact rotation and translation.
fn rigid_deviation(m: Matrix4) -> f32 {
    if !m.is_finite() {
        return f32::NAN;
    }
    let [a, b, c, d] = m.cols;
    let (a3, b3, c3) = (a.xyz(), b.xyz(), c.xyz());
    if a3.cross(b3).dot(c3) < 0.0 {
        return f32::INFINITY;
    }
    let gram = [
        a3.dot(a3) - 1.0,
        b3.dot(b3) - 1.0,
        c3.dot(c3) - 1.0,
        a3.dot(b3),
        b3.dot(c3),
        c3.dot(a3),
        a.w,
        b.w,
        c.w,
        d.w - 1.0,
    ];
    // NaN from an overflow of the dot products counts as not rigid.
    gram.iter().fold(0.0f32, |worst, e| {
        if e.abs() > worst || e.is_nan() {
            e.abs()
        } else {
            worst
        }
    })
}

impl TryFrom<Matrix4> for RigTForm {
    type Error = NotRigid;

    /// The rigid body transform a matrix holds, the inverse of
    /// [`Matrix4::from_rig_tform`]: its upper-left 3x3 block must be a
    /// rotation (orthonormal columns within
    /// [`accuracy::RIGID_TOLERANCE`](crate::accuracy::RIGID_TOLERANCE),
    /// determinant positive) and its last row `[0, 0, 0, 1]` within the
    /// same tolerance. The translation is the last column, exactly; the
    /// rotation is [`Quat::from_matrix`]'s, normalized.
    ///
    /// # Accuracy
    ///
    /// The rotation within
    /// [`accuracy::FROM_MATRIX_MAX_ANGLE_ERROR`](crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR)
    /// of the matrix's.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::from_rotation_x(0.4));
    /// let back = RigTForm::try_from(Matrix4::from(a)).unwrap();
    /// assert_eq!(back.t, a.t);
    /// assert!(back.r.angle_to(a.r) < 1e-6);
    /// assert!(RigTForm::try_from(Matrix4::from_scale(Cvec3::new(2.0, 2.0, 2.0))).is_err());
    /// ```
    fn try_from(m: Matrix4) -> Result<Self, NotRigid> {
        let deviation = rigid_deviation(m);
        if deviation.is_nan() || deviation > crate::accuracy::RIGID_TOLERANCE {
            return Err(NotRigid { deviation });
        }
        Ok(Self::new(m.cols[3].xyz(), Quat::from_matrix(m).normalize()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_draws::rig_tform;
    use crate::vec::Cvec3;
    use rand::SeedableRng;

    #[test]
    fn matrices_of_rig_tforms_come_back() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(31);
        for _ in 0..10_000 {
            let a = rig_tform(&mut rng);
            let back = RigTForm::try_from(Matrix4::from(a)).unwrap();
            assert_eq!(
                back.t.to_array().map(f32::to_bits),
                a.t.to_array().map(f32::to_bits)
            );
            assert!(back.r.angle_to(a.r) <= 2.0 * crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR);
        }
    }

    #[test]
    fn matrices_that_are_not_rigid_are_refused() {
        let mut shear = Matrix4::IDENTITY;
        shear.cols[1].x = 0.01;
        let mut projective = Matrix4::IDENTITY;
        projective.cols[2].w = -1.0;
        let mut nan = Matrix4::IDENTITY;
        nan.cols[0].y = f32::NAN;
        let mut huge = Matrix4::IDENTITY;
        huge.cols[0].x = f32::MAX;
        let cases = [
            Matrix4::from_scale(Cvec3::new(1.0, 1.0, 1.001)),
            Matrix4::from_scale(Cvec3::new(1.0, 1.0, -1.0)),
            shear,
            projective,
            nan,
            huge,
            Matrix4::from_cols_array(&[0.0; 16]),
        ];
        for m in cases {
            let e = RigTForm::try_from(m).unwrap_err();
            assert!(
                e.deviation.is_nan() || e.deviation > crate::accuracy::RIGID_TOLERANCE,
                "{m:?}"
            );
            assert!(std::format!("{e}").starts_with("not a rigid body transform"));
        }
        let mirror = RigTForm::try_from(Matrix4::from_scale(Cvec3::new(1.0, 1.0, -1.0)));
        assert_eq!(mirror.unwrap_err().deviation, f32::INFINITY);
        // Within the tolerance: accepted, and the rotation made unit.
        let nearly = Matrix4::from_scale(Cvec3::new(1.0, 1.0, 1.0 + 1e-5));
        assert!(RigTForm::try_from(nearly).unwrap().r.is_normalized());
    }

    /// glam's `Affine3A::from_mat4` and nalgebra's `Isometry3::to_matrix`,
    /// which lead to the crate's conversions, map points as glam's and
    /// nalgebra's do, and refuse what a `RigTForm` cannot hold.
    #[test]
    #[allow(deprecated)]
    fn glams_from_mat4_and_nalgebras_to_matrix_map_points_as_theirs() {
        use rand::Rng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(44);
        for _ in 0..10_000 {
            let a = rig_tform(&mut rng);
            let m = a.to_matrix();
            assert_eq!(m, Matrix4::from(a));
            let iso = nalgebra::Isometry3::from_parts(
                nalgebra::Translation3::new(a.t.x, a.t.y, a.t.z),
                nalgebra::UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(
                    a.r.w, a.r.x, a.r.y, a.r.z,
                )),
            );
            let theirs = iso.to_matrix();
            assert!(m
                .to_cols_array()
                .iter()
                .zip(theirs.as_slice())
                .all(|(x, y)| (x - y).abs() < 1e-5));
            let g = glam::Mat4::from_cols_array(&m.to_cols_array());
            let affine = glam::Affine3A::from_mat4(g);
            let ours = RigTForm::from_mat4(m).expect("rigid");
            let p = Cvec3::new(rng.random(), rng.random(), rng.random()) * 10.0;
            let gp = affine.transform_point3(glam::Vec3::from_array(p.to_array()));
            assert!((ours.transform_point(p) - Cvec3::from_array(gp.to_array())).norm() < 1e-4);
            let scaled = m * Matrix4::from_scale(Cvec3::splat(rng.random_range(1.1..3.0)));
            let e = RigTForm::from_mat4(scaled).unwrap_err();
            assert!(e.deviation > crate::accuracy::RIGID_TOLERANCE);
            assert!(std::format!("{e}").contains("to_scale_rotation_translation"));
        }
    }
}
