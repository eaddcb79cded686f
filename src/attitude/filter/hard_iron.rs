//! The hard-iron estimate: the field fixed to the sensor (a magnet, or a
//! magnetized part, carried with it), which the calibration cannot know,
//! learned as the sensor's attitude varies and taken off each reading.

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

    /// The share of the estimate that the gate and the learning take off
    /// a reading: all of it while the gate is `open` (the fields, with it
    /// taken off, have passed, net) or while it is longer than the gate's
    /// `radius`; none while it is within the radius and the gate has kept
    /// fields out. A field fixed to the sensor tilts the heading whatever
    /// its size (by its part across the horizontal field, over the
    /// horizontal field), so a confirmed estimate is taken off whole; a
    /// small one learned while fields were kept out may be the wander of
    /// an estimate that a disturbance, a lagging magnetometer or the
    /// calibration's residual made, and the field as read is judged.
    #[inline]
    pub(super) fn share(&self, radius: f32, open: bool) -> f32 {
        if open || self.estimate.norm_squared() > radius * radius {
            1.0
        } else {
            0.0
        }
    }

    /// While the gate has kept fields out (not `open`), an estimate beyond
    /// the gate's `radius` but within twice it is not confirmed: it may
    /// hold part of a disturbance fixed to the earth, learned over the
    /// attitudes the sensor turned through, which taken off whole would let
    /// that disturbance's fields pass at those attitudes with its heading.
    /// The heading is then turned only by the reading with the share
    /// beyond the radius taken off (none at the radius, all from twice
    /// it), if that passes the gate as well: this reading, in the earth
    /// frame of `attitude`, or `None`. `Some(None)`: the estimate is in that
    /// range and the reading fails the gate against `reference` once only
    /// that share is taken off; `None`: the estimate is confirmed or small,
    /// and the reading of [`share`](Self::share) turns the heading.
    #[inline]
    pub(super) fn unconfirmed(
        &self,
        mag: Cvec3,
        attitude: Quat,
        reference: Cvec3,
        radius: f32,
        open: bool,
    ) -> Option<Option<Cvec3>> {
        let strength = self.estimate.norm_squared();
        if open || !(strength > radius * radius && strength < 4.0 * radius * radius) {
            return None;
        }
        let beyond = float::sqrt(strength) / radius - 1.0;
        let field = attitude * (mag - self.estimate * beyond);
        let Some(horizontal) = horizontal_part(field) else {
            return Some(None);
        };
        let passes = (Cvec3::new(horizontal, field.z, 0.0) - reference).norm() <= radius;
        Some(passes.then_some(field))
    }

    /// The reading `mag` with the share `taken` of the estimate taken off,
    /// in the earth frame of `attitude`, if it can give a heading. A
    /// reading that is usable as it is but not once the estimate is taken
    /// off (an estimate grown beyond any field, after huge glitches were
    /// taken for the reference) starts the estimate over.
    #[inline]
    pub(super) fn take_off(&mut self, mag: Cvec3, attitude: Quat, taken: f32) -> Option<Reading> {
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

    /// Whether a reading whose step the reference takes in the share
    /// `pull` (1, or the reference's length over the reading's distance
    /// from it) could be explained by an estimate: one further from the
    /// reference than `MAX_HARD_IRON + 1` times its length would need an
    /// estimate beyond its bound, and is a glitch (1e30, a register read
    /// unscaled), not a field, which teaches it nothing.
    #[inline]
    pub(super) fn could_explain(&self, pull: f32) -> bool {
        pull * (MAX_HARD_IRON + 1.0) >= 1.0
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
    /// out, but only as far as the sensor's attitude varies. So a step
    /// that would grow the estimate is taken only in the share `growth`
    /// (the attitudes' variety, for a field the gate passed: see
    /// `OrientationFilter::correct_heading`), while one that shrinks it is
    /// taken whole: an estimate that the fields no longer bear out is
    /// unlearned as fast as a kept-out field teaches one. A step that
    /// would take the estimate beyond `MAX_HARD_IRON` times the
    /// reference's length is not taken (NaN and infinity fail too, and a
    /// bound that overflows holds the estimate).
    #[inline]
    pub(super) fn learn(
        &mut self,
        reading: &Reading,
        offset: Cvec3,
        weight: f32,
        growth: f32,
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
        // plus the part of the estimate not taken off.
        let step = reading.corrected * along + up * (offset.y - reading.field.z * along)
            - self.estimate * (1.0 - reading.taken);
        let weight = if step.dot(self.estimate) < 0.0 {
            weight
        } else {
            weight * growth
        };
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The earth's field, level, facing north: (0, 16, -41) µT, whose
    /// reference is (16, -41) and gate radius a tenth of its length.
    const FIELD: Cvec3 = Cvec3::new(0.0, 16.0, -41.0);

    fn reference() -> Cvec3 {
        Cvec3::new(16.0, -41.0, 0.0)
    }

    fn radius() -> f32 {
        0.1 * reference().norm()
    }

    #[test]
    fn a_confirmed_or_strong_estimate_is_taken_off_whole_a_weak_unconfirmed_one_not() {
        let small = HardIron {
            estimate: Cvec3::new(0.0, 0.0, 0.5 * radius()),
        };
        let strong = HardIron {
            estimate: Cvec3::new(0.0, 0.0, 1.2 * radius()),
        };
        assert_eq!(small.share(radius(), true), 1.0);
        assert_eq!(small.share(radius(), false), 0.0);
        assert_eq!(strong.share(radius(), false), 1.0);
        assert_eq!(HardIron::new().share(radius(), false), 0.0);
    }

    /// An unconfirmed estimate between the gate's radius and twice it
    /// turns the heading only through the field with its share beyond the
    /// radius taken off, when that field passes the gate: here 1.5 times
    /// the radius along the vertical, half of it taken off. A reading that
    /// carries the whole estimate passes once half is off only if it lies
    /// within the radius of the reference then; outside that range, or
    /// with the gate open, the estimate is not in question.
    #[test]
    fn an_unconfirmed_estimate_turns_the_heading_by_its_share_beyond_the_radius() {
        let r = radius();
        let h = HardIron {
            estimate: Cvec3::new(0.0, 0.0, 1.5 * r),
        };
        let attitude = Quat::IDENTITY;
        // A magnet of 1.5 r read with the field: half of it left, 0.75 r
        // off the reference, within the radius.
        let read = FIELD + h.estimate;
        let partial = h.unconfirmed(read, attitude, reference(), r, false);
        let want = FIELD + h.estimate * 0.5;
        let field = partial.flatten().expect("passes with half off");
        assert!((field - want).norm() < 1e-4, "{field:?} {want:?}");
        // A reading 2.5 r off along the vertical fails once half is off.
        let far = FIELD + Cvec3::new(0.0, 0.0, 2.5 * r);
        assert_eq!(
            h.unconfirmed(far, attitude, reference(), r, false),
            Some(None)
        );
        // The gate open, or an estimate outside (r, 2r): not in question.
        assert_eq!(h.unconfirmed(read, attitude, reference(), r, true), None);
        for size in [0.9, 2.1] {
            let other = HardIron {
                estimate: Cvec3::new(0.0, 0.0, size * r),
            };
            assert_eq!(
                other.unconfirmed(read, attitude, reference(), r, false),
                None,
                "{size}"
            );
        }
    }

    /// A reading further from the reference than `MAX_HARD_IRON + 1` of
    /// its lengths (its pull below a third) is no field an estimate could
    /// explain; one within it is.
    #[test]
    fn only_a_reading_an_estimate_could_explain_teaches_it() {
        let h = HardIron::new();
        assert!(h.could_explain(1.0) && h.could_explain(0.34));
        assert!(!h.could_explain(0.32) && !h.could_explain(0.0));
    }
}
