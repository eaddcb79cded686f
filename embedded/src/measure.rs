//! The marker protocol of the on-target instruction counts
//! (`bin/bench.rs`, `bin/filter_cost.rs`), read by `cargo xtask`:
//!
//! - A bracket is a call of [`start`] (symbol `measure_start`), the
//!   measured code, and a call of [`end`] (symbol `measure_end`). QEMU's
//!   exec trace (`-singlestep -d exec,nochain`) logs every executed
//!   instruction; the xtask finds the two symbols in the ELF and counts the
//!   instructions from the entry of the first to the entry of the second.
//! - Each row of the results is announced over semihosting with [`row`]:
//!   its name fields and its number of inputs. Its brackets follow in the
//!   order the rows were announced: for each input, an empty bracket (the
//!   calibration: the same calls with no work, on the same input) and then
//!   the measured one. The xtask reports the mean over the inputs of the
//!   difference.
//! - [`done`] closes the output with the number of rows, so that a firmware
//!   that stopped early is an error, not a shorter table.

use core::ptr::{addr_of_mut, write_volatile};

use cortex_m_semihosting::{hprint, hprintln};

/// Two statics, so that the two markers differ and are never merged.
static mut STARTED: u32 = 0;
static mut ENDED: u32 = 0;

/// Opens a bracket: never inlined, and named, so that its entry address is
/// in the ELF and every call of it shows in the trace.
#[inline(never)]
#[export_name = "measure_start"]
pub extern "C" fn start() {
    // SAFETY: a plain store to a static that nothing else touches; volatile,
    // so that the call is never optimized away as having no effect.
    unsafe { write_volatile(addr_of_mut!(STARTED), 1) }
}

/// Closes a bracket (as [`start`], on another static).
#[inline(never)]
#[export_name = "measure_end"]
pub extern "C" fn end() {
    // SAFETY: as in `start`, on a different static.
    unsafe { write_volatile(addr_of_mut!(ENDED), 1) }
}

/// Announces the next row: `inputs` pairs of brackets (empty, then
/// measured) follow for it, and `name` names it (fields without `|`; the
/// ops bench gives `operation`, `library` and the function of `ops.rs`).
/// Prints `measure <inputs>|<name[0]>|<name[1]>...`.
pub fn row(inputs: usize, name: &[&str]) {
    hprint!("measure {}", inputs);
    for field in name {
        hprint!("|{}", field);
    }
    hprintln!();
}

/// Ends the output: `measure done <rows>`.
pub fn done(rows: usize) {
    hprintln!("measure done {}", rows);
}
