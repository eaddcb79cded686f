//! Euler angles: [`EulerRot`], [`Quat::from_euler`] and [`Quat::to_euler`].
//!
//! Every order reduces to the one order `XYZ` by relabelling the axes:
//! a rotation `R_i(a) R_j(b) R_k(c)` about the axes `(i, j, k)` is, in
//! coordinates where `i, j, k` are `x, y, z`, the rotation
//! `R_x(a) R_y(b) R_z(c)`. The relabelling is a proper rotation when
//! `(i, j, k)` is a cyclic order of `(x, y, z)`; for the other three
//! orders, `k` maps to `-z` instead, which turns `c` into `-c`.
//!
//! For `XYZ` with half angles `A, B, C`, the product of the three axis
//! rotations gives `(w + y) + i (x + z) = (cos B + sin B) e^{i (A + C)}`
//! and `(w - y) + i (x - z) = (cos B - sin B) e^{i (A - C)}`, so `a + c`
//! and `a - c` are two atan2s of the components, and
//! `b = atan2(2 (w y + x z), |U| |V|)` with `|U| |V| = cos b`. Neither
//! needs an arcsine (inaccurate near `b = +-pi/2`) nor a rotation matrix.

use super::Quat;
use crate::float;

/// The order of the three rotations of a set of Euler angles: intrinsic
/// (each about an axis of the body, as turned by the rotations before it),
/// first axis first.
///
/// `Quat::from_euler(EulerRot::ZYX, a, b, c)` is
/// `Quat::from_rotation_z(a) * Quat::from_rotation_y(b) * Quat::from_rotation_x(c)`,
/// as glam's `EulerRot` of the same name. Rotations about fixed (world)
/// axes are the intrinsic order read backwards: turning about the world's
/// x, then y, then z axis by `x, y, z` is `from_euler(EulerRot::ZYX, z, y, x)`.
///
/// # Examples
///
/// ```
/// use rigtform::{EulerRot, Quat};
/// let (yaw, pitch, roll) = (0.3, -0.2, 1.1);
/// let q = Quat::from_euler(EulerRot::ZYX, yaw, pitch, roll);
/// let by_hand =
///     Quat::from_rotation_z(yaw) * Quat::from_rotation_y(pitch) * Quat::from_rotation_x(roll);
/// assert!(q.angle_to(by_hand) < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum EulerRot {
    /// Yaw about z, then pitch about the new y, then roll about the newest
    /// x: the aerospace (Tait–Bryan) yaw–pitch–roll of IMUs and aircraft,
    /// intrinsic Z-Y'-X''. The same rotation as turning about the world's
    /// x, y and z axes by roll, pitch and yaw.
    #[doc(alias = "YawPitchRoll")]
    ZYX,
    /// About z, then the new x, then the newest y.
    ZXY,
    /// About y, then the new x, then the newest z.
    YXZ,
    /// About y, then the new z, then the newest x.
    YZX,
    /// About x, then the new y, then the newest z.
    XYZ,
    /// About x, then the new z, then the newest y.
    XZY,
}

impl EulerRot {
    /// The six orders, for code that tries or offers each of them.
    ///
    /// ```
    /// use rigtform::{EulerRot, Quat};
    /// let q = Quat::from_rotation_x(0.5) * Quat::from_rotation_y(0.25);
    /// for order in EulerRot::ALL {
    ///     let (a, b, c) = q.to_euler(order);
    ///     assert!(Quat::from_euler(order, a, b, c).angle_to(q) < 1e-6);
    /// }
    /// ```
    pub const ALL: [Self; 6] = [
        Self::ZYX,
        Self::ZXY,
        Self::YXZ,
        Self::YZX,
        Self::XYZ,
        Self::XZY,
    ];

    /// Relabels `q`'s vector part so that this order becomes `XYZ`, and
    /// the sign that the third angle takes in those coordinates.
    fn relabel_to_xyz(self, q: Quat) -> (Quat, f32) {
        let Quat { w, x, y, z } = q;
        match self {
            Self::XYZ => (Quat::from_wxyz(w, x, y, z), 1.0),
            Self::YZX => (Quat::from_wxyz(w, y, z, x), 1.0),
            Self::ZXY => (Quat::from_wxyz(w, z, x, y), 1.0),
            Self::XZY => (Quat::from_wxyz(w, x, z, -y), -1.0),
            Self::YXZ => (Quat::from_wxyz(w, y, x, -z), -1.0),
            Self::ZYX => (Quat::from_wxyz(w, z, y, -x), -1.0),
        }
    }

    /// The inverse of [`relabel_to_xyz`](Self::relabel_to_xyz)'s relabelling.
    fn relabel_from_xyz(self, q: Quat) -> Quat {
        let Quat { w, x, y, z } = q;
        match self {
            Self::XYZ => Quat::from_wxyz(w, x, y, z),
            Self::YZX => Quat::from_wxyz(w, z, x, y),
            Self::ZXY => Quat::from_wxyz(w, y, z, x),
            Self::XZY => Quat::from_wxyz(w, x, -z, y),
            Self::YXZ => Quat::from_wxyz(w, y, x, -z),
            Self::ZYX => Quat::from_wxyz(w, -z, y, x),
        }
    }
}

/// `x` moved into [-pi, pi] by a whole turn, for `x` in [-3 pi, 3 pi].
fn wrap(x: f32) -> f32 {
    use core::f32::consts::{PI, TAU};
    if x > PI {
        x - TAU
    } else if x < -PI {
        x + TAU
    } else {
        x
    }
}

impl Quat {
    /// The rotation by the Euler angles `a`, `b`, `c` (radians) about the
    /// axes of `order`, intrinsic, first axis first: for
    /// [`EulerRot::ZYX`], yaw `a`, pitch `b` and roll `c`.
    ///
    /// # Preconditions
    ///
    /// Any finite angles (they need not be in the ranges
    /// [`to_euler`](Self::to_euler) returns). A NaN or infinite angle gives
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::EULER_MAX_ANGLE_ERROR`](crate::accuracy::EULER_MAX_ANGLE_ERROR)
    /// radians of the exact rotation for angles in [-pi, pi], and within as
    /// much of unit norm.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, EulerRot, Quat};
    /// // A quarter turn of yaw takes the nose (x) to the left wing (y).
    /// let q = Quat::from_euler(EulerRot::ZYX, FRAC_PI_2, 0.0, 0.0);
    /// assert!((q * Cvec3::X - Cvec3::Y).norm() < 1e-6);
    /// ```
    #[doc(alias = "from_euler_angles")]
    #[must_use]
    pub fn from_euler(order: EulerRot, a: f32, b: f32, c: f32) -> Self {
        let (_, sign) = order.relabel_to_xyz(Self::IDENTITY);
        let (sa, ca) = float::sin_cos(a * 0.5);
        let (sb, cb) = float::sin_cos(b * 0.5);
        let (sc, cc) = float::sin_cos(sign * c * 0.5);
        // (ca + sa i) (cb + sb j) (cc + sc k), expanded.
        let (w0, x0, y0, z0) = (ca * cb, sa * cb, ca * sb, sa * sb);
        let q = Self::from_wxyz(
            w0 * cc - z0 * sc,
            x0 * cc + y0 * sc,
            y0 * cc - x0 * sc,
            w0 * sc + z0 * cc,
        );
        order.relabel_from_xyz(q)
    }

    /// The Euler angles `(a, b, c)` of the rotation, about the axes of
    /// `order`, intrinsic, first axis first, so that
    /// `Quat::from_euler(order, a, b, c)` is the same rotation: for
    /// [`EulerRot::ZYX`], `(yaw, pitch, roll)`.
    ///
    /// `a` and `c` are in [-pi, pi], `b` in [-pi/2, pi/2]. `q` and `-q`
    /// give the same angles (the same bits unless `w` is zero).
    ///
    /// # Gimbal lock
    ///
    /// At `b = +-pi/2` only `a + c` (or `a - c`) is defined. Where the part
    /// of the quaternion that carries the other combination is below 2^-26
    /// of the part that carries this one, this returns `c = 0` and puts the
    /// whole turn in `a`: finite angles, and the same rotation to within
    /// 1e-7 radians. Elsewhere near the lock, `a` and `c` each take their
    /// share of the turn, however ill-conditioned the split.
    ///
    /// # Preconditions
    ///
    /// Any finite non-zero quaternion (the angles are scale-free). Zero
    /// gives `(0, 0, 0)`; NaN or infinite input gives NaN angles.
    ///
    /// # Accuracy
    ///
    /// `from_euler` of the returned angles, evaluated exactly, is within
    /// [`accuracy::EULER_MAX_ANGLE_ERROR`](crate::accuracy::EULER_MAX_ANGLE_ERROR)
    /// radians of the rotation of a unit `self`, at gimbal lock too. Near
    /// gimbal lock the split between `a` and `c` is ill-conditioned (many
    /// splits give nearly the same rotation); compare rotations, not angles.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{EulerRot, Quat};
    /// let q = Quat::from_euler(EulerRot::ZYX, 0.3, -0.2, 1.1);
    /// let (yaw, pitch, roll) = q.to_euler(EulerRot::ZYX);
    /// assert!((yaw - 0.3).abs() < 1e-6 && (pitch + 0.2).abs() < 1e-6 && (roll - 1.1).abs() < 1e-6);
    /// ```
    #[doc(alias = "euler_angles")]
    #[must_use]
    pub fn to_euler(self, order: EulerRot) -> (f32, f32, f32) {
        if !self.is_finite() {
            return (f32::NAN, f32::NAN, f32::NAN);
        }
        let (q, sign) = order.relabel_to_xyz(self.cn());
        // Power-of-two scaling keeps the sums below from overflowing or
        // losing everything to underflow; the angles are scale-free.
        let [x, y, z, w] = float::scale_for_squares(q.to_array()).v;
        let (u_re, u_im) = (w + y, x + z);
        let (v_re, v_im) = (w - y, x - z);
        let u = libm::hypotf(u_re, u_im);
        let v = libm::hypotf(v_re, v_im);
        let b = float::atan2(2.0 * (w * y + x * z), u * v);
        let plus = float::atan2(u_im, u_re);
        let minus = float::atan2(v_im, v_re);
        // Setting c = 0 moves the rotation by at most the smaller of |U|
        // and |V| times pi (relative to |q|), under 7e-8 rad below this
        // ratio of the two.
        const LOCK: f32 = 1.0 / (1u32 << 26) as f32;
        let (a, c) = if v <= LOCK * u {
            (wrap(2.0 * plus), 0.0)
        } else if u <= LOCK * v {
            (wrap(2.0 * minus), 0.0)
        } else {
            (wrap(plus + minus), wrap(plus - minus))
        };
        (a, b, sign * c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::EULER_MAX_ANGLE_ERROR;
    use core::f32::consts::{FRAC_PI_2, PI};

    /// Angles and rotations after one way and back, with either backend.
    const TOL: f32 = 4.0 * EULER_MAX_ANGLE_ERROR;

    fn axis(order: EulerRot, n: usize) -> fn(f32) -> Quat {
        let names = match order {
            EulerRot::ZYX => "zyx",
            EulerRot::ZXY => "zxy",
            EulerRot::YXZ => "yxz",
            EulerRot::YZX => "yzx",
            EulerRot::XYZ => "xyz",
            EulerRot::XZY => "xzy",
        };
        match names.as_bytes().get(n) {
            Some(b'x') => Quat::from_rotation_x,
            Some(b'y') => Quat::from_rotation_y,
            _ => Quat::from_rotation_z,
        }
    }

    #[test]
    fn from_euler_is_the_product_of_the_three_axis_rotations_in_order() {
        for order in EulerRot::ALL {
            for (a, b, c) in [(0.3, -0.2, 1.1), (-2.9, 1.5, 0.4), (3.0, -1.0, -3.1)] {
                let want = axis(order, 0)(a) * axis(order, 1)(b) * axis(order, 2)(c);
                let got = Quat::from_euler(order, a, b, c);
                assert!(got.angle_to(want) < TOL, "{order:?} {a} {b} {c}");
            }
        }
    }

    #[test]
    fn to_euler_recovers_angles_in_range_and_is_the_same_for_minus_q() {
        for order in EulerRot::ALL {
            for (a, b, c) in [(0.3, -0.2, 1.1), (-2.9, 1.5, 0.4), (3.0, -1.0, -3.1)] {
                let q = Quat::from_euler(order, a, b, c);
                let (x, y, z) = q.to_euler(order);
                assert!((x - a).abs() < TOL && (y - b).abs() < TOL && (z - c).abs() < TOL);
                assert_eq!((-q).to_euler(order), (x, y, z));
            }
        }
    }

    #[test]
    fn near_gimbal_lock_the_angles_are_finite_and_give_the_same_rotation() {
        for order in EulerRot::ALL {
            for b in [FRAC_PI_2, -FRAC_PI_2, FRAC_PI_2 - 1e-4, 1e-3 - FRAC_PI_2] {
                for (a, c) in [(0.4, 0.0), (1.0, -0.7), (-2.0, 3.0)] {
                    let q = axis(order, 0)(a) * axis(order, 1)(b) * axis(order, 2)(c);
                    let (x, y, z) = q.to_euler(order);
                    assert!(x.is_finite() && z.is_finite(), "{order:?} {a} {b} {c}");
                    assert!((y - b).abs() < 1e-3 + TOL, "{order:?} {a} {b} {c}: {y}");
                    assert!(Quat::from_euler(order, x, y, z).angle_to(q) < TOL);
                }
            }
        }
    }

    #[test]
    fn at_gimbal_lock_the_third_angle_is_zero() {
        // (w + y, x + z) = 0 in XYZ coordinates: b = -pi/2 exactly.
        let q = Quat::from_wxyz(0.5, 0.5, -0.5, -0.5);
        let (a, b, c) = q.to_euler(EulerRot::XYZ);
        assert_eq!((b, c), (-FRAC_PI_2, 0.0));
        assert!(Quat::from_euler(EulerRot::XYZ, a, b, c).angle_to(q) < TOL);
        // The same rotation read as yaw, pitch and roll: pitch +pi/2.
        let q = Quat::from_euler(EulerRot::ZYX, 0.0, FRAC_PI_2, 0.0);
        let (_, pitch, roll) = q.to_euler(EulerRot::ZYX);
        assert_eq!(roll, 0.0);
        assert!((pitch - FRAC_PI_2).abs() < TOL);
    }

    #[test]
    fn bad_input_gives_documented_results() {
        assert!(Quat::from_euler(EulerRot::XYZ, f32::NAN, 0.0, 0.0)
            .w
            .is_nan());
        let (a, b, c) = Quat::NAN.to_euler(EulerRot::ZYX);
        assert!(a.is_nan() && b.is_nan() && c.is_nan());
        assert_eq!(
            Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).to_euler(EulerRot::ZYX),
            (0.0, 0.0, 0.0)
        );
        let huge = Quat::from_euler(EulerRot::YXZ, 0.5, 0.25, -PI / 3.0).map(|c| c * 1e38);
        let (a, b, c) = huge.to_euler(EulerRot::YXZ);
        assert!((a - 0.5).abs() < TOL && (b - 0.25).abs() < TOL && (c + PI / 3.0).abs() < TOL);
    }
}
