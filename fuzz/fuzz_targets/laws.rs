//! Every law of the registry (`rigtform_proofs::laws::registry::LAWS`): the
//! input picks a law and the seed of the draws it is checked on, so a law
//! added to the registry is fuzzed with nothing else to edit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_proofs::draw::Draws;
use rigtform_proofs::laws::assert_holds;
use rigtform_proofs::laws::registry::LAWS;

fuzz_target!(|input: (u8, u64)| {
    let (which, seed) = input;
    if let Some(law) = LAWS.get(usize::from(which) % LAWS.len()) {
        assert_holds((law.case)(&mut Draws::new(seed)));
    }
});
