//! `min` and `max` for operands that are not NaN, as one comparison each:
//! on the Cortex-M4F, `f32::min` and `f32::max` are library calls
//! (NaN-aware), ten times as many instructions, and the filter's update
//! takes several.

/// `a.min(b)` for operands that are not NaN.
#[inline(always)]
pub(super) fn min(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

/// `a.max(b)` for operands that are not NaN.
#[inline(always)]
pub(super) fn max(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}
