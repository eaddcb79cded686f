//! Instructions executed per call of each operation of `rigtform_embedded::ops`
//! (rigtform, glam, nalgebra, micromath), on an emulated Cortex-M4F.
//!
//! Each call is bracketed by two never-inlined marker functions that write
//! to two different statics, [`bench_start`] and [`bench_end`]; QEMU's exec
//! trace (`-singlestep -d exec,nochain`) logs every instruction executed,
//! and `bench.sh` beside `Cargo.toml` counts the instructions between the
//! markers, minus those of the same bracket around [`ops::empty`] on the
//! same input (the calibration: passing the input in and the result out).
//! Run it with `embedded/bench.sh`, not directly.

#![no_std]
#![no_main]

use core::hint::black_box;
use core::ptr::{addr_of_mut, write_volatile};

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;
use rigtform_embedded::ops::{self, Input, Op, Output};
use rigtform_proofs::draw::Draws;

/// Inputs per operation; `bench.sh` reports the mean count over them.
const INPUTS: usize = 8;

static mut START: u32 = 0;
static mut END: u32 = 0;

/// The first marker: its address is where a bracket opens in the trace.
#[inline(never)]
#[no_mangle]
pub extern "C" fn bench_start() {
    // SAFETY: a plain store to a static that nothing else touches; volatile,
    // so that the marker is never optimized away or merged with the other.
    unsafe { write_volatile(addr_of_mut!(START), 1) }
}

/// The second marker: where a bracket closes.
#[inline(never)]
#[no_mangle]
pub extern "C" fn bench_end() {
    // SAFETY: as in `bench_start`, on a different static.
    unsafe { write_volatile(addr_of_mut!(END), 1) }
}

/// One call of `op`, between the markers. The input is hidden from the
/// optimizer after the first marker and the result handed out before the
/// second, so the work stays inside.
#[inline(never)]
fn bracket(op: Op, x: &Input, out: &mut Output) {
    bench_start();
    black_box(op)(black_box(x), black_box(&mut *out));
    bench_end();
}

#[entry]
fn main() -> ! {
    let mut d = Draws::new(5);
    let inputs: [Input; INPUTS] = core::array::from_fn(|_| Input {
        a: quat(d.unit_quat()),
        b: quat(d.unit_quat()),
        u: d.vec3(10.0).to_array(),
        v: d.vec3(10.0).to_array(),
        t: d.uniform(0.0, 1.0),
    });
    let mut out: Output = [0.0; 16];
    hprintln!("bench inputs {}", INPUTS);
    for &(operation, library, op) in ops::OPS {
        hprintln!("bench op {}|{}", operation, library);
        for x in &inputs {
            bracket(ops::empty, x, &mut out);
            bracket(op, x, &mut out);
        }
    }
    black_box(out);
    hprintln!("bench done");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

fn quat(q: rigtform::Quat) -> [f32; 4] {
    [q.w, q.x, q.y, q.z]
}
