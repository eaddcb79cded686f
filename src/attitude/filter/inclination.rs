//! The inclination: the accelerometer, averaged in the almost inertial
//! frame of the integrated gyro, and the smallest turn that makes the
//! average point up.

use super::min_max::{max, min};
use crate::attitude::low_pass::butterworth_step;
use crate::attitude::params::FilterParams;
use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// The largest specific force the filter takes, in units of `gravity`:
/// 1000 g, beyond what any accelerometer of an IMU measures (MEMS parts
/// reach 16 to 32 g, shock sensors 200 to 400 g). It bounds the average
/// and its rounding errors (1000 g times 2^-24 is 6e-5 g) whatever `dt`
/// is; a sample's own bound ([`plausible_specific_force`]) is smaller at
/// every sample rate below 4 kHz.
pub(super) const MAX_SPECIFIC_FORCE: f32 = 1000.0;

/// The peak of the Butterworth low-pass's impulse response, times
/// `tau_acc` per unit of impulse: `2 exp(-x) sin(x)` at `x = pi / 4`. A
/// sample that departs from gravity by `a` for `dt` seconds (`dt` at most
/// `tau_acc`) moves the average by at most `IMPULSE_PEAK * a * dt /
/// tau_acc`, about `tau_acc / 4` seconds later.
const IMPULSE_PEAK: f32 = 0.644_794;

/// The accelerometer's second-order Butterworth low-pass in the inertial
/// frame: its output, and its rate of change times `tau_acc`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct Inclination {
    pub(super) average: Cvec3,
    pub(super) rate: Cvec3,
}

impl Inclination {
    /// Started by the first usable sample.
    pub(super) const fn new() -> Self {
        Self {
            average: Cvec3::ZERO,
            rate: Cvec3::ZERO,
        }
    }

    /// As if at rest: the average at gravity, straight up.
    pub(super) const fn at_rest(gravity: f32) -> Self {
        Self {
            average: Cvec3::new(0.0, 0.0, gravity),
            rate: Cvec3::ZERO,
        }
    }

    /// Takes the specific force `inertial` (the sample in the inertial
    /// frame), the `first` sample restarting the low-pass there, with the
    /// low-pass's `factors` (see [`butterworth`](crate::attitude::low_pass::butterworth)).
    /// Returns the turn that makes the average point up in the earth
    /// frame, seen through `correction`; `None` if the average is more
    /// than `acc_gate` from gravity (a sustained acceleration with a
    /// vertical part), or beyond the largest specific force (left by
    /// parameters that were changed since, or NaN: the low-pass restarts
    /// at this sample).
    #[inline]
    pub(super) fn step(
        &mut self,
        inertial: Cvec3,
        correction: Quat,
        factors: (f32, f32),
        first: bool,
        p: &FilterParams,
    ) -> Option<Quat> {
        if first {
            *self = Self {
                average: inertial,
                rate: Cvec3::ZERO,
            };
        }
        let (average, rate) = butterworth_step(self.average, self.rate, inertial, factors);
        let length = average.norm();
        // NaN fails the test too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        if !(length <= MAX_SPECIFIC_FORCE * p.gravity) {
            *self = Self {
                average: inertial,
                rate: Cvec3::ZERO,
            };
            return None;
        }
        *self = Self { average, rate };
        if (length - p.gravity).abs() > p.acc_gate * p.gravity {
            return None;
        }
        let up = (correction * average).try_normalize()?;
        Some(rotation_to_up(up))
    }
}

/// `acc` if it is a usable specific force for `dt` seconds: finite, not
/// zero (free fall, or a bus that read zeros: no direction), and not so
/// far from gravity that this one sample alone would take the average
/// half-way out of the `acc_gate`. The average moves by at most
/// `IMPULSE_PEAK * |acc - gravity| * min(dt, tau_acc) / tau_acc`, so the
/// bound is a velocity change within one sample: `acc_gate * gravity *
/// tau_acc / (2 IMPULSE_PEAK)`, 2.3 m/s with the defaults (66 g in one
/// sample at 285 Hz, 23 g at 100 Hz, 230 g at 1 kHz). A carried sensor
/// changes its velocity that fast only in an impact, whose direction says
/// nothing of the attitude. Compared through the norm: the sample's
/// distance from gravity is at least the norms' difference, so this
/// passes a few samples it could have caught, never the reverse of that
/// by more than `2 gravity dt`.
pub(super) fn plausible_specific_force(acc: Cvec3, dt: f32, p: &FilterParams) -> Option<Cvec3> {
    // The square overflows to infinity or underflows to zero only far
    // outside the bounds below.
    let length = float::sqrt(acc.norm_squared());
    // NaN, infinite, zero, or beyond the largest specific force (an
    // infinite length passes only an infinite gravity, and then fails the
    // impulse test as NaN).
    if !(length > 0.0 && length <= MAX_SPECIFIC_FORCE * p.gravity) {
        return None;
    }
    let tau = max(p.tau_acc, 0.0);
    let impulse = (length - p.gravity).abs() * min(dt, tau);
    let bound = p.acc_gate * p.gravity * tau * (0.5 / IMPULSE_PEAK);
    (impulse <= bound).then_some(acc)
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
mod tests {
    use super::*;

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

    /// The impulse peak is the Butterworth's: the largest value of its
    /// impulse response, `2 exp(-x) sin(x)`, at `x = pi / 4`.
    #[test]
    fn the_impulse_peak_is_the_largest_response() {
        let response = |x: f64| 2.0 * (-x).exp() * x.sin();
        let peak = response(core::f64::consts::FRAC_PI_4);
        assert!((peak - f64::from(IMPULSE_PEAK)).abs() < 1e-6, "{peak}");
        for i in 1..400 {
            assert!(response(f64::from(i) * 0.01) <= peak + 1e-12);
        }
    }

    /// With the defaults at 285 Hz, a reading 66 g from gravity passes and
    /// one 67 g from it does not (the bound is a velocity change of
    /// 2.3 m/s within the sample); zero, NaN and infinite readings never
    /// pass.
    #[test]
    fn a_sample_beyond_a_plausible_impulse_is_not_used() {
        let p = FilterParams::DEFAULT;
        let dt = 0.0035;
        let up = |g: f32| Cvec3::new(0.0, 0.0, g * p.gravity);
        assert!(plausible_specific_force(up(67.0), dt, &p).is_some());
        assert!(plausible_specific_force(up(68.0), dt, &p).is_none());
        for bad in [Cvec3::ZERO, Cvec3::NAN, Cvec3::new(f32::INFINITY, 0.0, 0.0)] {
            assert!(plausible_specific_force(bad, dt, &p).is_none(), "{bad:?}");
        }
    }
}
