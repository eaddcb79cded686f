//! The exponential and logarithm maps of rotations, and one step of gyro
//! integration built on them: [`Quat::from_scaled_axis`],
//! [`Quat::to_scaled_axis`], [`Quat::integrate`]. Consistent with the
//! power operator: `exp(a log q)` is `q.pow(a)`.

use super::power::Polar;
use super::Quat;
use crate::float;
use crate::vec::Cvec3;

/// Below this squared angle (0.1, an angle of 0.316 rad), `from_scaled_axis`
/// uses the Taylor series of `cos(theta/2)` and `sin(theta/2)/theta` to the
/// `theta^4` term. The first term left out is `theta^6/46080` (2.2e-8 at the
/// limit, below half an ulp of 1) for the cosine and `theta^6/645120` for
/// the sine factor: the series is as accurate as the kernels, needs no
/// square root or division, and is exact for subnormal angles, whose squares
/// vanish.
const SERIES_LIMIT: f32 = 0.1;

impl Quat {
    /// The exponential map: the rotation by `|v|` radians about the axis
    /// `v / |v|` (right-hand rule), `[cos(|v|/2), sin(|v|/2) v/|v|]`. This
    /// is `exp([0, v/2])` as a quaternion exponential, and the inverse of
    /// [`to_scaled_axis`](Self::to_scaled_axis).
    ///
    /// For angles below 0.316 rad (the common case of one gyro step) it
    /// evaluates a Taylor series with no square root, division or
    /// trigonometric function, within
    /// [`FROM_SCALED_AXIS_MAX_REL_ERROR`](crate::accuracy::FROM_SCALED_AXIS_MAX_REL_ERROR)
    /// of the angle relative to it, down to f32's normal range (1e-38 rad).
    ///
    /// # Preconditions
    ///
    /// None beyond finiteness: any length works (the angle is reduced
    /// exactly by the sine and cosine kernels), and the zero vector gives
    /// [`Quat::IDENTITY`]. A NaN or infinite component gives [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Rotation error at most
    /// [`accuracy::FROM_SCALED_AXIS_MAX_REL_ERROR`](crate::accuracy::FROM_SCALED_AXIS_MAX_REL_ERROR)
    /// times `|v|` radians (relative to the angle, from 1e-38 rad, f32's
    /// normal range, to 1000 rad; below, the subnormal components' products
    /// round absolutely), norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of 1
    /// (`scaled_axis_maps_are_within_their_bounds` in `tests/attitude.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::FRAC_PI_2;
    /// use rigtform::{Cvec3, Quat};
    /// let q = Quat::from_scaled_axis(Cvec3::new(0.0, 0.0, FRAC_PI_2));
    /// assert!(q.angle_to(Quat::from_rotation_z(FRAC_PI_2)) < 1e-6);
    /// // Tiny angles keep their full relative precision:
    /// let tiny = Quat::from_scaled_axis(Cvec3::new(2e-20, 0.0, 0.0));
    /// assert_eq!((tiny.w, tiny.x), (1.0, 1e-20));
    /// ```
    #[must_use]
    pub fn from_scaled_axis(v: Cvec3) -> Self {
        if !v.is_finite() {
            return Self::NAN;
        }
        let t2 = v.norm_squared();
        if t2 < SERIES_LIMIT {
            // cos(t/2) = 1 - t^2/8 + t^4/384, sin(t/2)/t = 1/2 - t^2/48 + t^4/3840.
            let w = 1.0 - t2 * (1.0 / 8.0 - t2 * (1.0 / 384.0));
            let s = 0.5 - t2 * (1.0 / 48.0 - t2 * (1.0 / 3840.0));
            return Self::from_scalar_vector(w, v * s);
        }
        // Half of each component first: the half-angle |v/2| cannot overflow,
        // even where |v| itself would (components near f32::MAX).
        let half_angle = (v * 0.5).norm();
        let (s, c) = float::sin_cos(half_angle);
        // v is finite and at least 0.316 long, so it has a direction.
        Self::from_scalar_vector(c, v.normalize() * s)
    }

    /// The logarithm map: the rotation vector `theta k` of this rotation,
    /// with `k` the unit axis and `theta = 2 atan2(|v|, w)` in [0, 2 pi]
    /// (the notes' `phi` of the "Power" section, doubled). It inverts
    /// [`from_scaled_axis`](Self::from_scaled_axis) for angles up to 2 pi,
    /// and is consistent with [`pow`](Self::pow):
    /// `Quat::from_scaled_axis(a * q.to_scaled_axis())` is `q.pow(a)`.
    ///
    /// Like `pow`, it does not conditionally negate: `q` and `-q` give
    /// vectors of angles `theta` and `2 pi - theta` about opposite axes (the
    /// same rotation). Use `q.cn().to_scaled_axis()` for the short way, a
    /// vector at most pi long.
    ///
    /// # Preconditions
    ///
    /// Any finite quaternion; it need not be unit (the angle comes from
    /// atan2, which is scale-free, and subnormal or huge components are
    /// scaled exactly). A pure real quaternion has no axis: `w >= 0` (and
    /// zero) gives the zero vector, `w < 0` (a turn by 2 pi) gives
    /// `[2 pi, 0, 0]`, the same choice of the x axis that `pow` makes. NaN
    /// or infinite input gives [`Cvec3::NAN`].
    ///
    /// # Accuracy
    ///
    /// Within [`accuracy::TO_SCALED_AXIS_MAX_REL_ERROR`](crate::accuracy::TO_SCALED_AXIS_MAX_REL_ERROR)
    /// times the vector's length, for unit input, from angles of 2^-99 to
    /// 2 pi (below, the result's components round absolutely, near or
    /// below f32's normal range); `from_scaled_axis(a * q.to_scaled_axis())` is within
    /// [`accuracy::EXP_LOG_POW_MAX_ANGLE_ERROR`](crate::accuracy::EXP_LOG_POW_MAX_ANGLE_ERROR)
    /// `* max(1, |a| theta)` radians of `q.pow(a)`
    /// (`tests/attitude.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat};
    /// let v = Cvec3::new(0.3, -0.2, 0.1);
    /// assert!((Quat::from_scaled_axis(v).to_scaled_axis() - v).norm() < 1e-7);
    /// // exp(a log q) is q^a:
    /// let q = Quat::from_rotation_y(2.0);
    /// let third = Quat::from_scaled_axis(q.to_scaled_axis() * (1.0 / 3.0));
    /// assert!(third.angle_to(q.pow(1.0 / 3.0)) < 1e-6);
    /// ```
    #[must_use]
    pub fn to_scaled_axis(self) -> Cvec3 {
        if !self.is_finite() {
            return Cvec3::NAN;
        }
        let Polar { axis, phi } = self.polar();
        axis * (2.0 * phi)
    }

    /// One step of strapdown gyro integration: `self * exp(omega dt / 2)`,
    /// renormalized. `self` maps body (sensor) coordinates to the reference
    /// (earth) frame and `omega` is the angular rate measured in the body
    /// frame, in rad/s, taken as constant over the step: the step is then
    /// exact (the exponential map, no first-order approximation), and the
    /// renormalization keeps a chain of any number of steps on the unit
    /// sphere.
    ///
    /// For a rate given in the reference frame, multiply on the left
    /// instead: `Quat::from_scaled_axis(omega * dt) * q`.
    ///
    /// # Preconditions
    ///
    /// `self` is a non-zero quaternion (a unit one, unless you want it
    /// normalized on the way). `dt = 0` returns `self` normalized; a
    /// negative `dt` integrates backwards in time. NaN or infinite `omega`
    /// or `dt`, a product `omega * dt` that overflows, or a zero or
    /// non-finite `self` give [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Each step is within [`accuracy::INTEGRATE_STEP_MAX_ANGLE_ERROR`](crate::accuracy::INTEGRATE_STEP_MAX_ANGLE_ERROR)
    /// radians of the exact rotation for steps `|omega dt|` up to 1 rad,
    /// and the norm within
    /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of 1 after any number of steps (`tests/attitude.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::{Cvec3, Quat};
    /// // Half a turn per second about z, for one second at 100 Hz:
    /// let omega = Cvec3::new(0.0, 0.0, PI);
    /// let mut q = Quat::IDENTITY;
    /// for _ in 0..100 {
    ///     q = q.integrate(omega, 0.01);
    /// }
    /// assert!(q.angle_to(Quat::from_rotation_z(PI)) < 1e-5);
    /// ```
    #[must_use]
    pub fn integrate(self, omega: Cvec3, dt: f32) -> Self {
        (self * Self::from_scaled_axis(omega * dt)).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy;
    use core::f32::consts::{PI, TAU};

    #[test]
    fn scaled_axis_of_edge_inputs() {
        assert_eq!(Quat::from_scaled_axis(Cvec3::ZERO), Quat::IDENTITY);
        assert_eq!(Quat::IDENTITY.to_scaled_axis(), Cvec3::ZERO);
        assert_eq!(
            Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).to_scaled_axis(),
            Cvec3::ZERO
        );
        assert_eq!(
            Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0).to_scaled_axis(),
            Cvec3::new(TAU, 0.0, 0.0)
        );
        assert!(!Quat::from_scaled_axis(Cvec3::new(f32::NAN, 0.0, 0.0)).is_finite());
        assert!(!Quat::from_scaled_axis(Cvec3::new(f32::INFINITY, 0.0, 0.0)).is_finite());
        assert!(!Quat::NAN.to_scaled_axis().is_finite());
        // Components near f32::MAX: a finite (if meaningless) unit result.
        let huge = Quat::from_scaled_axis(Cvec3::new(f32::MAX, f32::MAX, -f32::MAX));
        assert!(
            huge.is_finite() && (huge.norm() - 1.0).abs() < 1e-6,
            "{huge:?}"
        );
    }

    #[test]
    fn series_and_trigonometric_branches_meet_at_the_limit() {
        let limit = SERIES_LIMIT.sqrt();
        // An ulp of 1, or the backend's sine and cosine error if larger.
        let tol = accuracy::SIN_COS_MAX_ABS_ERROR.max(1.2e-7) as f64;
        for angle in [limit * (1.0 - 1e-6), limit, limit * (1.0 + 1e-6)] {
            let q = Quat::from_scaled_axis(Cvec3::new(0.0, angle, 0.0));
            let (s, c) = ((angle as f64) * 0.5).sin_cos();
            assert!((q.w as f64 - c).abs() <= tol, "{angle}: {q:?}");
            assert!((q.y as f64 - s).abs() <= tol, "{angle}: {q:?}");
        }
    }

    #[test]
    fn to_scaled_axis_does_not_take_the_short_way() {
        let q = Quat::from_rotation_x(0.5);
        let far = (-q).to_scaled_axis();
        let tol = accuracy::TO_SCALED_AXIS_MAX_REL_ERROR;
        assert!(
            (far - Cvec3::new(0.5 - TAU, 0.0, 0.0)).norm() <= tol * TAU,
            "{far:?}"
        );
        assert!(((-q).cn().to_scaled_axis() - Cvec3::new(0.5, 0.0, 0.0)).norm() <= tol * 0.5);
    }

    #[test]
    fn integrate_applies_body_rates_on_the_right() {
        // Turned a quarter about z, then a body rate about the body's x axis
        // turns about the reference frame's y axis.
        let q0 = Quat::from_rotation_z(PI / 2.0);
        let q = q0.integrate(Cvec3::new(1.0, 0.0, 0.0), 0.1);
        let want = Quat::from_rotation_y(0.1) * q0;
        assert!(q.angle_to(want) <= 4.0 * accuracy::INTEGRATE_STEP_MAX_ANGLE_ERROR);
        assert!(q0.angle_to(q) > 0.09);
    }

    #[test]
    fn integrate_of_bad_input_is_nan_and_zero_dt_normalizes() {
        let q = Quat::from_rotation_x(0.3);
        assert!(!q
            .integrate(Cvec3::new(f32::NAN, 0.0, 0.0), 0.01)
            .is_finite());
        assert!(!q.integrate(Cvec3::X, f32::INFINITY).is_finite());
        assert!(!q.integrate(Cvec3::X * 1e30, 1e30).is_finite());
        assert!(!Quat::from_wxyz(0.0, 0.0, 0.0, 0.0)
            .integrate(Cvec3::X, 0.01)
            .is_finite());
        let doubled = Quat::from_wxyz(2.0 * q.w, 2.0 * q.x, 0.0, 0.0);
        assert!(doubled.integrate(Cvec3::X, 0.0).angle_to(q) < 1e-7);
        assert!((doubled.integrate(Cvec3::X, 0.0).norm() - 1.0).abs() < 2.5e-7);
        // Backwards in time undoes a step forwards.
        let there = q.integrate(Cvec3::new(0.2, -1.0, 3.0), 0.05);
        assert!(
            there
                .integrate(Cvec3::new(0.2, -1.0, 3.0), -0.05)
                .angle_to(q)
                < 1e-6
        );
    }
}
