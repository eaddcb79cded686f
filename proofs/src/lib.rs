//! The laws of `rigtform`'s numerics contract, written once and checked in
//! four layers:
//!
//! - [`laws`]: one function per law, taking inputs that meet its stated
//!   preconditions and returning a [`laws::Verdict`];
//! - Kani proof harnesses over them (`src/harnesses.rs`): proofs where
//!   `cargo kani -p rigtform-proofs` runs, and 50,000 random draws each
//!   through a stand-in for `kani::any`/`kani::assume` where it does not
//!   (`cargo test -p rigtform-proofs`);
//! - the proptest properties of `rigtform`'s `tests/properties.rs`, the
//!   fuzz targets in `fuzz/` and the on-target tests in `embedded/`, which
//!   call the same laws.
//!
//! [`edge`] holds the edge values all of them start from and [`draw`] the
//! seeded generator the stand-in and the on-target tests share, [`reference`](mod@reference)
//! the notes' formulas in `f64` for the on-target accuracy checks.
//! [`contracts`] states what the stubbed float kernels promise.
//! [`firmware_step`] is the example of a firmware's own Kani harness over
//! the library, with its operations stubbed by their contracts.
//!
//! Nothing here is proven unless `cargo kani` ran it: Kani is not
//! installable on the machines this crate is developed on.
//!
//! `no_std` (the on-target tests link it), except for the stand-in, which
//! is compiled for tests only.

#![cfg_attr(not(test), no_std)]
#![deny(missing_docs)]

pub mod contracts;
pub mod draw;
pub mod edge;
pub mod firmware_step;
pub mod fuzz_laws;
pub mod laws;
pub mod reference;

#[cfg(any(kani, test))]
mod harnesses;
#[cfg(all(test, not(kani)))]
mod kani_stand_in;
#[cfg(kani)]
mod stubs;
