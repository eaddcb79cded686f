//! The scale-free sum of squares behind every `norm` and `normalize` of the
//! crate: no overflow and no underflow, from subnormal components to
//! `f32::MAX`.

use super::sqrt::sqrt;

/// 2^-100: below this, a sum of squares may have lost precision to underflow.
/// A component whose square underflows contributes at most 2^-150 of absolute
/// error, so above this threshold the relative error it causes is at most
/// 2^-50, far below one ulp (2^-24).
pub(crate) const SQUARES_UNDERFLOW: f32 = f32::from_bits((127 - 100) << 23);
/// Whether a sum of squares lies between [`SQUARES_UNDERFLOW`] and
/// `f32::MAX` (both included), where it needs no rescaling: one unsigned
/// comparison of the bits. For
/// non-negative floats the order of the bits is the order of the values;
/// NaN (either sign), infinity and negative numbers, -0 among them, have
/// bits outside the range and give `false`.
#[inline]
#[must_use]
pub(crate) fn needs_no_rescaling(sum: f32) -> bool {
    const LOW: u32 = SQUARES_UNDERFLOW.to_bits();
    sum.to_bits().wrapping_sub(LOW) <= f32::MAX.to_bits() - LOW
}
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
        Some(each(self.v, |c| c / n))
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
    if needs_no_rescaling(sum) || sum.is_nan() {
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
    let v = each(v, |c| c * scale);
    ScaledSquares {
        v,
        scale,
        sum: sum_of_squares(v),
    }
}

/// `a^2 + b^2 + c^2 + d^2`, in that order (slerp's slice evaluation must
/// add them as `scale_for_squares` does, to agree with it bit for bit).
#[inline]
pub(crate) fn sum_of_squares([a, b, c, d]: [f32; 4]) -> f32 {
    a * a + b * b + c * c + d * d
}

/// `f` of each of the four components, written out rather than
/// `v.map(f)`, which opt-level "s" leaves as a call into core's array
/// machinery.
#[inline(always)]
fn each([a, b, c, d]: [f32; 4], f: impl Fn(f32) -> f32) -> [f32; 4] {
    [f(a), f(b), f(c), f(d)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::sweep::ulps;

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
    fn needs_no_rescaling_is_the_range_from_the_underflow_threshold_to_max() {
        let inside = [
            SQUARES_UNDERFLOW,
            1.0,
            f32::MAX,
            f32::from_bits(SQUARES_UNDERFLOW.to_bits() + 1),
        ];
        for sum in inside {
            assert!(needs_no_rescaling(sum), "{sum:e}");
        }
        let outside = [
            f32::from_bits(SQUARES_UNDERFLOW.to_bits() - 1),
            0.0,
            -0.0,
            f32::MIN_POSITIVE,
            1e-45,
            -1.0,
            -f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
        ];
        for sum in outside {
            assert!(!needs_no_rescaling(sum), "{sum:e}");
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
