//! The attitude module on target: the exponential map against `pow`, gyro
//! integration, the smoother's time constant, and the orientation filter's
//! update on synthetic samples (inclination, rest bias, heading, bad input,
//! each bad sample skipped and a burst recovered from, bad setter values,
//! recovery after the gyro range, a magnet nearby), the outputs, and the
//! axes alignment and calibrations.

use rigtform::accuracy::{
    ATAN2_MAX_ABS_ERROR, EULER_MAX_ANGLE_ERROR, EXP_LOG_POW_MAX_ANGLE_ERROR,
    INTEGRATE_STEP_MAX_ANGLE_ERROR, SMOOTHER_DECAY_MAX_ERROR,
};
use rigtform::attitude::{
    AxesAlignment, Axis, FilterParams, InertialCalibration, MagneticCalibration, OrientationFilter,
    Smoother,
};
use rigtform::{Cvec3, EulerRot, Quat};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::laws::Violation;
use rigtform_proofs::reference::Quat64;

use crate::{each, Tally};

/// `Ok(cases)` if `measured <= bound`, else the violation of `law`.
fn within(law: &'static str, measured: f64, bound: f64, cases: u32) -> Result<u32, Violation> {
    if measured <= bound {
        Ok(cases)
    } else {
        Err(Violation {
            law,
            measured,
            bound,
        })
    }
}

/// Runs the attitude checks.
pub fn check_all(t: &mut Tally, draws: u32) {
    t.check("exp_of_scaled_log_is_pow", || {
        let mut d = Draws::new(61);
        each(0..draws, |_| {
            let q = d.unit_quat();
            let a = d.uniform(-2.0, 3.0);
            let got = Quat::from_scaled_axis(q.to_scaled_axis() * a);
            let (_, theta) = q.to_axis_angle();
            // pow turns the unreduced angle 2 atan2(|v|, w), up to 2 pi.
            let turn = if q.w < 0.0 {
                core::f32::consts::TAU - theta
            } else {
                theta
            };
            let error = Quat64::angle_between(got.into(), q.pow(a).into());
            let bound = f64::from(EXP_LOG_POW_MAX_ANGLE_ERROR * (a * turn).abs().max(1.0));
            within("exp_of_scaled_log_is_pow", error, bound, 1).map(|_| ())
        })
    });
    t.check(
        "integrating_a_constant_rate_is_the_axis_angle_rotation",
        || {
            // 25 rad/s about a skew axis at 2000/7 Hz for 2 s, as in BROAD trial 07.
            let omega = Cvec3::new(15.0, -20.0, 0.0);
            let (dt, steps) = (0.0035f32, 571u32);
            let mut q = Quat::IDENTITY;
            for _ in 0..steps {
                q = q.integrate(omega, dt);
            }
            let want = Quat::from_axis_angle(omega, omega.norm() * dt * steps as f32);
            let error = Quat64::angle_between(q.into(), want.into());
            let bound = f64::from(INTEGRATE_STEP_MAX_ANGLE_ERROR) * f64::from(steps) + 1e-5;
            within("integrate", error, bound, steps)
        },
    );
    t.check("smoother_step_response_has_its_time_constant", || {
        let target = Quat::from_rotation_x(1.0);
        let mut s = Smoother::new(Quat::IDENTITY, 0.5);
        for _ in 0..50 {
            s.update(target, 0.01);
        }
        let left = f64::from(s.attitude.angle_to(target));
        let error = libm::fabs(left - libm::exp(-1.0));
        within("smoother decay", error, SMOOTHER_DECAY_MAX_ERROR.into(), 50)
    });
    t.check("filter_finds_inclination_and_rest_bias", || {
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let tilt = Quat::from_rotation_x(0.3) * Quat::from_rotation_y(-0.2);
        let acc = tilt.inv() * Cvec3::new(0.0, 0.0, 9.81);
        let bias = Cvec3::new(0.01, -0.02, 0.005);
        for _ in 0..2000 {
            f.update(bias, acc, 0.01);
        }
        let up = f.attitude() * (acc * (1.0 / 9.81));
        let error = (up - Cvec3::Z).norm().max((f.bias() - bias).norm());
        within("filter at rest", error.into(), 1e-3, 2000)
    });
    t.check("filter_follows_gyro_and_magnetometer", || {
        let truth = Quat::from_rotation_z(0.5);
        let field = Cvec3::new(0.0, 16.0, -41.0);
        let acc = Cvec3::new(0.0, 0.0, 9.81);
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let first = f.update_with_mag(Cvec3::ZERO, acc, truth.inv() * field, 0.01);
        // A second of turning about the vertical at 1 rad/s, then the field.
        let mut g = OrientationFilter::new(FilterParams::DEFAULT);
        g.update(Cvec3::ZERO, acc, 0.01);
        for _ in 0..100 {
            g.update(Cvec3::new(0.0, 0.0, 1.0), acc, 0.01);
        }
        let error = first
            .angle_to(truth)
            .max(g.attitude().angle_to(Quat::from_rotation_z(1.0)));
        // The heading comes from one atan2 (the truth's from_rotation_z adds a
        // sine-cosine): the atan2 bound, or 1e-4 with the default kernels.
        let bound = ATAN2_MAX_ABS_ERROR.max(1e-4);
        within("filter heading and turn", error.into(), bound.into(), 101)
    });
    t.check("filter_reports_and_ignores_bad_samples", || {
        // A NaN gyro reading: NaN out, the last usable reading integrated
        // in its place. A NaN dt: NaN out, the attitude unchanged.
        let mut f = OrientationFilter::new(FilterParams::DEFAULT);
        let acc = Cvec3::new(0.0, 3.0, 9.0);
        let gyr = Cvec3::new(0.1, 0.0, 0.0);
        f.update(gyr, acc, 0.01);
        let mut held = f;
        held.update(gyr, acc, 0.01);
        let nan = f.update(Cvec3::NAN, acc, 0.01);
        let replaced = f.attitude() == held.attitude() && f.diagnostics().gyro_ignored;
        let before = f.attitude();
        let bad_dt = f.update(Cvec3::ZERO, acc, f32::NAN);
        let ok = !nan.is_finite() && !bad_dt.is_finite() && replaced && f.attitude() == before;
        within("filter bad input", if ok { 0.0 } else { 1.0 }, 0.0, 2)
    });
    t.check("filter_recovers_after_the_gyro_range_and_flags_it", || {
        // A 40 rad/s spin about x for half a second, read by a gyro of
        // 2000 °/s that clips, then still: recovered 2 s later.
        let range = 34.906_586;
        let params = FilterParams {
            gyro_range: range,
            ..FilterParams::DEFAULT
        };
        let mut f = OrientationFilter::new(params);
        let (dt, up) = (0.002, Cvec3::new(0.0, 0.0, 9.81));
        let mut truth = Quat::IDENTITY;
        for _ in 0..1000 {
            f.update(Cvec3::ZERO, up, dt);
        }
        let mut saturated = false;
        for _ in 0..250 {
            truth = truth.integrate(Cvec3::new(40.0, 0.0, 0.0), dt);
            f.update(Cvec3::new(range, 0.0, 0.0), truth.inv() * up, dt);
            saturated |= f.diagnostics().gyro_saturated;
        }
        for _ in 0..1000 {
            f.update(Cvec3::ZERO, truth.inv() * up, dt);
        }
        let d = f.diagnostics();
        let error = f.attitude().inv() * Cvec3::Z - truth.inv() * Cvec3::Z;
        let flags_ok = saturated && d.recovering && !d.gyro_saturated;
        within(
            "filter recovery (up vector error)",
            if flags_ok { error.norm().into() } else { 1.0 },
            0.01,
            1,
        )
    });
    t.check(
        "filter_outputs_agree_with_the_attitude_and_ignore_a_magnet",
        || {
            // Still at a known tilt and heading, with the field of a place: the
            // outputs against the truth, then a magnet that doubles the field.
            let truth = Quat::from_euler(EulerRot::ZYX, 0.4, -0.2, 0.3);
            let (g, field) = (Cvec3::new(0.0, 0.0, 9.81), Cvec3::new(0.0, 16.0, -41.0));
            let (acc, mag) = (truth.inv() * g, truth.inv() * field);
            let mut f = OrientationFilter::new(FilterParams::DEFAULT);
            for _ in 0..500 {
                f.update_with_mag(Cvec3::ZERO, acc, mag, 0.01);
            }
            // The compass heading of the truth's y axis (tilted, so not -yaw).
            let forward = truth * Cvec3::Y;
            let heading_of_y = libm::atan2f(forward.x, forward.y);
            let (yaw, pitch, roll) = f.euler(EulerRot::ZYX);
            let rebuilt = Quat::from_euler(EulerRot::ZYX, yaw, pitch, roll);
            let errors = [
                f.attitude().angle_to(truth),
                rebuilt.angle_to(truth),
                (f.heading() - heading_of_y).abs(),
                (f.gravity() - acc).norm() / 9.81,
                f.linear_acceleration(acc).norm() / 9.81,
                f.earth_acceleration(acc).norm() / 9.81,
            ];
            let worst = errors.iter().fold(0.0f32, |w, &e| w.max(e));
            f.update_with_mag(Cvec3::ZERO, acc, mag * 2.0, 0.01);
            let d = f.diagnostics();
            let flags_ok = d.mag_ignored && d.resting && !d.acc_ignored && !d.initialising;
            let error = if flags_ok { worst } else { 1.0 };
            // The heading is an atan2 and the Euler angles go through atan2s:
            // their bounds, or 1e-3 of the filter's own.
            let bound = ATAN2_MAX_ABS_ERROR.max(EULER_MAX_ANGLE_ERROR).max(1e-3);
            within("outputs and magnet", error.into(), bound.into(), 6)
        },
    );
    t.check(
        "filter_skips_each_bad_sample_and_corrects_again_at_once",
        || {
            // Still at a tilt and heading, resting: one bad sample, then a
            // clean one. The bad one is flagged, the state stays a unit
            // attitude, and the next sample is corrected by both sensors as in
            // a clean copy's run: within 5e-4 rad of it (the skipped sample's
            // share of the corrections; 1.1e-4 measured).
            let truth = Quat::from_rotation_z(0.7) * Quat::from_rotation_x(0.3);
            let (g, field) = (Cvec3::new(0.0, 0.0, 9.81), Cvec3::new(0.0, 16.0, -41.0));
            let (acc, mag) = (truth.inv() * g, truth.inv() * field);
            let gyr = Cvec3::new(0.01, -0.02, 0.005);
            let mut f = OrientationFilter::new(FilterParams::DEFAULT);
            for _ in 0..500 {
                f.update_with_mag(gyr, acc, mag, 0.01);
            }
            let big = |v: f32| Cvec3::new(v, -v, v);
            let nan = Cvec3::NAN;
            // (gyro, accelerometer, magnetometer, dt, which flag: 0 gyro, 1 acc, 2 mag)
            let glitches = [
                (nan, acc, mag, 0.01, 0),
                (big(f32::INFINITY), acc, mag, 0.01, 0),
                (big(3.4e38), acc, mag, 0.01, 0),
                (big(1e30), acc, mag, 0.01, 0),
                (gyr, acc, mag, f32::NAN, 0),
                (gyr, acc, mag, f32::INFINITY, 0),
                (gyr, acc, mag, 1e30, 0),
                (gyr, nan, mag, 0.01, 1),
                (gyr, big(f32::INFINITY), mag, 0.01, 1),
                (gyr, big(3.4e38), mag, 0.01, 1),
                (gyr, big(1e30), mag, 0.01, 1),
                (gyr, Cvec3::ZERO, mag, 0.01, 1),
                (gyr, acc, nan, 0.01, 2),
                (gyr, acc, big(f32::INFINITY), 0.01, 2),
                (gyr, acc, big(3.4e38), 0.01, 2),
                (gyr, acc, big(1e30), 0.01, 2),
                (gyr, acc, big(1e6), 0.01, 2),
                (gyr, acc, big(32767.0), 0.01, 2),
                (gyr, acc, Cvec3::ZERO, 0.01, 2),
                (gyr, acc, -mag, 0.01, 2),
            ];
            let mut worst: f32 = 0.0;
            let mut failed = false;
            for (bad_gyr, bad_acc, bad_mag, dt, flag) in glitches {
                let mut glitched = f;
                let mut clean = f;
                glitched.update_with_mag(bad_gyr, bad_acc, bad_mag, dt);
                let d = glitched.diagnostics();
                failed |= ![d.gyro_ignored, d.acc_ignored, d.mag_ignored][flag];
                let q = glitched.attitude();
                failed |= !(q.is_finite() && libm::fabsf(q.norm() - 1.0) < 1e-5);
                clean.update_with_mag(gyr, acc, mag, 0.01);
                glitched.update_with_mag(gyr, acc, mag, 0.01);
                clean.update_with_mag(gyr, acc, mag, 0.01);
                let d = glitched.diagnostics();
                failed |= d.gyro_ignored || d.acc_ignored || d.mag_ignored;
                worst = worst.max(glitched.attitude().angle_to(clean.attitude()));
            }
            let error = if failed { 1.0 } else { worst };
            within(
                "bad sample skipped",
                error.into(),
                5e-4,
                glitches.len() as u32,
            )
        },
    );
    t.check("filter_comes_back_after_a_burst_and_bad_setters", || {
        // A second of garbage on every sensor, then 30 s of clean samples;
        // a NaN bias and a NaN starting attitude, ignored; a smoother fed a
        // measurement whose squared norm overflows.
        let truth = Quat::from_rotation_z(-2.0) * Quat::from_rotation_y(0.4);
        let (g, field) = (Cvec3::new(0.0, 0.0, 9.81), Cvec3::new(0.0, 16.0, -41.0));
        let (acc, mag) = (truth.inv() * g, truth.inv() * field);
        let huge = Cvec3::new(3.4e38, -3.4e38, 3.4e38);
        let p = FilterParams::DEFAULT;
        let mut f = OrientationFilter::with_attitude(p, Quat::NAN);
        let started_new = f == OrientationFilter::new(p);
        f.set_bias(Cvec3::new(f32::NAN, f32::INFINITY, 0.0));
        let bias_kept = f.bias() == Cvec3::ZERO;
        for _ in 0..500 {
            f.update_with_mag(Cvec3::ZERO, acc, mag, 0.01);
        }
        for _ in 0..100 {
            f.update_with_mag(huge, huge, huge, 0.01);
        }
        for _ in 0..3000 {
            f.update_with_mag(Cvec3::ZERO, acc, mag, 0.01);
        }
        let mut s = Smoother::new(Quat::IDENTITY, 0.1);
        let measurement = Quat {
            w: 3e38,
            x: 0.0,
            y: 3e38,
            z: 0.0,
        };
        for _ in 0..200 {
            s.update(measurement, 0.01);
        }
        let half_turn_y = Quat::from_rotation_y(core::f32::consts::FRAC_PI_2);
        let ok = started_new && bias_kept && s.attitude.is_finite();
        let error = f
            .attitude()
            .angle_to(truth)
            .max(s.attitude.angle_to(half_turn_y));
        within(
            "burst and setters",
            if ok { error.into() } else { 1.0 },
            1e-3,
            3,
        )
    });
    t.check("calibrations_undo_offsets_scales_and_soft_iron", || {
        // A reading made by a gyro with an offset, scale errors and a small
        // misalignment, and by a magnetometer with hard and soft iron,
        // taken back by the calibrations built from those errors.
        let v = Cvec3::new(0.3, -1.2, 0.7);
        let (offset, scale) = (Cvec3::new(0.01, -0.02, 0.005), Cvec3::new(1.02, 0.97, 1.01));
        let (c, s) = (0.999_8, 0.019_998_667); // cos and sin of 0.02 rad
        let turned = Cvec3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
        let read = Cvec3::new(turned.x * scale.x, turned.y * scale.y, turned.z * scale.z) + offset;
        let gyro = InertialCalibration {
            misalignment: [
                Cvec3::new(c, s, 0.0),
                Cvec3::new(-s, c, 0.0),
                Cvec3::new(0.0, 0.0, 1.0),
            ],
            sensitivity: Cvec3::new(1.0 / scale.x, 1.0 / scale.y, 1.0 / scale.z),
            offset,
        };
        let field = Cvec3::new(3.0, 16.0, -41.0);
        let hard_iron = Cvec3::new(20.0, -5.0, 8.0);
        let measured = Cvec3::new(field.x * 1.1, field.y * 0.9, field.z) + hard_iron;
        let mag = MagneticCalibration {
            soft_iron: [
                Cvec3::new(1.0 / 1.1, 0.0, 0.0),
                Cvec3::new(0.0, 1.0 / 0.9, 0.0),
                Cvec3::new(0.0, 0.0, 1.0),
            ],
            hard_iron,
        };
        let error = ((gyro.apply(read) - v).norm() / v.norm())
            .max((mag.apply(measured) - field).norm() / field.norm());
        within("calibrations", error.into(), 1e-5, 2)
    });
    t.check("axes_alignment_and_calibration_undo_a_mounting", || {
        // Every one of the 24 mountings turns a reading without changing
        // its length, and the calibration removes a hard-iron offset.
        let field = Cvec3::new(3.0, 16.0, -41.0);
        let mag = MagneticCalibration {
            hard_iron: Cvec3::new(20.0, -5.0, 8.0),
            ..MagneticCalibration::IDENTITY
        };
        let axes = Axis::ALL;
        let mut worst: f32 = 0.0;
        let mut count = 0;
        for x in axes {
            for y in axes {
                if let Some(a) = AxesAlignment::new(x, y) {
                    let v = a.apply(mag.apply(field + mag.hard_iron));
                    worst = worst.max((v.norm() - field.norm()).abs());
                    count += 1;
                }
            }
        }
        let error = if count == 24 { worst } else { 1.0 };
        within("alignment keeps lengths", error.into(), 0.0, count)
    });
    t.check("filter_brings_a_late_magnetometer_forward", || {
        // Level, turning about the vertical at 2 rad/s, read by a
        // magnetometer 20 ms late: unknown, the delay turns the heading
        // by 2.3°; known (`mag_delay`), the reading is brought forward.
        let (dt, g, field) = (
            0.01,
            Cvec3::new(0.0, 0.0, 9.81),
            Cvec3::new(0.0, 16.0, -41.0),
        );
        let rate = Cvec3::new(0.0, 0.0, 2.0);
        let error = |delay: f32| {
            let mut f = OrientationFilter::new(FilterParams {
                mag_delay: delay,
                ..FilterParams::DEFAULT
            });
            let mut past = [Quat::IDENTITY; 3];
            for _ in 0..3000 {
                let truth = past[0].integrate(rate, dt);
                past = [truth, past[0], past[1]];
                f.update_with_mag(rate, truth.inv() * g, past[2].inv() * field, dt);
            }
            f.attitude().angle_to(past[0])
        };
        let (unknown, known) = (error(0.0), error(0.02));
        let ok = unknown > 2.0f32.to_radians();
        within(
            "late magnetometer (heading error, rad)",
            if ok { known.into() } else { 1.0 },
            0.05f64.to_radians(),
            2,
        )
    });
}
