//! What the vector types do with lengths and directions, written once as
//! the [`lengths!`] macro that [`coordinates!`](super::coordinates)
//! instances for each vector type: glam's and nalgebra's names for the
//! norm, distances, the projections and rejections, normalization with a
//! fallback, clamping a length, moving towards a point, and refraction.

/// The length and direction API of a vector type `$t` (one that has
/// `norm`, `try_normalize`, `dot`, the constants `ZERO`, `NAN` and `X`,
/// and the operators of [`euclidean!`](super::euclidean)).
macro_rules! lengths {
    ($t:ident) => {
        impl $t {
            /// The vector projection of `self` onto the line of `rhs`:
            /// `(self . u) u` with `u` the direction of `rhs` (glam's
            /// `project_onto`).
            ///
            /// # Preconditions
            ///
            /// `rhs` is finite and non-zero, and `self` finite; otherwise
            /// the result is NaN (never a panic). `rhs` need not be of unit
            /// length: it is normalized first, without overflow or
            /// underflow.
            ///
            /// # Accuracy
            ///
            /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
            /// times `|self|` of the exact projection of the f32 inputs
            /// (proven, for `|self|` from 2^-100; below, each rounding near
            /// underflow may add 2^-150).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let v = V::splat(3.0);
            /// assert_eq!(v.project_onto(V::Y * 10.0), V::Y * 3.0);
            /// assert!(v.project_onto(V::ZERO).is_nan());
            /// ```
            #[doc(alias = "project")]
            #[must_use]
            pub fn project_onto(self, rhs: Self) -> Self {
                match rhs.try_normalize() {
                    Some(u) => u * self.dot(u),
                    None => Self::NAN,
                }
            }

            /// The part of `self` perpendicular to `rhs`: `self` minus its
            /// [`project_onto`](Self::project_onto) `rhs` (glam's
            /// `reject_from`).
            ///
            /// # Preconditions
            ///
            /// As [`project_onto`](Self::project_onto): NaN for a zero or
            /// non-finite `rhs`.
            ///
            /// # Accuracy
            ///
            /// Within [`accuracy::PROJECT_MAX_REL_ERROR`](crate::accuracy::PROJECT_MAX_REL_ERROR)
            /// times `|self|` of the exact rejection (the error of the
            /// projection, and one rounding of the difference).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let v = V::splat(3.0);
            /// assert_eq!(v.reject_from(V::Y), v - V::Y * 3.0);
            /// ```
            #[doc(alias = "reject")]
            #[must_use]
            pub fn reject_from(self, rhs: Self) -> Self {
                self - self.project_onto(rhs)
            }

            /// `1 / |self|` (glam's `length_recip`): infinite for the zero
            /// vector, NaN for a NaN component.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::splat(0.5).length_recip(), 2.0 / V::ONE.norm());
            /// ```
            #[inline]
            #[must_use]
            pub fn length_recip(self) -> f32 {
                1.0 / self.norm()
            }

            /// `true` if the norm is within
            /// [`accuracy::IS_NORMALIZED_TOLERANCE`](crate::accuracy::IS_NORMALIZED_TOLERANCE)
            /// of 1, as [`Quat::is_normalized`](crate::Quat::is_normalized)
            /// (glam's `is_normalized`); `false` for NaN or infinite
            /// components.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert!(V::X.is_normalized());
            /// assert!(!V::ONE.is_normalized());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_normalized(self) -> bool {
                (self.norm_squared() - 1.0).abs() <= 2.0 * crate::accuracy::IS_NORMALIZED_TOLERANCE
            }

            /// glam's name for [`norm`](Self::norm): the Euclidean length,
            /// without intermediate overflow or underflow.
            ///
            /// # Accuracy
            ///
            /// As [`norm`](Self::norm).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::splat(2.0).length(), V::splat(2.0).norm());
            /// ```
            #[inline]
            #[must_use]
            pub fn length(self) -> f32 {
                self.norm()
            }

            /// glam's name for [`norm_squared`](Self::norm_squared).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::splat(2.0).length_squared(), V::splat(2.0).norm_squared());
            /// ```
            #[inline]
            #[must_use]
            pub fn length_squared(self) -> f32 {
                self.norm_squared()
            }

            /// The Euclidean distance `|self - other|`.
            ///
            /// # Accuracy
            ///
            /// [`norm`](Self::norm) of `self - other`, whose components are
            /// each rounded once (half an ulp): within 2 ulp of the length
            /// of that rounded difference. Infinite where a component of
            /// the difference overflows.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let (a, b) = (V::ONE, V::splat(4.0));
            /// assert_eq!(a.distance(b), (b - a).norm());
            /// ```
            #[inline]
            #[must_use]
            pub fn distance(self, other: Self) -> f32 {
                (self - other).norm()
            }

            /// The squared distance `|self - other|^2` (overflows beyond
            /// about 1.8e19, as [`norm_squared`](Self::norm_squared)).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let (a, b) = (V::ONE, V::splat(3.0));
            /// assert_eq!(a.distance_squared(b), (b - a).norm_squared());
            /// ```
            #[inline]
            #[must_use]
            pub fn distance_squared(self, other: Self) -> f32 {
                (self - other).norm_squared()
            }

            /// The unit vector in the direction of `self`, or the zero
            /// vector where there is none (zero, NaN or infinite input).
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ZERO.normalize_or_zero(), V::ZERO);
            /// assert_eq!(V::NAN.normalize_or_zero(), V::ZERO);
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize_or_zero(self) -> Self {
                self.normalize_or(Self::ZERO)
            }

            /// The unit vector in the direction of `self`, or `fallback`
            /// where there is none (zero, NaN or infinite input).
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ZERO.normalize_or(V::ONE), V::ONE);
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize_or(self, fallback: Self) -> Self {
                self.try_normalize().unwrap_or(fallback)
            }

            /// nalgebra's name for the crate's [`norm`](Self::norm) (glam's
            /// [`length`](Self::length)).
            ///
            /// ```
            /// # #![allow(deprecated)]
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ONE.magnitude(), V::ONE.norm());
            /// ```
            #[deprecated(note = "use `norm` (the notes' name) or `length` (glam's)")]
            #[inline]
            #[must_use]
            pub fn magnitude(self) -> f32 {
                self.norm()
            }

            /// nalgebra's name for the crate's
            /// [`norm_squared`](Self::norm_squared).
            ///
            /// ```
            /// # #![allow(deprecated)]
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ONE.magnitude_squared(), V::ONE.norm_squared());
            /// ```
            #[deprecated(
                note = "use `norm_squared` (the notes' name) or `length_squared` (glam's)"
            )]
            #[inline]
            #[must_use]
            pub fn magnitude_squared(self) -> f32 {
                self.norm_squared()
            }

            /// The vector projection of `self` onto the line of the unit
            /// vector `rhs`, `(self . rhs) rhs` (glam's
            /// `project_onto_normalized`), without normalizing `rhs` as
            /// [`project_onto`](Self::project_onto) does.
            ///
            /// # Preconditions
            ///
            /// `rhs` is of unit length (otherwise the result is scaled by
            /// its squared length).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let v = V::splat(3.0);
            /// assert_eq!(v.project_onto_normalized(V::Y), V::Y * 3.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn project_onto_normalized(self, rhs: Self) -> Self {
                rhs * self.dot(rhs)
            }

            /// The part of `self` perpendicular to the unit vector `rhs`:
            /// `self` minus its
            /// [`project_onto_normalized`](Self::project_onto_normalized)
            /// `rhs` (glam's `reject_from_normalized`), with its
            /// precondition.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// let v = V::splat(3.0);
            /// assert_eq!(v.reject_from_normalized(V::Y), v - V::Y * 3.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn reject_from_normalized(self, rhs: Self) -> Self {
                self - self.project_onto_normalized(rhs)
            }

            /// The unit vector in the direction of `self` and the length of
            /// `self` (glam's `normalize_and_length`), or `(X, 0)` where
            /// there is no direction (zero, NaN or infinite components), as
            /// glam. Both are found without overflow or underflow, so a
            /// huge or subnormal vector still has its direction (glam gives
            /// `(X, 0)` where its squared length overflows or underflows);
            /// the length is infinite where it is beyond `f32::MAX`.
            ///
            /// # Accuracy
            ///
            /// As [`try_normalize`](Self::try_normalize) and
            /// [`norm`](Self::norm).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!((V::Y * 3.0).normalize_and_length(), (V::Y, 3.0));
            /// assert_eq!(V::ZERO.normalize_and_length(), (V::X, 0.0));
            /// ```
            #[must_use]
            pub fn normalize_and_length(self) -> (Self, f32) {
                match self.try_normalize() {
                    Some(u) => (u, self.norm()),
                    None => (Self::X, 0.0),
                }
            }

            /// `self` with its length clamped to `[min, max]` (glam's
            /// `clamp_length`): the same direction, length `min` where it
            /// was shorter and `max` where it was longer, `self` otherwise.
            ///
            /// # Preconditions
            ///
            /// `0 <= min <= max` (glam asserts it; here, where
            /// `min > max`, a vector shorter than `min` gets length `min`
            /// and every other one `max`). A zero vector has no direction
            /// to lengthen: NaN where `min > 0`, as glam. So has one with
            /// an infinite component, where it is shortened; NaN in, NaN
            /// out.
            ///
            /// # Accuracy
            ///
            /// A clamped vector is `normalize() * min` (or `max`): its
            /// length within
            /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
            /// of the bound, relative, and one rounding of each component.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!((V::X * 10.0).clamp_length(1.0, 2.0), V::X * 2.0);
            /// assert_eq!((V::X * 0.5).clamp_length(1.0, 2.0), V::X);
            /// assert_eq!((V::X * 1.5).clamp_length(1.0, 2.0), V::X * 1.5);
            /// ```
            #[must_use]
            pub fn clamp_length(self, min: f32, max: f32) -> Self {
                let length = self.norm();
                if length < min {
                    self.normalize() * min
                } else if length > max {
                    self.normalize() * max
                } else {
                    self
                }
            }

            /// `self` with its length at most `max` (glam's
            /// `clamp_length_max`): [`clamp_length`](Self::clamp_length)
            /// with `min = 0`, its preconditions and accuracy.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!((V::X * 10.0).clamp_length_max(2.0), V::X * 2.0);
            /// assert_eq!(V::ZERO.clamp_length_max(2.0), V::ZERO);
            /// ```
            #[inline]
            #[must_use]
            pub fn clamp_length_max(self, max: f32) -> Self {
                self.clamp_length(0.0, max)
            }

            /// `self` with its length at least `min` (glam's
            /// `clamp_length_min`): [`clamp_length`](Self::clamp_length)
            /// with no upper bound, its preconditions and accuracy.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!((V::X * 0.5).clamp_length_min(2.0), V::X * 2.0);
            /// assert_eq!((V::X * 10.0).clamp_length_min(2.0), V::X * 10.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn clamp_length_min(self, min: f32) -> Self {
                self.clamp_length(min, f32::INFINITY)
            }

            /// The point `d` further from `self` towards `rhs`, or `rhs`
            /// itself where it is no further than `d` or closer than 1e-4
            /// (glam's `move_towards`, with glam's threshold): `self + (rhs
            /// - self) / |rhs - self| * d`. A negative `d` moves away.
            ///
            /// # Preconditions
            ///
            /// None: NaN in, NaN out; an infinite distance between the two
            /// gives NaN.
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// assert_eq!(V::ZERO.move_towards(V::X * 10.0, 2.0), V::X * 2.0);
            /// assert_eq!(V::ZERO.move_towards(V::X, 2.0), V::X);
            /// ```
            #[must_use]
            pub fn move_towards(self, rhs: Self, d: f32) -> Self {
                let a = rhs - self;
                let length = a.norm();
                if length <= d || length <= 1e-4 {
                    rhs
                } else {
                    self + a / length * d
                }
            }

            /// The direction of a ray `self` refracted through a surface of
            /// unit normal `normal` with the ratio of indices of refraction
            /// `eta` (glam's `refract`, GLSL's `refract`), or the zero
            /// vector for total internal reflection.
            ///
            /// # Preconditions
            ///
            /// `self` and `normal` are of unit length, `normal` facing the
            /// ray (`self . normal <= 0`). NaN in, NaN out (glam answers
            /// the zero vector for a NaN).
            ///
            /// ```
            #[doc = $crate::vec::example_uses!($t)]
            /// // Straight through, whatever the ratio.
            /// assert_eq!((-V::Y).refract(V::Y, 1.5), -V::Y);
            /// ```
            #[must_use]
            pub fn refract(self, normal: Self, eta: f32) -> Self {
                let n_dot_i = normal.dot(self);
                let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
                if k < 0.0 {
                    Self::ZERO
                } else {
                    self * eta - normal * (eta * n_dot_i + $crate::float::sqrt(k))
                }
            }
        }
    };
}

pub(crate) use lengths;
