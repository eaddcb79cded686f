//! The numerics contract (the README's "The contract"), item by item, on the edge values of
//! `testkit::EDGE_F32` (zeros, subnormals, +-1, 1 +- ulp, 1e30, f32::MAX,
//! infinities, NaN) and on random bit patterns.

use rigtform_testkit as testkit;

use core::f32::consts::PI;
use rand::{Rng, SeedableRng};
use rigtform::accuracy::{
    MUL_MAX_ANGLE_ERROR, NORMALIZE_MAX_NORM_ERROR, RENORMALIZED_CHAIN_NORM_ERROR,
    SLERP_MAX_ANGLE_ERROR, UNIT_NORM_ERROR,
};
use rigtform::{Cvec3, Cvec4, EulerRot, Matrix4, Quat, RigTForm};
use testkit::{edge_quats, finite_edges};

/// The documented error of a power that turns by `turn` radians, plus the
/// product inside `angle_to` that measures it.
fn pow_bound(turn: f32) -> f32 {
    testkit::pow_tol(1.0, turn) + MUL_MAX_ANGLE_ERROR
}

fn is_nan_quat(q: Quat) -> bool {
    q.w.is_nan() && q.x.is_nan() && q.y.is_nan() && q.z.is_nan()
}

fn is_unit(q: Quat, bound: f32) -> bool {
    q.is_finite() && ((q.norm() - 1.0).abs() <= bound)
}

// Contract item 1: no function panics, for any input bits. A panic fails the
// test; each call's result is also checked against its documented result.

/// `q` with every component times `k` (the crate has no `Quat * f32`).
fn scaled(q: Quat, k: f32) -> Quat {
    Quat::from_wxyz(q.w * k, q.x * k, q.y * k, q.z * k)
}

#[test]
fn no_quat_function_panics_on_any_edge_combination() {
    let alphas = [0.0, 1.0, 0.5, -1.5, f32::MAX, f32::NAN, f32::INFINITY];
    let other = Quat::from_rotation_y(0.7);
    let mut calls = 0u64;
    for q in edge_quats() {
        let finite = q.is_finite();
        for alpha in alphas {
            let p = q.pow(alpha);
            if !(finite && alpha.is_finite()) {
                assert!(is_nan_quat(p), "{q:?}^{alpha} = {p:?}");
            }
            let s = q.slerp(other, alpha);
            let n = q.nlerp(other, alpha);
            if !finite || !alpha.is_finite() {
                assert!(
                    !s.is_finite() && !n.is_finite(),
                    "{q:?} {alpha}: {s:?} {n:?}"
                );
            }
            // Strictly between keys, the spline reads all of them: NaN
            // out for a NaN or infinite key, and for a NaN t anywhere.
            let t = 0.5 * alpha;
            let c = Quat::catmull_rom(&[other, q, other], t);
            let between = 0.0 < t && t < 2.0;
            if (!finite && between) || t.is_nan() {
                assert!(is_nan_quat(c), "{q:?} {alpha}: {c:?}");
            }
            calls += 4;
        }
        let (axis, angle) = q.to_axis_angle();
        assert_eq!(finite, axis.is_finite() && angle.is_finite(), "{q:?}");
        if finite {
            assert!((0.0..=PI).contains(&angle), "{q:?}: {angle}");
        }
        let _ = (
            q * other,
            other * q,
            q.inv(),
            q.cn(),
            q.dot(other),
            q.norm(),
        );
        let _ = (
            q * Cvec3::X,
            q * Cvec4::new(1.0, 2.0, 3.0, 1.0),
            q.normalize(),
        );
        let _ = (q.angle_to(other), Quat::blend(&[(q, 1.0), (other, 0.5)]));
        let _ = Matrix4::from_quat(q).inverse();
        let (a, b, c) = q.to_euler(EulerRot::ZYX);
        assert_eq!(
            finite,
            a.is_finite() && b.is_finite() && c.is_finite(),
            "{q:?}"
        );
        let m = Quat::from_matrix(Matrix4::from_quat(q));
        assert!(m.is_finite() || m.is_nan(), "{q:?}: {m:?}");
        let arc = Quat::from_rotation_arc(q.vector(), other.vector());
        assert_eq!(q.vector().is_finite(), arc.is_finite(), "{q:?}: {arc:?}");
        let _ = (q.is_nan(), q.is_normalized(), q.to_string());
        calls += 17;
    }
    println!("{calls} calls on edge quaternions, no panic");
}

#[test]
fn no_function_panics_on_random_bit_patterns() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    let mut any = || f32::from_bits(rng.random());
    for _ in 0..100_000 {
        let q = Quat::from_wxyz(any(), any(), any(), any());
        let r = Quat::from_wxyz(any(), any(), any(), any());
        let v = Cvec3::new(any(), any(), any());
        let alpha = any();
        let a = RigTForm::new(v, q);
        let b = RigTForm::new(Cvec3::new(any(), any(), any()), r);
        let _ = (
            q.pow(alpha),
            q.slerp(r, alpha),
            q.nlerp(r, alpha),
            q.to_axis_angle(),
        );
        let _ = (
            q.angle_to(r),
            Quat::blend(&[(q, any()), (r, any())]),
            q.normalize(),
        );
        let _ = (Quat::from_axis_angle(v, alpha), v.normalize(), v.norm());
        let _ = (
            a * b,
            a.inv(),
            a.interpolate(b, alpha),
            a * Cvec4::from_point(v),
        );
        let _ = (
            Quat::from_euler(EulerRot::YXZ, alpha, any(), any()),
            q.to_euler(EulerRot::XZY),
            Quat::from_rotation_arc(v, b.t),
            RigTForm::look_at(v, b.t, a.t),
            a.transform_point(v),
            a.transform_vector(v),
            Quat::catmull_rom(&[q, r, q * r], alpha),
            RigTForm::catmull_rom(&[a, b, a * b, b], alpha),
        );
        let m = Matrix4::from_cols_array(&core::array::from_fn(|_| any()));
        let _ = (
            Quat::from_matrix(m),
            m.determinant(),
            Matrix4::orthographic(any(), any(), any(), any(), any(), any()),
        );
        let inv = m.inverse();
        assert!(inv.is_none_or(|i| i.is_finite()), "{m:?}");
        let n = m.normal_matrix();
        assert!(n.is_none_or(|i| i.is_finite()), "{m:?}");
        let _ = (
            Matrix4::from(a) * m,
            m.transpose(),
            Matrix4::perspective(any(), any(), any(), any()),
        );
    }
}

// Contract item 2: pow.

#[test]
fn pow_is_finite_and_unit_for_every_finite_nonzero_edge_input() {
    let mut checked = 0u64;
    for q in edge_quats().filter(|q| q.is_finite()) {
        if q == Quat::from_wxyz(0.0, 0.0, 0.0, 0.0) {
            continue;
        }
        for alpha in finite_edges() {
            let p = q.pow(alpha);
            assert!(
                is_unit(p, UNIT_NORM_ERROR),
                "{q:?}^{alpha} = {p:?}, norm {}",
                p.norm()
            );
            checked += 1;
        }
    }
    println!("pow: {checked} finite non-zero edge inputs, all unit");
}

#[test]
fn pow_of_zero_and_of_pure_reals() {
    for zero in [
        Quat::from_wxyz(0.0, 0.0, 0.0, 0.0),
        Quat::from_wxyz(-0.0, -0.0, 0.0, -0.0),
    ] {
        assert_eq!(zero.pow(0.3), Quat::IDENTITY);
    }
    for w in [1e-45, 1.0, 2.0, f32::MAX] {
        assert_eq!(Quat::from_wxyz(w, 0.0, 0.0, 0.0).pow(0.7), Quat::IDENTITY);
    }
    // w < 0 is a 2 pi turn; documented to go about the x axis.
    for w in [-1e-45, -1.0, -f32::MAX] {
        let p = Quat::from_wxyz(w, 0.0, -0.0, 0.0).pow(0.25);
        let want = Quat::from_rotation_x(PI / 2.0);
        assert!(
            p.angle_to(want) <= pow_bound(PI / 2.0) && p.dot(want) > 0.0,
            "{w}: {p:?}"
        );
    }
}

#[test]
fn pow_of_w_minus_one_exactly_and_of_tiny_and_huge_vector_parts() {
    let cases = [
        (Quat::from_wxyz(-1.0, 0.0, 0.0, 0.0), "w = -1 exactly"),
        (
            Quat::from_wxyz(-1.0, 1e-45, 0.0, 0.0),
            "w = -1, subnormal vector part",
        ),
        (
            Quat::from_wxyz(1.0, 1e-45, 1e-45, 0.0),
            "subnormal vector part",
        ),
        (
            Quat::from_wxyz(1.0, 0.0, 1e-40, -1e-40),
            "subnormal vector part",
        ),
        (
            Quat::from_wxyz(0.5, 1e-20, 0.0, 0.0),
            "vector part squared underflows",
        ),
        (Quat::from_wxyz(1e30, 1e30, 1e30, 1e30), "1e30 components"),
        (
            Quat::from_wxyz(f32::MAX, f32::MAX, f32::MAX, f32::MAX),
            "f32::MAX components",
        ),
        (
            Quat::from_wxyz(0.0, f32::MAX, -f32::MAX, 0.0),
            "pure vector, huge",
        ),
        (Quat::from_wxyz(1e-45, 0.0, 0.0, 1e-45), "all subnormal"),
    ];
    for (q, what) in cases {
        for alpha in [0.0, 0.5, 1.0, 2.0, -3.0] {
            let p = q.pow(alpha);
            assert!(is_unit(p, UNIT_NORM_ERROR), "{what}: {q:?}^{alpha} = {p:?}");
        }
        // The first power is the direction of q itself (not its antipode).
        let (p, n) = (q.pow(1.0), q.normalize());
        let turn = 2.0 * PI; // at most
        assert!(
            p.angle_to(n) <= pow_bound(turn) && p.dot(n) > 0.0,
            "{what}: {p:?} vs {n:?}"
        );
    }
    // Subnormal vector parts keep their direction exactly.
    let (three, four) = (f32::from_bits(3), f32::from_bits(4)); // 3 and 4 times 2^-149
    let p = Quat::from_wxyz(1.0, 0.0, three, four).pow(1e30);
    let axis = p.vector().normalize();
    assert!((axis - Cvec3::new(0.0, 0.6, 0.8)).norm() < 1e-6, "{axis:?}");
}

#[test]
fn pow_of_non_unit_quaternions_is_the_power_of_their_direction() {
    // Scaled copies of one rotation, down to subnormal components (which
    // round the direction: the reference is the f64 power of what was stored).
    let q = Quat::from_axis_angle(Cvec3::new(1.0, 2.0, 3.0), 1.1);
    for scale in [1e-40f32, 1e-20, 0.5, 3.0, 1e20, 1e38] {
        let s = scaled(q, scale);
        let p = s.pow(0.4);
        assert!(is_unit(p, UNIT_NORM_ERROR), "{scale}: {p:?}");
        let want = testkit::pow64(testkit::to_f64(s).normalize(), 0.4);
        assert!(
            testkit::angle_error(p, want) <= pow_bound(0.4 * 1.1) as f64,
            "{scale}: {p:?}"
        );
    }
}

#[test]
fn pow_with_any_finite_alpha_is_unit() {
    let q = Quat::from_rotation_z(2.5);
    for alpha in [f32::MAX, -f32::MAX, 1e38, 1e30, 1e10, -7.25e7, 1e-45] {
        assert!(is_unit(q.pow(alpha), UNIT_NORM_ERROR), "{alpha}");
    }
}

#[test]
fn nan_or_infinity_in_gives_nan_out() {
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let q = Quat::from_wxyz(bad, 0.0, 0.0, 0.0);
        let r = Quat::from_wxyz(1.0, 0.0, bad, 0.0);
        let good = Quat::from_rotation_x(0.3);
        assert!(is_nan_quat(q.pow(0.5)) && is_nan_quat(r.pow(0.5)));
        assert!(is_nan_quat(good.pow(bad)));
        assert!(!good.slerp(r, 0.5).is_finite() && !r.slerp(good, 0.5).is_finite());
        assert!(!good.slerp(good, bad).is_finite());
        assert!(is_nan_quat(q.normalize()) && q.try_normalize().is_none());
        assert!(is_nan_quat(good.nlerp(r, 0.5)));
        assert!(is_nan_quat(Quat::blend(&[(good, 1.0), (r, 1.0)])));
        assert!(q.to_axis_angle().1.is_nan() && good.angle_to(r).is_nan());
        assert!(is_nan_quat(Quat::from_axis_angle(
            Cvec3::new(bad, 0.0, 0.0),
            1.0
        )));
        assert!(is_nan_quat(Quat::from_axis_angle(Cvec3::X, bad)));
        assert!(Cvec3::new(0.0, bad, 0.0).normalize().x.is_nan());
        let a = RigTForm::new(Cvec3::new(bad, 0.0, 0.0), good);
        assert!(!a.interpolate(RigTForm::IDENTITY, 0.5).t.is_finite());
        assert_eq!(Matrix4::from(a).inverse(), None);
    }
}

#[test]
fn documented_results_for_degenerate_input() {
    assert_eq!(Quat::from_axis_angle(Cvec3::ZERO, 1.0), Quat::IDENTITY);
    assert_eq!(
        Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).to_axis_angle(),
        (Cvec3::X, 0.0)
    );
    assert_eq!(Quat::blend(&[]), Quat::IDENTITY);
    assert!(is_nan_quat(Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).normalize()));
    assert_eq!(
        Matrix4::from_scale(Cvec3::new(1.0, 1.0, 0.0)).inverse(),
        None
    );
    assert_eq!(
        Matrix4::from_scale(Cvec3::new(0.0, 1.0, 1.0)).normal_matrix(),
        None
    );
    // Degenerate projections give non-finite entries, never a panic.
    assert!(!Matrix4::perspective(1.0, 1.0, 2.0, 2.0).is_finite());
    assert!(!Matrix4::perspective(1.0, 0.0, 1.0, 2.0).is_finite());
}

// Contract item 3: slerp.

#[test]
fn slerp_of_identical_nearly_identical_antipodal_and_opposite_rotations() {
    let bases = [
        Quat::IDENTITY,
        Quat::from_axis_angle(Cvec3::new(1.0, -2.0, 0.5), 2.9),
        Quat::from_wxyz(0.0, 0.0, 0.0, 1.0),
        Quat::from_wxyz(-0.5, 0.5, -0.5, 0.5),
    ];
    for a in bases {
        let cases = [
            (a, "identical"),
            (
                Quat::from_axis_angle(Cvec3::new(0.3, 0.4, 0.5), 1e-6) * a,
                "1e-6 rad apart",
            ),
            (-a, "antipodal"),
            (Quat::from_wxyz(0.0, 0.6, 0.0, 0.8) * a, "pi apart"),
            (
                -(Quat::from_wxyz(0.0, 0.0, 1.0, 0.0) * a),
                "pi apart, negated",
            ),
        ];
        for (b, what) in cases {
            let theta = a.angle_to(b);
            for alpha in [0.0f32, 0.25, 0.5, 0.75, 1.0, -0.5, 1.5] {
                let s = a.slerp(b, alpha);
                assert!(
                    is_unit(s, UNIT_NORM_ERROR),
                    "{what}: {a:?} {b:?} {alpha}: {s:?}"
                );
                if (0.0..=1.0).contains(&alpha) {
                    // The short way: never further from a than alpha theta <= alpha pi.
                    let travelled = a.angle_to(s);
                    assert!(
                        (travelled - alpha * theta).abs()
                            <= PI * SLERP_MAX_ANGLE_ERROR + 2.0 * MUL_MAX_ANGLE_ERROR,
                        "{what}: {alpha}: travelled {travelled}, want {}",
                        alpha * theta
                    );
                }
            }
            assert_eq!(a.slerp(b, 0.0), a, "{what}: exact at alpha = 0");
        }
    }
}

#[test]
fn slerp_extrapolated_far_from_nearly_identical_inputs_is_unit() {
    // The direction of travel of inputs 1e-6 rad apart is known only
    // roughly; far out it must still give a unit result.
    let mut draws = testkit::Draws::new(32);
    for _ in 0..10_000 {
        let a = draws.unit_quat();
        let axis = draws.unit_vec64();
        let axis = Cvec3::new(axis.x as f32, axis.y as f32, axis.z as f32);
        for apart in [1e-6f32, 1e-4, 1e-2] {
            let b = Quat::from_axis_angle(axis, apart) * a;
            for alpha in [-3.0f32, 7.0, 1e6, -1e30, f32::MAX] {
                let s = a.slerp(b, alpha);
                assert!(is_unit(s, UNIT_NORM_ERROR), "{a:?} {b:?} {alpha}: {s:?}");
            }
        }
    }
}

#[test]
fn slerp_of_inputs_closer_than_f32_squares_can_tell_is_the_tiny_turn() {
    // 1e-20 apart: the part of b orthogonal to a has squares below 2^-100,
    // which slerp scales up by an exact power of two before taking the angle.
    let a = Quat::IDENTITY;
    let b = Quat::from_wxyz(1.0, 1e-20, 0.0, 0.0);
    for alpha in [0.25f32, 0.5, 1.0, 2.0] {
        let s = a.slerp(b, alpha);
        assert!(is_unit(s, UNIT_NORM_ERROR), "{alpha}: {s:?}");
        assert!(s.angle_to(a) <= SLERP_MAX_ANGLE_ERROR, "{alpha}: {s:?}");
        // The turn itself, to a few ulps.
        assert!((s.x - alpha * 1e-20).abs() <= 1e-26, "{alpha}: {s:?}");
    }
}

#[test]
fn slerp_of_large_non_unit_inputs_is_finite_and_scale_free() {
    // Far off the unit precondition, but finite: slerp is scale-free like
    // pow (a result with the norm of a), not NaN.
    let mut draws = testkit::Draws::new(33);
    for _ in 0..1_000 {
        let (a, b) = (draws.unit_quat(), draws.unit_quat());
        let alpha = draws.uniform(0.0, 1.0) as f32;
        let s = scaled(a, 1e12).slerp(scaled(b, 1e12), alpha);
        assert!(s.is_finite(), "{a:?} {b:?} {alpha}: {s:?}");
        let want = a.slerp(b, alpha);
        assert!(
            s.normalize().angle_to(want) <= 4.0 * SLERP_MAX_ANGLE_ERROR,
            "{a:?} {b:?}"
        );
    }
}

#[test]
fn slerp_extrapolated_from_non_unit_inputs_is_scale_free() {
    // Extrapolation takes its own path (the direction of the turn made
    // orthogonal to a by a projection divided by |a|^2); it too turns by
    // alpha times the angle whatever the norms, down to tiny ones, where
    // the projection's coefficient exceeds |a|^2.
    let mut draws = testkit::Draws::new(34);
    for _ in 0..1_000 {
        let (a, b) = (draws.unit_quat(), draws.unit_quat());
        for (sa, sb) in [(1e-10f32, 3e-10f32), (2.0, 0.5), (1e10, 1e11)] {
            for alpha in [-0.5f32, 1.5, 3.0] {
                let s = scaled(a, sa).slerp(scaled(b, sb), alpha);
                let want = a.slerp(b, alpha);
                assert!(
                    s.normalize().angle_to(want) <= 8.0 * SLERP_MAX_ANGLE_ERROR,
                    "{a:?} {b:?} {sa} {alpha}: {s:?} against {want:?}"
                );
            }
        }
    }
}

#[test]
fn slerp_of_antipodal_inputs_stays_put() {
    let a = Quat::from_axis_angle(Cvec3::new(2.0, 1.0, -1.0), 0.8);
    for alpha in [0.3f32, 1.0, 2.0] {
        assert!(a.slerp(-a, alpha).angle_to(a) <= SLERP_MAX_ANGLE_ERROR + MUL_MAX_ANGLE_ERROR);
    }
}

// Contract item 4: unit-norm preservation, and normalize for drift.

#[test]
fn long_chains_drift_slowly_and_normalize_restores_unit_norm() {
    let step = Quat::from_axis_angle(Cvec3::new(0.2, -0.7, 0.4), 0.013);
    let mut q = Quat::IDENTITY;
    let mut worst = 0.0f32;
    for _ in 0..100_000 {
        q *= step;
        worst = worst.max((q.norm() - 1.0).abs());
    }
    println!("norm drift after 100000 chained products: {worst:.3e}");
    // Rounding errors of each product are at most UNIT_NORM_ERROR and grow no faster than linearly.
    assert!(worst <= 100_000.0 * UNIT_NORM_ERROR);
    assert!((q.normalize().norm() - 1.0).abs() <= NORMALIZE_MAX_NORM_ERROR);
}

#[test]
fn normalize_works_from_subnormal_to_max() {
    for q in edge_quats().filter(|q| q.is_finite()) {
        match q.try_normalize() {
            Some(n) => assert!(is_unit(n, NORMALIZE_MAX_NORM_ERROR), "{q:?} -> {n:?}"),
            None => assert_eq!(q, Quat::from_wxyz(0.0, 0.0, 0.0, 0.0)),
        }
    }
}

#[test]
fn renormalized_product_chain_stays_unit() {
    // A gyro integrator's chain: a million products of small random
    // rotations (up to 0.1 rad each, from a fixed pool of 1,000).
    let mut draws = testkit::Draws::new(30);
    let steps: Vec<Quat> = (0..1000)
        .map(|_| {
            let axis = draws.unit_vec64();
            let axis = Cvec3::new(axis.x as f32, axis.y as f32, axis.z as f32);
            // Normalized: unit to an ulp.
            Quat::from_axis_angle(axis, draws.uniform(0.0, 0.1) as f32).normalize()
        })
        .collect();
    let (mut plain, mut renormalized) = (Quat::IDENTITY, Quat::IDENTITY);
    let (mut plain_drift, mut worst) = (0.0f32, 0.0f32);
    for i in 0..1_000_000 {
        let step = steps[i % steps.len()];
        plain *= step;
        renormalized = renormalized.mul_renormalized(step);
        plain_drift = plain_drift.max((plain.norm() - 1.0).abs());
        worst = worst.max((renormalized.norm() - 1.0).abs());
    }
    println!("1000000 products: plain drift {plain_drift:.3e}, renormalized {worst:.3e}");
    assert!(worst <= RENORMALIZED_CHAIN_NORM_ERROR, "{worst}");
}

#[test]
fn renormalized_product_is_the_same_rotation_as_the_plain_one() {
    let mut draws = testkit::Draws::new(31);
    for _ in 0..10_000 {
        let (a, b) = (draws.unit_quat(), draws.unit_quat());
        let (plain, renormalized) = (a * b, a.mul_renormalized(b));
        assert!(
            renormalized.angle_to(plain) <= MUL_MAX_ANGLE_ERROR,
            "{a:?} {b:?}"
        );
        assert!(is_unit(renormalized, UNIT_NORM_ERROR), "{a:?} {b:?}");
    }
    // A drifted input comes back to unit in one step: a norm of 1 + e
    // becomes 1 - 3 e^2 / 2 (1.5e-8 here), plus rounding.
    let drifted = Quat::from_wxyz(0.0, 0.0, 1.0 + 1e-4, 0.0);
    let n = drifted.mul_renormalized(Quat::IDENTITY).norm();
    assert!((n - 1.0).abs() <= UNIT_NORM_ERROR, "{n}");
    assert!(is_nan_quat(Quat::NAN.mul_renormalized(Quat::IDENTITY)));
}

/// Unit inputs one rotation to within an ulp but on opposite hemispheres
/// (cn flips one), and an extrapolating alpha (inputs from the `slerp` fuzz
/// target's seeds): the direction to turn in is subnormal, and must not
/// lose its precision in the normalization (infinities would come out).
#[test]
fn slerp_extrapolated_from_nearly_antipodal_inputs_is_unit() {
    let (h, t) = (8.8e-44, -4.408_238_2e-18);
    let a = Quat::from_wxyz(0.0, h, h, h).normalize();
    let b = Quat::from_wxyz(h, t, t, t).normalize();
    for alpha in [t, -1e-3, 1.5, -4.4e-18, 1e30, 0.5] {
        rigtform_proofs::laws::slerp_is_unit(a, b, alpha)
            .unwrap_or_else(|v| panic!("alpha {alpha:e}: {v:?}"));
        let s = a.slerp(b, alpha);
        assert!(is_unit(s, UNIT_NORM_ERROR), "alpha {alpha:e}: {s:?}");
        // Up to alpha = 1.5 it turns by at most 1.5 times the (sub-ulp)
        // angle between the inputs; beyond, the turn is as large as alpha
        // makes it.
        if alpha.abs() <= 1.5 {
            let bound = 1.5 * a.angle_to(b) + SLERP_MAX_ANGLE_ERROR;
            assert!(s.angle_to(a) <= bound, "alpha {alpha:e}: {s:?}");
        }
    }
}

/// Nearly antipodal inputs of very different scales, extrapolated far
/// (inputs from the `slerp` fuzz target's seeds): one Gram-Schmidt pass
/// leaves the direction of the turn off orthogonal by ulps of the rounding
/// it removes, which must not show in the norm (by 2e-6, unchecked).
#[test]
fn slerp_extrapolated_far_from_nearly_antipodal_inputs_of_any_scale_is_unit() {
    let b =
        Quat::from_wxyz(2.195_525_5e-18, -26_711_958.0, -26_711_958.0, -26_711_958.0).normalize();
    // The second first input is the same rotation as -b to within 1e-22
    // rad: most of the difference is rounding along a, which alpha must
    // not blow up into a turn (2.7e7 times that rounding).
    for w in [1.599_975_6, 9.094_808e-14] {
        let a = Quat::from_wxyz(w, 865_309_600.0, 865_309_600.0, 865_309_600.0).normalize();
        for alpha in [-26_711_958.0, 26_711_958.0, -3e5, 1e9, -1.511_584e21] {
            rigtform_proofs::laws::slerp_is_unit(a, b, alpha)
                .unwrap_or_else(|v| panic!("w {w:e}, alpha {alpha:e}: {v:?}"));
            let s = a.slerp(b, alpha);
            assert!(
                is_unit(s, UNIT_NORM_ERROR),
                "w {w:e}, alpha {alpha:e}: {s:?}"
            );
        }
    }
    let a = Quat::from_wxyz(9.094_808e-14, 865_309_600.0, 865_309_600.0, 865_309_600.0).normalize();
    let s = a.slerp(b, -26_711_958.0);
    assert!(s.angle_to(a) < 1e-14, "{s:?}");
}

#[test]
fn slerp_extrapolated_from_inputs_ulps_apart_turns_by_no_more_than_their_resolution() {
    // Inputs 3e-8 to 1e-5 rad apart differ by a few ulps to a few hundred:
    // the direction between them is partly rounding along a. Slerp turns by
    // the angle of the part orthogonal to a, so that extrapolating by alpha
    // is off by at most alpha times about two ulps (2^-22 rad), the
    // resolution of their difference; taking the angle of all of it was
    // off by up to 8e-7 alpha (27 times the turn at 3e-8 rad apart).
    use rigtform_proofs::reference::Quat64;
    let mut draws = testkit::Draws::new(35);
    for _ in 0..20_000 {
        let a = draws.unit_quat();
        let axis = draws.unit_vec64();
        let axis = Cvec3::new(axis.x as f32, axis.y as f32, axis.z as f32);
        for apart in [3e-8f32, 1e-7, 1e-6, 1e-5] {
            let b = Quat::from_axis_angle(axis, apart) * a;
            let (a64, b64) = (Quat64::from(a), Quat64::from(b));
            for alpha in [-1e3f32, 1e3, 1e5] {
                let want = Quat64::slerp(a64, b64, alpha.into());
                let got = Quat64::from(a.slerp(b, alpha));
                let err = Quat64::angle_between(got, want);
                let bound = f64::from(alpha.abs()) * 2f64.powi(-22);
                assert!(
                    err <= bound,
                    "{a:?} {b:?} {alpha}: off by {err:e}, bound {bound:e}"
                );
            }
        }
    }
}
