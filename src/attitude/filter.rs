//! [`OrientationFilter`]: gyroscope + accelerometer (6D) and + magnetometer
//! (9D) attitude estimation, with gyro-bias estimation.

use super::diagnostics::Flags;
use super::low_pass::{butterworth, butterworth_step, low_pass, smoothing_factor};
use super::rest::RestDetector;
use super::{Diagnostics, FilterParams};
use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// Time constant with which the magnetic reference follows the field.
const MAG_REFERENCE_TAU: f32 = 60.0;

/// The largest turn about each axis, in radians, by which a magnetometer
/// reading is brought forward over `FilterParams::mag_delay`: beyond it,
/// the first order is more than 3 % off.
const MAX_DELAY_TURN: f32 = 0.25;

/// The largest hard-iron estimate, in units of the reference field's
/// length. A magnet that swamps the earth's field twice over leaves no
/// heading to measure (a few percent of error in its estimate is as large
/// as the horizontal field); the bound also keeps the estimate finite
/// whatever fields were taken for the reference.
const MAX_HARD_IRON: f32 = 2.0;

/// The peak of the accelerometer low-pass's impulse response, times
/// `tau_acc` per unit of impulse: `2 exp(-x) sin(x)` at `x = pi / 4`
/// (see [`butterworth`]). A sample that departs from gravity by `a` for
/// `dt` seconds (`dt` at most `tau_acc`) moves the average by at most
/// `IMPULSE_PEAK * a * dt / tau_acc`, about `tau_acc / 4` seconds later.
const IMPULSE_PEAK: f32 = 0.644_794;

/// The largest specific force the filter takes, in units of `gravity`:
/// 1000 g, beyond what any accelerometer of an IMU measures (MEMS parts
/// reach 16 to 32 g, shock sensors 200 to 400 g). It bounds the
/// accelerometer average and its rounding errors (1000 g times 2^-24 is
/// 6e-5 g) whatever `dt` is; a sample's own bound (see
/// [`plausible_specific_force`]) is smaller at every sample rate below
/// 4 kHz.
pub(super) const MAX_SPECIFIC_FORCE: f32 = 1000.0;

/// The square of half a turn, in rad^2: a gyro reading that turns further
/// within one sample aliases (no sampled gyro tells it from a slower turn
/// the other way).
pub(super) const HALF_TURN_SQUARED: f32 = core::f32::consts::PI * core::f32::consts::PI;

/// The fraction of `gyro_range` from which a reading counts as saturated.
const SATURATION: f32 = 0.99;

/// The standard deviation of the bias estimate at rest, in rad/s
/// (0.01 °/s): a MEMS gyro's noise density of about 0.01 °/s/√Hz averaged
/// over `tau_bias_rest` (3 s) leaves 0.004 °/s, and the bias moves by
/// about as much again within the low-pass's delay.
const REST_BIAS_SIGMA: f32 = 0.01 * core::f32::consts::PI / 180.0;

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
///    second-order Butterworth low-pass with time constant `tau_acc`. In an
///    inertial frame, linear acceleration is the derivative of velocity,
///    which stays bounded, so the average tends to gravity: shaking,
///    running and vibration average out, rather than tilting the estimate
///    as in a filter that trusts each sample's direction. This is the
///    central idea of VQF (Laidig and Seel, *VQF: Highly Accurate IMU
///    Orientation Estimation with Bias Estimation and Magnetic Disturbance
///    Rejection*, Information Fusion 91, 2023), here in a simpler filter.
///    The Butterworth has the same delay as two first-order stages of
///    `tau_acc / 2` (both lag a steady drift by `tau_acc`), but its poles
///    are `sqrt(2)` times closer to zero, so it passes half the
///    acceleration at every frequency well above `1 / tau_acc`.
/// 3. `correction` is then turned, about a horizontal axis, by the
///    smallest rotation that makes the averaged vector point up: the
///    inclination correction. It is skipped while the averaged magnitude is
///    more than `acc_gate` away from gravity.
/// 4. With a magnetometer, `correction` also turns about the vertical
///    (only: a disturbed field can never tilt the estimate) towards
///    magnetic north (the horizontal part of the field along +y), by the
///    fraction `1 - exp(-dt / tau_mag)` of the heading error, while the
///    field passes the disturbance gate. Before the gate, a hard-iron
///    estimate is taken off the reading: the field fixed to the sensor (a
///    magnet, or a magnetized part, carried with it), which the
///    calibration cannot know. A field fixed to the sensor stays put in
///    the sensor frame as the sensor turns, while one fixed to the earth
///    (iron nearby) turns in it, so the estimate low-passes, in the sensor
///    frame, the part of each reading's disagreement with the reference
///    that no heading error explains (in the earth frame: the difference
///    of the horizontal parts, along the field's own horizontal direction,
///    and of the vertical parts), with `tau_mag`, over which the fields of
///    an earth-fixed disturbance turn and average out. It learns only
///    while the sensor turns faster than `rest_gyro` and is not at rest
///    (the rest detector reads the raw gyro, so a stale bias estimate
///    cannot make a still sensor seem to turn), once settled, and
///    while the inclination is known (corrected in that sample, slower
///    than `max_bias`: the dip depends on it); its step is clipped as the
///    reference's. While the sensor turns slower, nothing tells the two
///    kinds of field apart and nothing confirms the estimate: it fades
///    over 60 s, as the reference renews. It is taken
///    off only beyond the gate's radius (in full from twice that on): a
///    smaller one lets the field pass the gate as it is, and is the
///    calibration's residual error, which turns with the sensor and
///    averages out of the heading, where the estimate, wandering with the
///    attitudes of the last `tau_mag` seconds, would not.
/// 5. Gyro bias: while at rest (rest detection on gyro and accelerometer),
///    the bias low-passes the raw gyro. During motion, each inclination
///    correction, expressed in the sensor frame, is the drift a bias error
///    caused; the bias follows it as a scalar Kalman filter would, with the
///    time constant `bias_noise^2 / variance` (never shorter than
///    `tau_bias`), whenever an inclination correction was made. Every
///    correction counts, however strongly the current sample is
///    accelerated: the correction comes from the average, not from the
///    sample, and the leaks of linear acceleration into the average
///    cancel over the motion only if the corrections of all its phases
///    are taken (picking the samples near gravity would pick particular
///    phases of a periodic motion, whose leaks need not cancel;
///    `bias_noise` is the weight that the leaks call for). The
///    correction is taken to the sensor frame by the attitude averaged
///    through the accelerometer's low-pass (its first two rows, the
///    earth's horizontal axes in the sensor frame), since the average it
///    corrects saw the bias through that low-pass: in rotation faster than
///    `1 / tau_acc` the averaged axes shrink, and so does what the
///    correction is taken to say about the bias (the measurement model of
///    VQF's bias estimation, in a scalar filter). The
///    variance grows with `bias_drift` while the bias is not measured,
///    falls towards (0.01 °/s)^2 at rest, and shrinks with each motion
///    update. So a bias just learned at rest is barely moved by the
///    corrections that linear accelerations cause, while one never seen at
///    rest is learned from them. As the sensor turns, every sensor axis
///    spends time horizontal, where the inclination shows its bias. The
///    heading correction never feeds the bias, so that a magnetic
///    disturbance cannot corrupt it (nor, through it, the inclination).
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
/// 256 bytes including the 60 of the parameters and the 12 of the
/// hard-iron estimate (`size_of`, checked by a
/// test and by `cargo xtask filter-cost` on the target), no allocation. A
/// 6D update costs three quaternion products, three vector rotations, four
/// normalizations, an atan2, the low-pass of the accelerometer and of two
/// rows of the attitude matrix (Taylor series for the factors, or an
/// `exp_m1` and a sine-cosine where `dt / tau_acc` exceeds 1/16), the
/// smoothing factors of the rest detector and the bias, and a handful of
/// vector operations; the magnetometer adds two products, a rotation, an
/// atan2, a sine-cosine, two smoothing factors and the hard-iron
/// estimate's step (a row of the attitude matrix and a handful of vector
/// operations). Executed instructions
/// per update on the emulated Cortex-M4F (QEMU mps2-an386, opt-level "s",
/// LTO), counted by `cargo xtask filter-cost`, which fails above the
/// budget of 1,600 (6D) and 2,200 (9D) instructions and 256 bytes of
/// state: 1,494 (6D) and 2,147 (9D; 2,170 with `mag_delay` set).
///
/// # Bad input
///
/// The filter flags and skips what it cannot use, so that no single bad
/// sample moves its references or poisons its state: the attitude stays a
/// finite unit quaternion and the bias finite, whatever the samples,
/// parameters and setter values (fuzzed by `fuzz/fuzz_targets/attitude.rs`).
/// What each glitch costs, measured by injecting it into BROAD trial 16
/// 60 s in (in fast motion) against the clean run
/// (`tests/bad_samples.rs`, which prints the table; the clean run's 9D
/// total RMSE is 0.687°):
///
/// - Gyro NaN, infinite, or turning more than half a turn within the
///   sample (1e30 rad/s, `3.4e38`; no sampled gyro tells such a turn from
///   a slower one the other way): flagged
///   ([`Diagnostics::gyro_ignored`](super::Diagnostics::gyro_ignored)),
///   the update returns [`Quat::NAN`], and the last usable reading is
///   integrated in its place (the body's inertia keeps its rate from
///   changing much within a sample); the accelerometer and magnetometer of
///   the sample are used. One such sample: no correction off, the estimate
///   0.03° from the clean run's. A burst of 100 (0.35 s) loses that much of
///   the turn (up to 100° here); the corrections bring it back (within
///   0.1° of the clean run 64 s later).
/// - Gyro at `gyro_range` (when set): a single reading there is taken for a
///   glitch and replaced as above (no correction off, 0.03°); from the
///   second in a row on, the filter recovers as documented there. Without
///   the range, a full-scale reading is a real rate to the filter: one of
///   2000 °/s on each axis turns the estimate by 12°, and the field then
///   fails its gate until the inclination is back within about 5° (593
///   samples, 2 s, in all).
/// - `dt <= 0`: nothing happens (no time passed); the current attitude is
///   returned. NaN, infinite or huge `dt` (one over which even the last
///   usable rate turns more than half a turn: a gap the gyro did not
///   see): flagged as above, the update returns [`Quat::NAN`], the rest of
///   the state is unchanged. The sample's turn is lost (up to 1.2° in
///   trial 16, within 0.1° again 16 s later); no correction is off.
/// - Accelerometer NaN, infinite, zero (free fall, or a bus that read
///   zeros: no direction), or so far from gravity that the sample alone
///   would take the average half-way out of `acc_gate` (a velocity change
///   of 2.3 m/s within one sample with the defaults: 66 g at 285 Hz, 23 g
///   at 100 Hz; no carried sensor feels that but in an impact), or beyond
///   1000 g whatever `dt` (`3.4e38` and `1e30` are far beyond both):
///   flagged (`acc_ignored`), the sample only propagates the gyro, and it
///   neither counts as rest nor ends it. The correction is off for that
///   sample alone (for the 100 samples of a burst of 100, and not after
///   it). Below the bound a reading is a real specific force to the
///   filter: one of 16 g on each axis moves the estimate by 1°, with no
///   correction off.
/// - Magnetometer NaN, infinite, zero, without horizontal part, outside
///   the disturbance gate (`1e30`, `1e6`, int16 full scale, a field
///   opposite to the reference), or weaker than the gate's radius (whose
///   direction, once the hard-iron estimate is taken off, would be the
///   estimate's): flagged (`mag_ignored`), no heading
///   correction for that sample, and the reference field moves towards it
///   by at most the fraction `1 - exp(-dt / 60 s)` of its own length (it
///   follows no faster than it would a field its own length away): the
///   next usable field passes the gate again (after a burst of 100, five
///   samples near the gate's edge fall on the other side in the rest of
///   the trial). The first field sets the reference; if the next one
///   disagrees, it replaces it (the first may have been a glitch), until a
///   field passes the gate. A gate shut for a net 60 s (a new
///   environment, or a burst of identical glitches that confirmed itself
///   as the first fields; each field that passes takes back its own `dt`,
///   so a few that pass by chance do not put the renewal off by a minute)
///   gives the reference to the current field once the inclination is
///   known (the reference's dip is measured through it), and the hard-iron
///   estimate starts over from zero. The estimate moves towards a reading
///   by at most the fraction `1 - exp(-dt / tau_mag)` of the reference's
///   length, and stays within twice that length (a step beyond is not
///   taken); a usable reading that the estimate, taken off, would make
///   unusable (an estimate grown from huge glitches taken for the
///   reference) starts it over.
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
/// sensor: 9D total RMSE 1.383°, VQF's 3.752°): see the README's IMU
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
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrientationFilter {
    /// The parameters; they may be changed between updates.
    pub params: FilterParams,
    /// Sensor to the almost inertial frame: the integrated gyro.
    strapdown: Quat,
    /// The almost inertial frame to earth: all corrections.
    correction: Quat,
    /// The accelerometer low-pass in the inertial frame: its output, and
    /// its rate of change times `tau_acc`.
    acc_average: Cvec3,
    acc_rate: Cvec3,
    /// The gyro bias estimate, rad/s, sensor frame.
    bias: Cvec3,
    /// The last usable gyro reading, rad/s: it stands in for an unusable
    /// one.
    last_rate: Cvec3,
    rest: RestDetector,
    /// The hard-iron estimate: the field fixed to the sensor (a magnet on
    /// it), in the magnetometer's unit and the sensor frame, taken off
    /// every magnetometer reading.
    hard_iron: Cvec3,
    /// Reference field in the earth frame as (horizontal, vertical);
    /// zero until the first usable magnetometer sample (a usable field has
    /// a horizontal part, so zero is never a reference). Finite, so that
    /// every serde format, JSON included, holds it.
    mag_reference: [f32; 2],
    /// Negative until a field has passed the disturbance gate (until then
    /// the reference is one sample's, and a field outside the gate
    /// replaces it and sets the heading: the first may have been a
    /// glitch); then the net seconds for which the gate has been shut:
    /// up by `dt` for each field it shuts out, down by `dt` (not below
    /// zero) for each it passes.
    mag_shut: f32,
    /// The variance of the bias estimate, (rad/s)^2.
    bias_variance: f32,
    /// Seconds since the first usable accelerometer sample or the last
    /// saturated gyro sample: the corrections' time constants are at most
    /// this.
    settling: f32,
    /// [`Diagnostics::acc_error`].
    acc_error: f32,
    /// The flags of [`Diagnostics`], and whether the inclination has been
    /// set (from an accelerometer sample or a starting attitude); with
    /// [`Diagnostics::mag_error`].
    flags: Flags,
    /// The earth's x and y axes in the sensor frame (the first two rows of
    /// the attitude's matrix), through the same low-pass as the
    /// accelerometer, and their rates times `tau_acc`.
    axes_average: [Cvec3; 2],
    axes_rate: [Cvec3; 2],
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
            acc_average: Cvec3::ZERO,
            acc_rate: Cvec3::ZERO,
            bias: Cvec3::ZERO,
            last_rate: Cvec3::ZERO,
            rest: RestDetector::new(),
            hard_iron: Cvec3::ZERO,
            mag_reference: [0.0; 2],
            mag_shut: -1.0,
            bias_variance: params.max_bias * params.max_bias,
            settling: 0.0,
            axes_average: [Cvec3::X, Cvec3::Y],
            axes_rate: [Cvec3::ZERO, Cvec3::ZERO],
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
        f.acc_average = Cvec3::new(0.0, 0.0, params.gravity);
        f.axes_average = horizontal_axes(attitude);
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
        self.bias
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
        if !bias.is_finite() {
            return;
        }
        // NaN (a NaN parameter) counts as zero.
        let max = self.params.max_bias.max(0.0);
        self.bias = if bias.norm() > max {
            bias.try_normalize().map_or(Cvec3::ZERO, |unit| unit * max)
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
        if self.params.has_nan() {
            return Quat::NAN;
        }
        // No time passed (NaN fails this test and is taken below).
        if dt <= 0.0 {
            return self.attitude();
        }
        // A usable reading turns less than half a turn within one sample:
        // no sampled gyro tells more from a slower turn the other way (the
        // turn aliases), so such a reading is a glitch (1e30 rad/s). The
        // squares overflow to infinity, and NaN (in the reading or in `dt`)
        // fails the test. An unusable reading is replaced by the last
        // usable one (the body's inertia keeps its rate from changing much
        // within a sample), and the update reports it by returning NaN. If
        // that one turns too far as well, `dt` is NaN or spans a gap the
        // gyro did not see: the sample is skipped, only the flag changes.
        // (Restarting the short time constants of recovery after a run of
        // unusable readings was tried on BROAD trial 16: after 100 of them
        // in fast motion it doubled the 9D error, as the inclination then
        // follows each accelerated sample and the field fails its gate.)
        // A bias beyond `max_bias` (left by parameters that were changed
        // since) is clipped before it is subtracted.
        let max_bias = self.params.max_bias;
        // NaN fails the test too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(self.bias.norm_squared() <= max_bias * max_bias) {
            self.set_bias(self.bias);
        }
        let usable = |rate: Cvec3| ((rate - self.bias) * dt).norm_squared() <= HALF_TURN_SQUARED;
        let ignored = !usable(gyr);
        self.flags.set(Flags::GYRO_IGNORED, ignored);
        if ignored && !usable(self.last_rate) {
            return Quat::NAN;
        }
        let p = self.params;
        // A reading at the range has lost the true rate. A spin beyond the
        // range lasts longer than a sample: from the second such reading
        // in a row on, the clipped reading is integrated and the filter
        // recovers (short time constants). A single one amid slower
        // readings is a glitch (or the first sample of a spin), whose rate
        // the last reading below the range gives better, as for an
        // unusable one.
        let saturated = !ignored && {
            let range = SATURATION * p.gyro_range;
            gyr.x.abs() >= range || gyr.y.abs() >= range || gyr.z.abs() >= range
        };
        let spinning = saturated && self.flags.get(Flags::GYRO_SATURATED);
        let gyr = if ignored || (saturated && !spinning) {
            self.last_rate
        } else {
            gyr
        };
        if !(ignored || saturated) {
            self.last_rate = gyr;
        }
        let acc = plausible_specific_force(acc, dt, &p);
        // A sample without a usable vector neither counts as rest nor ends
        // it (a glitch must not restart the rest timer), and teaches the
        // bias nothing.
        if let Some(acc) = acc {
            self.rest.update(gyr, acc, dt, &p);
        }
        let resting = acc.is_some() && self.is_resting();
        if spinning {
            self.settling = 0.0;
            self.flags.set(Flags::RECOVERING, true);
        } else if self.flags.get(Flags::INITIALIZED) {
            // Finite, so that JSON holds it.
            self.settling = min(self.settling + dt, f32::MAX);
        }
        let settled = self.settling >= p.tau_acc;
        if settled {
            self.flags.set(Flags::INITIALISING, false);
            self.flags.set(Flags::RECOVERING, false);
        }
        self.flags.set(Flags::GYRO_SATURATED, saturated);
        self.flags.set(Flags::RESTING, resting);
        // The bias estimate's variance grows as the bias wanders, and at
        // rest falls towards what the raw gyro tells.
        // The estimate is clipped to max_bias, so its variance stays below
        // max_bias^2 (which also keeps it finite).
        self.bias_variance = min(
            self.bias_variance + p.bias_drift * p.bias_drift * dt,
            p.max_bias * p.max_bias,
        );
        if resting {
            let alpha = smoothing_factor(dt, p.tau_bias_rest);
            self.set_bias(low_pass(self.bias, gyr, alpha));
            let rest = REST_BIAS_SIGMA * REST_BIAS_SIGMA;
            self.bias_variance += (rest - self.bias_variance) * alpha;
        }

        self.strapdown = self.strapdown.integrate(gyr - self.bias, dt);

        // The inclination correction in the earth frame, as a rotation
        // vector, for the bias. The heading correction is left out: a
        // magnetic disturbance must not reach the bias either.
        let factors = butterworth(dt, min(p.tau_acc, self.settling));
        let first = !self.flags.get(Flags::INITIALIZED);
        let drift = match acc {
            Some(acc) => self.correct_inclination(acc, factors),
            None => None,
        };
        let corrected = drift.is_some();
        self.flags.set(Flags::ACC_IGNORED, !corrected);
        let drift = drift.unwrap_or(Cvec3::ZERO);
        self.acc_error = drift.norm();
        // The hard-iron estimate learns while the sensor turns and is not
        // at rest (see `correct_heading`), once settled, and while the
        // inclination is known: corrected in this sample (the
        // accelerometer average is within its gate of gravity), and
        // slower than `max_bias` (a
        // faster correction is convergence, after a gap in the gyro, say,
        // whose attitude gets the field's dip wrong).
        let heading = mag.map(|mag| {
            let rate = gyr - self.bias;
            let turning = !resting && rate.norm_squared() > p.rest_gyro * p.rest_gyro;
            let level = corrected && self.acc_error <= p.max_bias * dt;
            let mag = undelayed(mag, rate, p.mag_delay);
            self.correct_heading(mag, dt, turning, settled && level)
        });
        self.flags
            .set(Flags::MAG_IGNORED, heading.is_some_and(|h| h.is_none()));
        self.flags.set_mag_error(heading.flatten().unwrap_or(0.0));

        let attitude = self.attitude();
        if acc.is_some() {
            // The attitude through the accelerometer's low-pass, in the same
            // steps (see the bias below).
            let axes = horizontal_axes(attitude);
            if first {
                self.axes_average = axes;
            }
            let rows = self.axes_average.iter_mut().zip(&mut self.axes_rate);
            for ((average, rate), axis) in rows.zip(axes) {
                (*average, *rate) = butterworth_step(*average, *rate, axis, factors);
            }
        }
        // The corrections undid a drift of -drift in dt: in the sensor
        // frame, the bias error that would cause it. Faster corrections are
        // no bias (see max_bias).
        let rate = drift * (1.0 / dt);
        // The bias error that the average saw is the low-passed attitude's
        // (the earth's horizontal axes in the sensor frame, averaged as the
        // accelerometer was), not today's: in fast rotation it averages out,
        // and so does what the corrections tell of the bias.
        let [ex, ey] = self.axes_average;
        let error = ex * rate.x + ey * rate.y;
        let seen = 0.5 * (ex.norm_squared() + ey.norm_squared());
        // While settling, the corrections are convergence, not bias.
        if settled && !resting && corrected && rate.norm() <= p.max_bias {
            // A continuous Kalman update: the gain is variance / noise^2
            // per second, and the variance shrinks by the same fraction.
            let variance = self.bias_variance;
            let tau = (p.bias_noise * p.bias_noise / variance).max(p.tau_bias);
            // 0 / 0 (no noise, no uncertainty): nothing to learn.
            let alpha = if tau.is_nan() {
                0.0
            } else {
                smoothing_factor(dt, tau)
            };
            self.set_bias(self.bias - error * alpha);
            self.bias_variance = variance * (1.0 - alpha * seen);
        }
        if ignored {
            return Quat::NAN;
        }
        attitude
    }

    /// Averages the accelerometer in the inertial frame and turns the
    /// correction so that the average points up. Returns the correction's
    /// rotation vector (earth frame; zero for the first sample, which sets
    /// the inclination), `None` if the average is outside the gate.
    fn correct_inclination(&mut self, acc: Cvec3, factors: (f32, f32)) -> Option<Cvec3> {
        let p = self.params;
        let inertial = self.strapdown * acc;
        let first = !self.flags.get(Flags::INITIALIZED);
        if first {
            self.acc_average = inertial;
            self.acc_rate = Cvec3::ZERO;
            self.flags.set(Flags::INITIALIZED, true);
        }
        let (average, rate) = butterworth_step(self.acc_average, self.acc_rate, inertial, factors);
        let length = average.norm();
        // An average beyond the largest specific force (left by parameters
        // that were changed since) or NaN: the low-pass restarts here.
        // NaN fails the test too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(length <= MAX_SPECIFIC_FORCE * p.gravity) {
            self.acc_average = inertial;
            self.acc_rate = Cvec3::ZERO;
            return None;
        }
        self.acc_average = average;
        self.acc_rate = rate;
        if (length - p.gravity).abs() > p.acc_gate * p.gravity {
            return None;
        }
        let up = (self.correction * average).try_normalize()?;
        let turn = rotation_to_up(up);
        self.correction = (turn * self.correction).normalize();
        // Setting the inclination from the first sample is no drift.
        Some(if first {
            Cvec3::ZERO
        } else {
            turn.to_scaled_axis()
        })
    }

    /// Turns the correction about the vertical towards magnetic north, if
    /// the field passes the disturbance gate. Returns the heading error it
    /// saw (radians east of north), `None` if the field was not used. The
    /// hard-iron estimate learns from the field if the sensor is `turning`
    /// and the attitude `known`, and fades while it is not turning.
    fn correct_heading(&mut self, mag: Cvec3, dt: f32, turning: bool, known: bool) -> Option<f32> {
        let p = self.params;
        let attitude = self.attitude();
        let reference = self.mag_reference();
        let length = reference.norm();
        // The hard-iron estimate is taken off while it is beyond the
        // gate's radius (fully from twice that on): a smaller one lets the
        // field pass the gate as it is, and is the calibration's residual
        // error (a soft-iron or scale error, or a sensor-fixed field of a
        // microtesla), which turns with the sensor and so averages out of
        // the heading, where an estimate of it, wandering with the
        // attitudes of the last `tau_mag` seconds, would not.
        let strength = self.hard_iron.norm_squared();
        let radius = p.mag_gate * length;
        let least = if radius > 0.0 { radius } else { 0.0 };
        let taken = if strength > 4.0 * least * least {
            1.0
        } else if strength > least * least {
            float::sqrt(strength) / least - 1.0
        } else {
            0.0
        };
        let mut corrected = mag - self.hard_iron * taken;
        let mut field = attitude * corrected;
        let mut horizontal = horizontal_part(field);
        if horizontal.is_none() {
            // A reading that is usable as it is, but not once the estimate
            // is taken off: the estimate has grown beyond any field (after
            // huge glitches were taken for the reference), and starts over.
            let raw = attitude * mag;
            horizontal = horizontal_part(raw);
            if horizontal.is_some() {
                self.hard_iron = Cvec3::ZERO;
                corrected = mag;
                field = raw;
            }
        }
        let horizontal = horizontal?;
        let mut seen = Cvec3::new(horizontal, field.z, 0.0);
        // Finite: seen and reference are, and far below f32::MAX apart in
        // each component. Its norm may overflow to infinity.
        let offset = seen - reference;
        let distance = offset.norm();
        // The reading itself must be stronger than the gate's radius: a
        // weaker one is, for all the gate can tell, zero, and its
        // direction once the hard-iron estimate is taken off is the
        // estimate's, not the earth's (a reference and an estimate grown
        // from huge glitches would otherwise agree with any small reading
        // and turn the heading to the estimate).
        let inside = distance <= radius && mag.norm_squared() > radius * radius;
        // No reference yet, or one sample's that the next field disputes:
        // the field sets the heading at once and becomes the reference.
        let confirmed = self.mag_shut >= 0.0;
        let first = length == 0.0 || !(inside || confirmed);
        let fraction = if first {
            1.0
        } else {
            smoothing_factor(dt, min(p.tau_mag, self.settling))
        };
        if first {
            self.mag_reference = [seen.x, seen.y];
        } else if !inside && self.mag_shut >= MAG_REFERENCE_TAU && known {
            // The gate has been shut for a net MAG_REFERENCE_TAU: a new
            // environment, or a burst of identical glitches that confirmed
            // itself as the first fields. The field becomes the reference,
            // and corrects the heading as any field that passes does; the
            // hard-iron estimate, part of the model that failed, starts
            // over. Only while the inclination is known: the reference's
            // dip is measured through it (one taken while the sensor's
            // attitude is upside down has its vertical part reversed, and
            // would be renewed again a minute later).
            if self.hard_iron != Cvec3::ZERO {
                let raw = attitude * mag;
                if let Some(horizontal) = horizontal_part(raw) {
                    self.hard_iron = Cvec3::ZERO;
                    field = raw;
                    seen = Cvec3::new(horizontal, field.z, 0.0);
                }
            }
            self.mag_reference = [seen.x, seen.y];
            self.mag_shut = 0.0;
        } else {
            // The reference follows the field, but no faster than it would
            // follow one its own length away: a single reading, however
            // far off (a glitch of 1e30), moves it by at most the fraction
            // alpha of its length, while a new environment (rarely further
            // off than the earth's field itself) is followed as before.
            let pull = if distance > length {
                length / distance
            } else {
                1.0
            };
            let alpha = smoothing_factor(dt, MAG_REFERENCE_TAU);
            let moved = reference + offset * (alpha * pull);
            self.mag_reference = [moved.x, moved.y];
            // The hard-iron estimate low-passes, in the sensor frame, the
            // part of the reading's disagreement with the reference that no
            // heading error explains: in the earth frame, the difference of
            // the horizontal parts along the field's own horizontal
            // direction, and of the vertical parts (a heading error turns
            // the field about the vertical, which changes neither). A field
            // fixed to the sensor (a magnet carried with it) stays put in
            // that frame and is learned; one fixed to the earth (iron
            // nearby) turns in it as the sensor turns, and averages out
            // over the turns made within the heading correction's time
            // constant, with which the estimate follows. While the filter
            // settles, or the inclination is not known, the attitude is
            // not to be trusted, and the estimate holds. While the sensor
            // turns slower than `rest_gyro`, nothing tells the two apart
            // (neither turns against the other): nothing confirms the
            // estimate, and it fades as the reference renews, over
            // `MAG_REFERENCE_TAU` (a magnet may have gone, or a wrong
            // estimate been learned; a field that then fails the gate for
            // that long renews the reference). Its step is clipped as the
            // reference's: a single reading moves it by at most the
            // fraction of the reference's length that the heading
            // correction takes in one step.
            if !turning {
                self.hard_iron *= 1.0 - alpha;
            } else if known {
                // In the sensor frame: the corrected reading (the field
                // rotated back) scaled along, and the vertical difference
                // along up (the attitude matrix's third row).
                let along = offset.x / horizontal;
                let Quat { w, x, y, z } = attitude;
                let up = Cvec3::new(
                    2.0 * (x * z - w * y),
                    2.0 * (y * z + w * x),
                    1.0 - 2.0 * (x * x + y * y),
                );
                // The disagreement of the reading itself: the corrected
                // field's, plus the part of the estimate taken off.
                let step = corrected * along + up * (offset.y - field.z * along)
                    - self.hard_iron * (1.0 - taken);
                let estimate = self.hard_iron + step * (fraction * pull);
                let limit = MAX_HARD_IRON * length;
                let bound = limit * limit;
                // NaN and infinity fail too (a bound that overflows holds
                // the estimate).
                if bound <= f32::MAX && estimate.norm_squared() <= bound {
                    self.hard_iron = estimate;
                }
            }
            if !inside {
                if confirmed {
                    // Finite, so that JSON holds it.
                    self.mag_shut = (self.mag_shut + dt).min(f32::MAX);
                }
                return None;
            }
            // A field that passes takes back as much shut time as it
            // lasts, no more: a few fields that pass amid a minute of shut
            // gate (a disturbance or a wrong reference that agrees with
            // them by chance) do not confirm the reference, and the
            // renewal comes as late as the fields that passed, not a minute
            // after them.
            self.mag_shut = max(self.mag_shut - dt, 0.0);
        }
        // The field's angle east of north; turning by it about +z brings
        // it to north.
        let error = float::atan2(field.x, field.y);
        let turn = Quat::from_rotation_z(error * fraction);
        self.correction = (turn * self.correction).normalize();
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

    /// The reference field in the earth frame as (horizontal, vertical, 0).
    #[inline]
    fn mag_reference(&self) -> Cvec3 {
        let [horizontal, vertical] = self.mag_reference;
        Cvec3::new(horizontal, vertical, 0.0)
    }
}

/// `acc` if it is a usable specific force for `dt` seconds: finite, not
/// zero (free fall, or a bus that read zeros: no direction), and not so
/// far from gravity that this one sample alone would take the
/// accelerometer average half-way out of the `acc_gate`. The average moves
/// by at most `IMPULSE_PEAK * |acc - gravity| * min(dt, tau_acc) /
/// tau_acc`, so the bound is a velocity change within one sample:
/// `acc_gate * gravity * tau_acc / (2 IMPULSE_PEAK)`, 2.3 m/s with the
/// defaults, 66 g in one sample at 285 Hz, 23 g at 100 Hz, 230 g at 1 kHz.
/// A carried sensor changes its velocity that fast only in an impact,
/// whose direction says nothing of the attitude; a glitch (1e30, a
/// swapped byte) is far beyond it. With `dt` of `tau_acc` or more, the
/// bound is about the gate itself. Compared through the norm: the
/// sample's distance from gravity is at least the norms' difference, so
/// this passes a few samples it could have caught, never the reverse of
/// that by more than `2 gravity dt`.
fn plausible_specific_force(acc: Cvec3, dt: f32, p: &FilterParams) -> Option<Cvec3> {
    // The square overflows to infinity or underflows to zero only far
    // outside the bounds below.
    let length = float::sqrt(acc.norm_squared());
    // NaN, infinite, zero, or beyond the largest specific force.
    // (An infinite length passes only an infinite gravity, and then fails
    // the impulse test as NaN.)
    if !(length > 0.0 && length <= MAX_SPECIFIC_FORCE * p.gravity) {
        return None;
    }
    let tau = max(p.tau_acc, 0.0);
    let impulse = (length - p.gravity).abs() * min(dt, tau);
    let bound = p.acc_gate * p.gravity * tau * (0.5 / IMPULSE_PEAK);
    (impulse <= bound).then_some(acc)
}

/// The magnetometer reading `mag`, taken `delay` seconds ago (sensor
/// frame), brought forward by the turn the gyro measures over the delay at
/// the bias-free `rate`: a field fixed to the earth turns in the sensor
/// frame by `-rate * delay` meanwhile. To first order (`mag - turn x mag`,
/// whose length is off by `|turn|^2 / 2`: 0.006 % at 1 rad/s and 11 ms),
/// with each part of the turn clipped to `MAX_DELAY_TURN` (a delay or a
/// rate beyond the parameter's purpose). `delay` is not NaN and `rate` is
/// finite; the result is finite for finite `mag`, except where `mag` is
/// within a factor 2 of `f32::MAX` (its sum may then overflow to
/// infinity, and the field is unusable, as such a reading is in any case).
#[inline]
fn undelayed(mag: Cvec3, rate: Cvec3, delay: f32) -> Cvec3 {
    if delay == 0.0 {
        return mag;
    }
    let largest = max(max(rate.x.abs(), rate.y.abs()), rate.z.abs());
    let turn = if largest * delay.abs() <= MAX_DELAY_TURN {
        rate * delay
    } else {
        // A finite delay, so that no part of the product is 0 * infinity.
        let delay = max(min(delay, f32::MAX), -f32::MAX);
        let clip = |part: f32| max(min(part, MAX_DELAY_TURN), -MAX_DELAY_TURN);
        let turn = rate * delay;
        Cvec3::new(clip(turn.x), clip(turn.y), clip(turn.z))
    };
    mag - turn.cross(mag)
}

/// The length of the horizontal part of `field` (earth frame), if the
/// field can give a heading: finite, with a horizontal part, and neither
/// its rotation nor its length overflowed.
fn horizontal_part(field: Cvec3) -> Option<f32> {
    let horizontal = Cvec3::new(field.x, field.y, 0.0).norm();
    (field.is_finite() && horizontal.is_finite() && horizontal > 0.0).then_some(horizontal)
}

/// `a.min(b)` for operands that are not NaN, as one comparison: on the
/// Cortex-M4F, `f32::min` is a library call (NaN-aware), ten times as many
/// instructions.
#[inline(always)]
fn min(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

/// `a.max(b)` for operands that are not NaN, as [`min`].
#[inline(always)]
fn max(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}

/// The earth's x and y axes in the sensor frame: the first two rows of
/// the matrix of the unit quaternion `q` (sensor to earth).
fn horizontal_axes(q: Quat) -> [Cvec3; 2] {
    let Quat { w, x, y, z } = q;
    [
        Cvec3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ),
        Cvec3::new(
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ),
    ]
}

/// The smallest rotation that takes the unit vector `u` to +z: about the
/// axis `u x z`, by the angle between them; `[1 + u.z, u x z]` normalized
/// (the half-way vector construction). For `u = -z` exactly, a half turn
/// about x.
fn rotation_to_up(u: Cvec3) -> Quat {
    Quat::from_wxyz(1.0 + u.z, u.y, -u.x, 0.0)
        .try_normalize()
        .unwrap_or(Quat::from_wxyz(0.0, 1.0, 0.0, 0.0))
}

#[cfg(test)]
mod tests;
