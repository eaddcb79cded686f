//! `slerp`, `nlerp`, `blend`, `slerp_slice` and `Quat::catmull_rom` on raw
//! bit patterns (contract item 3): unit results for unit inputs and every
//! finite alpha, exactness at alpha = 0, the short way at constant angular
//! velocity, the rotation of the notes' formula in `f64` for alpha in
//! [-1, 2], the slice equal to slerp bit for bit, the spline's keys and
//! left invariance, NaN out for NaN in, and no panic on anything.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_proofs::fuzz_laws;

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    a: [f32; 4],
    b: [f32; 4],
    c: [f32; 4],
    alpha: f32,
    weights: [f32; 3],
}

// The checks live in rigtform-proofs, where the regression test replays
// fuzz/regressions/slerp/ through the same function.
fuzz_target!(|input: Input| {
    fuzz_laws::slerp(input.a, input.b, input.c, input.alpha, input.weights);
});
