//! uf-ahrs's three filters (its f32 port of VQF, Mahony and Madgwick) on a
//! BROAD trial, in process, scored with the same metric as ours.
//!
//! Each runs as the crate's README shows: `new(sample_period, default
//! parameters)`, then one `Ahrs::update` (9D) or `Ahrs::update_imu` (6D)
//! per sample, from the first sample, with the gyroscope in rad/s and the
//! accelerometer and magnetometer in the trial's units (uf-ahrs normalizes
//! them). The sample period is BROAD's, 3.5 ms, exactly.
//!
//! uf-ahrs's earth frame has x along magnetic north and z up (north, west,
//! up: its Mahony and Madgwick align the field's horizontal part with x, its
//! VQF turns the heading by `atan2(-m_y, m_x)`); BROAD's truth is east,
//! north, up. Each estimate is turned by +90 degrees about the vertical to
//! go from the one to the other, `q_enu = R_z(90°) q_nwu`. The turn does not
//! change the inclination error, so the 6D scores do not depend on it.

use core::time::Duration;

use nalgebra::{UnitQuaternion, Vector3};
use rigtform::{Cvec3, Quat};
use rigtform_testkit::broad::data::BroadSample;
use rigtform_testkit::broad::metric::{self, Run};
use uf_ahrs::{Ahrs, Madgwick, MadgwickParams, Mahony, MahonyParams, Vqf, VqfParams};

/// BROAD's sample period, 2000/7 Hz.
const PERIOD: Duration = Duration::from_micros(3500);

/// The three filters, in the order of [`run_all`]'s result.
pub const NAMES: [&str; 3] = ["uf-ahrs VQF", "uf-ahrs Mahony", "uf-ahrs Madgwick"];

/// One filter's 6D and 9D runs.
pub struct Runs {
    pub six: Run,
    pub nine: Run,
}

/// The 6D and 9D runs of uf-ahrs's VQF, Mahony and Madgwick (the order of
/// [`NAMES`]), each filter new for each run.
pub fn run_all(samples: &[BroadSample]) -> [Runs; 3] {
    let vqf = || Vqf::new(PERIOD, VqfParams::default());
    let mahony = || Mahony::new(PERIOD, MahonyParams::default());
    let madgwick = || Madgwick::new(PERIOD, MadgwickParams::default());
    [
        Runs {
            six: run(samples, vqf(), false),
            nine: run(samples, vqf(), true),
        },
        Runs {
            six: run(samples, mahony(), false),
            nine: run(samples, mahony(), true),
        },
        Runs {
            six: run(samples, madgwick(), false),
            nine: run(samples, madgwick(), true),
        },
    ]
}

/// `filter` over `samples` from the first one, 6D or with the
/// magnetometer, its estimates in BROAD's frame, scored.
fn run(samples: &[BroadSample], mut filter: impl Ahrs, with_mag: bool) -> Run {
    let estimates: Vec<Quat> = samples
        .iter()
        .map(|s| {
            let q = if with_mag {
                filter.update(vector(s.gyr), vector(s.acc), vector(s.mag))
            } else {
                filter.update_imu(vector(s.gyr), vector(s.acc))
            };
            to_enu(q)
        })
        .collect();
    Run {
        rmse: metric::score(samples, &estimates),
        estimates,
    }
}

fn vector(v: Cvec3) -> Vector3<f32> {
    Vector3::new(v.x, v.y, v.z)
}

/// `q` (sensor to north-west-up) as sensor to east-north-up: turned by +90
/// degrees about the vertical.
fn to_enu(q: UnitQuaternion<f32>) -> Quat {
    let q = Quat::from_wxyz(q.w, q.i, q.j, q.k);
    Quat::from_rotation_z(core::f32::consts::FRAC_PI_2) * q
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn north_west_up_becomes_east_north_up() {
        // The identity in north-west-up: the sensor's x points north, which
        // is east-north-up's y.
        let q = to_enu(UnitQuaternion::identity());
        let x = q * Cvec3::X;
        assert!((x - Cvec3::Y).length() < 1e-6, "{x:?}");
        assert!((q * Cvec3::Z - Cvec3::Z).length() < 1e-6);
    }

    #[test]
    fn each_filter_levels_a_resting_sensor_and_points_it_north() {
        // At rest, level, the sensor's y axis towards magnetic north (a
        // field of 20 uT north, 40 uT down in east-north-up).
        let sample = BroadSample {
            gyr: Cvec3::ZERO,
            acc: Cvec3::new(0.0, 0.0, 9.81),
            mag: Cvec3::new(0.0, 20.0, -40.0),
            truth: [1.0, 0.0, 0.0, 0.0],
            movement: true,
        };
        let samples = vec![sample; 20_000];
        for (name, runs) in NAMES.iter().zip(run_all(&samples)) {
            let last = |r: &Run| metric::sample_error(*r.estimates.last().unwrap(), sample.truth);
            let (six, nine) = (last(&runs.six), last(&runs.nine));
            assert!(six.inclination < 0.5, "{name} 6D: {six:?}");
            assert!(nine.total < 1.0, "{name} 9D: {nine:?}");
        }
    }
}
