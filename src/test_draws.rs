//! What the unit tests draw: how many cases, and random unit quaternions.

use rand::Rng;

use crate::Quat;

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
