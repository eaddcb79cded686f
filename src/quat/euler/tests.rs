//! The Euler angles' laws: every order against nalgebra's f64 rotations,
//! round trips, gimbal lock and edge values.

use super::*;
use crate::accuracy::EULER_MAX_ANGLE_ERROR;
use core::f32::consts::{FRAC_PI_2, PI};
use rand::{Rng, SeedableRng};

/// Angles and rotations after one way and back, with either backend.
const TOL: f32 = 4.0 * EULER_MAX_ANGLE_ERROR;

/// The rotation about one axis, by the letter of its name.
fn about(letter: u8) -> fn(f32) -> Quat {
    match letter {
        b'X' => Quat::from_rotation_x,
        b'Y' => Quat::from_rotation_y,
        _ => Quat::from_rotation_z,
    }
}

/// The order's three rotations multiplied by hand, read from its name:
/// `R_i(a) R_j(b) R_k(c)` for `IJK`, `R_k(c) R_j(b) R_i(a)` for `IJKEx`.
fn by_hand(order: EulerRot, a: f32, b: f32, c: f32) -> Quat {
    let name = std::format!("{order:?}");
    let n = name.as_bytes();
    let (ra, rb, rc) = (about(n[0])(a), about(n[1])(b), about(n[2])(c));
    if name.ends_with("Ex") {
        rc * rb * ra
    } else {
        ra * rb * rc
    }
}

/// glam's order of the same name.
fn glam_order(order: EulerRot) -> glam::EulerRot {
    use glam::EulerRot as G;
    [
        G::ZYX,
        G::ZXY,
        G::YXZ,
        G::YZX,
        G::XYZ,
        G::XZY,
        G::ZYZ,
        G::ZXZ,
        G::YXY,
        G::YZY,
        G::XYX,
        G::XZX,
        G::ZYXEx,
        G::ZXYEx,
        G::YXZEx,
        G::YZXEx,
        G::XYZEx,
        G::XZYEx,
        G::ZYZEx,
        G::ZXZEx,
        G::YXYEx,
        G::YZYEx,
        G::XYXEx,
        G::XZXEx,
    ][EulerRot::ALL.iter().position(|o| *o == order).unwrap_or(0)]
}

fn to_glam(q: Quat) -> glam::Quat {
    glam::Quat::from_xyzw(q.x, q.y, q.z, q.w)
}

/// `x - y` moved into [-pi, pi] (angles equal up to a whole turn).
fn turn_difference(x: f32, y: f32) -> f32 {
    let d = (x - y).rem_euclid(2.0 * PI);
    if d > PI {
        2.0 * PI - d
    } else {
        d
    }
}

/// Angles `(a, b, c)` with `b` at fraction `t` of the order's range.
fn angles_in_range(order: EulerRot, a: f32, t: f32, c: f32) -> (f32, f32, f32) {
    let (lo, hi) = order.middle_angle_range();
    (a, lo + t * (hi - lo), c)
}

#[test]
fn there_are_glams_24_orders_with_its_names() {
    assert_eq!(EulerRot::ALL.len(), 24);
    for (i, order) in EulerRot::ALL.into_iter().enumerate() {
        assert!(!EulerRot::ALL[..i].contains(&order));
        assert_eq!(
            std::format!("{order:?}"),
            std::format!("{:?}", glam_order(order))
        );
    }
}

#[test]
fn from_euler_is_the_product_of_the_three_axis_rotations_in_order() {
    for order in EulerRot::ALL {
        for (a, b, c) in [(0.3, -0.2, 1.1), (-2.9, 1.5, 0.4), (3.0, -1.0, -3.1)] {
            let want = by_hand(order, a, b, c);
            let got = Quat::from_euler(order, a, b, c);
            assert!(got.angle_to(want) < TOL, "{order:?} {a} {b} {c}");
        }
    }
}

#[test]
fn from_euler_and_to_euler_agree_with_glam_for_every_order() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(26);
    let mut worst = [0f32; 3];
    for order in EulerRot::ALL {
        let g = glam_order(order);
        for _ in 0..20_000 {
            let (a, b, c) = (
                rng.random_range(-PI..=PI),
                rng.random_range(-PI..=PI),
                rng.random_range(-PI..=PI),
            );
            let ours = Quat::from_euler(order, a, b, c);
            let theirs = glam::Quat::from_euler(g, a, b, c);
            // (glam's angle_between is an arccosine, coarse near 0.)
            let from = ours.angle_to(Quat::from_xyzw(theirs.x, theirs.y, theirs.z, theirs.w));
            assert!(
                from < 2e-6f32.max(2.0 * EULER_MAX_ANGLE_ERROR),
                "{order:?} {a} {b} {c}: {from}"
            );
            worst[0] = worst[0].max(from);
            // to_euler of a random rotation: the same angles as glam's
            // where the split of a and c is well-conditioned (the
            // middle angle at least 0.05 rad from the lock).
            let q = Quat::from_xyzw(
                rng.random_range(-1.0..=1.0),
                rng.random_range(-1.0..=1.0),
                rng.random_range(-1.0..=1.0),
                rng.random_range(-1.0..=1.0),
            )
            .normalize();
            let (x, y, z) = q.to_euler(order);
            let (lo, hi) = order.middle_angle_range();
            assert!((-PI..=PI).contains(&x) && (lo..=hi).contains(&y) && (-PI..=PI).contains(&z));
            let back = by_hand(order, x, y, z).angle_to(q);
            assert!(back < TOL, "{order:?} {q:?}: {back}");
            worst[1] = worst[1].max(back);
            if (y - lo).min(hi - y) > 0.05 {
                let (gx, gy, gz) = to_glam(q).to_euler(g);
                let d = turn_difference(x, gx)
                    .max(turn_difference(y, gy))
                    .max(turn_difference(z, gz));
                // (1e-5 rad: the split of a and c 0.05 rad from the
                // lock is 20 times worse conditioned than the rotation.)
                assert!(
                    d < 1e-5,
                    "{order:?} {q:?}: {:?} vs glam {:?}",
                    (x, y, z),
                    (gx, gy, gz)
                );
                worst[2] = worst[2].max(d);
            }
        }
    }
    std::println!(
        "Euler, 24 orders x 20,000: from_euler {:.3e} rad from glam's, to_euler's rotation {:.3e} rad from the input, its angles {:.3e} rad from glam's",
        worst[0], worst[1], worst[2]
    );
}

#[test]
fn to_euler_recovers_angles_in_range_and_is_the_same_for_minus_q() {
    for order in EulerRot::ALL {
        for (a, t, c) in [(0.3, 0.4, 1.1), (-2.9, 0.97, 0.4), (3.0, 0.1, -3.1)] {
            let (a, b, c) = angles_in_range(order, a, t, c);
            let q = Quat::from_euler(order, a, b, c);
            let (x, y, z) = q.to_euler(order);
            assert!(
                (x - a).abs() < TOL && (y - b).abs() < TOL && (z - c).abs() < TOL,
                "{order:?} {a} {b} {c}: {x} {y} {z}"
            );
            assert_eq!((-q).to_euler(order), (x, y, z));
        }
    }
}

#[test]
fn near_gimbal_lock_the_angles_are_finite_and_give_the_same_rotation() {
    for order in EulerRot::ALL {
        let (lo, hi) = order.middle_angle_range();
        for b in [lo, hi, lo + 1e-4, hi - 1e-3] {
            for (a, c) in [(0.4, 0.0), (1.0, -0.7), (-2.0, 3.0)] {
                let q = by_hand(order, a, b, c);
                let (x, y, z) = q.to_euler(order);
                assert!(x.is_finite() && z.is_finite(), "{order:?} {a} {b} {c}");
                assert!((y - b).abs() < 1e-3 + TOL, "{order:?} {a} {b} {c}: {y}");
                assert!(Quat::from_euler(order, x, y, z).angle_to(q) < TOL);
            }
        }
    }
}

#[test]
fn at_gimbal_lock_the_third_angle_is_zero() {
    // (w + y, x + z) = 0 in XYZ coordinates: b = -pi/2 exactly.
    let q = Quat::from_wxyz(0.5, 0.5, -0.5, -0.5);
    let (a, b, c) = q.to_euler(EulerRot::XYZ);
    assert_eq!((b, c), (-FRAC_PI_2, 0.0));
    assert!(Quat::from_euler(EulerRot::XYZ, a, b, c).angle_to(q) < TOL);
    // The same rotation read as yaw, pitch and roll: pitch +pi/2.
    let q = Quat::from_euler(EulerRot::ZYX, 0.0, FRAC_PI_2, 0.0);
    let (_, pitch, roll) = q.to_euler(EulerRot::ZYX);
    assert_eq!(roll, 0.0);
    assert!((pitch - FRAC_PI_2).abs() < TOL);
    // A turn about z alone, read as ZYZ: b = 0, the turn in a; read
    // as ZYZEx, in c (the first angle is the one set to zero).
    let q = Quat::from_rotation_z(0.7);
    let (a, b, c) = q.to_euler(EulerRot::ZYZ);
    assert_eq!((b, c), (0.0, 0.0));
    assert!((a - 0.7).abs() < TOL);
    let (a, b, c) = q.to_euler(EulerRot::ZYZEx);
    assert_eq!((a, b), (0.0, 0.0));
    assert!((c - 0.7).abs() < TOL);
}

#[test]
fn bad_input_gives_documented_results() {
    for order in EulerRot::ALL {
        assert!(Quat::from_euler(order, f32::NAN, 0.0, 0.0).w.is_nan());
        assert!(Quat::from_euler(order, 0.0, 0.0, f32::INFINITY).w.is_nan());
        let (a, b, c) = Quat::NAN.to_euler(order);
        assert!(a.is_nan() && b.is_nan() && c.is_nan());
        assert_eq!(
            Quat::from_wxyz(0.0, 0.0, 0.0, 0.0).to_euler(order),
            (0.0, 0.0, 0.0)
        );
        let (x, y, z) = angles_in_range(order, 0.5, 0.3, -PI / 3.0);
        let huge = Quat::from_euler(order, x, y, z).map(|c| c * 1e38);
        let (a, b, c) = huge.to_euler(order);
        assert!(
            (a - x).abs() < TOL && (b - y).abs() < TOL && (c - z).abs() < TOL,
            "{order:?}"
        );
    }
}
