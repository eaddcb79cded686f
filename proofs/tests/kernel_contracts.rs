//! The Kani harnesses of this crate replace the library's three float
//! kernels by their contracts (`src/contracts.rs`, `src/stubs.rs`); that is
//! sound only if the kernels meet them. This checks it on every edge value and on a sweep of every binade (every 4096th bit
//! pattern, NaNs included). The sine and cosine contract's tolerance comes
//! from the kernel's ulp bounds (`contracts::SIN_COS_ABS_BOUND`), which the
//! library's exhaustive kernel sweep establishes; the ignored test below
//! checks the two one-argument contracts on every f32.
//!
//! The library shows its kernels (`rigtform::kani_kernels`) only under
//! Kani or with its `kernel-contracts` feature, which this crate's
//! dev-dependency turns on: the check lives here, not in the library's own
//! unit tests, so that those need nothing that is not published.

use rigtform::kani_kernels::{atan2, sin_cos, sqrt};
use rigtform_proofs::contracts;
use rigtform_proofs::edge::EDGE_F32;

#[test]
fn kernels_meet_the_contracts_the_proofs_stub_them_by() {
    let sweep = (0..=u32::MAX).step_by(4096).map(f32::from_bits);
    for x in EDGE_F32.into_iter().chain(sweep) {
        let (s, c) = sin_cos(x);
        assert!(
            contracts::sin_cos(x, s, c),
            "sin_cos({x:e}) = ({s:e}, {c:e})"
        );
        assert!(contracts::sqrt(x, sqrt(x)), "sqrt({x:e}) = {:e}", sqrt(x));
        for (y, x) in [(x, 1.0), (1.0, x), (x, -x), (-x, x)] {
            let phi = atan2(y, x);
            assert!(contracts::atan2(y, x, phi), "atan2({y:e}, {x:e}) = {phi:e}");
        }
    }
    for y in EDGE_F32 {
        for x in EDGE_F32 {
            assert!(contracts::atan2(y, x, atan2(y, x)), "atan2({y:e}, {x:e})");
        }
    }
}

/// The one-argument kernels against their stubs' contracts on every f32
/// (NaNs included): run by hand after changing a kernel, with the kernel
/// sweeps (`cargo test --release -p rigtform-proofs --test kernel_contracts
/// -- --ignored`). atan2's two arguments are sampled above.
#[test]
#[ignore = "every f32, twice: run by hand in release"]
fn exhaustive_kernel_sweep_of_the_stub_contracts() {
    let mut broken = None;
    for bits in 0..=u32::MAX {
        let x = f32::from_bits(bits);
        let (s, c) = sin_cos(x);
        if !contracts::sin_cos(x, s, c) || !contracts::sqrt(x, sqrt(x)) {
            broken = Some(x);
            break;
        }
    }
    assert_eq!(broken, None, "a kernel breaks its contract");
}
