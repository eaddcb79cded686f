//! The identities and invariances of the notes, as proptest properties over
//! random unit quaternions, vectors and rigid body transforms. Tolerances are
//! the constants of `rigtform::accuracy`, times the number of rounded
//! operations each side of an identity goes through.

use rigtform_testkit as testkit;

use core::f32::consts::PI;
use proptest::prelude::*;
use rigtform::accuracy::{
    MATRIX_ENTRY_ERROR, MUL_MAX_ANGLE_ERROR, NORMALIZE_MAX_NORM_ERROR, POW_MAX_ANGLE_ERROR,
    ROTATE_MAX_REL_ERROR, UNIT_NORM_ERROR,
};
use rigtform::{accuracy, Cvec3, Cvec4, EulerRot, Matrix4, Quat, RigTForm};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::laws::registry::LAWS;
use rigtform_proofs::laws::{self, assert_holds};
use testkit::strategies::{
    finite_quat, mixed_f32, mixed_within, normalized_quat, quat_within, vec_within,
};
use testkit::{key_walk, max_entry_diff, pow_tol, rig_tform, slerp_tol, unit_quat, vec3};

/// The angle of a unit quaternion as the notes' power operator sees it, 2 atan2(|v|, w).
fn quat_angle(q: Quat) -> f32 {
    2.0 * q.vector().norm().atan2(q.w)
}

/// Distance between two translations, relative to their scale.
fn close(a: Cvec3, b: Cvec3, rel: f32) -> bool {
    (a - b).norm() <= rel * (1.0 + a.norm().max(b.norm()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn product_matches_the_matrix_product(a in unit_quat(), b in unit_quat()) {
        let lhs = Matrix4::from_quat(a * b).to_cols_array();
        let rhs = (Matrix4::from_quat(a) * Matrix4::from_quat(b)).to_cols_array();
        // One rounded product and three rounded matrices stand between the sides.
        prop_assert!(max_entry_diff(lhs, rhs) <= 3.0 * MATRIX_ENTRY_ERROR + MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn rotation_matches_the_notes_triple_product(q in unit_quat(), c in vec3()) {
        let pure = Quat::from_wxyz(0.0, c.x, c.y, c.z);
        let triple = q * pure * q.inv();
        prop_assert!(close(q * c, triple.vector(), 2.0 * ROTATE_MAX_REL_ERROR));
        prop_assert!(triple.w.abs() <= 2.0 * ROTATE_MAX_REL_ERROR * c.norm());
    }

    #[test]
    fn rotation_of_a_cvec4_rotates_xyz_and_copies_w(q in unit_quat(), c in vec3(), w in -2.0f32..2.0) {
        let r = q * Cvec4::new(c.x, c.y, c.z, w);
        prop_assert_eq!(r.xyz(), q * c);
        prop_assert_eq!(r.w, w);
    }

    #[test]
    fn rotation_preserves_length_and_the_matrix_agrees(q in unit_quat(), c in vec3()) {
        let r = q * c;
        prop_assert!((r.norm() - c.norm()).abs() <= ROTATE_MAX_REL_ERROR * c.norm());
        let m = Matrix4::from_quat(q) * Cvec4::from_vector(c);
        prop_assert!(close(m.xyz(), r, ROTATE_MAX_REL_ERROR + 4.0 * MATRIX_ENTRY_ERROR));
    }

    #[test]
    fn quat_times_its_inverse_is_identity(q in unit_quat()) {
        prop_assert!((q * q.inv()).angle_to(Quat::IDENTITY) <= MUL_MAX_ANGLE_ERROR);
        prop_assert!((q.inv() * q).angle_to(Quat::IDENTITY) <= MUL_MAX_ANGLE_ERROR);
        prop_assert_eq!(q.inv().inv(), q);
    }

    #[test]
    fn rigtform_times_its_inverse_is_identity(a in rig_tform()) {
        let i = a * a.inv();
        prop_assert!(i.t.norm() <= 2.0 * ROTATE_MAX_REL_ERROR * a.t.norm());
        prop_assert!(i.r.angle_to(Quat::IDENTITY) <= MUL_MAX_ANGLE_ERROR);
        let j = a.inv() * a;
        prop_assert!(j.t.norm() <= 2.0 * ROTATE_MAX_REL_ERROR * a.t.norm());
        let back = a.inv().inv();
        prop_assert_eq!(back.r, a.r);
        prop_assert!(close(back.t, a.t, 2.0 * ROTATE_MAX_REL_ERROR));
    }

    #[test]
    fn rigtform_inverse_agrees_with_the_matrix_inverse(a in rig_tform()) {
        let inv = Matrix4::from(a).inverse().expect("rigid motions are invertible");
        let scale = 1.0 + a.t.norm();
        prop_assert!(max_entry_diff(inv.to_cols_array(), Matrix4::from(a.inv()).to_cols_array())
            <= 8.0 * MATRIX_ENTRY_ERROR * scale);
    }

    #[test]
    fn products_of_unit_quaternions_stay_unit(a in unit_quat(), b in unit_quat(), alpha in -2.0f32..3.0, axis in vec3()) {
        prop_assume!(axis.norm() > 0.0);
        prop_assert!((Quat::from_axis_angle(axis, 7.0 * alpha).norm() - 1.0).abs() <= UNIT_NORM_ERROR);
        prop_assert!(((a * b).norm() - 1.0).abs() <= UNIT_NORM_ERROR);
        prop_assert!((a.pow(alpha).norm() - 1.0).abs() <= UNIT_NORM_ERROR);
        prop_assert!((a.slerp(b, alpha).norm() - 1.0).abs() <= UNIT_NORM_ERROR);
        prop_assert!((a.nlerp(b, alpha).norm() - 1.0).abs() <= NORMALIZE_MAX_NORM_ERROR);
    }

    #[test]
    fn pow_zero_is_exactly_identity(q in unit_quat()) {
        prop_assert_eq!(q.pow(0.0), Quat::IDENTITY);
    }

    #[test]
    fn pow_one_is_the_quaternion_itself(q in unit_quat()) {
        let p = q.pow(1.0);
        prop_assert!(p.angle_to(q) <= pow_tol(1.0, quat_angle(q)) + MUL_MAX_ANGLE_ERROR);
        // Not its antipode: pow does no conditional negation.
        prop_assert!(p.dot(q) > 0.0);
    }

    #[test]
    fn pow_adds_exponents(q in unit_quat(), a in -2.0f32..2.0, b in -2.0f32..2.0) {
        let lhs = q.pow(a) * q.pow(b);
        let rhs = q.pow(a + b);
        let theta = quat_angle(q);
        let tol = pow_tol(a, theta) + pow_tol(b, theta) + pow_tol(a + b, theta);
        prop_assert!(lhs.angle_to(rhs) <= tol + 2.0 * MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn pow_scales_the_angle_about_the_same_axis(axis in vec3(), angle in 0.01f32..3.1, alpha in 0.0f32..1.0) {
        prop_assume!(axis.norm() > 1e-3);
        let q = Quat::from_axis_angle(axis, angle);
        let want = Quat::from_axis_angle(axis, alpha * angle);
        prop_assert!(q.pow(alpha).angle_to(want) <= 2.0 * pow_tol(1.0, angle) + MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn slerp_hits_both_endpoints(a in unit_quat(), b in unit_quat()) {
        prop_assert_eq!(a.slerp(b, 0.0), a);
        prop_assert!(a.slerp(b, 1.0).angle_to(b) <= slerp_tol(1.0, a.angle_to(b)) + MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn slerp_takes_the_short_way(a in unit_quat(), b in unit_quat(), alpha in 0.0f32..1.0) {
        let theta = a.angle_to(b);
        prop_assert!(theta <= PI);
        // The midpoint of the long way would lie (2 pi - theta) / 2 >= pi / 2 away.
        let mid = a.slerp(b, 0.5);
        prop_assert!((a.angle_to(mid) - theta / 2.0).abs() <= slerp_tol(0.5, theta) + 2.0 * MUL_MAX_ANGLE_ERROR);
        // b and -b are one rotation, so they give one path.
        prop_assert!(a.slerp(-b, alpha).angle_to(a.slerp(b, alpha)) <= 2.0 * slerp_tol(alpha, theta) + MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn slerp_has_constant_angular_velocity(a in unit_quat(), b in unit_quat(), s in 0.0f32..1.0, t in 0.0f32..1.0) {
        // Every pair of points on the path is |s - t| theta apart: constant
        // speed, and (by the triangle equality) a single great circle, so a
        // single fixed axis.
        let theta = a.angle_to(b);
        let gap = a.slerp(b, s).angle_to(a.slerp(b, t));
        let tol = slerp_tol(s, theta) + slerp_tol(t, theta) + 3.0 * MUL_MAX_ANGLE_ERROR;
        prop_assert!((gap - (s - t).abs() * theta).abs() <= tol);
    }

    #[test]
    fn slerp_extrapolates_along_the_same_path(a in unit_quat(), b in unit_quat(), alpha in -1.0f32..2.0) {
        // Reversing the endpoints walks the same path backwards, also outside [0, 1].
        let forward = a.slerp(b, alpha);
        let backward = b.slerp(a, 1.0 - alpha);
        let theta = a.angle_to(b);
        let tol = slerp_tol(alpha, theta) + slerp_tol(1.0 - alpha, theta) + MUL_MAX_ANGLE_ERROR;
        prop_assert!(forward.angle_to(backward) <= tol);
        // Beyond b, the angle from a keeps growing as alpha theta (while that is at most pi).
        let beyond = 1.0 + alpha.abs() / 2.0;
        if beyond * theta <= PI {
            let got = a.angle_to(a.slerp(b, beyond));
            prop_assert!((got - beyond * theta).abs() <= slerp_tol(beyond, theta) + 3.0 * MUL_MAX_ANGLE_ERROR);
        }
    }

    #[test]
    fn slerp_is_left_invariant(g in unit_quat(), a in unit_quat(), b in unit_quat(), alpha in -1.0f32..2.0) {
        let moved_then_slerped = (g * a).slerp(g * b, alpha);
        let slerped_then_moved = g * a.slerp(b, alpha);
        let tol = 2.0 * slerp_tol(alpha, a.angle_to(b)) + 4.0 * MUL_MAX_ANGLE_ERROR;
        prop_assert!(moved_then_slerped.angle_to(slerped_then_moved) <= tol);
    }

    #[test]
    fn slerp_agrees_with_nalgebra_in_f64(a in unit_quat(), b in unit_quat(), alpha in 0.0f32..1.0) {
        use nalgebra::{Unit, UnitQuaternion};
        let na_a = UnitQuaternion::new_normalize(testkit::to_f64(a));
        let mut na_b = Unit::into_inner(UnitQuaternion::new_normalize(testkit::to_f64(b)));
        if na_a.as_ref().dot(&na_b) < 0.0 {
            na_b = -na_b; // nalgebra's slerp interpolates the components as given
        }
        let na_b = UnitQuaternion::new_normalize(na_b);
        if let Some(want) = na_a.try_slerp(&na_b, alpha as f64, 1e-9) {
            let tol = slerp_tol(alpha, a.angle_to(b)) + MUL_MAX_ANGLE_ERROR;
            prop_assert!(testkit::angle_error(a.slerp(b, alpha), *want.as_ref()) <= tol as f64);
        }
    }

    #[test]
    fn nlerp_and_blend_follow_the_slerp_path(a in unit_quat(), b in unit_quat(), alpha in 0.0f32..1.0) {
        // Same great circle as slerp, so the same rotation at each end and the midpoint.
        prop_assert!(a.nlerp(b, 0.5).angle_to(a.slerp(b, 0.5)) <= slerp_tol(0.5, a.angle_to(b)) + 3.0 * MUL_MAX_ANGLE_ERROR);
        prop_assert!(a.nlerp(b, 1.0).angle_to(b) <= 2.0 * MUL_MAX_ANGLE_ERROR);
        // Written on the side of the first input.
        prop_assert!(a.nlerp(b, alpha).dot(a) >= 0.0);
        // Two-way blend is nlerp.
        let blended = Quat::blend(&[(a, 1.0 - alpha), (b, alpha)]);
        prop_assert!(blended.dot(a) >= 0.0);
        prop_assert!(blended.angle_to(a.nlerp(b, alpha)) <= 2.0 * MUL_MAX_ANGLE_ERROR);
        // Sign alignment: negating any entry changes nothing.
        let flipped = Quat::blend(&[(-a, 1.0 - alpha), (-b, alpha)]);
        prop_assert!(flipped.angle_to(blended) <= 2.0 * MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn blend_of_many_equal_weights_is_the_mean_rotation_about_one_axis(axis in vec3(), angles in prop::array::uniform5(-1.0f32..1.0)) {
        prop_assume!(axis.norm() > 1e-3);
        let entries = angles.map(|a| (Quat::from_axis_angle(axis, a), 1.0));
        // About one axis, the normalized sum of (cos(a/2), sin(a/2) k) is the
        // rotation by 2 atan2(sum sin, sum cos).
        let (s, c) = angles.iter().fold((0.0f64, 0.0f64), |(s, c), &a| (s + (a as f64 / 2.0).sin(), c + (a as f64 / 2.0).cos()));
        let want = Quat::from_axis_angle(axis, 2.0 * s.atan2(c) as f32);
        prop_assert!(Quat::blend(&entries).angle_to(want) <= 4.0 * POW_MAX_ANGLE_ERROR);
    }

    #[test]
    fn cn_is_the_same_rotation_with_nonnegative_w(q in unit_quat()) {
        let c = q.cn();
        prop_assert!(c.w >= 0.0);
        prop_assert!(c == q || c == -q);
    }

    #[test]
    fn axis_angle_round_trips_with_angle_at_most_pi(q in unit_quat()) {
        let (axis, angle) = q.to_axis_angle();
        prop_assert!((0.0..=PI).contains(&angle));
        prop_assert!((axis.norm() - 1.0).abs() <= NORMALIZE_MAX_NORM_ERROR);
        prop_assert!(Quat::from_axis_angle(axis, angle).angle_to(q) <= pow_tol(1.0, angle) + 2.0 * MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn angle_to_is_a_symmetric_distance(a in unit_quat(), b in unit_quat()) {
        prop_assert!((a.angle_to(b) - b.angle_to(a)).abs() <= 2.0 * MUL_MAX_ANGLE_ERROR);
        prop_assert!(a.angle_to(-a) <= MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn rigtform_interpolation_is_left_invariant(g in rig_tform(), a in rig_tform(), b in rig_tform(), alpha in -1.0f32..2.0) {
        let lhs = (g * a).interpolate(g * b, alpha);
        let rhs = g * a.interpolate(b, alpha);
        prop_assert!(lhs.r.angle_to(rhs.r) <= 2.0 * slerp_tol(alpha, a.r.angle_to(b.r)) + 4.0 * MUL_MAX_ANGLE_ERROR);
        let scale = 1.0 + g.t.norm() + 3.0 * (a.t.norm() + b.t.norm());
        prop_assert!((lhs.t - rhs.t).norm() <= 8.0 * ROTATE_MAX_REL_ERROR * scale);
    }

    #[test]
    fn rigtform_interpolation_moves_the_origin_on_a_straight_line_at_constant_speed(a in rig_tform(), b in rig_tform(), alpha in 0.0f32..1.0) {
        prop_assert_eq!(a.interpolate(b, 0.0), a);
        let p = a.interpolate(b, alpha).t;
        prop_assert!(close(p, a.t + (b.t - a.t) * alpha, 1e-5));
    }

    #[test]
    fn rigtform_leaves_vectors_untranslated_and_translates_points(a in rig_tform(), c in vec3()) {
        let v = a * Cvec4::from_vector(c);
        prop_assert_eq!(v.w, 0.0);
        prop_assert_eq!(v.xyz(), a.r * c);
        let p = a * Cvec4::from_point(c);
        prop_assert_eq!(p.w, 1.0);
        prop_assert_eq!(p.xyz(), a.r * c + a.t);
    }

    #[test]
    fn rigtform_product_composes_actions(a in rig_tform(), b in rig_tform(), c in vec3()) {
        let p = Cvec4::from_point(c);
        let scale = 1.0 + a.t.norm() + b.t.norm() + c.norm();
        prop_assert!(((a * b) * p - a * (b * p)).norm() <= 6.0 * ROTATE_MAX_REL_ERROR * scale);
        let lhs = Matrix4::from(a * b).to_cols_array();
        let rhs = (Matrix4::from(a) * Matrix4::from(b)).to_cols_array();
        prop_assert!(max_entry_diff(lhs, rhs) <= 4.0 * MATRIX_ENTRY_ERROR * scale);
    }

    #[test]
    fn matrix_of_a_rigtform_transforms_like_the_rigtform(a in rig_tform(), c in vec3(), w in prop::sample::select(vec![0.0f32, 1.0])) {
        let p = Cvec4::new(c.x, c.y, c.z, w);
        let scale = 1.0 + a.t.norm() + c.norm();
        prop_assert!((Matrix4::from(a) * p - a * p).norm() <= 8.0 * MATRIX_ENTRY_ERROR * scale);
    }

    #[test]
    fn normal_matrix_of_trs_is_r_times_inverse_s(a in rig_tform(), s in prop::array::uniform3(0.1f32..10.0)) {
        let s = Cvec3::new(s[0], s[1], s[2]);
        let trs = Matrix4::from(a) * Matrix4::from_scale(s);
        let n = trs.normal_matrix().expect("non-zero scale");
        let want = Matrix4::from_quat(a.r) * Matrix4::from_scale(Cvec3::new(1.0 / s.x, 1.0 / s.y, 1.0 / s.z));
        prop_assert!(max_entry_diff(n.to_cols_array(), want.to_cols_array()) <= 40.0 * MATRIX_ENTRY_ERROR);
    }

    #[test]
    fn matrix_inverse_multiplies_back_to_identity(a in rig_tform(), s in prop::array::uniform3(0.1f32..10.0)) {
        let m = Matrix4::from(a) * Matrix4::from_scale(Cvec3::new(s[0], s[1], s[2]));
        let i = m.inverse().expect("non-zero scale");
        let scale = 1.0 + a.t.norm();
        prop_assert!(max_entry_diff((m * i).to_cols_array(), Matrix4::IDENTITY.to_cols_array())
            <= 100.0 * MATRIX_ENTRY_ERROR * scale);
    }

    #[test]
    fn transpose_is_an_involution_that_swaps_entries(m in prop::array::uniform16(-10.0f32..10.0)) {
        let a = Matrix4::from_cols_array(&m);
        prop_assert_eq!(a.transpose().transpose(), a);
        prop_assert_eq!(a.transpose().to_cols_array()[1], m[4]);
    }
}

#[test]
fn rigtform_interpolation_is_not_right_invariant() {
    // The notes' figure: the same motion, described with object frames whose
    // origins differ, interpolates differently, because the origin travels on
    // a straight line.
    let a = RigTForm::IDENTITY;
    let b = RigTForm::from_rotation_z(PI / 2.0);
    let h = RigTForm::from_translation(Cvec3::X); // another object origin
    let with_h = (a * h).interpolate(b * h, 0.5);
    let then_h = a.interpolate(b, 0.5) * h;
    let tol = 1e-6 + 4.0 * rigtform::accuracy::SIN_COS_MAX_ABS_ERROR;
    // Straight line from (1, 0, 0) to (0, 1, 0) passes through (0.5, 0.5, 0) ...
    assert!((with_h.t - Cvec3::new(0.5, 0.5, 0.0)).norm() <= tol);
    // ... while the interpolated rotation carries the offset on a circle.
    let h = core::f32::consts::FRAC_1_SQRT_2;
    assert!((then_h.t - Cvec3::new(h, h, 0.0)).norm() <= tol);
    assert!((with_h.t - then_h.t).norm() > 0.29);
    // The rotations agree: only the translation breaks right invariance.
    assert!(with_h.r.angle_to(then_h.r) <= 2.0 * slerp_tol(0.5, PI / 2.0));
}

#[test]
fn perspective_maps_the_edges_of_the_field_of_view_to_the_ndc_square() {
    // A point on the top edge of the view frustum, at any depth, lands on
    // y = 1 after the divide; on the right edge (the aspect ratio wider), x = 1.
    for (fovy, aspect) in [(0.4f32, 1.0f32), (1.2, 16.0 / 9.0), (2.5, 0.5)] {
        let p = Matrix4::perspective(fovy, aspect, 0.1, 100.0);
        let half = (fovy as f64 / 2.0).tan() as f32;
        for depth in [0.5f32, 3.0, 50.0] {
            let top = p * Cvec4::new(0.0, half * depth, -depth, 1.0);
            let right = p * Cvec4::new(aspect * half * depth, 0.0, -depth, 1.0);
            let tol = 4.0 * rigtform::accuracy::TAN_MAX_REL_ERROR + 1e-6;
            assert!(
                (top.y / top.w - 1.0).abs() <= tol,
                "{fovy} {aspect} {depth}: {top:?}"
            );
            assert!(
                (right.x / right.w - 1.0).abs() <= tol,
                "{fovy} {aspect}: {right:?}"
            );
            assert_eq!(top.w, depth);
        }
    }
}

#[test]
fn perspective_maps_near_to_minus_one_and_far_to_plus_one() {
    for (near, far) in [(0.1f32, 100.0f32), (1.0, 2.0), (0.01, 1e4)] {
        let p = Matrix4::perspective(1.0, 1.5, near, far);
        let n = p * Cvec4::new(0.3, -0.2, -near, 1.0);
        let f = p * Cvec4::new(0.3, -0.2, -far, 1.0);
        assert!((n.z / n.w + 1.0).abs() < 1e-5, "{near} {far}: {n:?}");
        assert!((f.z / f.w - 1.0).abs() < 1e-5, "{near} {far}: {f:?}");
        assert_eq!((n.w, f.w), (near, far));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Every law of the contract, as the registry lists it
    /// (`rigtform_proofs::laws::registry::LAWS`), each on one input it
    /// draws from the case's seed: random unit quaternions and transforms,
    /// the slerp edge classes, the edge grid and edge exponents.
    #[test]
    fn every_law_holds(seed in any::<u64>()) {
        for law in LAWS {
            let verdict = (law.case)(&mut Draws::new(seed));
            prop_assert!(verdict.is_ok(), "{}: {:?} (seed {})", law.name, verdict, seed);
        }
    }

}

/// 2^20: the bound on translations and vectors of the laws' properties on
/// mixed draws, beyond any scene or sensor value in metres.
const MILLION: f32 = 1_048_576.0;

/// 2^60: the laws' bound where a product must stay finite.
const TWO_TO_60: f32 = 1.152_921_5e18;

/// Every Euler order.
fn euler_order() -> impl Strategy<Value = EulerRot> {
    prop::sample::select(EulerRot::ALL.to_vec())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 10_000,
        max_global_rejects: 100_000,
        ..ProptestConfig::default()
    })]

    // The laws again, on the draws that hunt edges: components from
    // subnormal to f32::MAX (normalized where a law wants unit inputs),
    // edge values, and the branches uniform rotations all but never meet
    // (nearby pairs, pure reals, half turns, exactly opposite directions).
    // Each property stands for a harness of proofs/src/harnesses.rs that
    // repeated it on the Kani stand-in and that Kani was not expected to
    // finish (several symbolic divisions, square roots and polynomials at
    // once).

    #[test]
    fn law_products_multiply_norms_from_tiny_to_huge(a in quat_within(MILLION), b in quat_within(MILLION)) {
        // Precondition: squared norms in [2^-40, 2^40] (no underflow).
        let n = |q: Quat| f64::from(q.norm_squared());
        prop_assume!((9.1e-13..=1.1e12).contains(&n(a)) && (9.1e-13..=1.1e12).contains(&n(b)));
        assert_holds(laws::product_norm_is_multiplicative(a, b));
    }

    #[test]
    fn law_quat_times_inverse_is_real_from_tiny_to_huge(q in quat_within(TWO_TO_60)) {
        assert_holds(laws::product_with_inverse_is_real(q));
    }

    #[test]
    fn law_rotations_of_normalized_quaternions_preserve_length(q in normalized_quat(), v in vec_within(MILLION)) {
        assert_holds(laws::rotation_preserves_length(q, v));
    }

    #[test]
    fn law_pow_is_unit_for_every_finite_input(q in finite_quat(), w in mixed_f32(), pure_real in any::<bool>(), alpha in mixed_f32()) {
        // Pure reals take their own path, which random components never do.
        let q = if pure_real { Quat::from_wxyz(w, 0.0, 0.0, 0.0) } else { q };
        assert_holds(laws::pow_is_unit(q, alpha));
    }

    #[test]
    fn law_slerp_is_unit_and_takes_the_short_way_for_every_finite_alpha(a in normalized_quat(), b in normalized_quat(), near in any::<bool>(), turn in mixed_within(4.9e-4), alpha in mixed_f32()) {
        // Half the pairs within 2^-11 rad of each other: the small-angle branch.
        let b = if near { (a * Quat::from_rotation_x(turn)).normalize() } else { b };
        assert_holds(laws::slerp_is_unit(a, b, alpha));
        assert_holds(laws::slerp_takes_the_short_way(a, b, alpha));
    }

    #[test]
    fn law_slerp_of_normalized_quaternions_turns_by_alpha_times_the_angle(a in normalized_quat(), b in normalized_quat(), alpha in 0.0f32..=1.0) {
        assert_holds(laws::slerp_turns_by_alpha_times_the_angle(a, b, alpha));
    }

    #[test]
    fn law_nlerp_and_blend_of_normalized_quaternions_are_unit(a in normalized_quat(), b in normalized_quat(), c in normalized_quat(), alpha in 0.0f32..=1.0, w in prop::array::uniform3(mixed_within(MILLION))) {
        assert_holds(laws::nlerp_is_unit(a, b, alpha));
        assert_holds(laws::blend_is_unit_or_identity(&[(a, w[0]), (b, w[1]), (c, w[2])]));
    }

    #[test]
    fn law_rigid_identities_with_normalized_rotations(r in normalized_quat(), t in vec_within(MILLION), v in vec_within(MILLION), point in any::<bool>()) {
        let a = RigTForm::new(t, r);
        assert_holds(laws::rigid_product_with_inverse_is_identity(a));
        assert_holds(laws::rigid_inverse_is_an_involution(a));
        assert_holds(laws::rigid_inverse_matches_matrix_inverse(a));
        let c = Cvec4::new(v.x, v.y, v.z, if point { 1.0 } else { 0.0 });
        assert_holds(laws::rigid_matrix_moves_points_as_the_transform(a, c));
    }

    #[test]
    fn law_euler_angles_give_back_normalized_rotations(q in normalized_quat(), order in euler_order()) {
        assert_holds(laws::euler_angles_give_back_the_rotation(q, order));
    }

    #[test]
    fn law_from_matrix_inverts_normalized_rotations_and_half_turns(q in normalized_quat(), v in vec_within(MILLION), half_turn in any::<bool>()) {
        // Half turns (w = 0): the trace is -1, so x, y or z is the largest
        // of Shepperd's four.
        let q = if half_turn {
            prop_assume!(v != Cvec3::ZERO);
            Quat::from_wxyz(0.0, v.x, v.y, v.z).normalize()
        } else {
            q
        };
        assert_holds(laws::from_matrix_inverts_from_quat(q));
    }

    #[test]
    fn law_rotation_arc_takes_from_to_to_also_when_opposite(from in vec_within(MILLION), to in vec_within(MILLION), nudge in mixed_within(1e-3), kind in 0u32..3) {
        // A third exactly opposite (-2 from: the cross product is exactly
        // zero, the half turn about a perpendicular), a third nearly.
        let to = match kind {
            0 => to,
            1 => from * -2.0,
            _ => from * -2.0 + Cvec3::new(nudge, 0.0, 0.0),
        };
        // Precondition: squared lengths in [2^-40, 2^80].
        let moderate = |v: Cvec3| (9.094_947e-13..=1.208_925_8e24).contains(&v.norm_squared());
        prop_assume!(moderate(from) && moderate(to));
        assert_holds(laws::rotation_arc_takes_from_to_to(from, to));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn from_euler_composes_the_axis_rotations_in_order(a in -PI..PI, b in -PI..PI, c in -PI..PI) {
        let q = Quat::from_euler(EulerRot::ZYX, a, b, c);
        let by_hand = Quat::from_rotation_z(a) * Quat::from_rotation_y(b) * Quat::from_rotation_x(c);
        prop_assert!(q.angle_to(by_hand) <= 2.0 * accuracy::EULER_MAX_ANGLE_ERROR + 2.0 * MUL_MAX_ANGLE_ERROR);
        let q = Quat::from_euler(EulerRot::XZY, a, b, c);
        let by_hand = Quat::from_rotation_x(a) * Quat::from_rotation_z(b) * Quat::from_rotation_y(c);
        prop_assert!(q.angle_to(by_hand) <= 2.0 * accuracy::EULER_MAX_ANGLE_ERROR + 2.0 * MUL_MAX_ANGLE_ERROR);
    }

    #[test]
    fn from_matrix_reads_the_rotation_of_a_rigid_matrix(a in rig_tform()) {
        let r = Quat::from_matrix(Matrix4::from(a));
        prop_assert!(r.angle_to(a.r) <= 2.0 * accuracy::FROM_MATRIX_MAX_ANGLE_ERROR + 8.0 * MATRIX_ENTRY_ERROR);
    }

    #[test]
    fn rotation_arc_is_left_invariant_in_its_directions(a in vec3(), b in vec3(), w in unit_quat()) {
        // Turning both directions by w turns the arc by w: q' = w q w^-1.
        prop_assume!(a.norm() > 1e-3 && b.norm() > 1e-3);
        prop_assume!(a.normalize().dot(b.normalize()) > -0.9);
        let q = Quat::from_rotation_arc(a, b);
        let turned = Quat::from_rotation_arc(w * a, w * b);
        prop_assert!(turned.angle_to(w * q * w.inv()) <= 8.0 * accuracy::ROTATION_ARC_MAX_ERROR + 4.0 * ROTATE_MAX_REL_ERROR);
    }

    #[test]
    fn look_at_sees_the_target_straight_ahead(eye in vec3(), target in vec3(), up in vec3()) {
        let sight = target - eye;
        prop_assume!(sight.norm() > 1e-2 && up.norm() > 1e-3);
        prop_assume!(up.normalize().cross(sight.normalize()).norm() > 0.1);
        let e = RigTForm::look_at(eye, target, up);
        let seen = e.inv().transform_point(target);
        // `seen` is `r^-1 target - r^-1 eye`: the two rotations' errors
        // scale with |target| and |eye|, and do not cancel however short
        // the sight between them; the angle's error turns the sight.
        let error = (seen - Cvec3::new(0.0, 0.0, -sight.norm())).norm();
        let rotations = 2.0 * ROTATE_MAX_REL_ERROR * (1.0 + eye.norm() + target.norm());
        prop_assert!(error <= rotations + 4.0 * accuracy::LOOK_AT_MAX_ANGLE_ERROR * sight.norm(), "{}", error);
        // y is on the side of up, and x is perpendicular to it.
        let (x, y) = (e.transform_vector(Cvec3::X), e.transform_vector(Cvec3::Y));
        prop_assert!(y.dot(up) > 0.0);
        prop_assert!(x.dot(up).abs() <= 4.0 * accuracy::LOOK_AT_MAX_ANGLE_ERROR * up.norm());
    }

    #[test]
    fn determinant_is_multiplicative_and_one_for_rigid_motions(a in rig_tform(), s in vec3()) {
        prop_assume!([s.x, s.y, s.z].iter().all(|c| c.abs() > 1e-2));
        let m = Matrix4::from(a);
        let k = Matrix4::from_scale(s);
        prop_assert!((m.determinant() - 1.0).abs() <= 8.0 * MATRIX_ENTRY_ERROR);
        let product = (m * k).determinant();
        let scale = s.x * s.y * s.z;
        prop_assert!((product - scale).abs() <= 16.0 * MATRIX_ENTRY_ERROR * scale.abs());
    }

    #[test]
    fn transform_point_and_vector_match_the_homogeneous_product(a in rig_tform(), b in rig_tform(), c in vec3()) {
        prop_assert_eq!(a.transform_point(c), (a * Cvec4::from_point(c)).xyz());
        prop_assert_eq!(a.transform_vector(c), (a * Cvec4::from_vector(c)).xyz());
        let mut ab = a;
        ab *= b;
        prop_assert_eq!(ab, a * b);
        // The two sides round differently: the error scales with every
        // length that goes through a rotation or a sum, not with the
        // result's (which may be small after cancellation).
        let scale = 1.0 + a.t.norm() + b.t.norm() + c.norm();
        let gap = (ab.transform_point(c) - a.transform_point(b.transform_point(c))).norm();
        prop_assert!(gap <= (4.0 * ROTATE_MAX_REL_ERROR + 2.0 * MUL_MAX_ANGLE_ERROR) * scale, "{gap}");
    }
}

/// The angular velocity jump, in rad per unit of `t`, of `path` at `s`:
/// the two one-sided velocities apart.
fn velocity_jump(path: impl Fn(f32) -> Quat + Copy, s: f32) -> f64 {
    let before = testkit::catmull_rom::one_sided_angular_velocity(path, s, -1.0);
    let after = testkit::catmull_rom::one_sided_angular_velocity(path, s, 1.0);
    (after - before).norm()
}

/// Piecewise slerp through `keys`, key `i` at `t = i`.
fn piecewise_slerp(keys: &[Quat], t: f32) -> Quat {
    let i = (t.max(0.0) as usize).min(keys.len() - 2);
    keys[i].slerp(keys[i + 1], t - i as f32)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    // Catmull-Rom splines on keyframes of a random walk (neighbours up to
    // 1.5 rad apart), the laws first.

        #[test]
    fn catmull_rom_angular_velocity_is_continuous_at_every_key(walk in key_walk(5)) {
        let keys: Vec<Quat> = walk.iter().map(|k| k.r).collect();
        let spline = |t: f32| Quat::catmull_rom(&keys, t);
        for i in 1..4 {
            let jump = velocity_jump(spline, i as f32);
            // The one-sided differences' truncation (h^2 times the third
            // derivative) and f32 rounding divided by h, measured up to
            // 2.4e-4; the velocities themselves are up to about 2 rad per
            // unit of t, and slerp key to key jumps by as much.
            prop_assert!(jump <= 1e-3, "key {}: jump {:e}", i, jump);
        }
    }

    #[test]
    fn catmull_rom_of_keys_written_as_q_or_minus_q_is_the_same_motion(walk in key_walk(5), signs in prop::array::uniform5(any::<bool>()), t in 0.0f32..4.0) {
        let keys: Vec<Quat> = walk.iter().map(|k| k.r).collect();
        let flipped: Vec<Quat> = keys.iter().zip(signs).map(|(&q, s)| if s { -q } else { q }).collect();
        let (a, b) = (Quat::catmull_rom(&keys, t), Quat::catmull_rom(&flipped, t));
        prop_assert!(a.angle_to(b) <= 1e-6, "{:?} {:?}", a, b);
        let frames: Vec<RigTForm> = walk.iter().zip(&flipped).map(|(k, &r)| RigTForm::new(k.t, r)).collect();
        let (f, g) = (RigTForm::catmull_rom(&walk, t), RigTForm::catmull_rom(&frames, t));
        prop_assert_eq!(f.t, g.t);
        prop_assert!(f.r.angle_to(g.r) <= 1e-6);
        prop_assert!(f.r.angle_to(a) <= 1e-6);
    }
}

#[test]
fn piecewise_slerp_jumps_at_the_keys_where_catmull_rom_does_not() {
    // A quarter turn about z, then one about x: slerp key to key changes
    // axis at once at the middle key.
    let keys = [
        Quat::IDENTITY,
        Quat::from_rotation_z(PI / 2.0),
        Quat::from_rotation_x(PI / 2.0) * Quat::from_rotation_z(PI / 2.0),
    ];
    let slerp_jump = velocity_jump(|t| piecewise_slerp(&keys, t), 1.0);
    let spline_jump = velocity_jump(|t| Quat::catmull_rom(&keys, t), 1.0);
    // Two velocities of pi/2 at right angles: a jump of pi/sqrt(2).
    assert!(
        (slerp_jump - core::f64::consts::PI / 2f64.sqrt()).abs() < 1e-3,
        "{slerp_jump}"
    );
    assert!(spline_jump < 1e-3, "{spline_jump}");
}

/// Pairs for the slice laws: random unit pairs mixed with slerp's edge
/// classes (identical, antipodal, nearly identical, a little off unit norm)
/// and with raw bit patterns and edge values (NaN, infinities, subnormals).
fn slice_pair() -> impl Strategy<Value = (Quat, Quat)> {
    use rigtform_proofs::edge::EDGE_F32;
    let edge = prop::sample::select(EDGE_F32.to_vec());
    let raw = || {
        prop::array::uniform4(any::<u32>()).prop_map(|b| {
            let [w, x, y, z] = b.map(f32::from_bits);
            Quat::from_wxyz(w, x, y, z)
        })
    };
    prop_oneof![
        4 => (unit_quat(), unit_quat()),
        1 => unit_quat().prop_map(|a| (a, a)),
        1 => unit_quat().prop_map(|a| (a, -a)),
        1 => (unit_quat(), 1e-7f32..1e-2).prop_map(|(a, t)| (a, a * Quat::from_rotation_y(t))),
        1 => (unit_quat(), unit_quat(), 0.99f32..1.01).prop_map(|(a, b, s)| (a, Quat::from_wxyz(b.w * s, b.x * s, b.y * s, b.z * s))),
        1 => (raw(), raw()),
        1 => (unit_quat(), edge.clone(), 0usize..4).prop_map(|(a, e, i)| {
            let mut c = [a.w, a.x, a.y, a.z];
            if let Some(c) = c.get_mut(i) {
                *c = e;
            }
            (Quat::from_wxyz(c[0], c[1], c[2], c[3]), a)
        }),
    ]
}

/// `alpha` for the slice laws: inside [0, 1] mostly (the vectorized
/// evaluation), its ends, extrapolation and edge values.
fn slice_alpha() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => 0.0f32..=1.0,
        1 => prop::sample::select(vec![0.0, -0.0, 1.0, 1e-45, 1.0 - f32::EPSILON / 2.0, f32::NAN, f32::INFINITY]),
        1 => -2.0f32..3.0,
        1 => any::<u32>().prop_map(f32::from_bits),
    ]
}

/// 70 pairs: a full block of the vectorized evaluation (64) and part of
/// another.
const SLICE_LEN: usize = 70;

proptest! {
    // Each case draws 70 pairs: the unit quaternions' rejection sampling
    // rejects more than proptest's default allows over a run.
    #![proptest_config(ProptestConfig { cases: 400, max_local_rejects: u32::MAX, ..ProptestConfig::default() })]

    #[test]
    fn law_slerp_slice_is_slerp_bit_for_bit(pairs in prop::collection::vec(slice_pair(), SLICE_LEN), alpha in slice_alpha()) {
        let starts: [Quat; SLICE_LEN] = core::array::from_fn(|i| pairs[i].0);
        let ends: [Quat; SLICE_LEN] = core::array::from_fn(|i| pairs[i].1);
        assert_holds(laws::slerp_slice_is_slerp_bit_for_bit(&starts, &ends, alpha));
    }

    #[test]
    fn law_interpolate_slice_is_interpolate_bit_for_bit(pairs in prop::collection::vec((slice_pair(), vec3(), vec3()), SLICE_LEN), alpha in slice_alpha()) {
        let starts: [RigTForm; SLICE_LEN] = core::array::from_fn(|i| RigTForm::new(pairs[i].1, pairs[i].0 .0));
        let ends: [RigTForm; SLICE_LEN] = core::array::from_fn(|i| RigTForm::new(pairs[i].2, pairs[i].0 .1));
        assert_holds(laws::interpolate_slice_is_interpolate_bit_for_bit(&starts, &ends, alpha));
    }
}
