//! Shared test support: the edge values, the input generators and the f64
//! reference that every test file draws on, so that no two files keep their
//! own copy.
#![allow(dead_code)] // each test file uses a different part

use nalgebra as na;
use proptest::prelude::*;
use rigtform::{Cvec3, Quat, RigTForm};
use rigtform_proofs::reference::Quat64;

/// The edge values (zeros, subnormals, +-1, 1 +- ulp, 1e30, `f32::MAX`,
/// infinities, NaN) that the proofs, fuzz seeds and on-target tests share.
#[allow(unused_imports)] // each test file uses a different part
pub use rigtform_proofs::edge::{edge_quats, finite_edges, EDGE_F32};

/// A point drawn uniformly in the 4-cube, kept if it lies in the unit ball
/// (away from the origin) and projected onto the sphere: rejection sampling
/// that makes unit quaternions uniformly distributed rotations.
fn unit_from_cube(v: [f64; 4]) -> Option<na::Quaternion<f64>> {
    let n2: f64 = v.iter().map(|c| c * c).sum();
    (0.01..=1.0)
        .contains(&n2)
        .then(|| na::Quaternion::new(v[0], v[1], v[2], v[3]).normalize())
}

/// A uniformly distributed unit quaternion, rounded to f32.
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

/// Random draws per operation: 100,000 unless the environment variable
/// `RIGTFORM_DRAWS` says otherwise (more for a deeper search, fewer for
/// mutation testing).
pub fn draw_count() -> usize {
    std::env::var("RIGTFORM_DRAWS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(100_000)
}

/// Plain random draws for the differential tests, which run far more cases
/// than proptest's default and track the largest error.
pub struct Draws(rand::rngs::StdRng);

impl Draws {
    pub fn new(seed: u64) -> Self {
        use rand::SeedableRng;
        Self(rand::rngs::StdRng::seed_from_u64(seed))
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        use rand::Rng;
        self.0.random_range(lo..hi)
    }
    pub fn unit_quat64(&mut self) -> na::Quaternion<f64> {
        loop {
            if let Some(q) = unit_from_cube([(); 4].map(|_| self.uniform(-1.0, 1.0))) {
                return q;
            }
        }
    }
    pub fn unit_quat(&mut self) -> Quat {
        to_f32(self.unit_quat64())
    }
    pub fn unit_vec64(&mut self) -> na::Vector3<f64> {
        let q = self.unit_quat64();
        na::Vector3::new(q.i, q.j, q.k).normalize()
    }
}

pub fn to_f64(q: Quat) -> na::Quaternion<f64> {
    na::Quaternion::new(q.w as f64, q.x as f64, q.y as f64, q.z as f64)
}

pub fn to_f32(q: na::Quaternion<f64>) -> Quat {
    Quat::new(q.w as f32, q.i as f32, q.j as f32, q.k as f32)
}

pub fn vec_to_f64(v: Cvec3) -> na::Vector3<f64> {
    na::Vector3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// The angle of the rotation between two quaternions, up to sign and
/// scale, in f64: `2 atan2(|v|, |w|)` of `b^-1 a` (accurate near 0 and pi).
pub fn rotation_angle64(a: na::Quaternion<f64>, b: na::Quaternion<f64>) -> f64 {
    Quat64::angle_between(to_reference(a), to_reference(b))
}

/// The angle between a computed f32 rotation and an f64 reference.
pub fn angle_error(got: Quat, want: na::Quaternion<f64>) -> f64 {
    rotation_angle64(to_f64(got), want)
}

fn to_reference(q: na::Quaternion<f64>) -> Quat64 {
    Quat64 {
        w: q.w,
        x: q.i,
        y: q.j,
        z: q.k,
    }
}

fn from_reference(q: Quat64) -> na::Quaternion<f64> {
    na::Quaternion::new(q.w, q.x, q.y, q.z)
}

/// The notes' power operator in f64 (`rigtform_proofs::reference`, which
/// the on-target tests use too): `phi = atan2(|v|, w)`,
/// `(cos(alpha phi), sin(alpha phi) v/|v|)`; pure real negative turns about x.
pub fn pow64(q: na::Quaternion<f64>, alpha: f64) -> na::Quaternion<f64> {
    from_reference(to_reference(q).pow(alpha))
}

/// `pow(cn(q1 q0^-1), alpha) q0` in f64, on the normalized inputs.
pub fn slerp64(
    q0: na::Quaternion<f64>,
    q1: na::Quaternion<f64>,
    alpha: f64,
) -> na::Quaternion<f64> {
    from_reference(Quat64::slerp(
        to_reference(q0.normalize()),
        to_reference(q1.normalize()),
        alpha,
    ))
}

/// The documented pow error (`accuracy::POW_MAX_ANGLE_ERROR`) for a turn of
/// `alpha` times `theta` radians: per radian turned, at least one radian.
pub fn pow_tol(alpha: f32, theta: f32) -> f32 {
    rigtform::accuracy::POW_MAX_ANGLE_ERROR * (alpha * theta).abs().max(1.0)
}

/// The documented slerp error (`accuracy::SLERP_MAX_ANGLE_ERROR`) for a turn
/// of `alpha` times `theta` radians.
pub fn slerp_tol(alpha: f32, theta: f32) -> f32 {
    rigtform::accuracy::SLERP_MAX_ANGLE_ERROR * (alpha * theta).abs().max(1.0)
}

/// Largest absolute entry difference of two column-major arrays.
pub fn max_entry_diff(a: [f32; 16], b: [f32; 16]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

/// The largest error seen, and the input that caused it.
pub struct Worst {
    name: &'static str,
    error: f64,
    input: String,
}

impl Worst {
    pub fn new(name: &'static str) -> Self {
        Self {
            name,
            error: 0.0,
            input: String::new(),
        }
    }
    pub fn see(&mut self, error: f64, input: impl FnOnce() -> String) {
        assert!(!error.is_nan(), "{}: NaN error for {}", self.name, input());
        if error > self.error {
            self.error = error;
            self.input = input();
        }
    }
    pub fn check(&self, bound: f32) {
        println!(
            "{:<44} max {:.3e}  (bound {:.1e})",
            self.name, self.error, bound
        );
        assert!(
            self.error <= bound as f64,
            "{}: error {:e} exceeds the documented bound {:e}, at {}",
            self.name,
            self.error,
            bound,
            self.input
        );
    }
}
