//! Laws of the glTF keyframe samplers (`rigtform::animation::Sampler`):
//! keys are hit, unit rotations in give unit rotations out, STEP is constant
//! between keys, and the ends clamp.

use super::{norm2, within, yes_or_no, Verdict, ONE_STEP_NORM_TOL};
use rigtform::animation::{Interpolation, Sampler};
use rigtform::Quat;

/// The value of key `k` of a sampler's values.
fn key(interpolation: Interpolation, values: &[Quat], k: usize) -> Quat {
    let i = k * interpolation.values_per_key()
        + usize::from(interpolation == Interpolation::CubicSpline);
    values.get(i).copied().unwrap_or(Quat::NAN)
}

/// At each key's time the sampler gives that key's rotation exactly as
/// stored; before the first key the first key and from the last on the
/// last, as stored.
///
/// Preconditions: `times` and `values` make a valid sampler (the law
/// checks that `Sampler::new` accepts them), the keys unit to
/// [`ONE_STEP_NORM_TOL`].
pub fn sampler_hits_its_keys(
    interpolation: Interpolation,
    times: &[f32],
    values: &[Quat],
) -> Verdict {
    let Ok(s) = Sampler::new(interpolation, times, values) else {
        return yes_or_no("sampler_hits_its_keys (valid channel)", false);
    };
    let n = times.len();
    for (k, &t) in times.iter().enumerate() {
        yes_or_no(
            "sampler_hits_its_keys",
            s.sample(t) == key(interpolation, values, k),
        )?;
    }
    let (first, last) = s.span();
    yes_or_no(
        "sampler_hits_its_keys (clamped before)",
        s.sample(first - 1.0) == key(interpolation, values, 0) || first - 1.0 == first,
    )?;
    yes_or_no(
        "sampler_hits_its_keys (clamped after)",
        s.sample(f32::INFINITY) == key(interpolation, values, n - 1)
            && s.sample(last) == key(interpolation, values, n - 1),
    )
}

/// Unit keys give unit samples at any finite time: STEP copies keys,
/// LINEAR slerps them, CUBICSPLINE normalizes its sum (or gives the
/// identity where the sum is zero).
///
/// Preconditions: a valid channel, keys (the values of keys, not the
/// tangents) unit to [`ONE_STEP_NORM_TOL`], `t` finite.
pub fn sampler_is_unit(
    interpolation: Interpolation,
    times: &[f32],
    values: &[Quat],
    t: f32,
) -> Verdict {
    let Ok(s) = Sampler::new(interpolation, times, values) else {
        return yes_or_no("sampler_is_unit (valid channel)", false);
    };
    let q = s.sample(t);
    yes_or_no("sampler_is_unit (finite)", q.is_finite())?;
    within(
        "sampler_is_unit",
        (norm2(q) - 1.0).abs(),
        2.0 * ONE_STEP_NORM_TOL,
    )
}

/// STEP gives the key at or before `t`, exactly, whatever `t` within the
/// keys; before the first key, the first.
///
/// Preconditions: a valid STEP channel, `t` not NaN.
pub fn step_sampler_is_constant_between_keys(times: &[f32], values: &[Quat], t: f32) -> Verdict {
    let Ok(s) = Sampler::new(Interpolation::Step, times, values) else {
        return yes_or_no(
            "step_sampler_is_constant_between_keys (valid channel)",
            false,
        );
    };
    let k = times
        .iter()
        .take_while(|&&key_time| key_time <= t)
        .count()
        .saturating_sub(1);
    yes_or_no(
        "step_sampler_is_constant_between_keys",
        s.sample(t) == values.get(k).copied().unwrap_or(Quat::NAN),
    )
}
