//! Argument reduction by quarter turns for every finite f32: Payne and
//! Hanek's method, in integers, with the bits of 2/pi.

use super::head_tail::sum_and_tail;

/// The bits of 2/pi after the binary point, 224 of them, behind one word of
/// zeros (which stands for the integer part and the bits before it, so
/// that small arguments need no special case): `0.A2F9836E 4E441529 ...`.
/// Computed with `tools/minimax.py constants`; they agree with FreeBSD
/// msun's `k_rem_pio2.c` table.
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

/// `a = quadrant * pi/2 + r + t` with `|r| <= pi/4` and a tail `t` below
/// an ulp of `r`, for any finite `a >= 3 pi/4`
/// (Payne and Hanek's reduction, in integers): `a = m 2^e` with a 24-bit
/// integer `m`; the bits of 2/pi worth more than 4 turns once multiplied by
/// `2^e` are skipped, the next 96 are multiplied by `m`, and the top 64 bits
/// of the product are `a / (2 pi)` modulo 1, as a fixed-point fraction of a
/// turn (about 2^-64 off, far below anything f32 can tell). Its top two
/// bits, rounded, are the quadrant; the rest is multiplied by 2 pi in
/// integers too and rounded to `r`, with `t` what that rounding lost.
pub(super) fn reduce_by_quarter_turns(a: f32) -> (u32, f32, f32) {
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
    // to a multiple of pi/2 than 2^-31 rad (exhaustive_kernel_sweep checks
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

/// Checks what the kernel's polynomials assume of a reduced argument (the
/// models `sin_poly_tail.g` and `cos_poly_tail.g`): `|r| <= PIO4_HI`, `t`
/// at most `2^-24 |r|` (half an ulp of `r`), and `r` the f32 nearest
/// `r + t` (the Fast2Sum's head).
#[cfg(test)]
pub(super) fn check_reduced_range(a: f32) {
    use super::head_tail::PIO4_HI;
    let (_, r, t) = reduce_by_quarter_turns(a);
    assert!(r.abs() <= PIO4_HI, "{a:e}: |r| = {r:e} above PIO4_HI");
    assert!(
        f64::from(t).abs() <= f64::from(r).abs() * 2f64.powi(-24),
        "{a:e}: the tail {t:e} is above 2^-24 |r| (r = {r:e})"
    );
    assert_eq!((f64::from(r) + f64::from(t)) as f32, r, "{a:e}: r, t");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::sin_cos::THREE_PI_4;

    /// The reduced argument's range at its extremes: the f32 next to odd
    /// multiples of pi/4 (where `|r|` is nearest pi/4), 3 pi/4 (the first
    /// argument of the reduced path) and the largest f32.
    #[test]
    fn reduced_arguments_stay_within_a_quarter_turn_with_a_small_tail() {
        let near = |x: f32| {
            [
                f32::from_bits(x.to_bits() - 1),
                x,
                f32::from_bits(x.to_bits() + 1),
            ]
        };
        let odd_eighths = (3..=4001u32)
            .step_by(2)
            .chain([(1 << 20) + 1, (1 << 30) + 1, 1_000_000_007])
            .map(|k| (f64::from(k) * core::f64::consts::FRAC_PI_4) as f32);
        let ends = [THREE_PI_4, f32::MAX];
        for x in odd_eighths.chain(ends).flat_map(near) {
            if x >= THREE_PI_4 && x.is_finite() {
                check_reduced_range(x);
            }
        }
    }

    /// The quadrant and the reduced angle of a few arguments worked out in
    /// f64 (exact enough below 2^20, where f64's pi/2 is off by far less
    /// than an f32 ulp of the rest).
    #[test]
    fn quadrant_and_rest_match_f64_for_moderate_arguments() {
        for a in [2.5f32, 4.0, 5.5, 7.0, 100.0, 1e3, 123_456.7] {
            let (quadrant, r, t) = reduce_by_quarter_turns(a);
            let q64 = (a as f64 / core::f64::consts::FRAC_PI_2).round();
            let r64 = a as f64 - q64 * core::f64::consts::FRAC_PI_2;
            assert_eq!(quadrant as f64, q64.rem_euclid(4.0), "{a}");
            assert!(
                (r as f64 + t as f64 - r64).abs() < 1e-9,
                "{a}: {r} {t} {r64}"
            );
        }
    }
}
