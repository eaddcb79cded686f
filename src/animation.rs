//! Keyframe samplers as glTF 2.0 defines them for node animation: a
//! [`Sampler`] over key times and key values, with glTF's three
//! [`Interpolation`]s (STEP, LINEAR and CUBICSPLINE), for rotations
//! ([`Quat`]) and for translations and scales ([`Cvec3`]).
//!
//! A glTF animation channel is an input accessor (key times in seconds,
//! strictly increasing) and an output accessor (key values), read here as
//! two slices; [`Sampler::new`] checks them once and [`Sampler::sample`]
//! evaluates the channel at any time, without allocating and without
//! panicking.
//!
//! # What each interpolation does
//!
//! Between keys `k` and `k + 1`, at times `t_k <= t < t_{k+1}`, with
//! `u = (t - t_k) / (t_{k+1} - t_k)`:
//!
//! - **STEP**: the value of key `k`, as stored.
//! - **LINEAR**: translations and scales `v_k (1 - u) + v_{k+1} u`;
//!   rotations [`Quat::slerp`]`(v_k, v_{k+1}, u)`.
//! - **CUBICSPLINE**: the cubic Hermite spline of the glTF specification
//!   (its appendix on interpolation): with `t_d = t_{k+1} - t_k`, `v_k` the
//!   value of key `k`, `b_k` its out-tangent and `a_{k+1}` the in-tangent of
//!   key `k + 1`,
//!
//!   `p(u) = (2u^3 - 3u^2 + 1) v_k + t_d (u^3 - 2u^2 + u) b_k + (-2u^3 + 3u^2) v_{k+1} + t_d (u^3 - u^2) a_{k+1}`,
//!
//!   evaluated component by component (for rotations on the four
//!   components of the quaternion), rotations then normalized. The values
//!   are laid out as glTF stores them: three per key, in-tangent, value,
//!   out-tangent, so a channel of `n` keys has `3 n` values.
//!
//! At a key's time the result is that key's value as stored, as the
//! specification requires. Before the first key the result is the first
//! key's value, from the last key's time on the last key's value (clamped,
//! as glTF viewers do; the specification leaves it to the viewer). With one
//! key every time gives that key.
//!
//! # Rotations more than a half turn apart
//!
//! `q` and `-q` are the same rotation, and two keys `a`, `b` whose
//! quaternion dot product is negative lie more than a half turn apart as
//! stored. LINEAR goes through [`Quat::slerp`], which always takes the
//! short way: it turns from `a` towards `-b`, by the angle between the two
//! rotations, which is at most a half turn. The glTF specification's
//! spherical linear interpolation does the same (it takes the absolute
//! value of the dot product for the angle and its sign for `b`), and so does
//! three.js (`Quaternion.slerpFlat` negates `b` when the dot product is
//! negative). An animation that is meant to turn by more than a half turn
//! between two keys cannot be written with LINEAR keys in any of the three:
//! the exporter has to add keys in between. Keys exactly a half turn apart
//! (dot product zero, up to rounding) have no short way; slerp then follows
//! the sign of the rounded dot product, as the specification and three.js
//! do.
//!
//! CUBICSPLINE rotations are not sign-aligned, by the specification and in
//! three.js alike: the spline runs through the four components as stored,
//! so keys `q` and `-q` give different paths. [`Sampler::sample`] follows
//! that. A Hermite sum that is zero (keys `q` and `-q` with zero tangents,
//! halfway) or that cannot be normalized gives [`Quat::IDENTITY`], as
//! three.js's `Quaternion.normalize` does for zero.
//!
//! # Where three.js and the specification differ
//!
//! three.js (`Interpolant.evaluate`, `QuaternionLinearInterpolant`,
//! `DiscreteInterpolant`, and its glTF loader's
//! `GLTFCubicSplineInterpolant` and `GLTFCubicSplineQuaternionInterpolant`)
//! evaluates the same formulas, in f64, rounding its results to f32. The
//! differences this crate has to choose between:
//!
//! - At a key's time the specification requires the key's value as-is.
//!   three.js evaluates the segment that starts there at `u = 0` instead:
//!   the same value, but normalized for CUBICSPLINE rotations (a rounding
//!   difference for unit keys, none for the others). This crate follows
//!   the specification.
//! - Beyond the keys three.js copies the first or last value as stored,
//!   not normalized; the specification says nothing. This crate does as
//!   three.js.
//! - The specification asks for unit rotation keys; three.js does not
//!   check. This crate does not either (see the preconditions of
//!   [`Sampler::sample`]).
//! - The specification requires key times to be strictly increasing (and
//!   not negative), every value finite and two keys at least for
//!   CUBICSPLINE; three.js checks none of it. [`Sampler::new`] rejects
//!   times that are not finite and strictly increasing, values that are
//!   not finite and counts that do not fit, with a [`SamplerError`]; it
//!   accepts negative times and a single CUBICSPLINE key (its value at
//!   every time), whose meaning is plain.
//!
//! `cargo xtask gltf-check` samples the same channels with three.js and
//! with these samplers and compares every sample (`tools/gltf-check/`),
//! holding both to 1e-6 (rad for rotations).
//!
//! # Examples
//!
//! ```
//! use core::f32::consts::PI;
//! use rigtform::animation::{Interpolation, Sampler};
//! use rigtform::{Cvec3, Quat};
//!
//! // A rotation channel as glTF stores it: key times and x, y, z, w values.
//! let times = [0.0, 1.0, 2.0];
//! let xyzw = [[0.0, 0.0, 0.0, 1.0], [0.0, 0.70710677, 0.0, 0.70710677], [0.0, 1.0, 0.0, 0.0]];
//! let keys = xyzw.map(|a| Quat { x: a[0], y: a[1], z: a[2], w: a[3] });
//! let rotation = Sampler::new(Interpolation::Linear, &times, &keys).unwrap();
//! let halfway = rotation.sample(0.5);
//! assert!(halfway.angle_to(Quat::from_rotation_y(PI / 4.0)) < 1e-6);
//! assert_eq!(rotation.sample(-3.0), keys[0]); // clamped
//!
//! // A translation with STEP keys.
//! let steps = [Cvec3::ZERO, Cvec3::X, Cvec3::Y];
//! let translation = Sampler::new(Interpolation::Step, &times, &steps).unwrap();
//! assert_eq!(translation.sample(1.7), Cvec3::X);
//! ```

use crate::{Cvec3, Quat};

/// How a glTF animation sampler interpolates between keys: the
/// `interpolation` property of a glTF animation sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// glTF's `STEP`: the value of the key at or before the time.
    Step,
    /// glTF's `LINEAR`: linear interpolation for translations and scales,
    /// [`Quat::slerp`] for rotations.
    Linear,
    /// glTF's `CUBICSPLINE`: the cubic Hermite spline of the specification,
    /// with an in-tangent, a value and an out-tangent per key.
    CubicSpline,
}

impl Interpolation {
    /// How many values a key takes: 3 for [`Interpolation::CubicSpline`]
    /// (in-tangent, value, out-tangent), 1 otherwise.
    ///
    /// ```
    /// use rigtform::animation::Interpolation;
    /// assert_eq!(Interpolation::CubicSpline.values_per_key(), 3);
    /// assert_eq!(Interpolation::Step.values_per_key(), 1);
    /// ```
    #[must_use]
    pub const fn values_per_key(self) -> usize {
        match self {
            Self::CubicSpline => 3,
            Self::Step | Self::Linear => 1,
        }
    }
}

/// Why [`Sampler::new`] rejected a channel. Indices count keys (times), or
/// values for [`SamplerError::NonFiniteValue`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerError {
    /// There are no key times.
    NoKeys,
    /// The key time at this index is NaN or infinite.
    NonFiniteTime(usize),
    /// The key time at this index is not greater than the one before it
    /// (glTF requires strictly increasing times).
    TimesNotIncreasing(usize),
    /// The interval that ends at this key is too long for an f32 (the
    /// difference of the two times overflows).
    IntervalTooLong(usize),
    /// The number of values is not the number of keys times the values per
    /// key of the interpolation.
    LengthMismatch {
        /// How many values the keys and the interpolation ask for.
        expected: usize,
        /// How many values there are.
        found: usize,
    },
    /// The value at this index (of the values slice) has a NaN or infinite
    /// component.
    NonFiniteValue(usize),
}

impl core::fmt::Display for SamplerError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            Self::NoKeys => write!(f, "the sampler has no key times"),
            Self::NonFiniteTime(i) => write!(f, "key time {i} is not finite"),
            Self::TimesNotIncreasing(i) => {
                write!(f, "key time {i} is not greater than the one before it")
            }
            Self::IntervalTooLong(i) => {
                write!(f, "the interval ending at key time {i} overflows an f32")
            }
            Self::LengthMismatch { expected, found } => {
                write!(f, "expected {expected} key values, found {found}")
            }
            Self::NonFiniteValue(i) => write!(f, "key value {i} is not finite"),
        }
    }
}

mod sealed {
    use crate::{Cvec3, Quat};
    use core::ops::{Add, Mul};

    /// What a [`super::Sampler`] needs of its values; implemented for
    /// [`Quat`] and [`Cvec3`] only.
    pub trait Value: Copy {
        /// The result of sampling at a NaN time.
        const NAN: Self;
        /// Every component finite.
        fn finite(self) -> bool;
        /// LINEAR between `a` and `b` at `u` in [0, 1].
        fn linear(a: Self, b: Self, u: f32) -> Self;
        /// `s[0] p0 + s[1] m0 + s[2] p1 + s[3] m1`, component by component,
        /// where the tangents `m0` and `m1` are `td` times the stored ones,
        /// then normalized for rotations. Evaluated as `(s[0] p0 + s[2] p1)
        /// + td (s[1] b0 + s[3] a1)`: the weighted tangents cannot overflow
        /// (the two weights sum to at most 0.3 in magnitude), and where `td`
        /// times them does, the result is infinite, never NaN (`0 * inf`
        /// at a segment's end, or `inf - inf`, would be).
        fn hermite(p0: Self, b0: Self, p1: Self, a1: Self, td: f32, s: [f32; 4]) -> Self;
    }

    /// The sum of [`Value::hermite`], component by component (as vectors:
    /// each operation is the same IEEE 754 operation on every component).
    fn hermite_sum<T>(p0: T, b0: T, p1: T, a1: T, td: f32, s: [f32; 4]) -> T
    where
        T: Add<Output = T> + Mul<f32, Output = T>,
    {
        (p0 * s[0] + p1 * s[2]) + (b0 * s[1] + a1 * s[3]) * td
    }

    impl Value for Quat {
        const NAN: Self = Quat::NAN;
        fn finite(self) -> bool {
            self.is_finite()
        }
        fn linear(a: Self, b: Self, u: f32) -> Self {
            a.slerp(b, u)
        }
        fn hermite(p0: Self, b0: Self, p1: Self, a1: Self, td: f32, s: [f32; 4]) -> Self {
            hermite_sum(p0, b0, p1, a1, td, s)
                .try_normalize()
                .unwrap_or(Quat::IDENTITY)
        }
    }

    impl Value for Cvec3 {
        const NAN: Self = Cvec3::NAN;
        fn finite(self) -> bool {
            self.is_finite()
        }
        fn linear(a: Self, b: Self, u: f32) -> Self {
            a.lerp(b, u)
        }
        fn hermite(p0: Self, b0: Self, p1: Self, a1: Self, td: f32, s: [f32; 4]) -> Self {
            hermite_sum(p0, b0, p1, a1, td, s)
        }
    }
}

/// The values a [`Sampler`] interpolates: [`Quat`] (rotations) and
/// [`Cvec3`] (translations and scales). Sealed: no other type implements it.
pub trait Keyframe: sealed::Value {}
impl Keyframe for Quat {}
impl Keyframe for Cvec3 {}

/// One glTF animation channel's keys, checked: key times (seconds,
/// strictly increasing, finite) and key values (finite), with their
/// [`Interpolation`]. Borrows the slices; never allocates.
///
/// See the [module docs](self) for the formulas, the clamping, and how
/// this compares with the glTF specification and three.js.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sampler<'a, T: Keyframe> {
    interpolation: Interpolation,
    times: &'a [f32],
    values: &'a [T],
}

impl<'a, T: Keyframe> Sampler<'a, T> {
    /// Checks a channel's key times and values and keeps them.
    ///
    /// `values` holds one value per key for [`Interpolation::Step`] and
    /// [`Interpolation::Linear`], three per key (in-tangent, value,
    /// out-tangent, as glTF lays them out) for
    /// [`Interpolation::CubicSpline`]. Rotations built from glTF data
    /// (x, y, z, w) are best written with named fields,
    /// `Quat { x: a[0], y: a[1], z: a[2], w: a[3] }`.
    ///
    /// # Errors
    ///
    /// In this order: [`SamplerError::NoKeys`] for no times;
    /// [`SamplerError::NonFiniteTime`] for a NaN or infinite time;
    /// [`SamplerError::TimesNotIncreasing`] for a time not greater than the
    /// one before (unsorted or repeated); [`SamplerError::IntervalTooLong`]
    /// where two neighbouring times are more than `f32::MAX` apart;
    /// [`SamplerError::LengthMismatch`] where the number of values does not
    /// fit; [`SamplerError::NonFiniteValue`] for a value with a NaN or
    /// infinite component. Never panics.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler, SamplerError};
    /// use rigtform::Cvec3;
    /// let values = [Cvec3::ZERO, Cvec3::X];
    /// assert!(Sampler::new(Interpolation::Linear, &[0.0, 1.0], &values).is_ok());
    /// assert_eq!(
    ///     Sampler::new(Interpolation::Linear, &[1.0, 0.0], &values),
    ///     Err(SamplerError::TimesNotIncreasing(1))
    /// );
    /// assert_eq!(
    ///     Sampler::new(Interpolation::CubicSpline, &[0.0, 1.0], &values),
    ///     Err(SamplerError::LengthMismatch { expected: 6, found: 2 })
    /// );
    /// assert_eq!(Sampler::<Cvec3>::new(Interpolation::Step, &[], &[]), Err(SamplerError::NoKeys));
    /// ```
    pub fn new(
        interpolation: Interpolation,
        times: &'a [f32],
        values: &'a [T],
    ) -> Result<Self, SamplerError> {
        if times.is_empty() {
            return Err(SamplerError::NoKeys);
        }
        if let Some(i) = times.iter().position(|t| !t.is_finite()) {
            return Err(SamplerError::NonFiniteTime(i));
        }
        let mut before = f32::NEG_INFINITY;
        for (i, &t) in times.iter().enumerate() {
            // Every time is finite by now.
            if t <= before {
                return Err(SamplerError::TimesNotIncreasing(i));
            }
            if i > 0 && !(t - before).is_finite() {
                return Err(SamplerError::IntervalTooLong(i));
            }
            before = t;
        }
        let expected = times.len().saturating_mul(interpolation.values_per_key());
        if values.len() != expected {
            return Err(SamplerError::LengthMismatch {
                expected,
                found: values.len(),
            });
        }
        if let Some(i) = values.iter().position(|v| !v.finite()) {
            return Err(SamplerError::NonFiniteValue(i));
        }
        Ok(Self {
            interpolation,
            times,
            values,
        })
    }

    /// The interpolation.
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler};
    /// let s = Sampler::new(Interpolation::Step, &[0.0], &[rigtform::Cvec3::X]).unwrap();
    /// assert_eq!(s.interpolation(), Interpolation::Step);
    /// ```
    #[must_use]
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// The key times.
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler};
    /// let s = Sampler::new(Interpolation::Step, &[0.5], &[rigtform::Cvec3::X]).unwrap();
    /// assert_eq!(s.times(), &[0.5]);
    /// ```
    #[must_use]
    pub fn times(&self) -> &'a [f32] {
        self.times
    }

    /// The key values (three per key for CUBICSPLINE: in-tangent, value,
    /// out-tangent).
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler};
    /// let s = Sampler::new(Interpolation::Step, &[0.5], &[rigtform::Cvec3::X]).unwrap();
    /// assert_eq!(s.values(), &[rigtform::Cvec3::X]);
    /// ```
    #[must_use]
    pub fn values(&self) -> &'a [T] {
        self.values
    }

    /// The first and last key times: the span in which the channel moves.
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler};
    /// use rigtform::Cvec3;
    /// let s = Sampler::new(Interpolation::Linear, &[0.5, 2.0], &[Cvec3::X, Cvec3::Y]).unwrap();
    /// assert_eq!(s.span(), (0.5, 2.0));
    /// ```
    #[must_use]
    pub fn span(&self) -> (f32, f32) {
        let first = self.times.first().copied().unwrap_or(0.0);
        let last = self.times.last().copied().unwrap_or(first);
        (first, last)
    }

    /// The value of key `k`: the middle of its three values for
    /// CUBICSPLINE. `k` is always a key here; the fallback is unreachable.
    fn key(&self, k: usize) -> T {
        let i = k
            .saturating_mul(self.interpolation.values_per_key())
            .saturating_add(usize::from(
                self.interpolation == Interpolation::CubicSpline,
            ));
        self.values.get(i).copied().unwrap_or(T::NAN)
    }

    /// The channel's value at time `t` (seconds).
    ///
    /// - Before the first key time: the first key's value; at or after the
    ///   last key time: the last key's value (as stored, not normalized).
    /// - At a key's time: that key's value, as stored (the specification
    ///   asks for the value as-is, without interpolation).
    /// - Between two keys: the [interpolation](Interpolation) of the
    ///   [module docs](self).
    /// - A NaN `t` gives NaN (`Quat::NAN`, `Cvec3::NAN`).
    ///
    /// # Preconditions
    ///
    /// Rotation keys of unit norm (within rounding), as glTF requires; the
    /// sampler does not check it. With keys of norm other than 1, STEP and
    /// the clamped ends return them as they are, LINEAR returns what
    /// [`Quat::slerp`] makes of them and CUBICSPLINE normalizes. No
    /// allocation, no panic, for any `t`; the time is found by bisection,
    /// `O(log n)` in the number of keys.
    ///
    /// # Accuracy
    ///
    /// Against the same evaluation in f64 from the same f32 keys and time
    /// (`tests/animation.rs`): LINEAR rotations within
    /// [`accuracy::SAMPLER_LINEAR_MAX_ANGLE_ERROR`](crate::accuracy::SAMPLER_LINEAR_MAX_ANGLE_ERROR)
    /// and CUBICSPLINE rotations within
    /// [`accuracy::SAMPLER_CUBIC_MAX_ANGLE_ERROR`](crate::accuracy::SAMPLER_CUBIC_MAX_ANGLE_ERROR)
    /// radians; translations and scales within
    /// [`accuracy::SAMPLER_VEC3_MAX_REL_ERROR`](crate::accuracy::SAMPLER_VEC3_MAX_REL_ERROR)
    /// of the largest magnitude among the segment's values and tangents
    /// (times the interval, for tangents). STEP is exact.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::animation::{Interpolation, Sampler};
    /// use rigtform::Cvec3;
    /// let times = [0.0, 2.0];
    /// // CUBICSPLINE: in-tangent, value, out-tangent for each key.
    /// let values = [Cvec3::ZERO, Cvec3::ZERO, Cvec3::ZERO, Cvec3::ZERO, Cvec3::X, Cvec3::ZERO];
    /// let s = Sampler::new(Interpolation::CubicSpline, &times, &values).unwrap();
    /// assert_eq!(s.sample(1.0), Cvec3::new(0.5, 0.0, 0.0)); // smoothstep halfway
    /// assert_eq!(s.sample(0.0), Cvec3::ZERO);
    /// assert_eq!(s.sample(9.0), Cvec3::X);
    /// assert!(s.sample(f32::NAN).x.is_nan());
    /// ```
    #[must_use]
    pub fn sample(&self, t: f32) -> T {
        let (first, last) = self.span();
        if t.is_nan() {
            return T::NAN;
        }
        if t < first {
            return self.key(0);
        }
        let n = self.times.len();
        if t >= last {
            return self.key(n.saturating_sub(1));
        }
        // first <= t < last, so there are two keys at least and the first
        // key after t is one of 1..n.
        let k1 = self.times.partition_point(|&key| key <= t);
        let k0 = k1.saturating_sub(1);
        let (Some(&t0), Some(&t1)) = (self.times.get(k0), self.times.get(k1)) else {
            return T::NAN;
        };
        if t == t0 {
            // The specification: a requested time that is a key's time
            // takes that key's value as-is, without interpolation.
            return self.key(k0);
        }
        let td = t1 - t0;
        let u = (t - t0) / td;
        match self.interpolation {
            Interpolation::Step => self.key(k0),
            Interpolation::Linear => T::linear(self.key(k0), self.key(k1), u),
            Interpolation::CubicSpline => {
                let at = |i: usize| self.values.get(i).copied().unwrap_or(T::NAN);
                // k1 < n and the values are 3 n, so none of these saturate.
                let (i0, i1) = (k0.saturating_mul(3), k1.saturating_mul(3));
                let p0 = at(i0.saturating_add(1));
                let b0 = at(i0.saturating_add(2));
                let a1 = at(i1);
                let p1 = at(i1.saturating_add(1));
                let uu = u * u;
                let uuu = uu * u;
                let s2 = -2.0 * uuu + 3.0 * uu;
                let s3 = uuu - uu;
                let s0 = 1.0 - s2;
                let s1 = s3 - uu + u;
                T::hermite(p0, b0, p1, a1, td, [s0, s1, s2, s3])
            }
        }
    }
}
