//! IMU attitude: the exponential and logarithm maps of rotations, strapdown
//! gyro integration, a frame-rate independent attitude smoother and an
//! orientation filter that fuses gyroscope, accelerometer and
//! (optionally) magnetometer.
//!
//! # Conventions
//!
//! - An attitude `q` maps sensor (body) coordinates to earth coordinates:
//!   `v_earth = q * v_sensor`. The earth frame is ENU (x east, y north,
//!   z up), as in the BROAD dataset the filter is evaluated on.
//! - Gyro rates are in rad/s in the sensor frame, so strapdown integration
//!   multiplies on the right: `q[k+1] = q[k] * exp(omega dt / 2)`
//!   ([`Quat::integrate`](crate::Quat::integrate)).
//! - Accelerometers measure specific force, which points *up* at rest
//!   (about `+9.81` m/s² on the upward axis).
//! - Every time constant `tau` means the same thing: a first-order response
//!   that leaves `exp(-t / tau)` of a step after `t` seconds, implemented
//!   with the smoothing factor `alpha = 1 - exp(-dt / tau)` so that it does
//!   not depend on the sample rate.
//!
//! # Contents
//!
//! - [`Quat::from_scaled_axis`](crate::Quat::from_scaled_axis) and
//!   [`Quat::to_scaled_axis`](crate::Quat::to_scaled_axis): exponential and
//!   logarithm maps (rotation vector <-> quaternion), a Taylor series below
//!   0.316 rad so tiny angles keep full relative precision, consistent with
//!   [`Quat::pow`](crate::Quat::pow) within
//!   [`EXP_LOG_POW_MAX_ANGLE_ERROR`](crate::accuracy::EXP_LOG_POW_MAX_ANGLE_ERROR).
//! - [`Quat::integrate`](crate::Quat::integrate): one exact exponential-map
//!   step of body rates, `q * exp(omega dt / 2)`, renormalized, so chains of
//!   any length stay on the unit sphere.
//! - [`Smoother`]: a slerp low-pass with a time constant,
//!   `alpha = 1 - exp(-dt / tau)`, the same response at 100 Hz and 1 kHz.
//! - [`OrientationFilter`] with [`FilterParams`]: gyroscope + accelerometer
//!   (6D) and + magnetometer (9D) fusion with gyro-bias estimation (at rest,
//!   and in motion from the corrections, weighted as a Kalman filter weighs
//!   them), acceleration-magnitude gating, and a magnetometer that can only
//!   turn the heading, with a hard-iron estimate that learns a field fixed
//!   to the sensor (a magnet carried with it) while the sensor turns. The
//!   accelerometer is averaged in an almost inertial frame by a
//!   second-order Butterworth low-pass (VQF's central idea, in a simpler
//!   filter), where linear accelerations average out. 256 bytes of state;
//!   `cargo xtask filter-cost` counts its instructions per update on the
//!   emulated Cortex-M4F and CI holds them to 1,600 (6D) and 2,200 (9D)
//!   (the counts: the attitude block of `docs/performance.md`).
//! - Around the filter: the sensor mounting ([`AxesAlignment`], the 24
//!   right-angle mountings) and calibrations ([`InertialCalibration`],
//!   [`MagneticCalibration`]), the outputs (gravity, linear and earth
//!   acceleration, heading, Euler angles), the gyro's range and the recovery
//!   after it saturates, a fast start-up, and [`Diagnostics`].
//!
//! On seven recordings of the BROAD dataset, with one parameter set chosen
//! from physics ([`FilterParams::DEFAULT`]), the mean 6D inclination RMSE
//! is 0.684° (VQF 0.711°) and the mean 9D total 2.302° (VQF 2.723°); no
//! trial is above 1.04 times VQF's. The repository's `docs/attitude.md`
//! gives the method, each parameter's physics, what was tried, and the
//! filter's limits.
//!
//! # Examples
//!
//! A 9D update and a smoothed display attitude:
//!
//! ```
//! use rigtform::attitude::{FilterParams, OrientationFilter, Smoother};
//! use rigtform::{Cvec3, Quat};
//!
//! let mut filter = OrientationFilter::new(FilterParams::DEFAULT);
//! let mut display = Smoother::new(Quat::IDENTITY, 0.1); // 0.1 s time constant
//! let (gyr, acc, mag) = (Cvec3::ZERO, Cvec3::new(0.0, 0.0, 9.81), Cvec3::new(0.0, 16.0, -41.0));
//! let attitude = filter.update_with_mag(gyr, acc, mag, 0.0035); // rad/s, m/s², µT, s
//! let shown = display.update(attitude, 0.0035);
//! assert!(attitude.angle_to(Quat::IDENTITY) < 1e-6 && shown.is_finite());
//! ```
//!
//! Mounting and calibration, applied to each reading before the filter:
//!
//! ```
//! use rigtform::attitude::{AxesAlignment, Axis, InertialCalibration, MagneticCalibration};
//! use rigtform::Cvec3;
//! // The chip turned a quarter turn on the board: its x along the board's +y.
//! let mounting = AxesAlignment::new(Axis::PosY, Axis::NegX).unwrap();
//! let gyro = InertialCalibration { offset: Cvec3::new(0.01, 0.0, -0.02), ..InertialCalibration::IDENTITY };
//! let mag = MagneticCalibration { hard_iron: Cvec3::new(12.0, -3.0, 40.0), ..MagneticCalibration::IDENTITY };
//! let gyr = mounting.apply(gyro.apply(Cvec3::new(0.01, 0.5, -0.02)));
//! assert!((gyr - Cvec3::new(-0.5, 0.0, 0.0)).norm() < 1e-6);
//! let field = mounting.apply(mag.apply(Cvec3::new(12.0, 13.0, -1.0)));
//! assert_eq!(field, Cvec3::new(-16.0, 0.0, -41.0));
//! ```
//!
//! The outputs:
//!
//! ```
//! use rigtform::attitude::{FilterParams, OrientationFilter};
//! use rigtform::{Cvec3, EulerRot, Quat};
//! let f = OrientationFilter::with_attitude(FilterParams::DEFAULT, Quat::from_rotation_z(0.5));
//! let pushed = Cvec3::new(0.0, 2.0, 9.81); // 2 m/s² along the sensor's y
//! assert!((f.linear_acceleration(pushed) - Cvec3::new(0.0, 2.0, 0.0)).norm() < 1e-5);
//! assert!((f.heading() + 0.5).abs() < 1e-6); // 0.5 rad west of north
//! let (yaw, _pitch, _roll) = f.euler(EulerRot::ZYX);
//! assert!((yaw - 0.5).abs() < 1e-6);
//! ```
//!
//! Start-up, the gyro's range, and the recovery after a saturated reading:
//!
//! ```
//! use rigtform::attitude::{FilterParams, OrientationFilter};
//! use rigtform::Cvec3;
//! let range = 2000f32.to_radians(); // the gyro's full scale, 34.9 rad/s
//! let params = FilterParams { gyro_range: range, ..FilterParams::DEFAULT };
//! let mut f = OrientationFilter::new(params);
//! let g = Cvec3::new(0.0, 0.0, 9.81);
//! f.update(Cvec3::ZERO, g, 0.01);
//! assert!(f.diagnostics().initialising); // start-up: short time constants
//! for _ in 0..400 {
//!     f.update(Cvec3::ZERO, g, 0.01); // 4 s still
//! }
//! assert!(!f.diagnostics().initialising);
//! // A spin beyond the range: the reading sticks at full scale (a single
//! // reading there is taken for a glitch; from the second on, recovery).
//! f.update(Cvec3::new(range, 0.0, 0.0), g, 0.01);
//! f.update(Cvec3::new(range, 0.0, 0.0), g, 0.01);
//! let d = f.diagnostics();
//! assert!(d.gyro_saturated && d.recovering);
//! for _ in 0..400 {
//!     f.update(Cvec3::ZERO, g, 0.01); // still again
//! }
//! let d = f.diagnostics();
//! assert!(!d.gyro_saturated && !d.recovering); // tau_acc after the last saturated sample
//! let up = f.attitude() * (g * (1.0 / 9.81));
//! assert!((up - Cvec3::Z).norm() < 1e-3); // level again
//! ```
//!
//! The diagnostics a firmware logs:
//!
//! ```
//! use rigtform::attitude::{FilterParams, OrientationFilter};
//! use rigtform::Cvec3;
//! let mut f = OrientationFilter::new(FilterParams::DEFAULT);
//! let (g, field) = (Cvec3::new(0.0, 0.0, 9.81), Cvec3::new(0.0, 16.0, -41.0));
//! for _ in 0..400 {
//!     f.update_with_mag(Cvec3::ZERO, g, field, 0.01); // 4 s still
//! }
//! f.update_with_mag(Cvec3::ZERO, g, field * 2.0, 0.01); // a magnet nearby
//! let d = f.diagnostics();
//! assert!(d.resting && d.mag_ignored && !d.initialising && !d.acc_ignored);
//! ```

mod alignment;
mod calibration;
mod diagnostics;
mod filter;
mod low_pass;
mod outputs;
mod params;
mod smoother;

pub use alignment::{AxesAlignment, Axis};
pub use calibration::{InertialCalibration, MagneticCalibration};
pub use diagnostics::Diagnostics;
pub use filter::OrientationFilter;
pub use params::FilterParams;
pub use smoother::Smoother;
