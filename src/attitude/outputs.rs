//! What firmware reads off an [`OrientationFilter`] besides the attitude:
//! gravity and linear acceleration in the sensor and earth frames, the
//! heading, and Euler angles.

use super::OrientationFilter;
use crate::float;
use crate::quat::EulerRot;
use crate::vec::Cvec3;

impl OrientationFilter {
    /// Gravity's reaction as the accelerometer sees it at the current
    /// attitude: the earth's up, `params.gravity` long, in the sensor frame
    /// (what a still accelerometer reads).
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, Quat::from_rotation_x(0.5));
    /// let acc = Quat::from_rotation_x(0.5).inv() * Cvec3::new(0.0, 0.0, 9.81);
    /// assert!((f.gravity() - acc).norm() < 1e-5);
    /// ```
    #[must_use]
    pub fn gravity(&self) -> Cvec3 {
        self.attitude().inv() * Cvec3::new(0.0, 0.0, self.params.gravity)
    }

    /// The linear acceleration in the sensor frame: the accelerometer
    /// reading `acc` (specific force, in the unit of `params.gravity`) less
    /// [`gravity`](Self::gravity). Zero for a sensor at rest.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// let f = OrientationFilter::new(FilterParams::DEFAULT); // level
    /// let acc = Cvec3::new(2.0, 0.0, 9.81); // pushed along x at 2 m/s²
    /// assert!((f.linear_acceleration(acc) - Cvec3::new(2.0, 0.0, 0.0)).norm() < 1e-6);
    /// ```
    #[must_use]
    pub fn linear_acceleration(&self, acc: Cvec3) -> Cvec3 {
        acc - self.gravity()
    }

    /// The linear acceleration in the earth frame (ENU): the reading `acc`
    /// turned into the earth frame, less gravity's `(0, 0, params.gravity)`.
    /// What a dead-reckoning step integrates.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// // Facing west (a quarter turn about up), pushed along the sensor's x:
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, Quat::from_rotation_z(1.5707964));
    /// let a = f.earth_acceleration(Cvec3::new(2.0, 0.0, 9.81));
    /// assert!((a - Cvec3::new(0.0, 2.0, 0.0)).norm() < 1e-5); // northwards
    /// ```
    #[must_use]
    pub fn earth_acceleration(&self, acc: Cvec3) -> Cvec3 {
        self.attitude() * acc - Cvec3::new(0.0, 0.0, self.params.gravity)
    }

    /// The compass heading of the sensor's y axis, in radians east of
    /// (magnetic, in 9D) north, in (-pi, pi]: 0 with y pointing north,
    /// pi / 2 with it pointing east. It is the heading of the y axis's
    /// horizontal part, so it stays defined up to a tilt of nearly 90°; 0
    /// when y points straight up or down.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Quat;
    /// // Turned 0.5 rad anticlockwise seen from above: 0.5 rad west of north.
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, Quat::from_rotation_z(0.5));
    /// assert!((f.heading() + 0.5).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn heading(&self) -> f32 {
        let forward = self.attitude() * Cvec3::Y;
        float::atan2(forward.x, forward.y)
    }

    /// The attitude as Euler angles in the given order (see [`EulerRot`]
    /// and [`Quat::to_euler`](crate::Quat::to_euler)), in radians; with `EulerRot::ZYX`, yaw about
    /// the earth's up (anticlockwise from the east-north frame, so
    /// `-heading`), then pitch, then roll.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{EulerRot, Quat};
    /// let q = Quat::from_euler(EulerRot::ZYX, 0.3, -0.2, 0.1);
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, q);
    /// let (yaw, pitch, roll) = f.euler(EulerRot::ZYX);
    /// assert!((yaw - 0.3).abs() < 1e-5 && (pitch + 0.2).abs() < 1e-5 && (roll - 0.1).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn euler(&self, order: EulerRot) -> (f32, f32, f32) {
        self.attitude().to_euler(order)
    }
}

#[cfg(test)]
mod tests {
    use super::super::FilterParams;
    use super::*;
    use crate::quat::Quat;

    /// At many attitudes, a still reading has no linear acceleration, and
    /// a push of known earth direction is found in both frames.
    #[test]
    fn gravity_and_linear_acceleration_split_the_reading() {
        let g = FilterParams::DEFAULT.gravity;
        for k in 0..24 {
            // Unit quaternions without the trigonometric kernels.
            let q = Quat::from_wxyz(3.0 - 0.25 * k as f32, 1.0, -2.0, k as f32 - 12.0).normalize();
            let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, q);
            let still = q.inv() * Cvec3::new(0.0, 0.0, g);
            assert!(f.linear_acceleration(still).norm() < 1e-5, "{k}");
            let push = Cvec3::new(1.5, -0.5, 3.0); // earth frame, m/s²
            let read = q.inv() * (Cvec3::new(0.0, 0.0, g) + push);
            assert!((f.earth_acceleration(read) - push).norm() < 1e-4, "{k}");
            assert!(
                (f.linear_acceleration(read) - q.inv() * push).norm() < 1e-4,
                "{k}"
            );
            assert!((f.gravity().norm() - g).abs() < 1e-4, "{k}");
        }
    }

    /// The heading follows a turn about up whatever the tilt, and agrees
    /// with the ZYX yaw up to its sign, within the kernels' errors (the
    /// rotations are built with sin_cos, the heading read with atan2).
    #[test]
    fn heading_is_the_turn_about_up() {
        use crate::accuracy::{ATAN2_MAX_ABS_ERROR, EULER_MAX_ANGLE_ERROR, SIN_COS_MAX_ABS_ERROR};
        let built = 8.0 * SIN_COS_MAX_ABS_ERROR + 1e-6;
        for k in -7..=7 {
            let yaw = 0.4 * k as f32;
            for tilt in [0.0f32, 0.3, -1.0] {
                let q = Quat::from_rotation_z(yaw) * Quat::from_rotation_x(tilt);
                let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, q);
                let heading = f.heading();
                assert!(
                    (heading + yaw).abs() <= built + ATAN2_MAX_ABS_ERROR,
                    "{yaw} {tilt}: {heading}"
                );
                let (z, _, _) = f.euler(EulerRot::ZYX);
                assert!(
                    (z - yaw).abs() <= built + EULER_MAX_ANGLE_ERROR,
                    "{yaw} {tilt}: {z}"
                );
            }
        }
    }
}
