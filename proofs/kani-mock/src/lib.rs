//! A mock of the parts of Kani that `rigtform` and `rigtform-proofs` use,
//! for compiling the library's contracts and `Arbitrary` implementations
//! and the harnesses under `cfg(kani)` where Kani is not installed
//! (`.ci/run`'s `kani_mock` stage). As `cargo kani` does, the stage hands
//! the crate to every compiled crate: built first, then
//! `RUSTFLAGS="--cfg kani --extern kani=<its rlib> -L dependency=<its deps>"`.
//!
//! It checks what a compile can check and `cargo kani` would otherwise be
//! the first to see: that every path a `#[kani::stub]` names exists and
//! that its two functions have the same signature (so that a renamed or
//! re-typed kernel fails here), that `#[kani::proof]` marks a function
//! without parameters, that `#[kani::unwind]` has one integer and
//! `#[kani::solver]` a solver Kani knows, and that the harnesses call
//! `any`, `any_where`, `assume` and `cover!` with the types Kani's have;
//! and of function contracts: that every `requires` is a `bool` and every
//! `ensures` a closure from a reference to the function's result to
//! `bool`, over the function's parameters, and that every path
//! `proof_for_contract` and `stub_verified` name exists.
//!
//! Nothing here runs: the functions are for type checking, and panic if
//! called (the harnesses run as tests through `src/kani_stand_in.rs`, and
//! as proofs only under `cargo kani`, which brings the real crate).

#![no_std]
#![deny(missing_docs)]

pub use rigtform_kani_mock_macros::{
    ensures, proof, proof_for_contract, requires, solver, stub, stub_verified, unwind,
};

/// The types `any` can produce, as in Kani: `any()` gives any value of
/// the type.
pub trait Arbitrary: Sized {
    /// Any value of the type: type checking only.
    ///
    /// # Panics
    ///
    /// Always: a mock is compiled, never run.
    fn any() -> Self;
}

/// The panic of every function of the mock.
fn never_run() -> ! {
    panic!("the Kani mock is for compiling harnesses; run them with cargo kani or cargo test")
}

impl Arbitrary for bool {
    fn any() -> Self {
        never_run()
    }
}
impl Arbitrary for f32 {
    fn any() -> Self {
        never_run()
    }
}
impl Arbitrary for u32 {
    fn any() -> Self {
        never_run()
    }
}

/// Kani's `any`: type checking only.
///
/// # Panics
///
/// Always: a mock is compiled, never run.
pub fn any<T: Arbitrary>() -> T {
    T::any()
}

/// Kani's `any_where`: type checking only.
///
/// # Panics
///
/// Always, like [`any`].
pub fn any_where<T: Arbitrary, F: FnOnce(&T) -> bool>(_keep: F) -> T {
    any()
}

/// Kani's `assume`: type checking only.
///
/// # Panics
///
/// Always, like [`any`].
pub fn assume(_condition: bool) {
    any::<bool>();
}

/// Kani's `cover!(condition, message)`: checks that the condition is a
/// `bool` and the message a string literal.
#[macro_export]
macro_rules! cover {
    ($condition:expr, $message:literal) => {{
        let _: bool = $condition;
        let _: &str = $message;
    }};
}
