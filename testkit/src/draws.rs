//! Seeded random draws for the tests that run far more cases than
//! proptest's default and track the largest error.

use nalgebra as na;
use rand::{Rng, SeedableRng};
use rigtform::{Cvec3, Quat, RigTForm};

use crate::reference::to_f32;

/// Random draws per operation: 100,000 unless the environment variable
/// `RIGTFORM_DRAWS` says otherwise (more for a deeper search, fewer for
/// mutation testing).
///
/// ```
/// assert!(rigtform_testkit::draw_count() > 0);
/// ```
pub fn draw_count() -> usize {
    std::env::var("RIGTFORM_DRAWS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(100_000)
}

/// A point of the 4-cube, kept if it lies in the unit ball (away from the
/// origin) and projected onto the sphere: rejection sampling that makes
/// unit quaternions uniformly distributed rotations.
pub(crate) fn unit_from_cube(v: [f64; 4]) -> Option<na::Quaternion<f64>> {
    let n2: f64 = v.iter().map(|c| c * c).sum();
    (0.01..=1.0)
        .contains(&n2)
        .then(|| na::Quaternion::new(v[0], v[1], v[2], v[3]).normalize())
}

/// A seeded source of random inputs: the same seed gives the same draws.
///
/// ```
/// use rigtform_testkit::Draws;
/// let (mut a, mut b) = (Draws::new(7), Draws::new(7));
/// assert_eq!(a.unit_quat(), b.unit_quat());
/// assert!((a.unit_quat().norm() - 1.0).abs() < 1e-6);
/// ```
pub struct Draws(rand::rngs::StdRng);

impl Draws {
    /// Draws from the seed `seed`.
    pub fn new(seed: u64) -> Self {
        Self(rand::rngs::StdRng::seed_from_u64(seed))
    }

    /// A number uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0.random_range(lo..hi)
    }

    /// A unit quaternion uniform over the rotations, in f64.
    pub fn unit_quat64(&mut self) -> na::Quaternion<f64> {
        loop {
            if let Some(q) = unit_from_cube([(); 4].map(|_| self.uniform(-1.0, 1.0))) {
                return q;
            }
        }
    }

    /// A unit quaternion uniform over the rotations, rounded to f32.
    pub fn unit_quat(&mut self) -> Quat {
        to_f32(self.unit_quat64())
    }

    /// A unit vector uniform over the sphere, in f64.
    pub fn unit_vec64(&mut self) -> na::Vector3<f64> {
        let q = self.unit_quat64();
        na::Vector3::new(q.i, q.j, q.k).normalize()
    }

    /// A rotation by an angle uniform in `[0, max_angle)` about an axis
    /// uniform over the sphere, in f64.
    pub fn turn64(&mut self, max_angle: f64) -> na::Quaternion<f64> {
        let axis = na::Unit::new_normalize(self.unit_vec64());
        *na::UnitQuaternion::from_axis_angle(&axis, self.uniform(0.0, max_angle)).as_ref()
    }

    /// `n` keyframes on a random walk: the first rotation uniform, each
    /// next one turned from it by up to [`KEY_STEP`] rad about a random
    /// axis, translations in [-10, 10]. Keys two apart are then less than
    /// pi apart, where the spline's conditional negations are well away
    /// from their switch.
    pub fn key_walk(&mut self, n: usize) -> Vec<RigTForm> {
        let mut r = self.unit_quat64();
        (0..n)
            .map(|_| {
                let t = [(); 3].map(|_| self.uniform(-10.0, 10.0) as f32);
                let key = RigTForm::new(Cvec3::new(t[0], t[1], t[2]), to_f32(r));
                r = self.turn64(KEY_STEP) * r;
                key
            })
            .collect()
    }
}

/// The largest turn, in radians, between neighbouring keys of
/// [`Draws::key_walk`] and [`key_walk`](crate::strategies::key_walk): two
/// steps stay 0.14 rad short of pi.
pub const KEY_STEP: f64 = 1.5;
