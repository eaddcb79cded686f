//! The three ways of the notes to go from one keyframe to the next: lerping
//! the 4x4 matrices (bad idea 1), lerping Euler angles (bad idea 2), and
//! `RigTForm::interpolate` (lerp the translation, slerp the rotation).
//!
//! Each is computed in a chosen world frame: with `w' = w G` the keyframes
//! there are `G^-1 K`, and the result, `G interp(G^-1 K0, G^-1 K1)`, is
//! expressed back in `w` so that it can be drawn from the same camera. A
//! left-invariant method gives the same motion for every `G`.

use rigtform::{EulerRot, Matrix4, Quat, RigTForm};

use crate::vertex::Placement;

/// An interpolation method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// `(1 - alpha) M0 + alpha M1` on the 4x4 matrices: each basis vector
    /// moves on a straight line, so the object shears and shrinks.
    MatrixLerp,
    /// Translation lerped, rotation factored into Euler angles
    /// ([`lerp_euler_angles`]) and each angle lerped: an unnatural path that depends on
    /// the world frame.
    EulerLerp,
    /// [`RigTForm::interpolate`]: the origin on a straight line at constant
    /// speed, the object turning about one axis at constant angular velocity.
    Slerp,
}

/// The lerp of two matrices, entry by entry.
///
/// ```
/// use rigtform::{Cvec3, Matrix4};
/// use rigtform_render::demo::interpolation::lerp_matrix;
/// let a = Matrix4::from_scale(Cvec3::new(1.0, 1.0, 1.0));
/// let b = Matrix4::from_scale(Cvec3::new(3.0, 3.0, 3.0));
/// assert_eq!(lerp_matrix(a, b, 0.5), Matrix4::from_scale(Cvec3::new(2.0, 2.0, 2.0)));
/// ```
#[must_use]
pub fn lerp_matrix(a: Matrix4, b: Matrix4, alpha: f32) -> Matrix4 {
    let [a0, a1, a2, a3] = a.cols;
    let [b0, b1, b2, b3] = b.cols;
    Matrix4::from_cols(
        a0.lerp(b0, alpha),
        a1.lerp(b1, alpha),
        a2.lerp(b2, alpha),
        a3.lerp(b3, alpha),
    )
}

impl Method {
    /// Where the object is at `alpha` between keyframes `k0` and `k1`,
    /// interpolated in the world frame `w' = w world` and expressed in `w`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// use rigtform_render::demo::interpolation::Method;
    /// use rigtform_render::Placement;
    /// let k0 = RigTForm::IDENTITY;
    /// let k1 = RigTForm::new(Cvec3::X, Quat::from_rotation_z(1.0));
    /// let Placement::Rigid(mid) = Method::Slerp.placement(k0, k1, RigTForm::IDENTITY, 0.5) else {
    ///     unreachable!()
    /// };
    /// assert!(mid.r.angle_to(Quat::from_rotation_z(0.5)) < 1e-6);
    /// ```
    #[must_use]
    pub fn placement(self, k0: RigTForm, k1: RigTForm, world: RigTForm, alpha: f32) -> Placement {
        let to_world = world.inv();
        let (a, b) = (to_world * k0, to_world * k1);
        match self {
            Method::MatrixLerp => Placement::Matrix(
                Matrix4::from(world) * lerp_matrix(Matrix4::from(a), Matrix4::from(b), alpha),
            ),
            Method::EulerLerp => {
                let r = lerp_euler_angles(a.r, b.r, alpha);
                Placement::Rigid(world * RigTForm::new(a.t.lerp(b.t, alpha), r))
            }
            Method::Slerp => Placement::Rigid(world * a.interpolate(b, alpha)),
        }
    }
}

/// The "bad idea": each of the yaw, pitch and roll angles of the two
/// rotations ([`EulerRot::ZYX`], the same as turning about the world's x,
/// then y, then z axis) lerped on its own.
///
/// ```
/// use rigtform::{EulerRot, Quat};
/// use rigtform_render::demo::interpolation::lerp_euler_angles;
/// let a = Quat::from_euler(EulerRot::ZYX, -1.0, 0.2, 0.0);
/// let b = Quat::from_euler(EulerRot::ZYX, 1.0, 0.4, 1.0);
/// let mid = lerp_euler_angles(a, b, 0.5);
/// assert!(mid.angle_to(Quat::from_euler(EulerRot::ZYX, 0.0, 0.3, 0.5)) < 1e-6);
/// ```
#[must_use]
pub fn lerp_euler_angles(a: Quat, b: Quat, alpha: f32) -> Quat {
    let (a, b) = (a.to_euler(EulerRot::ZYX), b.to_euler(EulerRot::ZYX));
    let lerp = |x: f32, y: f32| x + (y - x) * alpha;
    Quat::from_euler(
        EulerRot::ZYX,
        lerp(a.0, b.0),
        lerp(a.1, b.1),
        lerp(a.2, b.2),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use rigtform::{Cvec3, Cvec4};

    fn keyframes() -> (RigTForm, RigTForm) {
        let k0 = RigTForm::new(Cvec3::new(-1.0, 1.0, 0.0), Quat::from_rotation_x(0.3));
        let k1 = RigTForm::new(
            Cvec3::new(2.0, 1.0, -1.0),
            Quat::from_axis_angle(Cvec3::new(1.0, 1.0, 0.2), 2.6) * k0.r,
        );
        (k0, k1)
    }

    fn world() -> RigTForm {
        RigTForm::new(
            Cvec3::new(0.5, -2.0, 1.0),
            Quat::from_axis_angle(Cvec3::new(0.2, 0.4, 1.0), 1.3),
        )
    }

    fn apply(placement: Placement, p: Cvec3) -> Cvec3 {
        match placement {
            Placement::Rigid(r) => r.transform_point(p),
            Placement::Matrix(m) => (m * Cvec4::from_point(p)).xyz(),
        }
    }

    /// The largest distance between where the two placements put the corners
    /// of the unit cube.
    fn gap(a: Placement, b: Placement) -> f32 {
        (0..8)
            .map(|i| Cvec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32))
            .map(|p| (apply(a, p) - apply(b, p)).norm())
            .fold(0.0, f32::max)
    }

    #[test]
    fn every_method_hits_both_keyframes() {
        let (k0, k1) = keyframes();
        for m in [Method::MatrixLerp, Method::EulerLerp, Method::Slerp] {
            for w in [RigTForm::IDENTITY, world()] {
                assert!(
                    gap(m.placement(k0, k1, w, 0.0), Placement::Rigid(k0)) < 1e-4,
                    "{m:?}"
                );
                assert!(
                    gap(m.placement(k0, k1, w, 1.0), Placement::Rigid(k1)) < 1e-4,
                    "{m:?}"
                );
            }
        }
    }

    #[test]
    fn slerp_is_left_invariant_and_euler_lerp_is_not() {
        let (k0, k1) = keyframes();
        for alpha in [0.25, 0.5, 0.75] {
            let slerp = |w| Method::Slerp.placement(k0, k1, w, alpha);
            let euler = |w| Method::EulerLerp.placement(k0, k1, w, alpha);
            assert!(gap(slerp(RigTForm::IDENTITY), slerp(world())) < 1e-4);
            assert!(gap(euler(RigTForm::IDENTITY), euler(world())) > 0.1);
        }
    }

    #[test]
    fn matrix_lerp_shrinks_the_object_and_slerp_keeps_it_rigid() {
        let (k0, k1) = keyframes();
        let Placement::Matrix(m) = Method::MatrixLerp.placement(k0, k1, RigTForm::IDENTITY, 0.5)
        else {
            panic!("matrix lerp gives a matrix");
        };
        // The determinant is the volume scale.
        let det = m.determinant();
        // Turning by theta, the lerp halfway scales the plane of the turn
        // by cos(theta / 2) in each direction.
        let expected = (1.3f32).cos().powi(2);
        assert!(
            (det - expected).abs() < 1e-3,
            "det {det}, expected {expected}"
        );
        let Placement::Rigid(r) = Method::Slerp.placement(k0, k1, RigTForm::IDENTITY, 0.5) else {
            panic!("slerp gives a rigid body transform");
        };
        assert!((r.r.norm() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn euler_lerp_path_differs_from_slerp() {
        let (k0, k1) = keyframes();
        let (Placement::Rigid(e), Placement::Rigid(s)) = (
            Method::EulerLerp.placement(k0, k1, RigTForm::IDENTITY, 0.5),
            Method::Slerp.placement(k0, k1, RigTForm::IDENTITY, 0.5),
        ) else {
            panic!("both are rigid");
        };
        assert!(e.r.angle_to(s.r) > 0.2);
        assert!((e.t - s.t).norm() < 1e-6, "both lerp the translation");
    }
}
