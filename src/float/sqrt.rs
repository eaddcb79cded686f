//! The square root: one instruction of the processor where it has one
//! (`vsqrt.f32` on Arm hard-float targets, `sqrtss` on x86-64, `fsqrt` on
//! AArch64), libm's `sqrtf` elsewhere. Correctly rounded (0.5 ulp) either
//! way.

/// Square root, correctly rounded (0.5 ulp), with both backends.
///
/// - On Arm hard-float targets (`thumbv7em-none-eabihf` and every other
///   `eabihf` target: the hard-float ABI implies a VFP unit, and every VFP
///   has `vsqrt.f32`) this is that one FPU instruction, through
///   [`fpu_sqrt`]: libm's `sqrtf` is a bit-by-bit software loop there
///   (about 50 instructions).
/// - On x86-64 with SSE and AArch64 with NEON (every hosted target of
///   either) it is the vector unit's square root, through `core::arch`'s
///   intrinsic, which the compiler sees as a square root: a loop that calls
///   it vectorizes (`sqrtps`, `fsqrt v.4s`), as `Quat::slerp_slice`'s does.
///   libm's `sqrtf` is the same instruction there, but in inline assembly,
///   which a loop vectorizer cannot look into.
/// - Elsewhere it is libm's `sqrtf`.
/// - Under Kani (`cfg(kani)`), which reads none of these, it is the one
///   f32 that the correctly rounded square root is, described instead of
///   computed (`float/sqrt_kani.rs`).
#[inline]
#[must_use]
pub fn sqrt(x: f32) -> f32 {
    #[cfg(kani)]
    return super::sqrt_kani::sqrt(x);
    #[cfg(arm_fpu_sqrt)]
    return fpu_sqrt(x);
    #[cfg(vector_unit_sqrt)]
    return vector_unit_sqrt(x);
    #[cfg(not(any(arm_fpu_sqrt, vector_unit_sqrt, kani)))]
    return libm::sqrtf(x);
}

/// `sqrtss`, the correctly rounded square root of SSE, through
/// `core::arch`'s intrinsics: one of the few places of the crate's `unsafe`
/// code (src/lib.rs lists them).
///
/// The intrinsics are `#[target_feature]` functions, `unsafe` to call
/// from a function that does not enable the feature itself.
#[cfg(all(vector_unit_sqrt, target_arch = "x86_64"))]
#[allow(unsafe_code)]
#[inline(always)]
fn vector_unit_sqrt(x: f32) -> f32 {
    use core::arch::x86_64::{_mm_cvtss_f32, _mm_set_ss, _mm_sqrt_ss};
    // SAFETY: the three intrinsics need SSE, which this function is
    // compiled only with (`target_feature = "sse"`, enabled on every
    // x86-64 target but the soft-float kernel ones). They read and write
    // no memory; `sqrtss` answers NaN for negative or NaN input, as
    // IEEE 754 says, and cannot fault with the default MXCSR (exceptions
    // masked).
    unsafe { _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(x))) }
}

/// `fsqrt`, the correctly rounded square root of AArch64's SIMD and
/// floating-point unit, through `core::arch`'s NEON intrinsics on lane 0 of
/// a two-lane vector (the compiler reduces it to the scalar `fsqrt s`): one
/// of the few places of the crate's `unsafe` code (src/lib.rs lists
/// them).
///
/// The intrinsics are `#[target_feature]` functions, `unsafe` to call
/// from a function that does not enable the feature itself.
#[cfg(all(vector_unit_sqrt, target_arch = "aarch64"))]
#[allow(unsafe_code)]
#[inline(always)]
fn vector_unit_sqrt(x: f32) -> f32 {
    use core::arch::aarch64::{vdup_n_f32, vget_lane_f32, vsqrt_f32};
    // SAFETY: the three intrinsics need NEON, which this function is
    // compiled only with (`target_feature = "neon"`, enabled on every
    // AArch64 target but the soft-float ones). They read and write no
    // memory, and `fsqrt` answers NaN for negative or NaN input, as
    // IEEE 754 says, without trapping (floating-point traps are disabled
    // by default).
    unsafe { vget_lane_f32::<0>(vsqrt_f32(vdup_n_f32(x))) }
}

/// `vsqrt.f32`, the correctly rounded square root of the Arm FPU: one of
/// the few places of the crate's `unsafe` code (src/lib.rs lists them).
///
/// Stable Rust has no safe way to reach it in `no_std` code: `f32::sqrt` is
/// in `std` only (its `core` version is unstable), libm has no Arm FPU path,
/// and the `sreg` register class of `asm!` needs the `vfp2` target feature,
/// which stable Rust does not expose for Arm. So the value goes in and out
/// through a core register, and `s0` is saved and restored around the
/// instruction (five instructions in all).
#[cfg(arm_fpu_sqrt)]
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
        // Fewer points under Miri, which interprets every instruction.
        let (n, wide) = if cfg!(miri) {
            (200, 50)
        } else {
            (200_000, 10_000)
        };
        for x in spread(0.0, 4.0, n).chain(spread(1e-30, 1e30, wide)) {
            worst = worst.max(ulps(sqrt(x), (x as f64).sqrt()) * f32::EPSILON as f64);
        }
        std::println!("sqrt: max relative error {worst:.3e}");
        assert!(worst <= accuracy::SQRT_MAX_REL_ERROR as f64, "{worst}");
    }
}
