//! What a firmware's own Kani proof over `rigtform` looks like: one step of
//! an attitude estimate ([`firmware_step`]), and a harness that proves it
//! never gives a non-finite attitude, with the library's `normalize` and
//! `slerp` replaced by their contracts (`#[kani::stub_verified]`), which
//! the library's own harnesses check (`src/kani_contracts.rs` of
//! `rigtform`). `docs/kani.md` is the guide.
//!
//! The harness is written for
//! `cargo kani -p rigtform-proofs -Z function-contracts -Z stubbing --harness firmware_step::firmware_step_gives_a_finite_attitude`;
//! Kani is not installable on the machines this crate is developed on, so
//! it has not been run, and nothing here is proven. CI compiles it under
//! `cfg(kani)` against the mock of Kani (`.ci/run`'s `kani_mock` stage),
//! and the test below runs the step on random draws.

use rigtform::{Cvec3, Quat};

/// The largest rate the example's gyro reports: 2000 degrees per second,
/// in rad/s.
pub const GYRO_RANGE: f32 = 34.906_586;
/// The longest step the example takes, in seconds (100 Hz).
pub const MAX_DT: f32 = 0.01;

/// One step of an attitude estimate: turn `attitude` by the gyro sample
/// `gyro` (rad/s, in the body frame) over `dt` seconds and renormalize
/// ([`Quat::integrate`]: the exponential map, then `normalize`), then move
/// the fraction `follow` (in [0, 1]) of the way towards `target` (the
/// attitude another sensor suggests) by [`Quat::slerp`].
///
/// ```
/// use rigtform::{Cvec3, Quat};
/// use rigtform_proofs::firmware_step::firmware_step;
/// let q = firmware_step(Quat::IDENTITY, Cvec3::new(0.0, 0.0, 1.0), 0.01, Quat::IDENTITY, 0.5);
/// assert!((q.angle_to(Quat::from_rotation_z(0.005))) < 1e-6);
/// ```
#[must_use]
pub fn firmware_step(attitude: Quat, gyro: Cvec3, dt: f32, target: Quat, follow: f32) -> Quat {
    attitude.integrate(gyro, dt).slerp(target, follow)
}

/// The step gives a finite attitude for every unit `attitude` and `target`
/// (`rigtform`'s `kani::Arbitrary` for `Quat`), every gyro sample within
/// the sensor's range, every `dt` in (0, [`MAX_DT`]] and every `follow` in
/// [0, 1] (all four: **preconditions** of the firmware, what its sensors
/// and its loop give).
///
/// Stubbed by their contracts: `Quat::normalize` (inside `integrate`),
/// whose contract gives a unit quaternion for the finite, non-zero product,
/// and `Quat::slerp`, whose contract takes unit inputs and `follow` in
/// [0, 1] (Kani checks both `requires` at the call) and gives a finite
/// result. Read as they are: the Hamilton product and the exponential map
/// (polynomials and a square root, `sqrt` under `cfg(kani)` being the exact
/// description of the correctly rounded one).
#[cfg(kani)]
#[kani::proof]
#[kani::solver(cadical)]
#[kani::stub_verified(Quat::normalize)]
#[kani::stub_verified(Quat::slerp)]
fn firmware_step_gives_a_finite_attitude() {
    let attitude: Quat = kani::any();
    let target: Quat = kani::any();
    let gyro: Cvec3 = kani::any();
    kani::assume(
        gyro.x.abs() <= GYRO_RANGE && gyro.y.abs() <= GYRO_RANGE && gyro.z.abs() <= GYRO_RANGE,
    );
    let dt: f32 = kani::any();
    kani::assume(dt > 0.0 && dt <= MAX_DT);
    let follow: f32 = kani::any();
    kani::assume((0.0..=1.0).contains(&follow));
    let q = firmware_step(attitude, gyro, dt, target, follow);
    assert!(q.is_finite());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::draw::Draws;
    use rigtform::accuracy::UNIT_NORM_ERROR;
    use rigtform::kani_contracts::is_unit;

    /// What the harness proves under Kani, and what the contracts it
    /// stubs by promise on the way, on 20,000 random draws of its
    /// preconditions (and the edges of each range): the step's
    /// attitude is unit ([`is_unit`] after `integrate`, within
    /// `UNIT_NORM_ERROR` after `slerp`), so finite.
    #[test]
    fn firmware_step_keeps_a_unit_attitude_on_random_draws() {
        let mut d = Draws::new(24);
        for i in 0..20_000 {
            let (attitude, target) = (d.unit_quat(), d.unit_quat());
            let gyro = match i % 4 {
                0 => Cvec3::new(GYRO_RANGE, -GYRO_RANGE, GYRO_RANGE),
                1 => Cvec3::ZERO,
                _ => d.vec3(GYRO_RANGE),
            };
            let dt = if i % 3 == 0 {
                MAX_DT
            } else {
                d.uniform(1e-6, MAX_DT)
            };
            let follow = match i % 5 {
                0 => 0.0,
                1 => 1.0,
                _ => d.uniform(0.0, 1.0),
            };
            let turned = attitude.integrate(gyro, dt);
            assert!(is_unit(turned), "{attitude:?} {gyro:?} {dt}: {turned:?}");
            let q = firmware_step(attitude, gyro, dt, target, follow);
            assert!(
                q.is_finite(),
                "{attitude:?} {gyro:?} {dt} {target:?} {follow}"
            );
            assert!((q.norm() - 1.0).abs() <= UNIT_NORM_ERROR, "{q:?}");
        }
    }
}
