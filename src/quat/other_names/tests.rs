//! Each of glam's and nalgebra's names for `Quat`'s methods against the
//! crate it comes from.
#![allow(deprecated)]

use crate::{Cvec3, Quat};
use nalgebra as na;
use rand::{Rng, SeedableRng};

fn na_quat(q: Quat) -> na::UnitQuaternion<f32> {
    na::UnitQuaternion::new_unchecked(na::Quaternion::new(q.w, q.x, q.y, q.z))
}

fn from_na(q: na::UnitQuaternion<f32>) -> Quat {
    Quat::from_wxyz(q.w, q.i, q.j, q.k)
}

fn glam_quat(q: Quat) -> glam::Quat {
    glam::Quat::from_array(q.to_array())
}

/// Each of glam's and nalgebra's names gives what it gives there.
#[test]
fn other_names_mean_what_they_mean_in_glam_and_nalgebra() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(29);
    for _ in 0..10_000 {
        let mut draw = || {
            Quat::from_axis_angle(
                Cvec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                ),
                rng.random_range(-3.0..3.0),
            )
        };
        let (a, b) = (draw(), draw());
        let (ga, gb) = (glam_quat(a), glam_quat(b));
        let (na_a, na_b) = (na_quat(a), na_quat(b));
        assert_eq!(a.conjugate().to_array(), ga.conjugate().to_array());
        assert_eq!(a.inverse().to_array(), ga.inverse().to_array());
        assert!((a.length() - ga.length()).abs() < 1e-6);
        assert!((a.length_squared() - ga.length_squared()).abs() < 1e-6);
        assert!((a.angle_between(b) - ga.angle_between(gb)).abs() < 2e-3);
        assert!((a.angle() - na_a.angle()).abs() < 1e-5);
        assert!(a.rotation_to(b).angle_to(from_na(na_a.rotation_to(&na_b))) < 1e-5);
        assert_eq!(a.xyz().to_array(), ga.xyz().to_array());
        let v = Cvec3::new(1.0, -2.0, 0.5);
        let gv = ga.mul_vec3(glam::Vec3::from_array(v.to_array()));
        assert!((a.mul_vec3(v) - Cvec3::from_array(gv.to_array())).norm() < 1e-5);
        assert!(
            a.mul_quat(b)
                .angle_to(Quat::from_array(ga.mul_quat(gb).to_array()))
                < 1e-6
        );
        let t = rng.random_range(0.0..1.0);
        assert!(
            a.lerp(b, t)
                .angle_to(Quat::from_array(ga.lerp(gb, t).to_array()))
                < 1e-5
        );
        assert!(a.powf(t).angle_to(from_na(na_a.powf(t))) < 1e-5);
        let (roll, pitch, yaw) = (
            rng.random_range(-3.0..3.0),
            rng.random_range(-1.5..1.5),
            rng.random_range(-3.0..3.0),
        );
        let ours = Quat::from_euler_angles(roll, pitch, yaw);
        let theirs = na::UnitQuaternion::from_euler_angles(roll, pitch, yaw);
        assert!(ours.angle_to(from_na(theirs)) < 1e-5);
        let (r, p, y) = ours.euler_angles();
        let (nr, np, ny) = theirs.euler_angles();
        assert!((r - nr).abs() < 1e-3 && (p - np).abs() < 1e-3 && (y - ny).abs() < 1e-3);
        let w = Cvec3::new(-0.5, 2.0, 0.25);
        let nw = na::Vector3::new(w.x, w.y, w.z);
        let close = |u: Cvec3, v: na::Vector3<f32>| (u - Cvec3::new(v.x, v.y, v.z)).norm() < 1e-5;
        assert!(close(a.transform_vector(w), na_a.transform_vector(&nw)));
        assert!(close(
            a.inverse_transform_vector(w),
            na_a.inverse_transform_vector(&nw)
        ));
        let np = na::Point3::new(w.x, w.y, w.z);
        assert!(close(
            a.transform_point(w),
            na_a.transform_point(&np).coords
        ));
        assert!(close(
            a.inverse_transform_point(w),
            na_a.inverse_transform_point(&np).coords
        ));
        let up = Cvec3::new(0.1, 1.0, -0.2);
        if v.normalize().cross(up.normalize()).norm() > 0.1 {
            let (nv, nu) = (
                na::Vector3::new(v.x, v.y, v.z),
                na::Vector3::new(up.x, up.y, up.z),
            );
            let theirs = from_na(na::UnitQuaternion::face_towards(&nv, &nu));
            assert!(Quat::face_towards(v, up).angle_to(theirs) < 1e-5);
            let theirs = from_na(na::UnitQuaternion::look_at_rh(&nv, &nu));
            assert!(Quat::look_at_rh(v, up).angle_to(theirs) < 1e-5);
        }
        assert_eq!(a.scaled_axis(), a.to_scaled_axis());
        assert!(close(a.scaled_axis(), na_a.scaled_axis()));
    }
    assert_eq!(Quat::identity().to_array(), glam::Quat::IDENTITY.to_array());
    let mut rng = rand::rngs::StdRng::seed_from_u64(34);
    for _ in 0..10_000 {
        let mut v = || {
            Cvec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
            .normalize()
        };
        let (from, to) = (v(), v());
        let ours = Quat::from_rotation_arc_colinear(from, to);
        let theirs = glam::Quat::from_rotation_arc_colinear(
            glam::Vec3::from_array(from.to_array()),
            glam::Vec3::from_array(to.to_array()),
        );
        assert!(ours.angle_to(Quat::from_array(theirs.to_array())) < 1e-4);
        assert!(ours.angle() <= core::f32::consts::FRAC_PI_2 + 1e-6);
        let angle = rng.random_range(0.0..0.01f32);
        let q = Quat::from_axis_angle(from, angle);
        let g = glam::Quat::from_array(q.to_array());
        if (angle - 0.002_847_144_6).abs() > 1e-4 {
            assert_eq!(q.is_near_identity(), g.is_near_identity(), "{angle}");
        }
        assert!((q.length_recip() - g.length_recip()).abs() < 1e-6);
    }
}

/// nalgebra's accessors and unit wrapper's names, and glam's
/// `from_rotation_axes`, give what they give there.
#[test]
fn nalgebra_accessors_and_glams_rotation_axes_mean_what_they_mean_there() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(43);
    for _ in 0..10_000 {
        let q = crate::test_draws::unit_quat(&mut rng);
        let theirs = na_quat(q);
        let na_axis = theirs.axis().map(|a| Cvec3::new(a.x, a.y, a.z));
        let axis = q.axis().expect("a random rotation has an axis");
        assert!((axis - na_axis.expect("and nalgebra finds it")).norm() < 1e-6);
        assert_eq!((-q).axis(), q.axis());
        assert!((q.angle() - theirs.angle()).abs() < 1e-5);
        let m = crate::Matrix3::from_quat(q);
        let [x, y, z] = m.cols;
        let glams = glam::Quat::from_rotation_axes(
            glam::Vec3::from_array(x.to_array()),
            glam::Vec3::from_array(y.to_array()),
            glam::Vec3::from_array(z.to_array()),
        );
        let ours = Quat::from_rotation_axes(x, y, z);
        assert_eq!(ours, Quat::from_mat3(m));
        assert!(ours.angle_to(Quat::from_array(glams.to_array())) < 1e-5);
        let scaled = q * rng.random_range(0.1..10.0f32);
        let na_scaled = na::Quaternion::new(scaled.w, scaled.x, scaled.y, scaled.z);
        let normalized = from_na(na::UnitQuaternion::new_normalize(na_scaled));
        assert!((Quat::new_normalize(scaled) - normalized).norm() < 1e-6);
        let mut renormalized = scaled;
        let mut na_renormalized = na::Unit::new_unchecked(na_scaled);
        let norm = renormalized.renormalize();
        assert!((norm - na_renormalized.renormalize()).abs() <= 1e-6 * norm);
        assert_eq!(renormalized, scaled.normalize());
        assert!((renormalized - from_na(na_renormalized)).norm() < 1e-6);
        assert_eq!(
            q.imag().to_array(),
            [theirs.imag().x, theirs.imag().y, theirs.imag().z]
        );
        assert_eq!(q.scalar(), theirs.scalar());
        assert_eq!(*q.quaternion(), from_na(theirs));
        assert_eq!(Quat::new_unchecked(q).into_inner(), from_na(theirs));
    }
    assert_eq!(Quat::IDENTITY.axis(), None);
    assert!(na_quat(Quat::IDENTITY).axis().is_none());
    assert_eq!(Quat::NAN.axis(), None);
}
