//! `pow` on raw bit patterns: the atan2 edge cases of the contract (zero,
//! subnormal and huge vector parts, `w = +-1`, `w = 0`, any exponent).
//! Finite in, finite unit out, turned as the notes' formula in `f64` turns
//! (so that a `pow` that turns the wrong way for `w < 0` is caught, which no
//! norm check can do); NaN or infinity in, NaN out; and `cn` and `inv` keep
//! their exact laws on every input.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::Quat;
use rigtform_proofs::laws::{self, assert_holds};

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    q: [f32; 4],
    alpha: f32,
}

fuzz_target!(|input: Input| {
    let [w, x, y, z] = input.q;
    let q = Quat::new(w, x, y, z);
    if q.is_finite() && input.alpha.is_finite() {
        assert_holds(laws::pow_is_unit(q, input.alpha));
        if input.alpha.abs() <= 4.0 {
            assert_holds(laws::pow_turns_as_the_notes_define(q, input.alpha));
        }
    } else {
        assert_holds(laws::pow_of_non_finite_is_nan(q, input.alpha));
    }
    assert_holds(laws::cn_gives_non_negative_w_and_the_same_rotation(q));
    assert_holds(laws::inverse_is_an_involution(q));
});
