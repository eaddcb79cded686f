//! The MPU-6050 firmware's sensor path, from the sensor's registers to the
//! attitude: the chip checked by its `WHO_AM_I` register, the driver
//! ([`mpu6050_dmp`], embedded-hal 1.0) set to its widest ranges and read in
//! one burst, the counts scaled to SI units with the datasheet's
//! sensitivities, calibrated and turned to the body's axes with rigtform's
//! [`InertialCalibration`] and [`AxesAlignment`], `dt` taken from a
//! free-running timer, and the [`OrientationFilter`] updated.
//!
//! Nothing here knows the board: the bus is any [`embedded_hal::i2c::I2c`]
//! and the time any counter, so the same code runs in the firmware
//! (`src/bin/imu_mpu6050.rs`) and on the host against a mock bus
//! (`imu/replay.rs`, BROAD trial 16 as the sensor's register bytes). Bus errors and a wrong chip are returned as
//! [`Error`]s; nothing panics.
//!
//! The sensitivities are those of the MPU-6000/MPU-6050 Product
//! Specification (InvenSense PS-MPU-6000A-00, revision 3.4), sections 6.1
//! and 6.2: 16.4 LSB per °/s at ±2000 °/s, 2,048 LSB per g at ±16 g.

use core::fmt;

use embedded_hal::i2c::I2c;
use mpu6050_dmp::accel::AccelFullScale;
use mpu6050_dmp::address::Address;
use mpu6050_dmp::config::DigitalLowPassFilter;
use mpu6050_dmp::gyro::GyroFullScale;
use mpu6050_dmp::sensor::Mpu6050;
use rigtform::attitude::{AxesAlignment, FilterParams, InertialCalibration, OrientationFilter};
use rigtform::{Cvec3, Quat};

/// The MPU-6050's `WHO_AM_I` register.
pub const WHO_AM_I: u8 = 0x75;
/// What `WHO_AM_I` reads on an MPU-6050, whichever its I2C address
/// (0x68, or 0x69 with AD0 high). An MPU-6500 reads 0x70, an MPU-9250 0x71.
pub const MPU6050_ID: u8 = 0x68;

/// One gyro count in rad/s at ±2000 °/s: 1 / 16.4 °/s.
pub const GYRO_RAD_PER_S_PER_COUNT: f32 = core::f32::consts::PI / 180.0 / 16.4;
/// One accelerometer count in m/s² at ±16 g: 1 / 2,048 of standard gravity
/// (9.80665 m/s²).
pub const ACCEL_M_PER_S2_PER_COUNT: f32 = 9.80665 / 2048.0;
/// The gyro's range, ±2000 °/s, in rad/s: the filter's `gyro_range`.
pub const GYRO_RANGE: f32 = 2000.0 * core::f32::consts::PI / 180.0;

/// What went wrong talking to the sensor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error<E> {
    /// The bus failed (no acknowledge, arbitration lost, ...): the I2C
    /// implementation's error.
    Bus(E),
    /// The chip at the address is not an MPU-6050: its `WHO_AM_I` read
    /// `found`.
    WrongChip {
        /// What `WHO_AM_I` read.
        found: u8,
    },
    /// The driver took the chip for another (`mpu6050-dmp`'s own
    /// `WrongDevice`).
    DriverRefusedChip,
}

impl<E: fmt::Debug> fmt::Display for Error<E> {
    /// ```
    /// use rigtform_firmware_example::imu::Error;
    /// let e: Error<()> = Error::WrongChip { found: 0x71 };
    /// assert_eq!(
    ///     e.to_string(),
    ///     "no MPU-6050: WHO_AM_I (register 0x75) reads 0x71, an MPU-6050's reads 0x68"
    /// );
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Bus(e) => write!(f, "I2C bus error talking to the MPU-6050: {e:?}"),
            Error::WrongChip { found } => write!(
                f,
                "no MPU-6050: WHO_AM_I (register {WHO_AM_I:#04x}) reads {found:#04x}, \
                 an MPU-6050's reads {MPU6050_ID:#04x}"
            ),
            Error::DriverRefusedChip => f.write_str("the MPU-6050 driver refused the chip"),
        }
    }
}

impl<I: I2c> From<mpu6050_dmp::error::Error<I>> for Error<I::Error> {
    fn from(e: mpu6050_dmp::error::Error<I>) -> Self {
        use mpu6050_dmp::error::Error as Driver;
        match e {
            Driver::WriteError(e) | Driver::WriteReadError(e) => Error::Bus(e),
            Driver::WrongDevice => Error::DriverRefusedChip,
        }
    }
}

/// One reading of the gyro and the accelerometer, in the sensor's counts
/// and axes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counts {
    /// Angular rate, x, y, z.
    pub gyr: [i16; 3],
    /// Specific force, x, y, z.
    pub acc: [i16; 3],
}

impl Counts {
    /// The reading in SI units (rad/s and m/s²), still in the sensor's
    /// axes: each count times the datasheet's sensitivity.
    ///
    /// ```
    /// use rigtform_firmware_example::imu::{Counts, ACCEL_M_PER_S2_PER_COUNT};
    /// let (gyr, acc) = Counts { gyr: [0, 0, 164], acc: [0, 0, 2048] }.si();
    /// assert!((gyr.z - 10f32.to_radians()).abs() < 1e-6); // 10 °/s
    /// assert!((acc.z - 9.80665).abs() < 1e-5); // 1 g
    /// ```
    #[must_use]
    pub fn si(self) -> (Cvec3, Cvec3) {
        let scale = |c: [i16; 3], s: f32| {
            Cvec3::new(
                f32::from(c[0]) * s,
                f32::from(c[1]) * s,
                f32::from(c[2]) * s,
            )
        };
        (
            scale(self.gyr, GYRO_RAD_PER_S_PER_COUNT),
            scale(self.acc, ACCEL_M_PER_S2_PER_COUNT),
        )
    }
}

/// How the sensor sits on the body and what its calibration found: the
/// calibrations act in the sensor's axes, then the alignment turns the
/// reading into the body's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mounting {
    /// The body axes of the sensor's axes.
    pub alignment: AxesAlignment,
    /// The gyro's calibration, rad/s.
    pub gyro: InertialCalibration,
    /// The accelerometer's calibration, m/s².
    pub accel: InertialCalibration,
}

impl Mounting {
    /// The reading in SI units and the body's axes, calibrated.
    #[must_use]
    pub fn body(&self, counts: Counts) -> (Cvec3, Cvec3) {
        let (gyr, acc) = counts.si();
        (
            self.alignment.apply(self.gyro.apply(gyr)),
            self.alignment.apply(self.accel.apply(acc)),
        )
    }
}

/// The MPU-6050 on an I2C bus, checked and set up, through the
/// `mpu6050-dmp` driver.
pub struct Imu<I: I2c> {
    mpu: Mpu6050<I>,
}

impl<I: I2c> Imu<I> {
    /// Checks that the chip at `address` is an MPU-6050 (`WHO_AM_I`), wakes
    /// it, and sets ±2000 °/s, ±16 g and the 94 Hz / 98 Hz low-pass
    /// filter (`DLPF_CFG` 2). The bus is lost on an error; the errors say
    /// what failed.
    pub fn new(mut i2c: I, address: u8) -> Result<Self, Error<I::Error>> {
        let mut id = [0];
        i2c.write_read(address, &[WHO_AM_I], &mut id)
            .map_err(Error::Bus)?;
        if id[0] != MPU6050_ID {
            return Err(Error::WrongChip { found: id[0] });
        }
        let mut mpu = Mpu6050::new(i2c, Address(address)).map_err(|e| Error::from(e.error))?;
        mpu.set_accel_full_scale(AccelFullScale::G16)?;
        mpu.set_gyro_full_scale(GyroFullScale::Deg2000)?;
        mpu.set_digital_lowpass_filter(DigitalLowPassFilter::Filter2)?;
        Ok(Self { mpu })
    }

    /// The latest gyro and accelerometer reading, in one burst read of the
    /// data registers (0x3B to 0x48).
    pub fn read(&mut self) -> Result<Counts, Error<I::Error>> {
        let (acc, gyr) = self.mpu.motion6()?;
        Ok(Counts {
            gyr: [gyr.x(), gyr.y(), gyr.z()],
            acc: [acc.x(), acc.y(), acc.z()],
        })
    }

    /// The bus, back.
    pub fn release(self) -> I {
        self.mpu.release()
    }
}

/// Seconds between readings of a free-running counter that wraps at 2^32
/// (a 32-bit hardware timer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clock {
    ticks_per_second: f32,
    last: u32,
}

impl Clock {
    /// A clock that counts `ticks_per_second`, last read at `now`.
    #[must_use]
    pub fn new(ticks_per_second: u32, now: u32) -> Self {
        Self {
            ticks_per_second: ticks_per_second as f32,
            last: now,
        }
    }

    /// The time since the last reading, in seconds; `now` becomes the last
    /// reading. Exact up to 2^24 ticks (16.7 s at 1 MHz); a gap longer
    /// than the counter's period (71.6 min at 1 MHz) is not seen.
    ///
    /// ```
    /// use rigtform_firmware_example::imu::Clock;
    /// let mut clock = Clock::new(1_000_000, u32::MAX - 999);
    /// assert_eq!(clock.dt(2_500), 0.0035); // across the wrap
    /// ```
    pub fn dt(&mut self, now: u32) -> f32 {
        let ticks = now.wrapping_sub(self.last);
        self.last = now;
        ticks as f32 / self.ticks_per_second
    }
}

/// The attitude of the body: readings, timed, into the filter.
#[derive(Clone, Debug)]
pub struct Attitude {
    /// The filter, for its diagnostics and outputs.
    pub filter: OrientationFilter,
    mounting: Mounting,
    clock: Clock,
}

impl Attitude {
    /// The filter with `params`, `gyro_range` set to the sensor's
    /// ([`GYRO_RANGE`]), for a sensor mounted as `mounting`; `clock` read
    /// just before the first reading is taken.
    #[must_use]
    pub fn new(params: FilterParams, mounting: Mounting, clock: Clock) -> Self {
        Self {
            filter: OrientationFilter::new(FilterParams {
                gyro_range: GYRO_RANGE,
                ..params
            }),
            mounting,
            clock,
        }
    }

    /// The filter updated with `counts`, read at `now` on the clock's
    /// counter: the body's attitude (body to earth).
    pub fn update(&mut self, counts: Counts, now: u32) -> Quat {
        let (gyr, acc) = self.mounting.body(counts);
        let dt = self.clock.dt(now);
        self.filter.update(gyr, acc, dt)
    }
}

#[cfg(test)]
mod replay;

#[cfg(test)]
mod tests {
    use super::*;
    use rigtform::attitude::Axis;

    #[test]
    fn the_datasheet_sensitivities_give_si_units() {
        // 2000 °/s is 32,800 counts, past the range: 1000 °/s is 16,400.
        let (gyr, acc) = Counts {
            gyr: [16_400, -16_400, 0],
            acc: [2048, -4096, 32_767],
        }
        .si();
        assert!((gyr.x - 1000f32.to_radians()).abs() < 1e-5);
        assert!((gyr.y + 1000f32.to_radians()).abs() < 1e-5);
        assert_eq!(gyr.z, 0.0);
        assert!((acc.x - 9.80665).abs() < 1e-5);
        assert!((acc.y + 2.0 * 9.80665).abs() < 1e-5);
        assert!((acc.z - 16.0 * 9.80665).abs() < 1e-2);
        assert!((GYRO_RANGE - 34.906_586).abs() < 1e-5);
    }

    #[test]
    fn calibration_acts_in_the_sensor_axes_before_the_alignment() {
        let mounting = Mounting {
            // Sensor x along body +y, sensor y along body -x.
            alignment: AxesAlignment::new(Axis::PosY, Axis::NegX).unwrap(),
            gyro: InertialCalibration {
                offset: Cvec3::new(0.5, 0.0, 0.0),
                ..InertialCalibration::IDENTITY
            },
            accel: InertialCalibration::IDENTITY,
        };
        // A sensor-x reading of exactly its offset is no rate at all.
        let counts = Counts {
            gyr: [0, 0, 0],
            acc: [2048, 0, 0],
        };
        let offset_counts = (0.5 / GYRO_RAD_PER_S_PER_COUNT).round() as i16;
        let (gyr, acc) = mounting.body(Counts {
            gyr: [offset_counts, 0, 0],
            ..counts
        });
        assert!(gyr.norm() < GYRO_RAD_PER_S_PER_COUNT);
        // 1 g along the sensor's x is 1 g along the body's y.
        assert!((acc - Cvec3::new(0.0, 9.80665, 0.0)).norm() < 1e-5);
    }

    #[test]
    fn the_clock_counts_across_the_wrap() {
        let mut clock = Clock::new(1_000_000, u32::MAX);
        assert_eq!(clock.dt(3499), 0.0035);
        assert_eq!(clock.dt(3499 + 10_000), 0.01);
        assert_eq!(clock.dt(3499 + 10_000), 0.0);
    }
}
