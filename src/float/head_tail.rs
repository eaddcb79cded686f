//! Constants split into a head and a tail, and the exact sum that keeps a
//! tail: the few pieces of two-float arithmetic the kernels share.
//!
//! HI is the f32 nearest the constant, LO the f32 nearest the rest
//! (constant - HI), so that HI + LO carries about 48 bits.

/// pi/2 rounded to f32 (0x3fc90fdb).
pub(super) const PIO2_HI: f32 = core::f32::consts::FRAC_PI_2;
/// pi/2 - [`PIO2_HI`] rounded to f32 (0xb33bbd2e).
pub(super) const PIO2_LO: f32 = -4.371_139e-8;
/// pi/4 rounded to f32 (0x3f490fdb).
pub(super) const PIO4_HI: f32 = core::f32::consts::FRAC_PI_4;
/// pi/4 - [`PIO4_HI`] rounded to f32 (0xb2bbbd2e).
pub(super) const PIO4_LO: f32 = -2.185_569_4e-8;
/// pi rounded to f32 (0x40490fdb).
pub(super) const PI_HI: f32 = core::f32::consts::PI;
/// pi - [`PI_HI`] rounded to f32 (0xb3bbbd2e).
pub(super) const PI_LO: f32 = -8.742_278e-8;

/// `hi + lo` rounded to f32, and the tail that the rounding lost (exact,
/// Fast2Sum; `|hi| >= |lo|`).
#[inline]
pub(super) fn sum_and_tail(hi: f32, lo: f32) -> (f32, f32) {
    let r = hi + lo;
    (r, (hi - r) + lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each head is the constant rounded to f32 and each tail the rest,
    /// checked in f64 (whose 53 bits hold head + tail exactly).
    #[test]
    fn heads_and_tails_add_up_to_the_constants() {
        use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        for (hi, lo, exact) in [
            (PIO2_HI, PIO2_LO, FRAC_PI_2),
            (PIO4_HI, PIO4_LO, FRAC_PI_4),
            (PI_HI, PI_LO, PI),
        ] {
            assert_eq!(hi, exact as f32);
            assert_eq!(lo, (exact - hi as f64) as f32);
        }
    }

    #[test]
    fn sum_and_tail_loses_nothing() {
        let (r, t) = sum_and_tail(1.0, 1e-9);
        assert_eq!(r, 1.0);
        assert_eq!(r as f64 + t as f64, 1.0 + 1e-9f32 as f64);
    }
}
