//! The core products of [`Quat`], as the notes' "Operations" define
//! them: the Hamilton product `a * b` of two rotations (`b` first, then
//! `a`) and the rotation of a vector `q * v`, both through the inherent
//! methods that carry their Kani contracts (`mul_quat`, `mul_vec3`, glam's
//! names), and the product of an iterator.
//!
//! The Hamilton product is the notes' formula, and on x86-64 the same sums
//! four lanes at a time. Both evaluate every component as `a.w b_i ±
//! a.x b_j ± a.y b_k ± a.z b_l`, left to right, so they give the same
//! bits: changing the sign of a product is exact, and `s - p` is
//! `s + (-p)` in IEEE 754, NaN and signed zeros included
//! (`by_lanes_is_by_formula_bit_for_bit`).

use core::iter::Product;
use core::ops::{Mul, MulAssign};

use super::Quat;
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
        hamilton(self, other)
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

/// `a * b`: [`by_lanes`] on x86-64 with SSE, [`by_formula`] elsewhere and
/// under Kani (whose harnesses then need no model of the intrinsics).
#[inline(always)]
pub(super) fn hamilton(a: Quat, b: Quat) -> Quat {
    #[cfg(x86_sse_lanes)]
    return by_lanes(a, b);
    #[cfg(not(x86_sse_lanes))]
    return by_formula(a, b);
}

/// The notes' `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`, written out one
/// component at a time, the terms in the order of `a`'s components.
#[cfg(any(test, not(x86_sse_lanes)))]
#[inline(always)]
fn by_formula(a: Quat, b: Quat) -> Quat {
    Quat::from_wxyz(
        a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
        a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
        a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
        a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
    )
}

/// [`by_formula`] by columns in SSE registers, lanes in the order of the
/// memory layout, `x, y, z, w`: `a.w [bx by bz bw]`, plus
/// `a.x [bw -bz by -bx]`, plus `a.y [bz bw -bx -by]`, plus
/// `a.z [-by bx bw -bz]`, each column a shuffle of `b` with sign bits
/// flipped by an exclusive or. One of the few places of the crate's
/// `unsafe` code (src/lib.rs lists them).
///
/// The compiler does vectorize [`by_formula`] too, but it folds each
/// negated term into a subtraction and builds the sign pattern from
/// additions, subtractions and lane blends, about ten instructions more
/// per product than these columns.
#[cfg(x86_sse_lanes)]
#[allow(unsafe_code)]
#[inline(always)]
fn by_lanes(a: Quat, b: Quat) -> Quat {
    use core::arch::x86_64::{
        _mm_add_ps, _mm_cvtss_f32, _mm_mul_ps, _mm_set1_ps, _mm_set_ps, _mm_shuffle_ps, _mm_xor_ps,
    };
    // SAFETY: every intrinsic here needs SSE, which this function is
    // compiled only with (`target_feature = "sse"`, enabled on every
    // x86-64 target but the soft-float kernel ones). They work on
    // registers only, reading and writing no memory, and SSE arithmetic
    // cannot fault with the default MXCSR (exceptions masked).
    unsafe {
        // `_mm_set_ps` takes the lanes from the highest: lane 0 is `x`, as
        // in memory.
        let b_xyzw = _mm_set_ps(b.w, b.z, b.y, b.x);
        // `_mm_shuffle_ps::<imm>`: lane i takes lane (imm >> 2i) & 3.
        let b_wzyx = _mm_shuffle_ps::<0b00_01_10_11>(b_xyzw, b_xyzw);
        let b_zwxy = _mm_shuffle_ps::<0b01_00_11_10>(b_xyzw, b_xyzw);
        let b_yxwz = _mm_shuffle_ps::<0b10_11_00_01>(b_xyzw, b_xyzw);
        // -0.0 in a lane flips that lane's sign bit.
        let signs_x = _mm_set_ps(-0.0, 0.0, -0.0, 0.0);
        let signs_y = _mm_set_ps(-0.0, -0.0, 0.0, 0.0);
        let signs_z = _mm_set_ps(-0.0, 0.0, 0.0, -0.0);
        let mut r = _mm_mul_ps(_mm_set1_ps(a.w), b_xyzw);
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.x), _mm_xor_ps(b_wzyx, signs_x)));
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.y), _mm_xor_ps(b_zwxy, signs_y)));
        r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(a.z), _mm_xor_ps(b_yxwz, signs_z)));
        Quat::from_xyzw(
            _mm_cvtss_f32(r),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(r, r)),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b10_10_10_10>(r, r)),
            _mm_cvtss_f32(_mm_shuffle_ps::<0b11_11_11_11>(r, r)),
        )
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

#[cfg(all(test, x86_sse_lanes))]
mod lanes_tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Both NaN, or the same bits.
    fn same(p: Quat, q: Quat) -> bool {
        p.to_array()
            .iter()
            .zip(q.to_array())
            .all(|(a, b)| (a.is_nan() && b.is_nan()) || a.to_bits() == b.to_bits())
    }

    #[test]
    fn by_lanes_is_by_formula_bit_for_bit() {
        let q = Quat::from_wxyz(0.0, 1.0, 2.0, 3.0);
        assert!(same(q, q) && same(Quat::NAN, Quat::NAN));
        assert!(!same(q, Quat::from_wxyz(-0.0, 1.0, 2.0, 3.0)));
        assert!(!same(
            Quat::NAN,
            Quat::from_wxyz(f32::NAN, 1.0, f32::NAN, f32::NAN)
        ));
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let special = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f32::MIN_POSITIVE,
            -1e-40,
            f32::MAX,
            -f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let component = |rng: &mut rand::rngs::StdRng| match rng.random_range(0..4) {
            0 => special[rng.random_range(0..special.len())],
            1 => f32::from_bits(rng.random()),
            _ => rng.random_range(-1.0f32..1.0),
        };
        // Fewer draws under Miri, which interprets every instruction.
        let draws = if cfg!(miri) { 500 } else { 200_000 };
        for _ in 0..draws {
            let mut q = || {
                Quat::from_wxyz(
                    component(&mut rng),
                    component(&mut rng),
                    component(&mut rng),
                    component(&mut rng),
                )
            };
            let (a, b) = (q(), q());
            let (lanes, formula) = (by_lanes(a, b), by_formula(a, b));
            assert!(
                same(lanes, formula),
                "{a:?} * {b:?}: {lanes:?} against {formula:?}"
            );
        }
    }
}
