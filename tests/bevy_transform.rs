//! A Bevy `Transform` (Bevy 0.18, whose glam is 0.30) to a `RigTForm` and
//! back through the `convert-glam030` feature, as a Bevy user writes it:
//! the fields convert with `From`, exactly, and both types then move points
//! and compose alike. Run with
//! `cargo test --features convert-glam030 --test bevy_transform`.

use bevy_math::{Affine3A, Quat as BevyQuat, Vec3};
use bevy_transform::components::Transform;
use rand::{Rng, SeedableRng};
use rigtform::{Cvec3, Quat, RigTForm};

/// The rigid body transform of a Bevy transform without scale.
fn rig_tform(t: Transform) -> RigTForm {
    RigTForm::new(t.translation.into(), t.rotation.into())
}

/// The Bevy transform of a rigid body transform (scale 1).
fn transform(a: RigTForm) -> Transform {
    Transform::from_translation(a.t.into()).with_rotation(a.r.into())
}

fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

/// A random unit rotation, drawn as Bevy's `Quat`, and a translation.
fn random_transform(rng: &mut impl Rng) -> Transform {
    let axis = Vec3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
    )
    .normalize_or(Vec3::Z);
    let rotation = BevyQuat::from_axis_angle(axis, rng.random_range(-3.1..3.1));
    Transform::from_xyz(
        rng.random_range(-50.0..50.0),
        rng.random_range(-50.0..50.0),
        rng.random_range(-50.0..50.0),
    )
    .with_rotation(rotation)
}

#[test]
fn a_transform_goes_to_a_rig_tform_and_back_bit_for_bit() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(30);
    for _ in 0..10_000 {
        let t = random_transform(&mut rng);
        let back = transform(rig_tform(t));
        assert_eq!(bits(back.translation), bits(t.translation));
        assert_eq!(
            back.rotation.to_array().map(f32::to_bits),
            t.rotation.to_array().map(f32::to_bits)
        );
        assert_eq!(bits(back.scale), bits(Vec3::ONE));
    }
}

#[test]
fn both_move_points_and_compose_alike() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(31);
    for _ in 0..10_000 {
        let (t1, t2) = (random_transform(&mut rng), random_transform(&mut rng));
        let (a1, a2) = (rig_tform(t1), rig_tform(t2));
        let p = Vec3::new(
            rng.random_range(-10.0..10.0),
            rng.random_range(-10.0..10.0),
            rng.random_range(-10.0..10.0),
        );
        // Points of up to 60 units: a few f32 ulps of 60 apart.
        let ours = a1.transform_point(p.into());
        assert!((ours - Cvec3::from(t1.transform_point(p))).norm() < 1e-4);
        // Bevy's `t1 * t2` (t2 first) is the notes' `a1 * a2`.
        let composed = t1 * t2;
        let product = a1 * a2;
        assert!((product.t - Cvec3::from(composed.translation)).norm() < 1e-4);
        assert!(product.r.angle_to(Quat::from(composed.rotation)) < 1e-6);
        // The affine map Bevy computes is rigid, and gives the same motion.
        let back = RigTForm::try_from(t1.compute_affine()).unwrap();
        assert!((back.t - a1.t).norm() < 1e-5);
        assert!(back.r.angle_to(a1.r) < 1e-6);
    }
}

#[test]
fn a_scaled_transform_is_not_rigid() {
    let scaled = Transform::from_xyz(1.0, 2.0, 3.0).with_scale(Vec3::splat(2.0));
    let affine: Affine3A = scaled.compute_affine();
    let e = RigTForm::try_from(affine).unwrap_err();
    assert!(e.deviation > rigtform::accuracy::RIGID_TOLERANCE);
}
