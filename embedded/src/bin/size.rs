//! Firmware that calls one operation of `rigtform_embedded::ops`, the one
//! named by `RIGTFORM_SIZE_OP` when it is built: its flash size, less that
//! of the same firmware calling `ops::empty`, is what the operation costs
//! in flash with everything it pulls in (kernels, libm, soft-float and
//! compiler helpers). `cargo xtask m4f` builds it once per operation and
//! opt-level.

#![no_std]
#![no_main]

use core::hint::black_box;

use cortex_m_rt::entry;
use rigtform_embedded::ops::Input;

include!(concat!(env!("OUT_DIR"), "/size_op.rs"));

#[entry]
fn main() -> ! {
    let x = black_box(Input {
        a: [1.0, 0.0, 0.0, 0.0],
        b: [0.0, 1.0, 0.0, 0.0],
        u: [1.0, 2.0, 3.0],
        v: [4.0, 5.0, 6.0],
        t: 0.5,
    });
    // Opaque, so that every build clears it alike (an operation that writes
    // all 16 entries would otherwise save the clearing, and seem smaller
    // than none).
    let mut out = black_box([0.0; 16]);
    OP(&x, &mut out);
    black_box(out);
    loop {
        cortex_m::asm::nop();
    }
}

/// The smallest handler: a panic (nalgebra's slerp has one) stops here.
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {
        cortex_m::asm::nop();
    }
}
