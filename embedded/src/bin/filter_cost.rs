//! Executed instructions per call of the attitude updates on the emulated
//! Cortex-M4F: each call sits between the markers of
//! [`rigtform_embedded::measure`], after an empty bracket (the
//! calibration), once each, past the filters' warm-up. Run it with
//! `cargo xtask filter-cost`, not directly. The first row also names the filter's state
//! size (`state <bytes> bytes`, `size_of` on this target), which the xtask
//! checks against its budget with the instruction counts.
//!
//! Built with the feature `attitude-peers` (`cargo xtask filter-cost
//! --peers`), it then measures uf-ahrs's VQF, Mahony and Madgwick the same
//! way: each made as uf-ahrs's README shows (`new(sample period, default
//! parameters)`), warmed up on the same samples, then one `update_imu` (6D)
//! and one `update` (9D) on the same input as ours; each first row names
//! the filter's state size.

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
const ROWS: [&str; 5] = [
    "OrientationFilter::update (6D)",
    "OrientationFilter::update_with_mag (9D)",
    "OrientationFilter::update_with_mag (9D, mag_delay set)",
    "Quat::integrate",
    "Smoother::update",
];

/// uf-ahrs's filters and their rows (`filter`, `update`, then its state
/// size): 6D, then 9D, per filter.
#[cfg(feature = "attitude-peers")]
mod peers {
    use core::hint::black_box;
    use core::time::Duration;

    use rigtform::Cvec3;
    use rigtform_embedded::measure;
    use uf_ahrs::{Ahrs, Madgwick, MadgwickParams, Mahony, MahonyParams, Vqf, VqfParams};

    use super::{decimal, empty, sample};

    /// BROAD's sample period, the one ours runs at.
    const PERIOD: Duration = Duration::from_micros(3500);

    /// The rows, in the order of [`measure_all`]'s brackets.
    pub const ROWS: [&str; 6] = [
        "uf-ahrs Vqf::update_imu (6D)",
        "uf-ahrs Vqf::update (9D)",
        "uf-ahrs Mahony::update_imu (6D)",
        "uf-ahrs Mahony::update (9D)",
        "uf-ahrs Madgwick::update_imu (6D)",
        "uf-ahrs Madgwick::update (9D)",
    ];

    fn vector(v: Cvec3) -> nalgebra::Vector3<f32> {
        nalgebra::Vector3::new(v.x, v.y, v.z)
    }

    /// Announces the rows, the first of each filter with its state size.
    pub fn announce() {
        let sizes = [
            core::mem::size_of::<Vqf>(),
            core::mem::size_of::<Mahony>(),
            core::mem::size_of::<Madgwick>(),
        ];
        for (pair, size) in ROWS.chunks(2).zip(sizes) {
            let mut digits = [0u8; 10];
            measure::row(1, &[pair[0], "state", decimal(size, &mut digits), "bytes"]);
            measure::row(1, &[pair[1]]);
        }
    }

    /// `six` and `nine` warmed up as ours are, then one 6D and one 9D
    /// update each, bracketed.
    fn measure(mut six: impl Ahrs, mut nine: impl Ahrs) {
        for i in 0..1200 {
            let (gyr, acc, mag) = sample(i);
            six.update_imu(vector(gyr), vector(acc));
            nine.update(vector(gyr), vector(acc), vector(mag));
        }
        let (gyr, acc, mag) = sample(1200);
        let (gyr, acc, mag) = (vector(gyr), vector(acc), vector(mag));

        empty();
        measure::start();
        black_box(black_box(&mut six).update_imu(black_box(gyr), black_box(acc)));
        measure::end();

        empty();
        measure::start();
        black_box(black_box(&mut nine).update(black_box(gyr), black_box(acc), black_box(mag)));
        measure::end();
    }

    /// Every row's brackets, in the order of [`ROWS`].
    pub fn measure_all() {
        measure(
            Vqf::new(PERIOD, VqfParams::default()),
            Vqf::new(PERIOD, VqfParams::default()),
        );
        measure(
            Mahony::new(PERIOD, MahonyParams::default()),
            Mahony::new(PERIOD, MahonyParams::default()),
        );
        measure(
            Madgwick::new(PERIOD, MadgwickParams::default()),
            Madgwick::new(PERIOD, MadgwickParams::default()),
        );
    }
}

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
    // The magnetometer reading brought forward by the gyro's turn over
    // the delay: the 9D update's longest path.
    let mut late = OrientationFilter::new(FilterParams {
        mag_delay: 0.011,
        ..FilterParams::DEFAULT
    });
    let mut smoother = Smoother::new(Quat::IDENTITY, 0.5);
    // Warm up: past initialization and the start-up (tau_acc, 3 s), with
    // the correction and the bias update running.
    for i in 0..1200 {
        let (gyr, acc, mag) = sample(i);
        six.update(gyr, acc, 0.0035);
        nine.update_with_mag(gyr, acc, mag, 0.0035);
        late.update_with_mag(gyr, acc, mag, 0.0035);
    }
    let (gyr, acc, mag) = sample(1200);
    let q = Quat::from_rotation_y(0.4);

    let mut digits = [0u8; 10];
    let state = decimal(core::mem::size_of::<OrientationFilter>(), &mut digits);
    measure::row(1, &[ROWS[0], "state", state, "bytes"]);
    for name in &ROWS[1..] {
        measure::row(1, &[name]);
    }
    #[cfg(feature = "attitude-peers")]
    peers::announce();

    empty();
    measure::start();
    black_box(black_box(&mut six).update(black_box(gyr), black_box(acc), black_box(0.0035)));
    measure::end();

    for filter in [&mut nine, &mut late] {
        empty();
        measure::start();
        black_box(black_box(filter).update_with_mag(
            black_box(gyr),
            black_box(acc),
            black_box(mag),
            black_box(0.0035),
        ));
        measure::end();
    }

    empty();
    measure::start();
    black_box(black_box(q).integrate(black_box(gyr), black_box(0.0035)));
    measure::end();

    empty();
    measure::start();
    black_box(black_box(&mut smoother).update(black_box(q), black_box(0.0035)));
    measure::end();

    #[cfg(feature = "attitude-peers")]
    peers::measure_all();

    #[cfg(not(feature = "attitude-peers"))]
    measure::done(ROWS.len());
    #[cfg(feature = "attitude-peers")]
    measure::done(ROWS.len() + peers::ROWS.len());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
