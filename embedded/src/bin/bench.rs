//! Instructions executed per call of each operation of `rigtform_embedded::ops`
//! (rigtform, glam, nalgebra, micromath), on an emulated Cortex-M4F.
//!
//! Each call is bracketed by the markers of [`rigtform_embedded::measure`],
//! and so is the same call of [`ops::empty`] on the same input just before
//! it (the calibration: passing the input in and the result out). Each
//! operation is announced as a row `operation|library|function` with the
//! number of inputs. Run it with `cargo xtask m4f`, not directly.

#![no_std]
#![no_main]

use core::hint::black_box;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use panic_semihosting as _;
use rigtform_embedded::measure;
use rigtform_embedded::ops::{self, Input, Op, Output};
use rigtform_proofs::draw::Draws;

/// Inputs per operation; the xtask reports the mean count over them.
const INPUTS: usize = 8;

/// One call of `op`, between the markers. The input is hidden from the
/// optimizer after the first marker and the result handed out before the
/// second, so the work stays inside.
#[inline(never)]
fn bracket(op: Op, x: &Input, out: &mut Output) {
    measure::start();
    black_box(op)(black_box(x), black_box(&mut *out));
    measure::end();
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
    for e in ops::OPS {
        measure::row(INPUTS, &[e.operation, e.library, e.function]);
        for x in &inputs {
            bracket(ops::empty, x, &mut out);
            bracket(e.op, x, &mut out);
        }
    }
    black_box(out);
    measure::done(ops::OPS.len());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

fn quat(q: rigtform::Quat) -> [f32; 4] {
    [q.w, q.x, q.y, q.z]
}
