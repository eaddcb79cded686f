//! What each fuzz target checks on one input, as a function of the decoded
//! fields: the targets in `fuzz/fuzz_targets/` call these on what
//! `arbitrary` gives them, and `tests/fuzz_regressions.rs` calls them on
//! every file of `fuzz/regressions/<target>/`, so a committed regression
//! goes through exactly the laws the fuzzer ran on it.
//!
//! Each panics (through [`assert_holds`]) on the first law that fails.

use crate::laws::{self, assert_holds};
use rigtform::Quat;

/// The `pow` target on `q = (w, x, y, z)` and `alpha`: finite in, finite
/// unit out, and for `|alpha| <= 4` the rotation of the notes' formula;
/// NaN or infinity in, NaN out; `cn` and `inv` keep their exact laws.
///
/// ```
/// rigtform_proofs::fuzz_laws::pow([0.5, 0.5, -0.5, 0.5], 0.25);
/// ```
pub fn pow(q: [f32; 4], alpha: f32) {
    let q = Quat::from_wxyz(q[0], q[1], q[2], q[3]);
    if q.is_finite() && alpha.is_finite() {
        assert_holds(laws::pow_is_unit(q, alpha));
        if alpha.abs() <= 4.0 {
            assert_holds(laws::pow_turns_as_the_notes_define(q, alpha));
        }
    } else {
        assert_holds(laws::pow_of_non_finite_is_nan(q, alpha));
    }
    assert_holds(laws::cn_gives_non_negative_w_and_the_same_rotation(q));
    assert_holds(laws::inverse_is_an_involution(q));
}

const ZERO: Quat = Quat::from_wxyz(0.0, 0.0, 0.0, 0.0);
/// 2^60: inputs within it keep `b a^-1` finite.
const LIMIT: f32 = 1.152_921_5e18;

/// The unit quaternion of a finite non-zero input.
fn unit(q: Quat) -> Option<Quat> {
    (q.is_finite() && q != ZERO).then(|| q.normalize())
}

fn within_limit(q: Quat) -> bool {
    [q.w, q.x, q.y, q.z].iter().all(|c| c.abs() <= LIMIT)
}

/// The `slerp` target on the quaternions `a`, `b`, `c` (as `[w, x, y, z]`),
/// `alpha` and three blend weights: `slerp`, `nlerp`, `blend` and
/// `Quat::catmull_rom` never panic; NaN out for NaN in; `slerp_slice` is
/// slerp bit for bit on the raw, normalized and edge pairs; exactness at
/// `alpha = 0`; for the normalized inputs, unit results, the short way, the
/// notes' rotation for `alpha` in [-1, 2], the turn by `alpha` times the
/// angle, the spline's keys, unit norm, left invariance and two-key path,
/// and blend unit or the identity.
///
/// ```
/// let a = [1.0, 0.0, 0.0, 0.0];
/// let b = [0.0, 1.0, 0.0, 0.0];
/// rigtform_proofs::fuzz_laws::slerp(a, b, a, 0.5, [1.0, 1.0, 1.0]);
/// ```
pub fn slerp(a: [f32; 4], b: [f32; 4], c: [f32; 4], alpha: f32, weights: [f32; 3]) {
    let (a, b, c) = (wxyz(a), wxyz(b), wxyz(c));

    // No panic on anything; NaN or infinity in, NaN out.
    let _ = (a.slerp(b, alpha), a.nlerp(b, alpha));
    let _ = Quat::blend(&[(a, weights[0]), (b, weights[1]), (c, weights[2])]);
    // The raw inputs, their normalized versions and the edge pairs, side by
    // side in one slice.
    let units = [unit(a), unit(b), unit(c)].map(|u| u.unwrap_or(Quat::IDENTITY));
    let starts = [a, b, c, units[0], units[0], units[0], units[1]];
    let ends = [b, c, a, units[1], units[0], -units[0], units[2]];
    assert_holds(laws::slerp_slice_is_slerp_bit_for_bit(
        &starts, &ends, alpha,
    ));
    // The spline through a, b, c at alpha: the keys themselves at whole
    // alpha and beyond the ends, whatever their bits.
    let keys = [a, b, c];
    let _ = Quat::catmull_rom(&keys, alpha);
    for t in [libm::floorf(alpha), alpha - 3.0, alpha + 3.0, f32::NAN] {
        if !(0.0 < t && t < 2.0) || t == 1.0 || t.is_nan() {
            assert_holds(laws::catmull_rom_is_the_key_at_and_beyond_each_key(
                &keys, t,
            ));
        }
    }
    if !(a.is_finite() && b.is_finite() && alpha.is_finite()) {
        assert_holds(laws::slerp_of_non_finite_is_nan(a, b, alpha));
    }
    if within_limit(a) && within_limit(b) {
        assert_holds(laws::slerp_is_exact_at_zero(a, b));
    }

    let (Some(ua), Some(ub), Some(uc)) = (unit(a), unit(b), unit(c)) else {
        return;
    };
    if alpha.is_finite() {
        assert_holds(laws::slerp_is_unit(ua, ub, alpha));
        assert_holds(laws::slerp_takes_the_short_way(ua, ub, alpha));
    }
    if (-1.0..=2.0).contains(&alpha) {
        assert_holds(laws::slerp_matches_the_notes(ua, ub, alpha));
    }
    // Identical and antipodal pairs, whatever the fuzzer drew for b.
    assert_holds(laws::slerp_is_unit(ua, ua, 0.5));
    assert_holds(laws::slerp_is_unit(ua, -ua, 0.5));
    assert_holds(laws::slerp_reaches_the_rotation_of_b_at_one(ua, ub));
    if (0.0..=1.0).contains(&alpha) {
        assert_holds(laws::slerp_turns_by_alpha_times_the_angle(ua, ub, alpha));
        assert_holds(laws::nlerp_is_unit(ua, ub, alpha));
    }
    if !alpha.is_nan() {
        assert_holds(laws::catmull_rom_is_unit(&[ua, ub, uc], alpha));
    }
    // The laws that ask for neighbours at most 1.5 rad apart.
    let close = ua.angle_to(ub) <= 1.5 && ub.angle_to(uc) <= 1.5;
    if close && alpha.is_finite() {
        assert_holds(laws::catmull_rom_is_left_invariant(ua, [ub, uc, ub], alpha));
        assert_holds(laws::catmull_rom_is_left_invariant(uc, [ua, ub, uc], alpha));
    }
    if ua.angle_to(ub) <= 3.0 && alpha.is_finite() {
        assert_holds(laws::catmull_rom_of_two_keys_follows_the_slerp_path(
            ua, ub, alpha,
        ));
    }
    if weights.iter().all(|w| w.is_finite()) {
        assert_holds(laws::blend_is_unit_or_identity(&[
            (ua, weights[0]),
            (ub, weights[1]),
            (uc, weights[2]),
        ]));
    }
}

/// A fuzz input's four floats as a quaternion, scalar first: the order the
/// committed seeds and regressions were written in.
fn wxyz([w, x, y, z]: [f32; 4]) -> Quat {
    Quat::from_wxyz(w, x, y, z)
}

/// The `sampler` target on four raw key times, 48 raw values (twelve
/// quaternions as x, y, z, w, glTF's order), a selector (its bits pick the
/// interpolation and the number of keys, 1 to 4) and a time: `Sampler::new`
/// and `Sampler::sample` never panic on the raw data; on strictly
/// increasing times made from the raw ones and the normalized values, the
/// keys are hit, the ends clamp, samples are unit and STEP is constant
/// between keys.
///
/// ```
/// let mut values = [0.0f32; 48];
/// for q in values.chunks_exact_mut(4) {
///     q[3] = 1.0;
/// }
/// rigtform_proofs::fuzz_laws::sampler([0.0, 1.0, 2.0, 3.0], values, 2.0, 1.5);
/// ```
pub fn sampler(times: [f32; 4], values: [f32; 48], selector: f32, t: f32) {
    use rigtform::animation::{Interpolation, Sampler};
    let bits = selector.to_bits();
    let interpolation = match bits % 3 {
        0 => Interpolation::Step,
        1 => Interpolation::Linear,
        _ => Interpolation::CubicSpline,
    };
    let n = 1 + (bits >> 2) as usize % 4;
    let raw: [Quat; 12] = core::array::from_fn(|i| {
        let c = |k: usize| values.get(4 * i + k).copied().unwrap_or(0.0);
        Quat {
            x: c(0),
            y: c(1),
            z: c(2),
            w: c(3),
        }
    });
    let count = n * interpolation.values_per_key();
    // The raw bits: an error or a sample, never a panic.
    if let Ok(s) = Sampler::new(interpolation, &times[..n], &raw[..count]) {
        let _ = s.sample(t);
    }
    // A valid channel from the same bits: key i at i plus a fraction.
    let valid_times: [f32; 4] = core::array::from_fn(|i| {
        let f = times[i];
        i as f32
            + if f.is_finite() {
                libm::fabsf(f) % 1.0 * 0.75
            } else {
                0.0
            }
    });
    let units = raw.map(|q| unit(q).unwrap_or(Quat::IDENTITY));
    let (times, units) = (&valid_times[..n], &units[..count]);
    assert_holds(laws::sampler_hits_its_keys(interpolation, times, units));
    let at = if t.is_finite() { t } else { 0.5 };
    assert_holds(laws::sampler_is_unit(interpolation, times, units, at));
    if interpolation == Interpolation::Step {
        assert_holds(laws::step_sampler_is_constant_between_keys(
            times, units, at,
        ));
    }
}
