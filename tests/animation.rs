//! The glTF keyframe samplers (`rigtform::animation`): their accuracy
//! against the same evaluation in f64 (the constants of
//! `rigtform::accuracy` the docs quote), their laws as proptest
//! properties, and their answers to bad input.

use nalgebra as na;
use proptest::prelude::*;
use rigtform::accuracy;
use rigtform::animation::{Interpolation, Sampler, SamplerError};
use rigtform::{Cvec3, Quat};
use rigtform_testkit as testkit;
use testkit::strategies::{unit_quat, vec3};
use testkit::{angle_error, draw_count, slerp64, to_f64, vec_to_f64, Draws, Worst};

/// Five key times: a start in [0, 10] s and intervals in [0.01, 2] s.
fn draw_times(draws: &mut Draws) -> Vec<f32> {
    let mut t = draws.uniform(0.0, 10.0) as f32;
    (0..5)
        .map(|_| {
            let now = t;
            t += draws.uniform(0.01, 2.0) as f32;
            now
        })
        .collect()
}

/// A time uniform over the keys, and the segment it falls in with its `u`
/// in f64: the reference's view of where `t` is.
fn draw_time(draws: &mut Draws, times: &[f32]) -> (f32, usize, f64) {
    let (first, last) = (times[0], times[times.len() - 1]);
    let t = draws.uniform(first as f64, last as f64) as f32;
    let k0 = times.partition_point(|&k| k <= t).clamp(1, times.len() - 1) - 1;
    let (t0, t1) = (times[k0] as f64, times[k0 + 1] as f64);
    (t, k0, (t as f64 - t0) / (t1 - t0))
}

fn hermite64(u: f64) -> [f64; 4] {
    let (uu, uuu) = (u * u, u * u * u);
    [
        2.0 * uuu - 3.0 * uu + 1.0,
        uuu - 2.0 * uu + u,
        -2.0 * uuu + 3.0 * uu,
        uuu - uu,
    ]
}

fn quat64(q: Quat) -> na::Vector4<f64> {
    na::Vector4::new(q.w as f64, q.x as f64, q.y as f64, q.z as f64)
}

fn tangent_quat(draws: &mut Draws) -> Quat {
    let mut c = || draws.uniform(-1.0, 1.0) as f32;
    Quat {
        w: c(),
        x: c(),
        y: c(),
        z: c(),
    }
}

fn draw_vec3(draws: &mut Draws, r: f64) -> Cvec3 {
    let mut c = || draws.uniform(-r, r) as f32;
    Cvec3::new(c(), c(), c())
}

#[test]
fn linear_rotation_is_within_its_bound() {
    let mut draws = Draws::new(251);
    let mut worst = Worst::new("Sampler<Quat> LINEAR: angle error (rad)");
    for _ in 0..draw_count() / 4 {
        let times = draw_times(&mut draws);
        let keys: Vec<Quat> = (0..5).map(|_| draws.unit_quat()).collect();
        let sampler = Sampler::new(Interpolation::Linear, &times, &keys).unwrap();
        for _ in 0..4 {
            let (t, k0, u) = draw_time(&mut draws, &times);
            let want = slerp64(to_f64(keys[k0]), to_f64(keys[k0 + 1]), u);
            worst.see(angle_error(sampler.sample(t), want), || {
                format!("{times:?} {keys:?} t = {t:?}")
            });
        }
    }
    worst.check(accuracy::SAMPLER_LINEAR_MAX_ANGLE_ERROR);
}

#[test]
fn cubic_rotation_is_within_its_bound() {
    let mut draws = Draws::new(252);
    let mut worst = Worst::new("Sampler<Quat> CUBICSPLINE: angle error / condition");
    let mut norm = Worst::new("Sampler<Quat> CUBICSPLINE: |norm - 1|");
    for _ in 0..draw_count() / 4 {
        let times = draw_times(&mut draws);
        let values: Vec<Quat> = (0..15)
            .map(|i| {
                if i % 3 == 1 {
                    draws.unit_quat()
                } else {
                    tangent_quat(&mut draws)
                }
            })
            .collect();
        let sampler = Sampler::new(Interpolation::CubicSpline, &times, &values).unwrap();
        for _ in 0..4 {
            let (t, k0, u) = draw_time(&mut draws, &times);
            let td = times[k0 + 1] as f64 - times[k0] as f64;
            let s = hermite64(u);
            let terms = [
                quat64(values[3 * k0 + 1]) * s[0],
                quat64(values[3 * k0 + 2]) * (s[1] * td),
                quat64(values[3 * k0 + 4]) * s[2],
                quat64(values[3 * k0 + 3]) * (s[3] * td),
            ];
            let sum = terms[0] + terms[1] + terms[2] + terms[3];
            if sum.norm() < 1e-3 {
                continue; // the direction of a near-zero sum is not defined by its inputs
            }
            // How much the sum cancels: rounding errors of the terms, relative
            // to their size, grow by this factor in the sum's direction.
            let condition = terms.iter().map(|v| v.norm()).sum::<f64>() / sum.norm();
            let want = na::Quaternion::new(sum[0], sum[1], sum[2], sum[3]).normalize();
            let got = sampler.sample(t);
            worst.see(angle_error(got, want) / condition, || {
                format!("{times:?} {values:?} t = {t:?}")
            });
            norm.see((to_f64(got).norm() - 1.0).abs(), || format!("t = {t:?}"));
        }
    }
    worst.check(accuracy::SAMPLER_CUBIC_MAX_ANGLE_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}

#[test]
fn vec3_is_within_its_bound() {
    let mut draws = Draws::new(253);
    let mut worst = Worst::new("Sampler<Cvec3> LINEAR, CUBICSPLINE: rel. error");
    for _ in 0..draw_count() / 4 {
        let times = draw_times(&mut draws);
        let keys: Vec<Cvec3> = (0..5).map(|_| draw_vec3(&mut draws, 100.0)).collect();
        let cubic: Vec<Cvec3> = (0..15).map(|_| draw_vec3(&mut draws, 100.0)).collect();
        let linear = Sampler::new(Interpolation::Linear, &times, &keys).unwrap();
        let spline = Sampler::new(Interpolation::CubicSpline, &times, &cubic).unwrap();
        let max = |vs: &[na::Vector3<f64>]| vs.iter().map(|v| v.amax()).fold(0.0, f64::max);
        for _ in 0..4 {
            let (t, k0, u) = draw_time(&mut draws, &times);
            let (a, b) = (vec_to_f64(keys[k0]), vec_to_f64(keys[k0 + 1]));
            let want = a * (1.0 - u) + b * u;
            let got = vec_to_f64(linear.sample(t));
            worst.see((got - want).amax() / max(&[a, b]), || {
                format!("LINEAR {times:?} {keys:?} t = {t:?}")
            });

            let td = times[k0 + 1] as f64 - times[k0] as f64;
            let s = hermite64(u);
            let v = |i: usize| vec_to_f64(cubic[3 * k0 + i]);
            let terms = [v(1), v(2) * td, v(4), v(3) * td];
            let want = terms[0] * s[0] + terms[1] * s[1] + terms[2] * s[2] + terms[3] * s[3];
            let got = vec_to_f64(spline.sample(t));
            worst.see((got - want).amax() / max(&terms), || {
                format!("CUBICSPLINE {times:?} {cubic:?} t = {t:?}")
            });
        }
    }
    worst.check(accuracy::SAMPLER_VEC3_MAX_REL_ERROR);
}

#[test]
fn bad_input_gets_its_documented_error() {
    let keys = [Cvec3::X, Cvec3::Y, Cvec3::Z];
    let new = |times: &[f32], values: &[Cvec3]| {
        Sampler::new(Interpolation::Linear, times, values).map(|_| ())
    };
    assert_eq!(new(&[], &[]), Err(SamplerError::NoKeys));
    assert_eq!(
        new(&[0.0, f32::NAN, 2.0], &keys),
        Err(SamplerError::NonFiniteTime(1))
    );
    assert_eq!(
        new(&[0.0, 1.0, f32::INFINITY], &keys),
        Err(SamplerError::NonFiniteTime(2))
    );
    assert_eq!(
        new(&[0.0, 2.0, 1.0], &keys),
        Err(SamplerError::TimesNotIncreasing(2))
    );
    assert_eq!(
        new(&[0.0, 1.0, 1.0], &keys),
        Err(SamplerError::TimesNotIncreasing(2))
    );
    assert_eq!(
        new(&[-3e38, 3e38, 3.1e38], &keys),
        Err(SamplerError::IntervalTooLong(1))
    );
    assert_eq!(
        new(&[0.0, 1.0], &keys),
        Err(SamplerError::LengthMismatch {
            expected: 2,
            found: 3
        })
    );
    assert_eq!(
        Sampler::new(Interpolation::CubicSpline, &[0.0], &keys[..2]).map(|_| ()),
        Err(SamplerError::LengthMismatch {
            expected: 3,
            found: 2
        })
    );
    let nan_key = [Cvec3::X, Cvec3::new(0.0, f32::NAN, 0.0), Cvec3::Z];
    assert_eq!(
        new(&[0.0, 1.0, 2.0], &nan_key),
        Err(SamplerError::NonFiniteValue(1))
    );
    let inf_quat = [
        Quat::IDENTITY,
        Quat {
            w: 0.0,
            x: f32::INFINITY,
            y: 0.0,
            z: 0.0,
        },
    ];
    assert_eq!(
        Sampler::new(Interpolation::Step, &[0.0, 1.0], &inf_quat).map(|_| ()),
        Err(SamplerError::NonFiniteValue(1))
    );
    // Every error has a message.
    assert_eq!(
        SamplerError::NonFiniteTime(4).to_string(),
        "key time 4 is not finite"
    );
}

#[test]
fn one_key_is_the_value_at_every_time_and_nan_time_is_nan() {
    let q = [Quat::from_rotation_x(1.0)];
    for interpolation in [Interpolation::Step, Interpolation::Linear] {
        let s = Sampler::new(interpolation, &[2.0], &q).unwrap();
        for t in [f32::NEG_INFINITY, -1.0, 2.0, 3.0, f32::INFINITY] {
            assert_eq!(s.sample(t), q[0]);
        }
        assert!(s.sample(f32::NAN).is_nan());
    }
    let cubic = [Cvec3::X, Cvec3::Y, Cvec3::Z];
    let s = Sampler::new(Interpolation::CubicSpline, &[2.0], &cubic).unwrap();
    assert_eq!(s.sample(0.0), Cvec3::Y);
    assert!(s.sample(f32::NAN).x.is_nan());
}

/// Tangents whose product with a long interval overflows f32: the sample
/// is finite or infinite, never NaN, at a segment's end (where a weight is
/// 0, and `0 * inf` would be NaN) and inside it (where tangent terms of
/// opposite signs could make `inf - inf`).
#[test]
fn overflowing_tangents_make_no_nan() {
    let big = 2.9e7;
    let times = [-1.2e31, -2.1e-28, 0.0];
    let mut values = [Cvec3::ZERO; 9];
    values[2] = Cvec3::new(big, -big, 0.0); // out-tangent of key 0
    values[3] = Cvec3::new(big, big, big); // in-tangent of key 1
    let s = Sampler::new(Interpolation::CubicSpline, &times, &values).unwrap();
    for t in [-2.1039314e-28, -1e31, -6e30, -1e30, -1.0, -2.1e-28, -1e-40] {
        let v = s.sample(t);
        assert!(
            !v.x.is_nan() && !v.y.is_nan() && !v.z.is_nan(),
            "{t}: {v:?}"
        );
    }
    let rotations = [Quat::from_xyzw(big, -big, big, big); 9];
    let s = Sampler::new(Interpolation::CubicSpline, &times, &rotations).unwrap();
    for t in [-2.1039314e-28, -6e30, -1.0] {
        assert!(s.sample(t).is_finite(), "{t}");
    }
}

#[test]
fn cubic_rotations_through_zero_give_identity() {
    // q, then -q, zero tangents: the Hermite sum is zero halfway.
    let q = Quat::from_rotation_z(1.0);
    let zero = Quat {
        w: 0.0,
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };
    let values = [zero, q, zero, zero, -q, zero];
    let s = Sampler::new(Interpolation::CubicSpline, &[0.0, 1.0], &values).unwrap();
    assert_eq!(s.sample(0.5), Quat::IDENTITY);
}

#[test]
fn keys_more_than_a_half_turn_apart_go_the_short_way() {
    // Stored 300 degrees apart about z: LINEAR turns by the 60 degrees between them.
    let a = Quat::from_rotation_z(0.0);
    let b = Quat::from_rotation_z(300f32.to_radians());
    assert!(a.dot(b) < 0.0);
    let keys = [a, b];
    let s = Sampler::new(Interpolation::Linear, &[0.0, 1.0], &keys).unwrap();
    let mid = s.sample(0.5);
    // Within slerp's bound (the short way is 60 degrees; the long way's
    // halfway point, 150 degrees, would be 180 degrees off).
    let bound = 2.0 * accuracy::SAMPLER_LINEAR_MAX_ANGLE_ERROR;
    assert!(mid.angle_to(Quat::from_rotation_z(-30f32.to_radians())) < bound);
}

/// Strictly increasing times: a start and positive intervals.
fn times(n: usize) -> impl Strategy<Value = Vec<f32>> {
    (
        -10.0f32..10.0,
        prop::collection::vec(0.01f32..3.0, n.saturating_sub(1)),
    )
        .prop_map(|(start, gaps)| {
            let mut t = start;
            std::iter::once(start)
                .chain(gaps.into_iter().map(|g| {
                    t += g;
                    t
                }))
                .collect()
        })
}

fn interpolation() -> impl Strategy<Value = Interpolation> {
    prop::sample::select(vec![
        Interpolation::Step,
        Interpolation::Linear,
        Interpolation::CubicSpline,
    ])
}

/// A channel of 1 to 6 keys: times and three values per key (the middle
/// ones unit rotations), of which STEP and LINEAR take every third.
fn rotation_channel() -> impl Strategy<Value = (Interpolation, Vec<f32>, Vec<Quat>)> {
    (interpolation(), 1usize..7).prop_flat_map(|(interpolation, n)| {
        (
            Just(interpolation),
            times(n),
            prop::collection::vec((unit_quat(), unit_quat(), unit_quat()), n),
        )
            .prop_map(|(interpolation, times, triples)| {
                let values = triples
                    .into_iter()
                    .flat_map(|(a, v, b)| match interpolation {
                        Interpolation::CubicSpline => vec![a, v, b],
                        _ => vec![v],
                    })
                    .collect();
                (interpolation, times, values)
            })
    })
}

fn key_value(interpolation: Interpolation, values: &[Quat], k: usize) -> Quat {
    match interpolation {
        Interpolation::CubicSpline => values[3 * k + 1],
        _ => values[k],
    }
}

proptest! {
    #[test]
    fn law_keys_are_hit_exactly((interpolation, times, values) in rotation_channel()) {
        let s = Sampler::new(interpolation, &times, &values).unwrap();
        for (k, &t) in times.iter().enumerate() {
            let key = key_value(interpolation, &values, k);
            prop_assert_eq!(s.sample(t), key, "key {}", k);
        }
        // Clamped on both sides.
        prop_assert_eq!(s.sample(times[0] - 1.0), key_value(interpolation, &values, 0));
        prop_assert_eq!(s.sample(f32::INFINITY), key_value(interpolation, &values, times.len() - 1));
    }

    #[test]
    fn law_samples_of_unit_keys_are_unit((interpolation, times, values) in rotation_channel(), f in 0.0f32..=1.0) {
        let s = Sampler::new(interpolation, &times, &values).unwrap();
        let (first, last) = s.span();
        let q = s.sample(first + f * (last - first));
        prop_assert!((q.norm() - 1.0).abs() <= accuracy::UNIT_NORM_ERROR, "{q:?}");
    }

    #[test]
    fn law_step_is_constant_between_keys((_i, times, values) in rotation_channel(), f in 0.0f32..1.0) {
        let keys: Vec<Quat> = values.iter().copied().take(times.len()).collect();
        let s = Sampler::new(Interpolation::Step, &times, &keys).unwrap();
        for k in 0..times.len().saturating_sub(1) {
            let t = times[k] + f * (times[k + 1] - times[k]);
            if t < times[k + 1] {
                prop_assert_eq!(s.sample(t), keys[k]);
            }
        }
    }

    #[test]
    fn law_cubic_spline_is_continuous(
        times in times(4),
        values in prop::collection::vec(vec3(), 12),
        f in 0.0f32..1.0,
        k in 0usize..3,
    ) {
        // At any time, a step of 1e-3 s moves the spline by at most the
        // bound of its derivative times the step (plus rounding): the
        // derivative of the Hermite cubic is at most 1.5 |v1 - v0| / td
        // + |b0| + |a1| in each component (|s0'|, |s2'| <= 1.5 / td, |s1'|,
        // |s3'| <= 1).
        let s = Sampler::new(Interpolation::CubicSpline, &times, &values).unwrap();
        let td = times[k + 1] - times[k];
        let t = times[k] + f * td;
        let h = 1e-3f32;
        let (p0, b0, a1, p1) = (values[3 * k + 1], values[3 * k + 2], values[3 * k + 3], values[3 * k + 4]);
        let slope = 1.5 * (p1 - p0).norm() / td + b0.norm() + a1.norm();
        let scale = p0.norm() + p1.norm() + td * (b0.norm() + a1.norm());
        let step = (s.sample((t + h).min(times[k + 1])) - s.sample(t)).norm();
        prop_assert!(step <= slope * h * 1.01 + 1e-5 * scale, "{step} > {slope} * {h}");
        // Across the key at the segment's end: from both sides, the key.
        let end = times[k + 1];
        let before = s.sample(end - h.min(td) * 1e-3);
        prop_assert!((before - p1).norm() <= slope * h * 1e-3 * 1.01 + 1e-5 * scale);
        prop_assert!((s.sample(end) - p1).norm() <= 1e-6 * scale);
    }

    #[test]
    fn law_no_input_bits_panic(
        interpolation in interpolation(),
        times in prop::collection::vec(any::<u32>().prop_map(f32::from_bits), 0..5),
        values in prop::collection::vec(prop::array::uniform3(any::<u32>().prop_map(f32::from_bits)), 0..12),
        t in any::<u32>().prop_map(f32::from_bits),
    ) {
        let values: Vec<Cvec3> = values.into_iter().map(Cvec3::from_array).collect();
        if let Ok(s) = Sampler::new(interpolation, &times, &values) {
            let v = s.sample(t);
            // STEP only copies keys, which the sampler checked are finite.
            prop_assert!(t.is_nan() || v.is_finite() || interpolation != Interpolation::Step);
            prop_assert_eq!(v.x.is_nan() && v.y.is_nan() && v.z.is_nan(), t.is_nan() && v.x.is_nan());
        }
    }
}
