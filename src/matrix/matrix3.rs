//! [`Matrix3`]: a 3x3 matrix, for the normal matrix a shader takes as a
//! `mat3` and for the linear part of an affine map. What it shares with
//! [`Matrix4`] is instanced at the bottom from `matrix/template.rs`.

use super::template::{columns, largest_magnitude, INVERSE_ENTRY_LIMIT, INVERSE_MINOR_LIMIT};
use super::Matrix4;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// A 3x3 matrix in the conventions of [`Matrix4`]: column vectors
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

impl Default for Matrix3 {
    /// The identity matrix.
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Matrix3 {
    /// The identity matrix.
    pub const IDENTITY: Self = Self::from_cols(Cvec3::X, Cvec3::Y, Cvec3::Z);
    /// Every entry zero.
    pub const ZERO: Self = Self::from_cols(Cvec3::ZERO, Cvec3::ZERO, Cvec3::ZERO);
    /// Every entry NaN: what [`col`](Self::col) and [`row`](Self::row)
    /// answer for an index out of range, in each of their components.
    pub const NAN: Self = Self::from_cols(Cvec3::NAN, Cvec3::NAN, Cvec3::NAN);

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

    /// The rotation matrix of a unit quaternion: `from_quat(q) * v == q * v`
    /// for every vector `v`; the upper-left block of
    /// [`Matrix4::from_quat`], entry for entry.
    ///
    /// # Preconditions
    ///
    /// `q` is a unit quaternion, as for [`Matrix4::from_quat`].
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
        Self::from(Matrix4::from_quat(q))
    }

    /// The upper-left 3x3 block of `m` (glam's `Mat3::from_mat4`); same as
    /// `Matrix3::from(m)`.
    ///
    /// ```
    /// use rigtform::{Matrix3, Matrix4};
    /// assert_eq!(Matrix3::from_mat4(Matrix4::IDENTITY), Matrix3::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_mat4(m: Matrix4) -> Self {
        Self::from(m)
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
    /// Relative error at most
    /// [`accuracy::MATRIX3_DETERMINANT_MAX_REL_ERROR`](crate::accuracy::MATRIX3_DETERMINANT_MAX_REL_ERROR)
    /// times the condition number `|M| |M^-1|` (Frobenius).
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
    /// Relative error (Frobenius norm) at most
    /// [`accuracy::MATRIX3_INVERSE_MAX_REL_ERROR`](crate::accuracy::MATRIX3_INVERSE_MAX_REL_ERROR)
    /// times the condition number `|M| |M^-1|`.
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

impl From<Matrix4> for Matrix3 {
    /// The upper-left 3x3 block (glam's `Mat3::from_mat4`): the linear
    /// part of an affine map, without its translation.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::X) * Matrix4::from_scale(Cvec3::splat(2.0));
    /// assert_eq!(Matrix3::from(m), Matrix3::from_cols(Cvec3::X * 2.0, Cvec3::Y * 2.0, Cvec3::Z * 2.0));
    /// ```
    #[inline]
    fn from(m: Matrix4) -> Self {
        let [a, b, c, _] = m.cols;
        Self::from_cols(a.xyz(), b.xyz(), c.xyz())
    }
}

impl From<Matrix3> for Matrix4 {
    /// The affine map of the linear part `m`, with no translation (glam's
    /// `Mat4::from_mat3`).
    ///
    /// ```
    /// use rigtform::{Matrix3, Matrix4};
    /// assert_eq!(Matrix4::from(Matrix3::IDENTITY), Matrix4::IDENTITY);
    /// ```
    #[inline]
    fn from(m: Matrix3) -> Self {
        let [a, b, c] = m.cols;
        Matrix4::from_cols(
            crate::Cvec4::from_vector(a),
            crate::Cvec4::from_vector(b),
            crate::Cvec4::from_vector(c),
            crate::Cvec4::W,
        )
    }
}

columns!(Matrix3, Cvec3, 9, { a: x, b: y, c: z });

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn to_glam(m: Matrix3) -> glam::Mat3 {
        glam::Mat3::from_cols_array(&m.to_cols_array())
    }

    fn to_f64(m: Matrix3) -> nalgebra::Matrix3<f64> {
        nalgebra::Matrix3::from_column_slice(&m.to_cols_array().map(f64::from))
    }

    use crate::test_draws::count as draws;

    #[test]
    fn inverse_and_determinant_are_within_their_bounds_of_nalgebra_in_f64() {
        use crate::accuracy::{MATRIX3_DETERMINANT_MAX_REL_ERROR, MATRIX3_INVERSE_MAX_REL_ERROR};
        let mut rng = rand::rngs::StdRng::seed_from_u64(27);
        let (mut worst_inv, mut worst_det, mut seen) = (0f64, 0f64, 0);
        for _ in 0..draws() {
            let m =
                Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-1.0..=1.0)));
            let m64 = to_f64(m);
            let Some(inv64) = m64.try_inverse() else {
                continue;
            };
            let cond = m64.norm() * inv64.norm();
            if cond > 1e4 {
                continue;
            }
            seen += 1;
            let inv = m.inverse().expect("invertible");
            let e_inv = (to_f64(inv) - inv64).norm() / inv64.norm() / cond;
            let det64 = m64.determinant();
            let e_det = (f64::from(m.determinant()) - det64).abs() / det64.abs() / cond;
            worst_inv = worst_inv.max(e_inv);
            worst_det = worst_det.max(e_det);
            assert!(
                e_inv <= f64::from(MATRIX3_INVERSE_MAX_REL_ERROR),
                "{m:?}: {e_inv:e}"
            );
            assert!(
                e_det <= f64::from(MATRIX3_DETERMINANT_MAX_REL_ERROR),
                "{m:?}: {e_det:e}"
            );
            // glam's inverse (cofactors too) agrees, within both errors.
            let g = to_glam(m).inverse();
            let size = g.to_cols_array().iter().fold(0f32, |a, b| a.max(b.abs()));
            assert!(g.abs_diff_eq(to_glam(inv), 1e-5 * cond as f32 * size));
        }
        std::println!(
            "Matrix3 over {seen} draws (condition <= 1e4): inverse {worst_inv:.3e}, determinant {worst_det:.3e} (relative, per unit of condition)"
        );
    }

    #[test]
    fn products_transpose_and_conversions_agree_with_glam() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(28);
        for _ in 0..1000 {
            let a =
                Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..=4.0)));
            let b =
                Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..=4.0)));
            let v = Cvec3::new(rng.random(), rng.random(), rng.random());
            let gv = glam::Vec3::new(v.x, v.y, v.z);
            let close = |x: glam::Mat3, y: glam::Mat3| x.abs_diff_eq(y, 1e-5);
            assert!(close(to_glam(a * b), to_glam(a) * to_glam(b)));
            assert!(
                ((to_glam(a) * gv).to_array().iter().zip((a * v).to_array()))
                    .all(|(x, y)| (x - y).abs() <= 1e-5)
            );
            assert_eq!(to_glam(a.transpose()), to_glam(a).transpose());
            assert_eq!(a.determinant().signum(), to_glam(a).determinant().signum());
            for i in 0..3 {
                assert_eq!(a.col(i).to_array(), to_glam(a).col(i).to_array());
                assert_eq!(a.row(i).to_array(), to_glam(a).row(i).to_array());
            }
            let q = Quat::from_axis_angle(v + Cvec3::ONE, rng.random_range(-3.0..3.0));
            let gq = glam::Quat::from_xyzw(q.x, q.y, q.z, q.w);
            assert!(close(
                to_glam(Matrix3::from_quat(q)),
                glam::Mat3::from_quat(gq)
            ));
            let m4 = Matrix4::from_cols_array(&core::array::from_fn(|_| rng.random()));
            let g4 = glam::Mat4::from_cols_array(&m4.to_cols_array());
            assert_eq!(to_glam(Matrix3::from(m4)), glam::Mat3::from_mat4(g4));
            assert_eq!(Matrix3::from_mat4(m4), Matrix3::from(m4));
            assert_eq!(Matrix4::from_mat3(a), Matrix4::from(a));
            let back = Matrix4::from(a).to_cols_array();
            assert_eq!(back, glam::Mat4::from_mat3(to_glam(a)).to_cols_array());
            assert_eq!(Matrix3::from(<[f32; 9]>::from(a)), a);
        }
        assert!(Matrix3::IDENTITY.col(3).is_nan() && Matrix3::IDENTITY.row(usize::MAX).is_nan());
        assert_eq!(Matrix3::default(), Matrix3::IDENTITY);
        assert_eq!(to_glam(Matrix3::IDENTITY), glam::Mat3::IDENTITY);
        assert_eq!(to_glam(Matrix3::ZERO), glam::Mat3::ZERO);
        assert_eq!(
            std::format!(
                "{}",
                Matrix3::from_cols_array(&core::array::from_fn(|i| i as f32 * 0.5))
            ),
            std::format!(
                "{}",
                glam::Mat3::from_cols_array(&core::array::from_fn(|i| i as f32 * 0.5))
            )
        );
        let mut m = Matrix3::IDENTITY;
        m *= Matrix3::from_cols(Cvec3::X * 2.0, Cvec3::Y, Cvec3::Z);
        assert_eq!(m.determinant(), 2.0);
    }

    #[test]
    fn singular_huge_and_non_finite_matrices_have_no_inverse() {
        let rank2 = Matrix3::from_cols(Cvec3::X, Cvec3::Y, Cvec3::X + Cvec3::Y);
        assert_eq!(rank2.inverse(), None);
        assert_eq!(Matrix3::NAN.inverse(), None);
        let mut inf = Matrix3::IDENTITY;
        inf.cols[2].z = f32::INFINITY;
        assert_eq!(inf.inverse(), None);
        // Minors of 2^86, beyond the 2^62 that keeps the determinant finite.
        let big = Matrix3::from_cols(Cvec3::X, Cvec3::Y, Cvec3::Z)
            * Matrix3::from_cols(
                Cvec3::X * 2f32.powi(43),
                Cvec3::Y * 2f32.powi(43),
                Cvec3::Z * 2f32.powi(43),
            );
        assert_eq!(big.inverse(), None);
        // 1 / det overflows for a tiny determinant.
        let tiny = Matrix3::from_cols(Cvec3::X * 1e-20, Cvec3::Y * 1e-20, Cvec3::Z);
        assert_eq!(tiny.inverse(), None);
        let huge = Matrix3::from_cols(Cvec3::X * 1e19, Cvec3::Y, Cvec3::Z);
        assert_eq!(huge.inverse(), None);
        assert!(Matrix3::NAN.determinant().is_nan());
    }
}
