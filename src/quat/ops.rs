//! The core products of [`Quat`], as the notes' "Operations" define
//! them: the Hamilton product `a * b` of two rotations (`b` first, then
//! `a`) and the rotation of a vector `q * v`, both through the inherent
//! methods that carry their Kani contracts (`mul_quat`, `mul_vec3`, glam's
//! names), and the product of an iterator.
//!
//! The Hamilton product is evaluated by the backend of `quat.rs`: the
//! notes' formula (`quat/scalar.rs`), or on x86-64 the same sums four
//! lanes at a time (`quat/sse2.rs`), with the same bits.

use core::iter::Product;
use core::ops::{Mul, MulAssign};

use super::{backend, Quat};
use crate::vec::{Cvec3, Cvec4};

impl Quat {
    /// `self * other`, the Hamilton product: glam's name.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::from_rotation_x(0.2), Quat::from_rotation_y(0.7));
    /// assert_eq!(a.mul_quat(b), a * b);
    /// ```
    ///
    /// `*` calls this method, so its Kani contract (`docs/kani.md`) covers
    /// both spellings.
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::quat_mul_requires(self, other))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &Quat| crate::kani_contracts::quat_mul_ensures(self, other, *r)))]
    #[inline]
    #[must_use]
    pub fn mul_quat(self, other: Self) -> Self {
        backend::hamilton(self, other)
    }

    /// `self * v`, the rotated vector: glam's name.
    ///
    /// # Preconditions
    ///
    /// As `Quat * Cvec3`: `self` is a unit quaternion.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_rotation_z(0.5);
    /// assert_eq!(q.mul_vec3(Cvec3::X), q * Cvec3::X);
    /// ```
    ///
    /// `*` calls this method, so its Kani contract (`docs/kani.md`) covers
    /// both spellings.
    #[cfg_attr(kani, kani::requires(crate::kani_contracts::rotate_requires(self, v)))]
    #[cfg_attr(kani, kani::ensures(|r: &Cvec3| crate::kani_contracts::rotate_ensures(self, v, *r)))]
    #[inline]
    #[must_use]
    pub fn mul_vec3(self, v: Cvec3) -> Cvec3 {
        rotate(self, v)
    }
}

impl Mul<Quat> for Quat {
    type Output = Quat;

    /// The Hamilton product of the notes' "Operations":
    /// `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`. As rotations, `a * b`
    /// applies `b` first, then `a`. On x86-64 the four components are
    /// summed at once in SSE registers, with the same bits as the formula.
    ///
    /// Accuracy: for unit inputs the product is within
    /// [`accuracy::MUL_MAX_ANGLE_ERROR`](crate::accuracy::MUL_MAX_ANGLE_ERROR)
    /// radians of the exact rotation and within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of unit norm.
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let (a, b) = (Quat::from_rotation_x(0.5), Quat::from_rotation_y(0.5));
    /// let v = Cvec3::new(1.0, 2.0, 3.0);
    /// assert!(((a * b) * v - a * (b * v)).norm() < 1e-5);
    /// ```
    #[inline]
    fn mul(self, o: Quat) -> Quat {
        // Through the inherent method, which carries the Kani contract.
        self.mul_quat(o)
    }
}

impl MulAssign<Quat> for Quat {
    /// `*self = *self * other`: `other` applied first, then `self`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::from_rotation_x(0.5);
    /// q *= Quat::from_rotation_y(0.5);
    /// assert_eq!(q, Quat::from_rotation_x(0.5) * Quat::from_rotation_y(0.5));
    /// ```
    #[inline]
    fn mul_assign(&mut self, other: Quat) {
        *self = *self * other;
    }
}

impl Product for Quat {
    /// The Hamilton product of the items, left to right, starting from
    /// [`Quat::IDENTITY`]: `[a, b, c]` gives `a * b * c`, which applies `c`
    /// first (as rotations).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let (a, b) = (Quat::from_rotation_x(0.3), Quat::from_rotation_y(0.4));
    /// let p: Quat = [a, b].into_iter().product();
    /// assert_eq!(p, Quat::IDENTITY * a * b);
    /// ```
    fn product<I: Iterator<Item = Quat>>(iter: I) -> Quat {
        iter.fold(Quat::IDENTITY, Mul::mul)
    }
}

impl<'a> Product<&'a Quat> for Quat {
    /// As the product of values.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let q = Quat::from_rotation_z(0.5);
    /// let p: Quat = [q, q].iter().product();
    /// assert!(p.angle_to(Quat::from_rotation_z(1.0)) < 1e-6);
    /// ```
    fn product<I: Iterator<Item = &'a Quat>>(iter: I) -> Quat {
        iter.copied().product()
    }
}

impl Mul<Cvec3> for Quat {
    type Output = Cvec3;

    /// Rotates `v`: the vector part of the notes' triple product
    /// `q [0, v] q^-1`, evaluated as `v + w t + u x t` with `u` the vector
    /// part of `q` and `t = 2 u x v` (the same value for a unit `q`, in 18
    /// multiplications instead of the triple product's 32).
    ///
    /// Preconditions: `self` is a unit quaternion (for another, the result
    /// is not a rotation). Accuracy: error at most
    /// [`accuracy::ROTATE_MAX_REL_ERROR`](crate::accuracy::ROTATE_MAX_REL_ERROR)
    /// times `|v|`.
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// let v = Quat::from_rotation_y(PI) * Cvec3::new(1.0, 2.0, 3.0);
    /// assert!((v - Cvec3::new(-1.0, 2.0, -3.0)).norm() < 1e-6);
    /// ```
    #[inline]
    fn mul(self, v: Cvec3) -> Cvec3 {
        // Through the inherent method, which carries the Kani contract.
        self.mul_vec3(v)
    }
}

/// `q * v`, the formula of `Mul<Cvec3> for Quat` (its doc).
#[inline]
fn rotate(q: Quat, v: Cvec3) -> Cvec3 {
    let u = q.vector();
    let t = u.cross(v) * 2.0;
    v + t * q.w + u.cross(t)
}

impl Mul<Cvec4> for Quat {
    type Output = Cvec4;

    /// Rotates the first three coordinates and copies the fourth, as the
    /// notes' `quat * cvec4` ("copy over the 0/1 fourth coordinate").
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec4, Quat};
    /// let c = Quat::from_rotation_z(FRAC_PI_2) * Cvec4::new(1.0, 0.0, 0.0, 1.0);
    /// assert!((c - Cvec4::new(0.0, 1.0, 0.0, 1.0)).norm() < 1e-6);
    /// assert_eq!(c.w, 1.0);
    /// ```
    #[inline]
    fn mul(self, c: Cvec4) -> Cvec4 {
        let r = self * c.xyz();
        Cvec4::new(r.x, r.y, r.z, c.w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_of_axis_rotations_matches_the_notes_formula() {
        // i j = k, j k = i, k i = j (Hamilton).
        let i = Quat::from_wxyz(0.0, 1.0, 0.0, 0.0);
        let j = Quat::from_wxyz(0.0, 0.0, 1.0, 0.0);
        let k = Quat::from_wxyz(0.0, 0.0, 0.0, 1.0);
        assert_eq!(i * j, k);
        assert_eq!(j * k, i);
        assert_eq!(k * i, j);
        assert_eq!(i * i, Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0));
    }

    #[test]
    fn product_of_rotations_composes_them_in_order() {
        let qs = [
            Quat::from_rotation_x(0.3),
            Quat::from_rotation_y(-1.1),
            Quat::from_rotation_z(2.0),
        ];
        let p: Quat = qs.into_iter().product();
        assert_eq!(p, Quat::IDENTITY * qs[0] * qs[1] * qs[2]);
        let empty: Quat = core::iter::empty::<Quat>().product();
        assert_eq!(empty, Quat::IDENTITY);
        let zero: Quat = core::iter::empty::<Quat>().sum();
        assert_eq!(zero, Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
    }
}
