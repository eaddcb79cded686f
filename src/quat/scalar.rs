//! The evaluations that keep a quaternion's four components together, in
//! plain f32, one component at a time: every target but x86-64 with SSE
//! (and Kani), which takes `quat/sse2.rs`, the same operations in the same
//! order four lanes at a time (also compiled for the tests on x86-64, which
//! hold the two to the same bits). The backend is chosen where `quat.rs`
//! declares it; both files have the same functions.

use super::Quat;
use crate::float;

/// `a * b`, the notes' `[w1 w2 - c1.c2, w1 c2 + w2 c1 + c1 x c2]`, written
/// out one component at a time, the terms in the order of `a`'s
/// components.
#[inline(always)]
pub(super) fn hamilton(a: Quat, b: Quat) -> Quat {
    Quat::from_wxyz(
        a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
        a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
        a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
        a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
    )
}

/// `p . q` summed in pairs, `(x x' + z z') + (y y' + w w')`: shorter
/// chains than in sequence, and the order of a vector unit's halves.
#[inline(always)]
fn dot_in_pairs(p: Quat, q: Quat) -> f32 {
    (p.x * q.x + p.z * q.z) + (p.y * q.y + p.w * q.w)
}

/// [`Quat::nlerp`]: `b` takes the sign of the dot product (an exclusive or
/// of its sign bits: `alpha (-b)` is `-(alpha b)` exactly, with no branch
/// for random pairs to mispredict), the lerp `(1 - alpha) a + alpha b`,
/// divided by its norm where the sum of squares needs no rescaling (every
/// unit pair but extreme extrapolation, checked by one comparison), and
/// [`Quat::normalize`] for the rest.
#[inline(always)]
pub(super) fn nlerp(a: Quat, b: Quat, alpha: f32) -> Quat {
    let sign = dot_in_pairs(a, b).to_bits() & float::SIGN;
    let b = b.map(|c| f32::from_bits(c.to_bits() ^ sign));
    let lerp = a.weighted_sum(1.0 - alpha, b, alpha);
    let sum = dot_in_pairs(lerp, lerp);
    if float::needs_no_rescaling(sum) {
        let n = float::sqrt(sum);
        return lerp.map(|c| c / n);
    }
    lerp.normalize()
}
