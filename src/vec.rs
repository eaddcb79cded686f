//! Coordinate vectors: [`Cvec3`] (a point or a direction) and [`Cvec4`]
//! (homogeneous coordinates: `w = 1` for a point, `w = 0` for a vector).
//!
//! One file per type (`vec/cvec3.rs`, `vec/cvec4.rs`) with its own methods;
//! what the two share, and the norms they share with
//! [`Quat`](crate::Quat), is written once in `vec/template.rs`, as macros
//! each type instances.

mod template;

mod cvec3;
mod cvec4;
#[cfg(test)]
mod tests;

pub use cvec3::Cvec3;
pub use cvec4::Cvec4;
pub(crate) use template::{arithmetic, euclidean, example_uses};
