//! What [`Matrix3`](crate::Matrix3) and [`Matrix4`](crate::Matrix4) share,
//! written once: the [`columns!`] macro each matrix's file instances (the
//! identity as the default, the constants, the constructors from rows,
//! arrays and a diagonal, the rotation constructors of glam, the products
//! with a column vector, a matrix and a scalar, sums and differences, a
//! column or a row by index, the finiteness tests, and glam's names for
//! these), and the limits both inverses check their entries against.
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

/// The API of a square matrix `$m` of `$d` columns of type `$v` (`$n`
/// entries); `{ col: field, ... }` pairs each column with the component of
/// a vector that scales it in `m * v`, and `glam(...)` names glam's
/// methods for the product with a matrix and with a vector, the sum and
/// the difference (`mul_mat4`, `mul_vec4`, `add_mat4`, `sub_mat4`).
macro_rules! columns {
    (
        $m:ident, $v:ident, $d:literal, $n:literal,
        glam($mul_m:ident, $mul_v:ident, $add_m:ident, $sub_m:ident),
        { $c0:ident: $f0:ident $(, $c:ident: $f:ident)* }
    ) => {
        impl $m {
            /// Every entry zero.
            pub const ZERO: Self = Self { cols: [$v::ZERO; $d] };
            /// Every entry NaN: what [`col`](Self::col) and
            /// [`row`](Self::row) answer for an index out of range, in each
            /// of their components.
            pub const NAN: Self = Self { cols: [$v::NAN; $d] };

            /// Builds a matrix from its rows (glam's `from_rows`): the
            /// transpose of the matrix of those columns.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            #[doc = concat!("let [", stringify!($c0) $(, ", ", stringify!($c))*, "] = core::array::from_fn(|i| m.row(i));")]
            #[doc = concat!("assert_eq!(M::from_rows(", stringify!($c0) $(, ", ", stringify!($c))*, "), m);")]
            /// ```
            #[inline]
            #[must_use]
            pub const fn from_rows($c0: $v $(, $c: $v)*) -> Self {
                Self::from_cols($c0 $(, $c)*).transpose()
            }

            /// Builds a matrix from its entries in row-major order (glam's
            /// `from_rows_array`), the inverse of
            /// [`to_rows_array`](Self::to_rows_array).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(M::from_rows_array(&m.to_rows_array()), m);
            /// assert_eq!(M::from_rows_array(&m.to_cols_array()), m.transpose());
            /// ```
            #[inline]
            #[must_use]
            pub const fn from_rows_array(m: &[f32; $n]) -> Self {
                Self::from_cols_array(m).transpose()
            }

            /// The entries in row-major order (glam's `to_rows_array`), as
            /// APIs that take rows want them; the crate's arrays are
            /// column-major.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(m.to_rows_array()[1], m.row(0)[1]);
            /// ```
            #[inline]
            #[must_use]
            pub const fn to_rows_array(self) -> [f32; $n] {
                self.transpose().to_cols_array()
            }

            /// Builds a matrix from an array of its columns' arrays (glam's
            /// `from_cols_array_2d`), the inverse of
            /// [`to_cols_array_2d`](Self::to_cols_array_2d).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(M::from_cols_array_2d(&m.to_cols_array_2d()), m);
            /// ```
            #[inline]
            #[must_use]
            pub const fn from_cols_array_2d(m: &[[f32; $d]; $d]) -> Self {
                let [$c0 $(, $c)*] = *m;
                Self::from_cols($v::from_array($c0) $(, $v::from_array($c))*)
            }

            /// The columns as arrays (glam's `to_cols_array_2d`): `m[i][j]`
            /// is the entry in column `i`, row `j`.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            /// assert_eq!(m.to_cols_array_2d()[1], m.col(1).to_array());
            /// ```
            #[inline]
            #[must_use]
            pub const fn to_cols_array_2d(self) -> [[f32; $d]; $d] {
                let [$c0 $(, $c)*] = self.cols;
                [$c0.to_array() $(, $c.to_array())*]
            }

            /// The matrix with `diagonal` on its diagonal and zeros
            /// elsewhere (glam's `from_diagonal`): the scale by each
            /// component.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_diagonal(V::splat(2.0));
            /// assert_eq!(m * V::ONE, V::splat(2.0));
            /// assert_eq!(M::from_diagonal(V::ONE), M::IDENTITY);
            /// ```
            #[inline]
            #[must_use]
            pub const fn from_diagonal(diagonal: $v) -> Self {
                Self::from_cols(
                    $v { $f0: diagonal.$f0, ..$v::ZERO }
                    $(, $v { $f: diagonal.$f, ..$v::ZERO })*
                )
            }

            /// The entries on the diagonal (glam's `diagonal`).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::IDENTITY.diagonal(), V::ONE);
            /// ```
            #[inline]
            #[must_use]
            pub const fn diagonal(self) -> $v {
                let [$c0 $(, $c)*] = self.cols;
                $v { $f0: $c0.$f0 $(, $f: $c.$f)* }
            }

            /// The rotation by `angle` radians about `axis` (glam's
            /// `from_axis_angle`): the rotation matrix of
            /// [`Quat::from_axis_angle(axis, angle)`](crate::Quat::from_axis_angle).
            ///
            /// # Preconditions
            ///
            /// Those of [`Quat::from_axis_angle`](crate::Quat::from_axis_angle):
            /// `axis` need not be of unit length (glam asks that it be); a
            /// zero axis gives the identity, a NaN or infinite input NaN
            /// entries.
            ///
            /// # Accuracy
            ///
            /// Each entry within
            /// [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
            /// of the exact rotation matrix of that quaternion.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use core::f32::consts::FRAC_PI_2;
            /// let m = M::from_axis_angle(rigtform::Cvec3::Z, FRAC_PI_2);
            /// assert!((m * V::X - V::Y).norm() < 1e-6);
            /// ```
            #[must_use]
            pub fn from_axis_angle(axis: $crate::Cvec3, angle: f32) -> Self {
                Self::from_quat($crate::Quat::from_axis_angle(axis, angle))
            }

            /// The rotation by `angle` radians about the x axis (glam's
            /// `from_rotation_x`): the rotation matrix of
            /// [`Quat::from_rotation_x`](crate::Quat::from_rotation_x), each
            /// entry within
            /// [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
            /// of that quaternion's exact matrix.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use core::f32::consts::FRAC_PI_2;
            /// assert!((M::from_rotation_x(FRAC_PI_2) * V::Y - V::Z).norm() < 1e-6);
            /// ```
            #[must_use]
            pub fn from_rotation_x(angle: f32) -> Self {
                Self::from_quat($crate::Quat::from_rotation_x(angle))
            }

            /// As [`from_rotation_x`](Self::from_rotation_x), about y.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use core::f32::consts::FRAC_PI_2;
            /// assert!((M::from_rotation_y(FRAC_PI_2) * V::Z - V::X).norm() < 1e-6);
            /// ```
            #[must_use]
            pub fn from_rotation_y(angle: f32) -> Self {
                Self::from_quat($crate::Quat::from_rotation_y(angle))
            }

            /// As [`from_rotation_x`](Self::from_rotation_x), about z.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use core::f32::consts::FRAC_PI_2;
            /// assert!((M::from_rotation_z(FRAC_PI_2) * V::X - V::Y).norm() < 1e-6);
            /// ```
            #[must_use]
            pub fn from_rotation_z(angle: f32) -> Self {
                Self::from_quat($crate::Quat::from_rotation_z(angle))
            }

            /// The rotation of the Euler angles `a`, `b`, `c` in `order`
            /// (glam's `from_euler`): the rotation matrix of
            /// [`Quat::from_euler`](crate::Quat::from_euler), with its
            /// conventions (intrinsic, first axis first).
            ///
            /// # Accuracy
            ///
            /// Each entry within
            /// [`accuracy::MATRIX_ENTRY_ERROR`](crate::accuracy::MATRIX_ENTRY_ERROR)
            /// of the exact rotation matrix of that quaternion.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use rigtform::EulerRot;
            /// assert_eq!(M::from_euler(EulerRot::ZYX, 0.5, 0.0, 0.0), M::from_rotation_z(0.5));
            /// ```
            #[must_use]
            pub fn from_euler(order: $crate::EulerRot, a: f32, b: f32, c: f32) -> Self {
                Self::from_quat($crate::Quat::from_euler(order, a, b, c))
            }

            /// The Euler angles in `order` of the rotation in the upper-left
            /// 3x3 block (glam's `to_euler`):
            /// [`Quat::to_euler`](crate::Quat::to_euler) of
            /// [`Quat::from_mat3`](crate::Quat::from_mat3) of the block.
            ///
            /// # Preconditions
            ///
            /// The block is a rotation matrix, as for
            /// [`Quat::from_matrix`](crate::Quat::from_matrix); a scale or a
            /// shear gives angles of no meaning, a NaN or infinite entry NaN
            /// angles.
            ///
            /// # Accuracy
            ///
            /// The rotation of the angles within
            /// [`accuracy::FROM_MATRIX_MAX_ANGLE_ERROR`](crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR)
            /// plus [`accuracy::EULER_MAX_ANGLE_ERROR`](crate::accuracy::EULER_MAX_ANGLE_ERROR)
            /// radians of the block's.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use rigtform::EulerRot;
            /// let (z, y, x) = M::from_euler(EulerRot::ZYX, 0.3, -0.2, 0.1).to_euler(EulerRot::ZYX);
            /// assert!((z - 0.3).abs() < 1e-6 && (y + 0.2).abs() < 1e-6 && (x - 0.1).abs() < 1e-6);
            /// ```
            #[must_use]
            pub fn to_euler(self, order: $crate::EulerRot) -> (f32, f32, f32) {
                $crate::Quat::from_mat3($crate::Matrix3::from(self)).to_euler(order)
            }

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
            /// assert!(M::IDENTITY.is_finite() && !M::NAN.is_finite());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_finite(self) -> bool {
                self.cols.iter().all(|c| c.is_finite())
            }

            /// `true` if any entry is NaN (glam's `is_nan`).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert!(M::NAN.is_nan() && !M::from_diagonal(V::splat(f32::INFINITY)).is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_nan(self) -> bool {
                self.cols.iter().any(|c| c.is_nan())
            }

            /// Every entry's absolute value (glam's `abs`).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!((-M::IDENTITY).abs(), M::IDENTITY);
            /// ```
            #[inline]
            #[must_use]
            pub fn abs(self) -> Self {
                self.map_cols($v::abs)
            }

            /// glam's `try_inverse`: the inverse, or `None` where there is
            /// none to give, which is what [`inverse`](Self::inverse)
            /// returns here (glam's `inverse` returns a matrix: non-finite
            /// entries for a singular one, or a panic with glam's assert
            /// features).
            ///
            /// # Preconditions and accuracy
            ///
            /// Those of [`inverse`](Self::inverse).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_diagonal(V::splat(2.0));
            /// assert_eq!(m.try_inverse(), m.inverse());
            /// assert_eq!(M::ZERO.try_inverse(), None);
            /// ```
            #[inline]
            #[must_use]
            pub fn try_inverse(self) -> Option<Self> {
                self.inverse()
            }

            /// The inverse, or the zero matrix where there is none to give
            /// (glam's `inverse_or_zero`).
            ///
            /// # Preconditions and accuracy
            ///
            /// Those of [`inverse`](Self::inverse): zero wherever it is
            /// `None`.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::from_diagonal(V::splat(2.0)).inverse_or_zero(), M::from_diagonal(V::splat(0.5)));
            /// assert_eq!(M::NAN.inverse_or_zero(), M::ZERO);
            /// ```
            #[inline]
            #[must_use]
            pub fn inverse_or_zero(self) -> Self {
                self.inverse().unwrap_or(Self::ZERO)
            }

            #[doc = concat!("`self * rhs`, glam's `", stringify!($mul_m), "` (which takes `rhs` by reference, as here).")]
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            #[doc = concat!("assert_eq!(m.", stringify!($mul_m), "(&m), m * m);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn $mul_m(self, rhs: &Self) -> Self {
                self * *rhs
            }

            #[doc = concat!("`self * rhs` for a column vector, glam's `", stringify!($mul_v), "`.")]
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// let m = M::from_cols_array(&core::array::from_fn(|i| i as f32));
            #[doc = concat!("assert_eq!(m.", stringify!($mul_v), "(V::ONE), m * V::ONE);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn $mul_v(self, rhs: $v) -> $v {
                self * rhs
            }

            #[doc = concat!("`self + rhs`, glam's `", stringify!($add_m), "` (which takes `rhs` by reference, as here).")]
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            #[doc = concat!("assert_eq!(M::IDENTITY.", stringify!($add_m), "(&M::IDENTITY), M::IDENTITY * 2.0);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn $add_m(self, rhs: &Self) -> Self {
                self + *rhs
            }

            #[doc = concat!("`self - rhs`, glam's `", stringify!($sub_m), "` (which takes `rhs` by reference, as here).")]
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            #[doc = concat!("assert_eq!(M::IDENTITY.", stringify!($sub_m), "(&M::IDENTITY), M::ZERO);")]
            /// ```
            #[inline]
            #[must_use]
            pub fn $sub_m(self, rhs: &Self) -> Self {
                self - *rhs
            }

            /// `self * rhs`, every entry times the scalar `rhs` (glam's
            /// `mul_scalar`).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::IDENTITY.mul_scalar(3.0), M::from_diagonal(V::splat(3.0)));
            /// ```
            #[inline]
            #[must_use]
            pub fn mul_scalar(self, rhs: f32) -> Self {
                self * rhs
            }

            /// `self / rhs`, every entry over the scalar `rhs` (glam's
            /// `div_scalar`; IEEE 754: by zero gives infinities or NaN,
            /// never a panic).
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::IDENTITY.div_scalar(2.0), M::from_diagonal(V::splat(0.5)));
            /// ```
            #[inline]
            #[must_use]
            pub fn div_scalar(self, rhs: f32) -> Self {
                self / rhs
            }

            /// `f` of each column.
            #[inline]
            fn map_cols(mut self, f: impl Fn($v) -> $v) -> Self {
                for c in &mut self.cols {
                    *c = f(*c);
                }
                self
            }

            /// `f` of each column and the same column of `other`.
            #[inline]
            fn zip_cols(mut self, other: Self, f: impl Fn($v, $v) -> $v) -> Self {
                for (c, o) in self.cols.iter_mut().zip(other.cols) {
                    *c = f(*c, o);
                }
                self
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

        impl From<$crate::Quat> for $m {
            /// The rotation matrix of a unit quaternion, as `from_quat`
            /// (nalgebra's `Matrix4::from(UnitQuaternion)`), with its
            /// preconditions and accuracy.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// use rigtform::Quat;
            /// let q = Quat::from_rotation_y(0.4);
            /// assert_eq!(M::from(q), M::from_quat(q));
            /// ```
            #[inline]
            fn from(q: $crate::Quat) -> Self {
                Self::from_quat(q)
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

        impl core::ops::Mul<f32> for $m {
            type Output = $m;

            /// Every entry times `s`.
            ///
            /// ```
            #[doc = $crate::matrix::template::example_uses!($m, $v)]
            /// assert_eq!(M::IDENTITY * 2.0, M::from_diagonal(V::splat(2.0)));
            /// assert_eq!(2.0 * M::IDENTITY, M::IDENTITY * 2.0);
            /// ```
            #[inline]
            fn mul(self, s: f32) -> $m {
                self.map_cols(|c| c * s)
            }
        }

        impl core::ops::Div<f32> for $m {
            type Output = $m;

            /// Every entry divided by `s` (IEEE 754: by zero gives
            /// infinities or NaN, never a panic).
            #[inline]
            fn div(self, s: f32) -> $m {
                self.map_cols(|c| c / s)
            }
        }

        impl core::ops::Add for $m {
            type Output = $m;

            /// Entry by entry.
            #[inline]
            fn add(self, o: $m) -> $m {
                self.zip_cols(o, |a, b| a + b)
            }
        }

        impl core::ops::Sub for $m {
            type Output = $m;

            /// Entry by entry.
            #[inline]
            fn sub(self, o: $m) -> $m {
                self.zip_cols(o, |a, b| a - b)
            }
        }

        impl core::ops::Neg for $m {
            type Output = $m;

            /// Every entry negated (exact).
            #[inline]
            fn neg(self) -> $m {
                self.map_cols(|c| -c)
            }
        }

        $crate::vec::arithmetic!($m, zero $m::ZERO);

        impl core::iter::Product for $m {
            /// The matrix product, from the identity, left to right.
            #[inline]
            fn product<I: Iterator<Item = $m>>(iter: I) -> $m {
                iter.fold($m::IDENTITY, |a, b| a * b)
            }
        }
    };
}

pub(super) use {columns, example_uses};
