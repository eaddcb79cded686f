//! The gyro reading the filter integrates: whether it is usable, whether
//! it is at the sensor's range, and the last usable reading, which stands
//! in for one that is not.

use crate::vec::Cvec3;

/// The square of half a turn, in rad^2: a reading that turns further
/// within one sample aliases (no sampled gyro tells it from a slower turn
/// the other way).
pub(super) const HALF_TURN_SQUARED: f32 = core::f32::consts::PI * core::f32::consts::PI;

/// The fraction of `gyro_range` from which a reading counts as saturated
/// (a sensor at full scale reads its largest code, which scale
/// calibration may move slightly below the range).
const SATURATION: f32 = 0.99;

/// The gyro's state: the last usable reading below the range, in rad/s,
/// bias included.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct Gyro {
    pub(super) last_rate: Cvec3,
}

/// What one gyro reading gives the update.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rate {
    /// The rate to integrate, rad/s, bias included.
    pub(super) rate: Cvec3,
    /// The reading was unusable; the last usable one stands in.
    pub(super) ignored: bool,
    /// The reading is at the range on some axis.
    pub(super) saturated: bool,
    /// The second saturated reading in a row, or a later one: a spin
    /// beyond the range, which the integrated gyro has lost.
    pub(super) spinning: bool,
}

impl Gyro {
    /// No reading yet: the last usable rate is zero.
    pub(super) const fn new() -> Self {
        Self {
            last_rate: Cvec3::ZERO,
        }
    }

    /// Takes the reading `gyr`, `dt` seconds after the previous one, with
    /// the bias estimate `bias` and the sensor's range `range`;
    /// `was_saturated` if the previous reading was at the range.
    ///
    /// A usable reading turns less than half a turn within the sample,
    /// bias taken off (the squares overflow to infinity, and NaN in the
    /// reading or in `dt` fails the test). An unusable one is replaced by
    /// the last usable one: the body's inertia keeps its rate from
    /// changing much within a sample. A single reading at the range amid
    /// slower ones is a glitch, or the first sample of a spin, whose rate
    /// the last reading below the range gives better, and is replaced too;
    /// from the second in a row on, the reading is integrated as it is.
    /// `None` if the last usable reading turns too far as well: `dt` is
    /// NaN, or spans a gap the gyro did not see.
    #[inline]
    pub(super) fn step(
        &mut self,
        gyr: Cvec3,
        bias: Cvec3,
        dt: f32,
        range: f32,
        was_saturated: bool,
    ) -> Option<Rate> {
        let usable = |rate: Cvec3| ((rate - bias) * dt).norm_squared() <= HALF_TURN_SQUARED;
        let ignored = !usable(gyr);
        if ignored && !usable(self.last_rate) {
            return None;
        }
        let saturated = !ignored && {
            let range = SATURATION * range;
            gyr.x.abs() >= range || gyr.y.abs() >= range || gyr.z.abs() >= range
        };
        let spinning = saturated && was_saturated;
        let rate = if ignored || (saturated && !spinning) {
            self.last_rate
        } else {
            gyr
        };
        if !(ignored || saturated) {
            self.last_rate = gyr;
        }
        Some(Rate {
            rate,
            ignored,
            saturated,
            spinning,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const RANGE: f32 = 34.9;

    #[test]
    fn an_unusable_reading_is_replaced_by_the_last_usable_one() {
        let mut gyro = Gyro::new();
        let good = Cvec3::new(0.1, -0.2, 0.3);
        let rate = gyro.step(good, Cvec3::ZERO, 0.01, RANGE, false);
        assert!(rate.is_some_and(|r| r.rate == good && !r.ignored));
        for bad in [Cvec3::NAN, Cvec3::new(0.0, 320.0, 0.0)] {
            let r = gyro.step(bad, Cvec3::ZERO, 0.01, RANGE, false);
            assert!(r.is_some_and(|r| r.rate == good && r.ignored), "{bad:?}");
        }
        // A gap over which even the last rate turns more than half a turn.
        assert!(gyro.step(good, Cvec3::ZERO, 100.0, RANGE, false).is_none());
        assert!(gyro
            .step(good, Cvec3::ZERO, f32::NAN, RANGE, false)
            .is_none());
    }

    #[test]
    fn one_reading_at_the_range_is_a_glitch_and_two_a_spin() {
        let mut gyro = Gyro::new();
        let good = Cvec3::new(0.0, 1.0, 0.0);
        let _ = gyro.step(good, Cvec3::ZERO, 0.001, RANGE, false);
        let full = Cvec3::new(RANGE, 0.0, 0.0);
        let first = gyro.step(full, Cvec3::ZERO, 0.001, RANGE, false);
        assert!(first.is_some_and(|r| r.saturated && !r.spinning && r.rate == good));
        let second = gyro.step(full, Cvec3::ZERO, 0.001, RANGE, true);
        assert!(second.is_some_and(|r| r.spinning && r.rate == full));
        // The last usable rate stays the one below the range.
        assert_eq!(gyro.last_rate, good);
    }
}
