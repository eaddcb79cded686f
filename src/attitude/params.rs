//! [`FilterParams`]: the parameters of the [`OrientationFilter`](super::OrientationFilter),
//! with the physics each default comes from.

/// The parameters of an [`OrientationFilter`](super::OrientationFilter), with their units. One set,
/// [`FilterParams::DEFAULT`], chosen from sensor and motion physics (see the
/// field docs and the README's IMU section), not fitted to any recording.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
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
    /// vertical drifts only 1° in 10 s. The hard-iron estimate (a field
    /// fixed to the sensor, such as a magnet carried with it) follows with
    /// the same time constant the fields the gate keeps out, and those it
    /// passes in the share of the attitude's variety over the last
    /// `tau_acc`: only as the sensor's attitude varies do the fields of a
    /// disturbance fixed to the earth turn in the sensor frame and average
    /// out.
    pub tau_mag: f32,
    /// The shortest time constant, in seconds, with which the gyro bias
    /// follows the corrections during motion (default 20 s): the bias loop
    /// stays well damped only while it is several times `tau_acc`, since a
    /// bias error shows in the corrections only after the accelerometer
    /// average's delay. Infinite: no bias estimation during motion.
    pub tau_bias: f32,
    /// How fast the true gyro bias wanders, as a random walk, in rad/s per
    /// square root of a second (default 5e-5, 0.003 °/s/√s: 0.07 °/s in
    /// ten minutes). A MEMS gyro's bias moves mostly with its temperature,
    /// by 0.01 to 0.03 °/s per kelvin (datasheets), and a carried device
    /// warms by a kelvin or two in its first minutes: 0.01 to 0.06 °/s in
    /// ten minutes, which the default covers. It sets how fast the bias
    /// estimate's uncertainty grows while nothing measures it, and so how
    /// much weight a correction during motion gets (see `bias_noise`): a
    /// larger value lets the leaks of linear acceleration into the
    /// corrections move a bias learned at rest.
    pub bias_drift: f32,
    /// During motion, each inclination correction, seen in the sensor
    /// frame, measures the bias, with this noise density in rad/s per
    /// square root of a hertz (default 0.57 °/s/√Hz, 0.01): a velocity
    /// change of 0.5 m/s leaks about 0.7° of tilt into the accelerometer
    /// average (see `tau_acc`), which the correction takes out over about
    /// `tau_acc`, a rate of about 0.23 °/s correlated over about 3 s: a
    /// density of `sqrt(2 * 3 s) * 0.23 °/s`. The bias follows the
    /// corrections as a Kalman filter does: with the time constant
    /// `bias_noise^2 / variance`, where `variance` is the estimate's
    /// (which starts at `max_bias^2`, falls to about (0.01 °/s)^2 at rest,
    /// grows with `bias_drift`, and in motion stays at least what a gyro
    /// scale error of 0.1 % makes of the rate), but never faster than
    /// `tau_bias`.
    /// Right after a rest the bias is known and motion barely moves it; a
    /// bias that was never seen at rest is learned within minutes.
    /// Infinite: no bias estimation during motion.
    pub bias_noise: f32,
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
    /// the inclination is corrected (and the bias learns from the
    /// correction) only while the averaged specific force is within it of
    /// `gravity`. The current sample is not gated: the correction comes
    /// from the average, and a sample's magnitude says little about the
    /// average's error (in a vertical circle at 1 g, the samples near
    /// gravity all fall at two phases of each turn, where the average's
    /// leak turns the same way). The gate catches a sustained acceleration
    /// with a vertical part (a lift, a climb); a sustained horizontal one
    /// (a car speeding up) changes the magnitude only to second order: at
    /// 0.46 g sideways the averaged vector is tilted 25° before it is 10 %
    /// longer than gravity. No accelerometer-only filter can tell that
    /// from a tilt.
    pub acc_gate: f32,
    /// Magnetic disturbance gate, a fraction of the reference field
    /// (default 0.1): the heading is corrected only while the measured
    /// field, in the earth frame, is within this distance of the reference
    /// field (its horizontal and vertical parts, so a change of the dip
    /// counts as much as a change of strength). The reference is the first
    /// field measured (replaced by the next if that disagrees, until one
    /// agrees), and then follows the measurements with a 60 s time
    /// constant, but no faster than it would follow a field its own length
    /// away, so that a single reading, however far off, barely moves it,
    /// while a new environment is accepted in the end (after 56 s for a
    /// field 30 % stronger, 102 s for one twice as strong; tested). The
    /// filter's hard-iron estimate is taken off the measured field in full
    /// while the gate passes fields with it taken off (net); while the gate
    /// has kept fields out, only an estimate longer than this fraction of
    /// the reference is (see the filter's docs).
    pub mag_gate: f32,
    /// The gyro's full scale in rad/s (default `f32::MAX`: unknown, no
    /// saturation detected for finite readings; finite so that formats
    /// without infinity, such as JSON, can store the parameters). A reading
    /// within 1 % of it on any axis is taken as saturated (a sensor at full
    /// scale reads its largest code, which scale calibration may move
    /// slightly below the range): it has lost the true rate. A single such
    /// reading amid slower ones is taken for a glitch and replaced by the
    /// last reading below the range. From the second in a row on (a spin
    /// beyond the range), the integrated gyro has lost the rotation, so the
    /// filter recovers as at start-up, with time constants that start at
    /// zero and grow back to `tau_acc` and `tau_mag` over `tau_acc` seconds
    /// after the last saturated sample (see [`Diagnostics`](super::Diagnostics)). Set it
    /// to the sensor's range, for instance 2000 °/s, 34.9 rad/s, where
    /// saturation is rare (a spin, a knock). Where the motion exceeds the
    /// range again and again, leave it unset: each saturated sample
    /// restarts the short time constants, and the filter then follows the
    /// accelerometer through linear accelerations (BROAD trial 16 read by
    /// a 350 °/s gyro, 1,011 samples at the range: 6D inclination RMSE
    /// 50° with the range set, 3.5° without).
    pub gyro_range: f32,
    /// How long the magnetometer's readings lag the gyroscope's, in
    /// seconds (default 0: none). A magnetometer that samples slower than
    /// the gyro, holds its last value or averages internally reads the
    /// field of a moment ago; while the sensor turns, that field is turned
    /// against today's by the turn since, which tilts the field's dip and
    /// turns its heading by `rate * mag_delay` (0.6° at 1 rad/s with a
    /// delay of 11 ms). The filter brings each reading forward by the turn
    /// the gyro measured over the delay (to first order, each part of the
    /// turn at most a quarter of a radian). Negative if the gyro lags the
    /// magnetometer (a gyro low-pass). To measure it without a reference,
    /// turn the sensor by hand and find the shift `s` that best fits
    /// `d mag / dt = -(gyr(t - s) - bias) x mag(t)` over the recording
    /// (the repository's `tools/mag_delay.py` does, for BROAD's CSVs);
    /// `docs/attitude.md` gives BROAD's sensor's (11 ms) and what it
    /// changes there.
    #[cfg_attr(feature = "serde", serde(default))]
    pub mag_delay: f32,
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
        bias_drift: 5e-5,
        bias_noise: 0.01,
        tau_bias_rest: 3.0,
        rest_gyro: 0.035,
        max_bias: 0.035,
        rest_acc: 0.05,
        rest_time: 1.5,
        acc_gate: 0.1,
        mag_gate: 0.1,
        gyro_range: f32::MAX,
        mag_delay: 0.0,
    };
}

impl FilterParams {
    /// `true` if any parameter is NaN.
    pub(super) fn has_nan(&self) -> bool {
        [
            self.gravity,
            self.tau_acc,
            self.tau_mag,
            self.tau_bias,
            self.bias_drift,
            self.bias_noise,
            self.tau_bias_rest,
            self.rest_gyro,
            self.max_bias,
            self.rest_acc,
            self.rest_time,
            self.acc_gate,
            self.mag_gate,
            self.gyro_range,
            self.mag_delay,
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
