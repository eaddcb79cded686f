//! [`Matrix4`]: the few 4x4 matrices that survive in the renderer (the
//! notes' "more code"): the projection, the model-view matrix (MVM, with a
//! scale on the right) and the normal matrix (NMVM). What it shares with
//! [`Matrix3`](crate::Matrix3) is instanced at the bottom from
//! `matrix/template.rs`.

use super::template::{columns, largest_magnitude, INVERSE_ENTRY_LIMIT, INVERSE_MINOR_LIMIT};
use super::Matrix3;
use crate::float;
use crate::quat::Quat;
use crate::rigtform::RigTForm;
use crate::vec::{Cvec3, Cvec4};

/// 2^125: the largest product of an entry and a minor over the
/// determinant that [`Matrix4::inverse`] takes.
const INVERSE_PRODUCT_LIMIT: f32 = 4.253_529_6e37;

/// A 4x4 matrix in OpenGL conventions: column vectors (`m * v`), stored
/// column-major, so [`to_cols_array`](Self::to_cols_array) can go straight to
/// `glUniformMatrix4fv` with `transpose = false`.
///
/// # Examples
///
/// ```
/// use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};
/// let a = RigTForm::new(Cvec3::new(0.0, 0.0, -5.0), Quat::from_rotation_y(0.3));
/// let mvm = Matrix4::from(a) * Matrix4::from_scale(Cvec3::new(2.0, 2.0, 2.0));
/// let p = Cvec4::from_point(Cvec3::X);
/// assert!((mvm * p - a * Cvec4::from_point(Cvec3::X * 2.0)).norm() < 1e-5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Matrix4 {
    /// The four columns; `cols[3]` holds the translation of an affine map.
    pub cols: [Cvec4; 4],
}

impl Matrix4 {
    /// The identity matrix.
    pub const IDENTITY: Self = Self::from_cols(
        Cvec4::new(1.0, 0.0, 0.0, 0.0),
        Cvec4::new(0.0, 1.0, 0.0, 0.0),
        Cvec4::new(0.0, 0.0, 1.0, 0.0),
        Cvec4::new(0.0, 0.0, 0.0, 1.0),
    );

    /// Builds a matrix from its four columns.
    ///
    /// ```
    /// use rigtform::{Cvec4, Matrix4};
    /// let m = Matrix4::from_cols(
    ///     Cvec4::new(1.0, 0.0, 0.0, 0.0),
    ///     Cvec4::new(0.0, 1.0, 0.0, 0.0),
    ///     Cvec4::new(0.0, 0.0, 1.0, 0.0),
    ///     Cvec4::new(0.0, 0.0, 0.0, 1.0),
    /// );
    /// assert_eq!(m, Matrix4::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_cols(c0: Cvec4, c1: Cvec4, c2: Cvec4, c3: Cvec4) -> Self {
        Self {
            cols: [c0, c1, c2, c3],
        }
    }

    /// Builds a matrix from 16 entries in column-major order (the inverse
    /// of [`to_cols_array`](Self::to_cols_array)).
    ///
    /// ```
    /// use rigtform::Matrix4;
    /// let a = Matrix4::from_cols_array(&core::array::from_fn(|i| i as f32));
    /// assert_eq!(a.cols[1].x, 4.0);
    /// assert_eq!(Matrix4::from_cols_array(&a.to_cols_array()), a);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_cols_array(m: &[f32; 16]) -> Self {
        Self::from_cols(
            Cvec4::new(m[0], m[1], m[2], m[3]),
            Cvec4::new(m[4], m[5], m[6], m[7]),
            Cvec4::new(m[8], m[9], m[10], m[11]),
            Cvec4::new(m[12], m[13], m[14], m[15]),
        )
    }

    /// The 16 entries in column-major order, as OpenGL takes them.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::new(1.0, 2.0, 3.0)).to_cols_array();
    /// assert_eq!(&m[12..], &[1.0, 2.0, 3.0, 1.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_cols_array(self) -> [f32; 16] {
        let [a, b, c, d] = self.cols;
        [
            a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w, c.x, c.y, c.z, c.w, d.x, d.y, d.z, d.w,
        ]
    }

    /// The translation `T` by `t` (the notes' `makeTranslation`).
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(m * Cvec4::new(0.0, 0.0, 0.0, 1.0), Cvec4::new(1.0, 2.0, 3.0, 1.0));
    /// assert_eq!(m * Cvec4::new(1.0, 0.0, 0.0, 0.0), Cvec4::new(1.0, 0.0, 0.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_translation(t: Cvec3) -> Self {
        let i = Self::IDENTITY.cols;
        Self::from_cols(i[0], i[1], i[2], Cvec4::from_point(t))
    }

    /// The scale by `s.x`, `s.y`, `s.z` along the axes (the object scaling a
    /// `RigTForm` cannot hold; multiply it on the right of the MVM).
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, Matrix4};
    /// let m = Matrix4::from_scale(Cvec3::new(2.0, 3.0, 4.0));
    /// assert_eq!(m * Cvec4::new(1.0, 1.0, 1.0, 1.0), Cvec4::new(2.0, 3.0, 4.0, 1.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_scale(s: Cvec3) -> Self {
        Self::from_cols(
            Cvec4::new(s.x, 0.0, 0.0, 0.0),
            Cvec4::new(0.0, s.y, 0.0, 0.0),
            Cvec4::new(0.0, 0.0, s.z, 0.0),
            Cvec4::new(0.0, 0.0, 0.0, 1.0),
        )
    }

    /// The rotation matrix of a unit quaternion (the notes' `makeRotation`):
    /// `from_quat(q) * v == q * v` for every vector `v`.
    ///
    /// # Preconditions
    ///
    /// `q` is a unit quaternion (the entries use `1 - 2(y^2 + z^2)` and
    /// friends, which assume it). `q` and `-q` give the same matrix.
    ///
    /// # Accuracy
    ///
    /// Each entry is within [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
    /// of the exact rotation matrix of `q` (`tests/differential.rs`), so
    /// `from_quat(a * b)` and `from_quat(a) * from_quat(b)` agree within
    /// three times that plus the product's error (`tests/properties.rs`).
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec4, Matrix4, Quat};
    /// let m = Matrix4::from_quat(Quat::from_rotation_z(FRAC_PI_2));
    /// assert!((m * Cvec4::new(1.0, 0.0, 0.0, 0.0) - Cvec4::new(0.0, 1.0, 0.0, 0.0)).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn from_quat(q: Quat) -> Self {
        Self::from(Matrix3::from_quat(q))
    }

    /// The matrix `T R` of a rigid body transform (the notes'
    /// `rigTFormToMatrix`), built directly: the rotation's columns, and the
    /// translation in the last column. Same as `Matrix4::from(a)`.
    ///
    /// # Preconditions
    ///
    /// `a.r` is a unit quaternion.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};
    /// let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::from_rotation_x(0.4));
    /// let p = Cvec4::from_point(Cvec3::new(-1.0, 0.5, 2.0));
    /// assert!((Matrix4::from_rig_tform(a) * p - a * p).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn from_rig_tform(a: RigTForm) -> Self {
        let [c0, c1, c2, _] = Self::from_quat(a.r).cols;
        Self::from_cols(c0, c1, c2, Cvec4::from_point(a.t))
    }

    /// The transpose.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(m.transpose().cols[0].w, 1.0);
    /// assert_eq!(m.transpose().transpose(), m);
    /// ```
    #[inline]
    #[must_use]
    pub const fn transpose(self) -> Self {
        let [a, b, c, d] = self.cols;
        Self::from_cols(
            Cvec4::new(a.x, b.x, c.x, d.x),
            Cvec4::new(a.y, b.y, c.y, d.y),
            Cvec4::new(a.z, b.z, c.z, d.z),
            Cvec4::new(a.w, b.w, c.w, d.w),
        )
    }

    /// The inverse matrix, or `None` when there is none to give.
    ///
    /// Computed from 3-vector cross products of the columns (the
    /// block-wise cofactor form in E. Lengyel, *Foundations of Game Engine
    /// Development*, vol. 1, section 1.7.5), in f32.
    ///
    /// # Preconditions
    ///
    /// None. Returns `None` for a singular matrix (a zero determinant) and
    /// for NaN or infinite entries. Every step is checked before the next
    /// one can overflow, so that no product or sum ever meets an infinity
    /// and every `Some` holds finite entries: `None` also when an entry is
    /// beyond 2^63 (about 9e18), when a 2x2 minor of the columns is beyond
    /// 2^62, when `1 / det` overflows, or when a minor over the determinant
    /// times the largest entry is beyond 2^125 (about 4e37), even if the
    /// inverse itself would fit.
    ///
    /// # Accuracy
    ///
    /// Each entry within
    /// [`accuracy::INVERSE_MAX_REL_ERROR`](crate::accuracy::INVERSE_MAX_REL_ERROR)
    /// times `(Ac + |C| T / |det|) / |det|` of the exact one, `C` being its
    /// cofactor, `Ac` the magnitudes of the cofactor's six products and `T`
    /// those of the determinant's 24 (proven, where `T <= 4096 |det|`): the
    /// cofactor's rounding, and the determinant's error, which grows as the
    /// expansion cancels, so a nearly singular matrix yields a
    /// correspondingly inaccurate inverse.
    ///
    /// # Examples
    ///
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::X) * Matrix4::from_scale(Cvec3::new(2.0, 4.0, 8.0));
    /// let i = m.inverse().unwrap();
    /// assert_eq!(m * i, Matrix4::IDENTITY);
    /// assert_eq!(Matrix4::from_scale(Cvec3::new(1.0, 0.0, 1.0)).inverse(), None);
    /// ```
    #[must_use]
    pub fn inverse(self) -> Option<Self> {
        // Entries within 2^63: each product of two is within 2^126, each
        // 2x2 minor (a difference of two) within 2^127, all finite.
        if !self.is_finite() {
            return None;
        }
        let entry = largest_magnitude(&self.to_cols_array());
        if entry > INVERSE_ENTRY_LIMIT {
            return None;
        }
        let Cofactors {
            a,
            b,
            c,
            d,
            x,
            y,
            z,
            w,
            s,
            t,
            u,
            v,
        } = self.cofactors();
        // Minors within 2^62: the six products of the determinant are
        // within 2^124, their sum within 2^127.
        let minors = [s, t, u, v].map(|m| largest_magnitude(&[m.x, m.y, m.z]));
        if largest_magnitude(&minors) > INVERSE_MINOR_LIMIT {
            return None;
        }
        let det = s.dot(v) + t.dot(u);
        if det == 0.0 {
            return None;
        }
        let inv_det = 1.0 / det;
        if !inv_det.is_finite() {
            return None;
        }
        let (s, t, u, v) = (s * inv_det, t * inv_det, u * inv_det, v * inv_det);
        // Each product below is an entry times a scaled minor, within
        // 2^125 once their largest are; sums of up to three stay within
        // 2^127. (A scaled minor that overflowed is infinite, and so is
        // this product: no NaN on the way.)
        let scaled = [s, t, u, v].map(|m| largest_magnitude(&[m.x, m.y, m.z]));
        if largest_magnitude(&scaled) * entry > INVERSE_PRODUCT_LIMIT {
            return None;
        }
        // Rows of the inverse.
        let r0 = b.cross(v) + t * y;
        let r1 = v.cross(a) - t * x;
        let r2 = d.cross(u) + s * w;
        let r3 = u.cross(c) - s * z;
        let rows = Self::from_cols(
            Cvec4::new(r0.x, r0.y, r0.z, -b.dot(t)),
            Cvec4::new(r1.x, r1.y, r1.z, a.dot(t)),
            Cvec4::new(r2.x, r2.y, r2.z, -d.dot(s)),
            Cvec4::new(r3.x, r3.y, r3.z, c.dot(s)),
        );
        Some(rows.transpose())
    }

    /// The determinant: the factor by which the matrix scales volumes in
    /// 4D (for an affine map, that of its upper 3x3 block: the volume scale
    /// of the 3D map, negative where it mirrors).
    ///
    /// Computed from the same cross products of the columns as
    /// [`inverse`](Self::inverse): `det = s . v + t . u`.
    ///
    /// # Preconditions
    ///
    /// None. NaN or infinite entries, or products beyond `f32::MAX`, give a
    /// NaN or infinite determinant.
    ///
    /// # Accuracy
    ///
    /// Within
    /// [`accuracy::DETERMINANT_MAX_REL_ERROR`](crate::accuracy::DETERMINANT_MAX_REL_ERROR)
    /// times the sum of the magnitudes of the 24 products of the
    /// expansion (proven): relative to the determinant, that times how
    /// much the products cancel.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat, RigTForm};
    /// let m = Matrix4::from_scale(Cvec3::new(2.0, 3.0, -0.5));
    /// assert_eq!(m.determinant(), -3.0);
    /// let rigid = Matrix4::from(RigTForm::new(Cvec3::X, Quat::from_rotation_y(0.4)));
    /// assert!((rigid.determinant() - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn determinant(self) -> f32 {
        let Cofactors { s, t, u, v, .. } = self.cofactors();
        s.dot(v) + t.dot(u)
    }

    /// The columns split into their first three coordinates `a, b, c, d`
    /// and their last `x, y, z, w`, and the four 3-vectors whose products
    /// give the determinant and the inverse.
    #[inline]
    fn cofactors(self) -> Cofactors {
        let [ca, cb, cc, cd] = self.cols;
        let (a, b, c, d) = (ca.xyz(), cb.xyz(), cc.xyz(), cd.xyz());
        let (x, y, z, w) = (ca.w, cb.w, cc.w, cd.w);
        Cofactors {
            a,
            b,
            c,
            d,
            x,
            y,
            z,
            w,
            s: a.cross(b),
            t: c.cross(d),
            u: a * y - b * x,
            v: c * w - d * z,
        }
    }

    /// The normal matrix: the inverse transpose of the upper 3x3 block, as
    /// a `Matrix4` with no translation (the notes' `normalMatrix(MVM)`, the
    /// NMVM sent to the shaders). Normals transformed by it stay
    /// perpendicular to surfaces under non-uniform scaling; for `T R S` it
    /// is `R S^-1`.
    ///
    /// # Preconditions
    ///
    /// None. `None` when the 3x3 block is singular (a zero scale) or not
    /// finite, or its entries, minors or `1 / det` beyond the limits of
    /// [`inverse`](Self::inverse), or an entry of the result would not be
    /// finite.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let n = Matrix4::from_scale(Cvec3::new(2.0, 4.0, 0.5)).normal_matrix().unwrap();
    /// assert_eq!(n, Matrix4::from_scale(Cvec3::new(0.5, 0.25, 2.0)));
    /// ```
    #[must_use]
    pub fn normal_matrix(self) -> Option<Self> {
        // The inverse transpose of the block: its inverse, whose rows are
        // (b x c, c x a, a x b) / det, transposed (exactly).
        Matrix3::from(self)
            .inverse()
            .map(|inverse| Self::from(inverse.transpose()))
    }

    /// The perspective projection of `gluPerspective`: vertical field of
    /// view `fovy` (radians), `aspect = width / height`, and the positive
    /// distances `near` and `far` to the clipping planes. The camera looks
    /// down -z; after the divide by w, `z = -near` maps to NDC -1 and
    /// `z = -far` to +1.
    ///
    /// # Preconditions
    ///
    /// `0 < fovy < pi`, `aspect > 0`, `0 < near < far`, all finite. Nothing
    /// is checked and nothing panics: outside these, entries may be
    /// infinite or NaN (`near == far` divides by zero), and reversed or
    /// negative distances flip the depth order.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec4, Matrix4};
    /// let p = Matrix4::perspective(FRAC_PI_2, 1.0, 1.0, 10.0);
    /// let near = p * Cvec4::new(0.0, 0.0, -1.0, 1.0);
    /// let far = p * Cvec4::new(0.0, 0.0, -10.0, 1.0);
    /// assert!((near.z / near.w + 1.0).abs() < 1e-6);
    /// assert!((far.z / far.w - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn perspective(fovy: f32, aspect: f32, near: f32, far: f32) -> Self {
        let f = 1.0 / float::tan(fovy * 0.5);
        let depth = near - far;
        Self::from_cols(
            Cvec4::new(f / aspect, 0.0, 0.0, 0.0),
            Cvec4::new(0.0, f, 0.0, 0.0),
            Cvec4::new(0.0, 0.0, (far + near) / depth, -1.0),
            Cvec4::new(0.0, 0.0, 2.0 * far * near / depth, 0.0),
        )
    }

    /// The orthographic projection of `glOrtho`: the box `left..right`,
    /// `bottom..top` in x and y, and the positive distances `near` and
    /// `far` in front of the eye (which looks down -z) maps to the NDC cube
    /// [-1, 1]^3, `z = -near` to -1 and `z = -far` to +1. Parallel lines
    /// stay parallel: there is no divide by depth (`w` stays 1).
    ///
    /// # Preconditions
    ///
    /// `left != right`, `bottom != top`, `near != far`, all finite. Nothing
    /// is checked and nothing panics: an empty box divides by zero and
    /// gives infinite or NaN entries.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec4, Matrix4};
    /// let p = Matrix4::orthographic(-2.0, 2.0, -1.0, 1.0, 1.0, 9.0);
    /// assert_eq!(p * Cvec4::new(2.0, 1.0, -1.0, 1.0), Cvec4::new(1.0, 1.0, -1.0, 1.0));
    /// assert_eq!(p * Cvec4::new(-2.0, -1.0, -9.0, 1.0), Cvec4::new(-1.0, -1.0, 1.0, 1.0));
    /// ```
    #[doc(alias = "orthographic_rh_gl")]
    #[doc(alias = "ortho")]
    #[must_use]
    pub fn orthographic(left: f32, right: f32, bottom: f32, top: f32, near: f32, far: f32) -> Self {
        let (width, height, depth) = (right - left, top - bottom, far - near);
        Self::from_cols(
            Cvec4::new(2.0 / width, 0.0, 0.0, 0.0),
            Cvec4::new(0.0, 2.0 / height, 0.0, 0.0),
            Cvec4::new(0.0, 0.0, -2.0 / depth, 0.0),
            Cvec4::new(
                -(right + left) / width,
                -(top + bottom) / height,
                -(far + near) / depth,
                1.0,
            ),
        )
    }
}

/// What [`Matrix4::cofactors`] returns.
struct Cofactors {
    a: Cvec3,
    b: Cvec3,
    c: Cvec3,
    d: Cvec3,
    x: f32,
    y: f32,
    z: f32,
    w: f32,
    s: Cvec3,
    t: Cvec3,
    u: Cvec3,
    v: Cvec3,
}

impl From<RigTForm> for Matrix4 {
    /// Same as [`Matrix4::from_rig_tform`].
    #[inline]
    fn from(a: RigTForm) -> Self {
        Self::from_rig_tform(a)
    }
}

impl Matrix3 {
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

    /// The minor of `m` without its column `i` and its row `j` (glam's
    /// `from_mat4_minor`): the 3x3 sub-matrix whose determinant is the
    /// `(j, i)` minor of `m`. [`Matrix3::NAN`] where `i` or `j` is past the
    /// last column or row (glam panics there; this never does).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(Matrix3::from_mat4_minor(m, 3, 3), Matrix3::IDENTITY);
    /// assert_eq!(Matrix3::from_mat4_minor(m, 0, 0).col(2), Cvec3::new(2.0, 3.0, 1.0));
    /// assert!(Matrix3::from_mat4_minor(m, 4, 0).is_nan());
    /// ```
    #[must_use]
    pub fn from_mat4_minor(m: Matrix4, i: usize, j: usize) -> Self {
        /// The three indices of `0..4` other than `skip`.
        const fn others(skip: usize) -> [usize; 3] {
            match skip {
                0 => [1, 2, 3],
                1 => [0, 2, 3],
                2 => [0, 1, 3],
                _ => [0, 1, 2],
            }
        }
        if i > 3 || j > 3 {
            return Self::NAN;
        }
        let [r0, r1, r2] = others(j);
        let [a, b, c] = others(i).map(|k| {
            let col = m.col(k);
            Cvec3::new(col[r0], col[r1], col[r2])
        });
        Self::from_cols(a, b, c)
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
        Self::from_cols(
            Cvec4::from_vector(a),
            Cvec4::from_vector(b),
            Cvec4::from_vector(c),
            Cvec4::W,
        )
    }
}

columns!(Matrix4, Cvec4, 4, 16, glam(mul_mat4, mul_vec4, add_mat4, sub_mat4), { a: x, b: y, c: z, d: w });

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_of_a_general_matrix_multiplies_back_to_identity() {
        let m = Matrix4::from_cols_array(&[
            2.0, 1.0, 0.0, 0.5, //
            -1.0, 3.0, 1.0, 0.0, //
            0.0, 0.5, 4.0, -1.0, //
            1.0, 2.0, 3.0, 1.0,
        ]);
        let i = m.inverse().expect("invertible");
        for (got, want) in (m * i)
            .to_cols_array()
            .iter()
            .zip(Matrix4::IDENTITY.to_cols_array())
        {
            assert!((got - want).abs() < 1e-6, "{got} vs {want}");
        }
    }

    #[test]
    fn singular_and_non_finite_matrices_have_no_inverse() {
        let mut rank3 = Matrix4::IDENTITY;
        rank3.cols[2] = rank3.cols[0] + rank3.cols[1];
        assert_eq!(rank3.inverse(), None);
        assert_eq!(rank3.normal_matrix(), None);
        let mut nan = Matrix4::IDENTITY;
        nan.cols[1].y = f32::NAN;
        assert_eq!(nan.inverse(), None);
        assert_eq!(nan.normal_matrix(), None);
        let huge = Matrix4::from_scale(Cvec3::new(f32::MAX, f32::MAX, 1.0));
        assert_eq!(huge.inverse(), None); // det overflows
                                          // The determinant 2^129 overflows although every cofactor is finite:
                                          // documented as None (not the zero matrix that 1 / inf would give).
        let big = Matrix4::from_scale(Cvec3::new(2f32.powi(43), 2f32.powi(43), 2f32.powi(43)));
        assert_eq!(big.inverse(), None);
        assert_eq!(big.normal_matrix(), None);
    }

    #[test]
    fn determinant_is_the_volume_scale_and_arrays_round_trip() {
        let m = Matrix4::from_cols_array(&[
            2.0, 1.0, 0.0, 0.5, //
            -1.0, 3.0, 1.0, 0.0, //
            0.0, 0.5, 4.0, -1.0, //
            1.0, 2.0, 3.0, 1.0,
        ]);
        let det = m.determinant();
        let det64 =
            nalgebra::Matrix4::from_column_slice(&m.to_cols_array().map(f64::from)).determinant();
        assert!(
            (f64::from(det) - det64).abs() < 1e-6 * det64.abs(),
            "{det} vs {det64}"
        );
        let product = det * m.inverse().expect("invertible").determinant();
        assert!((product - 1.0).abs() < 1e-6, "{det}");
        let mut swapped = m;
        swapped.cols.swap(0, 1);
        assert_eq!(swapped.determinant(), -det);
        assert_eq!(Matrix4::from(<[f32; 16]>::from(m)), m);
        assert!(Matrix4::from_scale(Cvec3::new(f32::NAN, 1.0, 1.0))
            .determinant()
            .is_nan());
    }

    #[test]
    fn orthographic_maps_its_box_to_the_ndc_cube() {
        let p = Matrix4::orthographic(-3.0, 1.0, -2.0, 6.0, 1.0, 9.0);
        for (x, y, z) in [(-3.0, -2.0, -1.0), (1.0, 6.0, -9.0), (-1.0, 2.0, -5.0)] {
            let c = p * Cvec4::new(x, y, z, 1.0);
            let want = Cvec4::new((x + 1.0) / 2.0, (y - 2.0) / 4.0, (-z - 5.0) / 4.0, 1.0);
            assert!((c - want).norm() < 1e-6, "{c:?} vs {want:?}");
        }
    }

    #[test]
    fn perspective_keeps_x_and_y_scaled_by_the_field_of_view() {
        let p = Matrix4::perspective(core::f32::consts::FRAC_PI_2, 2.0, 0.5, 100.0);
        let c = p * Cvec4::new(1.0, 1.0, -1.0, 1.0);
        assert!((c.x / c.w - 0.5).abs() < 1e-6 && (c.y / c.w - 1.0).abs() < 1e-6);
    }
}
