//! The reader of BROAD trials and x-io Fusion logs (the `broad` binary's,
//! in rigtform-testkit) on any text: an error naming a line, or one sample
//! per row that is not blank, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform_testkit::broad::data::{self, Recording};

fuzz_target!(|text: &str| {
    match data::parse(text) {
        Ok(recording) => {
            let samples = match recording {
                Recording::Broad(s) => s.len(),
                Recording::Fusion(s) => s.len(),
            };
            let text = text.strip_prefix('\u{feff}').unwrap_or(text);
            let rows = text
                .lines()
                .skip(1)
                .filter(|l| !l.trim().is_empty())
                .count();
            assert_eq!(samples, rows, "{text:?}");
        }
        Err(e) => assert!(e.starts_with("line "), "{e}"),
    }
});
