//! Executed instructions per call of the attitude updates on the emulated
//! Cortex-M4F: each call sits between the markers of
//! [`rigtform_embedded::measure`], after an empty bracket (the
//! calibration), once each, past the filters' warm-up. Run it with
//! `cargo xtask filter-cost`, not directly. The first row also names the filter's state
//! size (`state <bytes> bytes`, `size_of` on this target), which the xtask
//! checks against its budget with the instruction counts.

#![no_std]
#![no_main]

use core::hint::black_box;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use panic_semihosting as _;
use rigtform::attitude::{FilterParams, OrientationFilter, Smoother};
use rigtform::{Cvec3, Quat};
use rigtform_embedded::measure;

/// The rows, in the order of their brackets below.
const ROWS: [&str; 4] = [
    "OrientationFilter::update (6D)",
    "OrientationFilter::update_with_mag (9D)",
    "Quat::integrate",
    "Smoother::update",
];

/// An empty bracket: the calibration of the measured one after it.
fn empty() {
    measure::start();
    measure::end();
}

/// A moving, tilted, biased sample at step `i` of 285.7 Hz: turning about
/// the vertical at 0.3 rad/s, tilted 0.2 rad.
fn sample(i: u32) -> (Cvec3, Cvec3, Cvec3) {
    let t = i as f32 * 0.0035;
    let truth = Quat::from_rotation_z(0.3 * t) * Quat::from_rotation_x(0.2);
    // The body rate of that turn, plus a bias within max_bias.
    let gyr =
        Quat::from_rotation_x(0.2).inv() * Cvec3::new(0.0, 0.0, 0.3) + Cvec3::new(0.01, -0.02, 0.0);
    let acc = truth.inv() * Cvec3::new(0.0, 0.0, 9.81);
    let mag = truth.inv() * Cvec3::new(0.0, 16.0, -41.0);
    (gyr, acc, mag)
}

/// `n` in decimal, written into the end of `digits`.
fn decimal(mut n: usize, digits: &mut [u8; 10]) -> &str {
    let mut start = digits.len();
    loop {
        start -= 1;
        digits[start] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 || start == 0 {
            break;
        }
    }
    core::str::from_utf8(&digits[start..]).unwrap_or("?")
}

#[entry]
fn main() -> ! {
    let mut six = OrientationFilter::new(FilterParams::DEFAULT);
    let mut nine = six;
    let mut smoother = Smoother::new(Quat::IDENTITY, 0.5);
    // Warm up: past initialization and the start-up (tau_acc, 3 s), with
    // the correction and the bias update running.
    for i in 0..1200 {
        let (gyr, acc, mag) = sample(i);
        six.update(gyr, acc, 0.0035);
        nine.update_with_mag(gyr, acc, mag, 0.0035);
    }
    let (gyr, acc, mag) = sample(1200);
    let q = Quat::from_rotation_y(0.4);

    let mut digits = [0u8; 10];
    let state = decimal(core::mem::size_of::<OrientationFilter>(), &mut digits);
    measure::row(1, &[ROWS[0], "state", state, "bytes"]);
    for name in &ROWS[1..] {
        measure::row(1, &[name]);
    }

    empty();
    measure::start();
    black_box(black_box(&mut six).update(black_box(gyr), black_box(acc), black_box(0.0035)));
    measure::end();

    empty();
    measure::start();
    black_box(black_box(&mut nine).update_with_mag(
        black_box(gyr),
        black_box(acc),
        black_box(mag),
        black_box(0.0035),
    ));
    measure::end();

    empty();
    measure::start();
    black_box(black_box(q).integrate(black_box(gyr), black_box(0.0035)));
    measure::end();

    empty();
    measure::start();
    black_box(black_box(&mut smoother).update(black_box(q), black_box(0.0035)));
    measure::end();

    measure::done(ROWS.len());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
