//! (tests only) The MPU-6050 firmware's sensor path on the host: BROAD trial 16 replayed
//! as the register bytes an MPU-6050 would return on a mock I2C bus
//! (embedded-hal-mock), through the driver, the scaling, the alignment and
//! the timer, gives the attitude the filter gives when fed the same
//! samples, quantized to the sensor's counts, directly. A wrong chip and a
//! bus error are errors, and a failed reading leaves the attitude as it
//! was.

use super::{
    Attitude, Clock, Error, Imu, Mounting, ACCEL_M_PER_S2_PER_COUNT, GYRO_RAD_PER_S_PER_COUNT,
    GYRO_RANGE,
};
use embedded_hal::i2c::ErrorKind;
use embedded_hal_mock::eh1::i2c::{Mock, Transaction};
use rigtform::attitude::{
    AxesAlignment, Axis, FilterParams, InertialCalibration, OrientationFilter,
};
use rigtform::Cvec3;
use rigtform_testkit::broad::data::{self, BroadSample, Recording, BROAD_DT};

const ADDRESS: u8 = 0x68;
/// The microseconds of BROAD's sample period, 2000/7 Hz.
const PERIOD_US: u32 = 3500;

/// What the driver's set-up reads and writes after `WHO_AM_I`, with the
/// registers at their reset values: wake (PWR_MGMT_1 0x40 -> 0x00),
/// ±16 g (ACCEL_CONFIG 0x18), ±2000 °/s (GYRO_CONFIG 0x18), DLPF_CFG 2.
fn set_up() -> Vec<Transaction> {
    vec![
        Transaction::write_read(ADDRESS, vec![0x75], vec![0x68]),
        Transaction::write_read(ADDRESS, vec![0x6B], vec![0x40]),
        Transaction::write(ADDRESS, vec![0x6B, 0x00]),
        Transaction::write_read(ADDRESS, vec![0x1C], vec![0x00]),
        Transaction::write(ADDRESS, vec![0x1C, 0x18]),
        Transaction::write_read(ADDRESS, vec![0x1B], vec![0x00]),
        Transaction::write(ADDRESS, vec![0x1B, 0x18]),
        Transaction::write_read(ADDRESS, vec![0x1A], vec![0x00]),
        Transaction::write(ADDRESS, vec![0x1A, 0x02]),
    ]
}

/// The 14 data registers from ACCEL_XOUT_H (0x3B), big-endian: the
/// accelerometer's x, y, z, the temperature, the gyro's x, y, z.
fn burst(gyr: [i16; 3], acc: [i16; 3]) -> Transaction {
    let temperature: i16 = 1200; // about 40 °C; the path ignores it
    let words = [acc[0], acc[1], acc[2], temperature, gyr[0], gyr[1], gyr[2]];
    let bytes = words.iter().flat_map(|w| w.to_be_bytes()).collect();
    Transaction::write_read(ADDRESS, vec![0x3B], bytes)
}

/// A value in counts of `scale`, rounded to nearest as the sensor's
/// converter does (all of trial 16 is within the ranges).
fn counts(value: f32, scale: f32) -> i16 {
    let c = (value / scale).round();
    assert!(c.abs() < 32_767.0, "{value} is out of range");
    c as i16
}

/// The sensor's mounting: its x along the body's y, its y along the
/// body's -x (its z along the body's z).
fn mounting() -> Mounting {
    Mounting {
        alignment: AxesAlignment::new(Axis::PosY, Axis::NegX).unwrap(),
        gyro: InertialCalibration::IDENTITY,
        accel: InertialCalibration::IDENTITY,
    }
}

/// The sensor's reading of a body-frame vector, in counts: component `i`
/// is the body's component along the sensor's axis `i`.
fn sensor_counts(body: Cvec3, scale: f32, alignment: AxesAlignment) -> [i16; 3] {
    let [x, y, z] = [Cvec3::X, Cvec3::Y, Cvec3::Z].map(|e| alignment.apply(e).dot(body));
    [counts(x, scale), counts(y, scale), counts(z, scale)]
}

fn trial_16() -> Vec<BroadSample> {
    match data::read(&rigtform_testkit::broad::trial_16()).unwrap() {
        Recording::Broad(samples) => samples,
        Recording::Fusion(_) => panic!("trial 16 is a BROAD trial"),
    }
}

#[test]
fn trial_16_through_the_registers_gives_the_filter_on_the_same_samples() {
    let samples = trial_16();
    let alignment = mounting().alignment;
    let mut expected = set_up();
    expected.extend(samples.iter().map(|s| {
        burst(
            sensor_counts(s.gyr, GYRO_RAD_PER_S_PER_COUNT, alignment),
            sensor_counts(s.acc, ACCEL_M_PER_S2_PER_COUNT, alignment),
        )
    }));
    let mut bus = Mock::new(&expected);
    let mut imu = Imu::new(bus.clone(), ADDRESS).unwrap();
    // The timer starts 20 samples before its wrap.
    let start = 0u32.wrapping_sub(20 * PERIOD_US);
    let mut attitude = Attitude::new(
        FilterParams::DEFAULT,
        mounting(),
        Clock::new(1_000_000, start.wrapping_sub(PERIOD_US)),
    );
    // The same samples, each component quantized to the sensor's counts,
    // straight into the filter at BROAD's period.
    let mut direct = OrientationFilter::new(FilterParams {
        gyro_range: GYRO_RANGE,
        ..FilterParams::DEFAULT
    });
    let quantized = |v: Cvec3, scale: f32| {
        Cvec3::new(
            f32::from(counts(v.x, scale)) * scale,
            f32::from(counts(v.y, scale)) * scale,
            f32::from(counts(v.z, scale)) * scale,
        )
    };
    let mut scored = 0;
    for (k, s) in samples.iter().enumerate() {
        let now = start.wrapping_add(k as u32 * PERIOD_US);
        let ours = attitude.update(imu.read().unwrap(), now);
        let theirs = direct.update(
            quantized(s.gyr, GYRO_RAD_PER_S_PER_COUNT),
            quantized(s.acc, ACCEL_M_PER_S2_PER_COUNT),
            BROAD_DT,
        );
        assert_eq!(ours, theirs, "sample {k}");
        assert!(ours.is_finite());
        scored += 1;
    }
    assert_eq!(scored, samples.len());
    assert!(samples.len() > 50_000);
    // The replay read every register the mock was given, in order.
    bus.done();
}

#[test]
fn a_chip_that_is_not_an_mpu_6050_is_refused_by_its_who_am_i() {
    // An MPU-9250 at the same address.
    let mut bus = Mock::new(&[Transaction::write_read(ADDRESS, vec![0x75], vec![0x71])]);
    let e = Imu::new(bus.clone(), ADDRESS).err().unwrap();
    assert_eq!(e, Error::WrongChip { found: 0x71 });
    assert_eq!(
        e.to_string(),
        "no MPU-6050: WHO_AM_I (register 0x75) reads 0x71, an MPU-6050's reads 0x68"
    );
    bus.done();
}

#[test]
fn bus_errors_are_errors_and_leave_the_attitude_as_it_was() {
    // Nothing answers at the address.
    let nack = ErrorKind::NoAcknowledge(embedded_hal::i2c::NoAcknowledgeSource::Address);
    let mut bus =
        Mock::new(&[Transaction::write_read(ADDRESS, vec![0x75], vec![0x68]).with_error(nack)]);
    let e = Imu::new(bus.clone(), ADDRESS).err().unwrap();
    assert_eq!(e, Error::Bus(nack));
    assert!(e.to_string().starts_with("I2C bus error"), "{e}");
    bus.done();

    // A failure during set-up, then one while reading: the reading after
    // it goes on from the attitude before, with dt spanning the gap.
    let mut broken = set_up();
    broken[4] = broken[4].clone().with_error(ErrorKind::ArbitrationLoss);
    let mut bus = Mock::new(&broken[..5]);
    let e = Imu::new(bus.clone(), ADDRESS).err().unwrap();
    assert_eq!(e, Error::Bus(ErrorKind::ArbitrationLoss));
    bus.done();

    let level = ([0, 0, 0], [0, 0, 2048]);
    let turning = ([0, 0, 1640], [0, 0, 2048]); // 100 °/s about z
    let mut expected = set_up();
    expected.push(burst(level.0, level.1));
    expected.push(burst(turning.0, turning.1).with_error(ErrorKind::Bus));
    expected.push(burst(turning.0, turning.1));
    let mut bus = Mock::new(&expected);
    let mut imu = Imu::new(bus.clone(), ADDRESS).unwrap();
    let mut attitude = Attitude::new(FilterParams::DEFAULT, mounting(), Clock::new(1_000_000, 0));
    let before = attitude.update(imu.read().unwrap(), 10_000);
    assert_eq!(imu.read(), Err(Error::Bus(ErrorKind::Bus)));
    assert_eq!(attitude.filter.attitude(), before);
    let after = attitude.update(imu.read().unwrap(), 30_000);
    // 20 ms at 100 °/s: 2° about the vertical.
    let turned = before.angle_to(after).to_degrees();
    assert!((turned - 2.0).abs() < 0.05, "{turned}");
    bus.done();
}
