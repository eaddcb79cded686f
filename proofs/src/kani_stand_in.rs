//! A stand-in for the `kani` functions the harnesses use (`any`,
//! `any_where`, `assume`, `cover!`), so that their bodies also run as
//! ordinary tests where Kani is not installed (as on our machines).
//! Compiled only for tests without `cfg(kani)`; the harnesses import it
//! under the name `kani`, which under Kani is the real crate.
//!
//! It is a random tester, not a model checker: each harness body runs
//! [`draw_count`] times (50,000 by default; `RIGTFORM_PROOF_DRAWS` sets
//! it) on inputs drawn by [`Draws::f32_mixed`](crate::draw::Draws::f32_mixed)
//! (edge values, moderate values and raw bit patterns; a signalling NaN is
//! drawn as the quiet NaN of the same payload, since Kani's solver knows one
//! kind of NaN). A draw that fails `assume` is thrown away and drawn again;
//! `any_where` retries its own value first. Every value or draw thrown away
//! counts as a rejection, and a harness fails when fewer than one draw in
//! [`MIN_ACCEPTANCE_INVERSE`] is kept. A failing draw prints its seed, and
//! `RIGTFORM_PROOF_SEED=<seed> RIGTFORM_PROOF_DRAWS=1` replays it.
//!
//! What Kani flags and a random test would not see: Kani checks every float
//! operation for making a NaN from operands that are not NaN (`0 / 0`,
//! `inf - inf`, `inf * 0`), whatever the result is then used for. In debug
//! builds on x86-64 the stand-in reads the SSE invalid-operation flag after
//! every draw (kept or rejected: Kani checks the operations before a failed
//! assumption too), and a draw that raised it fails the harness. Quiet NaN
//! operands do not raise it, so the flag marks exactly the NaNs made from
//! numbers (and float-to-integer conversions out of range, which Kani does
//! not check and the crate's code on the harnesses' paths does not make).
//!
//! `cover!` counts the kept draws that meet its condition; a harness fails
//! if one of its covers is met by none of them (the branch it names was not
//! reached, so its law was not tested there).

use crate::draw::Draws;
use std::cell::{Cell, RefCell};
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

std::thread_local! {
    static SOURCE: RefCell<Draws> = const { RefCell::new(Draws::new(0)) };
    /// Values thrown away inside `any_where` since the harness started.
    static RETRIED: Cell<usize> = const { Cell::new(0) };
    /// Each `cover!` of the running harness, with its kept hits; the hits
    /// of the running draw are counted once it is kept.
    static COVERS: RefCell<Vec<Cover>> = const { RefCell::new(Vec::new()) };
}

/// One `cover!` site: its message, whether the running draw met it, and
/// how many kept draws did.
struct Cover {
    message: &'static str,
    in_this_draw: bool,
    kept_hits: usize,
}

/// The harness fails when fewer than one draw (or value) in this many is
/// kept: its assumptions would then test too little to mean anything.
pub const MIN_ACCEPTANCE_INVERSE: usize = 20;

/// The payload of a rejected draw (an `assume` that failed).
struct Rejected;

/// Values the stand-in can draw.
pub trait Arbitrary: Sized {
    /// One value from `d`.
    fn draw(d: &mut Draws) -> Self;
}

impl Arbitrary for f32 {
    fn draw(d: &mut Draws) -> Self {
        // On the bits: even comparing a signalling NaN raises the
        // invalid-operation flag, which must mean a NaN made from numbers.
        let bits = d.f32_mixed().to_bits();
        if bits & 0x7fff_ffff > 0x7f80_0000 {
            f32::from_bits(bits | 0x0040_0000) // the quiet bit
        } else {
            f32::from_bits(bits)
        }
    }
}

impl Arbitrary for bool {
    fn draw(d: &mut Draws) -> Self {
        d.next_u32() & 1 == 1
    }
}

impl Arbitrary for u32 {
    fn draw(d: &mut Draws) -> Self {
        d.next_u32()
    }
}

/// Any value of `T` (`kani::any`).
pub fn any<T: Arbitrary>() -> T {
    SOURCE.with(|s| T::draw(&mut s.borrow_mut()))
}

/// Any value of `T` that meets `keep` (`kani::any_where`): up to 64 tries,
/// then the whole draw is rejected.
pub fn any_where<T: Arbitrary, F: Fn(&T) -> bool>(keep: F) -> T {
    for _ in 0..64 {
        let value = any();
        if keep(&value) {
            return value;
        }
        RETRIED.with(|r| r.set(r.get() + 1));
    }
    assume(false);
    any()
}

/// Marks that the running draw met `condition`, named by `message`
/// (`kani::cover!`).
pub fn record_cover(condition: bool, message: &'static str) {
    COVERS.with(|c| {
        let mut covers = c.borrow_mut();
        let at = match covers.iter().position(|k| k.message == message) {
            Some(at) => at,
            None => {
                covers.push(Cover {
                    message,
                    in_this_draw: false,
                    kept_hits: 0,
                });
                covers.len() - 1
            }
        };
        if let Some(k) = covers.get_mut(at) {
            k.in_this_draw |= condition;
        }
    });
}

/// `kani::cover!(condition, message)`: see [`cover`].
macro_rules! cover {
    ($condition:expr, $message:literal) => {
        $crate::kani_stand_in::record_cover($condition, $message)
    };
}
pub(crate) use cover;

/// Counts the covers the draw just run met, if it was kept, and clears
/// them for the next.
fn settle_covers(kept: bool) {
    COVERS.with(|c| {
        for k in c.borrow_mut().iter_mut() {
            if kept && k.in_this_draw {
                k.kept_hits += 1;
            }
            k.in_this_draw = false;
        }
    });
}

/// Reads and clears the x86-64 invalid-operation flag (MXCSR bit 0, with
/// the other five exception flags): whether an SSE operation made a NaN
/// from numbers (or converted an out-of-range float to an integer) since
/// the last call.
#[cfg(all(target_arch = "x86_64", debug_assertions))]
#[allow(unsafe_code)]
fn take_invalid_flag() -> bool {
    let mut csr: u32 = 0;
    // SAFETY: stmxcsr stores this thread's SSE control and status register
    // into `csr`, a live u32; ldmxcsr loads it back with the six sticky
    // exception flags cleared, changing neither masks nor rounding.
    unsafe {
        core::arch::asm!("stmxcsr [{}]", in(reg) &mut csr, options(nostack));
        let cleared = csr & !0x3f;
        core::arch::asm!("ldmxcsr [{}]", in(reg) &cleared, options(nostack, readonly));
    }
    csr & 1 != 0
}

/// Release builds may fold or reorder float operations, and other targets
/// have their own flag registers: the check runs in debug builds on x86-64.
#[cfg(not(all(target_arch = "x86_64", debug_assertions)))]
fn take_invalid_flag() -> bool {
    false
}

/// Whether [`run`] checks the invalid-operation flag on this build.
const CHECKS_INVALID_FLAG: bool = cfg!(all(target_arch = "x86_64", debug_assertions));

/// Only the draws that meet `condition` count (`kani::assume`).
pub fn assume(condition: bool) {
    if !condition {
        panic::panic_any(Rejected);
    }
}

/// How many accepted draws each harness runs.
pub fn draw_count() -> usize {
    std::env::var("RIGTFORM_PROOF_DRAWS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(50_000)
}

fn base_seed() -> u64 {
    std::env::var("RIGTFORM_PROOF_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_2026)
}

/// Runs `body` on [`draw_count`] accepted draws, each from its own seed.
/// Panics (failing the test) with the seed of the first draw that breaks
/// the body or raises the invalid-operation flag, when fewer than one draw
/// or value in [`MIN_ACCEPTANCE_INVERSE`] was kept, or when a `cover!` was
/// met by no kept draw. Prints the counts.
pub fn run(name: &str, body: impl Fn()) {
    static QUIET_REJECTIONS: Once = Once::new();
    QUIET_REJECTIONS.call_once(|| {
        let default = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if !info.payload().is::<Rejected>() {
                default(info);
            }
        }));
    });
    let wanted = draw_count();
    let mut seeds = Draws::new(base_seed());
    let (mut accepted, mut rejected) = (0usize, 0usize);
    RETRIED.with(|r| r.set(0));
    COVERS.with(|c| c.borrow_mut().clear());
    let too_many = |rejected: usize, retried: usize| {
        rejected + retried > (MIN_ACCEPTANCE_INVERSE - 1) * wanted.max(1)
    };
    // The first draw replays the base seed itself (what a failure prints).
    let mut seed = base_seed();
    take_invalid_flag();
    while accepted < wanted && !too_many(rejected, RETRIED.with(Cell::get)) {
        SOURCE.with(|s| *s.borrow_mut() = Draws::new(seed));
        let outcome = panic::catch_unwind(AssertUnwindSafe(&body));
        let kept = outcome.is_ok();
        let invalid = take_invalid_flag();
        settle_covers(kept);
        let replay = format!("RIGTFORM_PROOF_SEED={seed} RIGTFORM_PROOF_DRAWS=1");
        match outcome {
            Err(payload) if !payload.is::<Rejected>() => {
                eprintln!("{name}: failed on draw {accepted}; replay with {replay}");
                panic::resume_unwind(payload);
            }
            _ if invalid => panic!(
                "{name}: draw {accepted} made a NaN from numbers (the invalid-operation \
                 flag), which Kani fails; replay with {replay}"
            ),
            Ok(()) => accepted += 1,
            Err(_) => rejected += 1,
        }
        seed = seeds.next_u64();
    }
    let retried = RETRIED.with(Cell::get);
    let flag = if CHECKS_INVALID_FLAG {
        "none raised the invalid-operation flag"
    } else {
        "invalid-operation flag not checked in this build"
    };
    println!(
        "{name}: {accepted} draws kept, {rejected} rejected by assume, {retried} values \
         redrawn by any_where; {flag}"
    );
    let covers: Vec<(&'static str, usize)> = COVERS.with(|c| {
        c.borrow()
            .iter()
            .map(|k| (k.message, k.kept_hits))
            .collect()
    });
    for (message, hits) in &covers {
        println!("{name}: cover \"{message}\" met by {hits} kept draws");
    }
    assert!(
        accepted == wanted,
        "{name}: only {accepted} of {wanted} draws kept ({rejected} rejected, {retried} values \
         redrawn): fewer than one in {MIN_ACCEPTANCE_INVERSE}"
    );
    if let Some((message, _)) = covers.iter().find(|(_, hits)| *hits == 0) {
        panic!("{name}: no kept draw met cover \"{message}\"");
    }
}
