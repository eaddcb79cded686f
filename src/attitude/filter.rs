//! [`OrientationFilter`]: gyroscope + accelerometer (6D) and + magnetometer
//! (9D) attitude estimation, with gyro-bias estimation.

use super::low_pass::{low_pass, smoothing_factor};
use super::rest::RestDetector;
use super::FilterParams;
use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// Time constant with which the magnetic reference follows the field.
const MAG_REFERENCE_TAU: f32 = 60.0;

/// An orientation filter for gyroscope + accelerometer (6D, [`update`](Self::update))
/// and gyroscope + accelerometer + magnetometer (9D,
/// [`update_with_mag`](Self::update_with_mag)): a complementary filter with
/// gyro-bias estimation, in the attitude conventions of the
/// [module](super) (sensor to ENU earth frame).
///
/// # How it works
///
/// The attitude is the product `correction * strapdown`:
///
/// 1. `strapdown` integrates the bias-corrected gyro exactly
///    ([`Quat::integrate`]). It maps the sensor frame into an almost
///    inertial frame, which drifts only as slowly as the gyro errors.
/// 2. The accelerometer, rotated into that frame, goes through a
///    critically damped second-order low-pass (two first-order stages of
///    `tau_acc / 2`). In an inertial frame, linear acceleration is the
///    derivative of velocity, which stays bounded, so the average tends to
///    gravity: shaking, running and vibration average out, rather than
///    tilting the estimate as in a filter that trusts each sample's
///    direction. This is the central idea of VQF (Laidig and Seel,
///    *VQF: Highly Accurate IMU Orientation Estimation with Bias Estimation
///    and Magnetic Disturbance Rejection*, Information Fusion 91, 2023),
///    here in a simpler filter.
/// 3. `correction` is then turned, about a horizontal axis, by the
///    smallest rotation that makes the averaged vector point up: the
///    inclination correction. It is skipped while the averaged magnitude is
///    more than `acc_gate` away from gravity.
/// 4. With a magnetometer, `correction` also turns about the vertical
///    (only: a disturbed field can never tilt the estimate) towards
///    magnetic north (the horizontal part of the field along +y), by the
///    fraction `1 - exp(-dt / tau_mag)` of the heading error, while the
///    field passes the disturbance gate.
/// 5. Gyro bias: while at rest (rest detection on gyro and accelerometer),
///    the bias low-passes the raw gyro. During motion, each inclination
///    correction, expressed in the sensor frame, is the drift a bias error
///    caused; the bias follows it with time constant `tau_bias` (Mahony's
///    integral term, in time-constant form), when the sample passes the
///    acceleration gate. As the sensor turns, every sensor axis spends
///    time horizontal, where the inclination shows its bias. The heading
///    correction never feeds the bias, so that a magnetic disturbance
///    cannot corrupt it (nor, through it, the inclination).
///
/// The first sample with a usable accelerometer vector sets the
/// inclination (the low-pass starts there, as if at rest); with a
/// magnetometer, the first usable field sets the heading.
///
/// Every time constant works through `1 - exp(-dt / tau)`, so that the
/// time constants in seconds hold at any sample rate and with jittering
/// `dt` (tested for the [`Smoother`](super::Smoother) at 100 Hz, 1 kHz and
/// with jittering steps; not tested for the filter as a whole).
///
/// # State and cost
///
/// 156 bytes including the 44 of the parameters (`size_of`, checked by a
/// test), no allocation. A 6D update costs three quaternion products,
/// three vector rotations, four normalizations, an atan2, three `exp_m1`
/// for the smoothing factors (four at rest) and a handful of vector
/// operations; the magnetometer adds two products, a rotation, an atan2, a
/// sine-cosine and two `exp_m1`. Executed instructions per update
/// on the emulated Cortex-M4F (QEMU mps2-an386, opt-level "s", LTO, counted
/// by `cargo xtask filter-cost`, by hand: CI does not check them): 1,351 (6D)
/// and 1,891 (9D) with the default kernels, 1,353 and 1,856 with `fast-math`.
///
/// # Bad input
///
/// - NaN or infinite gyro or `dt`: the update returns [`Quat::NAN`] and
///   leaves the state unchanged (one bad sample does not poison the
///   filter). `dt <= 0`: nothing happens (no time passed); the current
///   attitude is returned.
/// - NaN, infinite or zero accelerometer vector: the sample only
///   propagates the gyro (no correction, no rest detection). A zero vector
///   (free fall) is a valid specific force, but carries no direction.
/// - NaN, infinite or zero magnetometer vector, or a field without
///   horizontal part: no heading correction for that sample.
/// - Parameters: zero or negative time constants mean "immediate" (no
///   smoothing), infinite ones "never". While any parameter is NaN, every
///   update returns [`Quat::NAN`] and leaves the state unchanged.
///
/// # Accuracy
///
/// Measured on real recordings with optical ground truth (BROAD trials 02,
/// 07 and 16): see the README's IMU section and the `broad` binary of `compare/`. On
/// trial 16 (shipped in `testkit/data/`), 6D inclination RMSE below
/// [`accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG`](crate::accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG)
/// degrees (`tests/broad.rs`).
///
/// # Examples
///
/// ```
/// use rigtform::attitude::{FilterParams, OrientationFilter};
/// use rigtform::{Cvec3, Quat};
///
/// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
/// // Lying still, tilted 0.3 rad about x: gravity's reaction seen in the sensor frame.
/// let tilt = Quat::from_rotation_x(0.3);
/// let acc = tilt.inv() * Cvec3::new(0.0, 0.0, 9.81);
/// let gyr = Cvec3::new(0.01, -0.02, 0.005); // a biased gyro, at rest
/// for _ in 0..2000 {
///     f.update(gyr, acc, 0.01); // 100 Hz, 20 s
/// }
/// // Inclination found, bias learned at rest:
/// let up = f.attitude() * (acc * (1.0 / 9.81));
/// assert!((up - Cvec3::Z).norm() < 1e-3);
/// assert!((f.bias() - gyr).norm() < 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrientationFilter {
    /// The parameters; they may be changed between updates.
    pub params: FilterParams,
    /// Sensor to the almost inertial frame: the integrated gyro.
    strapdown: Quat,
    /// The almost inertial frame to earth: all corrections.
    correction: Quat,
    /// The two stages of the accelerometer low-pass, in the inertial frame.
    acc_stage1: Cvec3,
    acc_stage2: Cvec3,
    /// The gyro bias estimate, rad/s, sensor frame.
    bias: Cvec3,
    rest: RestDetector,
    /// Reference field in the earth frame as (horizontal, vertical, 0);
    /// NaN until the first usable magnetometer sample.
    mag_reference: Cvec3,
    /// Whether the inclination has been set from an accelerometer sample.
    initialized: bool,
}

impl OrientationFilter {
    /// A filter that sets its inclination from the first usable
    /// accelerometer sample, and its heading from the first usable
    /// magnetometer sample (until then it reports a heading of its own
    /// choosing). Bias estimate zero.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// let q = f.update(Cvec3::ZERO, Cvec3::new(0.0, 9.81, 0.0), 0.01);
    /// // Sensor y axis up: a quarter turn about x (sensor to earth).
    /// assert!((q * Cvec3::Y - Cvec3::Z).norm() < 1e-6);
    /// ```
    #[must_use]
    pub const fn new(params: FilterParams) -> Self {
        Self {
            params,
            strapdown: Quat::IDENTITY,
            correction: Quat::IDENTITY,
            acc_stage1: Cvec3::ZERO,
            acc_stage2: Cvec3::ZERO,
            bias: Cvec3::ZERO,
            rest: RestDetector::new(),
            mag_reference: Cvec3::NAN,
            initialized: false,
        }
    }

    /// A filter that starts from a known `attitude` (a unit quaternion),
    /// as if it had been at rest there: the accelerometer average starts at
    /// gravity as that attitude predicts it, so a wrong starting
    /// inclination is corrected over about `tau_acc` seconds, not at once.
    /// The heading is still set by the first usable magnetometer sample in
    /// 9D.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// let start = Quat::from_rotation_y(0.2);
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, start);
    /// assert!(f.attitude().angle_to(start) < 1e-6);
    /// ```
    #[must_use]
    pub fn with_attitude(params: FilterParams, attitude: Quat) -> Self {
        let mut f = Self::new(params);
        f.correction = attitude;
        let gravity = Cvec3::new(0.0, 0.0, params.gravity);
        f.acc_stage1 = gravity;
        f.acc_stage2 = gravity;
        f.initialized = true;
        f
    }

    /// The attitude estimate: sensor to earth (ENU), a unit quaternion.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Quat;
    /// let f = OrientationFilter::new(FilterParams::DEFAULT);
    /// assert_eq!(f.attitude(), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub fn attitude(&self) -> Quat {
        self.correction * self.strapdown
    }

    /// The gyro bias estimate in rad/s, in the sensor frame: subtracted
    /// from every gyro sample.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// assert_eq!(OrientationFilter::new(FilterParams::DEFAULT).bias(), Cvec3::ZERO);
    /// ```
    #[inline]
    #[must_use]
    pub fn bias(&self) -> Cvec3 {
        self.bias
    }

    /// Sets the gyro bias estimate (rad/s, sensor frame), for instance from
    /// a calibration stored at the previous shutdown. Like the estimate, it
    /// is clipped to at most `params.max_bias` long.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// f.set_bias(Cvec3::new(0.01, 0.0, 0.0));
    /// assert_eq!(f.bias().x, 0.01);
    /// f.set_bias(Cvec3::new(0.0, 1.0, 0.0)); // beyond max_bias
    /// assert_eq!(f.bias().y, FilterParams::DEFAULT.max_bias);
    /// ```
    pub fn set_bias(&mut self, bias: Cvec3) {
        let (length, max) = (bias.norm(), self.params.max_bias);
        self.bias = if length > max {
            bias * (max / length)
        } else {
            bias
        };
    }

    /// `true` while the rest detector sees the sensor at rest (and the
    /// bias is learned from the raw gyro).
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// let g = Cvec3::new(0.0, 0.0, 9.81);
    /// f.update(Cvec3::ZERO, g, 1.0);
    /// assert!(!f.is_resting());
    /// f.update(Cvec3::ZERO, g, 1.0);
    /// assert!(f.is_resting()); // 2 s still, more than rest_time
    /// ```
    #[inline]
    #[must_use]
    pub fn is_resting(&self) -> bool {
        self.rest.is_resting(&self.params)
    }

    /// One 6D update: gyro `gyr` (rad/s, sensor frame), accelerometer `acc`
    /// (specific force in the unit of `params.gravity`, sensor frame),
    /// `dt` seconds since the previous sample. Returns the new attitude.
    /// See the type's docs for the method and for bad input.
    ///
    /// In 6D the heading is the integrated gyro alone: it drifts with the
    /// part of the bias that points up, which the accelerometer cannot see.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// let g = Cvec3::new(0.0, 0.0, 9.81);
    /// f.update(Cvec3::ZERO, g, 0.01);
    /// // Turning about the vertical at 1 rad/s for a second:
    /// for _ in 0..100 {
    ///     f.update(Cvec3::new(0.0, 0.0, 1.0), g, 0.01);
    /// }
    /// assert!(f.attitude().angle_to(Quat::from_rotation_z(1.0)) < 1e-4);
    /// assert!(!f.update(Cvec3::NAN, g, 0.01).is_finite()); // reported,
    /// assert!(f.attitude().is_finite()); // and ignored
    /// ```
    pub fn update(&mut self, gyr: Cvec3, acc: Cvec3, dt: f32) -> Quat {
        self.update_with_optional_mag(gyr, acc, None, dt)
    }

    /// One 9D update: as [`update`](Self::update), plus the magnetometer
    /// `mag` (any unit, sensor frame), used for the heading only.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// // Level, facing 0.5 rad west of magnetic north: the field is seen
    /// // turned the other way in the sensor frame.
    /// let truth = Quat::from_rotation_z(0.5);
    /// let field = Cvec3::new(0.0, 16.0, -41.0); // µT in ENU, Berlin
    /// let (acc, mag) = (Cvec3::new(0.0, 0.0, 9.81), truth.inv() * field);
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// let q = f.update_with_mag(Cvec3::ZERO, acc, mag, 0.01);
    /// assert!(q.angle_to(truth) < 1e-5);
    /// ```
    pub fn update_with_mag(&mut self, gyr: Cvec3, acc: Cvec3, mag: Cvec3, dt: f32) -> Quat {
        self.update_with_optional_mag(gyr, acc, Some(mag), dt)
    }

    fn update_with_optional_mag(
        &mut self,
        gyr: Cvec3,
        acc: Cvec3,
        mag: Option<Cvec3>,
        dt: f32,
    ) -> Quat {
        if !(gyr.is_finite() && dt.is_finite()) || self.params.has_nan() {
            return Quat::NAN;
        }
        if dt <= 0.0 {
            return self.attitude();
        }
        let p = self.params;
        let acc = acc.is_finite().then_some(acc).filter(|a| *a != Cvec3::ZERO);
        if let Some(acc) = acc {
            self.rest.update(gyr, acc, dt, &p);
        } else {
            self.rest.interrupt();
        }
        let resting = self.is_resting();
        if resting {
            self.set_bias(low_pass(
                self.bias,
                gyr,
                smoothing_factor(dt, p.tau_bias_rest),
            ));
        }

        self.strapdown = self.strapdown.integrate(gyr - self.bias, dt);

        // The inclination correction in the earth frame, as a rotation
        // vector, for the bias. The heading correction is left out: a
        // magnetic disturbance must not reach the bias either.
        let drift = match acc {
            Some(acc) => self.correct_inclination(acc, dt),
            None => Cvec3::ZERO,
        };
        if let Some(mag) = mag {
            self.correct_heading(mag, dt);
        }

        let attitude = self.attitude();
        let gated = acc.is_some_and(|a| (a.norm() - p.gravity).abs() <= p.acc_gate * p.gravity);
        // The corrections undid a drift of -drift in dt: in the sensor
        // frame, the bias error that would cause it. Faster corrections are
        // no bias (see max_bias).
        let error = attitude.inv() * drift * (1.0 / dt);
        if !resting && gated && error.norm() <= p.max_bias {
            self.set_bias(self.bias - error * smoothing_factor(dt, p.tau_bias));
        }
        attitude
    }

    /// Averages the accelerometer in the inertial frame and turns the
    /// correction so that the average points up. Returns the correction's
    /// rotation vector (earth frame).
    fn correct_inclination(&mut self, acc: Cvec3, dt: f32) -> Cvec3 {
        let p = self.params;
        let inertial = self.strapdown * acc;
        let first = !self.initialized;
        if first {
            self.acc_stage1 = inertial;
            self.acc_stage2 = inertial;
            self.initialized = true;
        }
        let alpha = smoothing_factor(dt, 0.5 * p.tau_acc);
        let stage1 = low_pass(self.acc_stage1, inertial, alpha);
        let stage2 = low_pass(self.acc_stage2, stage1, alpha);
        self.acc_stage1 = stage1;
        self.acc_stage2 = stage2;
        if (stage2.norm() - p.gravity).abs() > p.acc_gate * p.gravity {
            return Cvec3::ZERO;
        }
        let Some(up) = (self.correction * stage2).try_normalize() else {
            return Cvec3::ZERO;
        };
        let turn = rotation_to_up(up);
        self.correction = (turn * self.correction).normalize();
        // Setting the inclination from the first sample is no drift.
        if first {
            Cvec3::ZERO
        } else {
            turn.to_scaled_axis()
        }
    }

    /// Turns the correction about the vertical towards magnetic north, if
    /// the field passes the disturbance gate.
    fn correct_heading(&mut self, mag: Cvec3, dt: f32) {
        let p = self.params;
        let field = self.attitude() * mag;
        let horizontal = Cvec3::new(field.x, field.y, 0.0).norm();
        // NaN, infinite or zero field, or one without a horizontal part.
        if !horizontal.is_finite() || horizontal <= 0.0 {
            return;
        }
        let seen = Cvec3::new(horizontal, field.z, 0.0);
        let first = !self.mag_reference.is_finite();
        if first {
            self.mag_reference = seen;
        }
        let reference = self.mag_reference;
        self.mag_reference = low_pass(reference, seen, smoothing_factor(dt, MAG_REFERENCE_TAU));
        if !first && (seen - reference).norm() > p.mag_gate * reference.norm() {
            return;
        }
        // The field's angle east of north; turning by it about +z brings
        // it to north.
        let error = float::atan2(field.x, field.y);
        let fraction = if first {
            1.0
        } else {
            smoothing_factor(dt, p.tau_mag)
        };
        let turn = Quat::from_rotation_z(error * fraction);
        self.correction = (turn * self.correction).normalize();
    }
}

/// The smallest rotation that takes the unit vector `u` to +z: about the
/// axis `u x z`, by the angle between them; `[1 + u.z, u x z]` normalized
/// (the half-way vector construction). For `u = -z` exactly, a half turn
/// about x.
fn rotation_to_up(u: Cvec3) -> Quat {
    Quat::new(1.0 + u.z, u.y, -u.x, 0.0)
        .try_normalize()
        .unwrap_or(Quat::new(0.0, 1.0, 0.0, 0.0))
}

#[cfg(test)]
mod tests;
