//! `pow` on raw bit patterns: the atan2 edge cases of the contract (zero,
//! subnormal and huge vector parts, `w = +-1`, `w = 0`, any exponent).
//! Finite in, finite unit out, turned as the notes' formula in `f64` turns
//! (so that a `pow` that turns the wrong way for `w < 0` is caught, which no
//! norm check can do); NaN or infinity in, NaN out; and `cn` and `inv` keep
//! their exact laws on every input.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_proofs::fuzz_laws;

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    q: [f32; 4],
    alpha: f32,
}

// The checks live in rigtform-proofs, where the regression test replays
// fuzz/regressions/pow/ through the same function.
fuzz_target!(|input: Input| fuzz_laws::pow(input.q, input.alpha));
