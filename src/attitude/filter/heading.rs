//! The heading's magnetic reference and its disturbance gate: which
//! fields may turn the heading towards magnetic north, and how the
//! reference follows the field.

use super::min_max::{max, min};
use crate::attitude::low_pass::smoothing_factor;
use crate::vec::Cvec3;

/// Time constant with which the magnetic reference follows the field, in
/// seconds, and the net time the gate stays shut before the field becomes
/// the reference.
pub(super) const MAG_REFERENCE_TAU: f32 = 60.0;

/// The largest turn about each axis, in radians, by which a magnetometer
/// reading is brought forward over `FilterParams::mag_delay`: beyond it,
/// the first order is more than 3 % off.
const MAX_DELAY_TURN: f32 = 0.25;

/// The reference field and the gate's shut time.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct Heading {
    /// The reference field in the earth frame as (horizontal, vertical);
    /// zero until the first usable field (a usable field has a horizontal
    /// part, so zero is never a reference).
    pub(super) reference: [f32; 2],
    /// Negative until a field has passed the gate (until then the
    /// reference is one sample's, and a field outside the gate replaces
    /// it: the first may have been a glitch); then the net seconds for
    /// which the gate has been shut: up by `dt` for each field it shuts
    /// out, down by `dt` (not below zero) for each it passes.
    pub(super) shut: f32,
}

/// What the gate made of a field.
#[derive(Clone, Copy, Debug)]
pub(super) enum Verdict {
    /// The field became the reference and sets the heading at once: there
    /// was none, or only one sample's that this field disputes.
    Set,
    /// The gate has been shut for a net [`MAG_REFERENCE_TAU`] and the
    /// inclination is known: the field is to become the reference
    /// ([`Heading::renew`]) and correct the heading.
    Renew,
    /// The reference followed the field.
    Follow {
        /// The field less the reference before it moved.
        offset: Cvec3,
        /// The share of the reference's step taken: 1, or less for a
        /// field further off than the reference's length.
        pull: f32,
        /// The reference's smoothing factor over the sample.
        alpha: f32,
        /// The field passed the gate and corrects the heading.
        inside: bool,
    },
}

impl Heading {
    /// No reference yet.
    pub(super) const fn new() -> Self {
        Self {
            reference: [0.0; 2],
            shut: -1.0,
        }
    }

    /// The reference field in the earth frame as (horizontal, vertical, 0).
    #[inline]
    pub(super) fn reference(&self) -> Cvec3 {
        let [horizontal, vertical] = self.reference;
        Cvec3::new(horizontal, vertical, 0.0)
    }

    /// Judges the field `seen` (horizontal, vertical, 0), of the reading
    /// `mag`, against the reference of length `length` with the gate's
    /// radius `radius`, `dt` seconds after the previous sample, and moves
    /// the reference; `known` while the inclination is.
    ///
    /// A field passes while it is within `radius` of the reference, and
    /// the reading itself is longer than `radius`: a weaker one is, for all
    /// the gate can tell, zero, and its direction once the hard-iron
    /// estimate is taken off is the estimate's. The reference follows the
    /// field over [`MAG_REFERENCE_TAU`], but no faster than it would a
    /// field its own length away: a single reading, however far off,
    /// moves it by at most that fraction of its length, while a new
    /// environment (rarely further off than the earth's field itself) is
    /// followed as before. A field that passes takes back as much shut
    /// time as it lasts, no more, so that a few that agree by chance amid
    /// a minute of shut gate do not put the renewal off. Shut time is
    /// kept finite, so that JSON holds it.
    #[inline]
    pub(super) fn gate(
        &mut self,
        seen: Cvec3,
        mag: Cvec3,
        length: f32,
        radius: f32,
        known: bool,
        dt: f32,
    ) -> Verdict {
        let reference = self.reference();
        // Finite: seen and reference are, and far below f32::MAX apart in
        // each component. Its norm may overflow to infinity.
        let offset = seen - reference;
        let distance = offset.norm();
        let inside = distance <= radius && mag.norm_squared() > radius * radius;
        let confirmed = self.shut >= 0.0;
        if length == 0.0 || !(inside || confirmed) {
            self.reference = [seen.x, seen.y];
            return Verdict::Set;
        }
        if !inside && self.shut >= MAG_REFERENCE_TAU && known {
            return Verdict::Renew;
        }
        let pull = if distance > length {
            length / distance
        } else {
            1.0
        };
        let alpha = smoothing_factor(dt, MAG_REFERENCE_TAU);
        let moved = reference + offset * (alpha * pull);
        self.reference = [moved.x, moved.y];
        if !inside {
            if confirmed {
                self.shut = min(self.shut + dt, f32::MAX);
            }
        } else {
            self.shut = max(self.shut - dt, 0.0);
        }
        Verdict::Follow {
            offset,
            pull,
            alpha,
            inside,
        }
    }

    /// The field `seen` becomes the reference, and the gate opens.
    #[inline]
    pub(super) fn renew(&mut self, seen: Cvec3) {
        self.reference = [seen.x, seen.y];
        self.shut = 0.0;
    }
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
pub(super) fn undelayed(mag: Cvec3, rate: Cvec3, delay: f32) -> Cvec3 {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reading_is_brought_forward_by_at_most_a_quarter_radian() {
        let north = Cvec3::new(0.0, 1.0, 0.0);
        // 1 rad/s about x over 10 ms: -0.01 rad about x, to first order.
        let near = undelayed(north, Cvec3::new(1.0, 0.0, 0.0), 0.01);
        assert!(
            (near - Cvec3::new(0.0, 1.0, -0.01)).norm() < 1e-7,
            "{near:?}"
        );
        // A gyro that lags: the reading is taken back instead.
        let back = undelayed(north, Cvec3::new(1.0, 0.0, 0.0), -0.01);
        assert!(
            (back - Cvec3::new(0.0, 1.0, 0.01)).norm() < 1e-7,
            "{back:?}"
        );
        // 10 rad/s over a second, and beyond: a quarter radian.
        for (rate, delay) in [
            (Cvec3::new(10.0, 0.0, 0.0), 1.0),
            (Cvec3::new(1e30, 0.0, 0.0), f32::MAX),
            (Cvec3::new(-1e30, 0.0, 0.0), -f32::MAX),
            (Cvec3::new(1e-30, 0.0, 0.0), f32::INFINITY),
        ] {
            let far = undelayed(north, rate, delay);
            assert!((far - Cvec3::new(0.0, 1.0, -0.25)).norm() < 1e-6, "{far:?}");
        }
        // No rate, no turn, whatever the delay.
        for delay in [f32::INFINITY, f32::NEG_INFINITY, f32::MAX] {
            assert_eq!(undelayed(north, Cvec3::ZERO, delay), north);
        }
    }
}
