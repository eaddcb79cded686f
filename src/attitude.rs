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
//!   logarithm maps, consistent with [`Quat::pow`](crate::Quat::pow).
//! - [`Quat::integrate`](crate::Quat::integrate): one exact step of body
//!   rates.
//! - [`Smoother`]: a slerp low-pass with a time constant.
//! - [`OrientationFilter`] with [`FilterParams`]: gyroscope + accelerometer
//!   (+ magnetometer) fusion with gyro-bias estimation.

mod alignment;
mod calibration;
mod diagnostics;
mod filter;
mod low_pass;
mod outputs;
mod params;
mod rest;
mod smoother;

pub use alignment::{AxesAlignment, Axis};
pub use calibration::{InertialCalibration, MagneticCalibration};
pub use diagnostics::Diagnostics;
pub use filter::OrientationFilter;
pub use params::FilterParams;
pub use smoother::Smoother;
