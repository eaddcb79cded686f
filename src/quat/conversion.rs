//! A [`Quat`] to and from other forms: its vector part, arrays (scalar
//! last, as glam, mint and glTF; or scalar first, as the notes), tuples,
//! [`Cvec4`], and the axis-angle form.

use super::power::Polar;
use super::Quat;
use crate::vec::{Cvec3, Cvec4};

impl Quat {
    /// The vector part `[x, y, z]`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// assert_eq!(Quat::from_wxyz(1.0, 2.0, 3.0, 4.0).vector(), Cvec3::new(2.0, 3.0, 4.0));
    /// ```
    #[inline]
    #[must_use]
    pub const fn vector(self) -> Cvec3 {
        Cvec3::new(self.x, self.y, self.z)
    }

    /// The components as an array `[x, y, z, w]`, scalar last: the order
    /// of glam's `to_array`, of mint, glTF and GPU shaders, and of the
    /// memory layout.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_xyzw(1.0, 2.0, 3.0, 4.0);
    /// assert_eq!(q.to_array(), [1.0, 2.0, 3.0, 4.0]);
    /// assert_eq!(Quat::IDENTITY.to_array(), [0.0, 0.0, 0.0, 1.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f32; 4] {
        [self.x, self.y, self.z, self.w]
    }

    /// Builds a quaternion from an array `[x, y, z, w]`, scalar last, as
    /// glam's `from_array` and glTF's rotation accessors.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_array([0.0, 0.0, 0.0, 1.0]), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_array([x, y, z, w]: [f32; 4]) -> Self {
        Self { x, y, z, w }
    }

    /// The quaternion of the 4-vector `[x, y, z, w]`, as it is (glam's
    /// `Quat::from_vec4`; the same as `Quat::from(v)`). No normalization:
    /// [`normalize`](Self::normalize) it if it is to be a rotation.
    ///
    /// ```
    /// use rigtform::{Cvec4, Quat};
    /// assert_eq!(Quat::from_vec4(Cvec4::W), Quat::IDENTITY);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_vec4(v: Cvec4) -> Self {
        Self::from_xyzw(v.x, v.y, v.z, v.w)
    }

    /// The components scalar first, `[w, x, y, z]`, as the notes write
    /// them.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::IDENTITY.to_wxyz(), [1.0, 0.0, 0.0, 0.0]);
    /// ```
    #[inline]
    #[must_use]
    pub const fn to_wxyz(self) -> [f32; 4] {
        [self.w, self.x, self.y, self.z]
    }

    /// The rotation as a unit axis and an angle in [0, pi] radians: the
    /// short way, whichever of `q` and `-q` is given.
    ///
    /// # Preconditions
    ///
    /// Any finite non-zero quaternion (the angle comes from atan2, which is
    /// scale-free). A pure real quaternion, or zero, is no rotation:
    /// `(Cvec3::X, 0.0)`. NaN or infinite input gives `(Cvec3::NAN, NaN)`.
    ///
    /// # Accuracy
    ///
    /// The angle is within [`accuracy::POW_MAX_ANGLE_ERROR`](crate::accuracy::POW_MAX_ANGLE_ERROR)
    /// of the exact one for unit input (atan2 stays accurate near 0 and pi, where acos does not).
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let (axis, angle) = Quat::from_axis_angle(Cvec3::Y, 1.5 * PI).to_axis_angle();
    /// // 270 degrees about +y is 90 degrees about -y:
    /// assert!((axis + Cvec3::Y).norm() < 1e-6);
    /// assert!((angle - 0.5 * PI).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn to_axis_angle(self) -> (Cvec3, f32) {
        if !self.is_finite() {
            return (Cvec3::NAN, f32::NAN);
        }
        let Polar { axis, phi } = self.cn().polar();
        (axis, 2.0 * phi)
    }
}

impl From<[f32; 4]> for Quat {
    /// Same as [`Quat::from_array`]: `[x, y, z, w]`, scalar last.
    #[inline]
    fn from(a: [f32; 4]) -> Self {
        Self::from_array(a)
    }
}

impl From<Quat> for [f32; 4] {
    /// Same as [`Quat::to_array`]: `[x, y, z, w]`, scalar last.
    #[inline]
    fn from(q: Quat) -> Self {
        q.to_array()
    }
}

impl From<Cvec4> for Quat {
    /// `x, y, z, w` as they are, glam's `Quat::from_vec4`.
    ///
    /// ```
    /// use rigtform::{Cvec4, Quat};
    /// assert_eq!(Quat::from(Cvec4::new(0.0, 0.0, 0.0, 1.0)), Quat::IDENTITY);
    /// ```
    #[inline]
    fn from(v: Cvec4) -> Self {
        Self::from_vec4(v)
    }
}

impl From<Quat> for Cvec4 {
    /// `x, y, z, w` as they are, glam's `Vec4::from(Quat)`.
    ///
    /// ```
    /// use rigtform::{Cvec4, Quat};
    /// assert_eq!(Cvec4::from(Quat::IDENTITY), Cvec4::new(0.0, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    fn from(q: Quat) -> Self {
        Cvec4::new(q.x, q.y, q.z, q.w)
    }
}

impl From<(f32, f32, f32, f32)> for Quat {
    /// `(x, y, z, w)`, scalar last, as [`Quat::from_xyzw`].
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from((0.0, 0.0, 0.0, 1.0)), Quat::IDENTITY);
    /// ```
    #[inline]
    fn from((x, y, z, w): (f32, f32, f32, f32)) -> Self {
        Self::from_xyzw(x, y, z, w)
    }
}

impl From<Quat> for (f32, f32, f32, f32) {
    /// `(x, y, z, w)`, scalar last, as [`Quat::to_array`].
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (x, y, z, w) = Quat::IDENTITY.into();
    /// assert_eq!((x, y, z, w), (0.0, 0.0, 0.0, 1.0));
    /// ```
    #[inline]
    fn from(q: Quat) -> Self {
        (q.x, q.y, q.z, q.w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::PI;

    #[test]
    fn to_axis_angle_of_a_half_turn_is_pi() {
        let (axis, angle) = Quat::from_wxyz(0.0, 0.0, 0.0, -1.0).to_axis_angle();
        assert_eq!(axis, -Cvec3::Z);
        assert_eq!(angle, PI);
    }

    /// glam's `from_vec4` and `Vec4::from(Quat)`: the components as they
    /// are, bit for bit.
    #[test]
    fn from_vec4_is_glams() {
        for v in [
            Cvec4::new(1.0, -2.0, 3.5, -0.0),
            Cvec4::NAN,
            Cvec4::W * f32::INFINITY,
        ] {
            let theirs = glam::Quat::from_vec4(glam::Vec4::from_array(v.to_array()));
            let ours = Quat::from_vec4(v);
            assert_eq!(
                ours.to_array().map(f32::to_bits),
                theirs.to_array().map(f32::to_bits)
            );
            assert_eq!(
                Quat::from(v).to_array().map(f32::to_bits),
                ours.to_array().map(f32::to_bits)
            );
            let back = glam::Vec4::from(theirs).to_array().map(f32::to_bits);
            assert_eq!(Cvec4::from(ours).to_array().map(f32::to_bits), back);
        }
    }
}
