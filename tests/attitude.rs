//! The exponential and logarithm maps and gyro integration against an f64
//! reference, with the bounds of `rigtform::accuracy` the docs quote
//! (`cargo test --test attitude -- --nocapture` prints the measured maxima).

use rigtform_testkit as testkit;

use nalgebra as na;
use rigtform::accuracy;
use rigtform::{Cvec3, Quat};
use testkit::{angle_error, draw_count, pow64, rotation_angle64, to_f64, vec_to_f64, Draws, Worst};

/// The exponential map in f64: the rotation by |v| about v.
fn exp64(v: na::Vector3<f64>) -> na::Quaternion<f64> {
    let angle = v.norm();
    if angle == 0.0 {
        return na::Quaternion::identity();
    }
    let (s, c) = (angle * 0.5).sin_cos();
    na::Quaternion::from_parts(c, v * (s / angle))
}

/// A random vector of length `angle` (uniform direction).
fn vector_of_length(draws: &mut Draws, angle: f64) -> Cvec3 {
    let k = draws.unit_vec64() * angle;
    Cvec3::new(k.x as f32, k.y as f32, k.z as f32)
}

/// An angle drawn log-uniformly over [1e-38, hi] half the time, uniformly
/// over [0, hi] otherwise: tiny angles and everyday ones.
fn angle(draws: &mut Draws, hi: f64) -> f64 {
    if draws.uniform(0.0, 1.0) < 0.5 {
        10f64.powf(draws.uniform(-38.0, hi.log10()))
    } else {
        draws.uniform(0.0, hi)
    }
}

#[test]
fn scaled_axis_maps_are_within_their_bounds() {
    let mut draws = Draws::new(61);
    let mut exp = Worst::new("from_scaled_axis: angle error / |v|");
    let mut exp_norm = Worst::new("from_scaled_axis: |norm - 1|");
    let mut log = Worst::new("to_scaled_axis: |error| / |v|");
    for _ in 0..draw_count() {
        let length = angle(&mut draws, 1000.0);
        let v = vector_of_length(&mut draws, length);
        if v == Cvec3::ZERO {
            continue;
        }
        let v64 = vec_to_f64(v);
        let q = Quat::from_scaled_axis(v);
        exp.see(angle_error(q, exp64(v64)) / v64.norm(), || format!("{v:?}"));
        exp_norm.see((to_f64(q).norm() - 1.0).abs(), || format!("{v:?}"));

        // The logarithm of a unit quaternion rounded to f32, against the
        // f64 logarithm of that same (rounded) quaternion.
        let length = angle(&mut draws, core::f64::consts::TAU);
        let w = vector_of_length(&mut draws, length);
        let q = Quat::from_scaled_axis(w);
        let q64 = to_f64(q);
        let beta = q64.imag().norm();
        if beta == 0.0 {
            continue;
        }
        let want = q64.imag() * (2.0 * beta.atan2(q64.w) / beta);
        let got = vec_to_f64(q.to_scaled_axis());
        log.see((got - want).norm() / want.norm(), || format!("{q:?}"));
    }
    exp.check(accuracy::FROM_SCALED_AXIS_MAX_REL_ERROR);
    exp_norm.check(accuracy::UNIT_NORM_ERROR);
    log.check(accuracy::TO_SCALED_AXIS_MAX_REL_ERROR);
}

#[test]
fn exp_of_scaled_log_is_pow() {
    let mut draws = Draws::new(62);
    let mut worst = Worst::new("exp(a log q) vs pow(q, a), per max(1, |a| theta)");
    for _ in 0..draw_count() {
        let q = draws.unit_quat();
        let a = draws.uniform(-2.0, 3.0) as f32;
        let got = Quat::from_scaled_axis(q.to_scaled_axis() * a);
        let theta = 2.0 * to_f64(q).imag().norm().atan2(q.w as f64);
        let scale = (a as f64 * theta).abs().max(1.0);
        worst.see(
            rotation_angle64(to_f64(got), to_f64(q.pow(a))) / scale,
            || format!("{q:?} {a}"),
        );
        // And both against the f64 power of the notes.
        let bound = accuracy::POW_MAX_ANGLE_ERROR + accuracy::EXP_LOG_POW_MAX_ANGLE_ERROR;
        assert!(angle_error(got, pow64(to_f64(q), a as f64)) / scale <= bound as f64);
    }
    worst.check(accuracy::EXP_LOG_POW_MAX_ANGLE_ERROR);
}

#[test]
fn integrate_step_is_within_its_bound() {
    let mut draws = Draws::new(63);
    let mut worst = Worst::new("integrate: angle error of one step (rad)");
    let mut norm = Worst::new("integrate: |norm - 1|");
    for _ in 0..draw_count() {
        let q = draws.unit_quat();
        let dt = draws.uniform(1e-4, 0.02) as f32;
        let length = angle(&mut draws, 1.0) / dt as f64;
        let omega = vector_of_length(&mut draws, length);
        let got = q.integrate(omega, dt);
        let step = vec_to_f64(omega) * dt as f64;
        let want = to_f64(q).normalize() * exp64(step);
        worst.see(angle_error(got, want), || format!("{q:?} {omega:?} {dt}"));
        norm.see((to_f64(got).norm() - 1.0).abs(), || {
            format!("{q:?} {omega:?} {dt}")
        });
    }
    worst.check(accuracy::INTEGRATE_STEP_MAX_ANGLE_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}

/// Integrating a constant rate `omega` for `T`
/// seconds is the rotation by `|omega| T` about `omega`, within the
/// per-step bound times the number of steps.
#[test]
fn integrating_a_constant_rate_is_the_axis_angle_rotation() {
    let cases = [
        (Cvec3::new(0.3, -1.2, 0.8), 100.0f32, 3.0f32),
        (Cvec3::new(0.0, 0.0, 25.0), 2000.0 / 7.0, 2.0),
        (Cvec3::new(-4.0, 2.0, 1.0), 1000.0, 1.5),
        (Cvec3::new(1e-3, 2e-3, -1e-3), 100.0, 10.0),
    ];
    for (omega, rate, seconds) in cases {
        let dt = 1.0 / rate;
        let steps = (seconds * rate).round() as u32;
        let start = Quat::from_rotation_x(0.4);
        let mut q = start;
        for _ in 0..steps {
            q = q.integrate(omega, dt);
        }
        // The exact turn in f64 over the f32 step times the step count.
        let turn = vec_to_f64(omega) * (dt as f64 * steps as f64);
        let exact = Quat::from_axis_angle(omega, (omega.norm() * dt) * steps as f32);
        let error = angle_error(q, to_f64(start) * exp64(turn));
        let bound = steps as f64 * accuracy::INTEGRATE_STEP_MAX_ANGLE_ERROR as f64;
        println!(
            "{omega:?} at {rate} Hz for {seconds} s: error {error:.3e} rad, bound {bound:.1e}"
        );
        assert!(error <= bound, "{omega:?} {rate}: {error}");
        assert!(
            q.angle_to(start * exact) as f64 <= bound + 1e-5,
            "{omega:?} {rate}"
        );
    }
}

#[test]
fn long_integration_chains_stay_unit() {
    let mut q = Quat::IDENTITY;
    let mut worst: f32 = 0.0;
    for i in 0..100_000u32 {
        let t = i as f32 * 1e-3;
        let omega = Cvec3::new(t.sin() * 5.0, 2.0, (3.0 * t).cos());
        q = q.integrate(omega, 1e-3);
        worst = worst.max((q.norm() - 1.0).abs());
    }
    println!("integrate: 100,000 steps, max |norm - 1| {worst:.3e}");
    assert!(worst <= accuracy::NORMALIZE_MAX_NORM_ERROR, "{worst}");
}

#[test]
fn to_scaled_axis_is_scale_free() {
    // The docs: any finite quaternion, not only unit ones, with subnormal or
    // huge components scaled exactly.
    let mut draws = Draws::new(71);
    for _ in 0..1_000 {
        let q = draws.unit_quat();
        let want = q.to_scaled_axis();
        let bound = 2.0 * accuracy::TO_SCALED_AXIS_MAX_REL_ERROR * want.norm().max(1e-30);
        for k in [2f32.powi(-120), 1e-20, 3.0, 1e20, 2f32.powi(100)] {
            let got = Quat::from_wxyz(q.w * k, q.x * k, q.y * k, q.z * k).to_scaled_axis();
            assert!(
                (got - want).norm() <= bound,
                "{q:?} times {k:e}: {got:?}, want {want:?}"
            );
        }
    }
    // Subnormal components: a quarter turn about x.
    let got = Quat::from_wxyz(1e-42, 1e-42, 0.0, 0.0).to_scaled_axis();
    let want = Cvec3::new(core::f32::consts::FRAC_PI_2, 0.0, 0.0);
    assert!((got - want).norm() <= 2.0 * accuracy::TO_SCALED_AXIS_MAX_REL_ERROR * want.norm());
}
