//! Support for running `rigtform`'s laws on an emulated Cortex-M: a tally
//! of named checks printed over semihosting, ending in the line
//! `N passed, M failed`, and the exit status QEMU hands back to the shell;
//! and the marker protocol of the instruction counts ([`measure`]).

#![no_std]

pub mod attitude;
pub mod measure;
#[cfg(feature = "peers")]
pub mod ops;

use cortex_m_semihosting::{debug, hprintln};
use rigtform_proofs::laws::Violation;

/// Named checks run so far.
#[derive(Default)]
pub struct Tally {
    passed: u32,
    failed: u32,
}

impl Tally {
    /// Runs one named check: `body` returns how many cases it checked, or
    /// the first law it found broken.
    pub fn check(&mut self, name: &str, body: impl FnOnce() -> Result<u32, Violation>) {
        match body() {
            Ok(cases) => {
                self.passed += 1;
                hprintln!("test {} ... ok ({} cases)", name, cases);
            }
            Err(v) => {
                self.failed += 1;
                hprintln!(
                    "test {} ... FAILED: {} measured {:e}, bound {:e}",
                    name,
                    v.law,
                    v.measured,
                    v.bound
                );
            }
        }
    }

    /// Prints the summary line and ends the emulation, with exit status 0
    /// only if every check passed.
    pub fn finish(self) -> ! {
        hprintln!("{} passed, {} failed", self.passed, self.failed);
        debug::exit(if self.failed == 0 {
            debug::EXIT_SUCCESS
        } else {
            debug::EXIT_FAILURE
        });
        // Only reached outside QEMU (semihosting exit is then ignored).
        loop {
            cortex_m::asm::wfi();
        }
    }
}

/// Checks `law` on every case, counting them; stops at the first violation.
pub fn each<T>(
    cases: impl Iterator<Item = T>,
    mut law: impl FnMut(T) -> Result<(), Violation>,
) -> Result<u32, Violation> {
    let mut n = 0;
    for case in cases {
        law(case)?;
        n += 1;
    }
    Ok(n)
}
