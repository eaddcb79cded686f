//! The contracts on the library's core operations (`kani::requires` and
//! `kani::ensures` under `cfg(kani)`, their conditions in the library's
//! `src/kani_contracts.rs`, shown here as `rigtform::kani_contracts`
//! by the `kernel-contracts` feature of this crate's dev-dependency),
//! checked on edge and random inputs: wherever an operation's `requires`
//! holds, its `ensures` holds of the result. Kani checks the same on every
//! input (`cargo kani -p rigtform -Z function-contracts`), where it is
//! installed; this is testing, on the draws counted below, not proof.
//!
//! Also: that the bounds the contracts state are no tighter than the ones
//! the Gappa models prove (read from each model's `#!` line), and that
//! every `ensures` rejects results the operation must not give (a contract
//! that accepted anything would make `stub_verified` vacuous).

use rigtform::kani_contracts as c;
use rigtform::{Cvec3, Quat, RigTForm};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::edge::{edge_quats, EDGE_F32};

/// Random draws per operation.
const DRAWS: usize = 200_000;

/// A quaternion with components in [-1, 1], unit or not: uniform,
/// unit, and edge components.
fn quat_in_box(d: &mut Draws) -> Quat {
    match d.below(3) {
        0 => d.unit_quat(),
        1 => Quat::from_xyzw(
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
            d.uniform(-1.0, 1.0),
        ),
        _ => {
            let mut edge = || {
                let x = EDGE_F32[d.below(EDGE_F32.len())];
                if x.abs() <= 1.0 {
                    x
                } else {
                    d.uniform(-1.0, 1.0)
                }
            };
            Quat::from_xyzw(edge(), edge(), edge(), edge())
        }
    }
}

/// A vector with components up to `VEC_BOUND`, from tiny to the bound.
fn bounded_vec(d: &mut Draws) -> Cvec3 {
    let scale = [1e-30, 1e-3, 1.0, 1e3, 1e15, c::VEC_BOUND][d.below(6)];
    d.vec3(1.0) * scale
}

#[test]
fn the_core_operations_meet_their_contracts_on_edge_and_random_inputs() {
    let mut d = Draws::new(2405);
    let mut counts = [0usize; 6];
    // Edge quaternions: normalize and inv on every one, the product with a
    // random unit quaternion on those in the box.
    for q in edge_quats() {
        assert!(c::is_conjugate(q, q.inv()), "inv {q:?}");
        if c::normalize_requires(q) {
            assert!(
                c::normalize_ensures(q, q.normalize()),
                "normalize {q:?}: {:?}",
                q.normalize()
            );
            counts[0] += 1;
        }
        let u = d.unit_quat();
        if c::quat_mul_requires(q, u) {
            assert!(c::quat_mul_ensures(q, u, q * u), "{q:?} * {u:?}");
            assert!(c::quat_mul_ensures(u, q, u * q), "{u:?} * {q:?}");
            counts[1] += 1;
        }
    }
    for _ in 0..DRAWS {
        let (a, b) = (quat_in_box(&mut d), quat_in_box(&mut d));
        assert!(c::quat_mul_requires(a, b));
        assert!(
            c::quat_mul_ensures(a, b, a * b),
            "{a:?} * {b:?} = {:?}",
            a * b
        );
        counts[1] += 1;

        let q = Quat::from_xyzw(d.f32_mixed(), d.f32_mixed(), d.f32_mixed(), d.f32_mixed());
        if c::normalize_requires(q) {
            assert!(
                c::normalize_ensures(q, q.normalize()),
                "normalize {q:?}: {:?}",
                q.normalize()
            );
            counts[0] += 1;
        }

        let v = bounded_vec(&mut d);
        assert!(c::rotate_requires(a, v));
        assert!(
            c::rotate_ensures(a, v, a * v),
            "{a:?} * {v:?} = {:?}",
            a * v
        );
        let w = d.vec3(1.0);
        assert!(
            c::rotate_ensures(a, w, a * w),
            "{a:?} * {w:?} = {:?}",
            a * w
        );
        counts[2] += 1;

        let (u, t) = (d.unit_quat(), d.unit_quat());
        let alpha = match d.below(4) {
            0 => 0.0,
            1 => 1.0,
            _ => d.uniform(0.0, 1.0),
        };
        assert!(c::slerp_requires(u, t, alpha), "{u:?} {t:?} {alpha}");
        let s = u.slerp(t, alpha);
        assert!(
            c::slerp_ensures(u, alpha, s),
            "{u:?}.slerp({t:?}, {alpha}) = {s:?}"
        );
        counts[3] += 1;

        let (f, g) = (
            RigTForm::new(bounded_vec(&mut d), a),
            RigTForm::new(bounded_vec(&mut d), b),
        );
        assert!(c::rigtform_inv_requires(f) && c::rigtform_inv_requires(g));
        assert!(c::rigtform_inv_ensures(f, f.inv()), "{f:?}.inv()");
        assert!(c::rigtform_inv_ensures(g, g.inv()), "{g:?}.inv()");
        assert!(c::rigtform_mul_requires(f, g));
        assert!(c::rigtform_mul_ensures(f, g, f * g), "{f:?} * {g:?}");
        counts[4] += 1;
        let p = bounded_vec(&mut d);
        assert!(c::transform_point_requires(f, p));
        assert!(
            c::transform_point_ensures(f.transform_point(p)),
            "{f:?} {p:?}"
        );
        counts[5] += 1;
    }
    println!(
        "contracts held on: normalize {}, quat product {}, rotate {}, slerp {}, rigtform inv and product {}, \
         transform_point {} inputs",
        counts[0], counts[1], counts[2], counts[3], counts[4], counts[5]
    );
    assert!(counts.iter().all(|&n| n >= DRAWS), "{counts:?}");
}

/// The square root Kani reads (`float/sqrt_kani.rs`) describes the
/// library's: on every 4096th bit pattern that is a positive finite f32.
#[test]
fn kanis_square_root_is_the_librarys() {
    use rigtform::kani_kernels::{is_correctly_rounded_sqrt, sqrt};
    let mut checked = 0;
    for x in (0..0x7f80_0000_u32)
        .step_by(4096)
        .map(f32::from_bits)
        .filter(|&x| x > 0.0)
    {
        assert!(
            is_correctly_rounded_sqrt(x, sqrt(x)),
            "sqrt({x:e}) = {:e}",
            sqrt(x)
        );
        checked += 1;
    }
    assert!(checked > 500_000, "{checked}");
}

#[test]
fn the_contracts_reject_what_the_operations_must_not_give() {
    let u = Quat::from_rotation_x(0.5);
    let off = Quat::from_xyzw(0.0, 0.0, 0.0, 1.0 + 1e-5);
    assert!(!c::quat_mul_ensures(u, u, Quat::NAN));
    assert!(!c::quat_mul_ensures(u, u, off));
    assert!(c::quat_mul_ensures(u, u, u * u));
    assert!(!c::quat_mul_requires(
        u,
        Quat::from_xyzw(1.5, 0.0, 0.0, 0.0)
    ));
    assert!(!c::normalize_ensures(
        Quat::from_xyzw(2.0, 0.0, 0.0, 0.0),
        Quat::from_xyzw(2.0, 0.0, 0.0, 0.0)
    ));
    assert!(!c::normalize_ensures(
        Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        Quat::IDENTITY
    ));
    assert!(!c::normalize_ensures(u, off));
    assert!(!c::is_conjugate(u, u));
    assert!(!c::is_conjugate(
        Quat::IDENTITY,
        Quat::from_xyzw(0.0, 0.0, 0.0, 1.0)
    )); // +0 is not -0
    assert!(!c::rotate_ensures(u, Cvec3::X, Cvec3::X * (1.0 + 1e-4)));
    assert!(!c::rotate_ensures(
        u,
        Cvec3::X,
        Cvec3::new(f32::NAN, 0.0, 0.0)
    ));
    assert!(!c::slerp_ensures(u, 0.0, u * u));
    assert!(!c::slerp_ensures(u, 0.5, Quat::NAN));
    assert!(!c::slerp_requires(u, u, 1.5));
    let f = RigTForm::new(Cvec3::X, u);
    assert!(!c::rigtform_inv_ensures(f, f));
    assert!(!c::rigtform_mul_ensures(
        f,
        f,
        RigTForm::new(Cvec3::new(f32::INFINITY, 0.0, 0.0), u * u)
    ));
    assert!(!c::rigtform_mul_ensures(
        f,
        f,
        RigTForm::new(Cvec3::X, u * 1.01)
    ));
    assert!(!c::transform_point_ensures(Cvec3::new(0.0, f32::NAN, 0.0)));
    assert!(!c::transform_point_requires(
        f,
        Cvec3::new(0.0, 0.0, c::VEC_BOUND * 2.0)
    ));
}

/// The bound a Gappa model or a Coq law proves for an accuracy constant:
/// the upper end of the goal that the model's `#!` line for the constant
/// names (`#! bound NAME QUANTITY in [LO, HI] ...`), or the bound of the
/// theorem a law's `(*!` line names (`(*! bound NAME THEOREM <= VALUE
/// ...`); `cargo xtask prove` checks that the certificate proves that goal
/// and that the theorem states that bound.
fn proven(model: &str, constant: &str) -> f64 {
    let folder = if model.ends_with(".v") {
        "coq"
    } else {
        "gappa"
    };
    let path = format!("{}/{folder}/{model}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter_map(|line| line.strip_prefix("#!").or_else(|| line.strip_prefix("(*!")))
        .filter(|line| line.split_whitespace().nth(1) == Some(constant))
        .find_map(|line| {
            // A law: `bound NAME THEOREM <= VALUE what`.
            if let Some((_, value)) = line.split_once(" <= ") {
                return value.split_whitespace().next()?.parse().ok();
            }
            let (_, interval) = line.split_once(" in [")?;
            let (ends, _) = interval.split_once(']')?;
            let (_, hi) = ends.split_once(',')?;
            hi.trim().parse().ok()
        })
        .unwrap_or_else(|| panic!("{path} has no claim for {constant}"))
}

/// The ends of a hypothesis `NAME in [LO, HI]` of a model, as decimals.
fn hypothesis(model: &str, name: &str) -> (f64, f64) {
    let path = format!("{}/gappa/{model}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let formula = text.split_once('{').map_or("", |(_, f)| f);
    let at = formula
        .find(&format!("{name} in ["))
        .unwrap_or_else(|| panic!("{path}: no hypothesis on {name}"));
    let rest = &formula[at + name.len() + 5..];
    let (ends, _) = rest.split_once(']').unwrap_or_default();
    let (lo, hi) = ends.split_once(',').unwrap_or_default();
    let parse = |t: &str| {
        t.trim()
            .parse::<f64>()
            .unwrap_or_else(|e| panic!("{path}: {t}: {e}"))
    };
    (parse(lo), parse(hi))
}

/// The contracts' constants are the bounds the models prove, read from
/// the goals their claims name: not copied numbers that can go stale.
#[test]
fn the_contracts_state_the_bounds_gappa_proves() {
    for (name, stated, model, constant) in [
        ("MUL_ERROR_PROVEN", c::MUL_ERROR_PROVEN, "mul.g", "-"),
        (
            "MUL_NORM_PROVEN",
            c::MUL_NORM_PROVEN,
            "mul_norm.v",
            "UNIT_NORM_ERROR",
        ),
        (
            "NORMALIZE_NORM_PROVEN",
            c::NORMALIZE_NORM_PROVEN,
            "normalize_norm.v",
            "NORMALIZE_MAX_NORM_ERROR",
        ),
        (
            "ROTATE_ERROR_PROVEN",
            c::ROTATE_ERROR_PROVEN,
            "rotate_error.v",
            "ROTATE_MAX_REL_ERROR",
        ),
    ] {
        let bound = proven(model, constant);
        println!("{name} = {stated:e}; {model} proves {bound:e}");
        assert_eq!(stated, bound, "{name} is not what {model} proves");
    }
}

/// A unit quaternion of the contracts (`is_unit`: norm within `UNIT_TOL`
/// of 1) lies in the domain of the models whose bounds the contracts of
/// the product and the rotation state: its squared norm within the
/// hypothesis of `mul.g` and `rotate.g` on `|q|^2`.
#[test]
fn the_contracts_domains_are_the_models_hypotheses() {
    let (lo, hi) = ((1.0 - c::UNIT_TOL).powi(2), (1.0 + c::UNIT_TOL).powi(2));
    for (model, name) in [("mul.g", "QA"), ("mul.g", "QB"), ("rotate.g", "Q")] {
        let (h_lo, h_hi) = hypothesis(model, name);
        println!("|q|^2 of a unit quaternion in [{lo:e}, {hi:e}]; {model} assumes {name} in [{h_lo:e}, {h_hi:e}]");
        assert!(
            h_lo <= lo && hi <= h_hi,
            "is_unit admits |q|^2 in [{lo}, {hi}], beyond {model}'s {name} in [{h_lo}, {h_hi}]"
        );
    }
}
