//! Kani stubs: the crate's float kernels (behind `src/float.rs`, re-exported
//! under Kani as `rigtform::kani_kernels`) replaced by "any value that
//! meets the contract" (`src/contracts.rs`), a sound over-approximation as
//! long as the kernels meet the contracts, which
//! `kernels_meet_the_contracts_the_proofs_stub_them_by` in
//! `tests/kernel_contracts.rs` checks.
//!
//! Compiled only under Kani (`cfg(kani)`), where the `kani` crate exists.

use crate::contracts;

/// Any `(s, c)` that `contracts::sin_cos` accepts for `x`.
pub fn sin_cos(x: f32) -> (f32, f32) {
    let (s, c): (f32, f32) = (kani::any(), kani::any());
    kani::assume(contracts::sin_cos(x, s, c));
    (s, c)
}

/// Any `phi` that `contracts::atan2` accepts for `(y, x)`.
pub fn atan2(y: f32, x: f32) -> f32 {
    let phi: f32 = kani::any();
    kani::assume(contracts::atan2(y, x, phi));
    phi
}

/// Any `r` that `contracts::sqrt` accepts for `x`.
pub fn sqrt(x: f32) -> f32 {
    let r: f32 = kani::any();
    kani::assume(contracts::sqrt(x, r));
    r
}
