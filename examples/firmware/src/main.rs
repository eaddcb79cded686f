//! A small firmware built on rigtform, to show what it costs in flash and
//! RAM: each pass of the main loop reads an IMU sample, updates the
//! attitude filter, eases a displayed attitude towards it with slerp, and
//! places a sensor mounted on a moving body with `RigTForm`s.
//!
//! The samples come from a fixed table, and the results go to
//! `black_box`, standing in for a radio or a display: the compiler can
//! neither precompute nor drop the work. `src/bin/imu_mpu6050.rs` reads a
//! real sensor instead.
//!
//! ```text
//! cd examples/firmware
//! cargo build --release --target thumbv7em-none-eabihf
//! llvm-size target/thumbv7em-none-eabihf/release/rigtform-firmware-example
//! ```

#![no_std]
#![no_main]

use core::hint::black_box;

use cortex_m_rt::entry;
// Built beside the MPU-6050 firmware (feature `microbit-v2`), cortex-m-rt
// takes its interrupt vectors from the nRF52833's device crate.
#[cfg(feature = "microbit-v2")]
use microbit as _;
use panic_halt as _;
use rigtform::attitude::{FilterParams, OrientationFilter};
use rigtform::{Cvec3, Cvec4, Quat, RigTForm};

/// Gyro (rad/s), accelerometer (m/s²) and magnetometer (µT) samples of a
/// slow turn, as a sensor driver would deliver them.
const SAMPLES: [[Cvec3; 3]; 4] = [
    [
        Cvec3::new(0.01, -0.02, 0.30),
        Cvec3::new(0.2, -0.1, 9.8),
        Cvec3::new(20.0, 3.0, -40.0),
    ],
    [
        Cvec3::new(0.02, -0.01, 0.31),
        Cvec3::new(0.3, -0.2, 9.7),
        Cvec3::new(19.0, 6.0, -40.0),
    ],
    [
        Cvec3::new(0.00, -0.02, 0.29),
        Cvec3::new(0.1, 0.0, 9.9),
        Cvec3::new(18.0, 9.0, -41.0),
    ],
    [
        Cvec3::new(0.01, 0.00, 0.30),
        Cvec3::new(0.2, 0.1, 9.8),
        Cvec3::new(16.0, 12.0, -41.0),
    ],
];

/// The sample period: 100 Hz.
const DT: f32 = 0.01;

#[entry]
fn main() -> ! {
    let mut filter = OrientationFilter::new(FilterParams::DEFAULT);
    let mut shown = Quat::IDENTITY;
    // Where the sensor sits on the body: 5 cm forward, turned a quarter
    // turn about z.
    let mount = RigTForm::new(
        Cvec3::new(0.05, 0.0, 0.0),
        Quat::from_rotation_z(core::f32::consts::FRAC_PI_2),
    );
    let mut step = 0usize;
    loop {
        let [gyr, acc, mag] = black_box(SAMPLES[step % SAMPLES.len()]);
        step = step.wrapping_add(1);
        let attitude = filter.update_with_mag(gyr, acc, mag, DT);
        // Ease the displayed attitude a fifth of the way each pass.
        shown = shown.slerp(attitude, 0.2);
        // The body's frame in the world, from the sensor's attitude and
        // where the sensor is mounted, and the world position of its tip.
        let body = RigTForm::new(black_box(Cvec3::new(1.0, 2.0, 0.0)), attitude) * mount.inv();
        let tip = body * Cvec4::from_point(Cvec3::new(0.3, 0.0, 0.0));
        black_box((shown, body, tip, filter.bias()));
    }
}
