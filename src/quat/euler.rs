//! Euler angles: [`EulerRot`], [`Quat::from_euler`] and [`Quat::to_euler`].
//!
//! An extrinsic order is the intrinsic order of its axes read backwards,
//! with the angles in reverse: `XYZEx` with `(a, b, c)` is `ZYX` with
//! `(c, b, a)`. Every intrinsic order then reduces to one of two, `XYZ`
//! (Tait–Bryan) or `XYX` (proper Euler), by relabelling the axes: a
//! rotation `R_i(a) R_j(b) R_k(c)` about the axes `(i, j, k)` is, in
//! coordinates where `i, j` are `x, y`, the rotation
//! `R_x(a) R_y(b) R_z(+-c)` or `R_x(a) R_y(b) R_x(c)`. The relabelling is a
//! proper rotation; where `(i, j)` is not a cyclic pair of `(x, y, z)`,
//! the third axis `k` of a Tait–Bryan order maps to `-z`, which turns `c`
//! into `-c`.
//!
//! For `XYZ` with half angles `A, B, C`, the product of the three axis
//! rotations gives `U = (w + y) + i (x + z) = (cos B + sin B) e^{i (A + C)}`
//! and `V = (w - y) + i (x - z) = (cos B - sin B) e^{i (A - C)}`, so `a + c`
//! and `a - c` are two atan2s of the components, and
//! `b = atan2(2 (w y + x z), |U| |V|)` with `|U| |V| = cos b`. For `XYX`,
//! `U = w + i x = cos B e^{i (A + C)}` and `V = y + i z = sin B e^{i (A - C)}`,
//! and `b = 2 atan2(|V|, |U|) = atan2(2 |U| |V|, |U|^2 - |V|^2)`. Neither needs an arcsine or arccosine
//! (inaccurate near the ends of their ranges) nor a rotation matrix.

use super::Quat;
use crate::float;

/// The order of the three rotations of a set of Euler angles: glam's 24
/// orders, with glam's names and meaning.
///
/// - Intrinsic (the plain names): each rotation is about an axis of the
///   body, as turned by the rotations before it, first axis first.
///   `Quat::from_euler(EulerRot::ZYX, a, b, c)` is
///   `Quat::from_rotation_z(a) * Quat::from_rotation_y(b) * Quat::from_rotation_x(c)`.
/// - Extrinsic (the names ending in `Ex`): each rotation is about an axis of
///   the world, which stays put, first axis first.
///   `Quat::from_euler(EulerRot::XYZEx, a, b, c)` turns about the world's x
///   by `a`, then its y by `b`, then its z by `c`: that is
///   `Quat::from_rotation_z(c) * Quat::from_rotation_y(b) * Quat::from_rotation_x(a)`,
///   the intrinsic order read backwards, `from_euler(EulerRot::ZYX, c, b, a)`.
/// - Tait–Bryan orders use three different axes (`XYZ`, `ZYX`, ...); proper
///   Euler orders repeat the first axis last (`ZYZ`, `XYX`, ...).
///
/// [`Quat::to_euler`] gives the middle angle in
/// [`middle_angle_range`](Self::middle_angle_range): [-pi/2, pi/2] for the
/// Tait–Bryan orders, and for the proper Euler orders [0, pi] where the
/// second axis follows the first anticyclically (`XZX`, `YXY`, `ZYZ`) and
/// [-pi, 0] where it follows cyclically (`XYX`, `YZY`, `ZXZ`), as glam.
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
/// // The same rotation about the world's axes: roll, then pitch, then yaw.
/// assert!(Quat::from_euler(EulerRot::XYZEx, roll, pitch, yaw).angle_to(q) < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum EulerRot {
    /// Yaw about z, then pitch about the new y, then roll about the newest
    /// x: the aerospace (Tait–Bryan) yaw–pitch–roll of IMUs and aircraft,
    /// intrinsic Z-Y'-X''. The same rotation as turning about the world's
    /// x, y and z axes by roll, pitch and yaw ([`XYZEx`](Self::XYZEx)).
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
    /// About z, then the new y, then the newest z (proper Euler).
    ZYZ,
    /// About z, then the new x, then the newest z (proper Euler: the
    /// classical precession, nutation and spin).
    ZXZ,
    /// About y, then the new x, then the newest y (proper Euler).
    YXY,
    /// About y, then the new z, then the newest y (proper Euler).
    YZY,
    /// About x, then the new y, then the newest x (proper Euler).
    XYX,
    /// About x, then the new z, then the newest x (proper Euler).
    XZX,
    /// About the world's z, then its y, then its x: intrinsic `XYZ` read
    /// backwards.
    ZYXEx,
    /// About the world's z, then its x, then its y: intrinsic `YXZ` read
    /// backwards.
    ZXYEx,
    /// About the world's y, then its x, then its z: intrinsic `ZXY` read
    /// backwards.
    YXZEx,
    /// About the world's y, then its z, then its x: intrinsic `XZY` read
    /// backwards.
    YZXEx,
    /// About the world's x, then its y, then its z: intrinsic `ZYX` read
    /// backwards (roll, pitch, yaw about fixed axes).
    XYZEx,
    /// About the world's x, then its z, then its y: intrinsic `YZX` read
    /// backwards.
    XZYEx,
    /// About the world's z, then its y, then its z: intrinsic `ZYZ` read
    /// backwards.
    ZYZEx,
    /// About the world's z, then its x, then its z: intrinsic `ZXZ` read
    /// backwards.
    ZXZEx,
    /// About the world's y, then its x, then its y: intrinsic `YXY` read
    /// backwards.
    YXYEx,
    /// About the world's y, then its z, then its y: intrinsic `YZY` read
    /// backwards.
    YZYEx,
    /// About the world's x, then its y, then its x: intrinsic `XYX` read
    /// backwards.
    XYXEx,
    /// About the world's x, then its z, then its x: intrinsic `XZX` read
    /// backwards.
    XZXEx,
}

/// The first two axes of an intrinsic order; relabelling the axes turns
/// them into `x, y`.
#[derive(Clone, Copy)]
enum Pair {
    Xy,
    Yz,
    Zx,
    Xz,
    Yx,
    Zy,
}

impl Pair {
    /// `true` for `x, y`, `y, z` and `z, x`, where the relabelling keeps
    /// the third axis of a Tait–Bryan order as `+z`; otherwise it becomes
    /// `-z`, which turns the third angle's sign.
    const fn cyclic(self) -> bool {
        matches!(self, Self::Xy | Self::Yz | Self::Zx)
    }

    /// `q` in coordinates where the pair is `x, y` (a proper rotation of
    /// the axes, so the same rotation).
    fn to_xy(self, q: Quat) -> Quat {
        let Quat { w, x, y, z } = q;
        match self {
            Self::Xy => Quat::from_wxyz(w, x, y, z),
            Self::Yz => Quat::from_wxyz(w, y, z, x),
            Self::Zx => Quat::from_wxyz(w, z, x, y),
            Self::Xz => Quat::from_wxyz(w, x, z, -y),
            Self::Yx => Quat::from_wxyz(w, y, x, -z),
            Self::Zy => Quat::from_wxyz(w, z, y, -x),
        }
    }

    /// The inverse of [`to_xy`](Self::to_xy): back to the order's own axes.
    fn back_from_xy(self, q: Quat) -> Quat {
        let Quat { w, x, y, z } = q;
        match self {
            Self::Xy => Quat::from_wxyz(w, x, y, z),
            Self::Yz => Quat::from_wxyz(w, z, x, y),
            Self::Zx => Quat::from_wxyz(w, y, z, x),
            Self::Xz => Quat::from_wxyz(w, x, -z, y),
            Self::Yx => Quat::from_wxyz(w, y, x, -z),
            Self::Zy => Quat::from_wxyz(w, -z, y, x),
        }
    }
}

/// What an order reduces to: its first two axes (of the intrinsic order
/// that reads it backwards, for an extrinsic one), whether the first axis
/// comes back third (proper Euler), and whether it is extrinsic (the
/// angles taken in reverse).
struct Form {
    pair: Pair,
    proper: bool,
    extrinsic: bool,
}

impl EulerRot {
    /// The 24 orders, in the order of the declaration (glam's): the six
    /// intrinsic Tait–Bryan orders, the six intrinsic proper Euler orders,
    /// then the same twelve extrinsic.
    ///
    /// ```
    /// use rigtform::{EulerRot, Quat};
    /// let q = Quat::from_rotation_x(0.5) * Quat::from_rotation_y(0.25);
    /// for order in EulerRot::ALL {
    ///     let (a, b, c) = q.to_euler(order);
    ///     assert!(Quat::from_euler(order, a, b, c).angle_to(q) < 1e-6);
    /// }
    /// ```
    pub const ALL: [Self; 24] = [
        Self::ZYX,
        Self::ZXY,
        Self::YXZ,
        Self::YZX,
        Self::XYZ,
        Self::XZY,
        Self::ZYZ,
        Self::ZXZ,
        Self::YXY,
        Self::YZY,
        Self::XYX,
        Self::XZX,
        Self::ZYXEx,
        Self::ZXYEx,
        Self::YXZEx,
        Self::YZXEx,
        Self::XYZEx,
        Self::XZYEx,
        Self::ZYZEx,
        Self::ZXZEx,
        Self::YXYEx,
        Self::YZYEx,
        Self::XYXEx,
        Self::XZXEx,
    ];

    /// The range of the middle angle that [`Quat::to_euler`] returns for
    /// this order, as glam's: `(-pi/2, pi/2)` for the Tait–Bryan orders,
    /// `(0, pi)` for `XZX`, `YXY`, `ZYZ` and their `Ex` forms, `(-pi, 0)`
    /// for `XYX`, `YZY`, `ZXZ` and theirs (both ends included). The first
    /// and third angles are always in [-pi, pi].
    ///
    /// ```
    /// use core::f32::consts::{FRAC_PI_2, PI};
    /// use rigtform::EulerRot;
    /// assert_eq!(EulerRot::ZYX.middle_angle_range(), (-FRAC_PI_2, FRAC_PI_2));
    /// assert_eq!(EulerRot::ZYZ.middle_angle_range(), (0.0, PI));
    /// assert_eq!(EulerRot::XYXEx.middle_angle_range(), (-PI, 0.0));
    /// ```
    #[must_use]
    pub const fn middle_angle_range(self) -> (f32, f32) {
        use core::f32::consts::{FRAC_PI_2, PI};
        let form = self.form();
        match (form.proper, form.pair.cyclic()) {
            (false, _) => (-FRAC_PI_2, FRAC_PI_2),
            (true, false) => (0.0, PI),
            (true, true) => (-PI, 0.0),
        }
    }

    /// The pair, kind and frame of the order.
    const fn form(self) -> Form {
        use Pair::{Xy, Xz, Yx, Yz, Zx, Zy};
        let (pair, proper, extrinsic) = match self {
            Self::XYZ => (Xy, false, false),
            Self::XZY => (Xz, false, false),
            Self::YXZ => (Yx, false, false),
            Self::YZX => (Yz, false, false),
            Self::ZXY => (Zx, false, false),
            Self::ZYX => (Zy, false, false),
            Self::XYX => (Xy, true, false),
            Self::XZX => (Xz, true, false),
            Self::YXY => (Yx, true, false),
            Self::YZY => (Yz, true, false),
            Self::ZXZ => (Zx, true, false),
            Self::ZYZ => (Zy, true, false),
            // Extrinsic: the intrinsic order that reads the axes backwards.
            Self::ZYXEx => (Xy, false, true),
            Self::YZXEx => (Xz, false, true),
            Self::ZXYEx => (Yx, false, true),
            Self::XZYEx => (Yz, false, true),
            Self::YXZEx => (Zx, false, true),
            Self::XYZEx => (Zy, false, true),
            Self::XYXEx => (Xy, true, true),
            Self::XZXEx => (Xz, true, true),
            Self::YXYEx => (Yx, true, true),
            Self::YZYEx => (Yz, true, true),
            Self::ZXZEx => (Zx, true, true),
            Self::ZYZEx => (Zy, true, true),
        };
        Form {
            pair,
            proper,
            extrinsic,
        }
    }
}

/// `x` moved into [-pi, pi] by a whole turn, for `x` in [-3 pi, 3 pi]. The
/// turn is `TAU` plus its tail (2 pi - `TAU`, -1.7e-7), so that the
/// subtraction rounds once, on the result, instead of adding `TAU`'s error.
fn wrap(x: f32) -> f32 {
    use core::f32::consts::{PI, TAU};
    /// 2 pi - TAU, rounded (twice the tail of pi, `float/head_tail.rs`).
    const TAU_LO: f32 = -1.748_455_6e-7;
    if x > PI {
        (x - TAU) - TAU_LO
    } else if x < -PI {
        (x + TAU) + TAU_LO
    } else {
        x
    }
}

impl Quat {
    /// The rotation by the Euler angles `a`, `b`, `c` (radians) about the
    /// axes of `order` (see [`EulerRot`] for intrinsic and extrinsic), first
    /// axis first: for [`EulerRot::ZYX`], yaw `a`, pitch `b` and roll `c`.
    /// The same rotation as glam's `Quat::from_euler` with the same order
    /// and angles.
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
    #[must_use]
    pub fn from_euler(order: EulerRot, a: f32, b: f32, c: f32) -> Self {
        let Form {
            pair,
            proper,
            extrinsic,
        } = order.form();
        let (a, c) = if extrinsic { (c, a) } else { (a, c) };
        // The third angle turns the other way about -z (Tait–Bryan orders
        // whose pair is not cyclic).
        let c = if proper || pair.cyclic() { c } else { -c };
        let (sa, ca) = float::sin_cos(a * 0.5);
        let (sb, cb) = float::sin_cos(b * 0.5);
        let (sc, cc) = float::sin_cos(c * 0.5);
        // (ca + sa i) (cb + sb j), then times (cc + sc k) for a Tait–Bryan
        // order (x, y, z) or (cc + sc i) for a proper one (x, y, x).
        let (w0, x0, y0, z0) = (ca * cb, sa * cb, ca * sb, sa * sb);
        let q = if proper {
            Self::from_wxyz(
                w0 * cc - x0 * sc,
                x0 * cc + w0 * sc,
                y0 * cc + z0 * sc,
                z0 * cc - y0 * sc,
            )
        } else {
            Self::from_wxyz(
                w0 * cc - z0 * sc,
                x0 * cc + y0 * sc,
                y0 * cc - x0 * sc,
                w0 * sc + z0 * cc,
            )
        };
        pair.back_from_xy(q)
    }

    /// The Euler angles `(a, b, c)` of the rotation, about the axes of
    /// `order` (see [`EulerRot`] for intrinsic and extrinsic), first axis
    /// first, so that `Quat::from_euler(order, a, b, c)` is the same
    /// rotation: for [`EulerRot::ZYX`], `(yaw, pitch, roll)`. The same
    /// angles as glam's `Quat::to_euler` away from gimbal lock.
    ///
    /// `a` and `c` are in [-pi, pi], `b` in the order's
    /// [`middle_angle_range`](EulerRot::middle_angle_range): [-pi/2, pi/2]
    /// for Tait–Bryan orders, [0, pi] or [-pi, 0] for proper Euler orders.
    /// `q` and `-q` give the same angles (the same bits unless `w` is zero).
    ///
    /// # Gimbal lock
    ///
    /// At `b = +-pi/2` (Tait–Bryan) or at `b = 0` and `b = +-pi` (proper
    /// Euler), the first and third axes line up and only `a + c` (or
    /// `a - c`) is defined. Where the part of the quaternion that carries
    /// the other combination is below 2^-26 of the part that carries this
    /// one, this returns `c = 0` (for an extrinsic order, `a = 0`: the
    /// angle of the last rotation of the intrinsic order it reverses) and
    /// puts the whole turn in the other: finite angles, and the same
    /// rotation to within 1e-7 radians. Elsewhere near the lock, `a` and `c`
    /// each take their share of the turn, however ill-conditioned the
    /// split.
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
    #[must_use]
    pub fn to_euler(self, order: EulerRot) -> (f32, f32, f32) {
        if !self.is_finite() {
            return (f32::NAN, f32::NAN, f32::NAN);
        }
        let Form {
            pair,
            proper,
            extrinsic,
        } = order.form();
        let q = pair.to_xy(self.cn());
        // Power-of-two scaling keeps the sums below from overflowing or
        // losing everything to underflow; the angles are scale-free.
        let Self { w, x, y, z } = q;
        let [x, y, z, w] = float::scale_for_squares([x, y, z, w]).v;
        // Two complex numbers U and V whose arguments are the half-angle
        // sum and difference of the first and third angles, and whose
        // moduli give the middle angle.
        let s = if pair.cyclic() { -1.0 } else { 1.0 };
        let ((u_re, u_im), (v_re, v_im)) = if proper {
            // U = w + i x = cos B e^{i (A + C)}, V = y + i z = sin B e^{i (A - C)};
            // glam's range for a cyclic pair is B in [-pi/2, 0]: sin B <= 0,
            // so V is taken with that sign.
            ((w, x), (s * y, s * z))
        } else {
            // U = (cos B + sin B) e^{i (A + C)}, V = (cos B - sin B) e^{i (A - C)}.
            ((w + y, x + z), (w - y, x - z))
        };
        let u = libm::hypotf(u_re, u_im);
        let v = libm::hypotf(v_re, v_im);
        let b = if proper {
            // b = 2 atan2(|V|, |U|), as one atan2 of the double angle (whose
            // error is then not doubled): sin b = 2 |U| |V|, cos b = |U|^2 - |V|^2.
            s * float::atan2(2.0 * u * v, (u - v) * (u + v))
        } else {
            float::atan2(2.0 * (w * y + x * z), u * v)
        };
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
        let c = if proper || pair.cyclic() { c } else { -c };
        if extrinsic {
            (c, b, a)
        } else {
            (a, b, c)
        }
    }
}

#[cfg(test)]
mod tests;
