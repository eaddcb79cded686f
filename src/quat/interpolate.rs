//! Interpolation between rotations: [`Quat::slerp`] as the notes define it
//! ("to interpolate"), [`Quat::nlerp`] and the n-way [`Quat::blend`] (the
//! notes' "4D lerp and renormalization").

use super::Quat;
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

/// How far the ratio of two squared norms may be from 1 for slerp to treat
/// the inputs as unit: well above the rounding of f32 unit quaternions
/// (a few 1e-7), well below any real drift.
pub(super) const NEARLY_UNIT: f32 = 1e-6;
/// 2^-12 rad: below this, `sin(x) / sin(phi)` is `x / phi` to f32's
/// precision (the two differ by less than `phi^2 / 6`, 2^-26).
pub(super) const SMALL_ANGLE: f32 = 1.0 / 4096.0;

impl Quat {
    /// Spherical linear interpolation, as the notes define it:
    /// `cn(other * self.inv()).pow(alpha) * self`.
    ///
    /// The rotation `other * self.inv()` that takes `self` to `other` is
    /// conditionally negated so it goes the short way (at most pi), then
    /// scaled by `alpha`. The result moves from `self` to `other` about one
    /// fixed axis with constant angular velocity, and is left invariant:
    /// `(g * a).slerp(g * b, t) == g * a.slerp(b, t)` up to sign.
    ///
    /// - `alpha = 0` gives exactly `self`; `alpha = 1` gives the rotation of
    ///   `other` (possibly written as `-other`).
    /// - `alpha` outside [0, 1] extrapolates along the same great circle.
    /// - Identical, nearly identical, antipodal (`other == -self`) and
    ///   opposite (pi apart) inputs all give finite unit results; for
    ///   rotations exactly pi apart both ways are equally short, and the sign
    ///   of the rounded dot product picks one.
    ///
    /// # How it is evaluated
    ///
    /// `pow(alpha) * self` of the notes traces the great circle of the unit
    /// 4-sphere through `self` and `other`, so for `alpha` in [0, 1] it is
    /// evaluated in that plane, without the two f32 products (each of which
    /// rounds by up to 2.5e-7 rad): the `w` of `other * self.inv()` is
    /// `self.dot(other)` (its sign is the `cn`), its vector part has the
    /// length of the part of `other` orthogonal to `self`, so the notes'
    /// `phi` is the atan2 of the two, and the result is
    /// `(sin((1 - alpha) phi) self + sin(alpha phi) other) / sin(phi)`.
    /// Rounding errors common to both coefficients only scale the result,
    /// and each endpoint is reached exactly (`slerp_in_plane`). Like `pow`,
    /// this is scale-free: inputs a little off unit norm still give the
    /// rotation between them. On x86-64 and AArch64, where an f64
    /// operation costs what an f32 one does, `alpha` in (0, 1] takes the
    /// same formula with `phi` from the wedge of the inputs and the sines in
    /// f64 (`quat/slerp_f64.rs`): one polynomial each, no branch that random
    /// inputs mispredict, and coefficients rounded to f32 once; inputs it
    /// does not take (norms more than 1e-6 apart, components beyond 2^16,
    /// angles of 2^-12 rad or less) go the way described here. For
    /// extrapolation (where the two coefficients
    /// grow and their rounding would show in the norm) the notes' formula itself is evaluated as a turn by
    /// `alpha phi` from `self` (`slerp_extrapolated`; it rounds `alpha phi`,
    /// so its error grows with the turn).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions, or nearly so (the result has
    /// the norm of `self`, up to rounding). NaN or infinite inputs give
    /// [`Quat::NAN`], as do inputs whose squared norms overflow
    /// (components of order 1e19 and beyond). Every finite `alpha` gives a
    /// unit result; beyond
    /// 2^125 in magnitude, where an ulp of `alpha phi` is many turns, it is
    /// taken as +-2^125.
    ///
    /// # Accuracy
    ///
    /// Rotation error at most [`accuracy::SLERP_MAX_ANGLE_ERROR`](crate::accuracy::SLERP_MAX_ANGLE_ERROR)
    /// `* max(1, |alpha| theta)` radians against an f64 reference, with
    /// `theta = self.angle_to(other)`; norm within
    /// [`accuracy::UNIT_NORM_ERROR`](crate::accuracy::UNIT_NORM_ERROR) of
    /// the norm of `self`, relative: `| |r| / |self| - 1 |`, for every
    /// finite `alpha` (a unit `self` of f32 is 1 only up to its own
    /// rounding, which the result keeps: 2.6e-7 relative but 3.0e-7 from 1
    /// at worst in 200,000 pairs one ulp apart extrapolated by up to
    /// `f32::MAX`, `far_extrapolation_of_nearby_inputs_keeps_the_norm_of_self`).
    /// Measured on random pairs and on every edge class above
    /// (`tests/differential.rs`). Extrapolating far (outside [-1, 2]) from
    /// inputs less than about 1e-5 rad apart, the error can instead reach
    /// `|alpha| 2^-22` rad, the resolution of their f32 difference.
    ///
    /// # Examples
    ///
    /// ```
    /// use core::f32::consts::PI;
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_z(0.0);
    /// let b = Quat::from_rotation_z(PI / 2.0);
    /// assert!(a.slerp(b, 0.5).angle_to(Quat::from_rotation_z(PI / 4.0)) < 1e-6);
    /// assert_eq!(a.slerp(b, 0.0), a);
    /// // The short way: -b is the same rotation as b.
    /// assert!(a.slerp(-b, 0.5).angle_to(Quat::from_rotation_z(PI / 4.0)) < 1e-6);
    /// ```
    // Inlined across crates on 64-bit desktop targets, where the call
    // costs as much as a share of the work; one out-of-line copy elsewhere
    // (flash on a Cortex-M4F).
    #[cfg_attr(any(target_arch = "x86_64", target_arch = "aarch64"), inline)]
    #[cfg_attr(
        kani,
        kani::requires(crate::kani_contracts::slerp_requires(self, other, alpha))
    )]
    #[cfg_attr(kani, kani::ensures(|r: &Quat| crate::kani_contracts::slerp_ensures(self, alpha, *r)))]
    #[must_use]
    pub fn slerp(self, other: Self, alpha: f32) -> Self {
        #[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
        {
            if let Some(q) = self.slerp_f64(other, alpha) {
                return q;
            }
            slerp_f32_in_registers(self, other, alpha)
        }
        #[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
        self.slerp_f32(other, alpha)
    }

    /// [`slerp`](Self::slerp) in f32, the whole of it on every target but
    /// x86-64 and AArch64, where it takes what the f64 evaluation does not,
    /// out of line, through [`slerp_f32_in_registers`].
    #[cfg_attr(
        not(any(target_arch = "x86_64", target_arch = "aarch64")),
        inline(always)
    )]
    fn slerp_f32(self, other: Self, alpha: f32) -> Self {
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

    /// Normalized linear interpolation: aligns the sign of `other` with
    /// `self` (negating it if `self.dot(other)` is negative or -0, so it
    /// goes the short way), lerps the four components as `(1 - alpha) self + alpha other`,
    /// and normalizes (the notes' "4D lerp and renormalization" hack).
    ///
    /// Cheaper than [`slerp`](Self::slerp), with the same path but not
    /// constant angular velocity (it is faster in the middle). For `alpha`
    /// in [0, 1] the result is written on the side of `self`
    /// (`result.dot(self) >= 0`).
    ///
    /// # Preconditions
    ///
    /// `self` and `other` are unit quaternions. The lerp can only vanish
    /// when they are not (or for extreme extrapolation of non-unit inputs);
    /// then, as for NaN or infinite input, the result is [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_y(0.2);
    /// let b = Quat::from_rotation_y(0.6);
    /// assert!(a.nlerp(b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// assert!(a.nlerp(-b, 0.5).angle_to(Quat::from_rotation_y(0.4)) < 1e-6);
    /// ```
    // Inlined across crates on 64-bit desktop targets, where the call
    // costs as much as a share of the work; one out-of-line copy elsewhere
    // (flash on a Cortex-M4F).
    #[cfg_attr(any(target_arch = "x86_64", target_arch = "aarch64"), inline)]
    #[must_use]
    pub fn nlerp(self, other: Self, alpha: f32) -> Self {
        // The sign goes on `other`, as an exclusive or of its sign bits
        // with the dot product's (`alpha (-other)` is `-(alpha other)`
        // exactly): no branch for random pairs to mispredict, and no
        // multiplication on the way from the dot product to the lerp.
        // Sums in pairs (the dot product's and the squares'): shorter
        // chains, and a vector unit adds two halves at once.
        let pairwise = |a: Self, b: Self| (a.w * b.w + a.y * b.y) + (a.x * b.x + a.z * b.z);
        let sign = pairwise(self, other).to_bits() & float::SIGN;
        let other = other.map(|c| f32::from_bits(c.to_bits() ^ sign));
        let lerp = self.weighted_sum(1.0 - alpha, other, alpha);
        // Divided by its norm where the sum of squares needs no rescaling
        // (every unit pair but extreme extrapolation), checked by one
        // comparison; `normalize` does the rest. Through `normalize` (its
        // sum in sequence, a second range check before the division) every
        // call would take about a fifth longer on x86-64 (5.4 against 4.5 ns).
        let sum = pairwise(lerp, lerp);
        if float::needs_no_rescaling(sum) {
            let n = float::sqrt(sum);
            return lerp.map(|c| c / n);
        }
        lerp.normalize()
    }

    /// `a self + b other`, component-wise.
    #[inline]
    pub(super) fn weighted_sum(self, a: f32, other: Self, b: f32) -> Self {
        Self::from_wxyz(
            a * self.w + b * other.w,
            a * self.x + b * other.x,
            a * self.y + b * other.y,
            a * self.z + b * other.z,
        )
    }

    /// N-way weighted blend: the normalized sum of `weight * q` over the
    /// entries, each `q` first sign-aligned to the first entry's (negated if
    /// its dot product with it is negative). No allocation; the slice may be
    /// of any length. This is the notes' "4D lerp and renormalization",
    /// useful for n-way blends; for two entries with weights `1 - t` and `t`
    /// it equals [`nlerp`](Self::nlerp).
    ///
    /// The result is written on the side of the first entry (`dot >= 0`
    /// with it) when the weights are positive. Weights need not sum to one
    /// (the result is normalized). Mind that
    /// sign alignment to the first entry is only a good choice when all
    /// rotations lie within a quarter turn (pi/2) of it.
    ///
    /// # Preconditions
    ///
    /// Unit quaternions and finite weights, of any size: they are scaled by
    /// a power of two first, so that weights near `f32::MAX` or subnormal
    /// ones blend as the same weights near 1 do. An empty slice, or weights
    /// that cancel to an exactly zero sum, give [`Quat::IDENTITY`] (no
    /// rotation information). A NaN or infinite quaternion or weight gives
    /// [`Quat::NAN`].
    ///
    /// # Accuracy
    ///
    /// Norm within [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR) of 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let a = Quat::from_rotation_z(0.3);
    /// let b = Quat::from_rotation_z(0.9);
    /// let blended = Quat::blend(&[(a, 1.0), (-b, 1.0)]); // -b is b
    /// assert!(blended.angle_to(Quat::from_rotation_z(0.6)) < 1e-6);
    /// assert_eq!(Quat::blend(&[]), Quat::IDENTITY);
    /// ```
    #[must_use]
    pub fn blend(entries: &[(Quat, f32)]) -> Self {
        let first = entries.first().map_or(Self::IDENTITY, |&(q, _)| q);
        // The weights scaled by a power of two (exactly, and the result does
        // not depend on their scale) so that the largest is about 1: the sum
        // neither overflows for weights near f32::MAX nor loses tiny ones.
        let largest = entries.iter().fold(0.0f32, |m, &(_, w)| m.max(w.abs()));
        let scale = weight_scale(largest);
        let mut sum = Self {
            w: 0.0,
            x: 0.0,
            y: 0.0,
            z: 0.0,
        };
        for &(q, weight) in entries {
            let weight = weight * scale;
            let weight = if q.dot(first) < 0.0 { -weight } else { weight };
            sum = sum.weighted_sum(1.0, q, weight);
        }
        // An empty slice, or weights that cancel: no rotation information.
        if sum.w == 0.0 && sum.x == 0.0 && sum.y == 0.0 && sum.z == 0.0 {
            return Self::IDENTITY;
        }
        sum.normalize()
    }
}

/// The power of two that brings `largest`, the largest magnitude of finite
/// weights, into [1, 4): 2^-e for `largest` in [2^e, 2^(e + 1)), e from -126
/// to 126, and 2^-126 above (2^127 and more); 2^126 for subnormal `largest`,
/// and 1 for zero, infinite or NaN `largest` (whose blend is the identity
/// or NaN whatever the scale). Built from the bits, so exact.
fn weight_scale(largest: f32) -> f32 {
    // The biased exponent: 0 for zero and subnormals, 255 for infinity
    // and NaN.
    let biased = (largest.to_bits() >> 23) & 0xff;
    match biased {
        0 if largest == 0.0 => 1.0,
        0 => f32::from_bits((126 + 127) << 23),
        255 => 1.0,
        // 2^(127 - biased), at least 2^-126: the biased exponent of the
        // scale is 254 - biased, at least 1.
        _ => f32::from_bits((254 - biased).max(1) << 23),
    }
}

/// [`Quat::slerp_f32`] out of line, for the inputs the f64 evaluation
/// leaves, on x86-64 and AArch64.
///
/// Out of line, so that the inlined `slerp` is that evaluation and one
/// call: with the rare cases' code inlined too, `slerp` is too large for
/// the compiler to inline into `RigTForm::interpolate` and callers' loops,
/// which then pay for a call every time. Through the C calling convention,
/// which passes the two quaternions and returns the result in registers:
/// the Rust one passes them through memory, so that every `slerp` stores
/// its inputs on the stack and loads them back on its critical path, in
/// case this call comes (31.0 against 29.5 ns per call on x86-64). Chains
/// of dependent slerps pay a little for the registers instead (about 5 %
/// in `catmull_rom`).
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
#[inline(never)]
extern "C" fn slerp_f32_in_registers(a: Quat, b: Quat, alpha: f32) -> Quat {
    a.slerp_f32(b, alpha)
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

    #[test]
    fn weight_scale_is_a_power_of_two_bringing_the_largest_weight_near_one() {
        for largest in [
            f32::MIN_POSITIVE,
            1e-30,
            0.3,
            1.0,
            1.5,
            7.0,
            1e30,
            2.0f32.powi(126),
            2.0f32.powi(127),
            f32::MAX,
        ] {
            let scale = weight_scale(largest);
            assert_eq!(scale.to_bits() & 0x007f_ffff, 0, "{largest}: {scale}");
            let scaled = largest * scale;
            assert!((1.0..4.0).contains(&scaled), "{largest}: {scaled}");
        }
        let tiny = f32::from_bits(1);
        assert!(tiny * weight_scale(tiny) > 0.0);
        for odd in [0.0, f32::INFINITY, f32::NAN] {
            assert_eq!(weight_scale(odd), 1.0);
        }
    }

    #[test]
    fn blend_is_unit_for_weights_near_the_largest_float() {
        let q = Quat::from_rotation_z(0.3);
        let r = Quat::from_rotation_x(0.5);
        let unit = |b: Quat| (b.norm() - 1.0).abs() <= crate::accuracy::NORMALIZE_MAX_NORM_ERROR;
        for big in [f32::MAX, -f32::MAX, 0.75 * f32::MAX, 2.0f32.powi(127), 1e38] {
            let both = Quat::blend(&[(q, big), (q, big)]);
            assert!(unit(both), "{big}: {both:?}");
            assert!(both.angle_to(q) < 1e-6, "{big}: {both:?}");
            let many = [(q, big), (r, big), (q, big), (r, f32::MAX)];
            assert!(unit(Quat::blend(&many)), "{big}");
        }
        // The scale does not change the answer: the same blend with the
        // weights divided by 2^100 and by 2^-100.
        let entries = [(q, 0.75), (r, 0.25)];
        let want = Quat::blend(&entries);
        for k in [-100, 100] {
            let scaled = entries.map(|(e, w)| (e, w * 2.0f32.powi(k)));
            assert_eq!(Quat::blend(&scaled), want, "2^{k}");
        }
        // Subnormal weights alone still blend, where their products with
        // the components underflowed.
        let tiny = f32::from_bits(3);
        let blended = Quat::blend(&[(q, tiny), (r, tiny)]);
        assert!(unit(blended), "{blended:?}");
        assert!(blended.angle_to(Quat::blend(&[(q, 1.0), (r, 1.0)])) < 1e-6);
        // Weights that are not finite still give NaN.
        assert!(Quat::blend(&[(q, f32::MAX), (r, f32::INFINITY)]).w.is_nan());
        assert!(Quat::blend(&[(q, f32::NAN), (r, f32::MAX)]).w.is_nan());
    }

    #[test]
    fn blend_and_nlerp_answer_on_the_side_of_their_first_input() {
        let a = Quat::from_rotation_x(0.4);
        let b = -Quat::from_rotation_y(0.9); // w < 0, the far side of a
        assert!(Quat::blend(&[(a, 1.0), (b, 1.0)]).dot(a) > 0.0);
        assert!(Quat::blend(&[(b, 1.0), (a, 3.0)]).dot(b) > 0.0);
        assert!(a.nlerp(b, 0.9).dot(a) > 0.0);
        assert!(b.nlerp(a, 0.9).dot(b) > 0.0);
    }

    #[test]
    fn blend_of_cancelling_weights_is_identity_and_nan_stays_nan() {
        let q = Quat::from_rotation_x(0.3);
        assert_eq!(Quat::blend(&[(q, 1.0), (q, -1.0)]), Quat::IDENTITY);
        assert!(!Quat::blend(&[(q, 1.0), (q, f32::NAN)]).w.is_finite());
        assert!(!Quat::blend(&[(q, f32::INFINITY)]).w.is_finite());
    }
}
