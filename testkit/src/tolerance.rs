//! The documented error bounds, applied to one input.

/// The documented pow error (`accuracy::POW_MAX_ANGLE_ERROR`) for a turn of
/// `alpha` times `theta` radians: per radian turned, at least one radian.
///
/// ```
/// use rigtform::accuracy::POW_MAX_ANGLE_ERROR;
/// assert_eq!(rigtform_testkit::pow_tol(0.5, 1.0), POW_MAX_ANGLE_ERROR);
/// assert_eq!(rigtform_testkit::pow_tol(-2.0, 3.0), 6.0 * POW_MAX_ANGLE_ERROR);
/// ```
pub fn pow_tol(alpha: f32, theta: f32) -> f32 {
    rigtform::accuracy::POW_MAX_ANGLE_ERROR * (alpha * theta).abs().max(1.0)
}

/// The documented slerp error (`accuracy::SLERP_MAX_ANGLE_ERROR`) for a turn
/// of `alpha` times `theta` radians.
pub fn slerp_tol(alpha: f32, theta: f32) -> f32 {
    rigtform::accuracy::SLERP_MAX_ANGLE_ERROR * (alpha * theta).abs().max(1.0)
}

/// Largest absolute entry difference of two column-major arrays.
///
/// ```
/// let mut b = [0.0; 16];
/// b[5] = -0.25;
/// assert_eq!(rigtform_testkit::max_entry_diff([0.0; 16], b), 0.25);
/// ```
pub fn max_entry_diff(a: [f32; 16], b: [f32; 16]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}
