//! The orientation filter on a real recording with optical ground truth:
//! BROAD trial 16 (fast translation), shipped gzipped in the testkit's
//! `data/` (attribution and changes in its `README.md`), scored with BROAD's
//! metric by the same code as the comparison binary `broad`.

use rigtform::accuracy;
use rigtform::attitude::FilterParams;
use rigtform_testkit::broad::{data, metric, trial_16};

fn samples() -> Vec<data::BroadSample> {
    match data::read(&trial_16()) {
        Ok(data::Recording::Broad(samples)) => samples,
        Ok(_) => panic!("{} is not a BROAD trial", trial_16().display()),
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn broad_16_inclination_and_total_rmse_stay_within_their_bounds() {
    let samples = samples();
    assert_eq!(samples.len(), 53_392);
    let six = metric::run(&samples, FilterParams::DEFAULT, false);
    let nine = metric::run(&samples, FilterParams::DEFAULT, true);
    println!("BROAD 16, 6D: {:?}", six.rmse);
    println!("BROAD 16, 9D: {:?}", nine.rmse);
    assert_eq!(
        six.rmse.samples, 32_073,
        "scored samples: movement phase, ground truth present"
    );
    for run in [&six, &nine] {
        assert!(run.estimates.iter().all(|q| q.is_finite()));
        // Per sample, neither part of the error exceeds the whole.
        let r = run.rmse;
        assert!(r.heading <= r.total && r.inclination <= r.total, "{r:?}");
    }
    assert!(six.rmse.inclination <= accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG as f64);
    assert!(nine.rmse.inclination <= accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG as f64);
    assert!(nine.rmse.total <= accuracy::FILTER_BROAD_16_TOTAL_RMSE_DEG as f64);
}

/// The sensor turned on its board (x along the board's -z, y along +x),
/// with a hard-iron offset on the magnetometer and an offset and scale on
/// the gyro: after `AxesAlignment` and the calibrations undo them, the
/// filter sees the recorded samples again and scores as on them.
#[test]
fn broad_16_through_a_mounting_and_calibrations_scores_as_recorded() {
    use rigtform::attitude::{
        AxesAlignment, Axis, InertialCalibration, MagneticCalibration, OrientationFilter,
    };
    use rigtform::Cvec3;
    let samples = samples();
    let mounting = AxesAlignment::new(Axis::NegZ, Axis::PosX).unwrap();
    // The mounting's inverse, by where it takes the body axes.
    let to_sensor = |v: Cvec3| {
        let (x, y, z) = (
            mounting.apply(Cvec3::X),
            mounting.apply(Cvec3::Y),
            mounting.apply(Cvec3::Z),
        );
        Cvec3::new(x.dot(v), y.dot(v), z.dot(v))
    };
    let hard_iron = Cvec3::new(25.0, -12.0, 7.0);
    let gyro_offset = Cvec3::new(0.02, -0.01, 0.015);
    let gyro = InertialCalibration {
        offset: gyro_offset,
        sensitivity: Cvec3::new(0.5, 0.5, 0.5),
        ..InertialCalibration::IDENTITY
    };
    let mag = MagneticCalibration {
        hard_iron,
        ..MagneticCalibration::IDENTITY
    };
    let mut filter = OrientationFilter::new(FilterParams::DEFAULT);
    let mut estimates = Vec::with_capacity(samples.len());
    for s in &samples {
        // What the turned, miscalibrated sensor would have read.
        let raw_gyr = to_sensor(s.gyr) * 2.0 + gyro_offset;
        let raw_acc = to_sensor(s.acc);
        let raw_mag = to_sensor(s.mag) + hard_iron;
        estimates.push(filter.update_with_mag(
            mounting.apply(gyro.apply(raw_gyr)),
            mounting.apply(raw_acc),
            mounting.apply(mag.apply(raw_mag)),
            data::BROAD_DT,
        ));
    }
    let through = metric::score(&samples, &estimates).total;
    let recorded = metric::run(&samples, FilterParams::DEFAULT, true)
        .rmse
        .total;
    println!("9D total through the mounting: {through}, as recorded: {recorded}");
    assert!((through - recorded).abs() < 0.01, "{through} {recorded}");
}

/// On the recording: the diagnostics see the still start as rest and the
/// start-up as initialising; the accelerometer is never ignored (its 3 s
/// average in the inertial frame stays within 10 % of gravity even through
/// the 9 g peaks of the translations); and the linear acceleration in the earth frame
/// averages out to near zero over the whole trial (the sensor ends where
/// it started, near enough), while single samples reach many m/s².
#[test]
fn broad_16_diagnostics_and_linear_acceleration() {
    use rigtform::attitude::OrientationFilter;
    let samples = samples();
    let mut filter = OrientationFilter::new(FilterParams::DEFAULT);
    let (mut resting_still, mut still, mut ignored_moving, mut moving) = (0, 0, 0, 0);
    let mut sum = rigtform::Cvec3::ZERO;
    let mut largest: f32 = 0.0;
    for (i, s) in samples.iter().enumerate() {
        filter.update_with_mag(s.gyr, s.acc, s.mag, data::BROAD_DT);
        let d = filter.diagnostics();
        if i == 0 {
            assert!(d.initialising);
        }
        if i == 2000 {
            assert!(!d.initialising, "7 s in, past tau_acc");
        }
        let a = filter.earth_acceleration(s.acc);
        sum += a;
        largest = largest.max(a.norm());
        // The first 20 s: the sensor lies still.
        if (1000..5700).contains(&i) {
            still += 1;
            resting_still += usize::from(d.resting);
        }
        if s.movement {
            moving += 1;
            ignored_moving += usize::from(d.acc_ignored);
        }
        assert!(!d.gyro_saturated && !d.recovering);
    }
    let mean = sum * (1.0 / samples.len() as f32);
    println!(
        "rest {resting_still}/{still} while still, accelerometer ignored {ignored_moving}/{moving} while moving, mean earth acceleration {mean:?}, largest {largest}"
    );
    assert!(resting_still * 10 >= still * 9);
    assert_eq!(ignored_moving, 0);
    assert!(mean.norm() < 0.1 && largest > 20.0, "{mean:?} {largest}");
}
