//! [`Quat::from_matrix`]: the rotation of a rotation matrix, by the method
//! of S. W. Shepperd ("Quaternion from rotation matrix", *Journal of
//! Guidance and Control* 1(3), 1978): of the four components, the one with
//! the largest square is taken from the diagonal, and the other three from
//! sums and differences of off-diagonal entries. That square is at least a
//! quarter (the four add up to 1), so no component is found by cancellation
//! near half turns, where the trace form `w = sqrt(1 + trace) / 2` loses
//! every digit.

use super::Quat;
use crate::matrix::Matrix4;
use crate::matrix3::Matrix3;
use crate::vec::Cvec3;

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

    /// The rotation whose matrix has the columns `x`, `y`, `z` (the images
    /// of the three axes), by Shepperd's method; unit, with `w >= 0`.
    pub(crate) fn from_basis(x: Cvec3, y: Cvec3, z: Cvec3) -> Self {
        // m[row][col]: column x holds m00, m10, m20.
        let (m00, m10, m20) = (x.x, x.y, x.z);
        let (m01, m11, m21) = (y.x, y.y, y.z);
        let (m02, m12, m22) = (z.x, z.y, z.z);
        // Four times the square of w, x, y and z.
        let w4 = 1.0 + m00 + m11 + m22;
        let x4 = 1.0 + m00 - m11 - m22;
        let y4 = 1.0 - m00 + m11 - m22;
        let z4 = 1.0 - m00 - m11 + m22;
        // With the largest, say w4 = 4 w^2: x = (m21 - m12) / (4 w), and so
        // on. Multiplied through by 4 w, the row below is the quaternion
        // times 4 w (a positive factor the normalization removes), so no
        // square root is needed before it.
        let q = if w4 >= x4 && w4 >= y4 && w4 >= z4 {
            Self::from_wxyz(w4, m21 - m12, m02 - m20, m10 - m01)
        } else if x4 >= y4 && x4 >= z4 {
            Self::from_wxyz(m21 - m12, x4, m01 + m10, m02 + m20)
        } else if y4 >= z4 {
            Self::from_wxyz(m02 - m20, m01 + m10, y4, m12 + m21)
        } else {
            Self::from_wxyz(m10 - m01, m02 + m20, m12 + m21, z4)
        };
        q.normalize().cn()
    }
}
