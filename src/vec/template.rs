//! The API the coordinate types share, written once: macros that each
//! type's file instances with its fields, as glam writes every vector type
//! from one template.
//!
//! - [`euclidean!`]: what [`Cvec3`](crate::Cvec3), [`Cvec4`](crate::Cvec4)
//!   and [`Quat`](crate::Quat) have as elements of a Euclidean space:
//!   norms and normalization without overflow or underflow, the finiteness
//!   tests, sums, differences and scaling;
//! - [`coordinates!`]: what the vectors alone have: constants, arrays and
//!   tuples, indexing, `lerp`, and glam's everyday component-wise methods;
//!   and, through [`lengths!`] (`vec/template/lengths.rs`), what they do
//!   with lengths and directions: distances, projections, normalization
//!   with a fallback, clamped lengths, `move_towards`, `refract`.
//!
//! Every example of a shared method names its type `V` (and, in
//! [`euclidean!`], a value of norm 1 of it `u`), so that one example reads
//! the same for every type it is instanced for.

/// The first lines of a shared method's example: `use rigtform::<type> as
/// V;`, and with a unit constant, `let u = V::<constant>;`.
macro_rules! example_uses {
    ($t:ident) => {
        concat!("use rigtform::", stringify!($t), " as V;")
    };
    ($t:ident, $unit:ident) => {
        concat!(
            "use rigtform::",
            stringify!($t),
            " as V;\nlet u = V::",
            stringify!($unit),
            "; // of norm 1"
        )
    };
}

/// The Euclidean-space API of a type of `f32` fields: `$unit` names a
/// constant of norm 1 (for the examples), `$pad` fills the four slots of
/// the scale-free sum of squares ([`scale_for_squares`]) when the type has
/// three fields, and `contract(requires, ensures)` names the Kani
/// conditions of `normalize` in `kani_contracts`, where it has them. The
/// type writes its own `dot` (the order of its sums is its own).
///
/// [`scale_for_squares`]: crate::float::scale_for_squares
macro_rules! euclidean {
    (
        $t:ident { $first:ident $(, $rest:ident)* } $(pad $pad:literal)?, unit $unit:ident
        $(, contract($requires:ident, $ensures:ident))?
    ) => {
        impl $t {
            /// The squared norm `self.dot(self)`. Overflows to infinity for
            /// components beyond about 1.8e19: use [`norm`](Self::norm) for
            /// the norm itself.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert_eq!((u * 3.0).norm_squared(), 9.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn norm_squared(self) -> f32 {
                self.dot(self)
            }

            /// The Euclidean norm (length), without intermediate overflow
            /// or underflow.
            ///
            /// # Accuracy
            ///
            /// Within 2 ulp of the exact norm for every finite input, from
            /// subnormal components (down to 1e-45) to `f32::MAX` (exact
            /// power-of-two rescaling, as C's `hypot`). Norms above
            /// `f32::MAX` round to infinity. NaN in, NaN out.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert_eq!((u * 5.0).norm(), 5.0);
            /// assert_eq!((u * 3e30).norm(), 3e30); // no overflow
            /// assert_eq!((u * 1e-40).norm(), 1e-40); // no underflow
            /// ```
            #[inline]
            #[must_use]
            pub fn norm(self) -> f32 {
                $crate::float::scale_for_squares([self.$first $(, self.$rest)* $(, $pad)?]).norm()
            }

            /// `self / |self|`, the value of norm 1 in the direction of
            /// `self`, or `None` if `self` is zero or has a NaN or infinite
            /// component.
            ///
            /// # Accuracy
            ///
            /// The result's norm is within
            /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
            /// of 1, for every finite non-zero input, subnormal or huge.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert_eq!((u * 1e-40).try_normalize(), Some(u));
            /// assert_eq!((u * 0.0).try_normalize(), None);
            /// ```
            #[inline]
            #[must_use]
            pub fn try_normalize(self) -> Option<Self> {
                let [$first $(, $rest)*, ..] =
                    $crate::float::scale_for_squares([self.$first $(, self.$rest)* $(, $pad)?])
                        .unit()?;
                Some(Self { $first $(, $rest)* })
            }

            /// `self / |self|`: pulls a value that drifted off norm 1 back
            /// onto it.
            ///
            /// # Preconditions
            ///
            /// `self` is finite and non-zero. Otherwise every component of
            /// the result is NaN (never a panic);
            /// [`try_normalize`](Self::try_normalize) returns an `Option`
            /// instead.
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert_eq!((u * 7.0).normalize(), u);
            /// assert!((u * 0.0).normalize().is_nan());
            /// ```
            $(
                #[cfg_attr(kani, kani::requires(crate::kani_contracts::$requires(self)))]
                #[cfg_attr(kani, kani::ensures(|r: &$t| crate::kani_contracts::$ensures(self, *r)))]
            )?
            #[inline]
            #[must_use]
            pub fn normalize(self) -> Self {
                self.try_normalize().unwrap_or(Self { $first: f32::NAN $(, $rest: f32::NAN)* })
            }

            /// `true` if every component is finite (neither NaN nor
            /// infinite).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert!(u.is_finite() && !(u * f32::INFINITY).is_finite());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_finite(self) -> bool {
                self.$first.is_finite() $(&& self.$rest.is_finite())*
            }

            /// `true` if any component is NaN.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t, $unit)]
            /// assert!((u * f32::NAN).is_nan() && !u.is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_nan(self) -> bool {
                self.$first.is_nan() $(|| self.$rest.is_nan())*
            }
        }

        impl core::ops::Add for $t {
            type Output = Self;
            /// Component by component.
            #[inline]
            fn add(self, o: Self) -> Self {
                Self { $first: self.$first + o.$first $(, $rest: self.$rest + o.$rest)* }
            }
        }
        impl core::ops::Sub for $t {
            type Output = Self;
            /// Component by component.
            #[inline]
            fn sub(self, o: Self) -> Self {
                Self { $first: self.$first - o.$first $(, $rest: self.$rest - o.$rest)* }
            }
        }
        impl core::ops::Neg for $t {
            type Output = Self;
            /// Every component negated (exact).
            #[inline]
            fn neg(self) -> Self {
                Self { $first: -self.$first $(, $rest: -self.$rest)* }
            }
        }
        impl core::ops::Mul<f32> for $t {
            type Output = Self;
            /// Every component times `s`.
            #[inline]
            fn mul(self, s: f32) -> Self {
                Self { $first: self.$first * s $(, $rest: self.$rest * s)* }
            }
        }
        impl core::ops::Div<f32> for $t {
            type Output = Self;
            /// Every component divided by `s` (IEEE 754: by zero gives
            /// infinities or NaN, never a panic).
            #[inline]
            fn div(self, s: f32) -> Self {
                Self { $first: self.$first / s $(, $rest: self.$rest / s)* }
            }
        }
        $crate::vec::arithmetic!($t, zero Self { $first: 0.0 $(, $rest: 0.0)* });
    };
}

/// What follows from a type's `+`, `-`, `* f32` and `/ f32`, written once
/// for the vectors, [`Quat`](crate::Quat) and the matrices: the assigning
/// forms, `f32 * $t`, and the sum of an iterator, from `$zero`.
macro_rules! arithmetic {
    ($t:ident, zero $zero:expr) => {
        impl core::ops::Mul<$t> for f32 {
            type Output = $t;
            /// Every component of `v` times `self`, as `v * self`.
            #[inline]
            fn mul(self, v: $t) -> $t {
                v * self
            }
        }
        impl core::ops::AddAssign for $t {
            /// `*self = *self + o`.
            #[inline]
            fn add_assign(&mut self, o: Self) {
                *self = *self + o;
            }
        }
        impl core::ops::SubAssign for $t {
            /// `*self = *self - o`.
            #[inline]
            fn sub_assign(&mut self, o: Self) {
                *self = *self - o;
            }
        }
        impl core::ops::MulAssign<f32> for $t {
            /// `*self = *self * s`.
            #[inline]
            fn mul_assign(&mut self, s: f32) {
                *self = *self * s;
            }
        }
        impl core::ops::DivAssign<f32> for $t {
            /// `*self = *self / s`.
            #[inline]
            fn div_assign(&mut self, s: f32) {
                *self = *self / s;
            }
        }
        impl core::iter::Sum for $t {
            /// The component-wise sum, from zero, left to right.
            #[inline]
            fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
                iter.fold($zero, |a, b| a + b)
            }
        }
        impl<'a> core::iter::Sum<&'a $t> for $t {
            /// The component-wise sum, from zero, left to right.
            #[inline]
            fn sum<I: Iterator<Item = &'a Self>>(iter: I) -> Self {
                iter.copied().sum()
            }
        }
    };
}

/// The smaller of `a` and `b`, NaN if either is NaN.
#[inline]
pub(super) fn min_or_nan(a: f32, b: f32) -> f32 {
    if a < b {
        a
    } else if a >= b {
        b
    } else {
        f32::NAN
    }
}

/// The larger of `a` and `b`, NaN if either is NaN.
#[inline]
pub(super) fn max_or_nan(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else if a <= b {
        b
    } else {
        f32::NAN
    }
}

/// What the vector types alone have, besides [`euclidean!`]: the
/// constants, arrays and tuples in the order of the fields, indexing (the
/// last field takes every index past the end, so indexing never panics),
/// `lerp`, glam's everyday component-wise methods, and [`lengths!`].
macro_rules! coordinates {
    (
        $t:ident, $n:literal, [$first:ident $(, $rest:ident)*],
        index { $($i:literal => $f:ident),+ } last $last:ident
    ) => {
        impl $t {
            /// Every component 0.
            pub const ZERO: Self = Self::splat(0.0);
            /// Every component 1.
            pub const ONE: Self = Self::splat(1.0);
            /// Every component NaN: what the crate returns for undefined
            /// results.
            pub const NAN: Self = Self::splat(f32::NAN);

            /// The vector with every component `v` (glam's `splat`).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::splat(2.0), V::ONE * 2.0);
            /// ```
            #[inline]
            #[must_use]
            pub const fn splat(v: f32) -> Self {
                Self { $first: v $(, $rest: v)* }
            }

            /// The coordinates as an array, in the order of the fields.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::X.to_array()[0], 1.0);
            /// ```
            #[inline]
            #[must_use]
            pub const fn to_array(self) -> [f32; $n] {
                [self.$first $(, self.$rest)*]
            }

            /// The vector of an array of coordinates, in the order of the
            /// fields.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::from_array(V::Y.to_array()), V::Y);
            /// ```
            #[inline]
            #[must_use]
            pub const fn from_array([$first $(, $rest)*]: [f32; $n]) -> Self {
                Self { $first $(, $rest)* }
            }

            /// Linear interpolation `(1 - alpha) self + alpha other`:
            /// exactly `self` at `alpha = 0` and exactly `other` at
            /// `alpha = 1`; extrapolates outside [0, 1].
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let (a, b) = (V::ZERO, V::splat(2.0));
            /// assert_eq!(a.lerp(b, 0.5), V::ONE);
            /// assert_eq!(a.lerp(b, 1.0), b);
            /// ```
            #[inline]
            #[must_use]
            pub fn lerp(self, other: Self, alpha: f32) -> Self {
                self * (1.0 - alpha) + other * alpha
            }

            /// The sum of the components, left to right (glam's
            /// `element_sum`).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ONE.element_sum(), V::ONE.dot(V::ONE));
            /// ```
            #[inline]
            #[must_use]
            pub fn element_sum(self) -> f32 {
                self.$first $(+ self.$rest)*
            }

            /// The product of the components, left to right (glam's
            /// `element_product`).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let n = V::ONE.element_sum() as i32;
            /// assert_eq!(V::splat(2.0).element_product(), 2f32.powi(n));
            /// ```
            #[inline]
            #[must_use]
            pub fn element_product(self) -> f32 {
                self.$first $(* self.$rest)*
            }

            /// The point half way, `(self + other) / 2` evaluated as
            /// `self * 0.5 + other * 0.5`, which cannot overflow for finite
            /// inputs (glam's `midpoint`).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ZERO.midpoint(V::splat(2.0)), V::ONE);
            /// ```
            #[inline]
            #[must_use]
            pub fn midpoint(self, other: Self) -> Self {
                self * 0.5 + other * 0.5
            }

            /// The component-wise minimum. A NaN in either operand gives
            /// NaN in that component (glam and `f32::min` return the other
            /// operand instead); of `0.0` and `-0.0` either may come back.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let a = V::splat(2.0);
            /// assert_eq!(a.min(V::ONE), V::ONE);
            /// assert!(a.min(V::NAN).is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn min(self, other: Self) -> Self {
                use $crate::vec::template::min_or_nan;
                Self {
                    $first: min_or_nan(self.$first, other.$first)
                    $(, $rest: min_or_nan(self.$rest, other.$rest))*
                }
            }

            /// The component-wise maximum. A NaN in either operand gives
            /// NaN in that component (glam and `f32::max` return the other
            /// operand instead); of `0.0` and `-0.0` either may come back.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let a = V::splat(2.0);
            /// assert_eq!(a.max(V::ONE), a);
            /// ```
            #[inline]
            #[must_use]
            pub fn max(self, other: Self) -> Self {
                use $crate::vec::template::max_or_nan;
                Self {
                    $first: max_or_nan(self.$first, other.$first)
                    $(, $rest: max_or_nan(self.$rest, other.$rest))*
                }
            }

            /// The component-wise absolute value.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!((-V::ONE).abs(), V::ONE);
            /// ```
            #[inline]
            #[must_use]
            pub fn abs(self) -> Self {
                Self { $first: self.$first.abs() $(, $rest: self.$rest.abs())* }
            }

            /// The smallest component; NaN if any component is NaN.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let mut v = V::splat(3.0);
            /// v.y = -1.0;
            /// assert_eq!(v.min_element(), -1.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn min_element(self) -> f32 {
                use $crate::vec::template::min_or_nan;
                let m = self.$first;
                $(let m = min_or_nan(m, self.$rest);)*
                m
            }

            /// The largest component; NaN if any component is NaN.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let mut v = V::splat(3.0);
            /// v.y = 7.0;
            /// assert_eq!(v.max_element(), 7.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn max_element(self) -> f32 {
                use $crate::vec::template::max_or_nan;
                let m = self.$first;
                $(let m = max_or_nan(m, self.$rest);)*
                m
            }

            /// Each component clamped to `[lo, hi]` (of the same
            /// component): `self.max(lo).min(hi)`, so a NaN in any operand
            /// gives NaN in that component, and where `lo > hi` the result
            /// is `hi` (glam asserts `lo <= hi`; this never panics).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let v = V::splat(5.0);
            /// assert_eq!(v.clamp(V::ZERO, V::ONE), V::ONE);
            /// ```
            #[inline]
            #[must_use]
            pub fn clamp(self, lo: Self, hi: Self) -> Self {
                self.max(lo).min(hi)
            }

        }

        impl core::ops::Mul for $t {
            type Output = Self;
            /// The component-wise product (glam's `Vec3 * Vec3`).
            #[inline]
            fn mul(self, o: Self) -> Self {
                Self { $first: self.$first * o.$first $(, $rest: self.$rest * o.$rest)* }
            }
        }
        impl core::ops::Div for $t {
            type Output = Self;
            /// The component-wise quotient (glam's `Vec3 / Vec3`).
            #[inline]
            fn div(self, o: Self) -> Self {
                Self { $first: self.$first / o.$first $(, $rest: self.$rest / o.$rest)* }
            }
        }
        impl core::ops::MulAssign for $t {
            /// `*self = *self * o`, component-wise.
            #[inline]
            fn mul_assign(&mut self, o: Self) {
                *self = *self * o;
            }
        }
        impl core::ops::DivAssign for $t {
            /// `*self = *self / o`, component-wise.
            #[inline]
            fn div_assign(&mut self, o: Self) {
                *self = *self / o;
            }
        }
        impl core::ops::Index<usize> for $t {
            type Output = f32;
            /// The coordinate at `i`, in the order of the fields. Every
            /// index past the end gives the last coordinate (never a panic).
            #[inline]
            fn index(&self, i: usize) -> &f32 {
                match i {
                    $($i => &self.$f,)+
                    _ => &self.$last,
                }
            }
        }
        impl core::ops::IndexMut<usize> for $t {
            /// The coordinate at `i`, in the order of the fields. Every
            /// index past the end gives the last coordinate (never a panic).
            #[inline]
            fn index_mut(&mut self, i: usize) -> &mut f32 {
                match i {
                    $($i => &mut self.$f,)+
                    _ => &mut self.$last,
                }
            }
        }
        impl From<[f32; $n]> for $t {
            /// Same as `from_array`.
            #[inline]
            fn from(a: [f32; $n]) -> Self {
                Self::from_array(a)
            }
        }
        impl From<$t> for [f32; $n] {
            /// Same as `to_array`.
            #[inline]
            fn from(v: $t) -> Self {
                v.to_array()
            }
        }
        impl From<(f32 $(, coordinates!(@f32 $rest))*)> for $t {
            /// The components in the order of the fields, as glam's.
            #[inline]
            fn from(($first $(, $rest)*): (f32 $(, coordinates!(@f32 $rest))*)) -> Self {
                Self { $first $(, $rest)* }
            }
        }
        impl From<$t> for (f32 $(, coordinates!(@f32 $rest))*) {
            /// The components in the order of the fields, as glam's.
            #[inline]
            fn from(v: $t) -> Self {
                (v.$first $(, v.$rest)*)
            }
        }
        $crate::vec::template::lengths!($t);
    };
    (@f32 $f:ident) => {
        f32
    };
}

mod lengths;

pub(crate) use lengths::lengths;
pub(crate) use {arithmetic, coordinates, euclidean, example_uses};
