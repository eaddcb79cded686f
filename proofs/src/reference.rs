//! The notes' formulas in `f64`, without `std`: the reference the on-target
//! tests measure `rigtform`'s `f32` results against (the host tests use
//! nalgebra for the same purpose).

use rigtform::Quat;

/// A quaternion in `f64`, scalar first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quat64 {
    /// Real part.
    pub w: f64,
    /// `i` part.
    pub x: f64,
    /// `j` part.
    pub y: f64,
    /// `k` part.
    pub z: f64,
}

impl From<Quat> for Quat64 {
    fn from(q: Quat) -> Self {
        Self {
            w: q.w.into(),
            x: q.x.into(),
            y: q.y.into(),
            z: q.z.into(),
        }
    }
}

/// The Hamilton product.
impl core::ops::Mul for Quat64 {
    type Output = Self;

    fn mul(self, o: Self) -> Self {
        Self {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }
}

impl Quat64 {
    /// The conjugate (the inverse of a unit quaternion).
    pub fn conj(self) -> Self {
        Self {
            w: self.w,
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }

    fn vector_norm(self) -> f64 {
        libm::sqrt(self.x * self.x + self.y * self.y + self.z * self.z)
    }

    /// The notes' power operator: `phi = atan2(|v|, w)`, then
    /// `(cos(alpha phi), sin(alpha phi) v / |v|)`; a pure real `w < 0`
    /// turns about x, as `rigtform` documents.
    pub fn pow(self, alpha: f64) -> Self {
        let beta = self.vector_norm();
        let (k, phi) = if beta == 0.0 {
            let phi = if self.w < 0.0 {
                core::f64::consts::PI
            } else {
                0.0
            };
            ([1.0, 0.0, 0.0], phi)
        } else {
            (
                [self.x / beta, self.y / beta, self.z / beta],
                libm::atan2(beta, self.w),
            )
        };
        let (s, c) = (libm::sin(alpha * phi), libm::cos(alpha * phi));
        Self {
            w: c,
            x: s * k[0],
            y: s * k[1],
            z: s * k[2],
        }
    }

    /// `pow(cn(b a^-1), alpha) a`.
    pub fn slerp(a: Self, b: Self, alpha: f64) -> Self {
        let mut d = b * a.conj();
        if d.w < 0.0 {
            d = Self {
                w: -d.w,
                x: -d.x,
                y: -d.y,
                z: -d.z,
            };
        }
        d.pow(alpha) * a
    }

    /// The angle of the rotation between two unit quaternions, up to sign:
    /// `2 atan2(|v|, |w|)` of `b^-1 a` (accurate near 0 and near pi).
    pub fn angle_between(a: Self, b: Self) -> f64 {
        let d = b.conj() * a;
        2.0 * libm::atan2(d.vector_norm(), libm::fabs(d.w))
    }
}

/// The Leibniz expansion of the determinant of the `n` x `n` matrix `m`
/// (column-major, `n` from 1 to 4): the determinant and the sum of its
/// `n!` products' magnitudes, the `T` that the determinants' and inverses'
/// error bounds (`accuracy::DETERMINANT_MAX_REL_ERROR` and the others) are
/// relative to. For entries that are f32 values, a product of up to four
/// rounds in f64 by 2^-53 of itself, far below the errors measured.
///
/// ```
/// use rigtform_proofs::reference::leibniz_expansion;
/// // [[2, 1], [1, 3]] (columns): 2 * 3 - 1 * 1, from products of 6 and 1.
/// assert_eq!(leibniz_expansion(&[2.0, 1.0, 1.0, 3.0], 2), (5.0, 7.0));
/// ```
///
/// # Preconditions
///
/// `n` at most 4 and `m.len() == n * n`; otherwise the result is NaN.
pub fn leibniz_expansion(m: &[f64], n: usize) -> (f64, f64) {
    if n > 4 || m.len() != n * n {
        return (f64::NAN, f64::NAN);
    }
    let mut perm = [0usize, 1, 2, 3];
    let (mut det, mut total) = (0f64, 0f64);
    let mut visit = |perm: &[usize; 4], sign: f64| {
        let p: f64 = (0..n).map(|col| m[col * n + perm[col]]).product();
        det += sign * p;
        total += p.abs();
    };
    // Heap's algorithm: every permutation of the first n once, the sign
    // flipping at each swap.
    let (mut c, mut sign, mut i) = ([0usize; 4], 1.0, 0);
    visit(&perm, sign);
    while i < n {
        if c[i] < i {
            let j = if i % 2 == 0 { 0 } else { c[i] };
            perm.swap(j, i);
            sign = -sign;
            visit(&perm, sign);
            c[i] += 1;
            i = 0;
        } else {
            c[i] = 0;
            i += 1;
        }
    }
    (det, total)
}

/// The head and tail at which the sine and cosine kernel's narrow path
/// (`sin_cos_quarter` in `src/float/sin_cos.rs`) evaluates its polynomials
/// for `0 <= a <= 3 pi/4`: `(a, 0)` up to pi/4; beyond, the head `pi/2 -
/// a` (exact, Sterbenz) and the tail of pi/2 added by Fast2Sum, where the
/// cosine polynomial gives the sine and the sine polynomial the cosine.
/// Returns `(r, t, swapped)`.
///
/// ```
/// use rigtform_proofs::reference::narrow_head_and_tail;
/// assert_eq!(narrow_head_and_tail(0.5), (0.5, 0.0, false));
/// let (r, t, swapped) = narrow_head_and_tail(1.5);
/// // pi/2 - 1.5 within the tail of pi/2's own rounding (2^-49).
/// assert!(swapped && (f64::from(r) + f64::from(t) - (core::f64::consts::FRAC_PI_2 - 1.5)).abs() < 2e-15);
/// ```
pub fn narrow_head_and_tail(a: f32) -> (f32, f32, bool) {
    // pi/2 rounded to f32, and the rest rounded to f32 (the kernel's
    // PIO2_HI and PIO2_LO).
    let (half, half_lo) = (core::f32::consts::FRAC_PI_2, f32::from_bits(0xb33b_bd2e));
    if a > core::f32::consts::FRAC_PI_4 {
        let head = half - a;
        let r = head + half_lo;
        (r, (head - r) + half_lo, true)
    } else {
        (a, 0.0, false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pow_of_a_half_turn_is_a_quarter_turn() {
        let q = Quat64::from(Quat::from_wxyz(0.0, 0.0, 0.0, 1.0)); // pi about z
        let h = q.pow(0.5);
        let quarter = core::f64::consts::FRAC_PI_4;
        assert!((h.w - quarter.cos()).abs() < 1e-15 && (h.z - quarter.sin()).abs() < 1e-15);
    }

    #[test]
    fn slerp_takes_the_short_way_and_angles_ignore_sign() {
        let a = Quat64::from(Quat::IDENTITY);
        let half_turn_x = |angle: f64| Quat64 {
            w: libm::cos(angle / 2.0),
            x: libm::sin(angle / 2.0),
            y: 0.0,
            z: 0.0,
        };
        let b = half_turn_x(0.5);
        let minus_b = Quat64 {
            w: -b.w,
            x: -b.x,
            y: -b.y,
            z: -b.z,
        }; // w < 0: same rotation
        let mid = Quat64::slerp(a, minus_b, 0.5);
        assert!((Quat64::angle_between(mid, a) - 0.25).abs() < 1e-12);
        assert!(Quat64::angle_between(mid, half_turn_x(0.25)) < 1e-12);
        assert!(Quat64::angle_between(minus_b, b) < 1e-12);
    }
}
