//! The square root: the FPU's `vsqrt.f32` on Arm hard-float targets, libm's
//! `sqrtf` elsewhere. Correctly rounded (0.5 ulp) either way. Beside them,
//! [`sqrt_by_newton`], the same results in arithmetic that a loop can
//! vectorize.

#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
use super::bits::select;

/// Square root, correctly rounded (0.5 ulp), with both backends.
///
/// On Arm hard-float targets (`thumbv7em-none-eabihf` and every other
/// `eabihf` target: the hard-float ABI implies a VFP unit, and every VFP has
/// `vsqrt.f32`) this is that one FPU instruction, through [`fpu_sqrt`]:
/// libm's `sqrtf` is a bit-by-bit software loop there (about 50
/// instructions). Elsewhere it is libm's `sqrtf`, which uses the hardware
/// instruction where libm knows one (`sqrtss` on x86-64).
///
/// `fast-math` keeps it on purpose: micromath's `sqrt` is a single
/// bit-level estimate with a relative error of up to 6.1 % (6.066e-2 over
/// [1e-3, 4], `micromaths_sqrt_is_too_coarse_for_normalize`; and its
/// `sqrt(0)` is 8e-20), which would leave `normalize` nearly useless.
#[inline]
#[must_use]
pub fn sqrt(x: f32) -> f32 {
    #[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
    return fpu_sqrt(x);
    #[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
    return libm::sqrtf(x);
}

/// Square root of `0 <= x <= f32::MAX`, correctly rounded (so equal to
/// [`sqrt`], bit for bit), in plain arithmetic: no square root instruction
/// and no inline assembly, so that the compiler can vectorize a loop that
/// calls it (libm's `sqrtf` on x86-64 is inline assembly, which a loop
/// vectorizer cannot look into, and `core` has no stable square root).
/// Used by [`Quat::slerp_slice`](crate::Quat::slerp_slice) on 64-bit
/// desktop targets; it costs more than one `sqrtss` per call.
///
/// In f64 (where `x` is exact): the inverse square root from the well-known
/// bit-level estimate (a magic constant less half the bits; relative error
/// below 3.5 %), three Newton steps (below 4e-11),
/// times `x`, rounded to f32: within an ulp of the correctly rounded root.
/// Then the neighbour whose midpoint with it lies on the other side of
/// `sqrt(x)` replaces it: the midpoint of two adjacent f32 has 25
/// significant bits, so its square is exact in f64 and the comparison with
/// `x` is exact (and never equal: such a square has more significant bits
/// than an f32).
///
/// # Preconditions
///
/// `x` is finite and not negative (+0 and subnormals included); for other
/// input the result is unspecified (but never a panic).
///
/// # Accuracy
///
/// Correctly rounded: `sqrt_by_newton_equals_sqrt_on_a_sample` compares it
/// with [`sqrt`] bit for bit on every 997th f32, and the ignored
/// `sqrt_by_newton_exhaustive_kernel_sweep` on every f32 of [0, f32::MAX].
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
// With fast-math, slerp_slice is a loop of slerp and this goes unused
// (its tests still check it).
#[cfg_attr(feature = "fast-math", allow(dead_code))]
#[inline(always)]
#[must_use]
pub(crate) fn sqrt_by_newton(x: f32) -> f32 {
    let y = f64::from(x);
    let mut r = f64::from_bits(0x5fe6_eb50_c7b5_37a9_u64.wrapping_sub(y.to_bits() >> 1));
    let half_y = 0.5 * y;
    for _ in 0..3 {
        r *= 1.5 - half_y * r * r;
    }
    let c = (y * r) as f32;
    // c is at most f32::MAX's root, far below infinity: its successor's
    // bits do not wrap. Below 0 there is nothing: 0 stays its own lower
    // neighbour.
    let up = f32::from_bits(c.to_bits().wrapping_add(1));
    let down = f32::from_bits(c.to_bits().saturating_sub(1));
    let mid_up = (f64::from(c) + f64::from(up)) * 0.5;
    let mid_down = (f64::from(c) + f64::from(down)) * 0.5;
    let c = select(y > mid_up * mid_up, up, c);
    select(y < mid_down * mid_down, down, c)
}

/// `vsqrt.f32`, the correctly rounded square root of the Arm FPU: the one
/// `unsafe` block of the crate.
///
/// Stable Rust has no safe way to reach it in `no_std` code: `f32::sqrt` is
/// in `std` only (its `core` version is unstable), libm has no Arm FPU path,
/// and the `sreg` register class of `asm!` needs the `vfp2` target feature,
/// which stable Rust does not expose for Arm. So the value goes in and out
/// through a core register, and `s0` is saved and restored around the
/// instruction (five instructions in all).
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[allow(unsafe_code)]
#[inline]
fn fpu_sqrt(x: f32) -> f32 {
    let bits: u32;
    // SAFETY: the block reads only its input register and writes only its
    // output register and `s0`, which it pushes first and pops last; the
    // push and pop use the stack below the stack pointer, which asm! allows
    // (no `nostack`). `vsqrt.f32` cannot fault: the FPU answers NaN for
    // negative or NaN input, as IEEE 754 says. Every `eabihf` target has a
    // VFP unit, since its calling convention passes floats in `s` registers.
    unsafe {
        core::arch::asm!(
            "vpush {{s0}}",
            "vmov s0, {x}",
            "vsqrt.f32 s0, s0",
            "vmov {r}, s0",
            "vpop {{s0}}",
            x = in(reg) x.to_bits(),
            r = lateout(reg) bits,
            options(pure, nomem, preserves_flags),
        );
    }
    f32::from_bits(bits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy;
    use crate::float::sweep::{spread, ulps};

    /// `sqrt_by_newton` and `sqrt`, bit for bit, on every `step`-th f32 of
    /// [0, f32::MAX].
    #[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
    fn sqrt_by_newton_sweep(step: usize) {
        let top = f32::MAX.to_bits();
        for bits in (0..=top).step_by(step).chain([top, 1, 0x0080_0000]) {
            let x = f32::from_bits(bits);
            assert_eq!(
                sqrt_by_newton(x).to_bits(),
                sqrt(x).to_bits(),
                "sqrt_by_newton({x:e})"
            );
        }
    }

    #[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
    #[test]
    fn sqrt_by_newton_equals_sqrt_on_a_sample() {
        sqrt_by_newton_sweep(997);
    }

    /// Every f32 of [0, f32::MAX]:
    /// `cargo test --release --lib -- --ignored exhaustive_kernel_sweep`.
    #[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
    #[test]
    #[ignore = "seconds in release, minutes in debug: run by hand after changing it"]
    fn sqrt_by_newton_exhaustive_kernel_sweep() {
        sqrt_by_newton_sweep(1);
    }

    #[test]
    fn sweep_sqrt() {
        let mut worst: f64 = 0.0;
        for x in spread(0.0, 4.0, 200_000).chain(spread(1e-30, 1e30, 10_000)) {
            worst = worst.max(ulps(sqrt(x), (x as f64).sqrt()) * f32::EPSILON as f64);
        }
        std::println!("sqrt: max relative error {worst:.3e}");
        assert!(worst <= accuracy::SQRT_MAX_REL_ERROR as f64, "{worst}");
    }
}
