//! A stand-in for the three `kani` functions the harnesses use, so that
//! their bodies also run as ordinary tests where Kani is not installed
//! (as on our machines). Compiled only for tests without `cfg(kani)`; the
//! harnesses import it under the name `kani`, which under Kani is the real
//! crate.
//!
//! It is a random tester, not a model checker: each harness body runs
//! [`draw_count`] times (50,000 by default; `RIGTFORM_PROOF_DRAWS` sets
//! it) on inputs drawn by [`Draws::f32_mixed`](crate::draw::Draws::f32_mixed)
//! (edge values, moderate values and raw bit patterns). A draw that fails
//! `assume` is thrown away and drawn again; `any_where` retries its own
//! value first. A failing draw prints its seed, and
//! `RIGTFORM_PROOF_SEED=<seed> RIGTFORM_PROOF_DRAWS=1` replays it.

use crate::draw::Draws;
use std::cell::RefCell;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

std::thread_local! {
    static SOURCE: RefCell<Draws> = const { RefCell::new(Draws::new(0)) };
}

/// The payload of a rejected draw (an `assume` that failed).
struct Rejected;

/// Values the stand-in can draw.
pub trait Arbitrary: Sized {
    /// One value from `d`.
    fn draw(d: &mut Draws) -> Self;
}

impl Arbitrary for f32 {
    fn draw(d: &mut Draws) -> Self {
        d.f32_mixed()
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
    }
    assume(false);
    any()
}

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
/// the body, or when more than twenty draws per wanted one were rejected
/// (a harness whose assumptions throw nearly everything away tests little).
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
    // The first draw replays the base seed itself (what a failure prints).
    let mut seed = base_seed();
    while accepted < wanted && rejected <= 20 * wanted {
        SOURCE.with(|s| *s.borrow_mut() = Draws::new(seed));
        match panic::catch_unwind(AssertUnwindSafe(&body)) {
            Ok(()) => accepted += 1,
            Err(payload) if payload.is::<Rejected>() => rejected += 1,
            Err(payload) => {
                eprintln!(
                    "{name}: failed on draw {accepted}; replay with \
                     RIGTFORM_PROOF_SEED={seed} RIGTFORM_PROOF_DRAWS=1"
                );
                panic::resume_unwind(payload);
            }
        }
        seed = seeds.next_u64();
    }
    println!("{name}: checked by {accepted} random draws ({rejected} rejected by assume)");
    assert!(
        accepted == wanted,
        "{name}: only {accepted} of {wanted} draws met the assumptions"
    );
}
