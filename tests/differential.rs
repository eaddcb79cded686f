//! Differential test against an f64 reference: nalgebra in f64 for products,
//! rotations and rotation matrices; the notes' formulas evaluated in f64
//! (`testkit::pow64`, `testkit::slerp64`) for the power operator and slerp.
//!
//! Each test draws many random inputs, tracks the largest error, prints it
//! (`cargo test --test differential -- --nocapture`) and asserts that it
//! stays within the constant of `rigtform::accuracy` that the docs quote.

use rigtform_testkit as testkit;

use nalgebra as na;
use rigtform::accuracy;
use rigtform::{Cvec3, EulerRot, Matrix3, Matrix4, Quat};
use rigtform_proofs::reference::leibniz_expansion;
use testkit::{angle_error, draw_count, slerp64, to_f64, Draws, Worst};

fn norm_error(q: Quat) -> f64 {
    (to_f64(q).norm() - 1.0).abs()
}

#[test]
fn product_is_within_its_bounds() {
    let mut draws = Draws::new(1);
    let mut angle = Worst::new("a * b: angle error (rad)");
    let mut norm = Worst::new("a * b: | |a b| / (|a| |b|) - 1 |");
    for _ in 0..draw_count() {
        let (a, b) = (draws.unit_quat(), draws.unit_quat());
        let got = a * b;
        angle.see(angle_error(got, to_f64(a) * to_f64(b)), || {
            format!("{a:?} {b:?}")
        });
        // The norm the product adds: relative to the inputs' norms, which
        // carry through it (UNIT_NORM_ERROR's doc).
        let own = to_f64(got).norm() / (to_f64(a).norm() * to_f64(b).norm());
        norm.see((own - 1.0).abs(), || format!("{a:?} {b:?}"));
    }
    angle.check(accuracy::MUL_MAX_ANGLE_ERROR);
    norm.check(accuracy::UNIT_NORM_ERROR);
}

#[test]
fn rotation_is_within_its_bound() {
    let mut draws = Draws::new(2);
    let mut worst = Worst::new("q * v: error / |v|");
    for _ in 0..draw_count() {
        let q = draws.unit_quat();
        let v = draws.unit_vec64() * draws.uniform(1e-3, 1e3);
        let v = Cvec3::new(v.x as f32, v.y as f32, v.z as f32);
        let want = na::UnitQuaternion::new_normalize(to_f64(q)) * testkit::vec_to_f64(v);
        let got = testkit::vec_to_f64(q * v);
        worst.see((got - want).norm() / testkit::vec_to_f64(v).norm(), || {
            format!("{q:?} {v:?}")
        });
    }
    worst.check(accuracy::ROTATE_MAX_REL_ERROR);
}

#[test]
fn pow_is_within_its_bounds() {
    let mut draws = Draws::new(3);
    let mut angle = Worst::new("q.pow(alpha): angle error / max(1, turn)");
    let mut norm = Worst::new("q.pow(alpha): |norm - 1|");
    for i in 0..draw_count() {
        let q = draws.unit_quat();
        let alpha = match i % 8 {
            0 => 0.0,
            1 => 1.0,
            2 => 0.5,
            _ => draws.uniform(-2.0, 3.0) as f32,
        };
        let got = q.pow(alpha);
        let q64 = to_f64(q).normalize();
        let want = testkit::pow64(q64, alpha as f64);
        // The documented bound is per radian turned (at least one radian):
        // the f32 rounding of alpha phi grows with it.
        let turned = (alpha as f64 * 2.0 * q64.imag().norm().atan2(q64.w)).abs();
        angle.see(angle_error(got, want) / turned.max(1.0), || {
            format!("{q:?} {alpha}")
        });
        norm.see(norm_error(got), || format!("{q:?} {alpha}"));
    }
    angle.check(accuracy::POW_MAX_ANGLE_ERROR);
    norm.check(accuracy::UNIT_NORM_ERROR);
}

#[test]
fn to_axis_angle_is_within_its_bound() {
    let mut draws = Draws::new(4);
    let mut worst = Worst::new("to_axis_angle: angle error");
    for _ in 0..draw_count() {
        let q = draws.unit_quat();
        let q64 = to_f64(q);
        let want = 2.0 * q64.imag().norm().atan2(q64.w.abs());
        let (axis, angle) = q.to_axis_angle();
        let axis_err = (testkit::vec_to_f64(axis) - q64.imag().normalize() * q64.w.signum()).norm();
        worst.see(
            (angle as f64 - want).abs().max(axis_err * want.min(1.0)),
            || format!("{q:?}"),
        );
    }
    worst.check(accuracy::POW_MAX_ANGLE_ERROR);
}

/// How the second slerp endpoint is drawn from the first.
#[derive(Clone, Copy, Debug)]
enum Pair {
    Random,
    Identical,
    Apart(f64),
    Antipodal,
}

fn slerp_class(name: &'static str, pair: Pair, seed: u64) -> (Worst, Worst) {
    let mut draws = Draws::new(seed);
    let mut worst = Worst::new(name);
    let mut norm = Worst::new("  ... |norm - 1|");
    for _ in 0..draw_count() / 4 {
        let a64 = draws.unit_quat64();
        let b64 = match pair {
            Pair::Random => draws.unit_quat64(),
            Pair::Identical => a64,
            Pair::Antipodal => -a64,
            Pair::Apart(angle) => {
                let axis = na::Unit::new_normalize(draws.unit_vec64());
                *na::UnitQuaternion::from_axis_angle(&axis, angle).as_ref() * a64
            }
        };
        let (a, b) = (testkit::to_f32(a64), testkit::to_f32(b64));
        let alpha = draws.uniform(-1.0, 2.0) as f32;
        let got = a.slerp(b, alpha);
        let want = slerp64(to_f64(a), to_f64(b), alpha as f64);
        assert!(got.is_finite(), "{name}: {a:?} {b:?} {alpha}");
        let turned = alpha.abs() as f64 * testkit::rotation_angle64(to_f64(a), to_f64(b));
        worst.see(angle_error(got, want) / turned.max(1.0), || {
            format!("{a:?} {b:?} {alpha}")
        });
        norm.see(norm_error(got), || format!("{a:?} {b:?} {alpha}"));
    }
    (worst, norm)
}

#[test]
fn slerp_is_within_its_bound_on_every_edge_class() {
    let classes = [
        (
            "slerp, random pairs: angle error / max(1, turn)",
            Pair::Random,
        ),
        ("slerp, identical", Pair::Identical),
        ("slerp, 1e-6 rad apart", Pair::Apart(1e-6)),
        ("slerp, 1e-3 rad apart", Pair::Apart(1e-3)),
        (
            "slerp, pi - 1e-4 rad apart",
            Pair::Apart(core::f64::consts::PI - 1e-4),
        ),
        ("slerp, antipodal (q, -q)", Pair::Antipodal),
    ];
    for (seed, (name, pair)) in classes.into_iter().enumerate() {
        let (angle, norm) = slerp_class(name, pair, 10 + seed as u64);
        angle.check(accuracy::SLERP_MAX_ANGLE_ERROR);
        norm.check(accuracy::UNIT_NORM_ERROR);
    }
}

#[test]
fn slerp_of_rotations_exactly_pi_apart_is_finite_unit_and_halfway_at_the_middle() {
    // Both ways round are equally short; either is right, so compare the
    // angle travelled rather than the rotation.
    let mut draws = Draws::new(20);
    let mut worst = Worst::new("slerp, pi apart: angle travelled error / turn");
    for _ in 0..draw_count() / 4 {
        let a = draws.unit_quat();
        let axis = draws.unit_vec64();
        let b = Quat::from_wxyz(0.0, axis.x as f32, axis.y as f32, axis.z as f32) * a;
        let alpha = draws.uniform(0.0, 1.0) as f32;
        let got = a.slerp(b, alpha);
        assert!(got.is_finite());
        let travelled = a.angle_to(got) as f64;
        let exact = testkit::rotation_angle64(to_f64(a), to_f64(b));
        let turned = (alpha as f64 * exact).max(1.0);
        worst.see(
            ((travelled - alpha as f64 * exact).abs() / turned).max(norm_error(got)),
            || format!("{a:?} {b:?} {alpha}"),
        );
    }
    worst.check(accuracy::SLERP_MAX_ANGLE_ERROR);
}

#[test]
fn rotation_matrix_is_within_its_bound() {
    let mut draws = Draws::new(5);
    let mut worst = Worst::new("Matrix4::from_quat: entry error");
    for _ in 0..draw_count() {
        let q = draws.unit_quat();
        let want = na::UnitQuaternion::new_normalize(to_f64(q)).to_rotation_matrix();
        let got = Matrix4::from_quat(q).to_cols_array();
        let mut err: f64 = 0.0;
        for c in 0..3 {
            for r in 0..3 {
                err = err.max((got[4 * c + r] as f64 - want[(r, c)]).abs());
            }
        }
        worst.see(err, || format!("{q:?}"));
    }
    worst.check(accuracy::MATRIX_ENTRY_ERROR);
}

#[test]
fn normalize_is_within_its_bound_from_subnormal_to_huge() {
    let mut draws = Draws::new(6);
    let mut worst = Worst::new("normalize (1e-44 to 1e38): |norm - 1|");
    let mut ulps = Worst::new("Quat::norm (1e-44 to 1e38): error in ulps");
    for _ in 0..draw_count() {
        let scale = 10f64.powf(draws.uniform(-44.0, 38.0));
        let q = [(); 4].map(|_| (draws.uniform(-1.0, 1.0) * scale) as f32);
        let q = Quat::from_wxyz(q[0], q[1], q[2], q[3]);
        let exact = to_f64(q).norm();
        let ulp = {
            let n = exact as f32;
            (f32::from_bits(n.to_bits() + 1) - n) as f64
        };
        ulps.see((q.norm() as f64 - exact).abs() / ulp, || format!("{q:?}"));
        if let Some(n) = q.try_normalize() {
            worst.see(norm_error(n), || format!("{q:?}"));
        } else {
            assert_eq!(
                q,
                Quat::from_wxyz(0.0, 0.0, 0.0, 0.0),
                "only zero has no direction"
            );
        }
    }
    worst.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
    ulps.check(2.0); // the 2 ulp that Quat::norm and Cvec3::norm document
}

#[test]
fn inverse_of_general_matrices_is_within_its_bound() {
    // Random 4x4 matrices with every entry in [-1, 1] (projective ones, not
    // only affine) whose expansion cancels by at most 2^12 (the bound's
    // domain), against nalgebra in f64. Each entry's error is relative to
    // `(Ac + |C| T / |det|) / |det|`: `C` its cofactor, `Ac` the cofactor's
    // six products' magnitudes, `T` the determinant's 24; the
    // determinant's is relative to `T`.
    let mut draws = Draws::new(7);
    let mut worst = Worst::new("Matrix4::inverse: error per entry / (Ac + |C| T / |det|) / |det|");
    let mut det = Worst::new("Matrix4::determinant: error / sum of the expansion's terms");
    let mut tested = 0;
    for _ in 0..draw_count() / 4 {
        let m: [f32; 16] = core::array::from_fn(|_| draws.uniform(-1.0, 1.0) as f32);
        let m64 = na::Matrix4::from_column_slice(&m.map(f64::from));
        let (det64, total) = (m64.determinant(), leibniz_expansion(&m.map(f64::from), 4).1);
        if total > 4096.0 * det64.abs() {
            continue;
        }
        let got_det = Matrix4::from_cols_array(&m).determinant() as f64;
        det.see((got_det - det64).abs() / total, || format!("{m:?}"));
        let got = Matrix4::from_cols_array(&m)
            .inverse()
            .expect("a matrix within the bound's domain has an inverse")
            .to_cols_array();
        let mut error = 0f64;
        for row in 0..4 {
            for col in 0..4 {
                // Entry (row, col) of the inverse: the cofactor of entry
                // (col, row) over the determinant.
                let sub = m64.remove_row(col).remove_column(row);
                let sign = if (row + col) % 2 == 0 { 1.0 } else { -1.0 };
                let cofactor = sign * sub.determinant();
                let scale = (leibniz_expansion(sub.as_slice(), 3).1
                    + cofactor.abs() * total / det64.abs())
                    / det64.abs();
                let e = (f64::from(got[4 * col + row]) - cofactor / det64).abs();
                error = error.max(e / scale);
            }
        }
        worst.see(error, || format!("{m:?}"));
        tested += 1;
    }
    assert!(
        tested > draw_count() / 8,
        "too few draws within the domain: {tested}"
    );
    det.check(accuracy::DETERMINANT_MAX_REL_ERROR);
    worst.check(accuracy::INVERSE_MAX_REL_ERROR);
}

#[test]
fn inverse_and_determinant_of_3x3_matrices_are_within_their_bounds() {
    // Random 3x3 matrices with every entry in [-1, 1] whose condition is at
    // most 1e4, against nalgebra in f64. The determinant's error is relative
    // to the sum of its expansion's magnitudes (the bound's measure, which
    // needs no condition). Each entry of the inverse, where the expansion
    // cancels by at most 2^12 (the bound's domain), is relative to its
    // minor's products and the determinant's error carried through 1 / det.
    let mut draws = Draws::new(27);
    let mut worst = Worst::new("Matrix3::inverse: error per entry / (Am + |M| T / |det|) / |det|");
    let mut det = Worst::new("Matrix3::determinant: error / sum of the expansion's terms");
    let mut tested = 0;
    for _ in 0..draw_count() {
        let m: [f32; 9] = core::array::from_fn(|_| draws.uniform(-1.0, 1.0) as f32);
        let c = m.map(f64::from);
        let m64 = na::Matrix3::from_column_slice(&c);
        let Some(inv64) = m64.try_inverse() else {
            continue;
        };
        let cond = m64.norm() * inv64.norm();
        if cond > 1e4 {
            continue;
        }
        tested += 1;
        let matrix = Matrix3::from_cols_array(&m);
        let (det64, total) = (m64.determinant(), leibniz_expansion(&c, 3).1);
        let got_det = f64::from(matrix.determinant());
        det.see((got_det - det64).abs() / total, || format!("{m:?}"));
        let inv = matrix
            .inverse()
            .expect("a matrix of condition <= 1e4 has an inverse");
        let got = inv.to_cols_array();
        if total <= 4096.0 * det64.abs() {
            let mut error = 0f64;
            for (i, j) in (0..3).flat_map(|i| (0..3).map(move |j| (i, j))) {
                let (p, q) = (3 * ((i + 1) % 3), 3 * ((i + 2) % 3));
                let (k, l) = ((j + 1) % 3, (j + 2) % 3);
                let minor = c[p + k] * c[q + l] - c[p + l] * c[q + k];
                let am = (c[p + k] * c[q + l]).abs() + (c[p + l] * c[q + k]).abs();
                let scale = (am + minor.abs() * total / det64.abs()) / det64.abs();
                let e = (f64::from(got[3 * j + i]) - minor / det64).abs();
                error = error.max(e / scale);
            }
            worst.see(error, || format!("{m:?}"));
        }
        // glam's inverse (cofactors too) agrees, within both errors.
        let g = glam::Mat3::from_cols_array(&m).inverse();
        let size = g.to_cols_array().iter().fold(0f32, |a, b| a.max(b.abs()));
        let ours = glam::Mat3::from_cols_array(&got);
        assert!(g.abs_diff_eq(ours, 1e-5 * cond as f32 * size), "{m:?}");
    }
    assert!(
        tested > draw_count() / 2,
        "too few draws of condition <= 1e4: {tested}"
    );
    det.check(accuracy::MATRIX3_DETERMINANT_MAX_REL_ERROR);
    worst.check(accuracy::MATRIX3_INVERSE_MAX_REL_ERROR);
}

#[test]
fn catmull_rom_is_within_its_bound() {
    let mut draws = Draws::new(30);
    let mut angle = Worst::new("Quat::catmull_rom, 5 keys: angle error (rad)");
    let mut norm = Worst::new("  ... |norm - 1|");
    for _ in 0..draw_count() {
        let keys: Vec<Quat> = draws.key_walk(5).iter().map(|k| k.r).collect();
        let t = draws.uniform(0.0, 4.0) as f32;
        let got = Quat::catmull_rom(&keys, t);
        let keys64: Vec<_> = keys.iter().map(|&q| to_f64(q)).collect();
        let want = testkit::catmull_rom::catmull_rom64(&keys64, t as f64);
        angle.see(angle_error(got, want), || format!("{keys:?} {t}"));
        norm.see(norm_error(got), || format!("{keys:?} {t}"));
    }
    angle.check(accuracy::CATMULL_ROM_MAX_ANGLE_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}

#[test]
fn euler_angles_are_within_their_bound_at_gimbal_lock_too() {
    use core::f64::consts::PI;
    let mut draws = Draws::new(8);
    let mut from = Worst::new("Quat::from_euler: angle error");
    let mut norm = Worst::new("Quat::from_euler: |norm - 1|");
    let mut to = Worst::new("Quat::to_euler: angle error of the angles' rotation");
    for i in 0..draw_count() {
        let order = EulerRot::ALL[i % EulerRot::ALL.len()];
        let a = draws.uniform(-PI, PI) as f32;
        let c = draws.uniform(-PI, PI) as f32;
        // One draw in four at or within a hair of gimbal lock: the ends of
        // the middle angle's range (+-pi/2 for Tait-Bryan orders, 0 and
        // +-pi for proper Euler orders).
        let (lo, hi) = order.middle_angle_range();
        let (lo, hi) = (f64::from(lo), f64::from(hi));
        let b = match (i / EulerRot::ALL.len()) % 8 {
            0 => lo as f32,
            1 => hi as f32,
            2 => (lo + draws.uniform(0.0, 1e-4)) as f32,
            3 => (hi - draws.uniform(0.0, 1e-4)) as f32,
            _ => draws.uniform(lo, hi) as f32,
        };
        let got = Quat::from_euler(order, a, b, c);
        let want = testkit::euler64(order, a as f64, b as f64, c as f64);
        from.see(angle_error(got, want), || format!("{order:?} {a} {b} {c}"));
        norm.see(norm_error(got), || format!("{order:?} {a} {b} {c}"));

        // to_euler of a random rotation, and of the rotation just built.
        for q in [draws.unit_quat(), got] {
            let (x, y, z) = q.to_euler(order);
            let back = testkit::euler64(order, x as f64, y as f64, z as f64);
            to.see(angle_error(q, back), || format!("{order:?} {q:?}"));
        }
    }
    from.check(accuracy::EULER_MAX_ANGLE_ERROR);
    norm.check(accuracy::EULER_MAX_ANGLE_ERROR);
    to.check(accuracy::EULER_MAX_ANGLE_ERROR);
}

#[test]
fn from_matrix_is_within_its_bound_at_half_turns_too() {
    let mut draws = Draws::new(9);
    let mut angle = Worst::new("Quat::from_matrix: angle error");
    let mut norm = Worst::new("Quat::from_matrix: |norm - 1|");
    for i in 0..draw_count() {
        let q = match i % 4 {
            // Half turns and near half turns, where the trace form fails.
            0 => Quat::from_axis_angle(
                Cvec3::new(
                    draws.uniform(-1.0, 1.0) as f32,
                    draws.uniform(-1.0, 1.0) as f32,
                    draws.uniform(-1.0, 1.0) as f32,
                ),
                core::f32::consts::PI - draws.uniform(0.0, 1e-3) as f32,
            ),
            _ => draws.unit_quat(),
        };
        let m = Matrix4::from_quat(q).to_cols_array();
        let m64 = na::Matrix3::from_fn(|r, c| m[4 * c + r] as f64);
        // The exact rotation of the f32 entries: the nearest rotation
        // matrix (they are orthonormal to about 1e-7), then its quaternion.
        let guess = na::UnitQuaternion::new_normalize(to_f64(q)).to_rotation_matrix();
        let rot = na::Rotation3::from_matrix_eps(&m64, 1e-15, 100, guess);
        let want = na::UnitQuaternion::from_rotation_matrix(&rot).into_inner();
        let got = Quat::from_matrix(Matrix4::from_cols_array(&m));
        angle.see(angle_error(got, want), || format!("{q:?}"));
        norm.see(norm_error(got), || format!("{q:?}"));
    }
    angle.check(accuracy::FROM_MATRIX_MAX_ANGLE_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}

#[test]
fn rotation_arc_is_within_its_bound_for_opposite_directions_too() {
    let mut draws = Draws::new(10);
    let mut mapped = Worst::new("Quat::from_rotation_arc: |q a - b|");
    let mut short = Worst::new("Quat::from_rotation_arc: angle error (<= 90 deg)");
    let mut norm = Worst::new("Quat::from_rotation_arc: |norm - 1|");
    let f32v = |v: na::Vector3<f64>| Cvec3::new(v.x as f32, v.y as f32, v.z as f32);
    for i in 0..draw_count() {
        let a64 = draws.unit_vec64() * draws.uniform(1e-3, 1e3);
        let b64 = match i % 4 {
            // Nearly opposite, exactly opposite, nearly the same, random.
            0 => -a64 + draws.unit_vec64() * a64.norm() * draws.uniform(0.0, 1e-3),
            1 => -a64 * draws.uniform(1e-3, 1e3),
            2 => a64 + draws.unit_vec64() * a64.norm() * draws.uniform(0.0, 1e-3),
            _ => draws.unit_vec64() * draws.uniform(1e-3, 1e3),
        };
        let (a, b) = (f32v(a64), f32v(b64));
        let q = Quat::from_rotation_arc(a, b);
        let (a64, b64) = (testkit::vec_to_f64(a), testkit::vec_to_f64(b));
        let rotated = na::UnitQuaternion::new_normalize(to_f64(q)) * a64.normalize();
        mapped.see((rotated - b64.normalize()).norm(), || {
            format!("{a:?} {b:?}")
        });
        norm.see(norm_error(q), || format!("{a:?} {b:?}"));
        // The axis a x b is ill-conditioned as the directions approach
        // opposite (at 170 degrees a tilt of 1e-7 in either input already
        // moves it by 6e-7): the angle is compared up to 90 degrees.
        if a64.normalize().dot(&b64.normalize()) >= 0.0 {
            let want = na::UnitQuaternion::rotation_between(&a64, &b64)
                .expect("not opposite")
                .into_inner();
            short.see(angle_error(q, want), || format!("{a:?} {b:?}"));
        }
    }
    short.check(accuracy::ROTATION_ARC_MAX_ERROR);
    mapped.check(accuracy::ROTATION_ARC_MAX_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}

#[test]
fn look_at_is_within_its_bound() {
    let mut draws = Draws::new(11);
    let mut angle = Worst::new("RigTForm::look_at: angle error");
    let mut norm = Worst::new("RigTForm::look_at: |norm - 1|");
    let f32v = |v: na::Vector3<f64>| Cvec3::new(v.x as f32, v.y as f32, v.z as f32);
    for _ in 0..draw_count() {
        let eye = f32v(draws.unit_vec64() * draws.uniform(0.0, 100.0));
        let target = f32v(draws.unit_vec64() * draws.uniform(0.0, 100.0));
        let up = f32v(draws.unit_vec64() * draws.uniform(1e-3, 1e3));
        let got = rigtform::RigTForm::look_at(eye, target, up).r;
        // The exact eye frame of the same f32 points: z back along the line
        // of sight, x = up x z, y = z x x.
        let (eye, target, up) = (
            testkit::vec_to_f64(eye),
            testkit::vec_to_f64(target),
            testkit::vec_to_f64(up),
        );
        let z = (eye - target).normalize();
        let x = up.cross(&z).normalize();
        // The roll is ill-conditioned as `up` nears the line of sight (its
        // error grows as 1 / sin of the angle between them): the bound holds
        // from 0.1 (about 6 degrees) on.
        if up.normalize().cross(&z).norm() < 0.1 {
            continue;
        }
        let y = z.cross(&x);
        let rot = na::Rotation3::from_basis_unchecked(&[x, y, z]);
        let want = na::UnitQuaternion::from_rotation_matrix(&rot).into_inner();
        angle.see(angle_error(got, want), || {
            format!("{eye:?} {target:?} {up:?}")
        });
        norm.see(norm_error(got), || format!("{eye:?} {target:?} {up:?}"));
    }
    angle.check(accuracy::LOOK_AT_MAX_ANGLE_ERROR);
    norm.check(accuracy::NORMALIZE_MAX_NORM_ERROR);
}
