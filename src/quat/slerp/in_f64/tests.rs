//! The f64 evaluation's laws: which pairs it takes, its pair and arc
//! against f64 arithmetic on the same inputs, the bits of every register
//! form alike, and its polynomials swept against `std`'s f64.

use super::*;
use crate::accuracy::{
    PHI_OVER_SINE_F64_MAX_REL_ERROR, PHI_SQUARED_F64_MAX_REL_ERROR, SINC_F64_MAX_REL_ERROR,
    SLERP_COEFFICIENT_F64_MAX_REL_ERROR,
};
use crate::float::sweep::{floats, SAMPLE_STEP};
use core::f32::consts::FRAC_PI_2;
use rand::{Rng, SeedableRng};

pub(in crate::quat) use crate::test_draws::unit_quat as unit;

/// Ordinary pairs, random unit quaternions with `alpha` in (0, 1], are
/// the f64 evaluation's, and `slerp` returns its result.
#[test]
fn takes_ordinary_pairs() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(12);
    for _ in 0..10_000 {
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        let alpha: f32 = rng.random_range(0.0..=1.0);
        if alpha == 0.0 {
            continue;
        }
        let q = a.slerp_f64(b, alpha).expect("an ordinary pair");
        assert_eq!(q, a.slerp(b, alpha));
    }
}

/// Inputs off unit norm are taken while their squared norms are within
/// 1e-6 of each other relative to the second's, whatever its size.
#[test]
fn takes_pairs_of_equal_norms_off_unit() {
    let a = Quat::from_rotation_x(0.3).map(|c| c * 2.0);
    let b = Quat::from_rotation_y(0.7).map(|c| c * 2.0);
    assert!(a.slerp_f64(b, 0.5).is_some());
    // Each component two ulps of 1 larger: |a|^2 is about 4 (1 + 4.8e-7),
    // 1.9e-6 above |b|^2 and within 1e-6 of 4.
    let a = a.map(|c| c * (1.0 + 2.0 * f32::EPSILON));
    assert!((a.norm_squared() - b.norm_squared()).abs() < 4e-6);
    assert!(a.slerp_f64(b, 0.5).is_some());
    assert!(a.map(|c| c * 1.01).slerp_f64(b, 0.5).is_none());
}

/// Two ordinary unit quaternions, 1.37 rad apart.
pub(in crate::quat) fn ordinary_pair() -> (Quat, Quat) {
    (Quat::from_rotation_x(0.3), Quat::from_rotation_y(0.7))
}

/// Pairs the evaluation leaves to the f32 one: norms more than 1e-6
/// apart, components beyond 2^16, non-finite input, pairs 2^-12 rad
/// apart or less (identical ones included).
pub(in crate::quat) fn rare_pairs() -> [(Quat, Quat); 8] {
    let (a, b) = ordinary_pair();
    let near = a * Quat::from_rotation_z(2.0 * SMALL_ANGLE * 0.9);
    let huge = Quat::from_wxyz(1e5, 0.0, 0.0, 0.0);
    [
        (a, a),
        (a, -a),
        (a, near),
        (a.map(|c| c * 1.01), b),
        (huge, huge * Quat::from_rotation_x(1.0)),
        (huge, b),
        (Quat::NAN, b),
        (a, Quat::from_wxyz(f32::INFINITY, 0.0, 0.0, 0.0)),
    ]
}

/// The pair just past the small angles, which the evaluation takes.
pub(in crate::quat) fn just_past_the_small_angles() -> (Quat, Quat) {
    let (a, _) = ordinary_pair();
    (a, a * Quat::from_rotation_z(2.0 * SMALL_ANGLE * 1.1))
}

/// What the evaluation leaves to the f32 one: `alpha` outside (0, 1],
/// and the rare pairs.
#[test]
fn leaves_the_rare_inputs_to_the_f32_evaluation() {
    let (a, b) = ordinary_pair();
    for alpha in [0.0, -0.25, 1.5, f32::NAN, f32::INFINITY] {
        assert!(a.slerp_f64(b, alpha).is_none(), "alpha {alpha}");
    }
    for (p, q) in rare_pairs() {
        assert!(p.slerp_f64(q, 0.5).is_none(), "{p:?} {q:?}");
    }
    let (a, past) = just_past_the_small_angles();
    assert!(a.slerp_f64(past, 0.5).is_some());
}

/// Pairs at an exact right angle (a zero dot product, `near == far`),
/// where neither sign of `b` is shorter, are left to the f32
/// evaluation, so that `slerp(a, b)` and `slerp(a, -b)` choose alike.
#[test]
fn pairs_at_a_right_angle_are_left_to_the_f32_evaluation() {
    let a = Quat::from_xyzw(1.0, 0.0, 0.0, 0.0);
    for b in [
        Quat::from_xyzw(0.0, 1.0, 0.0, 0.0),
        Quat::from_xyzw(0.0, 0.0, 0.6, 0.8),
    ] {
        let pair = Pair::of_quats(&a, &b);
        assert_eq!(pair.near(), pair.far());
        assert!(!pair.applies());
        assert!(a.slerp_f64(b, 0.5).is_none() && a.slerp_f64(-b, 0.5).is_none());
    }
}

/// The pair is not formed (no dot product, which would make NaN of
/// `inf * 0`) when either input's squared norm is beyond the bound,
/// infinite or NaN, whichever of the two it is.
#[test]
fn pairs_beyond_the_bound_are_not_formed() {
    let (a, _) = ordinary_pair();
    let beyond = [
        Quat::from_wxyz(f32::INFINITY, 0.0, 0.0, 0.0),
        Quat::from_wxyz(0.0, 7e4, 0.0, 0.0),
        Quat::NAN,
    ];
    for q in beyond {
        assert!(Pair::checked::<Two>(&a, &q).is_none(), "{q:?}");
        assert!(Pair::checked::<Two>(&q, &a).is_none(), "{q:?}");
    }
    assert!(Pair::checked::<Two>(&a, &a.map(|c| c * 6e4)).is_some());
}

/// `near` and `far` are `|a - cn(b)|^2` and `|a + cn(b)|^2`, against
/// the sums of the squared f64 differences and sums of the components
/// (exact but for the last bits), relatively: `far` within 2^-50,
/// `near` within 1e-12 for random unit pairs and, where its subtraction
/// cancels, for pairs a small angle apart (2^-12 to 2^-6 rad, where
/// slerp takes the evaluation), within 2^-25.
#[test]
fn near_and_far_are_the_squared_lengths_of_difference_and_sum() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(17);
    let mut worst = [0.0f64; 3];
    // Fewer under Miri, which interprets every instruction.
    let draws = if cfg!(miri) { 100 } else { 100_000 };
    for i in 0..draws {
        let a = unit(&mut rng);
        let small = i % 2 == 0;
        let b = if small {
            let angle = 2f32.powf(rng.random_range(-12.0..-6.0f32));
            let b = a * Quat::from_axis_angle(unit(&mut rng).xyz().normalize(), 2.0 * angle);
            if i % 4 == 0 {
                -b
            } else {
                b
            }
        } else {
            unit(&mut rng)
        };
        let pair = Pair::of_quats(&a, &b);
        let (p, q) = (a.to_array().map(f64::from), b.to_array().map(f64::from));
        let sign = pair.dot.signum();
        let length = |s: f64| -> f64 { p.iter().zip(&q).map(|(x, y)| (x + s * y).powi(2)).sum() };
        let (near, far) = (length(-sign), length(sign));
        let errors = [
            (pair.near() - near).abs() / near,
            (pair.far() - far).abs() / far,
        ];
        let k = usize::from(small);
        worst[k] = worst[k].max(errors[0]);
        worst[2] = worst[2].max(errors[1]);
    }
    assert!(worst[0] <= 1e-12, "{worst:?}");
    assert!(worst[1] <= 2f64.powi(-25), "{worst:?}");
    assert!(worst[2] <= 2f64.powi(-50), "{worst:?}");
}

/// The pair's arc is that between `a` and `cn(b)` (half the rotation
/// angle between them): its `phi^2` and `phi / sin(phi)` against f64
/// arithmetic on the same f32 inputs.
#[test]
fn arc_is_the_arc_between_the_pair() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(13);
    for _ in 0..10_000 {
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        let wide = |q: Quat| q.to_array().map(f64::from);
        let (p, q) = (wide(a), wide(b));
        let dot: f64 = p.iter().zip(&q).map(|(x, y)| x * y).sum();
        let along: f64 = q
            .iter()
            .zip(&p)
            .map(|(y, x)| (y - dot * x).powi(2))
            .sum::<f64>();
        let exact = along.sqrt().atan2(dot.abs());
        let arc = Arc::from_quotient(Pair::of_quats(&a, &b).quotient());
        let phi = arc.phi_squared.sqrt();
        assert!((phi - exact).abs() <= 1e-6 * exact + 1e-7, "{phi} {exact}");
        let ratio = exact / exact.sin();
        let error = (arc.phi_over_sine - ratio).abs();
        assert!(error <= 2e-7 * ratio, "{} {ratio}", arc.phi_over_sine);
    }
}

/// The largest relative error of `sinc(x^2)` over every `step`-th f32
/// `x` of [2^-30, pi/2] (`x^2` exact in f64), against `std`'s f64
/// `sin(x) / x`.
fn sinc_sweep(step: usize) -> (f64, f32) {
    let mut worst = (0.0, 0.0);
    for x in floats(9.3e-10, FRAC_PI_2, step) {
        let x64 = f64::from(x);
        let exact = x64.sin() / x64;
        let err = ((sinc(x64 * x64) - exact) / exact).abs();
        if err > worst.0 {
            worst = (err, x);
        }
    }
    worst
}

/// The arc of the lengths whose quotient is `t2` exactly (`t2` over
/// 1), and its exact `phi = 2 atan(sqrt(t2))` in
/// `std`'s f64.
fn right_angled(t2: f32) -> (f64, Arc<f64>) {
    let phi = 2.0 * f64::from(t2).sqrt().atan();
    (phi, Arc::from_quotient(f64::from(t2)))
}

/// The largest relative errors of the arc's `phi^2` and
/// `phi / sin(phi)` over every `step`-th f32 `t2` of [2^-30, 1], as
/// the tangent of the half angle squared (the lengths `t2` and 1, whose
/// quotient is `t2` exactly), against `phi = 2 atan(sqrt(t2))` in `std`'s f64.
fn arc_sweep(step: usize) -> [(f64, f32); 2] {
    let mut worst = [(0.0, 0.0); 2];
    for t2 in floats(9.3e-10, 1.0, step) {
        let (phi, arc) = right_angled(t2);
        let errors = [
            (arc.phi_squared - phi * phi) / (phi * phi),
            (arc.phi_over_sine - phi / phi.sin()) * phi.sin() / phi,
        ];
        for (w, e) in worst.iter_mut().zip(errors) {
            if e.abs() > w.0 {
                *w = (e.abs(), t2);
            }
        }
    }
    worst
}

#[test]
fn sinc_is_within_its_bound_on_a_sample() {
    let (err, x) = sinc_sweep(SAMPLE_STEP);
    assert!(err <= f64::from(SINC_F64_MAX_REL_ERROR), "{err:e} at {x}");
}

#[test]
fn arc_is_within_its_bounds_on_a_sample() {
    let [(square, t), (ratio, u)] = arc_sweep(SAMPLE_STEP);
    assert!(
        square <= f64::from(PHI_SQUARED_F64_MAX_REL_ERROR),
        "phi^2: {square:e} at {t}"
    );
    assert!(
        ratio <= f64::from(PHI_OVER_SINE_F64_MAX_REL_ERROR),
        "phi / sin(phi): {ratio:e} at {u}"
    );
}

/// The largest relative error of slerp's coefficients before their
/// rounding to f32, over every `step`-th f32 `t2` of [2^-25, 1] (the
/// arc as in [`arc_sweep`], `phi^2` above 2^-24) and shares from the
/// smallest f32 to 1, against `sin((1 - alpha) phi) / sin(phi)` and
/// `sin(alpha phi) / sin(phi)` in `std`'s f64.
fn coefficient_sweep(step: usize) -> (f64, f32, f32) {
    let alphas = [
        f32::from_bits(1),
        1e-30,
        1e-7,
        1e-3,
        0.1,
        0.25,
        1.0 / 3.0,
        0.5,
        0.7,
        0.9,
        0.999,
        1.0 - f32::EPSILON / 2.0,
        1.0,
    ];
    let mut worst = (0.0, 0.0, 0.0);
    for t2 in floats(2.9802322e-8, 1.0, step) {
        let (phi, arc) = right_angled(t2);
        for alpha in alphas {
            let share = f64::from(alpha);
            let [c0, c1] = [arc.coefficient(1.0 - share), arc.coefficient(share)];
            let share = f64::from(alpha);
            let exact = [(1.0 - share) * phi, share * phi].map(|x| x.sin() / phi.sin());
            for (c, e) in [c0, c1].into_iter().zip(exact) {
                let err = if e == 0.0 {
                    c.abs()
                } else {
                    ((c - e) / e).abs()
                };
                if err > worst.0 {
                    worst = (err, t2, alpha);
                }
            }
        }
    }
    worst
}

#[test]
fn coefficients_are_within_their_bound_on_a_sample() {
    let (err, t2, alpha) = coefficient_sweep(16 * SAMPLE_STEP);
    assert!(
        err <= f64::from(SLERP_COEFFICIENT_F64_MAX_REL_ERROR),
        "{err:e} at t2 = {t2}, alpha = {alpha}"
    );
}

/// The hypothesis of `proofs/gappa/arc_f64.g`: the arc's quotient
/// `t2 = |a - cn(b)|^2 / |a + cn(b)|^2` lies in [2^-170, 1] wherever slerp takes its result (`phi^2` above
/// 2^-24), on random unit pairs, pairs at right angles (where it is 1)
/// and pairs just past the small angles (where it is smallest).
#[test]
fn arc_quotient_stays_within_the_models_domain() {
    use crate::test_draws::unit_quat;
    use crate::Quat;
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(31);
    let (mut smallest, mut largest) = (f64::INFINITY, 0.0f64);
    for i in 0..200_000 {
        let a = unit_quat(&mut rng);
        let b = match i % 3 {
            // b less its part along a: a right angle.
            0 => {
                let b = unit_quat(&mut rng);
                let d = a.dot(b);
                Quat::from_array(core::array::from_fn(|k| {
                    b.to_array()[k] - d * a.to_array()[k]
                }))
                .normalize()
            }
            // Turned by twice the small angle's bound, or a little more.
            1 => {
                let turn = 2.0 * SMALL_ANGLE * rng.random_range(1.0..1.5f32);
                a * Quat::from_rotation_z(turn)
            }
            _ => unit_quat(&mut rng),
        };
        let p = Pair::of_quats(&a, &b);
        if !p.applies() || Arc::from_quotient(p.quotient()).phi_squared <= SMALL_ANGLE_SQUARED_F64 {
            continue;
        }
        let t2 = p.near() / p.far();
        (smallest, largest) = (smallest.min(t2), largest.max(t2));
    }
    assert!(largest > 0.999_99 && largest <= 1.0, "{largest}");
    assert!(
        smallest >= 2f64.powi(-170) && smallest < 2f64.powi(-25),
        "{smallest}"
    );
}

/// Every f32 of the ranges:
/// `cargo test --release --lib -- --ignored exhaustive_kernel_sweep_f64`.
#[test]
#[ignore = "minutes in release: run by hand after changing a polynomial"]
fn exhaustive_kernel_sweep_f64() {
    let (sinc_error, x) = sinc_sweep(1);
    let [(square, t), (ratio, u)] = arc_sweep(1);
    // Every 64th f32 `t2`: with 13 values of `alpha`, every f32
    // would take hours.
    let (coefficient, v, alpha) = coefficient_sweep(64);
    std::println!("coefficients: {coefficient:e} at t2 = {v}, alpha = {alpha}");
    std::println!(
        "sinc: {sinc_error:e} at {x}; phi^2: {square:e} at t2 = {t}; phi / sin(phi): {ratio:e} at t2 = {u}"
    );
    assert!(sinc_error <= f64::from(SINC_F64_MAX_REL_ERROR));
    assert!(square <= f64::from(PHI_SQUARED_F64_MAX_REL_ERROR));
    assert!(ratio <= f64::from(PHI_OVER_SINE_F64_MAX_REL_ERROR));
    assert!(coefficient <= f64::from(SLERP_COEFFICIENT_F64_MAX_REL_ERROR));
}

/// The single call in SSE2's registers gives the bits of two plain `f64`
/// lanes: on random unit pairs, pairs off unit norm (scaled by 1e-3 to
/// 1e3), and the rare pairs, both signs of the dot product among them.
#[cfg(x86_sse_lanes)]
#[test]
fn registers_give_the_bits_of_two_plain_lanes() {
    use super::super::lanes::F64x2;
    let mut rng = rand::rngs::StdRng::seed_from_u64(41);
    let mut pairs: std::vec::Vec<(Quat, Quat)> = rare_pairs().to_vec();
    // Fewer under Miri, which interprets every instruction.
    let draws = if cfg!(miri) { 100 } else { 100_000 };
    for i in 0..draws {
        let (a, b) = (unit(&mut rng), unit(&mut rng));
        let scale = if i % 4 == 0 {
            rng.random_range(1e-3..1e3f32)
        } else {
            1.0
        };
        pairs.push((a.map(|c| c * scale), b.map(|c| c * scale)));
    }
    let bits = |q: Option<Quat>| q.map(|q| q.to_array().map(f32::to_bits));
    let mut taken = 0;
    for (a, b) in pairs {
        let alpha = rng.random_range(0.0..=1.0f32).max(f32::MIN_POSITIVE);
        let wide = slerp_in::<F64x2>(a, b, alpha);
        assert_eq!(
            bits(slerp_in::<Two>(a, b, alpha)),
            bits(wide),
            "{a:?} {b:?} {alpha}"
        );
        taken += usize::from(wide.is_some());
    }
    assert!(taken > draws / 2, "{taken}");
}
