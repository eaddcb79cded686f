//! Every law of the contract, listed once, each with the inputs it is
//! checked on: the layers that draw their own inputs take their list from
//! here. The proptest property `every_law_holds` (`tests/properties.rs`),
//! the on-target runner (`embedded/src/bin/tests.rs`) and the fuzz target
//! `laws` (`fuzz/fuzz_targets/laws.rs`) run every entry of [`LAWS`]; a law
//! added here is checked by all three, with nothing else to edit. The Kani
//! harnesses, each built by hand for the solver, say which law they prove
//! in [`Law::harness`], and `proofs`' tests check that the names agree.
//!
//! An entry's [`Law::case`] draws one input meeting the law's
//! preconditions from a seeded [`Draws`] (random values, the slerp edge
//! classes, the edge grid of [`EDGE_F32`]) and returns the law's
//! [`Verdict`] on it.

use rigtform::animation::Interpolation;
use rigtform::{Cvec3, Cvec4, EulerRot, Matrix4, Quat, RigTForm};

use super::Verdict;
use crate::draw::Draws;
use crate::edge::EDGE_F32;

/// One law, and how to check it on one drawn input.
#[derive(Clone, Copy)]
pub struct Law {
    /// The law's function name in [`laws`](super), with the inputs in
    /// parentheses where one law has several entries.
    pub name: &'static str,
    /// Draws one input meeting the law's preconditions and checks it.
    pub case: fn(&mut Draws) -> Verdict,
    /// The Kani harness of `src/harnesses.rs` that proves it, or why there
    /// is none.
    pub harness: Harness,
}

/// Whether a law has a Kani harness.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Harness {
    /// The names of the harness functions in `src/harnesses.rs` (a law
    /// split for the solver, one harness per exponent range, has several).
    Proof(&'static [&'static str]),
    /// Why the law has no harness.
    None(&'static str),
}

/// Exponents that find the edges: 0, the ends and middle of [0, 1], both
/// sides of it, and the tiny and huge.
pub const ALPHAS: [f32; 9] = [0.0, 0.25, 0.5, 1.0, -2.0, 3.0, 1e-30, 1e30, f32::MAX];

/// One of [`EDGE_F32`].
fn edge(d: &mut Draws) -> f32 {
    EDGE_F32
        .get(d.below(EDGE_F32.len()))
        .copied()
        .unwrap_or(0.0)
}

/// A point of the edge grid: every component one of [`EDGE_F32`].
fn edge_quat(d: &mut Draws) -> Quat {
    Quat::from_wxyz(edge(d), edge(d), edge(d), edge(d))
}

/// A finite point of the edge grid.
fn finite_edge_quat(d: &mut Draws) -> Quat {
    loop {
        let q = edge_quat(d);
        if q.is_finite() {
            return q;
        }
    }
}

/// A finite `f32` of any magnitude: a random sign, exponent and mantissa
/// (subnormals and zeros included).
fn finite(d: &mut Draws) -> f32 {
    loop {
        let x = f32::from_bits(d.next_u32());
        if x.is_finite() {
            return x;
        }
    }
}

/// One of [`ALPHAS`].
fn edge_alpha(d: &mut Draws) -> f32 {
    ALPHAS.get(d.below(ALPHAS.len())).copied().unwrap_or(0.5)
}

/// One of the 24 orders of Euler angles.
fn euler_order(d: &mut Draws) -> EulerRot {
    EulerRot::ALL
        .get(d.below(EulerRot::ALL.len()))
        .copied()
        .unwrap_or(EulerRot::XYZ)
}

/// `law` of a [`pair`] and an `alpha` drawn after it.
fn on_pair(
    d: &mut Draws,
    alpha: impl Fn(&mut Draws) -> f32,
    law: fn(Quat, Quat, f32) -> Verdict,
) -> Verdict {
    let (a, b) = pair(d);
    law(a, b, alpha(d))
}

/// A pair of unit quaternions: half of them random, the other half one of
/// the slerp edge classes (identical, 1e-6 rad apart, antipodal: the same
/// rotation as `-a`, and opposite: a half turn apart).
fn pair(d: &mut Draws) -> (Quat, Quat) {
    let a = d.unit_quat();
    let axis = d.vec3(1.0);
    let b = match d.below(8) {
        0 => a,
        1 => Quat::from_axis_angle(axis, 1e-6) * a,
        2 => -a,
        3 => Quat::from_axis_angle(axis, core::f32::consts::PI) * a,
        _ => d.unit_quat(),
    };
    (a, b)
}

fn rig_tform(d: &mut Draws) -> RigTForm {
    RigTForm::new(d.vec3(100.0), d.unit_quat())
}

/// Four keyframes on a random walk: the first rotation uniform, each next
/// one turned by up to 1.5 rad about a random axis (the spline laws'
/// precondition), translations within 100.
fn key_walk(d: &mut Draws) -> [RigTForm; 4] {
    let mut r = d.unit_quat();
    core::array::from_fn(|_| {
        let key = RigTForm::new(d.vec3(100.0), r);
        r = (Quat::from_axis_angle(d.vec3(1.0), d.uniform(0.0, 1.5)) * r).normalize();
        key
    })
}

/// A glTF sampler's key times and rotations: four keys from 0.5 s,
/// intervals of 0.05 to 2 s, and CUBICSPLINE's tangents of up to 1 per
/// component around the keys.
fn sampler_keys(d: &mut Draws) -> ([f32; 4], [Quat; 4], [Quat; 12]) {
    let r = key_walk(d).map(|k| k.r);
    let mut time = 0.5;
    let times = core::array::from_fn(|_| {
        let now = time;
        time += d.uniform(0.05, 2.0);
        now
    });
    let mut tangent = || {
        Quat::from_xyzw(
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
        )
    };
    let cubic = core::array::from_fn(|i| if i % 3 == 1 { r[i / 3] } else { tangent() });
    (times, r, cubic)
}

const INTERPOLATIONS: [Interpolation; 3] = [
    Interpolation::Step,
    Interpolation::Linear,
    Interpolation::CubicSpline,
];

/// An entry: the law's name, its case, and its harness.
macro_rules! law {
    ($name:literal, $harness:expr, $input:ident => $law:path) => {
        Law {
            name: $name,
            case: |d: &mut Draws| $law($input(d)),
            harness: $harness,
        }
    };
    ($name:literal, $harness:expr, |$d:ident| $case:expr) => {
        Law {
            name: $name,
            case: |$d: &mut Draws| $case,
            harness: $harness,
        }
    };
}

use super as laws;

/// Why a law Kani is not expected to finish has no harness.
const BEYOND_THE_SOLVER: &str =
    "beyond the solver: tests/properties.rs runs it on the mixed draws of testkit::strategies";
use Harness::{None as NoHarness, Proof};

/// Every law, with its inputs.
pub const LAWS: &[Law] = &[
    law!(
        "product_norm_is_multiplicative",
        Proof(&[
            "quat_product_multiplies_norms_small",
            "quat_product_multiplies_norms_moderate",
            "quat_product_multiplies_norms_large"
        ]),
        |d| { laws::product_norm_is_multiplicative(d.unit_quat(), d.unit_quat()) }
    ),
    law!(
        "rotation_preserves_length",
        NoHarness(BEYOND_THE_SOLVER),
        |d| { laws::rotation_preserves_length(d.unit_quat(), d.vec3(1e3)) }
    ),
    law!(
        "normalize_is_unit (edge grid)",
        Proof(&[
            "normalize_is_unit_from_subnormal_to_max",
            "normalize_is_unit_scaled_up",
            "normalize_is_unit_unscaled",
            "normalize_is_unit_scaled_down"
        ]),
        |d| {
            // Zero has no direction; one of subnormals only stands in for it.
            let q = finite_edge_quat(d);
            let q = if q == Quat::from_wxyz(0.0, 0.0, 0.0, 0.0) {
                Quat::from_wxyz(1e-45, -1e-45, 0.0, 1e-40)
            } else {
                q
            };
            laws::normalize_is_unit(q)
        }
    ),
    law!(
        "pow_is_unit (edge grid, edge alphas)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| { laws::pow_is_unit(finite_edge_quat(d), edge_alpha(d)) }
    ),
    law!(
        "pow_is_unit (random, any finite alpha)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| { laws::pow_is_unit(d.unit_quat(), finite(d)) }
    ),
    law!(
        "pow_turns_as_the_notes_define",
        Proof(&["pow_turns_as_the_notes_define"]),
        |d| { laws::pow_turns_as_the_notes_define(d.unit_quat(), d.uniform(-4.0, 4.0)) }
    ),
    law!(
        "pow_of_non_finite_is_nan",
        Proof(&["pow_of_non_finite_input_is_nan"]),
        |d| {
            let q = edge_quat(d);
            if q.is_finite() {
                laws::pow_of_non_finite_is_nan(q, f32::NAN)
            } else {
                laws::pow_of_non_finite_is_nan(q, edge_alpha(d))
            }
        }
    ),
    law!(
        "slerp_is_unit (pairs, edge alphas)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| on_pair(d, edge_alpha, laws::slerp_is_unit)
    ),
    law!(
        "slerp_is_unit (pairs, alpha in [-2, 3])",
        NoHarness(BEYOND_THE_SOLVER),
        |d| on_pair(d, |d| d.uniform(-2.0, 3.0), laws::slerp_is_unit)
    ),
    law!(
        "slerp_is_unit (pairs, any finite alpha)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| on_pair(d, finite, laws::slerp_is_unit)
    ),
    law!(
        "slerp_of_non_finite_is_nan",
        Proof(&["slerp_of_non_finite_input_is_nan"]),
        |d| {
            let (a, b) = pair(d);
            let bad = edge_quat(d);
            match d.below(3) {
                0 if !bad.is_finite() => laws::slerp_of_non_finite_is_nan(bad, b, edge_alpha(d)),
                1 if !bad.is_finite() => laws::slerp_of_non_finite_is_nan(a, bad, edge_alpha(d)),
                _ => laws::slerp_of_non_finite_is_nan(
                    a,
                    b,
                    [f32::NAN, f32::INFINITY, -f32::INFINITY][d.below(3)],
                ),
            }
        }
    ),
    law!(
        "slerp_is_exact_at_zero",
        Proof(&["slerp_is_exact_at_zero"]),
        |d| {
            let (a, b) = pair(d);
            laws::slerp_is_exact_at_zero(a, b)
        }
    ),
    law!(
        "slerp_turns_by_alpha_times_the_angle",
        NoHarness(BEYOND_THE_SOLVER),
        |d| on_pair(
            d,
            |d| d.uniform(0.0, 1.0),
            laws::slerp_turns_by_alpha_times_the_angle
        )
    ),
    law!(
        "slerp_matches_the_notes",
        NoHarness("f64 sines and arctangents of libm"),
        |d| on_pair(d, |d| d.uniform(-1.0, 2.0), laws::slerp_matches_the_notes)
    ),
    law!(
        "slerp_takes_the_short_way",
        NoHarness(BEYOND_THE_SOLVER),
        |d| on_pair(d, |d| d.uniform(-2.0, 3.0), laws::slerp_takes_the_short_way)
    ),
    law!(
        "slerp_reaches_the_rotation_of_b_at_one",
        NoHarness("the same as slerp_turns_by_alpha_times_the_angle at 1"),
        |d| {
            let (a, b) = pair(d);
            laws::slerp_reaches_the_rotation_of_b_at_one(a, b)
        }
    ),
    law!("nlerp_is_unit", NoHarness(BEYOND_THE_SOLVER), |d| on_pair(
        d,
        |d| d.uniform(0.0, 1.0),
        laws::nlerp_is_unit
    )),
    law!(
        "blend_is_unit_or_identity",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let (a, b, c) = (d.unit_quat(), d.unit_quat(), d.unit_quat());
            let w = [
                d.uniform(-1.0, 2.0),
                d.uniform(0.0, 1.0),
                d.uniform(-3.0, 3.0),
            ];
            laws::blend_is_unit_or_identity(&[(a, w[0]), (b, w[1]), (c, w[2])])
        }
    ),
    law!("inverse_is_an_involution (edge grid)", Proof(&["quat_inverse_is_an_involution"]), edge_quat => laws::inverse_is_an_involution),
    law!(
        "product_with_inverse_is_real",
        Proof(&[
            "quat_times_inverse_is_real_small",
            "quat_times_inverse_is_real_moderate",
            "quat_times_inverse_is_real_large"
        ]),
        |d| { laws::product_with_inverse_is_real(d.unit_quat()) }
    ),
    law!("cn_gives_non_negative_w_and_the_same_rotation (edge grid)", Proof(&["cn_gives_non_negative_w_and_the_same_rotation"]), edge_quat => laws::cn_gives_non_negative_w_and_the_same_rotation),
    law!("rigid_product_with_inverse_is_identity", NoHarness(BEYOND_THE_SOLVER), rig_tform => laws::rigid_product_with_inverse_is_identity),
    law!("rigid_inverse_is_an_involution", NoHarness(BEYOND_THE_SOLVER), rig_tform => laws::rigid_inverse_is_an_involution),
    law!("rigid_inverse_matches_matrix_inverse", NoHarness(BEYOND_THE_SOLVER), rig_tform => laws::rigid_inverse_matches_matrix_inverse),
    law!(
        "rigid_matrix_moves_points_as_the_transform",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let (a, p) = (rig_tform(d), d.vec3(100.0));
            laws::rigid_matrix_moves_points_as_the_transform(a, Cvec4::from_point(p))?;
            laws::rigid_matrix_moves_points_as_the_transform(a, Cvec4::from_vector(p))
        }
    ),
    law!(
        "interpolate_is_exact_at_zero",
        Proof(&["rigtform_interpolate_is_exact_at_zero"]),
        |d| { laws::interpolate_is_exact_at_zero(rig_tform(d), rig_tform(d)) }
    ),
    law!(
        "slerp_slice_is_slerp_bit_for_bit (20 pairs, edge alphas)",
        NoHarness("loops over slices; the lanes' unsafe code is Miri's"),
        |d| {
            let pairs: [(Quat, Quat); 20] = core::array::from_fn(|_| pair(d));
            laws::slerp_slice_is_slerp_bit_for_bit(
                &pairs.map(|p| p.0),
                &pairs.map(|p| p.1),
                edge_alpha(d),
            )
        }
    ),
    law!(
        "interpolate_slice_is_interpolate_bit_for_bit (20 transforms, edge alphas)",
        NoHarness("loops over slices; the lanes' unsafe code is Miri's"),
        |d| {
            let starts: [RigTForm; 20] = core::array::from_fn(|_| rig_tform(d));
            let ends: [RigTForm; 20] = core::array::from_fn(|_| rig_tform(d));
            laws::interpolate_slice_is_interpolate_bit_for_bit(&starts, &ends, edge_alpha(d))
        }
    ),
    law!(
        "matrix_inverse_is_none_or_finite (mixed bits, edge scales)",
        Proof(&["matrix_inverse_is_none_or_finite"]),
        |d| {
            let m: [f32; 16] = core::array::from_fn(|_| d.f32_mixed());
            laws::matrix_inverse_is_none_or_finite(Matrix4::from_cols_array(&m))?;
            laws::matrix_inverse_is_none_or_finite(Matrix4::from_scale(Cvec3::new(
                edge(d),
                1.0,
                2.0,
            )))
        }
    ),
    law!(
        "euler_angles_give_back_the_rotation",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let order = euler_order(d);
            laws::euler_angles_give_back_the_rotation(d.unit_quat(), order)
        }
    ),
    law!(
        "euler_angles_give_back_the_rotation (gimbal lock)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let order = euler_order(d);
            let pi = core::f32::consts::PI;
            let b = if d.below(2) == 0 { pi / 2.0 } else { -pi / 2.0 };
            let q = Quat::from_euler(order, d.uniform(-pi, pi), b, d.uniform(-pi, pi));
            laws::euler_angles_give_back_the_rotation(q, order)
        }
    ),
    law!(
        "from_matrix_inverts_from_quat",
        NoHarness(BEYOND_THE_SOLVER),
        |d| { laws::from_matrix_inverts_from_quat(d.unit_quat()) }
    ),
    law!(
        "rotation_arc_takes_from_to_to",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let (from, to) = (d.vec3(10.0), d.vec3(10.0));
            if from.norm_squared() < 1e-6 || to.norm_squared() < 1e-6 {
                return Ok(());
            }
            laws::rotation_arc_takes_from_to_to(from, to)
        }
    ),
    law!(
        "rotation_arc_takes_from_to_to (nearly the same or opposite)",
        NoHarness(BEYOND_THE_SOLVER),
        |d| {
            let from = d.vec3(10.0);
            if from.norm_squared() < 1e-6 {
                return Ok(());
            }
            let scale = if d.below(2) == 0 { -2.0 } else { 3.0 };
            laws::rotation_arc_takes_from_to_to(from, from * scale + d.vec3(1e-6))
        }
    ),
    law!(
        "catmull_rom_is_the_key_at_and_beyond_each_key (edge keys)",
        Proof(&["catmull_rom_is_the_key_at_and_beyond_each_key"]),
        |d| {
            let keys = [d.unit_quat(), edge_quat(d), d.unit_quat()];
            for t in [
                f32::NAN,
                -1.0,
                0.0,
                1.0,
                2.0,
                7.0,
                f32::INFINITY,
                d.uniform(-20.0, 0.0),
            ] {
                laws::catmull_rom_is_the_key_at_and_beyond_each_key(&keys, t)?;
            }
            Ok(())
        }
    ),
    law!(
        "catmull_rom_is_unit",
        NoHarness("three slerps of a spline are beyond the solver"),
        |d| { laws::catmull_rom_is_unit(&key_walk(d).map(|k| k.r), d.uniform(-0.5, 3.5)) }
    ),
    law!(
        "catmull_rom_is_left_invariant",
        NoHarness("three slerps of a spline are beyond the solver"),
        |d| {
            laws::catmull_rom_is_left_invariant(
                d.unit_quat(),
                key_walk(d).map(|k| k.r),
                d.uniform(-0.5, 3.5),
            )
        }
    ),
    law!(
        "catmull_rom_of_two_keys_follows_the_slerp_path",
        NoHarness("three slerps of a spline are beyond the solver"),
        |d| {
            let r = key_walk(d).map(|k| k.r);
            laws::catmull_rom_of_two_keys_follows_the_slerp_path(r[0], r[1], d.uniform(-1.5, 2.5))
        }
    ),
    law!(
        "catmull_rom_translation_is_the_cubic",
        NoHarness("f64 reference of the cubic"),
        |d| { laws::catmull_rom_translation_is_the_cubic(&key_walk(d), d.uniform(-0.5, 3.5)) }
    ),
    law!("sampler_hits_its_keys", NoHarness("loops over keys"), |d| {
        let (times, r, cubic) = sampler_keys(d);
        for kind in INTERPOLATIONS {
            let values: &[Quat] = if kind == Interpolation::CubicSpline {
                &cubic
            } else {
                &r
            };
            laws::sampler_hits_its_keys(kind, &times, values)?;
        }
        Ok(())
    }),
    law!("sampler_is_unit", NoHarness("loops over keys"), |d| {
        let (times, r, cubic) = sampler_keys(d);
        let at = d.uniform(0.0, 7.0);
        for kind in INTERPOLATIONS {
            let values: &[Quat] = if kind == Interpolation::CubicSpline {
                &cubic
            } else {
                &r
            };
            laws::sampler_is_unit(kind, &times, values, at)?;
        }
        Ok(())
    }),
    law!(
        "step_sampler_is_constant_between_keys",
        Proof(&["step_sampler_copies_its_keys"]),
        |d| {
            let (times, r, _) = sampler_keys(d);
            laws::step_sampler_is_constant_between_keys(&times, &r, d.uniform(0.0, 7.0))
        }
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Each law's function appears in the registry, so that every layer
    /// that takes its list from here checks it.
    #[test]
    fn every_law_of_the_contract_is_registered() {
        let source = include_str!("../laws.rs").to_owned()
            + include_str!("constructors.rs")
            + include_str!("animation.rs");
        for line in source.lines() {
            let Some(rest) = line.strip_prefix("pub fn ") else {
                continue;
            };
            let name = rest.split(['(', '<']).next().unwrap_or_default();
            if name == "assert_holds" {
                continue;
            }
            assert!(
                LAWS.iter()
                    .any(|law| law.name.split(' ').next() == Some(name)),
                "the law {name} is not in LAWS"
            );
        }
    }

    /// Every harness the registry names is a function of `src/harnesses.rs`,
    /// and every harness there is named by an entry.
    #[test]
    fn the_harnesses_named_exist() {
        let harnesses = include_str!("../harnesses.rs");
        let mut named = std::vec::Vec::new();
        for law in LAWS.iter() {
            if let Harness::Proof(names) = law.harness {
                for name in names {
                    named.push(*name);
                    assert!(
                        harnesses.contains(&std::format!("fn {name}()")),
                        "{}: no harness {name}",
                        law.name
                    );
                }
            }
        }
        let mut lines = harnesses.lines().peekable();
        while let Some(line) = lines.next() {
            if line.contains("#[cfg_attr(not(kani), test)]") {
                let body = lines.find(|l| l.starts_with("fn ")).unwrap_or_default();
                let name = body[3..].split('(').next().unwrap_or_default();
                assert!(
                    named.contains(&name),
                    "the harness {name} proves no registered law"
                );
            }
        }
    }

    /// Names are unique, and every law holds on a few thousand draws.
    #[test]
    fn every_entry_holds_on_seeded_draws() {
        for (i, law) in LAWS.iter().enumerate() {
            assert!(
                LAWS[..i].iter().all(|other| other.name != law.name),
                "{}",
                law.name
            );
            let mut d = Draws::new(i as u64);
            for _ in 0..2_000 {
                if let Err(v) = (law.case)(&mut d) {
                    panic!("{}: {v:?}", law.name);
                }
            }
        }
    }
}
