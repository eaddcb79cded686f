//! Bit-level helpers of the branch-free kernels.

/// The sign bit of an f32.
pub(crate) const SIGN: u32 = 0x8000_0000;

/// `if c { a } else { b }`, by bit masks: no branch for the data to
/// mispredict (both values are computed anyway).
#[inline]
pub(crate) fn select(c: bool, a: f32, b: f32) -> f32 {
    let mask = u32::from(c).wrapping_neg();
    f32::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn select_picks_by_the_condition_and_keeps_every_bit() {
        assert_eq!(select(true, -0.0, 1.0).to_bits(), (-0.0f32).to_bits());
        assert_eq!(select(false, 1.0, -0.0).to_bits(), (-0.0f32).to_bits());
        assert!(select(true, f32::NAN, 1.0).is_nan());
        assert_eq!(select(false, f32::NAN, 2.5), 2.5);
    }
}
