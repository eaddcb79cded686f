//! The edge values every layer starts from: the unit tests, the fuzz seed
//! corpus, the proof stand-in and the on-target tests draw on this one list.
//!
//! As libm's test generators do, it walks out from 0, +-1, the subnormals,
//! the largest finite value, the infinities and NaN.

/// libm-style edge values of `f32`.
pub const EDGE_F32: [f32; 24] = [
    0.0,
    -0.0,
    1e-45, // the smallest subnormal
    -1e-45,
    1e-40, // a subnormal
    f32::MIN_POSITIVE,
    1e-30,
    1e-7,
    -1e-7,
    0.5,
    1.0,
    -1.0,
    0.999_999_9, // 1 - ulp
    1.000_000_1, // 1 + ulp
    2.0,
    -3.5,
    1e7,
    1e30,
    -1e30,
    f32::MAX,
    -f32::MAX,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::NAN,
];

/// The finite entries of [`EDGE_F32`].
///
/// ```
/// assert_eq!(rigtform_proofs::edge::finite_edges().count(), 21);
/// ```
pub fn finite_edges() -> impl Iterator<Item = f32> {
    EDGE_F32.into_iter().filter(|x| x.is_finite())
}

/// Every quaternion whose four components are edge values (24^4 = 331,776),
/// in a fixed order.
///
/// ```
/// assert_eq!(rigtform_proofs::edge::edge_quats().count(), 331_776);
/// ```
pub fn edge_quats() -> impl Iterator<Item = rigtform::Quat> {
    (0..EDGE_F32.len().pow(4)).map(|i| {
        let n = EDGE_F32.len();
        let at = |k: usize| EDGE_F32.get(k % n).copied().unwrap_or(0.0);
        rigtform::Quat::from_wxyz(at(i), at(i / n), at(i / (n * n)), at(i / (n * n * n)))
    })
}
