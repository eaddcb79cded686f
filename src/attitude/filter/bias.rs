//! The gyro bias estimate: a scalar Kalman filter whose variance grows as
//! the bias wanders, which learns the raw gyro at rest and, in motion, the
//! inclination corrections seen in the sensor frame.

use super::min_max::{max, min};
use crate::attitude::low_pass::{butterworth_step, low_pass, smoothing_factor};
use crate::attitude::params::FilterParams;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// The standard deviation of the bias estimate at rest, in rad/s
/// (0.01 °/s): a MEMS gyro's noise density of about 0.01 °/s/√Hz averaged
/// over `tau_bias_rest` (3 s) leaves 0.004 °/s, and the bias moves by
/// about as much again within the low-pass's delay.
const REST_BIAS_SIGMA: f32 = 0.01 * core::f32::consts::PI / 180.0;

/// The time constant, in seconds, over which the variance grows towards a
/// lasting disagreement at rest: twice the rest detector's low-pass, so
/// that the start of a motion, which the detector sees within a few tenths
/// of a second, is over before the estimate learns again, while a bias
/// that jumped at rest (by 1 °/s, say) is learned again within seconds.
const REST_ESCAPE_TAU: f32 = 1.0;

/// A calibrated MEMS gyro's scale and cross-axis errors, as a fraction of
/// the rate (0.1 %: datasheets give 0.5 to 2 % before calibration, and a
/// calibration leaves a tenth of that).
const SCALE_ERROR: f32 = 0.001;

/// The bias estimate, its variance, and the attitude through the
/// accelerometer's low-pass, through which the corrections measure it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct Bias {
    /// The estimate, rad/s, sensor frame.
    pub(super) estimate: Cvec3,
    /// Its variance, (rad/s)^2.
    pub(super) variance: f32,
    /// The earth's x and y axes in the sensor frame (the first two rows of
    /// the attitude's matrix), through the same low-pass as the
    /// accelerometer, and their rates times `tau_acc`.
    pub(super) axes_average: [Cvec3; 2],
    pub(super) axes_rate: [Cvec3; 2],
}

impl Bias {
    /// No bias, as uncertain as `max_bias`, level.
    pub(super) const fn new(max_bias: f32) -> Self {
        Self {
            estimate: Cvec3::ZERO,
            variance: max_bias * max_bias,
            axes_average: [Cvec3::X, Cvec3::Y],
            axes_rate: [Cvec3::ZERO, Cvec3::ZERO],
        }
    }

    /// Sets the estimate to `bias`, clipped to at most `max_bias` long (in
    /// its direction; to zero while `max_bias` is zero, negative or NaN).
    /// A bias with a NaN or infinite component is ignored.
    pub(super) fn set(&mut self, bias: Cvec3, max_bias: f32) {
        if !bias.is_finite() {
            return;
        }
        let max = max_bias.max(0.0);
        self.estimate = if bias.norm() > max {
            bias.try_normalize().map_or(Cvec3::ZERO, |unit| unit * max)
        } else {
            bias
        };
    }

    /// Clips an estimate beyond `max_bias`, left by parameters that were
    /// changed since (NaN fails the test too).
    #[inline]
    pub(super) fn clip(&mut self, max_bias: f32) {
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(self.estimate.norm_squared() <= max_bias * max_bias) {
            self.set(self.estimate, max_bias);
        }
    }

    /// The prediction over `dt` seconds, with `rate` the rest detector's
    /// 0.5 s low-pass of the gyro: the variance grows as the bias wanders
    /// (`bias_drift`), and in motion it is at least what a gyro scale error
    /// makes of the rate: a calibrated gyro's scale and cross-axis errors of
    /// [`SCALE_ERROR`] read a turn at `w` as a bias of `SCALE_ERROR * |w|`
    /// more, which no rest showed. It stays below `max_bias^2`, as the
    /// estimate is clipped to `max_bias` (which also keeps it finite).
    ///
    /// While `resting`, the low-pass reads the bias plus averaged noise,
    /// and the estimate follows it over `tau_bias_rest` while it is within
    /// three standard deviations of the estimate (its variance plus the
    /// low-pass's own, [`REST_BIAS_SIGMA`]^2); the variance then falls
    /// towards that of the low-pass. A low-pass further off is the start
    /// of a motion that the rest detector has not seen yet (it sees one a
    /// tenth of a second or more late), whose readings would move the
    /// estimate by what the sensor turned, and teaches nothing; if the
    /// disagreement lasts, the variance grows towards it over
    /// [`REST_ESCAPE_TAU`], and a bias that really moved at rest is learned
    /// again.
    #[inline]
    pub(super) fn predict(&mut self, rate: Cvec3, resting: bool, dt: f32, p: &FilterParams) {
        let most = p.max_bias * p.max_bias;
        let drifted = self.variance + p.bias_drift * p.bias_drift * dt;
        let offset = rate - self.estimate;
        let disagreement = offset.norm_squared();
        if !resting {
            let scale = SCALE_ERROR * SCALE_ERROR * disagreement;
            self.variance = min(max(drifted, scale), most);
            return;
        }
        self.variance = min(drifted, most);
        let rest = REST_BIAS_SIGMA * REST_BIAS_SIGMA;
        if disagreement <= 9.0 * (self.variance + rest) {
            let alpha = smoothing_factor(dt, p.tau_bias_rest);
            self.set(low_pass(self.estimate, rate, alpha), p.max_bias);
            self.variance += (rest - self.variance) * alpha;
        } else {
            let alpha = smoothing_factor(dt, REST_ESCAPE_TAU);
            self.variance += (min(disagreement, most) - self.variance) * alpha;
        }
    }

    /// Low-passes the earth's horizontal axes in the sensor frame of
    /// `attitude`, as the accelerometer was (its `factors`), starting at
    /// them with the `first` sample.
    #[inline]
    pub(super) fn average_axes(&mut self, attitude: Quat, factors: (f32, f32), first: bool) {
        let axes = horizontal_axes(attitude);
        if first {
            self.axes_average = axes;
        }
        let rows = self.axes_average.iter_mut().zip(&mut self.axes_rate);
        for ((average, rate), axis) in rows.zip(axes) {
            (*average, *rate) = butterworth_step(*average, *rate, axis, factors);
        }
    }

    /// How much the attitude has varied over the last `tau_acc` seconds,
    /// from 0 (a steady attitude) towards 1: the earth's horizontal axes
    /// in the sensor frame, averaged as the accelerometer is, shrink as the
    /// sensor turns about any axis, and their squared lengths' mean falls
    /// from 1.
    #[inline]
    pub(super) fn variety(&self) -> f32 {
        let [ex, ey] = self.axes_average;
        max(1.0 - 0.5 * (ex.norm_squared() + ey.norm_squared()), 0.0)
    }

    /// The update in motion: the inclination correction undid a drift of
    /// `-drift` (a rotation vector in the earth frame) in `dt`, which a
    /// bias error would cause. A correction faster than `max_bias` is
    /// convergence, not bias, and teaches nothing.
    ///
    /// The average that the correction corrects saw the bias through the
    /// accelerometer's low-pass, so the correction is taken to the sensor
    /// frame by the averaged axes: in rotation faster than `1 / tau_acc`
    /// they shrink, and so does what the correction says about the bias.
    /// The gain is a continuous Kalman filter's, `variance / bias_noise^2`
    /// per second (never more than `1 / tau_bias`), and the variance
    /// shrinks by the same fraction, times how much of the bias the axes
    /// see.
    #[inline]
    pub(super) fn learn(&mut self, drift: Cvec3, dt: f32, p: &FilterParams) {
        let rate = drift * (1.0 / dt);
        // NaN fails the test too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(rate.norm() <= p.max_bias) {
            return;
        }
        let [ex, ey] = self.axes_average;
        let error = ex * rate.x + ey * rate.y;
        let seen = 0.5 * (ex.norm_squared() + ey.norm_squared());
        let variance = self.variance;
        let tau = (p.bias_noise * p.bias_noise / variance).max(p.tau_bias);
        // 0 / 0 (no noise, no uncertainty): nothing to learn.
        let alpha = if tau.is_nan() {
            0.0
        } else {
            smoothing_factor(dt, tau)
        };
        self.set(self.estimate - error * alpha, p.max_bias);
        self.variance = variance * (1.0 - alpha * seen);
    }
}

/// The earth's x and y axes in the sensor frame: the first two rows of
/// the matrix of the unit quaternion `q` (sensor to earth).
pub(super) fn horizontal_axes(q: Quat) -> [Cvec3; 2] {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The prediction's variance: while nothing measures the bias it
    /// grows by `bias_drift^2` per second (a random walk), and in motion it
    /// is at least `(0.1 % of the turn rate)^2`, never beyond `max_bias^2`.
    #[test]
    fn the_variance_grows_as_a_random_walk_and_stays_open_in_turns() {
        let p = FilterParams::DEFAULT;
        let mut bias = Bias::new(p.max_bias);
        bias.variance = 0.0;
        for _ in 0..1000 {
            bias.predict(Cvec3::ZERO, false, 0.01, &p);
        }
        let walk = p.bias_drift * p.bias_drift * 10.0;
        assert!(
            (bias.variance - walk).abs() <= 1e-3 * walk,
            "{}",
            bias.variance
        );
        let turn = Cvec3::new(0.0, 6.0, 0.0);
        bias.predict(turn, false, 0.01, &p);
        let floor = (SCALE_ERROR * 6.0) * (SCALE_ERROR * 6.0);
        assert!(
            (bias.variance - floor).abs() <= 1e-6 * floor,
            "{}",
            bias.variance
        );
        bias.predict(Cvec3::new(1e3, 0.0, 0.0), false, 0.01, &p);
        assert_eq!(bias.variance, p.max_bias * p.max_bias);
    }

    #[test]
    fn horizontal_axes_are_the_first_two_rows_of_the_rotation_matrix() {
        for q in [
            Quat::from_rotation_x(0.7) * Quat::from_rotation_z(-2.1),
            Quat::from_euler(crate::EulerRot::ZYX, 1.2, -0.4, 2.9),
            Quat::from_rotation_y(3.0),
        ] {
            let [c0, c1, c2, _] = crate::Matrix4::from_quat(q).cols;
            let rows = [Cvec3::new(c0.x, c1.x, c2.x), Cvec3::new(c0.y, c1.y, c2.y)];
            for (got, want) in horizontal_axes(q).into_iter().zip(rows) {
                assert!(
                    (got - want).norm() < 1e-6,
                    "{q:?}: {got:?} against {want:?}"
                );
            }
        }
    }
}
