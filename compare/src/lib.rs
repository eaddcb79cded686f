//! `rigtform` beside its peers: glam (its default SIMD build and its
//! `scalar-math` build), nalgebra, cgmath and micromath, measured on the
//! same inputs in the same run.
//!
//! - `benches/ops.rs`: criterion benchmarks of every operation beside the
//!   same operation of each peer that has it
//!   (`cargo bench -p rigtform-compare --bench ops`).
//! - `src/bin/accuracy.rs`: the accuracy report against an f64 reference,
//!   with NaN and panic counts per input class
//!   (`cargo run --release -p rigtform-compare --bin accuracy`).
//! - `src/bin/broad/`: the orientation filter on BROAD trials and x-io's
//!   Fusion log, beside the published figures of Madgwick, Mahony and VQF
//!   (`cargo run --release -p rigtform-compare --bin broad`).
//!
//! This library holds what the three share: [`inputs`] and the
//! [`convert`]ers into each library's types.

pub mod convert;
pub mod inputs;

pub use convert::*;
pub use inputs::Inputs;
