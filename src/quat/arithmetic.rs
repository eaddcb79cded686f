//! A [`Quat`] as a 4-vector: sums, differences, scaling, and the sum and
//! product of an iterator, as glam and nalgebra offer them. The notes'
//! product of rotations is `*` between two quaternions (`quat.rs`); these
//! are the linear operations under blends, splines and hand-written
//! filters. None of them normalizes.

use core::iter::{Product, Sum};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Sub, SubAssign};

use super::Quat;

impl Quat {
    /// `a self + b other`, component-wise: the sum under slerp, nlerp and
    /// blend.
    #[inline]
    pub(crate) fn weighted_sum(self, a: f32, other: Self, b: f32) -> Self {
        Self::from_wxyz(
            a * self.w + b * other.w,
            a * self.x + b * other.x,
            a * self.y + b * other.y,
            a * self.z + b * other.z,
        )
    }
}

impl Add for Quat {
    type Output = Quat;

    /// Component by component; not a rotation of any kind (see
    /// [`Quat::slerp`] and [`Quat::nlerp`] for blends).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let s = Quat::from_xyzw(1.0, 2.0, 3.0, 4.0) + Quat::from_xyzw(1.0, 1.0, 1.0, 1.0);
    /// assert_eq!(s, Quat::from_xyzw(2.0, 3.0, 4.0, 5.0));
    /// ```
    #[inline]
    fn add(self, o: Quat) -> Quat {
        Quat::from_xyzw(self.x + o.x, self.y + o.y, self.z + o.z, self.w + o.w)
    }
}

impl Sub for Quat {
    type Output = Quat;

    /// Component by component.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::IDENTITY - Quat::IDENTITY, Quat::from_xyzw(0.0, 0.0, 0.0, 0.0));
    /// ```
    #[inline]
    fn sub(self, o: Quat) -> Quat {
        Quat::from_xyzw(self.x - o.x, self.y - o.y, self.z - o.z, self.w - o.w)
    }
}

impl Mul<f32> for Quat {
    type Output = Quat;

    /// Every component times `s`: the same rotation for `s > 0` (the
    /// rotation methods expect unit norm, so [`normalize`](Quat::normalize)
    /// before rotating with it).
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::IDENTITY * 2.0, Quat::from_xyzw(0.0, 0.0, 0.0, 2.0));
    /// ```
    #[inline]
    fn mul(self, s: f32) -> Quat {
        Quat::from_xyzw(self.x * s, self.y * s, self.z * s, self.w * s)
    }
}

impl Mul<Quat> for f32 {
    type Output = Quat;

    /// Every component of `q` times `self`, as `q * self`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(0.5 * Quat::IDENTITY, Quat::IDENTITY * 0.5);
    /// ```
    #[inline]
    fn mul(self, q: Quat) -> Quat {
        q * self
    }
}

impl Div<f32> for Quat {
    type Output = Quat;

    /// Every component divided by `s` (IEEE 754: by zero gives infinities
    /// or NaN, never a panic).
    ///
    /// ```
    /// use rigtform::Quat;
    /// assert_eq!(Quat::from_xyzw(0.0, 0.0, 0.0, 2.0) / 2.0, Quat::IDENTITY);
    /// ```
    #[inline]
    fn div(self, s: f32) -> Quat {
        Quat::from_xyzw(self.x / s, self.y / s, self.z / s, self.w / s)
    }
}

impl AddAssign for Quat {
    /// `*self = *self + o`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::IDENTITY;
    /// q += Quat::IDENTITY;
    /// assert_eq!(q, Quat::IDENTITY * 2.0);
    /// ```
    #[inline]
    fn add_assign(&mut self, o: Quat) {
        *self = *self + o;
    }
}

impl SubAssign for Quat {
    /// `*self = *self - o`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::IDENTITY * 3.0;
    /// q -= Quat::IDENTITY;
    /// assert_eq!(q, Quat::IDENTITY * 2.0);
    /// ```
    #[inline]
    fn sub_assign(&mut self, o: Quat) {
        *self = *self - o;
    }
}

impl MulAssign<f32> for Quat {
    /// `*self = *self * s`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::IDENTITY;
    /// q *= 4.0;
    /// assert_eq!(q.w, 4.0);
    /// ```
    #[inline]
    fn mul_assign(&mut self, s: f32) {
        *self = *self * s;
    }
}

impl DivAssign<f32> for Quat {
    /// `*self = *self / s`.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let mut q = Quat::IDENTITY * 4.0;
    /// q /= 4.0;
    /// assert_eq!(q, Quat::IDENTITY);
    /// ```
    #[inline]
    fn div_assign(&mut self, s: f32) {
        *self = *self / s;
    }
}

impl Sum for Quat {
    /// The component-wise sum, starting from zero (not a blend of
    /// rotations: see [`Quat::blend`], which aligns signs first).
    ///
    /// ```
    /// use rigtform::Quat;
    /// let s: Quat = [Quat::IDENTITY; 3].into_iter().sum();
    /// assert_eq!(s, Quat::IDENTITY * 3.0);
    /// ```
    fn sum<I: Iterator<Item = Quat>>(iter: I) -> Quat {
        iter.fold(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0), Add::add)
    }
}

impl<'a> Sum<&'a Quat> for Quat {
    /// As the sum of values.
    ///
    /// ```
    /// use rigtform::Quat;
    /// let s: Quat = [Quat::IDENTITY; 2].iter().sum();
    /// assert_eq!(s, Quat::IDENTITY * 2.0);
    /// ```
    fn sum<I: Iterator<Item = &'a Quat>>(iter: I) -> Quat {
        iter.copied().sum()
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

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Each operator against glam's on the same components, bit for bit:
    /// both are one IEEE 754 operation per component.
    #[test]
    fn operators_agree_with_glam_bit_for_bit() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(26);
        let bits = |q: Quat| q.to_array().map(f32::to_bits);
        let g = |q: Quat| glam::Quat::from_array(q.to_array());
        let r = |q: glam::Quat| Quat::from_array(q.to_array());
        for _ in 0..10_000 {
            let mut draw =
                || Quat::from_array(core::array::from_fn(|_| rng.random_range(-4.0..4.0)));
            let (a, b) = (draw(), draw());
            let s = rng.random_range(-3.0f32..3.0);
            assert_eq!(bits(a + b), bits(r(g(a) + g(b))));
            assert_eq!(bits(a - b), bits(r(g(a) - g(b))));
            assert_eq!(bits(a * s), bits(r(g(a) * s)));
            assert_eq!(bits(s * a), bits(r(g(a) * s)));
            assert_eq!(bits(a / s), bits(r(g(a) / s)));
            let sum: Quat = [a, b, a].iter().sum();
            assert_eq!(bits(sum), bits(r([g(a), g(b), g(a)].iter().sum())));
            let (mut c, mut d) = (a, a);
            c += b;
            d -= b;
            assert_eq!((c, d), (a + b, a - b));
            c *= s;
            d /= s;
            assert_eq!((c, d), ((a + b) * s, (a - b) / s));
        }
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
