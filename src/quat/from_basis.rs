//! The rotation of an orthonormal basis (the columns of a rotation
//! matrix; `Quat::from_matrix` and `look_at` come here), by the method
//! of S. W. Shepperd ("Quaternion from rotation matrix", *Journal of
//! Guidance and Control* 1(3), 1978): of the four components, the one with
//! the largest square is taken from the diagonal, and the other three from
//! sums and differences of off-diagonal entries. That square is at least a
//! quarter (the four add up to 1), so no component is found by cancellation
//! near half turns, where the trace form `w = sqrt(1 + trace) / 2` loses
//! every digit.

use super::Quat;
use crate::vec::Cvec3;

impl Quat {
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
