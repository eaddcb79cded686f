//! What the unit tests draw: how many cases, random unit quaternions and
//! rigid body transforms.

use rand::Rng;

use crate::{Cvec3, Quat, RigTForm};

/// 200,000 draws, or `RIGTFORM_DRAWS` (the bounds in `accuracy` were
/// measured with 10,000,000).
pub(crate) fn count() -> usize {
    std::env::var("RIGTFORM_DRAWS")
        .ok()
        .and_then(|d| d.parse().ok())
        .unwrap_or(200_000)
}

/// A random unit quaternion: a point of the cube `[-1, 1]^4` normalized,
/// away from the cube's centre.
pub(crate) fn unit_quat(rng: &mut impl Rng) -> Quat {
    loop {
        let q = Quat::from_wxyz(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        if q.norm_squared() > 0.01 {
            return q.normalize();
        }
    }
}

/// A random rigid body transform: a translation and an axis and angle of
/// components in [-10, 10).
pub(crate) fn rig_tform(rng: &mut impl Rng) -> RigTForm {
    let mut c = || rng.random_range(-10.0f32..10.0);
    let t = Cvec3::new(c(), c(), c());
    let r = Quat::from_axis_angle(Cvec3::new(c(), c(), c()), c());
    RigTForm::new(t, r)
}
