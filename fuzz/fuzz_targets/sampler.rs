//! The glTF keyframe samplers (`rigtform::animation::Sampler`) on raw bit
//! patterns: no panic on any times, values or time; on valid channels made
//! from the same bits, the keys are hit, the ends clamp, samples of unit
//! keys are unit and STEP is constant between keys.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_proofs::fuzz_laws;

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    times: [f32; 4],
    values: [f32; 48],
    selector: f32,
    t: f32,
}

// The checks live in rigtform-proofs, where the regression test replays
// fuzz/regressions/sampler/ through the same function.
fuzz_target!(|input: Input| {
    fuzz_laws::sampler(input.times, input.values, input.selector, input.t);
});
