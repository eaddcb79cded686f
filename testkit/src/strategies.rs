//! Proptest strategies for the crate's types, with the distributions of
//! [`Draws`](crate::Draws).

use nalgebra as na;
use proptest::prelude::*;
use rigtform::{Cvec3, Quat, RigTForm};

use crate::draws::unit_from_cube;
use crate::reference::to_f32;

/// A unit quaternion uniform over the rotations, rounded to f32.
pub fn unit_quat() -> impl Strategy<Value = Quat> {
    prop::array::uniform4(-1.0f64..1.0)
        .prop_filter_map("inside the unit ball, away from 0", unit_from_cube)
        .prop_map(to_f32)
}

/// A vector with components in [-100, 100].
pub fn vec3() -> impl Strategy<Value = Cvec3> {
    prop::array::uniform3(-100.0f32..100.0).prop_map(|[x, y, z]| Cvec3::new(x, y, z))
}

/// A rigid body transform with a uniform unit rotation.
pub fn rig_tform() -> impl Strategy<Value = RigTForm> {
    (vec3(), unit_quat()).prop_map(|(t, r)| RigTForm::new(t, r))
}

/// `n` keyframes on a random walk, as [`Draws::key_walk`](crate::Draws::key_walk)
/// draws them: the first rotation uniform, each next one turned by up to
/// [`KEY_STEP`](crate::draws::KEY_STEP) rad about a random axis.
pub fn key_walk(n: usize) -> impl Strategy<Value = Vec<RigTForm>> {
    (
        unit_quat(),
        prop::collection::vec((unit_quat(), 0.0..crate::draws::KEY_STEP, vec3()), n),
    )
        .prop_map(|(first, steps)| {
            let mut r = crate::reference::to_f64(first);
            steps
                .into_iter()
                .map(|(axis, angle, t)| {
                    let key = RigTForm::new(t * 0.1, to_f32(r));
                    let axis = na::Unit::new_normalize(na::Vector3::new(
                        axis.x as f64,
                        axis.y as f64,
                        axis.z as f64,
                    ));
                    r = *na::UnitQuaternion::from_axis_angle(&axis, angle).as_ref() * r;
                    key
                })
                .collect()
        })
}

/// Any finite f32 as the Kani stand-in draws it (`rigtform_proofs`'
/// `Draws::f32_mixed`): a third the finite edge values (zeros, subnormals,
/// 1 and its neighbours, `f32::MAX`, ...), a third moderate (exponent in
/// [-20, 20], any sign and mantissa), a third any finite bit pattern.
pub fn mixed_f32() -> impl Strategy<Value = f32> {
    let edges: Vec<f32> = rigtform_proofs::edge::finite_edges().collect();
    prop_oneof![
        prop::sample::select(edges),
        (any::<bool>(), 107u32..=147, 0u32..0x0080_0000).prop_map(
            |(negative, exponent, mantissa)| f32::from_bits(
                u32::from(negative) << 31 | exponent << 23 | mantissa
            )
        ),
        any::<u32>()
            .prop_map(f32::from_bits)
            .prop_filter("finite", |x| x.is_finite()),
    ]
}

/// [`mixed_f32`] of magnitude at most `limit`.
pub fn mixed_within(limit: f32) -> impl Strategy<Value = f32> {
    prop_oneof![
        mixed_f32().prop_filter("within the limit", move |x| x.abs() <= limit),
        -limit..=limit,
    ]
}

/// A quaternion with [`mixed_f32`] components.
pub fn finite_quat() -> impl Strategy<Value = Quat> {
    prop::array::uniform4(mixed_f32()).prop_map(Quat::from_array)
}

/// A quaternion with [`mixed_within`] components.
pub fn quat_within(limit: f32) -> impl Strategy<Value = Quat> {
    prop::array::uniform4(mixed_within(limit)).prop_map(Quat::from_array)
}

/// A vector with [`mixed_within`] components.
pub fn vec_within(limit: f32) -> impl Strategy<Value = Cvec3> {
    prop::array::uniform3(mixed_within(limit)).prop_map(Cvec3::from)
}

/// A unit quaternion as the laws' preconditions mean it: half uniform
/// ([`unit_quat`]), half any finite non-zero quaternion ([`finite_quat`],
/// from subnormal to `f32::MAX` components) normalized, whose rounding is
/// what `normalize` leaves.
pub fn normalized_quat() -> impl Strategy<Value = Quat> {
    prop_oneof![
        unit_quat(),
        finite_quat()
            .prop_filter("not zero", |q| *q != Quat::from_xyzw(0.0, 0.0, 0.0, 0.0))
            .prop_map(Quat::normalize),
    ]
}
