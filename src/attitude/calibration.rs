//! Sensor calibration applied before the filter: [`InertialCalibration`]
//! (gyroscope and accelerometer: offset, sensitivity, misalignment) and
//! [`MagneticCalibration`] (hard-iron offset, soft-iron matrix).

use crate::vec::Cvec3;

/// `m v`, for a 3x3 matrix given by its rows.
fn mul_rows(m: [Cvec3; 3], v: Cvec3) -> Cvec3 {
    Cvec3::new(m[0].dot(v), m[1].dot(v), m[2].dot(v))
}

/// The 3x3 identity, by rows.
const IDENTITY_ROWS: [Cvec3; 3] = [
    Cvec3::new(1.0, 0.0, 0.0),
    Cvec3::new(0.0, 1.0, 0.0),
    Cvec3::new(0.0, 0.0, 1.0),
];

/// The calibration of a gyroscope or an accelerometer: the reading less
/// its `offset`, scaled per axis by `sensitivity`, then turned and sheared
/// by the `misalignment` matrix: `misalignment * ((v - offset) * sensitivity)`
/// (the product with `sensitivity` per component). The values come from a
/// calibration of the device (a turntable, or six static poses for the
/// accelerometer); the filter's own bias estimate then follows what the
/// gyro offset leaves.
///
/// # Examples
///
/// ```
/// use rigtform::attitude::InertialCalibration;
/// use rigtform::Cvec3;
/// let gyro = InertialCalibration {
///     offset: Cvec3::new(0.01, 0.0, -0.02),
///     sensitivity: Cvec3::new(1.0, 1.0, 0.98),
///     ..InertialCalibration::IDENTITY
/// };
/// let v = gyro.apply(Cvec3::new(0.51, 0.0, 0.98));
/// assert!((v - Cvec3::new(0.5, 0.0, 0.98)).norm() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct InertialCalibration {
    /// The rows of the misalignment matrix (identity: the axes are
    /// orthogonal and where the datasheet says).
    pub misalignment: [Cvec3; 3],
    /// Per-axis scale factors (ones: the datasheet's sensitivity holds).
    pub sensitivity: Cvec3,
    /// The zero-input reading, subtracted first, in the reading's unit.
    pub offset: Cvec3,
}

impl InertialCalibration {
    /// No correction: `apply` returns its input.
    pub const IDENTITY: Self = Self {
        misalignment: IDENTITY_ROWS,
        sensitivity: Cvec3::new(1.0, 1.0, 1.0),
        offset: Cvec3::ZERO,
    };

    /// The calibrated reading: `misalignment * ((v - offset) * sensitivity)`.
    /// NaN in, NaN out.
    ///
    /// ```
    /// use rigtform::attitude::InertialCalibration;
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(0.1, 9.8, -0.3);
    /// assert_eq!(InertialCalibration::IDENTITY.apply(v), v);
    /// ```
    #[must_use]
    pub fn apply(&self, v: Cvec3) -> Cvec3 {
        let d = v - self.offset;
        let s = self.sensitivity;
        mul_rows(
            self.misalignment,
            Cvec3::new(d.x * s.x, d.y * s.y, d.z * s.z),
        )
    }
}

impl Default for InertialCalibration {
    /// [`InertialCalibration::IDENTITY`].
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// The calibration of a magnetometer: the `hard_iron` offset (the field of
/// magnetised parts that turn with the sensor) subtracted, then the
/// `soft_iron` matrix (the distortion by nearby iron, which turns the
/// sphere of readings into an ellipsoid) applied: `soft_iron * (v - hard_iron)`.
/// The values come from an ellipsoid fit to readings taken while the device
/// is turned every way.
///
/// # Examples
///
/// ```
/// use rigtform::attitude::MagneticCalibration;
/// use rigtform::Cvec3;
/// let mag = MagneticCalibration {
///     hard_iron: Cvec3::new(12.0, -3.0, 40.0),
///     ..MagneticCalibration::IDENTITY
/// };
/// assert_eq!(mag.apply(Cvec3::new(12.0, 13.0, -1.0)), Cvec3::new(0.0, 16.0, -41.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
#[repr(C)]
pub struct MagneticCalibration {
    /// The rows of the soft-iron matrix.
    pub soft_iron: [Cvec3; 3],
    /// The hard-iron offset, in the reading's unit, subtracted first.
    pub hard_iron: Cvec3,
}

impl MagneticCalibration {
    /// No correction: `apply` returns its input.
    pub const IDENTITY: Self = Self {
        soft_iron: IDENTITY_ROWS,
        hard_iron: Cvec3::ZERO,
    };

    /// The calibrated field: `soft_iron * (v - hard_iron)`. NaN in, NaN out.
    ///
    /// ```
    /// use rigtform::attitude::MagneticCalibration;
    /// use rigtform::Cvec3;
    /// let v = Cvec3::new(0.0, 16.0, -41.0);
    /// assert_eq!(MagneticCalibration::IDENTITY.apply(v), v);
    /// ```
    #[must_use]
    pub fn apply(&self, v: Cvec3) -> Cvec3 {
        mul_rows(self.soft_iron, v - self.hard_iron)
    }
}

impl Default for MagneticCalibration {
    /// [`MagneticCalibration::IDENTITY`].
    fn default() -> Self {
        Self::IDENTITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quat::Quat;

    /// A sensor whose readings are distorted by a known offset, scale and
    /// misalignment reads true after the inverse calibration.
    #[test]
    fn undoes_a_known_distortion() {
        let truth = Cvec3::new(0.3, -0.7, 9.6);
        // Distortion: turn by about 4° about (1, 2, 3), scale (1.02, 0.97, 1.01), add an offset.
        let turn = Quat::from_wxyz(1.0, 0.0087, 0.0175, 0.0262).normalize();
        let scale = Cvec3::new(1.02, 0.97, 1.01);
        let offset = Cvec3::new(0.05, -0.02, 0.11);
        let t = turn.inv() * truth;
        let read = Cvec3::new(t.x * scale.x, t.y * scale.y, t.z * scale.z) + offset;
        let rows = [
            turn * Cvec3::new(1.0, 0.0, 0.0),
            turn * Cvec3::new(0.0, 1.0, 0.0),
            turn * Cvec3::new(0.0, 0.0, 1.0),
        ];
        // The matrix whose columns are those images is the rotation; its
        // rows are the images of the rows of the identity under turn^-1.
        let misalignment = [
            Cvec3::new(rows[0].x, rows[1].x, rows[2].x),
            Cvec3::new(rows[0].y, rows[1].y, rows[2].y),
            Cvec3::new(rows[0].z, rows[1].z, rows[2].z),
        ];
        let cal = InertialCalibration {
            misalignment,
            sensitivity: Cvec3::new(1.0 / scale.x, 1.0 / scale.y, 1.0 / scale.z),
            offset,
        };
        assert!(
            (cal.apply(read) - truth).norm() < 1e-5,
            "{:?}",
            cal.apply(read)
        );
        assert!(!cal.apply(Cvec3::NAN).is_finite());
    }

    /// A hard-iron offset and a soft-iron stretch along x: every reading of
    /// a turned field comes back to the field's length.
    #[test]
    fn puts_an_ellipsoid_back_on_the_sphere() {
        let field = Cvec3::new(0.0, 16.0, -41.0);
        let hard_iron = Cvec3::new(20.0, -5.0, 8.0);
        let cal = MagneticCalibration {
            soft_iron: [
                Cvec3::new(1.0 / 1.3, 0.0, 0.0),
                Cvec3::new(0.0, 1.0, 0.0),
                Cvec3::new(0.0, 0.0, 1.0),
            ],
            hard_iron,
        };
        for k in 0..12 {
            let q = Quat::from_wxyz(1.0, k as f32 - 6.0, 2.0, 0.5 * k as f32).normalize();
            let v = q * field;
            let read = Cvec3::new(1.3 * v.x, v.y, v.z) + hard_iron;
            let error = (cal.apply(read).norm() - field.norm()).abs();
            assert!(error < 1e-5 * field.norm(), "{k}: {error}");
        }
        assert_eq!(
            MagneticCalibration::default(),
            MagneticCalibration::IDENTITY
        );
    }
}
