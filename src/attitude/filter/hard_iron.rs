//! The hard-iron estimate: the field fixed to the sensor (a magnet, or a
//! magnetized part, carried with it), which the calibration cannot know,
//! learned while the sensor turns and taken off each reading.

use crate::float;
use crate::quat::Quat;
use crate::vec::Cvec3;

/// The largest estimate, in units of the reference field's length. A
/// magnet that swamps the earth's field twice over leaves no heading to
/// measure (a few percent of error in its estimate is as large as the
/// horizontal field); the bound also keeps the estimate finite whatever
/// fields were taken for the reference.
const MAX_HARD_IRON: f32 = 2.0;

/// The estimate, in the magnetometer's unit and the sensor frame.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct HardIron {
    pub(super) estimate: Cvec3,
}

/// A magnetometer reading with the estimate taken off.
#[derive(Clone, Copy, Debug)]
pub(super) struct Reading {
    /// In the sensor frame.
    corrected: Cvec3,
    /// In the earth frame.
    pub(super) field: Cvec3,
    /// The length of the field's horizontal part.
    horizontal: f32,
    /// The share of the estimate taken off.
    taken: f32,
}

impl Reading {
    /// The field as the reference holds one: (horizontal, vertical, 0).
    #[inline]
    pub(super) fn seen(&self) -> Cvec3 {
        Cvec3::new(self.horizontal, self.field.z, 0.0)
    }
}

impl HardIron {
    /// No field fixed to the sensor.
    pub(super) const fn new() -> Self {
        Self {
            estimate: Cvec3::ZERO,
        }
    }

    /// The reading `mag` with the estimate taken off, in the earth frame
    /// of `attitude`, if it can give a heading. The estimate is taken off
    /// while it is longer than the gate's `radius`, in full from twice
    /// that: a smaller one lets the field pass the gate as it is, and is
    /// the calibration's residual error, which turns with the sensor and
    /// so averages out of the heading, where an estimate of it, wandering
    /// with the attitudes of the last `tau_mag` seconds, would not. A
    /// reading that is usable as it is but not once the estimate is taken
    /// off (an estimate grown beyond any field, after huge glitches were
    /// taken for the reference) starts the estimate over.
    #[inline]
    pub(super) fn take_off(&mut self, mag: Cvec3, attitude: Quat, radius: f32) -> Option<Reading> {
        let strength = self.estimate.norm_squared();
        let least = if radius > 0.0 { radius } else { 0.0 };
        let taken = if strength > 4.0 * least * least {
            1.0
        } else if strength > least * least {
            float::sqrt(strength) / least - 1.0
        } else {
            0.0
        };
        let corrected = mag - self.estimate * taken;
        let field = attitude * corrected;
        if let Some(horizontal) = horizontal_part(field) {
            return Some(Reading {
                corrected,
                field,
                horizontal,
                taken,
            });
        }
        let raw = self.forget(mag, attitude)?;
        Some(Reading { taken, ..raw })
    }

    /// Starts over from zero, if the reading `mag` can give a heading as it
    /// is (in the earth frame of `attitude`); returns the reading then.
    #[inline]
    pub(super) fn forget(&mut self, mag: Cvec3, attitude: Quat) -> Option<Reading> {
        let field = attitude * mag;
        let horizontal = horizontal_part(field)?;
        self.estimate = Cvec3::ZERO;
        Some(Reading {
            corrected: mag,
            field,
            horizontal,
            taken: 0.0,
        })
    }

    /// Fades over the reference's time constant (its smoothing factor
    /// `alpha`) while nothing confirms the estimate: a sensor that turns
    /// slower than `rest_gyro` cannot tell a field fixed to it from one
    /// fixed to the earth (neither turns against the other); a magnet may
    /// have gone, or a wrong estimate been learned.
    #[inline]
    pub(super) fn fade(&mut self, alpha: f32) {
        self.estimate *= 1.0 - alpha;
    }

    /// Learns from `reading`, whose field is `offset` from the reference
    /// of length `length` (earth frame), with the `weight` of the heading
    /// correction's step. It low-passes, in the sensor frame of
    /// `attitude`, the part of the reading's disagreement with the
    /// reference that no heading error explains: in the earth frame, the
    /// difference of the horizontal parts along the field's own
    /// horizontal direction, and of the vertical parts (a heading error
    /// turns the field about the vertical, which changes neither). A field
    /// fixed to the sensor stays put in that frame and is learned; one
    /// fixed to the earth turns in it as the sensor turns, and averages
    /// out. A step that would take the estimate beyond `MAX_HARD_IRON`
    /// times the reference's length is not taken (NaN and infinity fail
    /// too, and a bound that overflows holds the estimate).
    #[inline]
    pub(super) fn learn(
        &mut self,
        reading: &Reading,
        offset: Cvec3,
        weight: f32,
        attitude: Quat,
        length: f32,
    ) {
        // In the sensor frame: the corrected reading (the field rotated
        // back) scaled along, and the vertical difference along up (the
        // attitude matrix's third row).
        let along = offset.x / reading.horizontal;
        let Quat { w, x, y, z } = attitude;
        let up = Cvec3::new(
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        );
        // The disagreement of the reading itself: the corrected field's,
        // plus the part of the estimate taken off.
        let step = reading.corrected * along + up * (offset.y - reading.field.z * along)
            - self.estimate * (1.0 - reading.taken);
        let estimate = self.estimate + step * weight;
        let limit = MAX_HARD_IRON * length;
        let bound = limit * limit;
        if bound <= f32::MAX && estimate.norm_squared() <= bound {
            self.estimate = estimate;
        }
    }
}

/// The length of the horizontal part of `field` (earth frame), if the
/// field can give a heading: finite, with a horizontal part, and neither
/// its rotation nor its length overflowed.
fn horizontal_part(field: Cvec3) -> Option<f32> {
    let horizontal = Cvec3::new(field.x, field.y, 0.0).norm();
    (field.is_finite() && horizontal.is_finite() && horizontal > 0.0).then_some(horizontal)
}
