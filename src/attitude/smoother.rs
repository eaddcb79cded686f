//! [`Smoother`]: a frame-rate independent slerp low-pass of an attitude.

use super::low_pass::smoothing_factor;
use crate::quat::Quat;

/// An attitude low-pass: each update slerps the state towards the
/// measurement by `alpha = 1 - exp(-dt / tau)`.
///
/// Slerp moves about one fixed axis at constant angular velocity, so for a
/// measurement held constant the angle between state and measurement
/// shrinks by the factor `1 - alpha = exp(-dt / tau)` at each update: it
/// decays as `exp(-t / tau)` whatever the update rate, and the same `tau`
/// gives the same response at 100 Hz and at 1 kHz, or with jittering `dt`.
/// It takes the short way (`q` and `-q` are one measurement).
///
/// Use it to take the jitter out of a displayed or logged attitude. It lags
/// a moving measurement by about `tau` seconds; it knows nothing of gyros
/// (for sensor fusion, see [`OrientationFilter`](super::OrientationFilter)).
///
/// State: one [`Quat`] and the time constant, 20 bytes.
///
/// # Examples
///
/// ```
/// use rigtform::{attitude::Smoother, Quat};
/// let mut s = Smoother::new(Quat::IDENTITY, 0.5); // tau = 0.5 s
/// let target = Quat::from_rotation_z(1.0);
/// for _ in 0..50 {
///     s.update(target, 0.01); // 100 Hz for 0.5 s
/// }
/// // One time constant later, exp(-1) of the angle is left:
/// assert!((s.attitude.angle_to(target) - (-1.0f32).exp()).abs() < 1e-4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct Smoother {
    /// The smoothed attitude, a unit quaternion.
    pub attitude: Quat,
    /// The time constant in seconds: after `tau` seconds of a constant
    /// measurement, `exp(-1)` (37 %) of the initial angle to it is left. Zero
    /// or negative: no smoothing (the state jumps to each measurement).
    /// `f32::INFINITY`: frozen.
    pub tau: f32,
}

impl Smoother {
    /// A smoother that starts at `attitude` (a unit quaternion) with time
    /// constant `tau` seconds.
    ///
    /// ```
    /// use rigtform::{attitude::Smoother, Quat};
    /// let s = Smoother::new(Quat::IDENTITY, 0.2);
    /// assert_eq!((s.attitude, s.tau), (Quat::IDENTITY, 0.2));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(attitude: Quat, tau: f32) -> Self {
        Self { attitude, tau }
    }

    /// Moves the state towards `measurement` (a unit quaternion) by
    /// `alpha = 1 - exp(-dt / tau)` along the slerp, and returns the new
    /// state: `attitude.slerp(measurement, alpha)`.
    ///
    /// # Preconditions
    ///
    /// `dt` is the time in seconds since the previous update. Documented
    /// results for the edges:
    ///
    /// - `dt <= 0`: nothing moves (no time passed; no extrapolation).
    /// - `tau <= 0`: the state becomes `measurement`'s rotation (no
    ///   smoothing); `tau = f32::INFINITY`: the state stays.
    /// - A NaN, infinite or zero `measurement`, or NaN `dt` or `tau`,
    ///   returns [`Quat::NAN`] and leaves the state unchanged, so one bad
    ///   sample does not poison the smoother. An infinite `dt` counts as a
    ///   very long time: the state becomes `measurement`.
    /// - A finite `measurement` that is not unit is normalized first (also
    ///   one whose squared norm overflows, such as `3e38` in every
    ///   component), so the state stays a unit quaternion.
    /// - A state that is no rotation (NaN, infinite or zero, written into
    ///   the public field) is replaced by the measurement at the next
    ///   update that has one; a finite non-unit state is normalized.
    ///
    /// # Accuracy
    ///
    /// Each update is a [`Quat::slerp`] (its error bound is
    /// [`accuracy::SLERP_MAX_ANGLE_ERROR`](crate::accuracy::SLERP_MAX_ANGLE_ERROR)
    /// per radian turned). The angle left to a constant measurement after
    /// `t` seconds is `theta_0 exp(-t / tau)` within
    /// [`accuracy::SMOOTHER_DECAY_MAX_ERROR`](crate::accuracy::SMOOTHER_DECAY_MAX_ERROR)
    /// radians over thousands of updates, at 100 Hz and at 1 kHz
    /// (`step_response_has_the_time_constant_at_100_hz_and_1_khz`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{attitude::Smoother, Quat};
    /// let mut s = Smoother::new(Quat::IDENTITY, 1.0);
    /// let m = Quat::from_rotation_x(0.5);
    /// assert_eq!(s.update(m, 0.0), Quat::IDENTITY); // no time, no change
    /// assert!(!s.update(Quat::NAN, 0.01).is_finite()); // reported ...
    /// assert_eq!(s.attitude, Quat::IDENTITY); // ... and ignored
    /// s.tau = 0.0;
    /// assert!(s.update(m, 0.01).angle_to(m) < 1e-6); // no smoothing
    /// s.attitude = Quat::NAN; // a corrupted state ...
    /// s.tau = 1.0;
    /// assert!(s.update(m, 0.01).angle_to(m) < 1e-6); // ... is replaced
    /// ```
    pub fn update(&mut self, measurement: Quat, dt: f32) -> Quat {
        let alpha = smoothing_factor(dt, self.tau);
        let Some(measurement) = measurement.try_normalize() else {
            return Quat::NAN;
        };
        if alpha.is_nan() {
            return Quat::NAN;
        }
        let state = self.attitude;
        // A unit state (to rounding) is kept bit for bit; another is
        // normalized, or replaced if it has no direction.
        let state = if (state.norm_squared() - 1.0).abs() <= 4.0 * f32::EPSILON {
            state
        } else {
            match state.try_normalize() {
                Some(unit) => unit,
                None => measurement,
            }
        };
        self.attitude = if alpha != 0.0 {
            state.slerp(measurement, alpha)
        } else {
            state
        };
        self.attitude
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::SMOOTHER_DECAY_MAX_ERROR;
    use crate::vec::Cvec3;

    /// The angle left after each of `checks` (in seconds), smoothing towards
    /// a constant measurement at `rate` Hz.
    fn decay(rate: f32, tau: f32, start: Quat, target: Quat, checks: &[f32]) -> [f32; 4] {
        let mut s = Smoother::new(start, tau);
        let dt = 1.0 / rate;
        let mut left = [0.0; 4];
        let mut step = 0u32;
        for (slot, &t) in left.iter_mut().zip(checks) {
            while (step as f32) < t * rate - 0.5 {
                s.update(target, dt);
                step += 1;
            }
            *slot = s.attitude.angle_to(target);
        }
        left
    }

    #[test]
    fn step_response_has_the_time_constant_at_100_hz_and_1_khz() {
        let tau = 0.5;
        let axis = Cvec3::new(1.0, -2.0, 0.5);
        let start = Quat::from_axis_angle(axis, 0.3);
        let target = Quat::from_axis_angle(Cvec3::new(0.0, 1.0, 1.0), -2.0);
        let theta0 = start.angle_to(target);
        let checks = [0.25, 0.5, 1.0, 2.0];
        let at_100 = decay(100.0, tau, start, target, &checks);
        let at_1000 = decay(1000.0, tau, start, target, &checks);
        let mut worst: f32 = 0.0;
        for ((t, a), b) in checks.iter().zip(at_100).zip(at_1000) {
            let want = theta0 * (-t / tau).exp();
            worst = worst.max((a - want).abs()).max((b - want).abs());
        }
        std::println!("smoother decay: max error {worst:.3e} rad");
        assert!(
            worst <= SMOOTHER_DECAY_MAX_ERROR,
            "{worst}: {at_100:?} {at_1000:?}"
        );
    }

    #[test]
    fn state_is_20_bytes_as_documented() {
        assert_eq!(core::mem::size_of::<Smoother>(), 20);
    }

    #[test]
    fn jittering_steps_give_the_same_response() {
        let target = Quat::from_rotation_y(1.5);
        let mut even = Smoother::new(Quat::IDENTITY, 0.3);
        let mut jitter = even;
        for i in 0..300 {
            even.update(target, 0.002);
            jitter.update(target, if i % 2 == 0 { 0.001 } else { 0.003 });
        }
        let (a, b) = (
            even.attitude.angle_to(target),
            jitter.attitude.angle_to(target),
        );
        assert!(
            (a - 1.5 * (-2.0f32).exp()).abs() < SMOOTHER_DECAY_MAX_ERROR,
            "{a}"
        );
        assert!((a - b).abs() < SMOOTHER_DECAY_MAX_ERROR, "{a} {b}");
    }

    #[test]
    fn bad_input_is_reported_and_ignored() {
        let q = Quat::from_rotation_z(0.2);
        let mut s = Smoother::new(q, 1.0);
        let m = Quat::from_rotation_z(1.0);
        for (measurement, dt) in [(Quat::NAN, 0.01), (m, f32::NAN)] {
            assert!(!s.update(measurement, dt).is_finite());
            assert_eq!(s.attitude, q);
        }
        assert_eq!(s.update(m, -0.5), q);
        s.tau = f32::NAN;
        assert!(!s.update(m, 0.01).is_finite());
        assert_eq!(s.attitude, q);
        s.tau = f32::INFINITY;
        assert_eq!(s.update(m, 0.01), q);
        s.tau = -1.0;
        // One slerp of at most pi radians: its documented error.
        let tol = crate::accuracy::SLERP_MAX_ANGLE_ERROR * core::f32::consts::PI;
        assert!(s.update(-m, 0.01).angle_to(m) <= tol);
        s.tau = 1.0;
        s.attitude = q;
        assert!(s.update(m, f32::INFINITY).angle_to(m) <= tol);
    }

    /// A finite measurement whose squared norm overflows, a zero one, and
    /// a state that is no rotation: the state stays a unit quaternion.
    #[test]
    fn huge_zero_and_corrupted_values_keep_the_state_unit() {
        let unit = |q: Quat| q.is_finite() && (q.norm() - 1.0).abs() < 1e-6;
        let mut s = Smoother::new(Quat::IDENTITY, 0.5);
        let huge = Quat {
            w: 3e38,
            x: 3e38,
            y: 0.0,
            z: 0.0,
        };
        let want = Quat::from_rotation_x(core::f32::consts::FRAC_PI_2);
        for _ in 0..2000 {
            assert!(unit(s.update(huge, 0.01)), "{:?}", s.attitude);
        }
        assert!(s.attitude.angle_to(want) < 1e-5, "{:?}", s.attitude);
        let zero = Quat {
            w: 0.0,
            x: 0.0,
            y: 0.0,
            z: 0.0,
        };
        let infinite = Quat {
            w: f32::INFINITY,
            ..zero
        };
        let before = s.attitude;
        assert!(!s.update(zero, 0.01).is_finite());
        assert_eq!(s.attitude, before);
        for bad in [Quat::NAN, zero, infinite] {
            s.attitude = bad;
            assert!(unit(s.update(want, 0.01)), "{bad:?}");
            assert!(s.attitude.angle_to(want) < 1e-6, "{bad:?}");
        }
        // A state off the unit sphere but with a direction is normalized.
        let turn = Quat::from_rotation_z(0.5);
        s.attitude = Quat {
            w: 4.0 * turn.w,
            z: 4.0 * turn.z,
            ..turn
        };
        assert!(unit(s.update(turn, 0.0)));
    }

    #[test]
    fn the_short_way_whatever_the_measurements_sign() {
        let mut a = Smoother::new(Quat::IDENTITY, 0.1);
        let mut b = a;
        let m = Quat::from_rotation_x(2.5);
        a.update(m, 0.01);
        b.update(-m, 0.01);
        let tol = crate::accuracy::SLERP_MAX_ANGLE_ERROR * core::f32::consts::PI;
        assert!(a.attitude.angle_to(b.attitude) <= 2.0 * tol);
        assert!(a.attitude.angle_to(Quat::IDENTITY) < 2.5 * 0.1);
    }
}
