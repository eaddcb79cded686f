//! The view and projection matrices of glam's camera functions on
//! [`Matrix4`], under the names glam's `Mat4` had for them (`look_at_rh`,
//! `perspective_rh`, ...; glam 0.34 has them as `camera::rh::view::look_at_mat4`
//! and `camera::rh::proj::{directx, opengl}::perspective...`). All are
//! right-handed: the eye looks down its -z axis.

use super::Matrix4;
use crate::float;
use crate::rigtform::RigTForm;
use crate::vec::{Cvec3, Cvec4};

impl Matrix4 {
    /// The view matrix of an eye at `eye` looking at `center`, its y axis
    /// as close to `up` as that allows: world coordinates to the eye's
    /// (glam's `camera::rh::view::look_at_mat4`, formerly
    /// `Mat4::look_at_rh`, and nalgebra's `Matrix4::look_at_rh`).
    ///
    /// This is the inverse of the eye frame [`RigTForm::look_at`]:
    /// `Matrix4::look_at_rh(eye, center, up)` is
    /// `Matrix4::from(RigTForm::look_at(eye, center, up).inv())`, exactly
    /// (it is computed that way).
    ///
    /// # Preconditions
    ///
    /// As [`RigTForm::look_at`]: `up` need not be of unit length; where it
    /// is zero or parallel to the line of sight the roll is the shortest
    /// turn's, and where `eye == center` the view looks down -z. NaN or
    /// infinite input gives NaN entries, never a panic (glam asserts or
    /// gives NaN there).
    ///
    /// # Accuracy
    ///
    /// The rotation block within
    /// [`accuracy::LOOK_AT_MAX_ANGLE_ERROR`](crate::accuracy::LOOK_AT_MAX_ANGLE_ERROR)
    /// radians (plus [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
    /// per entry) of the exact view of the same f32 points while `up` is at
    /// least 0.1 rad off the line of sight, and the translation within
    /// [`accuracy::LOOK_AT_RH_MAX_TRANSLATION_ERROR`](crate::accuracy::LOOK_AT_RH_MAX_TRANSLATION_ERROR)
    /// times `|eye|` (`src/matrix/camera.rs`'s tests, against nalgebra in
    /// f64).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let view = Matrix4::look_at_rh(Cvec3::new(0.0, 3.0, 4.0), Cvec3::ZERO, Cvec3::Y);
    /// // The target is straight ahead of the eye, 5 away.
    /// assert!((view.transform_point3(Cvec3::ZERO) - Cvec3::new(0.0, 0.0, -5.0)).norm() < 1e-5);
    /// ```
    #[doc(alias = "look_at_mat4")]
    #[doc(alias = "view")]
    #[must_use]
    pub fn look_at_rh(eye: Cvec3, center: Cvec3, up: Cvec3) -> Self {
        Self::from_rig_tform(RigTForm::look_at(eye, center, up).inv())
    }

    /// The perspective projection for wgpu, Vulkan, Metal and Direct3D:
    /// right-handed (the eye looks down -z), NDC depth 0 at `z = -near`
    /// and 1 at `z = -far`, y up (glam's
    /// `camera::rh::proj::directx::perspective`, formerly
    /// `Mat4::perspective_rh`). Vulkan's y points down: negate
    /// `cols[1].y`, or flip the viewport.
    ///
    /// # Preconditions
    ///
    /// `0 < fov_y < pi` (vertical field of view, radians), `aspect > 0`
    /// (width / height), `0 < near < far`, all finite. Nothing is checked
    /// and nothing panics: outside these, entries may be infinite or NaN
    /// (`near == far` divides by zero).
    ///
    /// # Accuracy
    ///
    /// The field-of-view entries within
    /// [`accuracy::TAN_MAX_REL_ERROR`](crate::accuracy::TAN_MAX_REL_ERROR)
    /// (plus a rounding) of `1 / tan(fov_y / 2)`; the depth entries are one
    /// division and product each.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Matrix4};
    /// let p = Matrix4::perspective_rh(FRAC_PI_2, 1.0, 0.5, 100.0);
    /// assert!(p.project_point3(Cvec3::new(0.0, 0.0, -0.5)).z.abs() < 1e-6);
    /// assert!((p.project_point3(Cvec3::new(0.0, 0.0, -100.0)).z - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn perspective_rh(fov_y: f32, aspect: f32, near: f32, far: f32) -> Self {
        let f = 1.0 / float::tan(fov_y * 0.5);
        let depth = near - far;
        Self::from_cols(
            Cvec4::new(f / aspect, 0.0, 0.0, 0.0),
            Cvec4::new(0.0, f, 0.0, 0.0),
            Cvec4::new(0.0, 0.0, far / depth, -1.0),
            Cvec4::new(0.0, 0.0, near * far / depth, 0.0),
        )
    }

    /// The reverse-Z perspective projection with no far plane: right-handed,
    /// NDC depth 1 at `z = -near`, falling towards 0 at infinity (glam's
    /// `camera::rh::proj::directx::perspective_infinite_reverse`, formerly
    /// `Mat4::perspective_infinite_reverse_rh`). With a depth buffer cleared
    /// to 0 and the test `GREATER`, floating-point depth keeps its
    /// precision far away.
    ///
    /// # Preconditions
    ///
    /// `0 < fov_y < pi`, `aspect > 0`, `near > 0`, all finite. Nothing is
    /// checked and nothing panics.
    ///
    /// # Accuracy
    ///
    /// As [`perspective_rh`](Self::perspective_rh); the depth entries are
    /// `near` and -1, exactly.
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Matrix4};
    /// let p = Matrix4::perspective_infinite_reverse_rh(FRAC_PI_2, 1.0, 0.1);
    /// assert!((p.project_point3(Cvec3::new(0.0, 0.0, -0.1)).z - 1.0).abs() < 1e-6);
    /// assert!(p.project_point3(Cvec3::new(0.0, 0.0, -1e6)).z < 1e-6);
    /// ```
    #[must_use]
    pub fn perspective_infinite_reverse_rh(fov_y: f32, aspect: f32, near: f32) -> Self {
        let f = 1.0 / float::tan(fov_y * 0.5);
        Self::from_cols(
            Cvec4::new(f / aspect, 0.0, 0.0, 0.0),
            Cvec4::new(0.0, f, 0.0, 0.0),
            Cvec4::new(0.0, 0.0, 0.0, -1.0),
            Cvec4::new(0.0, 0.0, near, 0.0),
        )
    }

    /// glam's name for [`perspective`](Self::perspective), the OpenGL
    /// projection (`gluPerspective`: right-handed, NDC depth -1 at
    /// `z = -near` and +1 at `z = -far`); glam 0.34's
    /// `camera::rh::proj::opengl::perspective`. The same matrix, entry for
    /// entry.
    ///
    /// # Preconditions
    ///
    /// As [`perspective`](Self::perspective).
    ///
    /// ```
    /// use rigtform::Matrix4;
    /// assert_eq!(Matrix4::perspective_rh_gl(1.0, 1.5, 0.1, 100.0), Matrix4::perspective(1.0, 1.5, 0.1, 100.0));
    /// ```
    #[inline]
    #[must_use]
    pub fn perspective_rh_gl(fov_y: f32, aspect: f32, near: f32, far: f32) -> Self {
        Self::perspective(fov_y, aspect, near, far)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{
        LOOK_AT_MAX_ANGLE_ERROR, LOOK_AT_RH_MAX_TRANSLATION_ERROR, MATRIX_ENTRY_ERROR,
    };
    use rand::{Rng, SeedableRng};

    fn g4(m: Matrix4) -> glam::Mat4 {
        glam::Mat4::from_cols_array(&m.to_cols_array())
    }

    fn gv(v: Cvec3) -> glam::Vec3 {
        glam::Vec3::new(v.x, v.y, v.z)
    }

    fn p64(v: Cvec3) -> nalgebra::Point3<f64> {
        nalgebra::Point3::new(v.x.into(), v.y.into(), v.z.into())
    }

    use crate::test_draws::count as draws;

    fn cube(rng: &mut impl Rng, half: f32) -> Cvec3 {
        Cvec3::new(
            rng.random_range(-half..=half),
            rng.random_range(-half..=half),
            rng.random_range(-half..=half),
        )
    }

    #[test]
    fn look_at_rh_is_the_view_matrix_of_nalgebra_and_glam_and_the_inverse_eye_frame() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(31);
        let (mut worst_r, mut worst_t, mut seen) = (0f64, 0f64, 0usize);
        for _ in 0..draws() {
            let eye = cube(&mut rng, 100.0);
            let center = cube(&mut rng, 100.0);
            let up = cube(&mut rng, 1.0);
            // up at least 0.1 rad off the line of sight (the documented range).
            let sight = center - eye;
            if up.norm() < 1e-3 || sight.norm() < 1e-3 {
                continue;
            }
            let off = sight.angle_between(up);
            if !(0.1..=core::f32::consts::PI - 0.1).contains(&off) {
                continue;
            }
            seen += 1;
            let view = Matrix4::look_at_rh(eye, center, up);
            assert_eq!(
                view,
                Matrix4::from(RigTForm::look_at(eye, center, up).inv())
            );
            let want = nalgebra::Matrix4::look_at_rh(
                &p64(eye),
                &p64(center),
                &nalgebra::Vector3::new(up.x.into(), up.y.into(), up.z.into()),
            );
            let got = nalgebra::Matrix4::from_column_slice(&view.to_cols_array().map(f64::from));
            let block = (got.fixed_view::<3, 3>(0, 0) - want.fixed_view::<3, 3>(0, 0))
                .abs()
                .max();
            let translation = (got.fixed_view::<3, 1>(0, 3) - want.fixed_view::<3, 1>(0, 3)).norm()
                / f64::from(eye.norm()).max(f64::MIN_POSITIVE);
            worst_r = worst_r.max(block);
            worst_t = worst_t.max(translation);
            assert!(
                block <= f64::from(LOOK_AT_MAX_ANGLE_ERROR + MATRIX_ENTRY_ERROR),
                "{eye:?} {center:?} {up:?}: {block:e}"
            );
            assert!(
                translation <= f64::from(LOOK_AT_RH_MAX_TRANSLATION_ERROR),
                "{eye:?} {center:?} {up:?}: {translation:e}"
            );
            let theirs =
                glam::camera::rh::view::look_at_mat4(gv(eye), gv(center), gv(up.normalize()));
            assert!(
                g4(view).abs_diff_eq(theirs, 1e-5 * eye.norm().max(1.0)),
                "{view:?} vs {theirs:?}"
            );
        }
        std::println!(
            "look_at_rh over {seen} draws: rotation entries {worst_r:.3e}, translation {worst_t:.3e} relative to |eye|"
        );
        assert!(
            Matrix4::look_at_rh(Cvec3::NAN, Cvec3::ZERO, Cvec3::Y).cols[0]
                .x
                .is_nan()
        );
        // Up along the sight: still a rotation, no panic.
        assert!(Matrix4::look_at_rh(Cvec3::Y, Cvec3::ZERO, Cvec3::Y).is_finite());
    }

    #[test]
    fn projections_agree_with_glams_camera_functions() {
        use glam::camera::rh::proj::{directx, opengl};
        let mut rng = rand::rngs::StdRng::seed_from_u64(32);
        // glam's cotangent is cos / sin; ours 1 / tan.
        let tol = 1e-6 + 2.0 * crate::accuracy::TAN_MAX_REL_ERROR;
        for _ in 0..10_000 {
            let fov = rng.random_range(0.1..3.0);
            let aspect = rng.random_range(0.25..4.0);
            let near = 10f32.powf(rng.random_range(-3.0..1.0));
            let far = near * 10f32.powf(rng.random_range(0.1..5.0));
            let close = |a: Matrix4, b: glam::Mat4| {
                a.to_cols_array()
                    .iter()
                    .zip(b.to_cols_array())
                    .all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1e-30))
            };
            assert!(close(
                Matrix4::perspective_rh(fov, aspect, near, far),
                directx::perspective(fov, aspect, near, far)
            ));
            assert!(close(
                Matrix4::perspective_infinite_reverse_rh(fov, aspect, near),
                directx::perspective_infinite_reverse(fov, aspect, near)
            ));
            assert!(close(
                Matrix4::perspective_rh_gl(fov, aspect, near, far),
                opengl::perspective(fov, aspect, near, far)
            ));
            let p = Matrix4::perspective_rh(fov, aspect, near, far);
            // The depth row does not depend on the field of view.
            assert!(p.project_point3(Cvec3::new(0.0, 0.0, -near)).z.abs() < 1e-6);
            assert!((p.project_point3(Cvec3::new(0.0, 0.0, -far)).z - 1.0).abs() < 1e-5);
            let r = Matrix4::perspective_infinite_reverse_rh(fov, aspect, near);
            assert!((r.project_point3(Cvec3::new(0.0, 0.0, -near)).z - 1.0).abs() < 1e-6);
        }
    }
}
