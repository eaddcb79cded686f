//! [`OrientationFilter`]: gyroscope + accelerometer (6D) and + magnetometer
//! (9D) attitude estimation, with gyro-bias estimation.

use super::low_pass::{low_pass, smoothing_factor};
use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// The parameters of an [`OrientationFilter`], with their units. One set,
/// [`FilterParams::DEFAULT`], chosen from sensor and motion physics (see the
/// field docs and the README's IMU section), not fitted to any recording.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[repr(C)]
pub struct FilterParams {
    /// Magnitude of gravity in the accelerometer's unit: 9.81 for m/s²,
    /// 1.0 for g. Only the gates below use it (relative to it).
    pub gravity: f32,
    /// Time constant of the inclination correction, in seconds (default
    /// 3 s): the delay of the low-pass that averages the accelerometer in
    /// an almost inertial frame. Longer rejects linear accelerations better
    /// (a velocity change `dv` leaks in as at most about
    /// `2 dv / (e g tau_acc)` radians of tilt) but lets gyro errors drift
    /// longer (about `residual bias * tau_acc`). With `dv` about 0.5 m/s
    /// for hand-held motion and a residual bias of about 0.1 °/s, the sum
    /// is smallest between 3 and 5 s; 3 s is the low end, because gyro
    /// scale errors during fast rotation also drift. Zero or negative: the
    /// inclination follows each accelerometer sample (no averaging).
    pub tau_acc: f32,
    /// Time constant of the heading correction by the magnetometer, in
    /// seconds (default 10 s). Indoor magnetic disturbances pass in seconds
    /// as the sensor moves, while a residual gyro bias of 0.1 °/s about the
    /// vertical drifts only 1° in 10 s.
    pub tau_mag: f32,
    /// Time constant, in seconds, with which the gyro bias follows the
    /// corrections during motion (default 20 s): it has to be several times
    /// `tau_acc` for the bias loop to stay well damped, and long enough to
    /// average out the corrections that linear accelerations cause. The
    /// bias changes with temperature over minutes. Infinite: no bias
    /// estimation during motion.
    pub tau_bias: f32,
    /// Time constant, in seconds, of the bias estimate while at rest, where
    /// the gyro reads its bias plus noise (default 3 s).
    pub tau_bias_rest: f32,
    /// Rest detection, gyro: the rate (rad/s) must stay within this of its
    /// 0.5 s low-pass (default 2 °/s, 0.035 rad/s: above the noise of MEMS
    /// gyros, below deliberate motion).
    pub rest_gyro: f32,
    /// The largest gyro bias the filter learns, in rad/s (default 2 °/s,
    /// 0.035 rad/s, the zero-rate offset of a MEMS gyro after factory
    /// calibration). The estimate is clipped to it; rest is only detected
    /// while the low-passed gyro is below it, so that a slow steady turn is
    /// not taken for a bias; and during motion, corrections faster than it
    /// (convergence from a wrong start) are not taken for a bias either.
    pub max_bias: f32,
    /// Rest detection, accelerometer: the specific force must stay within
    /// this fraction of `gravity` of its 0.5 s low-pass (default 0.05).
    pub rest_acc: f32,
    /// Rest detection: how long both conditions must hold, in seconds
    /// (default 1.5 s).
    pub rest_time: f32,
    /// Acceleration-magnitude gate, a fraction of `gravity` (default 0.1):
    /// the inclination is corrected only while the averaged specific force
    /// is within it of `gravity`, and the bias learns from a correction only
    /// while the current sample is within it too (a correction made during
    /// strong linear acceleration says little about the gyro). The first
    /// gate catches a sustained acceleration with a vertical part (a lift,
    /// a climb); a sustained horizontal one (a car speeding up) changes the
    /// magnitude only to second order: at 0.46 g sideways the averaged
    /// vector is tilted 25° before it is 10 % longer than gravity. No
    /// accelerometer-only filter can tell that from a tilt.
    pub acc_gate: f32,
    /// Magnetic disturbance gate, a fraction of the reference field
    /// (default 0.1): the heading is corrected only while the measured
    /// field, in the earth frame, is within this distance of the reference
    /// field (its horizontal and vertical parts, so a change of the dip
    /// counts as much as a change of strength). The reference is the first
    /// field measured, and then follows the measurements with a 60 s time
    /// constant, so that a new environment is accepted in the end (after
    /// about a minute for a field 30 % off; longer the further off it is).
    pub mag_gate: f32,
}

impl FilterParams {
    /// The one parameter set used for every recording, chosen from physics
    /// (each field's docs give the argument).
    ///
    /// ```
    /// use rigtform::attitude::FilterParams;
    /// assert_eq!(FilterParams::default(), FilterParams::DEFAULT);
    /// assert_eq!(FilterParams::DEFAULT.tau_acc, 3.0);
    /// ```
    pub const DEFAULT: Self = Self {
        gravity: 9.81,
        tau_acc: 3.0,
        tau_mag: 10.0,
        tau_bias: 20.0,
        tau_bias_rest: 3.0,
        rest_gyro: 0.035,
        max_bias: 0.035,
        rest_acc: 0.05,
        rest_time: 1.5,
        acc_gate: 0.1,
        mag_gate: 0.1,
    };
}

impl FilterParams {
    /// `true` if any parameter is NaN.
    fn has_nan(&self) -> bool {
        [
            self.gravity,
            self.tau_acc,
            self.tau_mag,
            self.tau_bias,
            self.tau_bias_rest,
            self.rest_gyro,
            self.max_bias,
            self.rest_acc,
            self.rest_time,
            self.acc_gate,
            self.mag_gate,
        ]
        .iter()
        .any(|p| p.is_nan())
    }
}

impl Default for FilterParams {
    /// [`FilterParams::DEFAULT`].
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Time constant of the low-passes behind rest detection, in seconds.
const REST_LOW_PASS_TAU: f32 = 0.5;
/// Time constant with which the magnetic reference follows the field.
const MAG_REFERENCE_TAU: f32 = 60.0;

/// The rest detector: low-passes of the raw gyro and accelerometer in the
/// sensor frame, and how long both have stayed close to them.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
struct Rest {
    gyro: Cvec3,
    acc: Cvec3,
    /// Seconds that both conditions have held.
    time: f32,
}

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
    rest: Rest,
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
            // NaN: started by the first sample.
            rest: Rest {
                gyro: Cvec3::NAN,
                acc: Cvec3::NAN,
                time: 0.0,
            },
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
        self.rest.time >= self.params.rest_time
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
            self.detect_rest(gyr, acc, dt);
        } else {
            self.rest.time = 0.0;
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

    /// Updates the rest detector with one sample.
    fn detect_rest(&mut self, gyr: Cvec3, acc: Cvec3, dt: f32) {
        let p = self.params;
        if !self.rest.acc.is_finite() {
            self.rest.gyro = gyr;
            self.rest.acc = acc;
        }
        let alpha = smoothing_factor(dt, REST_LOW_PASS_TAU);
        let gyro = low_pass(self.rest.gyro, gyr, alpha);
        let acc_lp = low_pass(self.rest.acc, acc, alpha);
        let still = (gyr - gyro).norm() <= p.rest_gyro
            && gyro.norm() <= p.max_bias
            && (acc - acc_lp).norm() <= p.rest_acc * p.gravity;
        self.rest = Rest {
            gyro,
            acc: acc_lp,
            time: if still { self.rest.time + dt } else { 0.0 },
        };
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
mod tests {
    use super::*;
    use crate::accuracy;

    const G: f32 = 9.81;
    /// Berlin's field in ENU, µT.
    const FIELD: Cvec3 = Cvec3::new(0.0, 16.0, -41.0);

    /// The inclination error of `estimate` against `truth`, in radians:
    /// the angle between the up directions they predict.
    fn inclination_error(estimate: Quat, truth: Quat) -> f32 {
        let up = (estimate.inv() * Cvec3::Z).dot(truth.inv() * Cvec3::Z);
        float::atan2(
            (estimate.inv() * Cvec3::Z)
                .cross(truth.inv() * Cvec3::Z)
                .norm(),
            up,
        )
    }

    /// A synthetic recording: the true attitude turns with body rate
    /// `rate(t)` from `start`; the sensors see it exactly, plus `bias` on
    /// the gyro and `linear(t)` (earth frame) on the accelerometer. Calls
    /// `check(t, truth, estimate)` after each update.
    #[allow(clippy::too_many_arguments)]
    fn simulate(
        filter: &mut OrientationFilter,
        start: Quat,
        seconds: f32,
        hz: f32,
        bias: Cvec3,
        rate: impl Fn(f32) -> Cvec3,
        linear: impl Fn(f32) -> Cvec3,
        with_mag: bool,
        mut check: impl FnMut(f32, Quat, Quat),
    ) {
        let dt = 1.0 / hz;
        let mut truth = start;
        for i in 0..(seconds * hz) as u32 {
            let t = i as f32 * dt;
            let omega = rate(t);
            truth = truth.integrate(omega, dt);
            let acc = truth.inv() * (Cvec3::new(0.0, 0.0, G) + linear(t));
            let gyr = omega + bias;
            let q = if with_mag {
                filter.update_with_mag(gyr, acc, truth.inv() * FIELD, dt)
            } else {
                filter.update(gyr, acc, dt)
            };
            check(t + dt, truth, q);
        }
    }

    /// A slow tumbling motion about all three axes.
    fn tumble(t: f32) -> Cvec3 {
        Cvec3::new(
            0.6 * (0.7 * t).sin(),
            0.5 * (0.45 * t).cos(),
            0.4 * (0.3 * t + 1.0).sin(),
        )
    }

    #[test]
    fn state_size_is_as_documented() {
        assert_eq!(core::mem::size_of::<OrientationFilter>(), 156);
        assert_eq!(core::mem::size_of::<FilterParams>(), 44);
    }

    #[test]
    fn converges_from_a_wrong_initial_attitude() {
        let truth0 = Quat::from_rotation_z(0.4) * Quat::from_rotation_x(0.2);
        let wrong = Quat::from_axis_angle(Cvec3::new(1.0, 1.0, 0.3), 0.6) * truth0;
        for (hz, with_mag) in [(100.0, false), (1000.0, false), (100.0, true)] {
            let mut f = OrientationFilter::with_attitude(FilterParams::DEFAULT, wrong);
            let (mut at_5s, mut end_incl, mut end_total) = (0.0, 0.0, 0.0);
            // With the magnetometer, longer: the field's reference was taken
            // at the wrong inclination, and the disturbance gate stays shut
            // until the reference has followed the field (60 s).
            let seconds = if with_mag { 180.0 } else { 60.0 };
            simulate(
                &mut f,
                truth0,
                seconds,
                hz,
                Cvec3::ZERO,
                tumble,
                |_| Cvec3::ZERO,
                with_mag,
                |t, truth, q| {
                    if (t - 5.0).abs() < 0.5 / hz {
                        at_5s = inclination_error(q, truth);
                    }
                    end_incl = inclination_error(q, truth);
                    end_total = q.angle_to(truth);
                },
            );
            let start = inclination_error(wrong, truth0);
            std::println!("{hz} Hz, mag {with_mag}: inclination {start} -> {at_5s} (5 s) -> {end_incl} ({seconds} s), total {end_total}");
            assert!(
                at_5s < 0.5 * start && end_incl < 0.2f32.to_radians(),
                "{hz} {with_mag}"
            );
            if with_mag {
                assert!(end_total < 0.5f32.to_radians(), "{end_total}");
            }
        }
    }

    #[test]
    fn learns_a_constant_gyro_bias_in_motion() {
        // Never at rest: only the corrections can reveal the bias. The
        // accelerometer reads 3 % high, within the gates.
        let bias = Cvec3::new(0.012, -0.015, 0.009);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let mut worst_late: f32 = 0.0;
        simulate(
            &mut f,
            Quat::IDENTITY,
            300.0,
            100.0,
            bias,
            tumble,
            |_| Cvec3::new(0.0, 0.0, 0.03 * G),
            true,
            |t, truth, q| {
                if t > 200.0 {
                    worst_late = worst_late.max(q.angle_to(truth));
                }
            },
        );
        let error = (f.bias() - bias).norm();
        std::println!("bias error after 300 s: {error:.2e} rad/s of {:.2e}; late attitude error {worst_late:.2e}", bias.norm());
        assert!(error < 0.1 * bias.norm(), "{:?}", f.bias());
        assert!(!f.is_resting());
        assert!(worst_late < 0.5f32.to_radians(), "{worst_late}");
    }

    #[test]
    fn learns_the_bias_at_rest() {
        let bias = Cvec3::new(-0.02, 0.01, 0.025);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let start = Quat::from_rotation_y(0.5);
        simulate(
            &mut f,
            start,
            20.0,
            200.0,
            bias,
            |_| Cvec3::ZERO,
            |_| Cvec3::ZERO,
            false,
            |_, _, _| {},
        );
        assert!(f.is_resting());
        assert!((f.bias() - bias).norm() < 1e-4, "{:?}", f.bias());
        // Above max_bias: clipped, and a steady turn that fast is no rest.
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let fast = Cvec3::new(0.0, 0.0, 0.1);
        simulate(
            &mut f,
            start,
            20.0,
            200.0,
            fast,
            |_| Cvec3::ZERO,
            |_| Cvec3::ZERO,
            false,
            |_, _, _| {},
        );
        assert!(!f.is_resting());
        assert!(f.bias().norm() <= FilterParams::DEFAULT.max_bias * 1.000_001);
    }

    #[test]
    fn a_stored_bias_is_subtracted_from_the_first_sample() {
        let bias = Cvec3::new(0.02, -0.01, 0.02);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        f.set_bias(bias);
        assert_eq!(f.bias(), bias);
        let acc = Cvec3::new(0.0, 0.0, G);
        // A second at 100 Hz, too short for rest detection: only the stored
        // bias keeps the attitude from drifting by 0.03 rad.
        for _ in 0..100 {
            f.update(bias, acc, 0.01);
        }
        assert!(
            f.attitude().angle_to(Quat::IDENTITY) < 1e-5,
            "{:?}",
            f.attitude()
        );
    }

    #[test]
    fn the_first_field_sets_the_heading_at_once() {
        let truth = Quat::from_rotation_z(-2.0) * Quat::from_rotation_y(0.3);
        let acc = truth.inv() * Cvec3::new(0.0, 0.0, G);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let q = f.update_with_mag(Cvec3::ZERO, acc, truth.inv() * FIELD, 0.01);
        // One atan2 and one sine-cosine: 1e-5 with libm, their errors with fast-math.
        let tol = (accuracy::ATAN2_MAX_ABS_ERROR + 2.0 * accuracy::SIN_COS_MAX_ABS_ERROR).max(1e-5);
        assert!(q.angle_to(truth) < tol, "{q:?}");
    }

    #[test]
    fn a_disturbed_field_is_kept_from_the_heading() {
        // Ten seconds of a clean field, then ten in which it is turned by
        // 40 degrees about the vertical and 30 % stronger.
        let disturbance = Quat::from_rotation_z(0.7);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let mut truth = Quat::from_rotation_x(0.1);
        let dt = 0.01;
        let mut worst: f32 = 0.0;
        for i in 0..2000 {
            let t = i as f32 * dt;
            let rate = tumble(t) * 0.5;
            truth = truth.integrate(rate, dt);
            let field = if t < 10.0 {
                FIELD
            } else {
                disturbance * FIELD * 1.3
            };
            let acc = truth.inv() * Cvec3::new(0.0, 0.0, G);
            let q = f.update_with_mag(rate, acc, truth.inv() * field, dt);
            worst = worst.max(q.angle_to(truth));
        }
        assert!(worst < 0.5f32.to_radians(), "{}", worst.to_degrees());
    }

    #[test]
    fn a_sustained_acceleration_with_a_vertical_part_stops_the_correction() {
        // At rest, then 10 s of 0.3 g forwards and 0.5 g upwards (a lift
        // that also moves): without the gate, the average would tilt by
        // atan(0.3 / 1.5), 11 degrees; the gate closes at 1.1 g, about 3.
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let push = |t: f32| {
            if t > 5.0 && t < 15.0 {
                Cvec3::new(0.3 * G, 0.0, 0.5 * G)
            } else {
                Cvec3::ZERO
            }
        };
        let mut worst: f32 = 0.0;
        simulate(
            &mut f,
            Quat::IDENTITY,
            15.0,
            100.0,
            Cvec3::ZERO,
            |_| Cvec3::ZERO,
            push,
            false,
            |_, truth, q| {
                worst = worst.max(inclination_error(q, truth));
            },
        );
        std::println!(
            "lift: worst {:.2} deg, bias {:?}",
            worst.to_degrees(),
            f.bias()
        );
        assert!(worst < 4f32.to_radians(), "{}", worst.to_degrees());
        // Nor does the bias learn from the corrections made meanwhile.
        assert!(f.bias().norm() < 1e-4, "{:?}", f.bias());
    }

    #[test]
    fn the_bias_estimate_is_clipped_to_max_bias() {
        let max = FilterParams::DEFAULT.max_bias;
        let bias = Cvec3::new(0.05, 0.0, 0.0);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        f.set_bias(Cvec3::new(0.03, 0.0, 0.0));
        simulate(
            &mut f,
            Quat::IDENTITY,
            200.0,
            100.0,
            bias,
            tumble,
            |_| Cvec3::ZERO,
            false,
            |_, _, _| {},
        );
        let b = f.bias();
        assert!((b.norm() - max).abs() < 1e-6 && b.x > 0.99 * max, "{b:?}");
    }

    #[test]
    fn vibration_is_no_rest() {
        // A still gyro on a shaking table: the accelerometer moves by 1 m/s².
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let bias = Cvec3::new(0.01, 0.0, 0.0);
        let shake = |t: f32| Cvec3::new((30.0 * t).sin(), 0.0, 0.0);
        simulate(
            &mut f,
            Quat::IDENTITY,
            10.0,
            200.0,
            bias,
            |_| Cvec3::ZERO,
            shake,
            false,
            |_, _, _| {},
        );
        assert!(!f.is_resting());
    }

    #[test]
    fn averages_out_strong_linear_acceleration() {
        // Shaken sideways at 2 g, 1.5 Hz, and up and down at 1 g, 2.3 Hz.
        let shake = |t: f32| {
            let w1 = 2.0 * core::f32::consts::PI * 1.5;
            let w2 = 2.0 * core::f32::consts::PI * 2.3;
            Cvec3::new(2.0 * G * (w1 * t).sin(), 0.0, G * (w2 * t).sin())
        };
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let mut worst: f32 = 0.0;
        let start = Quat::from_rotation_x(0.3);
        let slow = |t: f32| tumble(t) * 0.3;
        simulate(
            &mut f,
            start,
            60.0,
            200.0,
            Cvec3::ZERO,
            slow,
            shake,
            false,
            // Shaking that starts at full swing sets the sensor moving at
            // 2 g / w1 = 2.1 m/s on average, a velocity step that takes
            // about 5 tau_acc to pass; after that, the steady state.
            |t, truth, q| {
                if t > 15.0 {
                    worst = worst.max(inclination_error(q, truth));
                }
            },
        );
        std::println!(
            "shaken: worst inclination error {:.3} deg",
            worst.to_degrees()
        );
        // One sample's direction is off by up to 63 degrees; the two-stage
        // average leaves 2 g / (1 + (w1 tau_acc / 2)^2) = 0.01 g, 0.6 degrees.
        assert!(worst < 1f32.to_radians(), "{worst}");
    }

    #[test]
    fn a_disturbed_magnetometer_cannot_tilt_the_estimate() {
        let mut clean = OrientationFilter::new(FilterParams::DEFAULT);
        let mut disturbed = clean;
        let dt = 0.01;
        let mut truth = Quat::from_rotation_x(0.2);
        let mut worst: f32 = 0.0;
        for i in 0..6000 {
            let t = i as f32 * dt;
            truth = truth.integrate(tumble(t), dt);
            let (gyr, acc) = (tumble(t), truth.inv() * Cvec3::new(0.0, 0.0, G));
            // A steel cabinet: a field of any direction, changing.
            let junk = Cvec3::new(30.0 * (0.5 * t).sin(), -20.0, 60.0 * (0.2 * t).cos());
            clean.update_with_mag(gyr, acc, truth.inv() * FIELD, dt);
            let q = disturbed.update_with_mag(gyr, acc, truth.inv() * FIELD + junk, dt);
            worst = worst.max(inclination_error(q, truth));
        }
        assert!(worst < 0.05f32.to_radians(), "{worst}");
    }

    #[test]
    fn bad_input_is_reported_and_ignored() {
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let acc = Quat::from_rotation_x(0.4).inv() * Cvec3::new(0.0, 0.0, G);
        let gyr = Cvec3::new(0.1, 0.0, 0.0);
        for _ in 0..10 {
            f.update(gyr, acc, 0.01);
        }
        let before = f;
        // Compared as text: the unset magnetic reference is NaN.
        let unchanged = |f: &OrientationFilter| std::format!("{f:?}") == std::format!("{before:?}");
        for (g, d) in [
            (Cvec3::NAN, 0.01),
            (Cvec3::new(f32::INFINITY, 0.0, 0.0), 0.01),
            (gyr, f32::NAN),
            (gyr, f32::INFINITY),
        ] {
            assert!(!f.update(g, acc, d).is_finite());
            assert!(unchanged(&f));
        }
        assert_eq!(f.update(gyr, acc, 0.0), before.attitude());
        assert_eq!(f.update(gyr, acc, -1.0), before.attitude());
        assert!(unchanged(&f));
        // No accelerometer information: the gyro alone.
        for bad in [Cvec3::NAN, Cvec3::ZERO, Cvec3::new(f32::INFINITY, 0.0, 0.0)] {
            let mut g = before;
            let q = g.update(gyr, bad, 0.01);
            let want = before.attitude().integrate(gyr, 0.01);
            assert!(q.angle_to(want) < 1e-5, "{bad:?}");
        }
        // No usable field: no heading correction.
        for bad in [Cvec3::NAN, Cvec3::ZERO, Cvec3::new(0.0, 0.0, -40.0)] {
            let mut a = before;
            let mut b = before;
            assert_eq!(
                a.update_with_mag(gyr, acc, bad, 0.01),
                b.update(gyr, acc, 0.01),
                "{bad:?}"
            );
        }
        // NaN parameters: NaN out, no panic.
        let mut n = OrientationFilter::new(FilterParams {
            tau_acc: f32::NAN,
            ..FilterParams::DEFAULT
        });
        assert!(!n.update(gyr, acc, 0.01).is_finite());
        assert_eq!(n.attitude(), Quat::IDENTITY);
        // Huge but finite values: no panic.
        let mut h = OrientationFilter::new(FilterParams::DEFAULT);
        let huge = Cvec3::new(f32::MAX, -f32::MAX, f32::MAX);
        let _ = h.update_with_mag(huge, huge, huge, f32::MAX);
        let _ = h.update_with_mag(gyr, acc, huge, 1e-30);
    }

    #[test]
    fn rotation_to_up_takes_the_vector_up() {
        for u in [
            Cvec3::new(0.3, -0.4, 0.866),
            Cvec3::X,
            Cvec3::new(0.0, 0.6, -0.8),
            -Cvec3::Z,
            Cvec3::Z,
        ] {
            let u = u.normalize();
            let q = rotation_to_up(u);
            assert!((q * u - Cvec3::Z).norm() < 1e-6, "{u:?}");
            // About a horizontal axis: no heading.
            assert!(q.z.abs() < 1e-7, "{u:?}");
        }
    }
}
