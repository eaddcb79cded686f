//! The rotation of a matrix as a [`Quat`], and back: [`Quat::from_matrix`]
//! and [`Quat::from_mat3`] (by the method of `quat/from_basis.rs`), and
//! glam's and nalgebra's names for these conversions. They live with the
//! matrices, which the quaternions do not know of.

use crate::matrix::Matrix3;
use crate::matrix::Matrix4;
use crate::quat::Quat;

impl Quat {
    /// The rotation of the upper-left 3x3 block of `m`: the inverse of
    /// [`Matrix4::from_quat`], up to sign (`q` and `-q` are the same
    /// rotation; the result has `w >= 0`).
    ///
    /// # Preconditions
    ///
    /// The block is a rotation matrix (orthonormal columns, determinant +1),
    /// as [`Matrix4::from_quat`] and [`Matrix4::from_rig_tform`] make; the
    /// translation column and the last row are ignored. For any other
    /// finite block the result is still a unit quaternion, but not a
    /// meaningful rotation (remove a scale first). NaN or infinite entries,
    /// or entries beyond about 1e38 whose sums overflow, give
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::FROM_MATRIX_MAX_ANGLE_ERROR`](crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR)
    /// radians of the exact rotation of the f32 matrix, half turns included,
    /// and within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of unit norm.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat};
    /// let q = Quat::from_axis_angle(Cvec3::new(1.0, 2.0, 3.0), 3.1);
    /// let back = Quat::from_matrix(Matrix4::from_quat(q));
    /// assert!(back.angle_to(q) < 1e-6);
    /// ```
    #[doc(alias = "from_rotation_matrix")]
    #[must_use]
    pub fn from_matrix(m: Matrix4) -> Self {
        let [a, b, c, _] = m.cols;
        Self::from_basis(a.xyz(), b.xyz(), c.xyz())
    }

    /// The rotation of a 3x3 rotation matrix (glam's `from_mat3`): as
    /// [`from_matrix`](Self::from_matrix), with the same preconditions and
    /// accuracy.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3, Quat};
    /// let q = Quat::from_axis_angle(Cvec3::new(1.0, -2.0, 0.5), 2.0);
    /// assert!(Quat::from_mat3(Matrix3::from_quat(q)).angle_to(q) < 1e-6);
    /// ```
    #[must_use]
    pub fn from_mat3(m: Matrix3) -> Self {
        let [a, b, c] = m.cols;
        Self::from_basis(a, b, c)
    }

    /// nalgebra's `from_rotation_matrix`: here [`from_mat3`](Self::from_mat3)
    /// (or [`from_matrix`](Self::from_matrix) for a `Matrix4`).
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Matrix3, Quat};
    /// let m = Matrix3::from_quat(Quat::from_rotation_y(0.4));
    /// assert_eq!(Quat::from_rotation_matrix(&m), Quat::from_mat3(m));
    /// ```
    #[deprecated(since = "0.1.0", note = "use `Quat::from_mat3(m)` (by value)")]
    #[inline]
    #[must_use]
    pub fn from_rotation_matrix(m: &Matrix3) -> Self {
        Self::from_mat3(*m)
    }

    /// nalgebra's `to_rotation_matrix`: here `Matrix3::from_quat(q)`.
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Matrix3, Quat};
    /// let q = Quat::from_rotation_y(0.4);
    /// assert_eq!(q.to_rotation_matrix(), Matrix3::from_quat(q));
    /// ```
    #[deprecated(since = "0.1.0", note = "use `Matrix3::from_quat(q)`")]
    #[inline]
    #[must_use]
    pub fn to_rotation_matrix(self) -> Matrix3 {
        Matrix3::from_quat(self)
    }

    /// nalgebra's `to_homogeneous`: here `Matrix4::from_quat(q)`.
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Matrix4, Quat};
    /// let q = Quat::from_rotation_y(0.4);
    /// assert_eq!(q.to_homogeneous(), Matrix4::from_quat(q));
    /// ```
    #[deprecated(since = "0.1.0", note = "use `Matrix4::from_quat(q)`")]
    #[inline]
    #[must_use]
    pub fn to_homogeneous(self) -> Matrix4 {
        Matrix4::from_quat(self)
    }

    /// glam's `from_mat4(&m)`: here [`from_matrix`](Self::from_matrix),
    /// which takes the matrix by value.
    ///
    /// ```
    /// # #![allow(deprecated)]
    /// use rigtform::{Matrix4, Quat};
    /// let m = Matrix4::from_quat(Quat::from_rotation_y(0.4));
    /// assert_eq!(Quat::from_mat4(&m), Quat::from_matrix(m));
    /// ```
    #[deprecated(since = "0.1.0", note = "use `Quat::from_matrix(m)` (by value)")]
    #[inline]
    #[must_use]
    pub fn from_mat4(m: &Matrix4) -> Self {
        Self::from_matrix(*m)
    }
}

#[cfg(test)]
#[allow(deprecated)]
mod tests {
    use super::*;
    use crate::vec::Cvec3;

    /// glam's `from_mat4` gives the same rotation as the name that leads
    /// to [`Quat::from_matrix`].
    #[test]
    fn from_mat4_is_glams() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(35);
        for _ in 0..10_000 {
            let mut c = || rng.random_range(-1.0f32..1.0);
            let a = Quat::from_axis_angle(Cvec3::new(c(), c(), c()), 3.0 * c());
            let m = Matrix4::from_quat(a);
            let from_glam = glam::Quat::from_mat4(&glam::Mat4::from_cols_array(&m.to_cols_array()));
            assert!(Quat::from_mat4(&m).angle_to(Quat::from_array(from_glam.to_array())) < 1e-5);
            assert_eq!(
                Quat::from_rotation_matrix(&Matrix3::from_quat(a)),
                Quat::from_mat3(Matrix3::from_quat(a))
            );
            assert_eq!(a.to_rotation_matrix(), Matrix3::from_quat(a));
            assert_eq!(a.to_homogeneous(), m);
        }
    }
}
