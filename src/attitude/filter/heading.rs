//! The heading's magnetic reference and its disturbance gate: which
//! fields may turn the heading towards magnetic north, and how the
//! reference follows the field.

use super::min_max::{max, min};
use crate::attitude::low_pass::smoothing_factor;
use crate::quat::Quat;
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

    /// `true` unless the gate has kept fields out for longer, net, than it
    /// has passed them since.
    #[inline]
    pub(super) fn is_open(&self) -> bool {
        self.shut <= 0.0
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

/// The largest turn, in radians, that [`about_vertical`] builds from the
/// series of its half angle's sine and cosine.
const SMALL_TURN: f32 = 1.0 / 16.0;

/// A turn about the vertical (+z): the rotation quaternion
/// `(w, 0, 0, z)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct VerticalTurn {
    w: f32,
    z: f32,
}

impl VerticalTurn {
    /// `self * q`, from the turn's two components: `w q + z (k q)`, where
    /// `k q = (-q.z, -q.y, q.x, q.w)` (w, x, y, z); half the operations of
    /// a general product.
    #[inline]
    pub(super) fn turn(self, q: Quat) -> Quat {
        let Self { w, z } = self;
        Quat::from_wxyz(
            w * q.w - z * q.z,
            w * q.x - z * q.y,
            w * q.y + z * q.x,
            w * q.z + z * q.w,
        )
    }
}

/// The rotation by `angle` radians about the vertical (+z), as
/// [`Quat::from_rotation_z`] gives it. The heading correction's turns, but
/// for the first fields, are small (the heading error times
/// `1 - exp(-dt / tau_mag)`, a few thousandths of a radian): up to
/// [`SMALL_TURN`], the half angle `h` (at most 1/32) gives its sine as
/// `h (1 - h^2 / 6)` and its cosine as `1 - h^2 / 2`, whose first dropped
/// terms, `h^5 / 120` and `h^4 / 24`, are below 2^-24 of them, without the
/// kernel's argument reduction.
#[inline]
pub(super) fn about_vertical(angle: f32) -> VerticalTurn {
    if angle.abs() > SMALL_TURN {
        let q = Quat::from_rotation_z(angle);
        return VerticalTurn { w: q.w, z: q.z };
    }
    let h = angle * 0.5;
    let squared = h * h;
    VerticalTurn {
        w: 1.0 - 0.5 * squared,
        z: h * (1.0 - squared * (1.0 / 6.0)),
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

    /// The series agree with the kernel's rotation to within an ulp or two
    /// up to the largest turn they build, beyond it the kernel builds the
    /// rotation, and the turn of a quaternion is the Hamilton product.
    #[test]
    fn a_small_turn_about_the_vertical_is_the_kernels_rotation() {
        let q = Quat::from_rotation_x(0.7) * Quat::from_rotation_y(-1.9);
        for angle in [
            0.0f32, 1e-30, -3.5e-4, 1e-3, -0.01, 0.0625, -0.0625, 0.07, -2.0, 3.1,
        ] {
            let turn = about_vertical(angle);
            let kernel = Quat::from_rotation_z(angle);
            let apart = (turn.w - kernel.w).abs().max((turn.z - kernel.z).abs());
            assert!(apart <= 2.0 * f32::EPSILON, "{angle}: {turn:?} {kernel:?}");
            let product = kernel * q;
            let turned = turn.turn(q);
            assert!(
                turned.angle_to(product) < 1e-6,
                "{angle}: {turned:?} {product:?}"
            );
        }
        let beyond = about_vertical(0.07);
        let kernel = Quat::from_rotation_z(0.07);
        assert_eq!((beyond.w, beyond.z), (kernel.w, kernel.z));
    }

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
