//! Test support for `rigtform`, shared by its integration tests and by the
//! comparisons with other crates (`rigtform-compare`), so that no two of
//! them keep their own copy of a generator, a reference or a tolerance.
//!
//! - [`draws`]: seeded random draws (unit quaternions uniform over the
//!   rotations) and the draw count `RIGTFORM_DRAWS` sets;
//! - [`strategies`]: the same distributions as proptest strategies;
//! - [`reference`](mod@reference): conversions to nalgebra's f64 types and the notes'
//!   `pow` and `slerp` in f64, to measure errors against;
//! - [`catmull_rom`]: the Catmull-Rom splines of rotations and
//!   translations in f64;
//! - [`tolerance`]: the documented error bounds of `pow` and `slerp` for a
//!   given turn, and entry-wise matrix differences;
//! - [`worst`]: the largest error seen, checked against a bound;
//! - [`broad`]: the BROAD recordings (one trial is shipped in `data/`) and
//!   the benchmark's error metric.
//!
//! The edge values (zeros, subnormals, +-1, 1 +- ulp, 1e30, `f32::MAX`,
//! infinities, NaN) come from `rigtform_proofs::edge`, which the proofs,
//! fuzz seeds and on-target tests share; they are re-exported here.

pub mod broad;
pub mod catmull_rom;
pub mod draws;
pub mod reference;
pub mod strategies;
pub mod tolerance;
pub mod worst;

pub use draws::{draw_count, Draws};
pub use reference::{
    angle_error, euler64, pow64, rotation_angle64, slerp64, to_f32, to_f64, vec_to_f64,
};
pub use rigtform_proofs::edge::{edge_quats, finite_edges, EDGE_F32};
pub use strategies::{key_walk, rig_tform, unit_quat, vec3};
pub use tolerance::{max_entry_diff, pow_tol, slerp_tol};
pub use worst::Worst;
