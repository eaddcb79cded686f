//! The stubs are sound only if the real kernels meet their contracts: this
//! checks libm's `sincosf`, `atan2f` and `sqrtf` against
//! `rigtform_proofs::contracts` on every edge value, on a dense sweep and
//! on random bit patterns.

use proptest::prelude::*;
use rigtform_proofs::contracts;
use rigtform_proofs::edge::EDGE_F32;

fn sin_cos_ok(x: f32) -> bool {
    let (s, c) = libm::sincosf(x);
    contracts::sin_cos(x, s, c)
}

fn atan2_ok(y: f32, x: f32) -> bool {
    contracts::atan2(y, x, libm::atan2f(y, x))
}

fn sqrt_ok(x: f32) -> bool {
    contracts::sqrt(x, libm::sqrtf(x))
}

#[test]
fn kernels_meet_their_contracts_on_every_edge_value() {
    for x in EDGE_F32 {
        assert!(sin_cos_ok(x), "sincosf({x})");
        assert!(sqrt_ok(x), "sqrtf({x})");
        for y in EDGE_F32 {
            assert!(atan2_ok(y, x), "atan2f({y}, {x})");
        }
    }
}

#[test]
fn kernels_meet_their_contracts_on_a_sweep_of_every_binade() {
    // Every 4096th f32 bit pattern: all binades, both signs, NaNs included.
    for bits in (0..=u32::MAX).step_by(4096) {
        let x = f32::from_bits(bits);
        assert!(sin_cos_ok(x), "sincosf({x:e})");
        assert!(sqrt_ok(x), "sqrtf({x:e})");
        assert!(
            atan2_ok(x, 1.0) && atan2_ok(1.0, x) && atan2_ok(x, -x),
            "atan2f at {x:e}"
        );
    }
}

#[test]
fn contracts_reject_what_the_kernels_must_not_return() {
    assert!(!contracts::sin_cos(1.0, 0.9, 0.9)); // off the unit circle
    assert!(!contracts::sin_cos(0.0, 0.0, 0.999)); // cos(0) is exactly 1
    assert!(!contracts::sin_cos(f32::INFINITY, 0.0, 1.0)); // must be NaN
    assert!(!contracts::atan2(-1.0, 1.0, 0.7)); // wrong sign
    assert!(!contracts::atan2(1.0, -1.0, 3.2)); // beyond pi
    assert!(!contracts::atan2(f32::NAN, 1.0, 0.0));
    assert!(!contracts::sqrt(4.0, 2.001));
    assert!(!contracts::sqrt(-1.0, 1.0));
    assert!(!contracts::sqrt(0.0, 1e-20));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]

    #[test]
    fn sincosf_meets_its_contract(bits in any::<u32>()) {
        prop_assert!(sin_cos_ok(f32::from_bits(bits)));
    }

    #[test]
    fn atan2f_meets_its_contract(y in any::<u32>(), x in any::<u32>()) {
        prop_assert!(atan2_ok(f32::from_bits(y), f32::from_bits(x)));
    }

    #[test]
    fn sqrtf_meets_its_contract(bits in any::<u32>()) {
        prop_assert!(sqrt_ok(f32::from_bits(bits)));
    }
}
