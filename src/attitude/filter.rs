//! [`OrientationFilter`]: gyroscope + accelerometer (6D) and + magnetometer
//! (9D) attitude estimation, with gyro-bias estimation. This file is the
//! update's order; each estimator is a file of its own (`filter/`).

mod bias;
mod gyro;
mod hard_iron;
mod heading;
mod inclination;
mod min_max;
mod rest;
#[cfg(feature = "serde")]
mod saved;

use super::diagnostics::Flags;
use super::low_pass::{butterworth, smoothing_factor};
use super::{Diagnostics, FilterParams};
use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;
use bias::{horizontal_axes, Bias};
use gyro::Gyro;
use hard_iron::HardIron;
use heading::{undelayed, Heading, Verdict};
use inclination::{plausible_specific_force, Inclination};
use min_max::min;
use rest::RestDetector;

/// An orientation filter for gyroscope + accelerometer (6D, [`update`](Self::update))
/// and gyroscope + accelerometer + magnetometer (9D,
/// [`update_with_mag`](Self::update_with_mag)): a complementary filter with
/// gyro-bias estimation, in the attitude conventions of the
/// [module](super) (sensor to ENU earth frame).
///
/// # How it works
///
/// The attitude is the product `correction * strapdown`. `strapdown`
/// integrates the bias-corrected gyro exactly ([`Quat::integrate`]): it
/// maps the sensor frame into an almost inertial frame, which drifts only
/// as slowly as the gyro errors. In that frame the accelerometer goes
/// through a second-order Butterworth low-pass with time constant
/// `tau_acc`, where linear acceleration, the derivative of a bounded
/// velocity, averages out (the central idea of VQF: Laidig and Seel,
/// *VQF: Highly Accurate IMU Orientation Estimation with Bias Estimation
/// and Magnetic Disturbance Rejection*, Information Fusion 91, 2023, here
/// in a simpler filter). `correction` turns about a horizontal axis by the
/// smallest rotation that makes the average point up, while it is within
/// `acc_gate` of gravity; with a magnetometer, it also turns about the
/// vertical only (a disturbed field can never tilt the estimate) towards
/// magnetic north, by the fraction `1 - exp(-dt / tau_mag)` of the heading
/// error, while the field, less a learned hard-iron estimate (a magnet
/// carried with the sensor, of any size, learned as the sensor's attitude
/// varies), passes the disturbance gate. The gyro bias
/// follows the raw gyro at rest and, in motion, the inclination
/// corrections seen in the sensor frame, as a scalar Kalman filter would;
/// the heading correction never feeds it.
///
/// The first usable accelerometer sample sets the inclination (the
/// low-pass starts there, as if at rest), the first usable field the
/// heading. Until `tau_acc` seconds have passed, the corrections take the
/// time passed as their time constant. Every time constant works through
/// `1 - exp(-dt / tau)`, so that it holds at any sample rate. The
/// repository's `docs/attitude.md` gives each step's physics, and what
/// each costs and gains on real recordings.
///
/// # State and cost
///
/// 256 bytes including the 60 of the parameters (`size_of`, checked by a
/// test and by `cargo xtask filter-cost` on the target), no allocation.
/// Executed instructions per update on the emulated Cortex-M4F (QEMU
/// mps2-an386, opt-level "s", LTO), counted by `cargo xtask filter-cost`,
/// which fails above the budget of 1,600 (6D) and 2,200 (9D) instructions
/// and 256 bytes of state: 1,479 (6D) and 2,136 (9D; 2,161 with
/// `mag_delay` set).
///
/// # Bad input
///
/// The filter flags and skips what it cannot use, so that no single bad
/// sample moves its references or poisons its state: the attitude stays a
/// finite unit quaternion and the bias finite, whatever the samples,
/// parameters and setter values (fuzzed by `fuzz/fuzz_targets/attitude.rs`;
/// `docs/attitude.md` measures what each glitch costs on a recording):
///
/// - Gyro NaN, infinite, or turning more than half a turn within the
///   sample: flagged
///   ([`Diagnostics::gyro_ignored`](super::Diagnostics::gyro_ignored)),
///   the update returns [`Quat::NAN`], and the last usable reading is
///   integrated in its place (the body's inertia keeps its rate from
///   changing much within a sample); the accelerometer and magnetometer of
///   the sample are used.
/// - Gyro at `gyro_range` (when set): a single reading there is taken for a
///   glitch and replaced as above; from the second in a row on, the filter
///   recovers as documented there. Without the range, a full-scale reading
///   is a real rate to the filter.
/// - `dt <= 0`: nothing happens (no time passed); the current attitude is
///   returned. NaN, infinite or huge `dt` (one over which even the last
///   usable rate turns more than half a turn: a gap the gyro did not
///   see): flagged as above, the update returns [`Quat::NAN`], the rest of
///   the state is unchanged.
/// - Accelerometer NaN, infinite, zero (free fall, or a bus that read
///   zeros), so far from gravity that the sample alone would take the
///   average half-way out of `acc_gate` (a velocity change of 2.3 m/s
///   within one sample with the defaults: 66 g at 285 Hz, 23 g at 100 Hz;
///   no carried sensor feels that but in an impact), or beyond 1000 g
///   whatever `dt`: flagged (`acc_ignored`), the sample only propagates
///   the gyro, and it neither counts as rest nor ends it.
/// - Magnetometer NaN, infinite, zero, without horizontal part, outside
///   the disturbance gate, or weaker than the gate's radius (whose
///   direction, once the hard-iron estimate is taken off, would be the
///   estimate's): flagged (`mag_ignored`), no heading correction for that
///   sample, and the reference field moves towards it by at most the
///   fraction `1 - exp(-dt / 60 s)` of its own length. The first field
///   sets the reference; if the next one disagrees, it replaces it (the
///   first may have been a glitch), until a field passes the gate. A gate
///   shut for a net 60 s (each field that passes takes back its own `dt`)
///   gives the reference to the current field once the inclination is
///   known, and the hard-iron estimate starts over. The estimate moves
///   towards a reading by at most the fraction `1 - exp(-dt / tau_mag)` of
///   the reference's length, and stays within twice that length; a
///   reading further than three times that length from the reference
///   (which no estimate within its bound explains) teaches it nothing; a
///   usable reading that the estimate, taken off, would make unusable
///   starts it over.
/// - Parameters: zero or negative time constants mean "immediate" (no
///   smoothing), infinite ones "never". While any parameter is NaN, every
///   update returns [`Quat::NAN`] and leaves the state unchanged.
/// - [`set_bias`](Self::set_bias) ignores a non-finite bias;
///   [`with_attitude`](Self::with_attitude) starts as [`new`](Self::new)
///   from an attitude without direction (NaN, infinite, zero).
/// - The state holds no NaN and no infinity, so a filter saved with serde
///   at any point (before its first sample, before its first
///   magnetometer sample) reads back, in JSON too, as long as its
///   parameters are finite (JSON holds no infinity).
///
/// # Accuracy
///
/// Measured on real recordings with optical ground truth (BROAD trials 02,
/// 07, 08, 12, 16, 27 and 33, the last with a magnet fixed 2 cm from the
/// sensor: 9D total RMSE 1.355°, VQF's 3.752°): see the README's IMU
/// section, `docs/attitude.md` and the `broad` binary of `compare/`. On
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
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(from = "saved::Saved", into = "saved::Saved")
)]
pub struct OrientationFilter {
    /// The parameters; they may be changed between updates.
    pub params: FilterParams,
    /// Sensor to the almost inertial frame: the integrated gyro.
    strapdown: Quat,
    /// The almost inertial frame to earth: all corrections.
    correction: Quat,
    gyro: Gyro,
    rest: RestDetector,
    bias: Bias,
    inclination: Inclination,
    heading: Heading,
    hard_iron: HardIron,
    /// Seconds since the first usable accelerometer sample or the last
    /// saturated gyro sample: the corrections' time constants are at most
    /// this. Finite, so that JSON holds it.
    settling: f32,
    /// [`Diagnostics::acc_error`].
    acc_error: f32,
    /// The flags of [`Diagnostics`], and whether the inclination has been
    /// set (from an accelerometer sample or a starting attitude); with
    /// [`Diagnostics::mag_error`].
    flags: Flags,
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
            gyro: Gyro::new(),
            rest: RestDetector::new(),
            bias: Bias::new(params.max_bias),
            inclination: Inclination::new(),
            heading: Heading::new(),
            hard_iron: HardIron::new(),
            settling: 0.0,
            acc_error: 0.0,
            flags: Flags::new(Flags::INITIALISING),
        }
    }

    /// A filter that starts from a known `attitude` (a unit quaternion),
    /// as if it had been at rest there: the accelerometer average starts at
    /// gravity as that attitude predicts it, so a wrong starting
    /// inclination is corrected over about `tau_acc` seconds, not at once.
    /// The heading is still set by the first usable magnetometer sample in
    /// 9D.
    ///
    /// A finite `attitude` that is not unit is normalized (also one whose
    /// squared norm overflows). One that has no direction (zero, NaN or
    /// infinite, such as a corrupted value restored from flash) gives
    /// [`new`](Self::new)'s filter, which takes its inclination from the
    /// first usable accelerometer sample: a bad start cannot poison the
    /// updates.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::{Cvec3, Quat};
    /// let start = Quat::from_rotation_y(0.2);
    /// let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, start);
    /// assert!(f.attitude().angle_to(start) < 1e-6);
    /// let p = FilterParams::DEFAULT;
    /// let bad = OrientationFilter::with_attitude(p, Quat::NAN);
    /// assert_eq!(bad, OrientationFilter::new(p));
    /// ```
    #[must_use]
    pub fn with_attitude(params: FilterParams, attitude: Quat) -> Self {
        let mut f = Self::new(params);
        let Some(attitude) = attitude.try_normalize() else {
            return f;
        };
        f.correction = attitude;
        f.inclination = Inclination::at_rest(params.gravity);
        f.bias.axes_average = horizontal_axes(attitude);
        // Settled long ago; finite, so that JSON holds it.
        f.settling = f32::MAX;
        f.flags = Flags::new(Flags::INITIALIZED);
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
        self.bias.estimate
    }

    /// Sets the gyro bias estimate (rad/s, sensor frame), for instance from
    /// a calibration stored at the previous shutdown. Like the estimate, it
    /// is clipped to at most `params.max_bias` long (in its direction, also
    /// where its squared norm overflows; to zero while `max_bias` is zero
    /// or negative).
    ///
    /// A bias with a NaN or infinite component is ignored: the estimate
    /// stays as it was (a corrupted value restored from flash cannot poison
    /// the updates). Zero is a valid bias.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// f.set_bias(Cvec3::new(0.01, 0.0, 0.0));
    /// assert_eq!(f.bias().x, 0.01);
    /// f.set_bias(Cvec3::new(0.0, 1.0, 0.0)); // beyond max_bias
    /// assert_eq!(f.bias().y, FilterParams::DEFAULT.max_bias);
    /// f.set_bias(Cvec3::new(f32::NAN, 0.0, 0.0)); // ignored
    /// assert_eq!(f.bias().y, FilterParams::DEFAULT.max_bias);
    /// ```
    pub fn set_bias(&mut self, bias: Cvec3) {
        self.bias.set(bias, self.params.max_bias);
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
        if self.params.has_nan() {
            return Quat::NAN;
        }
        // No time passed (NaN fails this test and is taken below).
        if dt <= 0.0 {
            return self.attitude();
        }
        let p = self.params;
        self.bias.clip(p.max_bias);

        // 1. The gyro.
        let was_saturated = self.flags.get(Flags::GYRO_SATURATED);
        let step = self
            .gyro
            .step(gyr, self.bias.estimate, dt, p.gyro_range, was_saturated);
        self.flags
            .set(Flags::GYRO_IGNORED, step.is_none_or(|g| g.ignored));
        let Some(reading) = step else {
            return Quat::NAN;
        };
        let gyr = reading.rate;

        // 2. Rest. A sample without a usable accelerometer vector neither
        // counts as rest nor ends it (a glitch must not restart the rest
        // timer), and teaches the bias nothing.
        let acc = plausible_specific_force(acc, dt, &p);
        if let Some(acc) = acc {
            self.rest.update(gyr, acc, dt, &p);
        }
        let resting = acc.is_some() && self.is_resting();
        if reading.spinning {
            self.settling = 0.0;
            self.flags.set(Flags::RECOVERING, true);
        } else if self.flags.get(Flags::INITIALIZED) {
            self.settling = min(self.settling + dt, f32::MAX);
        }
        let settled = self.settling >= p.tau_acc;
        if settled {
            self.flags.set(Flags::INITIALISING, false);
            self.flags.set(Flags::RECOVERING, false);
        }
        self.flags.set(Flags::GYRO_SATURATED, reading.saturated);
        self.flags.set(Flags::RESTING, resting);
        self.bias.predict(self.rest.rate(), resting, dt, &p);

        // 3. The strapdown attitude.
        self.strapdown = self.strapdown.integrate(gyr - self.bias.estimate, dt);

        // 4. The inclination. Its correction in the earth frame, as a
        // rotation vector, is the drift the bias learns from (zero for the
        // first sample, which sets the inclination).
        let factors = butterworth(dt, min(p.tau_acc, self.settling));
        let first = !self.flags.get(Flags::INITIALIZED);
        let drift = acc.and_then(|acc| {
            self.flags.set(Flags::INITIALIZED, true);
            let inertial = self.strapdown * acc;
            let turn = self
                .inclination
                .step(inertial, self.correction, factors, first, &p)?;
            self.correction = (turn * self.correction).normalize();
            Some(if first {
                Cvec3::ZERO
            } else {
                turn.to_scaled_axis()
            })
        });
        let corrected = drift.is_some();
        self.flags.set(Flags::ACC_IGNORED, !corrected);
        let drift = drift.unwrap_or(Cvec3::ZERO);
        self.acc_error = drift.norm();

        // 5. The heading. The hard-iron estimate learns while the sensor
        // turns and is not at rest (the rest detector reads the raw gyro,
        // so a stale bias estimate cannot make a still sensor seem to
        // turn), once settled, and while the inclination is known:
        // corrected in this sample, and slower than `max_bias` (a faster
        // correction is convergence, after a gap in the gyro, say, whose
        // attitude gets the field's dip wrong).
        let mut attitude = self.attitude();
        let heading = mag.map(|mag| {
            let rate = gyr - self.bias.estimate;
            let turning = !resting && rate.norm_squared() > p.rest_gyro * p.rest_gyro;
            let level = corrected && self.acc_error <= p.max_bias * dt;
            let mag = undelayed(mag, rate, p.mag_delay);
            let variety = self.bias.variety();
            let known = settled && level;
            self.correct_heading(mag, dt, turning, known, variety, &mut attitude)
        });
        self.flags
            .set(Flags::MAG_IGNORED, heading.is_some_and(|h| h.is_none()));
        self.flags.set_mag_error(heading.flatten().unwrap_or(0.0));

        // 6. The bias in motion, from the inclination correction alone (a
        // magnetic disturbance must not reach it), once settled (before,
        // the corrections are convergence).
        if acc.is_some() {
            self.bias.average_axes(attitude, factors, first);
        }
        if settled && !resting && corrected {
            self.bias.learn(drift, dt, &p);
        }
        if reading.ignored {
            return Quat::NAN;
        }
        attitude
    }

    /// Turns the correction about the vertical towards magnetic north, if
    /// the reading `mag`, with the hard-iron estimate taken off, passes the
    /// disturbance gate. Returns the heading error it saw (radians east of
    /// north), `None` if the field was not used. The hard-iron estimate
    /// learns from the field if the sensor is `turning` and the attitude
    /// `known`, a growing estimate in the share `variety` of the
    /// attitudes' variety if the field passed, and fades while the sensor
    /// is not turning. `attitude` is the filter's, which a correction
    /// turns as it turns `correction`.
    fn correct_heading(
        &mut self,
        mag: Cvec3,
        dt: f32,
        turning: bool,
        known: bool,
        variety: f32,
        attitude: &mut Quat,
    ) -> Option<f32> {
        let p = self.params;
        let here = *attitude;
        let reference = self.heading.reference();
        let length = reference.norm();
        let radius = p.mag_gate * length;
        let open = self.heading.is_open();
        let share = self.hard_iron.share(radius, open);
        let mut reading = self.hard_iron.take_off(mag, here, share)?;
        let unconfirmed = self
            .hard_iron
            .unconfirmed(mag, here, reference, radius, open);
        let verdict = self
            .heading
            .gate(reading.seen(), mag, length, radius, known, dt);
        let fraction = match verdict {
            Verdict::Set => 1.0,
            _ => smoothing_factor(dt, min(p.tau_mag, self.settling)),
        };
        let mut field = reading.field;
        match verdict {
            Verdict::Set => {}
            // The hard-iron estimate, part of the model that failed,
            // starts over, and the field as read becomes the reference.
            Verdict::Renew => {
                if let Some(raw) = self.hard_iron.forget(mag, here) {
                    reading = raw;
                }
                field = reading.field;
                self.heading.renew(reading.seen());
            }
            Verdict::Follow {
                offset,
                pull,
                alpha,
                inside,
            } => {
                // The estimate's step is clipped as the reference's: a
                // single reading moves it by at most the fraction of the
                // reference's length that the heading correction takes. A
                // kept-out field, if it is fixed to the sensor, must be
                // learned to give the heading back, and is larger than
                // what is fixed to the earth and passes; a field that
                // passes is told from those only as the attitude varies.
                if !turning {
                    self.hard_iron.fade(alpha);
                } else if known && self.hard_iron.could_explain(pull) {
                    let growth = if inside { variety } else { 1.0 };
                    self.hard_iron
                        .learn(&reading, offset, fraction * pull, growth, here, length);
                }
                if !inside {
                    return None;
                }
                if let Some(partial) = unconfirmed {
                    field = partial?;
                }
            }
        }
        // The field's angle east of north; turning by it about +z brings
        // it to north.
        let error = float::atan2(field.x, field.y);
        let turn = heading::about_vertical(error * fraction);
        self.correction = turn.turn(self.correction).normalize();
        *attitude = self.attitude();
        Some(error)
    }

    /// The state flags and internal errors after the last update (see
    /// [`Diagnostics`]), for a firmware to log.
    ///
    /// ```
    /// use rigtform::attitude::{FilterParams, OrientationFilter};
    /// use rigtform::Cvec3;
    /// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    /// let g = Cvec3::new(0.0, 0.0, 9.81);
    /// for _ in 0..400 {
    ///     f.update(Cvec3::ZERO, g, 0.01); // 4 s still
    /// }
    /// let d = f.diagnostics();
    /// assert!(d.resting && !d.initialising && !d.acc_ignored);
    /// ```
    #[inline]
    #[must_use]
    pub fn diagnostics(&self) -> Diagnostics {
        self.flags.diagnostics(self.acc_error)
    }
}

#[cfg(test)]
mod tests;
