//! Kani stubs: libm's kernels replaced by "any value that meets the
//! contract" (`src/contracts.rs`), a sound over-approximation as long as
//! libm meets the contracts, which `tests/contracts.rs` checks.
//!
//! Compiled only under Kani (`cfg(kani)`), where the `kani` crate exists.

use crate::contracts;

/// Any `(s, c)` that `contracts::sin_cos` accepts for `x`.
pub fn sincosf(x: f32) -> (f32, f32) {
    let (s, c): (f32, f32) = (kani::any(), kani::any());
    kani::assume(contracts::sin_cos(x, s, c));
    (s, c)
}

/// Any `phi` that `contracts::atan2` accepts for `(y, x)`.
pub fn atan2f(y: f32, x: f32) -> f32 {
    let phi: f32 = kani::any();
    kani::assume(contracts::atan2(y, x, phi));
    phi
}

/// Any `r` that `contracts::sqrt` accepts for `x`.
pub fn sqrtf(x: f32) -> f32 {
    let r: f32 = kani::any();
    kani::assume(contracts::sqrt(x, r));
    r
}
