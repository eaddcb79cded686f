//! `slerp`, `nlerp`, `blend`, `slerp_slice` and `Quat::catmull_rom` on raw
//! bit patterns (contract item 3): unit results for unit inputs and every
//! finite alpha, exactness at alpha = 0, the short way at constant angular
//! velocity, the rotation of the notes' formula in `f64` for alpha in
//! [-1, 2], the slice equal to slerp bit for bit, the spline's keys and
//! left invariance, NaN out for NaN in, and no panic on anything.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::Quat;
use rigtform_proofs::laws::{self, assert_holds};

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    a: [f32; 4],
    b: [f32; 4],
    c: [f32; 4],
    alpha: f32,
    weights: [f32; 3],
}

const ZERO: Quat = Quat::new(0.0, 0.0, 0.0, 0.0);
/// 2^60: inputs within it keep `b a^-1` finite.
const LIMIT: f32 = 1.152_921_5e18;

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat::new(w, x, y, z)
}

/// The unit quaternion of a finite non-zero input.
fn unit(q: Quat) -> Option<Quat> {
    (q.is_finite() && q != ZERO).then(|| q.normalize())
}

fn within_limit(q: Quat) -> bool {
    [q.w, q.x, q.y, q.z].iter().all(|c| c.abs() <= LIMIT)
}

fuzz_target!(|input: Input| {
    let (a, b, c) = (quat(input.a), quat(input.b), quat(input.c));
    let alpha = input.alpha;

    // No panic on anything; NaN or infinity in, NaN out.
    let _ = (a.slerp(b, alpha), a.nlerp(b, alpha));
    let entries = [
        (a, input.weights[0]),
        (b, input.weights[1]),
        (c, input.weights[2]),
    ];
    let _ = Quat::blend(&entries);
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
    for t in [alpha.floor(), alpha - 3.0, alpha + 3.0, f32::NAN] {
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
    if input.weights.iter().all(|w| w.abs() <= LIMIT) {
        assert_holds(laws::blend_is_unit_or_identity(&[
            (ua, input.weights[0]),
            (ub, input.weights[1]),
            (uc, input.weights[2]),
        ]));
    }
});
