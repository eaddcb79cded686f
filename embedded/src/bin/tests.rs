//! The no_std subset of `rigtform`'s tests, run on an emulated Cortex-M4F
//! (`cargo test-m4f`) or Cortex-M0 (`cargo test-m0`): the laws of
//! `rigtform_proofs::laws` on edge values and seeded random draws, and the
//! accuracy this backend reaches on this core against an `f64` reference.

#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::hprintln;
use panic_semihosting as _;
use rigtform::accuracy::{POW_MAX_ANGLE_ERROR, SLERP_MAX_ANGLE_ERROR, UNIT_NORM_ERROR};
use rigtform::animation::Interpolation;
use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};
use rigtform_embedded::{each, Tally};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::edge::{edge_quats, finite_edges, EDGE_F32};
use rigtform_proofs::laws::{self, Violation};
use rigtform_proofs::reference::Quat64;

/// Random draws per law (the host runs far more; this keeps the slowest
/// configuration, soft-float on the M0, to seconds).
const DRAWS: u32 = 2_000;

/// Every 13th quaternion of the 24^4 edge grid (25,522 of 331,776).
fn some_edge_quats() -> impl Iterator<Item = Quat> {
    edge_quats().step_by(13)
}

fn unit_pairs(seed: u64) -> impl Iterator<Item = (Quat, Quat)> {
    let mut d = Draws::new(seed);
    (0..DRAWS).map(move |_| (d.unit_quat(), d.unit_quat()))
}

/// Pairs of the slerp edge classes: identical, 1e-6 rad apart, antipodal
/// (the same rotation as -q) and opposite (a half turn apart).
fn degenerate_pairs(seed: u64) -> impl Iterator<Item = (Quat, Quat)> {
    let mut d = Draws::new(seed);
    (0..DRAWS).map(move |i| {
        let a = d.unit_quat();
        let axis = d.vec3(1.0);
        let b = match i % 4 {
            0 => a,
            1 => Quat::from_axis_angle(axis, 1e-6) * a,
            2 => -a,
            _ => Quat::from_axis_angle(axis, core::f32::consts::PI) * a,
        };
        (a, b)
    })
}

fn rig_tforms(seed: u64) -> impl Iterator<Item = RigTForm> {
    let mut d = Draws::new(seed);
    (0..DRAWS).map(move |_| RigTForm::new(d.vec3(100.0), d.unit_quat()))
}

/// Four keyframes on a random walk: the first rotation uniform, each next
/// one turned by up to 1.5 rad about a random axis (the spline laws'
/// precondition), translations within 100.
fn key_walks(seed: u64) -> impl Iterator<Item = [RigTForm; 4]> {
    let mut d = Draws::new(seed);
    (0..DRAWS).map(move |_| {
        let mut r = d.unit_quat();
        core::array::from_fn(|_| {
            let key = RigTForm::new(d.vec3(100.0), r);
            r = (Quat::from_axis_angle(d.vec3(1.0), d.uniform(0.0, 1.5)) * r).normalize();
            key
        })
    })
}

const ALPHAS: [f32; 9] = [0.0, 0.25, 0.5, 1.0, -2.0, 3.0, 1e-30, 1e30, f32::MAX];

/// The largest `pow` and `slerp` angle errors per radian turned, and the
/// largest `|norm - 1|`, over random unit inputs and alphas in [-2, 3].
struct Accuracy {
    pow: f64,
    slerp: f64,
    norm: f64,
}

fn measure_accuracy() -> Accuracy {
    let mut d = Draws::new(99);
    let mut worst = Accuracy {
        pow: 0.0,
        slerp: 0.0,
        norm: 0.0,
    };
    for _ in 0..DRAWS {
        let (a, b) = (d.unit_quat(), d.unit_quat());
        let alpha = d.uniform(-2.0, 3.0);
        let (a64, b64) = (Quat64::from(a), Quat64::from(b));
        let turn = |angle: f64| (f64::from(alpha) * angle).abs().max(1.0);

        let p = a.pow(alpha);
        let p64 = a64.pow(alpha.into());
        let half_angle = libm::atan2(
            libm::sqrt(a64.x * a64.x + a64.y * a64.y + a64.z * a64.z),
            a64.w,
        );
        worst.pow = worst
            .pow
            .max(Quat64::angle_between(p.into(), p64) / turn(2.0 * half_angle));

        let s = a.slerp(b, alpha);
        let s64 = Quat64::slerp(a64, b64, alpha.into());
        let theta = Quat64::angle_between(a64, b64);
        worst.slerp = worst
            .slerp
            .max(Quat64::angle_between(s.into(), s64) / turn(theta));

        for q in [p, s, a * b] {
            let n = libm::sqrt((Quat64::from(q) * Quat64::from(q).conj()).w);
            worst.norm = worst.norm.max(libm::fabs(n - 1.0));
        }
    }
    worst
}

fn bounded(law: &'static str, measured: f64, bound: f32) -> Result<u32, Violation> {
    if measured <= f64::from(bound) {
        Ok(DRAWS)
    } else {
        Err(Violation {
            law,
            measured,
            bound: bound.into(),
        })
    }
}

#[entry]
fn main() -> ! {
    let mut t = Tally::default();
    hprintln!("rigtform on-target tests");

    t.check("product_norm_is_multiplicative", || {
        each(unit_pairs(1), |(a, b)| {
            laws::product_norm_is_multiplicative(a, b)
        })
    });
    t.check("rotation_preserves_length", || {
        let mut d = Draws::new(2);
        each(0..DRAWS, |_| {
            laws::rotation_preserves_length(d.unit_quat(), d.vec3(1e3))
        })
    });
    t.check("normalize_is_unit (edge grid)", || {
        let zero = Quat::from_wxyz(0.0, 0.0, 0.0, 0.0);
        // Plus one made of subnormals only, whose squares underflow.
        let tiny = Quat::from_wxyz(1e-45, -1e-45, 0.0, 1e-40);
        each(
            some_edge_quats()
                .filter(|q| q.is_finite() && *q != zero)
                .chain([tiny]),
            laws::normalize_is_unit,
        )
    });
    t.check("pow_is_unit (edge grid x alphas)", || {
        each(
            some_edge_quats()
                .filter(|q| q.is_finite())
                .flat_map(|q| ALPHAS.map(|alpha| (q, alpha))),
            |(q, alpha)| laws::pow_is_unit(q, alpha),
        )
    });
    t.check("pow_of_non_finite_is_nan", || {
        each(
            some_edge_quats()
                .filter(|q| !q.is_finite())
                .map(|q| (q, 0.5))
                .chain(finite_edges().map(|w| (Quat::from_wxyz(w, 0.0, 1.0, 0.0), f32::NAN))),
            |(q, alpha)| laws::pow_of_non_finite_is_nan(q, alpha),
        )
    });
    t.check("slerp_is_unit (random and degenerate pairs)", || {
        each(
            unit_pairs(3)
                .chain(degenerate_pairs(4))
                .flat_map(|(a, b)| ALPHAS.map(|alpha| (a, b, alpha))),
            |(a, b, alpha)| laws::slerp_is_unit(a, b, alpha),
        )
    });
    t.check("slerp_is_exact_at_zero", || {
        each(unit_pairs(5).chain(degenerate_pairs(6)), |(a, b)| {
            laws::slerp_is_exact_at_zero(a, b)
        })
    });
    t.check("slerp_reaches_the_rotation_of_b_at_one", || {
        each(unit_pairs(24).chain(degenerate_pairs(25)), |(a, b)| {
            laws::slerp_reaches_the_rotation_of_b_at_one(a, b)
        })
    });
    t.check("slerp_turns_by_alpha_times_the_angle", || {
        let mut d = Draws::new(7);
        each(unit_pairs(8).chain(degenerate_pairs(9)), |(a, b)| {
            laws::slerp_turns_by_alpha_times_the_angle(a, b, d.uniform(0.0, 1.0))
        })
    });
    t.check("nlerp_is_unit", || {
        let mut d = Draws::new(10);
        each(unit_pairs(11).chain(degenerate_pairs(12)), |(a, b)| {
            laws::nlerp_is_unit(a, b, d.uniform(0.0, 1.0))
        })
    });
    t.check("blend_is_unit_or_identity", || {
        let mut d = Draws::new(13);
        each(unit_pairs(14), |(a, b)| {
            let c = d.unit_quat();
            let w = [
                d.uniform(-1.0, 2.0),
                d.uniform(0.0, 1.0),
                d.uniform(-3.0, 3.0),
            ];
            laws::blend_is_unit_or_identity(&[(a, w[0]), (b, w[1]), (c, w[2])])
        })
    });
    t.check("inverse_is_an_involution (edge grid)", || {
        each(some_edge_quats(), laws::inverse_is_an_involution)
    });
    t.check(
        "cn_gives_non_negative_w_and_the_same_rotation (edge grid)",
        || {
            each(
                some_edge_quats(),
                laws::cn_gives_non_negative_w_and_the_same_rotation,
            )
        },
    );
    t.check("product_with_inverse_is_real", || {
        each(unit_pairs(15), |(a, _)| {
            laws::product_with_inverse_is_real(a)
        })
    });
    t.check("rigid_product_with_inverse_is_identity", || {
        each(rig_tforms(16), laws::rigid_product_with_inverse_is_identity)
    });
    t.check("rigid_inverse_is_an_involution", || {
        each(rig_tforms(17), laws::rigid_inverse_is_an_involution)
    });
    t.check("rigid_inverse_matches_matrix_inverse", || {
        each(rig_tforms(18), laws::rigid_inverse_matches_matrix_inverse)
    });
    t.check("rigid_matrix_moves_points_as_the_transform", || {
        let mut d = Draws::new(19);
        each(rig_tforms(20), |a| {
            let p = d.vec3(100.0);
            laws::rigid_matrix_moves_points_as_the_transform(a, Cvec4::from_point(p))?;
            laws::rigid_matrix_moves_points_as_the_transform(a, Cvec4::from_vector(p))
        })
    });
    t.check("interpolate_is_exact_at_zero", || {
        let mut b = rig_tforms(21);
        each(rig_tforms(22), |a| {
            laws::interpolate_is_exact_at_zero(a, b.next().unwrap_or(RigTForm::IDENTITY))
        })
    });
    t.check(
        "slerp_slice_is_slerp_bit_for_bit (8 pairs per slice)",
        || {
            let (mut units, mut edges) = (unit_pairs(24), degenerate_pairs(25));
            each(0..DRAWS / 8, |i| {
                let pairs: [(Quat, Quat); 8] = core::array::from_fn(|k| {
                    let pair = if k % 2 == 0 {
                        units.next()
                    } else {
                        edges.next()
                    };
                    pair.unwrap_or((Quat::IDENTITY, Quat::IDENTITY))
                });
                let alpha = ALPHAS
                    .get(i as usize % ALPHAS.len())
                    .copied()
                    .unwrap_or(0.5);
                laws::slerp_slice_is_slerp_bit_for_bit(
                    &pairs.map(|p| p.0),
                    &pairs.map(|p| p.1),
                    alpha,
                )
            })
        },
    );
    t.check(
        "interpolate_slice_is_interpolate_bit_for_bit (8 per slice)",
        || {
            let (mut starts, mut ends) = (rig_tforms(26), rig_tforms(27));
            each(0..DRAWS / 8, |i| {
                let starts: [RigTForm; 8] =
                    core::array::from_fn(|_| starts.next().unwrap_or(RigTForm::IDENTITY));
                let ends: [RigTForm; 8] =
                    core::array::from_fn(|_| ends.next().unwrap_or(RigTForm::IDENTITY));
                let alpha = ALPHAS
                    .get(i as usize % ALPHAS.len())
                    .copied()
                    .unwrap_or(0.5);
                laws::interpolate_slice_is_interpolate_bit_for_bit(&starts, &ends, alpha)
            })
        },
    );
    t.check(
        "matrix_inverse_is_none_or_finite (random bits and edges)",
        || {
            let mut d = Draws::new(23);
            each(0..DRAWS, |i| {
                let m: [f32; 16] = core::array::from_fn(|_| d.f32_mixed());
                let edge = EDGE_F32
                    .get(i as usize % EDGE_F32.len())
                    .copied()
                    .unwrap_or(0.0);
                laws::matrix_inverse_is_none_or_finite(Matrix4::from_cols_array(&m))?;
                laws::matrix_inverse_is_none_or_finite(Matrix4::from_scale(Cvec3::new(
                    edge, 1.0, 2.0,
                )))
            })
        },
    );

    t.check("catmull_rom_is_the_key_at_and_beyond_each_key", || {
        let mut others = unit_pairs(24);
        each(some_edge_quats(), |q| {
            let (a, b) = others.next().unwrap_or((Quat::IDENTITY, Quat::IDENTITY));
            let keys = [a, q, b];
            for t in [f32::NAN, -1.0, 0.0, 1.0, 2.0, 7.0, f32::INFINITY] {
                laws::catmull_rom_is_the_key_at_and_beyond_each_key(&keys, t)?;
            }
            Ok(())
        })
    });
    t.check("catmull_rom_is_unit and left invariant", || {
        let mut d = Draws::new(25);
        each(key_walks(26), |keys| {
            let r = keys.map(|k| k.r);
            let at = d.uniform(-0.5, 3.5);
            laws::catmull_rom_is_unit(&r, at)?;
            laws::catmull_rom_is_left_invariant(d.unit_quat(), r, at)?;
            laws::catmull_rom_of_two_keys_follows_the_slerp_path(r[0], r[1], at - 1.0)
        })
    });
    t.check("catmull_rom_translation_is_the_cubic", || {
        let mut d = Draws::new(27);
        each(key_walks(28), |keys| {
            laws::catmull_rom_translation_is_the_cubic(&keys, d.uniform(-0.5, 3.5))
        })
    });

    t.check("sampler_hits_its_keys and sampler_is_unit", || {
        let mut d = Draws::new(29);
        let kinds = [
            Interpolation::Step,
            Interpolation::Linear,
            Interpolation::CubicSpline,
        ];
        each(key_walks(30), |keys| {
            let r = keys.map(|k| k.r);
            // Key times from 0.5 s, intervals of 0.05 to 2 s.
            let mut time = 0.5;
            let times: [f32; 4] = core::array::from_fn(|_| {
                let now = time;
                time += d.uniform(0.05, 2.0);
                now
            });
            // CUBICSPLINE: tangents of up to 1 per component around the keys.
            let mut tangent = || Quat {
                x: d.uniform(-1.0, 1.0),
                y: d.uniform(-1.0, 1.0),
                z: d.uniform(-1.0, 1.0),
                w: d.uniform(-1.0, 1.0),
            };
            let cubic: [Quat; 12] =
                core::array::from_fn(|i| if i % 3 == 1 { r[i / 3] } else { tangent() });
            let at = d.uniform(0.0, 7.0);
            for kind in kinds {
                let values: &[Quat] = if kind == Interpolation::CubicSpline {
                    &cubic
                } else {
                    &r
                };
                laws::sampler_hits_its_keys(kind, &times, values)?;
                laws::sampler_is_unit(kind, &times, values, at)?;
            }
            laws::step_sampler_is_constant_between_keys(&times, &r, at)
        })
    });

    rigtform_embedded::attitude::check_all(&mut t, DRAWS);

    let accuracy = measure_accuracy();
    hprintln!(
        "accuracy on this core: pow {:.3e} rad per radian turned, slerp {:.3e}, |norm - 1| {:.3e} ({} draws)",
        accuracy.pow,
        accuracy.slerp,
        accuracy.norm,
        DRAWS
    );
    t.check("pow within accuracy::POW_MAX_ANGLE_ERROR", || {
        bounded("pow accuracy", accuracy.pow, POW_MAX_ANGLE_ERROR)
    });
    t.check("slerp within accuracy::SLERP_MAX_ANGLE_ERROR", || {
        bounded("slerp accuracy", accuracy.slerp, SLERP_MAX_ANGLE_ERROR)
    });
    t.check("unit norm within accuracy::UNIT_NORM_ERROR", || {
        bounded("unit norm", accuracy.norm, UNIT_NORM_ERROR)
    });

    t.finish()
}
