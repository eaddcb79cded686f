//! [`Matrix3`]: a 3x3 matrix, for the normal matrix a shader takes as a
//! `mat3` and for the linear part of an affine map. What it shares with
//! [`Matrix4`](crate::Matrix4) is instanced at the bottom from `matrix/template.rs`.

use super::template::{columns, largest_magnitude, INVERSE_ENTRY_LIMIT, INVERSE_MINOR_LIMIT};
use crate::quat::Quat;
use crate::vec::Cvec3;

/// A 3x3 matrix in the conventions of [`Matrix4`](crate::Matrix4): column vectors
/// (`m * v`), stored column-major, so [`to_cols_array`](Self::to_cols_array)
/// can go to `glUniformMatrix3fv` with `transpose = false`. glam's `Mat3`.
///
/// # Examples
///
/// ```
/// use rigtform::{Cvec3, Matrix3, Matrix4, Quat};
/// let m = Matrix3::from_quat(Quat::from_rotation_z(0.5));
/// assert!((m * Cvec3::X - Quat::from_rotation_z(0.5) * Cvec3::X).norm() < 1e-6);
/// // The upper-left block of a Matrix4.
/// assert_eq!(Matrix3::from(Matrix4::from_quat(Quat::from_rotation_z(0.5))), m);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Matrix3 {
    /// The three columns.
    pub cols: [Cvec3; 3],
}

impl Matrix3 {
    /// The identity matrix.
    pub const IDENTITY: Self = Self::from_cols(Cvec3::X, Cvec3::Y, Cvec3::Z);

    /// Builds a matrix from its three columns.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3};
    /// assert_eq!(Matrix3::from_cols(Cvec3::X, Cvec3::Y, Cvec3::Z), Matrix3::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_cols(c0: Cvec3, c1: Cvec3, c2: Cvec3) -> Self {
        Self { cols: [c0, c1, c2] }
    }

    /// Builds a matrix from 9 entries in column-major order (the inverse
    /// of [`to_cols_array`](Self::to_cols_array)).
    ///
    /// ```
    /// use rigtform::Matrix3;
    /// let a = Matrix3::from_cols_array(&core::array::from_fn(|i| i as f32));
    /// assert_eq!(a.cols[1].x, 3.0);
    /// assert_eq!(Matrix3::from_cols_array(&a.to_cols_array()), a);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_cols_array(m: &[f32; 9]) -> Self {
        Self::from_cols(
            Cvec3::new(m[0], m[1], m[2]),
            Cvec3::new(m[3], m[4], m[5]),
            Cvec3::new(m[6], m[7], m[8]),
        )
    }

    /// The 9 entries in column-major order.
    ///
    /// ```
    /// use rigtform::Matrix3;
    /// assert_eq!(Matrix3::IDENTITY.to_cols_array(), [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_cols_array(self) -> [f32; 9] {
        let [a, b, c] = self.cols;
        [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z]
    }

    /// The rotation matrix of a unit quaternion (the notes'
    /// `makeRotation`): `from_quat(q) * v == q * v` for every vector `v`;
    /// the upper-left block of [`Matrix4::from_quat`](crate::Matrix4::from_quat),
    /// entry for entry.
    ///
    /// # Preconditions
    ///
    /// `q` is a unit quaternion.
    ///
    /// # Accuracy
    ///
    /// Each entry within [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
    /// of the exact rotation matrix of `q`.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Matrix3, Quat};
    /// let m = Matrix3::from_quat(Quat::from_rotation_z(FRAC_PI_2));
    /// assert!((m * Cvec3::X - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn from_quat(q: Quat) -> Self {
        let Quat { w, x, y, z } = q;
        let (x2, y2, z2) = (x + x, y + y, z + z);
        let (xx, yy, zz) = (x * x2, y * y2, z * z2);
        let (xy, xz, yz) = (x * y2, x * z2, y * z2);
        let (wx, wy, wz) = (w * x2, w * y2, w * z2);
        Self::from_cols(
            Cvec3::new(1.0 - (yy + zz), xy + wz, xz - wy),
            Cvec3::new(xy - wz, 1.0 - (xx + zz), yz + wx),
            Cvec3::new(xz + wy, yz - wx, 1.0 - (xx + yy)),
        )
    }

    /// The transpose.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3};
    /// let m = Matrix3::from_cols(Cvec3::X, Cvec3::new(5.0, 1.0, 0.0), Cvec3::Z);
    /// assert_eq!(m.transpose().cols[0].y, 5.0);
    /// assert_eq!(m.transpose().transpose(), m);
    /// ```
    #[inline]
    #[must_use]
    pub const fn transpose(self) -> Self {
        let [a, b, c] = self.cols;
        Self::from_cols(
            Cvec3::new(a.x, b.x, c.x),
            Cvec3::new(a.y, b.y, c.y),
            Cvec3::new(a.z, b.z, c.z),
        )
    }

    /// The determinant `c0 . (c1 x c2)`: the factor by which the matrix
    /// scales volumes, negative where it mirrors.
    ///
    /// # Preconditions
    ///
    /// None. NaN or infinite entries, or products beyond `f32::MAX`, give a
    /// NaN or infinite determinant.
    ///
    /// # Accuracy
    ///
    /// Within
    /// [`accuracy::MATRIX3_DETERMINANT_MAX_REL_ERROR`](crate::accuracy::MATRIX3_DETERMINANT_MAX_REL_ERROR)
    /// times the sum of the magnitudes of the six products of the
    /// expansion (proven): relative to the determinant, that times how
    /// much the products cancel.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3};
    /// let m = Matrix3::from_cols(Cvec3::X * 2.0, Cvec3::Y * 3.0, Cvec3::Z * -0.5);
    /// assert_eq!(m.determinant(), -3.0);
    /// ```
    #[must_use]
    pub fn determinant(self) -> f32 {
        let [a, b, c] = self.cols;
        a.dot(b.cross(c))
    }

    /// The inverse matrix, or `None` when there is none to give: the
    /// cross products of the columns over the determinant,
    /// `rows (c1 x c2, c2 x c0, c0 x c1) / det`.
    ///
    /// # Preconditions
    ///
    /// None. `None` for a singular matrix (a zero determinant), for NaN or
    /// infinite entries, and where a step could overflow, so that every
    /// `Some` holds finite entries: an entry beyond 2^63 (about 9e18), a
    /// 2x2 minor beyond 2^62, `1 / det` not finite, or an entry of the
    /// inverse not finite.
    ///
    /// # Accuracy
    ///
    /// Each entry within
    /// [`accuracy::MATRIX3_INVERSE_MAX_REL_ERROR`](crate::accuracy::MATRIX3_INVERSE_MAX_REL_ERROR)
    /// times `(Am + |M| T / |det|) / |det|` of the exact one, `M` being
    /// its minor, `Am` the magnitudes of the minor's two products and `T`
    /// those of the determinant's six (proven, where `T <= 4096 |det|`):
    /// the minor's rounding, and the determinant's error, which grows as
    /// the expansion cancels.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3};
    /// let m = Matrix3::from_cols(Cvec3::X * 2.0, Cvec3::new(1.0, 4.0, 0.0), Cvec3::Z * 8.0);
    /// assert_eq!(m * m.inverse().unwrap(), Matrix3::IDENTITY);
    /// assert_eq!(Matrix3::ZERO.inverse(), None);
    /// ```
    #[must_use]
    pub fn inverse(self) -> Option<Self> {
        if !self.is_finite() || largest_magnitude(&self.to_cols_array()) > INVERSE_ENTRY_LIMIT {
            return None;
        }
        let [a, b, c] = self.cols;
        let (bc, ca, ab) = (b.cross(c), c.cross(a), a.cross(b));
        let minors = Self::from_cols(bc, ca, ab).to_cols_array();
        if largest_magnitude(&minors) > INVERSE_MINOR_LIMIT {
            return None;
        }
        let det = a.dot(bc);
        if det == 0.0 {
            return None;
        }
        let inv_det = 1.0 / det;
        if !inv_det.is_finite() {
            return None;
        }
        // Each entry is a finite minor times a finite 1 / det: finite, or
        // infinite where the inverse does not fit.
        let inverse = Self::from_cols(bc * inv_det, ca * inv_det, ab * inv_det).transpose();
        inverse.is_finite().then_some(inverse)
    }
}

columns!(Matrix3, Cvec3, 3, 9, glam(mul_mat3, mul_vec3, add_mat3, sub_mat3), { a: x, b: y, c: z });

#[cfg(test)]
mod tests;
