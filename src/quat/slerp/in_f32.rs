//! Slerp in f32: every input and every `alpha`, as the notes define it,
//! on its own wherever f64 is slow (a Cortex-M4F has no f64 unit), and on
//! x86-64 and AArch64 for the inputs the f64 evaluation leaves.

use super::super::Quat;
use super::{NEARLY_UNIT, SMALL_ANGLE};
use crate::float::{self, scale_for_squares, ScaledSquares};

/// 2^-21 (four ulps of 1): the cosine between a unit direction and the
/// quaternion it must be orthogonal to, below which slerp's extrapolation
/// takes the direction as orthogonal (a larger one would show in the norm
/// of the result, by up to that much).
const ORTHOGONAL_TO_ULPS: f32 = 4.768_371_6e-7;

/// 2^-63: the smallest length of the direction of slerp's extrapolation (in
/// the scaled units of `scale_for_squares`, where the difference it comes
/// from is at least 2^-50 long) whose squares are still normal, so that it
/// normalizes to full precision; shorter, it is rounding.
const MIN_ORTHOGONAL: f32 = 1.084_202_2e-19;

/// The bits of 2^125, the largest |alpha| slerp's extrapolation uses (an
/// immediate operand on Arm, where f32::MAX / 4 would be a load).
const ALPHA_LIMIT_BITS: u32 = 0x7e00_0000;

/// [`Quat::slerp`]'s f32 evaluation, the whole of slerp on targets without
/// the f64 one, callable on every target for the search of its norm's
/// worst case (`proofs/tests/worst_cases.rs`) and the correspondence of
/// `proofs/gappa/slerp_endpoint_f32.g`.
#[cfg(kernels_exported)]
#[must_use]
pub fn slerp_in_f32(a: Quat, b: Quat, alpha: f32) -> Quat {
    a.slerp_f32(b, alpha)
}

impl Quat {
    /// [`slerp`](Self::slerp) in f32, the whole of it on every target but
    /// x86-64 and AArch64, where it takes what the f64 evaluation does not,
    /// out of line, through [`slerp_f32_in_registers`].
    #[cfg_attr(not(desktop64), inline(always))]
    pub(super) fn slerp_f32(self, other: Self, alpha: f32) -> Self {
        // The squared norms are sums of squares: NaN exactly for a NaN
        // component, infinite for an infinite one or where they overflow
        // (components beyond about 1e19, where the products below would
        // overflow anyway). With |alpha|, one comparison catches every
        // non-finite input, and no operation makes a NaN from numbers
        // (as `x * 0.0` or `x - x` would from an infinity).
        let n2 = self.norm_squared();
        let on2 = other.norm_squared();
        // Written to be true for NaN too.
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let not_finite = !(n2 + on2 + alpha.abs() <= f32::MAX);
        if not_finite {
            return Self::NAN;
        }
        if alpha == 0.0 {
            return self;
        }
        // The w of other * self.inv(); cn flips other when it is negative
        // (multiplying by the sign, exactly, rather than branching on it).
        let dot = self.dot(other);
        let flip = 1.0f32.copysign(dot);
        let other = other.map(|c| c * flip);
        let dot = dot * flip;
        // The part of other orthogonal to self, times |self|^2 (exactly
        // orthogonal for any norm of self, in exact arithmetic), scaled by
        // a power of two if its squares would underflow.
        let u = scale_for_squares(other.weighted_sum(n2, self, -dot).to_array());
        if u.sum == 0.0 {
            // Identical or antipodal (or a zero input): the transition is
            // the identity, and so is its every power.
            return self;
        }
        // |u| = |self|^2 |other| sin(phi) and |self| dot = |self|^2 |other|
        // cos(phi), both times u.scale: the notes' phi in [0, pi/2].
        let n = float::sqrt(n2);
        let beta = float::sqrt(u.sum);
        let phi = float::atan2(beta, n * dot * u.scale);
        if !(0.0..=1.0).contains(&alpha) {
            return self.slerp_extrapolated(u, n2, n, beta, phi, alpha);
        }
        self.slerp_in_plane(other, n2, on2, phi, alpha)
    }

    /// Slerp for `alpha` in [0, 1]: `(sin((1 - alpha) phi) self +
    /// sin(alpha phi) other) / sin(phi)`, in the plane of `self` and
    /// `other` (already on the short side), with `n2 = |self|^2`,
    /// `on2 = |other|^2` and the notes' `phi` in (0, pi/2].
    #[inline(always)]
    fn slerp_in_plane(self, other: Self, n2: f32, on2: f32, phi: f32, alpha: f32) -> Self {
        // alpha phi and (1 - alpha) phi add up to phi exactly where f32
        // allows (Sterbenz), so that the result stays on the arc.
        let far = alpha * phi;
        let near = phi - far;
        let (c0, c1) = if phi > SMALL_ANGLE {
            // near, far and phi lie in [0, pi/2]. The rounding error of
            // 1 / sin(phi) is common to both coefficients: it changes the
            // norm, not the rotation.
            let (s0, s1, sin_phi) = float::sin3(near, far, phi);
            let r = 1.0 / sin_phi;
            (s0 * r, s1 * r)
        } else {
            // sin(x) / sin(phi) is x / phi within 2^-26 here.
            (near / phi, far / phi)
        };
        // For inputs off unit norm, other / |other| * |self| is the endpoint
        // on self's sphere. Within rounding of unit norm the factor is taken
        // as 1: computed, it would be off by as much as it corrects.
        let c1 = if (n2 - on2).abs() > NEARLY_UNIT * on2 {
            c1 * float::sqrt(n2 / on2)
        } else {
            c1
        };
        self.weighted_sum(c0, other, c1)
    }

    /// Slerp as a turn by `alpha phi` from `self` (any finite `alpha`): the
    /// point at that angle on the circle through `self` in the direction of
    /// `u` (the part of `other` orthogonal to `self`, `beta` long in its
    /// scaled units), made orthogonal to `self` once more (its rounding
    /// leaves a component along `self` of an ulp over `|u|`, a lot when
    /// `self` and `other` are nearly the same), then normalized. `n2` and
    /// `n` are `|self|^2` and `|self|`.
    #[inline(always)]
    fn slerp_extrapolated(
        self,
        u: ScaledSquares,
        n2: f32,
        n: f32,
        beta: f32,
        phi: f32,
        alpha: f32,
    ) -> Self {
        let dir = Self::from_array(u.v);
        let dir = dir.weighted_sum(1.0, self, -dir.dot(self) / n2);
        // When the inputs are one rotation to within ulps, u is mostly
        // rounding along self, and what the projection leaves is rounding
        // too: it may vanish, or be no more orthogonal to self than u was.
        // There is then no direction to turn in, and no turn worth the
        // name. Within a few ulps of orthogonal, the norm of the result is
        // off by no more than that.
        let m = float::sqrt(dir.norm_squared());
        // Written to be true for a NaN m too. The negated comparison keeps
        // slerp within its flash budget on the Cortex-M4F, where
        // `m.is_nan() || m < ..` is larger (`cargo xtask budget`).
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let no_direction = !(m >= MIN_ORTHOGONAL);
        if no_direction {
            return self;
        }
        let dir = dir.map(|c| c / m);
        let along = dir.dot(self);
        if along.abs() > ORTHOGONAL_TO_ULPS * n {
            return self;
        }
        // Orthogonal to a few ulps is not enough for the norm: the turn's
        // result would be off by up to cos sin times that (3.5e-7 relative
        // for inputs one ulp apart). A second projection takes the rest of
        // self out; it shortens dir by a part in (2^-21)^2 only, so dir
        // stays unit without another square root.
        let dir = dir.weighted_sum(1.0, self, -along / n2);
        // The angle of the part of u orthogonal to self, the part the turn
        // goes along, rather than of all of u, whose rounding alpha would
        // blow up into a turn. Where the two differ, the angle is tiny and
        // atan2 linear: the ratio of the lengths scales it.
        let phi = if phi < SMALL_ANGLE {
            phi * (m / beta)
        } else {
            phi
        };
        // |alpha| <= 2^125 and phi <= pi/2 keep alpha * phi finite.
        // Beyond, an ulp of alpha phi is far more than a turn (any angle is
        // as right as any other), so |alpha| is clamped, on its bits: one
        // comparison of integers, smaller on the Cortex-M4F than the two of
        // floats that `clamp` makes.
        let sign = alpha.to_bits() & float::SIGN;
        let magnitude = (alpha.to_bits() & !float::SIGN).min(ALPHA_LIMIT_BITS);
        let alpha = f32::from_bits(magnitude | sign);
        let (s, c) = float::sin_cos(alpha * phi);
        self.weighted_sum(c, dir, s * n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slerp_of_non_unit_inputs_ends_on_the_first_inputs_sphere() {
        // Norms 2 and 3: the endpoint is b's rotation at a's norm.
        let (a, b) = (Quat::from_rotation_x(0.4), Quat::from_rotation_y(1.3));
        let (a2, b3) = (a.map(|c| 2.0 * c), b.map(|c| 3.0 * c));
        for alpha in [0.5, 1.0] {
            let got = a2.slerp(b3, alpha);
            let tol = 8.0 * crate::accuracy::UNIT_NORM_ERROR;
            assert!(
                (got.norm() - 2.0).abs() < 2.0 * tol,
                "{alpha}: {}",
                got.norm()
            );
            let turn = 4.0 * crate::accuracy::SLERP_MAX_ANGLE_ERROR;
            assert!(got.angle_to(a.slerp(b, alpha)) < turn, "{alpha}");
        }
    }

    /// The norm of `q` in f64.
    fn norm_f64(q: Quat) -> f64 {
        let [w, x, y, z] = [q.w, q.x, q.y, q.z].map(f64::from);
        (w * w + x * x + y * y + z * z).sqrt()
    }

    #[test]
    fn far_extrapolation_of_nearby_inputs_keeps_the_norm_of_self() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let draws = if cfg!(miri) { 20 } else { 20_000 };
        let mut worst = (0.0f64, Quat::IDENTITY, Quat::IDENTITY, 0.0f32);
        for _ in 0..draws {
            let mut c = || rng.random_range(-1.0f32..1.0);
            let a = Quat {
                w: c(),
                x: c(),
                y: c(),
                z: c(),
            }
            .normalize();
            // b is a with one component one ulp up or down.
            let mut b = a;
            let component = match rng.random_range(0..4) {
                0 => &mut b.w,
                1 => &mut b.x,
                2 => &mut b.y,
                _ => &mut b.z,
            };
            let step = if rng.random() { 1 } else { -1i32 };
            *component = f32::from_bits(component.to_bits().wrapping_add_signed(step));
            for alpha in [
                -f32::MAX,
                f32::MAX,
                -1e30,
                1e20,
                rng.random_range(-1e6..1e6),
            ] {
                let r = a.slerp(b, alpha);
                let off = (norm_f64(r) / norm_f64(a) - 1.0).abs();
                if off > worst.0 {
                    worst = (off, a, b, alpha);
                }
            }
        }
        // The worst of 300,000 such draws without the second projection
        // of slerp_extrapolated: 3.72e-7 off.
        let bits = |q: [u32; 4]| Quat {
            w: f32::from_bits(q[0]),
            x: f32::from_bits(q[1]),
            y: f32::from_bits(q[2]),
            z: f32::from_bits(q[3]),
        };
        let a = bits([1_059_190_714, 3_206_621_361, 1_055_017_638, 3_182_944_438]);
        let b = bits([1_059_190_714, 3_206_621_361, 1_055_017_637, 3_182_944_438]);
        let off = (norm_f64(a.slerp(b, 1e20)) / norm_f64(a) - 1.0).abs();
        if off > worst.0 {
            worst = (off, a, b, 1e20);
        }
        let (off, a, b, alpha) = worst;
        assert!(
            off <= f64::from(crate::accuracy::UNIT_NORM_ERROR),
            "{off:e} at {a:?} {b:?} {alpha}"
        );
    }
}
