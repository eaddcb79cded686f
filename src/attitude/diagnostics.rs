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
    /// 6D).
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
/// flag, one bit each, so that the filter's state holds them in one byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub(super) struct Flags(u8);

impl Flags {
    /// [`Diagnostics::initialising`].
    pub(super) const INITIALISING: u8 = 1;
    /// [`Diagnostics::recovering`].
    pub(super) const RECOVERING: u8 = 1 << 1;
    /// [`Diagnostics::gyro_saturated`].
    pub(super) const GYRO_SATURATED: u8 = 1 << 2;
    /// [`Diagnostics::gyro_ignored`].
    pub(super) const GYRO_IGNORED: u8 = 1 << 3;
    /// [`Diagnostics::resting`].
    pub(super) const RESTING: u8 = 1 << 4;
    /// [`Diagnostics::acc_ignored`].
    pub(super) const ACC_IGNORED: u8 = 1 << 5;
    /// [`Diagnostics::mag_ignored`].
    pub(super) const MAG_IGNORED: u8 = 1 << 6;
    /// The filter's inclination has been set (from an accelerometer
    /// sample, or a starting attitude); not a diagnostic.
    pub(super) const INITIALIZED: u8 = 1 << 7;

    /// The flags in `bits` set, the others clear.
    #[inline]
    pub(super) const fn new(bits: u8) -> Self {
        Self(bits)
    }

    /// Whether the flag `bit` (one of the constants) is set.
    #[inline]
    pub(super) const fn get(self, bit: u8) -> bool {
        self.0 & bit != 0
    }

    /// Sets the flag `bit` (one of the constants) to `on`.
    #[inline]
    pub(super) fn set(&mut self, bit: u8, on: bool) {
        self.0 = (self.0 & !bit) | (bit & u8::from(on).wrapping_neg());
    }

    /// The flags as [`Diagnostics`], with the two errors.
    #[inline]
    pub(super) const fn diagnostics(self, acc_error: f32, mag_error: f32) -> Diagnostics {
        Diagnostics {
            acc_error,
            mag_error,
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
