//! [`AxesAlignment`]: the 24 right-angle mountings of a sensor on a board,
//! and [`Axis`], the signed axes they are named by.

use crate::vec::Cvec3;

/// A signed coordinate axis of the body (board) frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Axis {
    /// +x
    PosX,
    /// -x
    NegX,
    /// +y
    PosY,
    /// -y
    NegY,
    /// +z
    PosZ,
    /// -z
    NegZ,
}

impl Axis {
    /// All six, in declaration order.
    pub const ALL: [Axis; 6] = [
        Axis::PosX,
        Axis::NegX,
        Axis::PosY,
        Axis::NegY,
        Axis::PosZ,
        Axis::NegZ,
    ];

    /// The unit vector along this axis.
    ///
    /// ```
    /// use rigtform::attitude::Axis;
    /// use rigtform::Cvec3;
    /// assert_eq!(Axis::NegY.unit(), Cvec3::new(0.0, -1.0, 0.0));
    /// ```
    #[must_use]
    pub const fn unit(self) -> Cvec3 {
        match self {
            Axis::PosX => Cvec3::new(1.0, 0.0, 0.0),
            Axis::NegX => Cvec3::new(-1.0, 0.0, 0.0),
            Axis::PosY => Cvec3::new(0.0, 1.0, 0.0),
            Axis::NegY => Cvec3::new(0.0, -1.0, 0.0),
            Axis::PosZ => Cvec3::new(0.0, 0.0, 1.0),
            Axis::NegZ => Cvec3::new(0.0, 0.0, -1.0),
        }
    }
}

/// How a sensor is mounted on the board, at right angles: the body axes
/// that the sensor's x and y axes point along (its z axis is then their
/// cross product, so the mounting is a rotation, not a mirror). There are
/// 24 (6 choices for x, 4 for y). [`apply`](Self::apply) turns a sensor
/// reading into body coordinates; use the same alignment for the gyro,
/// the accelerometer and the magnetometer (after its calibration) when
/// they share a package.
///
/// # Examples
///
/// ```
/// use rigtform::attitude::{AxesAlignment, Axis};
/// use rigtform::Cvec3;
/// // The sensor turned a quarter turn about z on the board: its x along
/// // the board's +y, its y along the board's -x.
/// let a = AxesAlignment::new(Axis::PosY, Axis::NegX).unwrap();
/// assert_eq!(a.apply(Cvec3::new(1.0, 2.0, 3.0)), Cvec3::new(-2.0, 1.0, 3.0));
/// // x and y along one line is no mounting.
/// assert!(AxesAlignment::new(Axis::PosX, Axis::NegX).is_none());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AxesAlignment {
    /// The body axes of the sensor's x, y and z.
    axes: [Axis; 3],
}

impl AxesAlignment {
    /// The sensor's axes are the body's.
    pub const IDENTITY: Self = Self {
        axes: [Axis::PosX, Axis::PosY, Axis::PosZ],
    };

    /// The mounting whose sensor x points along the body axis `x` and
    /// sensor y along `y`; `None` unless they are perpendicular.
    ///
    /// ```
    /// use rigtform::attitude::{AxesAlignment, Axis};
    /// // Upside down about x: y and z flip.
    /// let a = AxesAlignment::new(Axis::PosX, Axis::NegY).unwrap();
    /// assert_eq!(a.z(), Axis::NegZ);
    /// ```
    #[must_use]
    pub fn new(x: Axis, y: Axis) -> Option<Self> {
        let z = x.unit().cross(y.unit());
        let z = Axis::ALL.into_iter().find(|a| a.unit() == z)?;
        Some(Self { axes: [x, y, z] })
    }

    /// The body axis of the sensor's z (the cross product of the other two).
    #[must_use]
    pub const fn z(self) -> Axis {
        self.axes[2]
    }

    /// A sensor reading `v` in body coordinates: `v.x` along the body axis
    /// of the sensor's x, and so on. Exact (only signs and order change).
    #[must_use]
    pub fn apply(self, v: Cvec3) -> Cvec3 {
        let mut out = [0.0; 3];
        for (axis, value) in self.axes.into_iter().zip([v.x, v.y, v.z]) {
            let (index, value) = match axis {
                Axis::PosX => (0, value),
                Axis::NegX => (0, -value),
                Axis::PosY => (1, value),
                Axis::NegY => (1, -value),
                Axis::PosZ => (2, value),
                Axis::NegZ => (2, -value),
            };
            out[index] = value;
        }
        Cvec3::new(out[0], out[1], out[2])
    }
}

impl Default for AxesAlignment {
    /// [`AxesAlignment::IDENTITY`].
    fn default() -> Self {
        Self::IDENTITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quat::Quat;

    #[test]
    fn there_are_24_mountings_and_each_is_a_rotation() {
        let mut count = 0;
        for x in Axis::ALL {
            for y in Axis::ALL {
                let Some(a) = AxesAlignment::new(x, y) else {
                    assert!(x.unit().cross(y.unit()) == Cvec3::ZERO, "{x:?} {y:?}");
                    continue;
                };
                count += 1;
                let (ex, ey, ez) = (
                    a.apply(Cvec3::new(1.0, 0.0, 0.0)),
                    a.apply(Cvec3::new(0.0, 1.0, 0.0)),
                    a.apply(Cvec3::new(0.0, 0.0, 1.0)),
                );
                assert_eq!((ex, ey), (x.unit(), y.unit()));
                // Right-handed: a rotation, so the cross product is kept.
                assert_eq!(ex.cross(ey), ez, "{x:?} {y:?}");
            }
        }
        assert_eq!(count, 24);
    }

    #[test]
    fn it_agrees_with_the_rotation_it_is() {
        // Sensor x along body +z, sensor y along body +x: a rotation that
        // takes x to z and y to x, which is a turn of -120° about (1, 1, 1).
        let a = AxesAlignment::new(Axis::PosZ, Axis::PosX).unwrap();
        // cos(-60°) and sin(-60°) / sqrt(3), exactly: no kernel involved.
        let q = Quat::from_wxyz(0.5, -0.5, -0.5, -0.5);
        let v = Cvec3::new(0.3, -1.2, 2.5);
        assert!(
            (a.apply(v) - q * v).norm() < 1e-5,
            "{:?} {:?}",
            a.apply(v),
            q * v
        );
        assert_eq!(AxesAlignment::default().apply(v), v);
        // Only signs and order change: an infinity stays in its component.
        let inf = Cvec3::new(f32::INFINITY, 1.0, 2.0);
        assert_eq!(a.apply(inf), Cvec3::new(1.0, 2.0, f32::INFINITY));
    }
}
