//! An MPU-6050 on a micro:bit v2 (nRF52833, Cortex-M4F), read over I2C
//! into rigtform's orientation filter, the attitude logged with defmt.
//!
//! The sensor (a GY-521 board, say) sits on the edge connector's I2C pins
//! (P19 SCL, P20 SDA, 3 V, GND) at address 0x68, turned a quarter turn on
//! the body: its x along the body's y, its y along the body's -x. TIMER1
//! counts microseconds for `dt`, TIMER0 paces the loop at about 250 Hz, and
//! every 50th attitude goes out over RTT (`probe-rs run --chip nRF52833_xxAA`
//! shows it). The path from the registers to the filter is the crate's
//! library ([`rigtform_firmware_example::imu`]), which the host tests
//! replay a recorded trial through.
//!
//! ```text
//! cd examples/firmware
//! cargo build --release --target thumbv7em-none-eabihf --features microbit-v2 --bin imu-mpu6050
//! ```

#![no_std]
#![no_main]

use cortex_m_rt::entry;
use defmt_rtt as _;
use embedded_hal::delay::DelayNs;
use embedded_hal::i2c::Error as _;
use microbit::hal::twim::{self, Twim};
use microbit::hal::Timer;
use microbit::Board;
use panic_probe as _;
use rigtform::attitude::{AxesAlignment, Axis, FilterParams, InertialCalibration};
use rigtform_firmware_example::imu::{Attitude, Clock, Error, Imu, Mounting};

/// The sensor's I2C address (AD0 low).
const ADDRESS: u8 = 0x68;

/// Log one attitude in this many.
const LOG_EVERY: u32 = 50;

#[entry]
fn main() -> ! {
    let Some(board) = Board::take() else {
        defmt::panic!("the board's peripherals were taken before main");
    };
    let i2c = Twim::new(
        board.TWIM0,
        board.i2c_external.into(),
        twim::Frequency::K400,
    );
    // A free-running microsecond counter: periodic at its top value, so it
    // wraps as a 32-bit counter does.
    let mut clock = Timer::periodic(board.TIMER1);
    clock.start(u32::MAX);
    let mut pace = Timer::new(board.TIMER0);

    let mut imu = match Imu::new(i2c, ADDRESS) {
        Ok(imu) => imu,
        Err(e) => halt(e),
    };
    let mounting = Mounting {
        alignment: AxesAlignment::new(Axis::PosY, Axis::NegX).unwrap_or_default(),
        // A bench calibration's result goes here: the gyro's offset at
        // rest, the accelerometer's offset and sensitivity from six poses.
        gyro: InertialCalibration::IDENTITY,
        accel: InertialCalibration::IDENTITY,
    };
    let mut attitude = Attitude::new(
        FilterParams::DEFAULT,
        mounting,
        Clock::new(
            Timer::<microbit::pac::TIMER1>::TICKS_PER_SECOND,
            clock.read(),
        ),
    );
    let mut n: u32 = 0;
    loop {
        pace.delay_us(4_000);
        match imu.read() {
            Ok(counts) => {
                let q = attitude.update(counts, clock.read());
                n = n.wrapping_add(1);
                if n % LOG_EVERY == 0 {
                    defmt::info!(
                        "attitude {} heading {=f32} rad, bias {}",
                        q,
                        attitude.filter.heading(),
                        attitude.filter.bias()
                    );
                }
            }
            // A lost reading: the next one's dt spans the gap.
            Err(Error::Bus(e)) => defmt::warn!("MPU-6050 read failed: {}", e.kind()),
            Err(e) => halt(e),
        }
    }
}

/// Logs why the sensor cannot be used and stops.
fn halt(e: Error<twim::Error>) -> ! {
    match e {
        Error::Bus(e) => defmt::error!(
            "no answer from an MPU-6050 at {=u8:#x}: {}",
            ADDRESS,
            e.kind()
        ),
        Error::WrongChip { found } => defmt::error!(
            "the chip at {=u8:#x} is no MPU-6050: WHO_AM_I reads {=u8:#x}, not 0x68",
            ADDRESS,
            found
        ),
        Error::DriverRefusedChip => defmt::error!("the MPU-6050 driver refused the chip"),
    }
    loop {
        cortex_m::asm::wfi();
    }
}
