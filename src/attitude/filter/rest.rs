//! The rest detector of the [`OrientationFilter`](super::OrientationFilter):
//! while the sensor lies still, the gyro reads its bias.

use super::gyro::HALF_TURN_SQUARED;
use super::inclination::MAX_SPECIFIC_FORCE;
use crate::attitude::low_pass::{low_pass, smoothing_factor};
use crate::attitude::params::FilterParams;
use crate::vec::Cvec3;

/// Time constant of the low-passes behind rest detection, in seconds.
const REST_LOW_PASS_TAU: f32 = 0.5;

/// Low-passes of the raw gyro and accelerometer in the sensor frame, and
/// how long both samples have stayed close to them: at rest once that has
/// lasted `rest_time` (with the thresholds of [`FilterParams`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub(super) struct RestDetector {
    gyro: Cvec3,
    acc: Cvec3,
    /// Seconds that both conditions have held; negative before the first
    /// sample.
    time: f32,
}

impl RestDetector {
    /// A detector that starts its low-passes at the first sample.
    pub(super) const fn new() -> Self {
        Self {
            // Started by the first sample (a negative time). Finite, so
            // that every serde format holds it.
            gyro: Cvec3::ZERO,
            acc: Cvec3::ZERO,
            time: -1.0,
        }
    }

    /// A detector whose low-passes start at the sample `gyr`, `acc`, with
    /// no stillness counted yet.
    #[inline]
    const fn started_at(gyr: Cvec3, acc: Cvec3) -> Self {
        Self {
            gyro: gyr,
            acc,
            time: 0.0,
        }
    }

    /// Takes one sample (gyro `gyr`, accelerometer `acc`, both finite, `acc`
    /// not zero, `dt` seconds after the previous one): still if the gyro is within
    /// `rest_gyro` of its low-pass, the low-pass is below `max_bias`, and
    /// the accelerometer is within `rest_acc` of gravity of its own.
    #[inline]
    pub(super) fn update(&mut self, gyr: Cvec3, acc: Cvec3, dt: f32, p: &FilterParams) {
        // Before the first sample, or with a gyro low-pass beyond half a
        // turn per `dt` (no usable reading at this sample rate is; it is
        // left from readings at a far shorter `dt`, 1e23 rad/s at 1e-26 s,
        // which would take half a minute to decay below `max_bias` and
        // hide rest meanwhile): the low-passes start at this sample.
        // NaN fails the tests too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(self.time >= 0.0 && (self.gyro * dt).norm_squared() <= HALF_TURN_SQUARED) {
            *self = Self::started_at(gyr, acc);
        }
        let alpha = smoothing_factor(dt, REST_LOW_PASS_TAU);
        let gyro = low_pass(self.gyro, gyr, alpha);
        let acc_lp = low_pass(self.acc, acc, alpha);
        // Beyond the largest specific force the filter takes (left by
        // parameters that were changed since: a low-pass of samples near
        // a `gravity` of 1e18 would take over 20 s to forget them, and
        // hide rest meanwhile), or overflowed: the low-passes restart at
        // this sample.
        let bound = MAX_SPECIFIC_FORCE * p.gravity;
        let length_squared = acc_lp.norm_squared();
        // NaN fails the test too; `bound * bound` may overflow to
        // infinity, the first test catches an overflowed low-pass.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(length_squared <= f32::MAX && length_squared <= bound * bound) {
            *self = Self::started_at(gyr, acc);
            return;
        }
        let still = within(gyr - gyro, p.rest_gyro)
            && within(gyro, p.max_bias)
            && within(acc - acc_lp, p.rest_acc * p.gravity);
        *self = Self {
            gyro,
            acc: acc_lp,
            // Finite, so that JSON holds it.
            time: if still {
                (self.time + dt).min(f32::MAX)
            } else {
                0.0
            },
        };
    }

    /// `true` once the sensor has been still for `rest_time` seconds.
    #[inline]
    pub(super) fn is_resting(&self, p: &FilterParams) -> bool {
        self.time >= p.rest_time
    }

    /// The gyro's 0.5 s low-pass, rad/s: at rest, the bias plus averaged
    /// noise; in motion, the rate over the last half second.
    #[inline]
    pub(super) fn rate(&self) -> Cvec3 {
        self.gyro
    }
}

/// `|v| <= bound`, compared through the squares (a norm needs a square
/// root and a rescaling the comparison does not): false for a negative or
/// NaN `bound` and a NaN `v`; a `bound` whose square overflows holds every
/// `v`, as an infinite one does.
#[inline]
fn within(v: Cvec3, bound: f32) -> bool {
    bound >= 0.0 && v.norm_squared() <= bound * bound
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f32 = 0.01;

    fn gravity() -> Cvec3 {
        Cvec3::new(0.0, 0.0, FilterParams::DEFAULT.gravity)
    }

    #[test]
    fn within_compares_the_length_with_the_bound() {
        let v = Cvec3::new(3.0, 4.0, 0.0);
        assert!(within(v, 5.0) && within(v, 5.5) && !within(v, 4.99));
        assert!(within(Cvec3::ZERO, 0.0) && !within(Cvec3::ZERO, -1.0));
        assert!(!within(v, f32::NAN) && !within(Cvec3::NAN, 10.0));
        assert!(within(v, f32::INFINITY) && within(Cvec3::new(1e30, 0.0, 0.0), 1e20));
        assert!(!within(Cvec3::new(1e30, 0.0, 0.0), 1e15));
    }

    #[test]
    fn rest_begins_after_rest_time_of_stillness() {
        let p = FilterParams::DEFAULT;
        let mut rest = RestDetector::new();
        let bias = Cvec3::new(0.01, -0.01, 0.005);
        let steps = (p.rest_time / DT) as u32;
        for _ in 0..steps - 1 {
            rest.update(bias, gravity(), DT, &p);
        }
        assert!(!rest.is_resting(&p));
        for _ in 0..2 {
            rest.update(bias, gravity(), DT, &p);
        }
        assert!(rest.is_resting(&p));
    }

    #[test]
    fn a_steady_turn_faster_than_max_bias_is_no_rest() {
        let p = FilterParams::DEFAULT;
        let mut rest = RestDetector::new();
        let turn = Cvec3::new(0.0, 0.0, 2.0 * p.max_bias);
        for _ in 0..1000 {
            rest.update(turn, gravity(), DT, &p);
        }
        assert!(!rest.is_resting(&p));
    }

    /// Accelerometer noise well inside `rest_acc` of gravity (here 0.2 m/s²
    /// against 0.05 g) is still rest; the same gyro with a jolt of twice
    /// that fraction is not.
    #[test]
    fn accelerometer_noise_within_rest_acc_is_rest() {
        let p = FilterParams::DEFAULT;
        let mut rest = RestDetector::new();
        for i in 0..1000 {
            let noise = if i % 2 == 0 { 0.2 } else { -0.2 };
            rest.update(Cvec3::ZERO, gravity() + Cvec3::new(noise, 0.0, 0.0), DT, &p);
        }
        assert!(rest.is_resting(&p));
        let jolt = Cvec3::new(2.0 * p.rest_acc * p.gravity, 0.0, 0.0);
        rest.update(Cvec3::ZERO, gravity() + jolt, DT, &p);
        assert!(!rest.is_resting(&p));
    }

    /// Steps of `DT` until the detector sees rest, from `rest`, on a still
    /// sensor.
    fn steps_to_rest(mut rest: RestDetector, p: &FilterParams) -> u32 {
        (1..=10_000)
            .find(|_| {
                rest.update(Cvec3::ZERO, gravity(), DT, p);
                rest.is_resting(p)
            })
            .unwrap_or(u32::MAX)
    }

    /// Low-passes left by readings that no longer fit (a gyro reading of
    /// 1e23 rad/s, usable at a `dt` of 1e-26 s; accelerometer readings
    /// near a `gravity` of 1e18 that the parameters have since given up)
    /// restart at the next sample: rest is seen after `rest_time`, as
    /// from a new detector (a step later where the restart ends the
    /// step), not after the 20 to 30 s they would take to decay.
    #[test]
    fn low_passes_that_no_longer_fit_restart() {
        let p = FilterParams::DEFAULT;
        let fresh = steps_to_rest(RestDetector::new(), &p);
        assert!(fresh <= (p.rest_time / DT) as u32 + 2, "{fresh}");
        let mut spun = RestDetector::new();
        spun.update(Cvec3::new(0.0, 1e23, 0.0), gravity(), 1e-26, &p);
        assert_eq!(steps_to_rest(spun, &p), fresh);
        let mut heavy = RestDetector::new();
        let huge = FilterParams { gravity: 1e18, ..p };
        for _ in 0..10 {
            heavy.update(Cvec3::ZERO, Cvec3::new(0.0, 0.0, 1e18), DT, &huge);
        }
        assert_eq!(steps_to_rest(heavy, &p), fresh + 1);
    }

    /// Low-passes that still fit decay rather than restart: after a turn
    /// at 5 or 300 rad/s, or an average left at 500 g (within the largest
    /// specific force), rest is seen only once they have decayed, seconds
    /// after a new detector would see it.
    #[test]
    fn low_passes_that_fit_decay() {
        let p = FilterParams::DEFAULT;
        let fresh = steps_to_rest(RestDetector::new(), &p);
        // 300 rad/s is 0.95 of half a turn per sample.
        for rate in [5.0, 300.0] {
            let mut turned = RestDetector::new();
            for _ in 0..200 {
                turned.update(Cvec3::new(0.0, 0.0, rate), gravity(), DT, &p);
            }
            let after_turn = steps_to_rest(turned, &p);
            assert!(
                after_turn > fresh + 100,
                "{rate}: {after_turn} against {fresh}"
            );
        }
        let mut heavy = RestDetector::new();
        let strong = FilterParams {
            gravity: 500.0 * p.gravity,
            ..p
        };
        heavy.update(
            Cvec3::ZERO,
            Cvec3::new(0.0, 0.0, strong.gravity),
            DT,
            &strong,
        );
        let after_heavy = steps_to_rest(heavy, &p);
        assert!(after_heavy > fresh + 100, "{after_heavy} against {fresh}");
    }

    #[test]
    fn a_jolt_restarts_the_clock() {
        let p = FilterParams::DEFAULT;
        let mut rest = RestDetector::new();
        for _ in 0..1000 {
            rest.update(Cvec3::ZERO, gravity(), DT, &p);
        }
        assert!(rest.is_resting(&p));
        rest.update(Cvec3::ZERO, gravity() * 1.5, DT, &p);
        assert!(!rest.is_resting(&p));
    }
}
