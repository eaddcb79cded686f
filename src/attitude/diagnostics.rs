//! [`Diagnostics`]: what the [`OrientationFilter`](super::OrientationFilter)
//! did with the last sample, for a firmware to log.

/// The state flags and internal errors of an
/// [`OrientationFilter`](super::OrientationFilter) after its last update,
/// from [`diagnostics`](super::OrientationFilter::diagnostics). `Copy`,
/// 16 bytes.
///
/// # Examples
///
/// ```
/// use rigtform::attitude::{FilterParams, OrientationFilter};
/// use rigtform::Cvec3;
/// let mut f = OrientationFilter::new(FilterParams::DEFAULT);
/// let g = Cvec3::new(0.0, 0.0, 9.81);
/// f.update(Cvec3::ZERO, g, 0.01);
/// assert!(f.diagnostics().initialising);
/// // Free fall: no direction to correct with.
/// f.update(Cvec3::ZERO, Cvec3::ZERO, 0.01);
/// assert!(f.diagnostics().acc_ignored);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[repr(C)]
pub struct Diagnostics {
    /// The inclination correction's angle in the last update, in radians:
    /// how far the accelerometer average was from up (0 when ignored).
    pub acc_error: f32,
    /// The heading error the magnetometer saw in the last update, in
    /// radians (east of magnetic north is positive; 0 when ignored or in
    /// 6D), to 16 significant bits: a relative error of at most 2^-16
    /// (below 1.2e-38 rad, where `f32` has fewer bits, an absolute error of
    /// at most 2^-142 rad).
    pub mag_error: f32,
    /// Start-up: since the first usable accelerometer sample, less than
    /// `tau_acc` seconds have passed, and the corrections use the time
    /// passed as their time constant (the average of every sample so far)
    /// instead of `tau_acc` and `tau_mag`.
    pub initialising: bool,
    /// The same short time constants after the gyro stayed at its range
    /// (`FilterParams::gyro_range`) for two samples or more: the integrated
    /// gyro is no longer to be trusted, so the accelerometer and
    /// magnetometer take over quickly.
    pub recovering: bool,
    /// The gyro reading of the last update reached `gyro_range` on some axis.
    pub gyro_saturated: bool,
    /// The gyro reading of the last update was unusable (NaN, infinite, or
    /// more than half a turn within the sample: a glitch): the filter
    /// integrated the last usable reading instead, and the update returned
    /// NaN.
    pub gyro_ignored: bool,
    /// The rest detector sees the sensor at rest.
    pub resting: bool,
    /// The accelerometer made no inclination correction in the last update:
    /// no usable vector (NaN, infinite, zero, or a specific force no carried
    /// sensor feels within one sample; see the filter's "Bad input"), or
    /// its average outside `acc_gate` of gravity.
    pub acc_ignored: bool,
    /// A magnetometer sample made no heading correction in the last update:
    /// no usable field, or outside the disturbance gate (`mag_gate`).
    /// `false` in 6D.
    pub mag_ignored: bool,
}

/// The flags of [`Diagnostics`] and the filter's own "inclination set"
/// flag, one bit each in the low byte; the top 24 bits hold
/// [`Diagnostics::mag_error`] as the top 24 bits of its `f32` (rounded:
/// 16 significant bits, a relative error of at most 2^-16; for subnormal
/// errors an absolute one of at most 2^-142), so that the filter's state
/// holds both in one word.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub(super) struct Flags(u32);

impl Flags {
    /// [`Diagnostics::initialising`].
    pub(super) const INITIALISING: u32 = 1;
    /// [`Diagnostics::recovering`].
    pub(super) const RECOVERING: u32 = 1 << 1;
    /// [`Diagnostics::gyro_saturated`].
    pub(super) const GYRO_SATURATED: u32 = 1 << 2;
    /// [`Diagnostics::gyro_ignored`].
    pub(super) const GYRO_IGNORED: u32 = 1 << 3;
    /// [`Diagnostics::resting`].
    pub(super) const RESTING: u32 = 1 << 4;
    /// [`Diagnostics::acc_ignored`].
    pub(super) const ACC_IGNORED: u32 = 1 << 5;
    /// [`Diagnostics::mag_ignored`].
    pub(super) const MAG_IGNORED: u32 = 1 << 6;
    /// The filter's inclination has been set (from an accelerometer
    /// sample, or a starting attitude); not a diagnostic.
    pub(super) const INITIALIZED: u32 = 1 << 7;
    /// The bits of the flags; the others hold the heading error.
    const BITS: u32 = 0xff;

    /// The flags in `bits` set, the others clear, and no heading error.
    #[inline]
    pub(super) const fn new(bits: u32) -> Self {
        Self(bits & Self::BITS)
    }

    /// Whether the flag `bit` (one of the constants) is set.
    #[inline]
    pub(super) const fn get(self, bit: u32) -> bool {
        self.0 & bit != 0
    }

    /// Sets the flag `bit` (one of the constants) to `on`.
    #[inline]
    pub(super) fn set(&mut self, bit: u32, on: bool) {
        self.0 = (self.0 & !bit) | (bit & u32::from(on).wrapping_neg());
    }

    /// Keeps `error` as [`Diagnostics::mag_error`], rounded to its top 24
    /// bits. `error` is finite (a heading error, or 0), so that rounding
    /// cannot reach the bit patterns of infinity or NaN.
    #[inline]
    pub(super) fn set_mag_error(&mut self, error: f32) {
        let rounded = error.to_bits().wrapping_add(Self::BITS.div_ceil(2));
        self.0 = (rounded & !Self::BITS) | (self.0 & Self::BITS);
    }

    /// The flags as [`Diagnostics`], with the inclination error.
    #[inline]
    pub(super) const fn diagnostics(self, acc_error: f32) -> Diagnostics {
        Diagnostics {
            acc_error,
            mag_error: f32::from_bits(self.0 & !Self::BITS),
            initialising: self.get(Self::INITIALISING),
            recovering: self.get(Self::RECOVERING),
            gyro_saturated: self.get(Self::GYRO_SATURATED),
            gyro_ignored: self.get(Self::GYRO_IGNORED),
            resting: self.get(Self::RESTING),
            acc_ignored: self.get(Self::ACC_IGNORED),
            mag_ignored: self.get(Self::MAG_IGNORED),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_heading_error_is_kept_to_sixteen_bits_beside_the_flags() {
        let flags = Flags::RESTING | Flags::INITIALIZED | Flags::MAG_IGNORED;
        for error in [0.0, 1e-30, -0.05, 0.1, -1.0, core::f32::consts::PI] {
            let mut f = Flags::new(flags);
            f.set_mag_error(error);
            let kept = f.diagnostics(0.0).mag_error;
            assert!(
                (kept - error).abs() <= error.abs() * 2f32.powi(-16),
                "{error} kept as {kept}"
            );
            // The flags are untouched, and setting them leaves the error.
            assert_eq!(f.0 & Flags::BITS, flags);
            f.set(Flags::RESTING, false);
            f.set(Flags::ACC_IGNORED, true);
            assert_eq!(f.diagnostics(0.0).mag_error, kept);
            assert!(!f.get(Flags::RESTING) && f.get(Flags::ACC_IGNORED));
        }
        // Subnormal errors: within half of 2^-141, the lowest kept bit
        // (2^-142 is the subnormal with bit 7 set).
        let half_lowest = f32::from_bits(1 << 7);
        for error in [1e-40f32, -3e-42, f32::from_bits(0x7f)] {
            let mut f = Flags::new(0);
            f.set_mag_error(error);
            let kept = f.diagnostics(0.0).mag_error;
            assert!(
                (kept - error).abs() <= half_lowest,
                "{error} kept as {kept}"
            );
        }
        // Rounded, not cut: just below 1, the error is kept as 1.
        let mut f = Flags::new(0);
        f.set_mag_error(1.0 - f32::EPSILON);
        assert_eq!(f.diagnostics(0.0).mag_error, 1.0);
    }
}
