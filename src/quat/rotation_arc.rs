//! [`Quat::from_rotation_arc`]: the shortest rotation taking one direction
//! to another.
//!
//! With unit `a`, `b`, `c = a . b` and `n = a x b` (`|n| = sin theta`), the
//! quaternion `(1 + c, n)` is the rotation by `theta` about `n` times
//! `2 cos(theta / 2)`. Near opposite directions `1 + c` cancels, so it is
//! taken as `|n|^2 / (1 - c)` there (the same value, from accurate parts),
//! and the part of `n` along `a`, which is rounding error of the cross
//! product, is removed so that the axis stays perpendicular to `a`.

use super::Quat;
use crate::vec::Cvec3;

impl Quat {
    /// The shortest rotation taking the direction of `from` to the
    /// direction of `to`: about the axis `from x to`, by the angle between
    /// them (at most pi).
    ///
    /// # Preconditions
    ///
    /// Neither vector need be of unit length. A zero vector has no
    /// direction: the result is [`Quat::IDENTITY`]. Opposite directions have
    /// no shortest rotation: the result is a half turn about an axis
    /// perpendicular to `from` (`from` crossed with the coordinate axis
    /// along which `from` is smallest). NaN or infinite components give
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// `q * from` is within
    /// [`accuracy::ROTATION_ARC_MAX_ERROR`](crate::accuracy::ROTATION_ARC_MAX_ERROR)
    /// of the direction of `to` (unit vectors compared), opposite and
    /// nearly opposite directions included, and within as many radians of
    /// the exact shortest rotation for directions up to 90 degrees apart
    /// (towards opposite directions the axis `from x to` grows
    /// ill-conditioned, though `q` still takes `from` to `to`); the norm is
    /// within
    /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of 1.
    ///
    /// # Examples
    ///
    /// The tilt of a resting IMU: the rotation taking the measured gravity
    /// direction to the earth's down.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let accel = Cvec3::new(0.0, 4.9, 8.5); // m/s^2, tilted about x
    /// let tilt = Quat::from_rotation_arc(accel, Cvec3::Z);
    /// assert!((tilt * accel.normalize() - Cvec3::Z).norm() < 1e-6);
    /// assert!((tilt.to_axis_angle().0 - Cvec3::X).norm() < 1e-6); // about x only
    /// ```
    #[doc(alias = "from_two_vectors")]
    #[doc(alias = "rotation_between")]
    #[must_use]
    pub fn from_rotation_arc(from: Cvec3, to: Cvec3) -> Self {
        if !(from.is_finite() && to.is_finite()) {
            return Self::NAN;
        }
        let (Some(a), Some(b)) = (from.try_normalize(), to.try_normalize()) else {
            return Self::IDENTITY;
        };
        let c = a.dot(b);
        let n = a.cross(b);
        if c >= 0.0 {
            return Self::from_scalar_vector(1.0 + c, n).normalize();
        }
        let n = n - a * n.dot(a);
        let n2 = n.norm_squared();
        // Below 2^-22 the cross product of two unit vectors is rounding
        // noise in every direction: the directions are opposite as far as
        // f32 can tell, and a half turn about any perpendicular axis takes
        // `a` to within that much of `b`.
        if n2 <= NOISE * NOISE {
            return Self::from_scalar_vector(0.0, perpendicular(a));
        }
        Self::from_scalar_vector(n2 / (1.0 - c), n).normalize()
    }
}

/// The size of the rounding noise of the cross product of unit vectors.
const NOISE: f32 = 1.0 / (1u32 << 22) as f32;

/// A unit vector perpendicular to the unit vector `a`: `a` crossed with
/// the coordinate axis along which `a` is smallest.
fn perpendicular(a: Cvec3) -> Cvec3 {
    let (x, y, z) = (a.x.abs(), a.y.abs(), a.z.abs());
    let axis = if x <= y && x <= z {
        Cvec3::X
    } else if y <= z {
        Cvec3::Y
    } else {
        Cvec3::Z
    };
    a.cross(axis).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::{POW_MAX_ANGLE_ERROR, ROTATION_ARC_MAX_ERROR};

    /// The arc's error and that of reading its angle back (atan2), with
    /// either backend.
    const TOL: f32 = 2.0 * (ROTATION_ARC_MAX_ERROR + POW_MAX_ANGLE_ERROR);

    #[test]
    fn takes_from_to_to_the_short_way() {
        let (a, b) = (Cvec3::new(1.0, 2.0, -0.5), Cvec3::new(-3.0, 0.25, 2.0));
        let q = Quat::from_rotation_arc(a, b);
        assert!((q * a.normalize() - b.normalize()).norm() < TOL);
        let angle = libm::acosf(a.normalize().dot(b.normalize()));
        assert!((q.to_axis_angle().1 - angle).abs() < TOL);
        assert!((q.to_axis_angle().0 - a.cross(b).normalize()).norm() < TOL);
    }

    #[test]
    fn opposite_directions_give_a_half_turn_about_a_perpendicular_axis() {
        for a in [Cvec3::X, Cvec3::Y, -Cvec3::Z, Cvec3::new(1.0, -2.0, 3.0)] {
            let q = Quat::from_rotation_arc(a, -a * 2.5);
            assert!((q * a.normalize() + a.normalize()).norm() < TOL, "{a:?}");
            assert!(q.w.abs() < 1e-7 && q.vector().dot(a).abs() < 1e-6);
        }
    }

    #[test]
    fn same_direction_zero_and_non_finite_inputs_give_documented_results() {
        let a = Cvec3::new(0.3, -0.4, 1.2);
        assert!(Quat::from_rotation_arc(a, a * 7.0).angle_to(Quat::IDENTITY) < 1e-7);
        assert_eq!(Quat::from_rotation_arc(Cvec3::ZERO, a), Quat::IDENTITY);
        assert_eq!(Quat::from_rotation_arc(a, Cvec3::ZERO), Quat::IDENTITY);
        assert!(Quat::from_rotation_arc(Cvec3::NAN, a).is_nan());
        assert!(Quat::from_rotation_arc(a, Cvec3::new(f32::INFINITY, 0.0, 0.0)).is_nan());
    }
}
