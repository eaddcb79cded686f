//! Reproducible pseudo-random draws without `std` or allocation, for the
//! proof stand-in and the on-target tests (which cannot link `rand`'s
//! operating-system seeding, and need the same sequence on every machine).
//!
//! The generator is SplitMix64 (G. Steele, D. Lea, C. Flood, *Fast
//! splittable pseudorandom number generators*, OOPSLA 2014): a 64-bit
//! counter passed through a bijective mixer. It passes BigCrush, which is
//! far more than drawing test inputs needs.

use crate::edge::EDGE_F32;
use rigtform::{Cvec3, Quat};

/// A seeded stream of test inputs.
#[derive(Clone, Debug)]
pub struct Draws {
    state: u64,
}

impl Draws {
    /// A stream that depends only on `seed`.
    pub const fn new(seed: u64) -> Self {
        Self { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        // SplitMix64's increment (the golden ratio in 64 bits) and its two
        // multiply-xorshift rounds (the constants of the paper's mix64).
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        (self.next_u64() >> 32) as u32
    }

    /// A uniform integer in `0..n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        // Lemire's multiply-shift: bias below 2^-32 for the small n used here.
        ((self.next_u32() as u64 * n as u64) >> 32) as usize
    }

    /// A uniform `f32` in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        // 24 random bits: every multiple of 2^-24 in [0, 1) equally likely.
        let unit = (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
        lo + (hi - lo) * unit
    }

    /// An `f32` from a mixture that finds edge cases: a quarter are
    /// [`EDGE_F32`] values, a quarter moderate values (random sign and
    /// mantissa, magnitude between 2^-20 and 2^20), and half raw random bit
    /// patterns (every `f32`, NaNs and infinities included).
    pub fn f32_mixed(&mut self) -> f32 {
        match self.below(4) {
            0 => EDGE_F32
                .get(self.below(EDGE_F32.len()))
                .copied()
                .unwrap_or(0.0),
            1 => {
                let bits = self.next_u32();
                let exponent = 127 - 20 + (bits % 41); // 2^-20 ..= 2^20
                f32::from_bits((bits & 0x8000_0000) | (exponent << 23) | (bits >> 9))
            }
            _ => f32::from_bits(self.next_u32()),
        }
    }

    /// A uniformly distributed unit quaternion (rejection from the 4-cube,
    /// then normalized in `f32`), so a uniformly distributed rotation.
    pub fn unit_quat(&mut self) -> Quat {
        loop {
            let q = Quat::from_wxyz(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let n2 = q.norm_squared();
            if (0.01..=1.0).contains(&n2) {
                return q.normalize();
            }
        }
    }

    /// A vector with components uniform in `[-r, r)`.
    pub fn vec3(&mut self, r: f32) -> Cvec3 {
        Cvec3::new(
            self.uniform(-r, r),
            self.uniform(-r, r),
            self.uniform(-r, r),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_gives_the_same_stream_and_different_seeds_differ() {
        let (mut a, mut b, mut c) = (Draws::new(7), Draws::new(7), Draws::new(8));
        let xs: [u64; 4] = core::array::from_fn(|_| a.next_u64());
        let ys: [u64; 4] = core::array::from_fn(|_| b.next_u64());
        let zs: [u64; 4] = core::array::from_fn(|_| c.next_u64());
        assert_eq!(xs, ys);
        assert_ne!(xs, zs);
    }

    #[test]
    fn uniform_and_below_stay_in_range_and_cover_it() {
        let mut d = Draws::new(1);
        let (mut lo, mut hi) = (f32::MAX, f32::MIN);
        let mut seen = [false; 5];
        for _ in 0..10_000 {
            let x = d.uniform(-2.0, 3.0);
            assert!((-2.0..3.0).contains(&x), "{x}");
            lo = lo.min(x);
            hi = hi.max(x);
            let k = d.below(5);
            seen[k] = true;
        }
        assert!(lo < -1.99 && hi > 2.99, "{lo} {hi}");
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn mixed_draws_include_edges_moderates_and_non_finite_values() {
        let mut d = Draws::new(2);
        let draws: [f32; 4000] = core::array::from_fn(|_| d.f32_mixed());
        assert!(draws.iter().any(|x| x.is_nan()));
        assert!(draws.contains(&f32::MAX));
        assert!(draws
            .iter()
            .any(|&x| x != 0.0 && x.abs() < f32::MIN_POSITIVE));
        assert!(draws.iter().any(|&x| (1e-6..1e6).contains(&x.abs())));
    }

    #[test]
    fn unit_quats_are_unit_and_spread_over_both_hemispheres() {
        let mut d = Draws::new(3);
        let mut negative_w = 0;
        for _ in 0..1000 {
            let q = d.unit_quat();
            assert!((q.norm() - 1.0).abs() < 3e-7, "{q:?}");
            negative_w += usize::from(q.w < 0.0);
        }
        assert!((400..600).contains(&negative_w), "{negative_w}");
    }
}
