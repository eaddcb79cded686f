//! The square root: the FPU's `vsqrt.f32` on Arm hard-float targets, libm's
//! `sqrtf` elsewhere. Correctly rounded (0.5 ulp) either way.

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
