//! Euler angles, only to show why the notes reject them ("bad idea 2"):
//! `R = Rz(z) Ry(y) Rx(x)`, i.e. turn about the world x axis first, then
//! about y, then about z.

use rigtform::{Matrix4, Quat};

/// Three angles in radians: `x` in (-pi, pi], `y` in [-pi/2, pi/2],
/// `z` in (-pi, pi].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Euler {
    /// Angle about the x axis, applied first.
    pub x: f32,
    /// Angle about the y axis, applied second.
    pub y: f32,
    /// Angle about the z axis, applied last.
    pub z: f32,
}

impl Euler {
    /// Factors the rotation `q` into Euler angles. At gimbal lock
    /// (`y = +-pi/2`) the split between `x` and `z` is not unique and `z` is
    /// set to zero.
    ///
    /// ```
    /// use rigtform::Quat;
    /// use rigtform_render::demo::euler::Euler;
    /// let e = Euler::from_quat(Quat::from_rotation_y(0.5));
    /// assert!(e.x.abs() < 1e-6 && (e.y - 0.5).abs() < 1e-6 && e.z.abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn from_quat(q: Quat) -> Self {
        let [c0, c1, c2, _] = Matrix4::from_quat(q).cols;
        // m[row][col]: Rz Ry Rx has m20 = -sin y, m21 = cos y sin x,
        // m22 = cos y cos x, m10 = sin z cos y, m00 = cos z cos y.
        let (m00, m10, m20) = (c0.x, c0.y, c0.z);
        let (m11, m21) = (c1.y, c1.z);
        let (m12, m22) = (c2.y, c2.z);
        let y = (-m20).clamp(-1.0, 1.0).asin();
        if m20.abs() < 1.0 - 1e-6 {
            Self {
                x: m21.atan2(m22),
                y,
                z: m10.atan2(m00),
            }
        } else {
            // cos y = 0: with z = 0, m11 = cos x and m12 = -sin x.
            Self {
                x: (-m12).atan2(m11),
                y,
                z: 0.0,
            }
        }
    }

    /// The rotation `Rz(z) Ry(y) Rx(x)`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// use rigtform_render::demo::euler::Euler;
    /// let q = Euler { x: 0.0, y: 0.0, z: 0.7 }.to_quat();
    /// assert!(q.angle_to(Quat::from_rotation_z(0.7)) < 1e-6);
    /// ```
    #[must_use]
    pub fn to_quat(self) -> Quat {
        Quat::from_rotation_z(self.z)
            * Quat::from_rotation_y(self.y)
            * Quat::from_rotation_x(self.x)
    }

    /// Each angle lerped on its own: the "bad idea".
    ///
    /// ```
    /// use rigtform_render::demo::euler::Euler;
    /// let a = Euler { x: 0.0, y: 0.2, z: -1.0 };
    /// let b = Euler { x: 1.0, y: 0.4, z: 1.0 };
    /// let mid = a.lerp(b, 0.5);
    /// assert!((mid.x - 0.5).abs() < 1e-6 && (mid.y - 0.3).abs() < 1e-6 && mid.z.abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn lerp(self, other: Self, alpha: f32) -> Self {
        let l = |a: f32, b: f32| a + (b - a) * alpha;
        Self {
            x: l(self.x, other.x),
            y: l(self.y, other.y),
            z: l(self.z, other.z),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rigtform::Cvec3;

    #[test]
    fn euler_angles_round_trip() {
        let mut n = 0;
        for i in 0..20 {
            for j in 0..20 {
                let axis = Cvec3::new(
                    (i as f32).sin(),
                    (j as f32 * 0.7).cos(),
                    0.3 + i as f32 * 0.1,
                );
                let q = Quat::from_axis_angle(axis, -3.1 + 0.31 * j as f32);
                let back = Euler::from_quat(q).to_quat();
                assert!(q.angle_to(back) < 2e-3, "{q:?}: {}", q.angle_to(back));
                n += 1;
            }
        }
        assert_eq!(n, 400);
    }

    #[test]
    fn euler_angles_round_trip_at_gimbal_lock() {
        for x in [-2.0f32, 0.0, 0.4, 3.0] {
            let e = Euler {
                x,
                y: core::f32::consts::FRAC_PI_2,
                z: 0.0,
            };
            let back = Euler::from_quat(e.to_quat()).to_quat();
            assert!(e.to_quat().angle_to(back) < 2e-3);
        }
    }

    #[test]
    fn euler_angles_compose_in_xyz_order() {
        let e = Euler {
            x: 0.3,
            y: -0.2,
            z: 1.1,
        };
        let q = e.to_quat();
        let expected =
            Quat::from_rotation_z(1.1) * Quat::from_rotation_y(-0.2) * Quat::from_rotation_x(0.3);
        assert!(q.angle_to(expected) < 1e-6);
        let f = Euler::from_quat(q);
        assert!((f.x - 0.3).abs() < 1e-5 && (f.y + 0.2).abs() < 1e-5 && (f.z - 1.1).abs() < 1e-5);
    }
}
