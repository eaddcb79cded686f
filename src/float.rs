//! The one door to the float backend.
//!
//! Every square root and transcendental function the crate evaluates goes
//! through this file, so that a backend can be swapped (feature `fast-math`),
//! stubbed by a proof harness, or replaced by a faster kernel in one place.
//!
//! - default: f32-only kernels written here, for the arguments `pow` and
//!   `slerp` produce: [`atan2`] (one division onto [-tan(1/2), tan(1/2)]
//!   and a degree-13 odd minimax polynomial) and [`sin_cos`] (a degree-7 and
//!   a degree-8 minimax polynomial on [-pi/4, pi/4]; arguments up to 3 pi/4,
//!   all that slerp produces for `alpha` in [0, 1], need one subtraction,
//!   and every other finite argument an exact integer reduction by pi/2).
//!   Nothing is evaluated in f64, so on a Cortex-M4F (single-precision FPU)
//!   no soft-float helper is linked, and each kernel stays within 1 to 1.6
//!   ulp (the bound is in each doc comment; the tests at the bottom of this
//!   file sweep every f32 of each range, see `exhaustive_kernel_sweeps`).
//!   The coefficients come from `tools/minimax.py` (Remez exchange in
//!   multiple precision); the 2/pi bits and the split constants were
//!   computed with the same tool, and agree with FreeBSD msun's
//!   `k_rem_pio2.c` table.
//! - `fast-math`: [`micromath`]'s approximations of atan2, sin, cos and tan,
//!   with the much larger errors the sweep tests measure for them (see
//!   [`crate::accuracy`]), guarded where micromath breaks down: rescaled
//!   arguments, Taylor terms near zero, and the default kernels for zero,
//!   huge or non-finite arguments.
//!
//! The square root is the FPU's `vsqrt.f32` on Arm hard-float targets and
//! libm's `sqrtf` elsewhere (on x86-64 that is the `sqrtss` instruction);
//! the tangent, used only by `Matrix4::perspective`, is libm's `tanf`.
//!
//! It also holds [`scale_for_squares`], the overflow- and underflow-free sum of
//! squares behind every `norm` and `normalize` of the crate.

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

/// Four-quadrant arctangent of `y / x`, in [-pi, pi], with IEEE 754's
/// results for zeros and infinities (`atan2(+-0, -0) = +-pi`,
/// `atan2(inf, inf) = pi/4`, ...) and NaN for NaN.
///
/// Default backend: [`atan2_kernel`], within 1.6 ulp of the result
/// ([`ATAN2_ULP`]).
///
/// fast-math: micromath's rational approximation, absolute error about
/// 3e-3 rad (measured by `sweep_atan2` below), on arguments with magnitudes
/// within [2^-20, 2^20] (others are first divided by the larger magnitude),
/// where its squares cannot overflow or underflow (micromath's
/// `atan2(1e-30, 1e-30)` is NaN); the default kernel where either argument
/// is zero or not finite. The result gets the sign of `y`, as atan2's always
/// has: micromath returns +pi instead of -pi for a tiny negative `y` against
/// a negative `x`.
#[inline]
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    #[cfg(feature = "fast-math")]
    if y.is_finite() && x.is_finite() && y != 0.0 && x != 0.0 {
        let largest = y.abs().max(x.abs());
        let (y, x) = if (FAST_ATAN2_LOW..=FAST_ATAN2_HIGH).contains(&largest) {
            (y, x)
        } else {
            (y / largest, x / largest)
        };
        // The smaller argument may now be tiny beside the larger, or even
        // zero: its square then vanishes, which only rounds the angle to 0,
        // pi/2 or pi, as it should.
        return micromath::F32Ext::atan2(y, x).copysign(y);
    }
    atan2_kernel(y, x)
}

/// Sine and cosine of `x` (radians), as `(sin, cos)`.
///
/// Default backend: [`sin_cos_kernel`], within 1 ulp for `|x| <= 3 pi/4`
/// and within 1.25 ulp for every other finite `x` (exact argument reduction
/// for any size).
///
/// fast-math: micromath's parabola approximations, absolute error
/// about 1e-3 (measured by `sweep_sin_cos` below), for
/// `2^-6 <= |x| <= 2^9`; the default kernel beyond, where micromath's own
/// reduction loses accuracy (and returns infinities past 2^16). Below
/// 2^-6, where micromath's absolute error would swamp small rotations (its
/// `sin(1e-5)` is 0), Taylor polynomials of degree 3 and 2 instead: error below `x^5 / 120` (8e-12)
/// and `x^4 / 24` (2.5e-9, under half an ulp of 1).
#[inline]
#[must_use]
pub fn sin_cos(x: f32) -> (f32, f32) {
    #[cfg(feature = "fast-math")]
    {
        let a = x.abs();
        if a < FAST_SIN_COS_TAYLOR {
            let x2 = x * x;
            // The x^4 / 24 term of the cosine is below 2.5e-9, under half an
            // ulp of 1: f32 cannot hold it.
            // x (1 - x^2/6) rather than x - x^3/6 keeps the sign of -0.
            return (x * (1.0 - x2 * (1.0 / 6.0)), 1.0 - x2 * 0.5);
        }
        if a <= FAST_SIN_COS_LIMIT {
            return (micromath::F32Ext::sin(x), micromath::F32Ext::cos(x));
        }
    }
    sin_cos_kernel(x)
}

/// Tangent of `x` (radians), for `Matrix4::perspective` only. libm: within
/// 1 ulp. fast-math: micromath's tangent (about 1 % relative error over
/// half fields of view, measured by `sweep_tan` below) for `|x| <= 2^9`,
/// libm beyond.
#[inline]
#[must_use]
pub(crate) fn tan(x: f32) -> f32 {
    #[cfg(feature = "fast-math")]
    if x.abs() <= FAST_SIN_COS_LIMIT {
        return micromath::F32Ext::tan(x);
    }
    libm::tanf(x)
}

/// `e^x - 1`, accurate also where `e^x` is close to 1: libm's `expm1f`
/// (within 1 ulp), with both backends (micromath has no `exp_m1`, and the
/// smoothing factors `1 - e^(-dt/tau)` built on it need relative accuracy
/// for `dt` far below `tau`).
#[inline]
#[must_use]
pub(crate) fn exp_m1(x: f32) -> f32 {
    libm::expm1f(x)
}

/// 2^-6: below this, fast-math's sine and cosine are Taylor polynomials.
#[cfg(feature = "fast-math")]
const FAST_SIN_COS_TAYLOR: f32 = 0.015625;
/// 2^9: beyond this, micromath's f32 range reduction loses accuracy (its
/// absolute error grows from 1.1e-3 below 2^9 to 6.7e-3 near 2^16, and
/// `sin^2 + cos^2` drifts from 1 by up to 8e-3), so the default kernel,
/// with its exact reduction, takes over. Found by the proof harness
/// `pow_is_unit_for_every_finite_input` run with `fast-math`.
#[cfg(feature = "fast-math")]
const FAST_SIN_COS_LIMIT: f32 = 512.0;
/// 2^20 and 2^-20: the range in which micromath's atan2 squares its arguments safely.
#[cfg(feature = "fast-math")]
const FAST_ATAN2_HIGH: f32 = f32::from_bits((127 + 20) << 23);
#[cfg(feature = "fast-math")]
const FAST_ATAN2_LOW: f32 = f32::from_bits((127 - 20) << 23);

// Split constants: HI is the f32 nearest the constant, LO the f32 nearest
// the rest (constant - HI), so that HI + LO carries about 48 bits.
/// pi/2 rounded to f32 (0x3fc90fdb), and the rest (0xb33bbd2e).
const PIO2_HI: f32 = core::f32::consts::FRAC_PI_2;
const PIO2_LO: f32 = -4.371_139e-8;
/// pi/4 rounded to f32 (0x3f490fdb), and the rest (0xb2bbbd2e).
const PIO4_HI: f32 = core::f32::consts::FRAC_PI_4;
const PIO4_LO: f32 = -2.185_569_4e-8;
/// pi rounded to f32 (0x40490fdb), and the rest (0xb3bbbd2e).
const PI_HI: f32 = core::f32::consts::PI;
const PI_LO: f32 = -8.742_278e-8;
/// tan(1/2), rounded to f32: the bound of [`atan_poly`]'s range.
const TAN_HALF: f32 = 0.546_302_5;
/// 3 pi/4 rounded down to f32: up to here, [`sin_cos_kernel`] reduces by
/// one subtraction of pi/2 at most.
const THREE_PI_4: f32 = 2.356_194_3;

/// Minimax coefficients of `(atan(u) - u) / u^3` as a polynomial in `u^2`,
/// on |u| <= tan(1/2), for relative error (`tools/minimax.py atan`):
/// the approximation error is 7.7e-10 of the result, 1 % of an ulp.
const ATAN: [f32; 6] = [
    -0.333_333_16,
    0.199_989_1,
    -0.142_611_64,
    0.108_522_59,
    -0.076_592_16,
    0.034_324_907,
];
/// `(sin(r) - r) / r^3` as a polynomial in `r^2` on |r| <= pi/4, relative
/// error 3.8e-9 (`tools/minimax.py sin`).
const SIN: [f32; 3] = [-0.166_666_55, 0.008_332_161, -0.000_195_152_83];
/// `(cos(r) - 1 + r^2 / 2) / r^4` as a polynomial in `r^2` on |r| <= pi/4,
/// absolute error 1.2e-10 (`tools/minimax.py cos`).
const COS: [f32; 3] = [0.041_666_646, -0.001_388_731_6, 2.443_315_7e-5];

/// The bits of 2/pi after the binary point, 224 of them, behind one word of
/// zeros (which stands for the integer part and the bits before it, so
/// that small arguments need no special case): `0.A2F9836E 4E441529 ...`.
const TWO_OVER_PI: [u32; 8] = [
    0,
    0xA2F9_836E,
    0x4E44_1529,
    0xFC27_57D1,
    0xF534_DDC0,
    0xDB62_9599,
    0x3C43_9041,
    0xFE51_63AB,
];
/// 2 pi 2^61, rounded to an integer (0xc90fdaa22168c235): multiplying a
/// 64-bit fraction of a turn by it and keeping the top 64 bits gives
/// radians in units of 2^-61.
const TWO_PI_FIXED: u64 = 14_488_038_916_154_245_685;
/// 2^-12, 2^-24 and 2^-48, exact: the weights of the parts of the reduced
/// angle (radians in units of 2^-61, shifted right by 37 and 13, and
/// perhaps up by 12 first).
const TWO_POW_M12: f32 = f32::from_bits((127 - 12) << 23);
const TWO_POW_M24: f32 = f32::from_bits((127 - 24) << 23);
const TWO_POW_M48: f32 = f32::from_bits((127 - 48) << 23);

/// The ulp bounds of the default kernels, as the doc comments state them and
/// `kernels_are_within_their_ulp_bounds_on_a_sample` and
/// `exhaustive_kernel_sweeps` check them (measured maxima in the comments).
/// Each is the maximum of `exhaustive_kernel_sweeps` (every f32 of the
/// range) rounded up, so that the sampled variant in every test run checks
/// the same bound.
#[allow(dead_code)] // read by the sweep tests (default backend) and the docs
const ATAN_POLY_ULP: f64 = 1.0; // 0.821 at 0.5461395
#[allow(dead_code)] // read by the sweep tests (default backend) and the docs
const SIN_COS_POLY_ULP: f64 = 1.0; // sin 0.805 at 0.7828049, cos 0.749 at 0.7086515
#[allow(dead_code)] // read by the sweep tests (default backend) and the docs
const SIN_COS_NARROW_ULP: f64 = 1.0; // 0.858 at 2.3555665
#[allow(dead_code)] // read by the sweep tests (default backend) and the docs
const SIN_COS_ULP: f64 = 1.25; // 0.985 at 2.3279488e23
#[allow(dead_code)] // read by the sweep tests (default backend) and the docs
const ATAN2_ULP: f64 = 1.6; // 1.291 at t = 0.54892975

/// `atan(u)` for `|u| <= tan(1/2)`: `u + u^3 P(u^2)`, with `P` the degree-5
/// minimax polynomial [`ATAN`]. Within [`ATAN_POLY_ULP`] over the whole
/// range; odd, exactly: `atan_poly(-u) == -atan_poly(u)`.
#[inline]
fn atan_poly(u: f32) -> f32 {
    let s = u * u;
    // Estrin's scheme: three independent pairs, then two steps in s^2
    // (a shorter chain of dependent operations than Horner's).
    let s2 = s * s;
    let p = (ATAN[0] + s * ATAN[1]) + s2 * ((ATAN[2] + s * ATAN[3]) + s2 * (ATAN[4] + s * ATAN[5]));
    u + u * (s * p)
}

/// `sin(r + t)` for `|r| <= pi/4` (a little beyond is fine) and a tail
/// `t` below an ulp of `r`: `r + (t + r^3 P(r^2))` with `P` the degree-2
/// minimax polynomial [`SIN`]. Within 1 ulp for `t = 0`
/// ([`SIN_COS_POLY_ULP`]; 0.805 at worst); the tail carries the bits of a reduced argument
/// that do not fit in `r`.
#[inline]
fn sin_poly(r: f32, t: f32) -> f32 {
    let s = r * r;
    r + (t + r * (s * (SIN[0] + s * (SIN[1] + s * SIN[2]))))
}

/// `cos(r + t)` for `|r| <= pi/4` and a tail `t` below an ulp of `r`:
/// `1 - r^2/2 - r t + r^4 P(r^2)` with `P` the degree-2 minimax polynomial
/// [`COS`]. `1 - r^2/2` is rounded once, and its rounding error is
/// recovered (as in FreeBSD's `k_cos.c`), so the result is within 1 ulp
/// for `t = 0` ([`SIN_COS_POLY_ULP`]; 0.749 at worst).
#[inline]
fn cos_poly(r: f32, t: f32) -> f32 {
    let s = r * r;
    let half = 0.5 * s;
    let w = 1.0 - half;
    w + ((((1.0 - w) - half) - r * t) + s * s * (COS[0] + s * (COS[1] + s * COS[2])))
}

/// `hi + lo` rounded to f32, and the tail that the rounding lost (exact,
/// Fast2Sum; `|hi| >= |lo|`).
#[inline]
fn sum_and_tail(hi: f32, lo: f32) -> (f32, f32) {
    let r = hi + lo;
    (r, (hi - r) + lo)
}

/// The f32-only arctangent of the default backend (see [`atan2`]).
///
/// With `a = |x|` and `b = |y|`, the angle `phi` of the point `(a, b)` in
/// [0, pi/2] comes from one division and [`atan_poly`]:
/// `atan(b / a)` up to 1/2 rad, `pi/2 - atan(a / b)` from pi/2 - 1/2 on,
/// and `pi/4 + atan((b - a) / (b + a))` between (the identity
/// `atan(t) = pi/4 + atan((t - 1) / (t + 1))`, with the division done
/// once, and `|u| <= tan(pi/4 - 1/2)`, small enough that the rounding of
/// `b - a` and `b + a` costs less than an ulp of `phi`). Then `pi - phi`
/// for a negative `x`, and the sign of `y`. Constants are added as a head
/// and a tail, so that their rounding does not count.
///
/// Within [`ATAN2_ULP`] of the exact angle (the sweeps take every f32 `t`
/// in [0, 1] as `(t, 1)`, `(1, t)`, `(t, -1)`, `(1, -t)` and `(1 + t, 1)`;
/// `atan2_kernel_is_within_its_bound_on_random_pairs` takes pairs at every
/// scale).
#[inline]
#[must_use]
pub(crate) fn atan2_kernel(y: f32, x: f32) -> f32 {
    let (b, a) = (y.abs(), x.abs());
    // IEEE 754's limits, by substitution rather than a separate path: two
    // infinities count as (1, 1), two zeros as (0, 1). One infinity needs
    // nothing (the division below gives 0 for it), and NaN stays NaN.
    let infinite = a == f32::INFINITY && b == f32::INFINITY;
    let (b, a) = (select(infinite, 1.0, b), select(infinite, 1.0, a));
    let a = select(a == 0.0 && b == 0.0, 1.0, a);
    // The angle of (a, b) in [0, pi/2] as hi + atan(num / den) + lo: at
    // most 1/2 rad, at least pi/2 - 1/2, or between, where a and b are
    // within a factor 2 of each other (and b + a can only overflow if b is
    // huge, where a quarter of each is exact). Selected by bit masks, which
    // compile to no branch.
    let (low, high) = (b <= a * TAN_HALF, a <= b * TAN_HALF);
    let quarter = select(b > 1e37, 0.25, 1.0);
    let (qb, qa) = (b * quarter, a * quarter);
    let num = select(low, b, select(high, -a, qb - qa));
    let den = select(low, a, select(high, b, qb + qa));
    let hi = select(low, 0.0, select(high, PIO2_HI, PIO4_HI));
    let lo = select(low, 0.0, select(high, PIO2_LO, PIO4_LO));
    let phi = hi + (atan_poly(num / den) + lo);
    let phi = select(x.is_sign_negative(), PI_HI - (phi - PI_LO), phi);
    // phi >= 0: the sign of y is the sign of the result.
    f32::from_bits(phi.to_bits() | (y.to_bits() & SIGN))
}

/// The sign bit of an f32.
pub(crate) const SIGN: u32 = 0x8000_0000;

/// `if c { a } else { b }`, by bit masks: no branch for the data to
/// mispredict (both values are computed anyway).
#[inline]
fn select(c: bool, a: f32, b: f32) -> f32 {
    let mask = u32::from(c).wrapping_neg();
    f32::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

/// The f32-only sine and cosine of the default backend (see [`sin_cos`]).
///
/// - `|x| <= pi/4`: the polynomials directly.
/// - `|x| <= 3 pi/4` (every argument slerp produces for `alpha` in [0, 1],
///   since the half angle after `cn` is at most pi/2): `r = pi/2 - |x|`,
///   exact in its head (Sterbenz) and rounded once with the tail of pi/2,
///   then `sin x = cos r`, `cos x = sin r`.
/// - beyond: [`reduce_by_quarter_turns`], exact for every finite f32.
///
/// Within 1 ulp for `|x| <= 3 pi/4` ([`SIN_COS_NARROW_ULP`]) and 1.25 ulp
/// beyond ([`SIN_COS_ULP`]); NaN for NaN and infinite `x`.
#[must_use]
pub(crate) fn sin_cos_kernel(x: f32) -> (f32, f32) {
    let a = x.abs();
    if a > THREE_PI_4 || a.is_nan() {
        return sin_cos_reduced(x);
    }
    let (s, c) = sin_cos_quarter(a);
    // s >= 0 here: the sign of x is the sign of the sine.
    (f32::from_bits(s.to_bits() | (x.to_bits() & SIGN)), c)
}

/// Sine and cosine of `0 <= a <= 3 pi/4`, without a branch (so that
/// random arguments cost no mispredicted branch, and two calls side by side
/// can share vector instructions). Within a quarter turn of 0: `r + t` is
/// `a` itself, or `pi/2 - a` with sine and cosine swapped, whose head's
/// difference is exact (Sterbenz: `a` lies within a factor 2 of `PIO2_HI`)
/// and whose tail is kept. Within [`SIN_COS_NARROW_ULP`].
///
/// Inlined on 64-bit desktop targets, where the three calls of [`sin3`]
/// then share vector instructions; elsewhere one out-of-line copy keeps
/// flash small (a Cortex-M4F has no vector unit to gain from copies).
#[cfg_attr(any(target_arch = "x86_64", target_arch = "aarch64"), inline(always))]
fn sin_cos_quarter(a: f32) -> (f32, f32) {
    let swap = a > core::f32::consts::FRAC_PI_4;
    let (r, t) = if swap {
        sum_and_tail(PIO2_HI - a, PIO2_LO)
    } else {
        (a, 0.0)
    };
    let (s, c) = sin_cos_poly(r, t);
    if swap {
        (c, s)
    } else {
        (s, c)
    }
}

/// `(sin(r + t), cos(r + t))` for `|r| <= pi/4`: both polynomials, in one
/// function that the narrow and the reduced paths share.
#[cfg_attr(any(target_arch = "x86_64", target_arch = "aarch64"), inline(always))]
fn sin_cos_poly(r: f32, t: f32) -> (f32, f32) {
    (sin_poly(r, t), cos_poly(r, t))
}

/// Sines of three angles, each in [0, 3 pi/4]: the three that slerp
/// needs, side by side (on x86-64 the compiler evaluates them together in
/// vector registers; on a Cortex-M4F they are three calls of one body),
/// with the accuracy of [`sin_cos`] (default backend: within
/// [`SIN_COS_NARROW_ULP`]). Arguments outside the range get no reduction:
/// the caller guarantees the range.
#[inline]
#[must_use]
pub(crate) fn sin3(a: f32, b: f32, c: f32) -> (f32, f32, f32) {
    (
        sin_cos_quarter(a).0,
        sin_cos_quarter(b).0,
        sin_cos_quarter(c).0,
    )
}

/// [`sin_cos_kernel`] beyond 3 pi/4, by [`reduce_by_quarter_turns`]; NaN
/// for NaN and infinities.
#[cold]
fn sin_cos_reduced(x: f32) -> (f32, f32) {
    let a = x.abs();
    if !a.is_finite() {
        return (f32::NAN, f32::NAN);
    }
    let (quadrant, r, t) = reduce_by_quarter_turns(a);
    let (s, c) = sin_cos_poly(r, t);
    // Quadrants 0 to 3 map (s, c) to (s, c), (c, -s), (-s, -c), (-c, s):
    // swapped in the odd ones, the sine negated in 2 and 3, the cosine in 1
    // and 2, by flipping sign bits. sin(-x) = -sin(x): the sine's sign bit
    // flips with x's too.
    let (s, c) = if quadrant & 1 == 0 { (s, c) } else { (c, s) };
    let sin_flip = (quadrant >> 1) << 31;
    let cos_flip = ((quadrant + 1) >> 1 & 1) << 31;
    (
        f32::from_bits(s.to_bits() ^ sin_flip ^ (x.to_bits() & SIGN)),
        f32::from_bits(c.to_bits() ^ cos_flip),
    )
}

/// `a = quadrant * pi/2 + r + t` with `|r| <= pi/4` and a tail `t` below
/// an ulp of `r`, for any finite `a > 0`
/// (Payne and Hanek's reduction, in integers): `a = m 2^e` with a 24-bit
/// integer `m`; the bits of 2/pi worth more than 4 turns once multiplied by
/// `2^e` are skipped, the next 96 are multiplied by `m`, and the top 64 bits
/// of the product are `a / (2 pi)` modulo 1, as a fixed-point fraction of a
/// turn (about 2^-64 off, far below anything f32 can tell). Its top two
/// bits, rounded, are the quadrant; the rest is multiplied by 2 pi in
/// integers too and rounded to `r`, with `t` what that rounding lost.
fn reduce_by_quarter_turns(a: f32) -> (u32, f32, f32) {
    let bits = a.to_bits();
    // a >= 3 pi/4 is normal: its biased exponent is at least 128.
    let m = u64::from((bits & 0x007f_ffff) | 0x0080_0000);
    // a = m 2^e, e in [-22, 104].
    let e = (bits >> 23) as i32 - 150;
    // The first bit of 2/pi needed is bit e - 1 after the binary point,
    // which is bit e + 30 of the table (whose bit 32 is 2/pi's first).
    // e + 30 >= 8 for such an a, so the cast cannot wrap; the bound keeps
    // the three windows inside the table.
    let k = ((e + 30) as u32).min(134);
    let (j, shift) = ((k / 32) as usize, k % 32);
    let word = |i: usize| u64::from(TWO_OVER_PI.get(i).copied().unwrap_or(0));
    // 32 bits of the table, starting at bit 32 i + shift.
    let window = |i: usize| (((word(i) << 32) | word(i + 1)) << shift >> 32) as u32;
    let (w0, w1, w2) = (window(j), window(j + 1), window(j + 2));
    // Bits 32 to 95 of m (w0 w1 w2): the product's bits above 96 are whole
    // turns, those below 32 are beyond f32's reach.
    let low = m * u64::from(w2);
    let middle = m * u64::from(w1) + (low >> 32);
    let turns = middle.wrapping_add(u64::from((m as u32).wrapping_mul(w0)) << 32);
    // Round to the nearest quarter turn; the rest lies within an eighth.
    let quadrant = turns.wrapping_add(1 << 61) >> 62;
    let rest = turns.wrapping_sub(quadrant << 62) as i64;
    // |rest| < 2^61 turns / 2^64, times 2 pi 2^61 / 2^64: radians in units
    // of 2^-61, below pi/4 in magnitude.
    let radians = ((i128::from(rest) * i128::from(TWO_PI_FIXED)) >> 64) as i64;
    // To f32 through two 24-bit integers, each converted exactly (one
    // instruction each on a Cortex-M4F, where i64 to f32 is a library
    // call): bits 37 to 60 (with the sign) and 13 to 36. Where the angle is
    // small (a near multiple of pi/2), it is first shifted up by 12 bits,
    // so that the two keep at least 31 significant bits: no f32 lies closer
    // to a multiple of pi/2 than 2^-31 rad (exhaustive_kernel_sweeps checks
    // every one).
    let small = radians.unsigned_abs() < 1 << 49;
    let (radians, weight) = if small {
        (radians << 12, TWO_POW_M12)
    } else {
        (radians, 1.0)
    };
    let high = (radians >> 37) as i32 as f32 * (TWO_POW_M24 * weight);
    let low = ((radians >> 13) & 0x00ff_ffff) as i32 as f32 * (TWO_POW_M48 * weight);
    let (r, t) = sum_and_tail(high, low);
    (quadrant as u32, r, t)
}

/// 2^-100: below this, a sum of squares may have lost precision to underflow.
/// A component whose square underflows contributes at most 2^-150 of absolute
/// error, so above this threshold the relative error it causes is at most
/// 2^-50, far below one ulp (2^-24).
const SQUARES_UNDERFLOW: f32 = f32::from_bits((127 - 100) << 23);
/// 2^100, exact scale for small inputs: when the sum of squares is below
/// 2^-100, every component is below 2^-50 and becomes less than 2^50, while
/// the smallest subnormal (2^-149) becomes 2^-49, whose square is normal.
const SCALE_UP_SMALL: f32 = f32::from_bits((127 + 100) << 23);
/// 2^-66, exact scale for huge inputs: f32::MAX (< 2^128) becomes < 2^62,
/// whose square, times four, stays below 2^126.
const SCALE_DOWN_HUGE: f32 = f32::from_bits((127 - 66) << 23);

/// The components of a vector, scaled by an exact power of two, and the sum
/// of their squares.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScaledSquares {
    /// The input components times `scale`.
    pub(crate) v: [f32; 4],
    /// The power of two the components were multiplied by (1 in the common case).
    pub(crate) scale: f32,
    /// The sum of the squares of `v` (NaN if any input was NaN, infinite if
    /// any input was infinite, 0 only if every input was zero).
    pub(crate) sum: f32,
}

impl ScaledSquares {
    /// The Euclidean norm of the original, unscaled components (may round
    /// to infinity when the true norm exceeds `f32::MAX`).
    #[inline]
    #[must_use]
    pub(crate) fn norm(self) -> f32 {
        sqrt(self.sum) / self.scale
    }

    /// The original components divided by their norm, or `None` if they are
    /// all zero or any is NaN or infinite.
    #[inline]
    #[must_use]
    pub(crate) fn unit(self) -> Option<[f32; 4]> {
        if !(self.sum > 0.0 && self.sum <= f32::MAX) {
            return None;
        }
        let n = sqrt(self.sum);
        let [a, b, c, d] = self.v;
        Some([a / n, b / n, c / n, d / n])
    }
}

/// Sum of squares of `v` without overflow or underflow: the method of LAPACK's
/// `xNRM2` and of C's `hypot`, with exact power-of-two scaling.
///
/// In the common case (the sum of squares lies in [2^-100, f32::MAX]) this is
/// four multiplications and three additions with `scale == 1`. Otherwise the
/// components are multiplied by 2^100 (the sum underflowed) or 2^-66 (it
/// overflowed) and squared again, so that subnormal vectors (down to 2^-149)
/// and vectors with components up to `f32::MAX` keep full precision. The
/// resulting norm is within 2 ulp (`normalize_is_within_its_bound_from_subnormal_to_huge`
/// in `tests/differential.rs` measures 1.653 ulp over 10^7 draws).
#[inline]
#[must_use]
pub(crate) fn scale_for_squares(v: [f32; 4]) -> ScaledSquares {
    let sum = sum_of_squares(v);
    // NaN is in no range: it is returned as it is, with the sum NaN.
    if (SQUARES_UNDERFLOW..=f32::MAX).contains(&sum) || sum.is_nan() {
        return ScaledSquares { v, scale: 1.0, sum };
    }
    // The sum overflowed (some component is at least 2^63, or infinite) or may
    // have lost precision to underflow (every component is below 2^-50). Zero
    // and infinite components survive the scaling unchanged.
    let scale = if sum.is_infinite() {
        SCALE_DOWN_HUGE
    } else {
        SCALE_UP_SMALL
    };
    // Written out rather than `v.map(..)`, which opt-level "s" leaves as a
    // call into core's array machinery.
    let [a, b, c, d] = v;
    let v = [a * scale, b * scale, c * scale, d * scale];
    ScaledSquares {
        v,
        scale,
        sum: sum_of_squares(v),
    }
}

#[inline]
fn sum_of_squares([a, b, c, d]: [f32; 4]) -> f32 {
    a * a + b * b + c * c + d * d
}

#[cfg(test)]
mod tests {
    //! Sweeps of each kernel against `std`'s f64 functions, as libm tests its
    //! own: many points spread over the range `pow`, `slerp` and `perspective`
    //! use, with the error measured in units in the last place of the f32
    //! result.
    use super::*;
    use crate::accuracy;

    /// Distance from `got` to the exact `want`, in ulps of `want` rounded to f32.
    fn ulps(got: f32, want: f64) -> f64 {
        let w = want as f32;
        let ulp = (f32::from_bits(w.abs().to_bits() + 1) - w.abs()) as f64;
        (got as f64 - want).abs() / ulp
    }

    /// `n` points evenly spread over [lo, hi], endpoints included.
    fn spread(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f32> {
        (0..=n).map(move |i| (lo + (hi - lo) * i as f64 / n as f64) as f32)
    }

    /// Every `step`-th f32 from `lo` to `hi` (both included, both >= 0).
    #[cfg(not(feature = "fast-math"))]
    fn floats(lo: f32, hi: f32, step: usize) -> impl Iterator<Item = f32> {
        (lo.to_bits()..=hi.to_bits())
            .step_by(step)
            .chain([hi.to_bits()])
            .map(f32::from_bits)
    }

    /// The largest ulp error of each default-backend kernel over every
    /// `step`-th f32 of its range, with the argument that reached it.
    #[cfg(not(feature = "fast-math"))]
    fn kernel_sweeps(step: usize) {
        use core::f32::consts::FRAC_PI_4;
        struct Max(&'static str, f64, f32, f64);
        impl Max {
            fn see(&mut self, err: f64, arg: f32) {
                if err > self.1 || err.is_nan() {
                    self.1 = err;
                    self.2 = arg;
                }
            }
            fn check(&self) {
                std::println!("{:<44} max {:.3} ulp at {:e}", self.0, self.1, self.2);
                assert!(
                    self.1 <= self.3,
                    "{} exceeds {} ulp at {:e}",
                    self.0,
                    self.3,
                    self.2
                );
            }
        }
        let mut atan = Max("atan_poly, [0, tan(1/2)]", 0.0, 0.0, ATAN_POLY_ULP);
        for u in floats(0.0, TAN_HALF, step) {
            atan.see(ulps(atan_poly(u), (u as f64).atan()), u);
        }
        let mut sin = Max("sin_poly, [0, pi/4]", 0.0, 0.0, SIN_COS_POLY_ULP);
        let mut cos = Max("cos_poly, [0, pi/4]", 0.0, 0.0, SIN_COS_POLY_ULP);
        for r in floats(0.0, FRAC_PI_4, step) {
            sin.see(ulps(sin_poly(r, 0.0), (r as f64).sin()), r);
            cos.see(ulps(cos_poly(r, 0.0), (r as f64).cos()), r);
        }
        let mut narrow = Max("sin_cos_kernel, [0, 3 pi/4]", 0.0, 0.0, SIN_COS_NARROW_ULP);
        for x in floats(0.0, THREE_PI_4, step) {
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            narrow.see(ulps(s, x64.sin()).max(ulps(c, x64.cos())), x);
        }
        let mut general = Max("sin_cos_kernel, [3 pi/4, f32::MAX]", 0.0, 0.0, SIN_COS_ULP);
        for x in floats(THREE_PI_4, f32::MAX, step) {
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            general.see(ulps(s, x64.sin()).max(ulps(c, x64.cos())), x);
        }
        let mut atan2 = Max("atan2_kernel, t in [0, 1] against +-1", 0.0, 0.0, ATAN2_ULP);
        for t in floats(0.0, 1.0, step) {
            let t64 = t as f64;
            for (y, x) in [(t, 1.0), (1.0, t), (t, -1.0), (1.0, -t)] {
                atan2.see(ulps(atan2_kernel(y, x), (y as f64).atan2(x as f64)), t);
            }
            // The middle branch with a real division: (1 + t, 1).
            let y = 1.0 + t;
            atan2.see(ulps(atan2_kernel(y, 1.0), (y as f64).atan2(1.0)), t);
            let _ = t64;
        }
        for m in [atan, sin, cos, narrow, general, atan2] {
            m.check();
        }
    }

    /// Every 997th f32 of each kernel's range (about a million arguments
    /// each): the sampled variant of `exhaustive_kernel_sweeps` that every
    /// test run does.
    #[cfg(not(feature = "fast-math"))]
    #[test]
    fn kernels_are_within_their_ulp_bounds_on_a_sample() {
        kernel_sweeps(997);
    }

    /// Every f32 of each kernel's range, about 4.3 billion evaluations:
    /// `cargo test --release --lib -- --ignored exhaustive_kernel_sweeps`
    /// (a few minutes).
    #[cfg(not(feature = "fast-math"))]
    #[test]
    #[ignore = "minutes in release: run by hand after changing a kernel"]
    fn exhaustive_kernel_sweeps() {
        kernel_sweeps(1);
    }

    /// `atan2_kernel` on random pairs with exponents from subnormal to huge,
    /// every sign, against f64.
    #[cfg(not(feature = "fast-math"))]
    #[test]
    fn atan2_kernel_is_within_its_bound_on_random_pairs() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(5);
        let mut worst: (f64, f32, f32) = (0.0, 0.0, 0.0);
        for _ in 0..1_000_000 {
            // Any finite bit pattern: uniform in the exponent, not the value.
            let mut any = || loop {
                let x = f32::from_bits(rng.random());
                if x.is_finite() {
                    return x;
                }
            };
            let (y, x) = (any(), any());
            let err = ulps(atan2_kernel(y, x), (y as f64).atan2(x as f64));
            if err > worst.0 {
                worst = (err, y, x);
            }
        }
        std::println!(
            "atan2_kernel, random pairs: max {:.3} ulp at {:e}, {:e}",
            worst.0,
            worst.1,
            worst.2
        );
        assert!(worst.0 <= ATAN2_ULP, "{worst:?}");
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

    #[test]
    fn sweep_exp_m1() {
        let mut worst: f64 = 0.0;
        // The smoothing factors' range: -dt/tau from -1e-7 to -50.
        for x in spread(-50.0, 0.0, 200_000).chain(spread(-1e-3, -1e-7, 10_000)) {
            worst = worst.max(ulps(exp_m1(x), (x as f64).exp_m1()));
        }
        std::println!("exp_m1: max error {worst:.3} ulp");
        assert!(worst <= 1.0, "{worst}");
        assert_eq!(exp_m1(f32::NEG_INFINITY), -1.0);
        assert!(exp_m1(f32::NAN).is_nan());
    }

    #[test]
    fn sweep_atan2() {
        let mut worst: f64 = 0.0;
        let pi = core::f64::consts::PI;
        for t in spread(-pi, pi, 200_000) {
            let (y, x) = ((t as f64).sin() as f32, (t as f64).cos() as f32);
            let want = (y as f64).atan2(x as f64);
            worst = worst.max((atan2(y, x) as f64 - want).abs());
        }
        std::println!("atan2: max absolute error {worst:.3e} rad");
        assert!(worst <= accuracy::ATAN2_MAX_ABS_ERROR as f64, "{worst}");
    }

    /// The largest absolute error of `sin_cos` over `n` points of [lo, hi],
    /// checked against `SIN_COS_MAX_ABS_ERROR`.
    fn sweep_sin_cos_over(what: &str, lo: f64, hi: f64) {
        let mut worst: f64 = 0.0;
        for x in spread(lo, hi, 400_000) {
            let (s, c) = sin_cos(x);
            worst = worst
                .max((s as f64 - (x as f64).sin()).abs())
                .max((c as f64 - (x as f64).cos()).abs());
        }
        std::println!("{what}: max absolute error {worst:.3e}");
        assert!(worst <= accuracy::SIN_COS_MAX_ABS_ERROR as f64, "{worst}");
    }

    #[test]
    fn sweep_sin_cos() {
        sweep_sin_cos_over("sin_cos", -10.0, 10.0);
    }

    #[test]
    fn sweep_sin_cos_of_large_arguments() {
        // The turns pow and slerp hand to sin_cos with large exponents.
        sweep_sin_cos_over("sin_cos of large arguments", -70_000.0, 70_000.0);
    }

    /// The Kani harnesses of `rigtform-proofs` replace these three kernels
    /// by their contracts (`rigtform_proofs::contracts`); that is sound only
    /// if the kernels meet them, on every edge value and on a sweep of every
    /// binade (every 4096th bit pattern, NaNs included).
    #[test]
    fn kernels_meet_the_contracts_the_proofs_stub_them_by() {
        use rigtform_proofs::contracts;
        use rigtform_proofs::edge::EDGE_F32;
        let sweep = (0..=u32::MAX).step_by(4096).map(f32::from_bits);
        for x in EDGE_F32.into_iter().chain(sweep) {
            let (s, c) = sin_cos(x);
            assert!(
                contracts::sin_cos(x, s, c),
                "sin_cos({x:e}) = ({s:e}, {c:e})"
            );
            assert!(contracts::sqrt(x, sqrt(x)), "sqrt({x:e}) = {:e}", sqrt(x));
            for (y, x) in [(x, 1.0), (1.0, x), (x, -x), (-x, x)] {
                let phi = atan2(y, x);
                assert!(contracts::atan2(y, x, phi), "atan2({y:e}, {x:e}) = {phi:e}");
            }
        }
        for y in EDGE_F32 {
            for x in EDGE_F32 {
                assert!(contracts::atan2(y, x, atan2(y, x)), "atan2({y:e}, {x:e})");
            }
        }
    }

    /// sin is odd and cos even, bit for bit, on both paths; and the
    /// quadrant of the reduced path is right on either side of zero.
    #[cfg(not(feature = "fast-math"))]
    #[test]
    fn sin_cos_of_negative_arguments_mirrors_the_positive_ones() {
        let sweep = (0x3f80_0000..0x7f80_0000u32)
            .step_by(9973)
            .map(f32::from_bits);
        for x in sweep.chain([THREE_PI_4, 2.5, 4.0, 5.5, 7.0, 1e3, f32::MAX]) {
            let (s, c) = sin_cos(x);
            let (ns, nc) = sin_cos(-x);
            assert_eq!(ns.to_bits(), (-s).to_bits(), "sin(-{x:e})");
            assert_eq!(nc.to_bits(), c.to_bits(), "cos(-{x:e})");
            let x64 = -(x as f64);
            assert!(
                ulps(ns, x64.sin()).max(ulps(nc, x64.cos())) <= SIN_COS_ULP,
                "{x:e}"
            );
        }
    }

    #[test]
    fn sin_cos_is_relatively_accurate_near_zero() {
        // Small rotations need relative, not absolute, accuracy: within an
        // ulp of x for the sine, of 1 for the cosine, inside (-2^-6, 2^-6).
        for x in spread(-0.01562, 0.01562, 20_000).chain([1e-5, -3e-30, 1e-45]) {
            let (s, c) = sin_cos(x);
            let x64 = x as f64;
            assert!(
                (s as f64 - x64.sin()).abs() <= x64.abs() * 1.2e-7,
                "sin {x}: {s}"
            );
            assert!((c as f64 - x64.cos()).abs() <= 1.2e-7, "cos {x}: {c}");
        }
    }

    #[test]
    fn atan2_of_edge_arguments() {
        use core::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        let cases = [
            (0.0, 1.0, 0.0),
            (0.0, -1.0, PI),
            (-0.0, -1.0, -PI),
            (-1e-30, -1.0, -PI),
            (1.0, 0.0, FRAC_PI_2),
            (1e-30, 1e-30, FRAC_PI_4),
            (-1e-40, 1e-40, -FRAC_PI_4),
            (3e38, 3e38, FRAC_PI_4),
            (1e-45, 1e30, 0.0),
            (1e30, -1e-45, FRAC_PI_2),
            (f32::INFINITY, 1.0, FRAC_PI_2),
            (f32::INFINITY, f32::INFINITY, FRAC_PI_4),
            (1.0, f32::NEG_INFINITY, PI),
            (0.0, 0.0, 0.0),
        ];
        for (y, x, want) in cases {
            let got = atan2(y, x);
            assert!(
                (got - want).abs() <= accuracy::ATAN2_MAX_ABS_ERROR,
                "atan2({y}, {x}) = {got}"
            );
        }
        assert!(atan2(f32::NAN, 1.0).is_nan() && atan2(1.0, f32::NAN).is_nan());
    }

    /// The feature does what it says: inside their ranges the kernels are
    /// micromath's, bit for bit (the accuracy sweeps alone would also pass
    /// if everything had quietly fallen back to libm).
    #[cfg(feature = "fast-math")]
    #[test]
    fn fast_math_kernels_are_micromaths_inside_their_ranges() {
        use micromath::F32Ext;
        for (y, x) in [(0.5f32, 0.7f32), (-3.0, 2.0), (1e5, -3e5), (-1e-3, -2e-3)] {
            assert_eq!(atan2(y, x), F32Ext::atan2(y, x), "atan2({y}, {x})");
        }
        for x in [0.5f32, -2.0, 300.0, -500.0] {
            assert_eq!(sin_cos(x), (F32Ext::sin(x), F32Ext::cos(x)), "sin_cos({x})");
        }
        for x in [0.3f32, 1.2] {
            assert_eq!(tan(x), F32Ext::tan(x), "tan({x})");
        }
    }

    /// Why fast-math keeps libm's square root: micromath's (2.1) is off by
    /// several percent, as the `sqrt` doc says.
    #[cfg(feature = "fast-math")]
    #[test]
    fn micromaths_sqrt_is_too_coarse_for_normalize() {
        let mut worst: f64 = 0.0;
        for x in spread(1e-3, 4.0, 100_000) {
            let got = micromath::F32Ext::sqrt(x) as f64;
            worst = worst.max((got - (x as f64).sqrt()).abs() / (x as f64).sqrt());
        }
        std::println!("micromath sqrt: max relative error {worst:.3e}");
        assert!(
            worst > 0.05,
            "micromath's sqrt improved to {worst}: reconsider using it"
        );
        assert!(micromath::F32Ext::sqrt(0.0f32) != 0.0);
    }

    /// Arguments whose reduced value is tiny (they lie close to a multiple
    /// of pi/2), where the reduction must keep its low bits: the full sweep
    /// found 7.729179e28 at 9.3 ulp when it dropped them.
    #[cfg(not(feature = "fast-math"))]
    #[test]
    fn sin_cos_keeps_the_low_bits_of_tiny_reduced_arguments() {
        for x in [7.729_179e28_f32, 2.327_948_8e23, 5.544_331_8e23] {
            let (s, c) = sin_cos_kernel(x);
            let x64 = x as f64;
            let err = ulps(s, x64.sin()).max(ulps(c, x64.cos()));
            assert!(err <= SIN_COS_ULP, "{x:e}: {err} ulp");
        }
    }

    #[test]
    fn sin_cos_of_huge_arguments_stays_in_range() {
        for x in [1e10_f32, -3e20, 1e38, f32::MAX, -f32::MAX] {
            let (s, c) = sin_cos(x);
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
        }
    }

    #[test]
    fn sweep_tan() {
        let mut worst: f64 = 0.0;
        // Half of a field of view between 1 and 179 degrees.
        for x in spread(0.0087, 1.5621, 100_000) {
            let want = (x as f64).tan();
            worst = worst.max((tan(x) as f64 - want).abs() / want);
        }
        std::println!("tan: max relative error {worst:.3e}");
        assert!(worst <= accuracy::TAN_MAX_REL_ERROR as f64, "{worst}");
    }

    #[test]
    fn scaled_norm_is_exact_to_an_ulp_from_subnormal_to_max() {
        let cases: [[f32; 4]; 7] = [
            [3.0, 4.0, 0.0, 0.0],
            [3e-45, 4e-45, 0.0, 0.0],
            [1e-30, 1e-30, 1e-30, 1e-30],
            [f32::MAX, 0.0, 0.0, 0.0],
            [1e30, 1e30, 1e30, 1e30],
            [f32::MAX / 2.0, f32::MAX / 2.0, 0.0, 0.0],
            [1e-20, 0.0, 0.0, 1e-20],
        ];
        for v in cases {
            let exact = v
                .iter()
                .map(|&c| (c as f64) * (c as f64))
                .sum::<f64>()
                .sqrt();
            let got = scale_for_squares(v).norm();
            // Subnormal results have coarser ulps; compare relative to f32 ulps of the exact norm.
            assert!(ulps(got, exact) <= 2.0, "{v:?}: {got} vs {exact}");
        }
    }

    #[test]
    fn unit_of_degenerate_vectors_is_none() {
        assert!(scale_for_squares([0.0; 4]).unit().is_none());
        assert!(scale_for_squares([f32::NAN, 1.0, 0.0, 0.0])
            .unit()
            .is_none());
        assert!(scale_for_squares([f32::INFINITY, 1.0, 0.0, 0.0])
            .unit()
            .is_none());
        let u = scale_for_squares([1e-45, 0.0, 0.0, 0.0]).unit();
        assert_eq!(u, Some([1.0, 0.0, 0.0, 0.0]));
        let [a, b, c, d] = scale_for_squares([f32::MAX, f32::MAX, 0.0, 0.0])
            .unit()
            .expect("finite");
        let h = core::f64::consts::FRAC_1_SQRT_2;
        assert!(ulps(a, h) <= 1.0 && ulps(b, h) <= 1.0, "{a} {b}");
        assert_eq!((c, d), (0.0, 0.0));
    }

    #[test]
    fn nan_and_infinity_survive_the_norm() {
        assert!(scale_for_squares([f32::NAN, 0.0, 0.0, 0.0]).norm().is_nan());
        assert_eq!(
            scale_for_squares([f32::NEG_INFINITY, 0.0, 0.0, 0.0]).norm(),
            f32::INFINITY
        );
        assert_eq!(scale_for_squares([0.0, -0.0, 0.0, 0.0]).norm(), 0.0);
    }
}
