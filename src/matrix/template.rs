//! What [`Matrix3`](crate::Matrix3) and [`Matrix4`](crate::Matrix4) share,
//! written once: the [`columns!`] macro each matrix's file instances (the
//! identity as the default, the products with a column vector and with a
//! matrix, the array conversions, a column or a row by index, the finiteness test), and the
//! limits both inverses check their entries against.
//!
//! Every example of a shared method names its matrix type `M` and its
//! column type `V`.

/// 2^63: the largest entry an inverse takes (each product of two entries,
/// and each 2x2 minor, is then finite).
pub(super) const INVERSE_ENTRY_LIMIT: f32 = 9.223_372e18;
/// 2^62: the largest 2x2 minor an inverse takes (each product of an entry
/// and a minor is then finite).
pub(super) const INVERSE_MINOR_LIMIT: f32 = 4.611_686e18;

/// The largest `|x|` of finite `values` (0 for none), by comparisons
/// only.
pub(super) fn largest_magnitude(values: &[f32]) -> f32 {
    values.iter().fold(0.0, |m: f32, v| m.max(v.abs()))
}

/// The first line of a shared method's example: the matrix type as `M`,
/// its column type as `V`.
macro_rules! example_uses {
    ($m:ident, $v:ident) => {
        concat!(
            "use rigtform::{",
            stringify!($m),
            " as M, ",
            stringify!($v),
            " as V};"
        )
    };
}

/// The API of a square matrix `$m` of `$n` entries, stored as columns of
/// type `$v`; `{ col: field, ... }` pairs each column with the component
/// of a vector that scales it in `m * v`.
macro_rules! columns {
    ($m:ident, $v:ident, $n:literal, { $c0:ident: $f0:ident $(, $c:ident: $f:ident)* }) => {
        impl $m {
            /// The column `i`, or a vector of NaNs for an index past the
            /// last column (glam's `col` panics there; this never does).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::IDENTITY.col(1), V::Y);
            /// assert!(M::IDENTITY.col(usize::MAX).is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn col(&self, i: usize) -> $v {
                self.cols.get(i).copied().unwrap_or($v::NAN)
            }

            /// The row `i`, or a vector of NaNs for an index past the last
            /// row (glam's `row` panics there; this never does).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(m.row(1)[0], m.col(0)[1]);
            /// assert!(m.row(usize::MAX).is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn row(&self, i: usize) -> $v {
                self.transpose().col(i)
            }

            /// `true` if every entry is finite.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert!(M::IDENTITY.is_finite());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_finite(self) -> bool {
                self.cols.iter().all(|c| c.is_finite())
            }
        }

        impl Default for $m {
            /// The identity matrix.
            fn default() -> Self {
                Self::IDENTITY
            }
        }

        impl From<[f32; $n]> for $m {
            /// Same as `from_cols_array`: column-major.
            #[inline]
            fn from(m: [f32; $n]) -> Self {
                Self::from_cols_array(&m)
            }
        }

        impl From<$m> for [f32; $n] {
            /// Same as `to_cols_array`: column-major.
            #[inline]
            fn from(m: $m) -> Self {
                m.to_cols_array()
            }
        }

        impl core::ops::Mul<$v> for $m {
            type Output = $v;

            /// The matrix times a column vector: the columns weighted by
            /// the vector's components, summed in order.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let v = V::splat(2.0);
            /// assert_eq!(M::IDENTITY * v, v);
            /// assert_eq!(M::IDENTITY.transpose() * V::X, V::X);
            /// ```
            #[inline]
            fn mul(self, v: $v) -> $v {
                let [$c0 $(, $c)*] = self.cols;
                $c0 * v.$f0 $(+ $c * v.$f)*
            }
        }

        impl core::ops::Mul<$m> for $m {
            type Output = $m;

            /// The matrix product; `(a * b) * v == a * (b * v)`.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(m * M::IDENTITY, m);
            /// assert_eq!((m * m) * V::Y, m * (m * V::Y));
            /// ```
            #[inline]
            fn mul(self, o: $m) -> $m {
                let [$c0 $(, $c)*] = o.cols;
                $m::from_cols(self * $c0 $(, self * $c)*)
            }
        }

        impl core::ops::MulAssign<$m> for $m {
            /// `*self = *self * other`.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// let mut n = m;
            /// n *= m;
            /// assert_eq!(n, m * m);
            /// ```
            #[inline]
            fn mul_assign(&mut self, other: $m) {
                *self = *self * other;
            }
        }
    };
}

pub(super) use {columns, example_uses};
