//! glam's everyday `Mat4` API on [`Matrix4`]: building an affine map from
//! scale, rotation and translation and taking it apart, transforming
//! points and vectors, rows and columns, and the normal matrix as a
//! [`Matrix3`].

use super::Matrix4;
use crate::matrix::Matrix3;
use crate::quat::Quat;
use crate::rigtform::RigTForm;
use crate::vec::{Cvec3, Cvec4};

impl Matrix4 {
    /// The linear map `m` as an affine map with no translation (glam's
    /// `Mat4::from_mat3`); same as `Matrix4::from(m)`.
    ///
    /// ```
    /// use rigtform::{Matrix3, Matrix4};
    /// assert_eq!(Matrix4::from_mat3(Matrix3::IDENTITY), Matrix4::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub fn from_mat3(m: Matrix3) -> Self {
        Self::from(m)
    }

    /// The affine map of the linear part `m` and the translation
    /// `translation`: `Matrix4::from_translation(translation) *
    /// Matrix4::from_mat3(m)`, built directly (glam's
    /// `Mat4::from_mat3_translation`).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3, Matrix4};
    /// let m = Matrix4::from_mat3_translation(Matrix3::IDENTITY * 2.0, Cvec3::X);
    /// assert_eq!(m.transform_point3(Cvec3::Y), Cvec3::new(1.0, 2.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn from_mat3_translation(m: Matrix3, translation: Cvec3) -> Self {
        let [a, b, c, _] = Self::from(m).cols;
        Self::from_cols(a, b, c, Cvec4::from_point(translation))
    }

    /// The affine map `T R`: rotate by `rotation`, then translate by
    /// `translation` (glam's `Mat4::from_rotation_translation`). Same as
    /// `Matrix4::from(RigTForm::new(translation, rotation))`.
    ///
    /// # Preconditions
    ///
    /// `rotation` is a unit quaternion.
    ///
    /// # Accuracy
    ///
    /// The rotation block as [`from_quat`](Self::from_quat); the
    /// translation column is `translation`, exactly.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat};
    /// let m = Matrix4::from_rotation_translation(Quat::from_rotation_z(0.5), Cvec3::X);
    /// assert_eq!(m.col(3).xyz(), Cvec3::X);
    /// assert!((m.transform_point3(Cvec3::ZERO) - Cvec3::X).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn from_rotation_translation(rotation: Quat, translation: Cvec3) -> Self {
        Self::from_rig_tform(RigTForm::new(translation, rotation))
    }

    /// The affine map `T R S`: scale along the axes by `scale`, then rotate
    /// by `rotation`, then translate by `translation` (glam's
    /// `Mat4::from_scale_rotation_translation`, a glTF node's TRS).
    ///
    /// # Preconditions
    ///
    /// `rotation` is a unit quaternion.
    ///
    /// # Accuracy
    ///
    /// Each entry of the upper 3x3 block within
    /// [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
    /// times its column's `|scale|` (one more rounding of the product);
    /// the translation column is `translation`, exactly.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat};
    /// let (s, r, t) = (Cvec3::new(2.0, 1.0, 0.5), Quat::from_rotation_y(0.3), Cvec3::Z);
    /// let m = Matrix4::from_scale_rotation_translation(s, r, t);
    /// let by_parts = Matrix4::from_translation(t) * Matrix4::from_quat(r) * Matrix4::from_scale(s);
    /// assert!(m.to_cols_array().iter().zip(by_parts.to_cols_array()).all(|(a, b)| (a - b).abs() < 1e-6));
    /// ```
    #[must_use]
    pub fn from_scale_rotation_translation(
        scale: Cvec3,
        rotation: Quat,
        translation: Cvec3,
    ) -> Self {
        let [a, b, c, _] = Self::from_quat(rotation).cols;
        Self::from_cols(
            a * scale.x,
            b * scale.y,
            c * scale.z,
            Cvec4::from_point(translation),
        )
    }

    /// The scale, rotation and translation of an affine map `T R S`, the
    /// inverse of [`from_scale_rotation_translation`](Self::from_scale_rotation_translation)
    /// (glam's `Mat4::to_scale_rotation_translation`): the scale is the
    /// length of each column of the upper 3x3 block, with the sign of the
    /// determinant on `scale.x` (a mirror shows as a negative x scale, as in
    /// glam); the rotation is that of the block's columns over their
    /// scales ([`Quat::from_matrix`], `w >= 0`); the translation is the
    /// last column.
    ///
    /// # Preconditions
    ///
    /// `self` is affine (last row `0, 0, 0, 1`; it is not read) and its
    /// upper block a rotation times a diagonal scale (orthogonal columns:
    /// no shear). A shear still gives a unit quaternion, but not a
    /// meaningful rotation. A zero, NaN or infinite column gives
    /// [`Quat::NAN`] as the rotation (and its length as the scale), never a
    /// panic.
    ///
    /// # Accuracy
    ///
    /// For `T R S` built by `from_scale_rotation_translation` with unit
    /// `R` and scales in [1e-3, 1e3] of either sign, the rotation is within
    /// [`accuracy::SRT_ROTATION_MAX_ANGLE_ERROR`](crate::accuracy::SRT_ROTATION_MAX_ANGLE_ERROR)
    /// radians of `R` (up to sign, and with `-R` turned by a half turn
    /// about x where the x scale is negative), and each scale within
    /// [`accuracy::SRT_SCALE_MAX_REL_ERROR`](crate::accuracy::SRT_SCALE_MAX_REL_ERROR)
    /// of the input, relative, where `|R|^2` is within 1.2e-7 of 1 (an f32
    /// rounding of a unit quaternion); up to `2 ||R|^2 - 1|` more
    /// otherwise.
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4, Quat};
    /// let (s, r, t) = (Cvec3::new(2.0, 1.0, 0.5), Quat::from_rotation_y(0.3), Cvec3::Z);
    /// let (s2, r2, t2) = Matrix4::from_scale_rotation_translation(s, r, t).to_scale_rotation_translation();
    /// assert!((s2 - s).norm() < 1e-6 && r2.angle_to(r) < 1e-6 && t2 == t);
    /// ```
    #[must_use]
    pub fn to_scale_rotation_translation(&self) -> (Cvec3, Quat, Cvec3) {
        let [a, b, c, d] = self.cols;
        let (a, b, c) = (a.xyz(), b.xyz(), c.xyz());
        let det = Matrix3::from_cols(a, b, c).determinant();
        let mirror = if det < 0.0 { -1.0 } else { 1.0 };
        let scale = Cvec3::new(mirror * a.norm(), b.norm(), c.norm());
        let rotation = match (a.try_normalize(), b.try_normalize(), c.try_normalize()) {
            (Some(a), Some(b), Some(c)) => {
                Quat::from_matrix(Self::from(Matrix3::from_cols(a * mirror, b, c)))
            }
            _ => Quat::NAN,
        };
        (scale, rotation, d.xyz())
    }

    /// `p` transformed as a point (`w = 1`), the translation included:
    /// the first three coordinates of `self * [p, 1]`, without a divide by
    /// `w` (glam's `Mat4::transform_point3`).
    ///
    /// # Preconditions
    ///
    /// `self` is affine (its last row is not read); for a projection use
    /// [`project_point3`](Self::project_point3).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::X);
    /// assert_eq!(m.transform_point3(Cvec3::Y), Cvec3::new(1.0, 1.0, 0.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_point3(&self, p: Cvec3) -> Cvec3 {
        (*self * Cvec4::from_point(p)).xyz()
    }

    /// `v` transformed as a vector (`w = 0`), the translation left out:
    /// the first three coordinates of `self * [v, 0]` (glam's
    /// `Mat4::transform_vector3`).
    ///
    /// # Preconditions
    ///
    /// `self` is affine (its last row is not read). To transform normals
    /// under a non-uniform scale use [`normal_matrix3`](Self::normal_matrix3).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::X);
    /// assert_eq!(m.transform_vector3(Cvec3::Y), Cvec3::Y);
    /// ```
    #[inline]
    #[must_use]
    pub fn transform_vector3(&self, v: Cvec3) -> Cvec3 {
        (*self * Cvec4::from_vector(v)).xyz()
    }

    /// `p` transformed as a point by a projection, with the divide by `w`:
    /// `self * [p, 1]` as `[x, y, z] / w` (glam's `Mat4::project_point3`).
    ///
    /// # Preconditions
    ///
    /// None. Where `w` is zero (a point in the eye's plane) the result is
    /// infinite or NaN, never a panic.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Matrix4};
    /// let p = Matrix4::perspective_rh(FRAC_PI_2, 1.0, 1.0, 10.0);
    /// // The near plane lands at depth 0, the far plane at 1.
    /// assert!(p.project_point3(Cvec3::new(0.0, 0.0, -1.0)).z.abs() < 1e-6);
    /// assert!((p.project_point3(Cvec3::new(0.0, 0.0, -10.0)).z - 1.0).abs() < 1e-6);
    /// ```
    #[inline]
    #[must_use]
    pub fn project_point3(&self, p: Cvec3) -> Cvec3 {
        let h = *self * Cvec4::from_point(p);
        h.xyz() / h.w
    }

    /// The normal matrix as a [`Matrix3`] (a shader's `mat3`): the inverse
    /// transpose of the upper 3x3 block, the same entries as
    /// [`normal_matrix`](Self::normal_matrix)'s upper block.
    ///
    /// # Preconditions
    ///
    /// None: `None` where [`normal_matrix`](Self::normal_matrix) is `None`
    /// (a singular or non-finite block, or one whose inverse would not fit).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix3, Matrix4};
    /// let n = Matrix4::from_scale(Cvec3::new(2.0, 4.0, 0.5)).normal_matrix3().unwrap();
    /// assert_eq!(n, Matrix3::from_cols(Cvec3::X * 0.5, Cvec3::Y * 0.25, Cvec3::Z * 2.0));
    /// ```
    #[must_use]
    pub fn normal_matrix3(&self) -> Option<Matrix3> {
        self.normal_matrix().map(Matrix3::from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn g4(m: Matrix4) -> glam::Mat4 {
        glam::Mat4::from_cols_array(&m.to_cols_array())
    }

    fn gv(v: Cvec3) -> glam::Vec3 {
        glam::Vec3::new(v.x, v.y, v.z)
    }

    fn gq(q: Quat) -> glam::Quat {
        glam::Quat::from_xyzw(q.x, q.y, q.z, q.w)
    }

    fn cv(v: glam::Vec3) -> Cvec3 {
        Cvec3::new(v.x, v.y, v.z)
    }

    use crate::test_draws::count as draws;

    use crate::test_draws::unit_quat;

    /// The f32 rounding of a unit quaternion (drawn in f64): `|q|^2` within
    /// 2^-23 of 1, the domain of `SRT_SCALE_MAX_REL_ERROR`'s proof.
    fn rounded_unit_quat(rng: &mut impl Rng) -> Quat {
        loop {
            let q: [f64; 4] = core::array::from_fn(|_| rng.random_range(-1.0..1.0));
            let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
            if n > 0.1 {
                let [w, x, y, z] = q.map(|c| (c / n) as f32);
                return Quat::from_wxyz(w, x, y, z);
            }
        }
    }

    /// `|q|^2 - 1` in f64, exact for f32 components up to one rounding.
    fn norm_squared_error(q: Quat) -> f32 {
        let [x, y, z, w] = [q.x, q.y, q.z, q.w].map(f64::from);
        (w * w + x * x + y * y + z * z - 1.0) as f32
    }

    /// A scale of magnitude in [1e-3, 1e3], log-uniform.
    fn scale(rng: &mut impl Rng) -> f32 {
        10f32.powf(rng.random_range(-3.0..=3.0))
    }

    #[test]
    fn trs_round_trips_within_its_bounds_and_agrees_with_glam() {
        use crate::accuracy::{SRT_ROTATION_MAX_ANGLE_ERROR, SRT_SCALE_MAX_REL_ERROR};
        let mut rng = rand::rngs::StdRng::seed_from_u64(29);
        let (mut worst_r, mut worst_s) = (0f32, 0f32);
        for i in 0..draws() {
            // Every other rotation a result of `normalize`, whose `|q|^2` may
            // lie further from 1: the exact column of `from_quat` then has
            // length^2 `1 + 4 (y^2 + z^2) (|q|^2 - 1)`, and the scale carries
            // up to twice that distance besides.
            let q = if i % 2 == 0 {
                rounded_unit_quat(&mut rng)
            } else {
                unit_quat(&mut rng)
            };
            let allowed = SRT_SCALE_MAX_REL_ERROR + 2.0 * norm_squared_error(q).abs();
            let sign = if rng.random() { 1.0 } else { -1.0 };
            let s = Cvec3::new(sign * scale(&mut rng), scale(&mut rng), scale(&mut rng));
            let t = Cvec3::new(rng.random(), rng.random(), rng.random()) * 100.0;
            let m = Matrix4::from_scale_rotation_translation(s, q, t);
            let theirs = glam::Mat4::from_scale_rotation_translation(gv(s), gq(q), gv(t));
            assert!(g4(m).abs_diff_eq(theirs, 1e-6 * s.abs().max_element()));
            let (s2, q2, t2) = m.to_scale_rotation_translation();
            let angle = q2.angle_to(q);
            let rel = ((s2 - s) / s).abs().max_element();
            worst_r = worst_r.max(angle);
            if i % 2 == 0 {
                worst_s = worst_s.max(rel);
            }
            assert!(
                angle <= SRT_ROTATION_MAX_ANGLE_ERROR,
                "{s:?} {q:?}: {angle:e}"
            );
            assert!(rel <= allowed, "{s:?} {q:?}: {rel:e}");
            assert_eq!(t2, t);
            let (gs, gr, gt) = g4(m).to_scale_rotation_translation();
            assert!(((cv(gs) - s2) / s2).abs().max_element() < 1e-5);
            assert!(q2.angle_to(Quat::from_xyzw(gr.x, gr.y, gr.z, gr.w)) < 1e-4);
            assert_eq!(cv(gt), t2);
        }
        std::println!(
            "to_scale_rotation_translation over {} draws: rotation {worst_r:.3e} rad, scale {worst_s:.3e} relative (rounded unit rotations)",
            draws()
        );
        // Any signs: the parts rebuild the matrix.
        let s = Cvec3::new(2.0, -3.0, 0.5);
        let m = Matrix4::from_scale_rotation_translation(s, Quat::from_rotation_x(0.3), Cvec3::Y);
        let (s2, q2, t2) = m.to_scale_rotation_translation();
        assert!(s2.x < 0.0 && s2.y > 0.0);
        let back = Matrix4::from_scale_rotation_translation(s2, q2, t2);
        assert!(g4(back).abs_diff_eq(g4(m), 1e-5));
        // Degenerate blocks: a NaN rotation, no panic.
        let (s0, q0, _) =
            Matrix4::from_scale(Cvec3::new(1.0, 0.0, 1.0)).to_scale_rotation_translation();
        assert!(q0.w.is_nan() && s0 == Cvec3::new(1.0, 0.0, 1.0));
        let (_, q0, _) = Matrix4::from_scale(Cvec3::NAN).to_scale_rotation_translation();
        assert!(q0.w.is_nan());
        let q = Quat::from_rotation_y(-1.0);
        let m = Matrix4::from_rotation_translation(q, Cvec3::X);
        assert_eq!(
            g4(m).to_cols_array(),
            g4(Matrix4::from(RigTForm::new(Cvec3::X, q))).to_cols_array()
        );
        assert!(g4(m).abs_diff_eq(
            glam::Mat4::from_rotation_translation(gq(q), glam::Vec3::X),
            1e-6
        ));
    }

    #[test]
    fn transforms_rows_and_columns_agree_with_glam() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(30);
        for _ in 0..10_000 {
            let m =
                Matrix4::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..=4.0)));
            let p = Cvec3::new(rng.random(), rng.random(), rng.random()) * 8.0;
            let g = g4(m);
            let close = |a: Cvec3, b: glam::Vec3, scale: f32| {
                (a - cv(b)).abs().max_element() <= 1e-6 * scale
            };
            assert!(close(
                m.transform_point3(p),
                g.transform_point3(gv(p)),
                64.0
            ));
            assert!(close(
                m.transform_vector3(p),
                g.transform_vector3(gv(p)),
                64.0
            ));
            let h = m * Cvec4::from_point(p);
            let projected = m.project_point3(p);
            assert!(close(projected, g.project_point3(gv(p)), 64.0 / h.w.abs()));
            for i in 0..4 {
                assert_eq!(m.col(i).to_array(), g.col(i).to_array());
                assert_eq!(m.row(i).to_array(), g.row(i).to_array());
            }
            assert!(m.col(4).is_nan() && m.row(4).is_nan() && m.col(usize::MAX).is_nan());
            match (m.normal_matrix3(), m.normal_matrix()) {
                (Some(n3), Some(n4)) => {
                    assert_eq!(n3, Matrix3::from(n4));
                    let theirs = glam::Mat3::from_mat4(g).inverse().transpose();
                    let size = theirs
                        .to_cols_array()
                        .iter()
                        .fold(0f32, |a, b| a.max(b.abs()));
                    let ours = glam::Mat3::from_cols_array(&n3.to_cols_array());
                    assert!(ours.abs_diff_eq(theirs, 1e-3 * size), "{m:?}");
                }
                (None, None) => {}
                (a, b) => panic!("normal_matrix3 {a:?} but normal_matrix {b:?}"),
            }
        }
        // w = 0: infinite or NaN, no panic.
        let flat = Matrix4::from_cols(Cvec4::X, Cvec4::Y, Cvec4::Z, Cvec4::ZERO);
        assert!(!flat.project_point3(Cvec3::ONE).is_finite());
    }
}
