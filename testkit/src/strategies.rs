//! Proptest strategies for the crate's types, with the distributions of
//! [`Draws`](crate::Draws).

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
