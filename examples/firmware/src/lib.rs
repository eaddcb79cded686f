//! What the firmwares of this crate share and what their host tests check:
//! [`imu`], the MPU-6050 firmware's path from the sensor's registers to the
//! attitude, apart from the board so that it also runs on the host.

#![cfg_attr(not(test), no_std)]
#![deny(missing_docs)]

pub mod imu;
