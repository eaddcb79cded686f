//! The attitude filter and the smoother driven through sequences of
//! updates and setters from raw bit patterns: samples, `dt`, every
//! parameter, `set_bias`, `with_attitude`, and the smoother's measurement,
//! time constant and state. After every step the filter's attitude is a
//! finite unit quaternion and its bias finite, and the smoother's state is
//! one after every update it accepted; after the sequence, the default
//! parameters and 130 s of clean samples bring the filter's attitude back
//! to the truth, and 20 s bring the smoother's. No panic on anything.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::attitude::{FilterParams, OrientationFilter, Smoother};
use rigtform::{Cvec3, Quat};

#[derive(arbitrary::Arbitrary, Debug)]
enum Step {
    Update {
        gyr: [f32; 3],
        acc: [f32; 3],
        dt: f32,
    },
    UpdateWithMag {
        gyr: [f32; 3],
        acc: [f32; 3],
        mag: [f32; 3],
        dt: f32,
    },
    /// The same sample `count` times (bursts).
    Repeat {
        gyr: [f32; 3],
        acc: [f32; 3],
        mag: [f32; 3],
        dt: f32,
        count: u8,
    },
    SetBias([f32; 3]),
    SetParam {
        which: u8,
        value: f32,
    },
    WithAttitude([f32; 4]),
    Smooth {
        q: [f32; 4],
        dt: f32,
    },
    SetTau(f32),
    SetSmoothed([f32; 4]),
}

fn vec3([x, y, z]: [f32; 3]) -> Cvec3 {
    Cvec3::new(x, y, z)
}

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat { w, x, y, z }
}

fn is_unit(q: Quat) -> bool {
    q.is_finite() && (q.norm() - 1.0).abs() <= 1e-4
}

fn set_param(p: &mut FilterParams, which: u8, value: f32) {
    let field = match which % 15 {
        0 => &mut p.gravity,
        1 => &mut p.tau_acc,
        2 => &mut p.tau_mag,
        3 => &mut p.tau_bias,
        4 => &mut p.bias_drift,
        5 => &mut p.bias_noise,
        6 => &mut p.tau_bias_rest,
        7 => &mut p.rest_gyro,
        8 => &mut p.max_bias,
        9 => &mut p.rest_acc,
        10 => &mut p.rest_time,
        11 => &mut p.acc_gate,
        12 => &mut p.mag_gate,
        13 => &mut p.gyro_range,
        _ => &mut p.mag_delay,
    };
    *field = value;
}

/// The filter's state is usable: a finite unit attitude, a finite bias.
fn check(f: &OrientationFilter, step: &Step) {
    assert!(is_unit(f.attitude()), "{:?} after {step:?}", f.attitude());
    assert!(f.bias().is_finite(), "{:?} after {step:?}", f.bias());
}

/// 130 s at 100 Hz of a still sensor at `truth` in Berlin's field, with
/// the default parameters: the attitude comes back (within 0.5°).
fn comes_back(mut f: OrientationFilter) {
    f.params = FilterParams::DEFAULT;
    let truth = Quat::from_rotation_z(2.0) * Quat::from_rotation_x(0.4);
    let gravity = Cvec3::new(0.0, 0.0, 9.81);
    let field = Cvec3::new(0.0, 16.0, -41.0);
    let (acc, mag) = (truth.inv() * gravity, truth.inv() * field);
    for _ in 0..13_000 {
        f.update_with_mag(Cvec3::new(0.01, -0.02, 0.005), acc, mag, 0.01);
        assert!(is_unit(f.attitude()));
    }
    let error = f.attitude().angle_to(truth);
    assert!(error < 0.5f32.to_radians(), "{error} rad: {f:?}");
}

fuzz_target!(|steps: Vec<Step>| {
    let mut f = OrientationFilter::new(FilterParams::DEFAULT);
    let mut s = Smoother::new(Quat::IDENTITY, 0.5);
    for step in steps.iter().take(64) {
        match *step {
            Step::Update { gyr, acc, dt } => {
                f.update(vec3(gyr), vec3(acc), dt);
            }
            Step::UpdateWithMag { gyr, acc, mag, dt } => {
                f.update_with_mag(vec3(gyr), vec3(acc), vec3(mag), dt);
            }
            Step::Repeat {
                gyr,
                acc,
                mag,
                dt,
                count,
            } => {
                for _ in 0..count {
                    f.update_with_mag(vec3(gyr), vec3(acc), vec3(mag), dt);
                    check(&f, step);
                }
            }
            Step::SetBias(b) => f.set_bias(vec3(b)),
            Step::SetParam { which, value } => set_param(&mut f.params, which, value),
            Step::WithAttitude(q) => f = OrientationFilter::with_attitude(f.params, quat(q)),
            Step::Smooth { q, dt } => {
                let out = s.update(quat(q), dt);
                if out.is_finite() {
                    assert!(is_unit(s.attitude), "{:?} after {step:?}", s.attitude);
                    assert_eq!(out, s.attitude);
                }
            }
            Step::SetTau(tau) => s.tau = tau,
            Step::SetSmoothed(q) => s.attitude = quat(q),
        }
        check(&f, step);
    }
    comes_back(f);
    s.tau = 0.5;
    let target = Quat::from_rotation_y(-1.0);
    for _ in 0..2000 {
        s.update(target, 0.01);
    }
    assert!(s.attitude.angle_to(target) < 1e-3, "{s:?}");
});
