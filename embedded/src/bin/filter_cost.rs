//! Executed instructions per call of the attitude updates on the emulated
//! Cortex-M4F, by the method of the performance issue: each call sits
//! between two never-inlined marker functions, QEMU traces every executed
//! instruction (`-singlestep -d exec,nochain`), and `cost.sh` counts the
//! trace lines between the markers, minus those of an empty bracket.
//! Run: `./cost.sh` in `embedded/`.

#![no_std]
#![no_main]

use core::hint::black_box;
use core::sync::atomic::{AtomicU32, Ordering};

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use rigtform::attitude::{FilterParams, OrientationFilter, Smoother};
use rigtform::{Cvec3, Quat};

/// Two statics, so that the two markers differ and are not folded into one.
static OPENED: AtomicU32 = AtomicU32::new(0);
static CLOSED: AtomicU32 = AtomicU32::new(0);

/// Opens a measured bracket (called through [`open`], never inlined).
#[no_mangle]
#[inline(never)]
pub extern "C" fn cost_open(id: u32) {
    OPENED.store(id, Ordering::SeqCst);
}

/// Closes a measured bracket (called through [`close`], never inlined).
#[no_mangle]
#[inline(never)]
pub extern "C" fn cost_close(id: u32) {
    CLOSED.fetch_add(id + 1, Ordering::SeqCst);
}

/// Calls `cost_open` through an opaque pointer, so that LTO keeps it a
/// function of its own, whose address the trace shows.
fn open(id: u32) {
    black_box(cost_open as extern "C" fn(u32))(id);
}

/// As [`open`], for `cost_close`.
fn close(id: u32) {
    black_box(cost_close as extern "C" fn(u32))(id);
}

/// A moving, tilted, biased sample at step `i` of 285.7 Hz.
fn sample(i: u32) -> (Cvec3, Cvec3, Cvec3) {
    let t = i as f32 * 0.0035;
    let truth = Quat::from_rotation_z(0.3 * t) * Quat::from_rotation_x(0.2);
    let gyr = Cvec3::new(0.01, -0.02, 0.3);
    let acc = truth.inv() * Cvec3::new(0.0, 0.0, 9.81);
    let mag = truth.inv() * Cvec3::new(0.0, 16.0, -41.0);
    (gyr, acc, mag)
}

#[entry]
fn main() -> ! {
    let mut six = OrientationFilter::new(FilterParams::DEFAULT);
    let mut nine = six;
    let mut smoother = Smoother::new(Quat::IDENTITY, 0.5);
    // Warm up: past initialization, with the correction running.
    for i in 0..500 {
        let (gyr, acc, mag) = sample(i);
        six.update(gyr, acc, 0.0035);
        nine.update_with_mag(gyr, acc, mag, 0.0035);
    }
    let (gyr, acc, mag) = sample(500);
    let q = Quat::from_rotation_y(0.4);

    open(0);
    close(0);

    open(1);
    black_box(black_box(&mut six).update(black_box(gyr), black_box(acc), black_box(0.0035)));
    close(1);

    open(2);
    black_box(black_box(&mut nine).update_with_mag(
        black_box(gyr),
        black_box(acc),
        black_box(mag),
        black_box(0.0035),
    ));
    close(2);

    open(3);
    black_box(black_box(q).integrate(black_box(gyr), black_box(0.0035)));
    close(3);

    open(4);
    black_box(black_box(&mut smoother).update(black_box(q), black_box(0.0035)));
    close(4);

    hprintln!(
        "markers: last opened {}, closed sum {}",
        OPENED.load(Ordering::SeqCst),
        CLOSED.load(Ordering::SeqCst)
    );
    hprintln!("brackets: 0 empty, 1 OrientationFilter::update, 2 update_with_mag, 3 Quat::integrate, 4 Smoother::update");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
