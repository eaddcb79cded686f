//! The square root as Kani reads it: under `cfg(kani)`, [`sqrt`] is not an
//! instruction (inline assembly on Arm, a `core::arch` intrinsic on x86-64
//! and AArch64, neither of which a model checker can read) but the one f32
//! that the correctly rounded square root returns, described by the
//! inequality that defines it ([`is_correctly_rounded_sqrt`]) instead of
//! computed. The description is exact, not an over-approximation: every
//! positive finite `x` has one such `r`, the instruction's result (the
//! tests below check both on a sweep), so a proof under Kani is about the
//! square root every target computes.

/// Whether `r` is the correctly rounded (round to nearest) square root of
/// `x`, for a positive finite `x`: `r` is a positive normal f32 and `x`
/// lies between the squares of the midpoints from `r` to its neighbours,
/// `(r - l)^2 <= x <= (r + h)^2`, with `h` half an ulp of `r` and `l` the
/// same, or a quarter ulp where `r` is a power of two (the neighbour below
/// is then in the binade below, half as far). Exact in f64: `r +- h` has at
/// most 26 significant bits, its square at most 52. The bounds may be
/// inclusive because a square root of an f32 is never a midpoint between
/// two f32s.
///
/// Not part of the API: the contract check of the square root (`rigtform-proofs`'
/// `tests/kernel_contracts.rs`) and Kani's square root use it.
#[must_use]
pub fn is_correctly_rounded_sqrt(x: f32, r: f32) -> bool {
    if !(x > 0.0 && x < f32::INFINITY && (f32::MIN_POSITIVE..f32::INFINITY).contains(&r)) {
        return false;
    }
    // 2^e for r in [2^e, 2^(e+1)): r's exponent bits alone.
    let binade = f64::from(f32::from_bits(r.to_bits() & 0x7f80_0000));
    let half_ulp = binade * (1.0 / 16_777_216.0);
    let below = if r.to_bits() & 0x007f_ffff == 0 {
        half_ulp * 0.5
    } else {
        half_ulp
    };
    let (r, x) = (f64::from(r), f64::from(x));
    let (lo, hi) = (r - below, r + half_ulp);
    lo * lo <= x && x <= hi * hi
}

/// The square root under Kani: `x` itself for NaN, +-0 and +infinity, NaN
/// for negative `x`, and otherwise any `r` that
/// [`is_correctly_rounded_sqrt`] accepts, which is one value.
#[cfg(kani)]
#[must_use]
pub fn sqrt(x: f32) -> f32 {
    if x.is_nan() || x == 0.0 || x == f32::INFINITY {
        return x;
    }
    if x < 0.0 {
        return f32::NAN;
    }
    let r: f32 = kani::any();
    kani::assume(is_correctly_rounded_sqrt(x, r));
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::sweep::spread;

    /// The next f32 up and down from a positive normal `r`.
    fn neighbours(r: f32) -> [f32; 2] {
        [
            f32::from_bits(r.to_bits() + 1),
            f32::from_bits(r.to_bits() - 1),
        ]
    }

    /// The description accepts the instruction's square root and rejects
    /// both neighbours, so it names exactly one f32: on a sweep of [0, 4],
    /// every 9,973rd positive finite f32, and every power of two and its
    /// neighbours (where the neighbour below is closer).
    #[test]
    fn describes_the_correctly_rounded_square_root_and_nothing_else() {
        let n = if cfg!(miri) { 200 } else { 100_000 };
        let powers = (-149..128).flat_map(|e| {
            let p = libm::ldexpf(1.0, e);
            [
                p,
                f32::from_bits(p.to_bits() + 1),
                f32::from_bits(p.to_bits() - 1),
            ]
        });
        let mut checked = 0;
        for x in spread(0.0, 4.0, n)
            .chain(
                (1..0x7f80_0000_u32)
                    .step_by(if cfg!(miri) { 9_973_000 } else { 9_973 })
                    .map(f32::from_bits),
            )
            .chain(powers)
            .filter(|&x| x > 0.0 && x.is_finite())
        {
            let r = crate::float::sqrt(x);
            assert!(
                is_correctly_rounded_sqrt(x, r),
                "rejects sqrt({x:e}) = {r:e}"
            );
            for other in neighbours(r) {
                assert!(
                    !is_correctly_rounded_sqrt(x, other),
                    "accepts {other:e} for sqrt({x:e})"
                );
            }
            checked += 1;
        }
        assert!(checked > n, "{checked}");
    }

    #[test]
    fn rejects_what_is_not_a_positive_finite_root() {
        assert!(!is_correctly_rounded_sqrt(4.0, -2.0));
        assert!(!is_correctly_rounded_sqrt(-4.0, 2.0));
        assert!(!is_correctly_rounded_sqrt(0.0, 0.0));
        assert!(!is_correctly_rounded_sqrt(f32::INFINITY, f32::INFINITY));
        assert!(!is_correctly_rounded_sqrt(f32::NAN, 1.0));
        assert!(!is_correctly_rounded_sqrt(4.0, f32::NAN));
        assert!(is_correctly_rounded_sqrt(4.0, 2.0));
    }
}
