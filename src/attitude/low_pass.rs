//! The frame-rate independent first-order low-pass that every time constant
//! of the attitude module means: the smoothing factor
//! `alpha = 1 - exp(-dt / tau)`, and a low-pass of a 3-vector built on it.

use crate::float;
use crate::vec::Cvec3;

/// The fraction `alpha = 1 - exp(-dt / tau)` of the way towards a constant
/// input that a first-order low-pass with time constant `tau` moves in `dt`.
/// Steps compose exactly: two steps of `dt` leave `(1 - alpha)^2 =
/// exp(-2 dt / tau)` of the distance, as one step of `2 dt` does, so the
/// response does not depend on the sample rate.
///
/// Documented results for the edges: `dt <= 0` gives 0 (no time passed,
/// nothing moves; a negative `dt` does not extrapolate), `tau <= 0` with
/// `dt > 0` gives 1 (no smoothing), `tau = +inf` gives 0 (frozen). NaN in
/// either gives NaN. Computed with `exp_m1`, so `alpha` keeps its relative
/// precision for `dt` far below `tau`.
#[inline]
#[must_use]
pub(crate) fn smoothing_factor(dt: f32, tau: f32) -> f32 {
    if dt.is_nan() || tau.is_nan() {
        return f32::NAN;
    }
    if dt <= 0.0 {
        return 0.0;
    }
    if tau <= 0.0 {
        return 1.0;
    }
    let x = dt / tau;
    if x <= SERIES_LIMIT {
        // 1 - exp(-x) = x - x^2/2 + x^3/6 - x^4/24 + x^5/120 - ...: the
        // first omitted term, x^6/720, is below 2^-32 of the sum here.
        return x * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0)))));
    }
    // dt / tau may overflow to infinity: exp_m1(-inf) = -1 gives 1.
    -float::exp_m1(-x)
}

/// Below this `dt / tau`, the low-passes' factors are evaluated as their
/// Taylor series, to f32 precision (every update of a filter running at
/// 100 Hz or faster with time constants of a second or more), instead of
/// calling the `exp_m1` and `sin_cos` kernels.
const SERIES_LIMIT: f32 = 1.0 / 16.0;

/// One step of a first-order low-pass of a 3-vector: `value` moved the
/// fraction `alpha` (a [`smoothing_factor`]) of the way to `input`. Exact
/// for inputs held constant over each step, so its response does not
/// depend on the sample rate; the state is the caller's.
#[inline]
#[must_use]
pub(crate) fn low_pass(value: Cvec3, input: Cvec3, alpha: f32) -> Cvec3 {
    value + (input - value) * alpha
}

/// The coefficients of one step of a second-order Butterworth low-pass
/// with time constant `tau`, exact for an input held over the step (its
/// poles are `(-1 +- i) / tau`, its group delay at low frequency is `tau`,
/// as for a first-order low-pass of the same `tau`, or two first-order
/// stages of `tau / 2`). With the state as the output's distance `e` from
/// the input and its rate scaled by `tau`, `r`, one step is
/// `e' = (c + s) e + s r`, `r' = (c - s) r - 2 s e`, where
/// `c = exp(-dt / tau) cos(dt / tau)` and `s = exp(-dt / tau) sin(dt / tau)`;
/// [`butterworth`] returns `(c, s)`. The same edges as
/// [`smoothing_factor`]: `dt <= 0` gives `(1, 0)` (nothing moves), `tau <= 0`
/// or `dt / tau` beyond 30 (where `exp` leaves less than 1e-13) gives
/// `(0, 0)` (the output is the input), `tau = +inf` gives `(1, 0)`.
#[inline]
#[must_use]
pub(crate) fn butterworth(dt: f32, tau: f32) -> (f32, f32) {
    if dt.is_nan() || tau.is_nan() {
        return (f32::NAN, f32::NAN);
    }
    if dt <= 0.0 {
        return (1.0, 0.0);
    }
    if tau <= 0.0 {
        return (0.0, 0.0);
    }
    let x = dt / tau;
    if x <= SERIES_LIMIT {
        // exp((-1 + i) x) = sum ((-1 + i) x)^n / n!, with (-1 + i)^n =
        // -1 + i, -2i, 2 + 2i, -4, 4 - 4i for n = 1..5; the first omitted
        // terms, x^6 / 90 and x^7 / 630, are below 2^-30 of the sums here.
        let c = 1.0 - x * (1.0 - x * x * (1.0 / 3.0 - x * (1.0 / 6.0 - x * (1.0 / 30.0))));
        let s = x * (1.0 - x * (1.0 - x * (1.0 / 3.0 - x * x * (1.0 / 30.0))));
        return (c, s);
    }
    if x > 30.0 {
        return (0.0, 0.0);
    }
    let decay = 1.0 + float::exp_m1(-x);
    let (sin, cos) = float::sin_cos(x);
    (decay * cos, decay * sin)
}

/// One step of the second-order Butterworth low-pass of a 3-vector (see
/// [`butterworth`] for `(c, s)`): `output` moves towards `input`, `rate` is
/// its rate of change times `tau`. Returns the new `(output, rate)`.
#[inline]
#[must_use]
pub(crate) fn butterworth_step(
    output: Cvec3,
    rate: Cvec3,
    input: Cvec3,
    (c, s): (f32, f32),
) -> (Cvec3, Cvec3) {
    let e = output - input;
    (
        input + e * (c + s) + rate * s,
        rate * (c - s) - e * (2.0 * s),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smoothing_factor_of_edges() {
        assert_eq!(smoothing_factor(0.0, 1.0), 0.0);
        assert_eq!(smoothing_factor(-1.0, 1.0), 0.0);
        assert_eq!(smoothing_factor(0.01, 0.0), 1.0);
        assert_eq!(smoothing_factor(0.01, -2.0), 1.0);
        assert_eq!(smoothing_factor(0.01, f32::INFINITY), 0.0);
        assert_eq!(smoothing_factor(f32::INFINITY, 1.0), 1.0);
        assert_eq!(smoothing_factor(f32::MAX, 1e-30), 1.0);
        assert!(smoothing_factor(f32::NAN, 1.0).is_nan());
        assert!(smoothing_factor(f32::NAN, 0.0).is_nan());
        assert!(smoothing_factor(f32::NAN, -1.0).is_nan());
        assert!(smoothing_factor(0.01, f32::NAN).is_nan());
    }

    #[test]
    fn smoothing_factor_is_one_minus_exp_and_composes_exactly() {
        for (dt, tau) in [(0.01f32, 1.0f32), (1e-6, 3.0), (0.5, 0.1), (0.0035, 0.5)] {
            let want = 1.0 - (-(dt as f64) / tau as f64).exp();
            let got = smoothing_factor(dt, tau) as f64;
            assert!(
                (got - want).abs() <= 2.4e-7 * want,
                "{dt} {tau}: {got} {want}"
            );
            // Two half steps leave what one whole step leaves.
            let half = 1.0 - smoothing_factor(dt / 2.0, tau) as f64;
            assert!((half * half - (1.0 - want)).abs() < 1e-6, "{dt} {tau}");
        }
    }

    /// The series and the kernels agree with `exp(-x) cos x` and
    /// `exp(-x) sin x` in f64, on both sides of the series' limit.
    #[test]
    fn butterworth_factors_are_the_exact_decay() {
        for x in [
            1e-7f32, 1e-4, 0.0035, 0.03, 0.0624, 0.0626, 0.1, 1.0, 5.0, 29.0,
        ] {
            let (c, s) = butterworth(x, 1.0);
            let decay = (-(x as f64)).exp();
            let (want_c, want_s) = (decay * (x as f64).cos(), decay * (x as f64).sin());
            // Relative to the decay, and beyond that the 6e-8 to which
            // 1 + exp_m1(-x) rounds in f32; above the series' limit, the
            // sine and cosine kernel's error too.
            let kernel = if x > SERIES_LIMIT {
                decay * crate::accuracy::SIN_COS_MAX_ABS_ERROR as f64
            } else {
                0.0
            };
            let tolerance = |scale: f64| 3e-7 * scale + 6e-8 + kernel;
            assert!(
                (c as f64 - want_c).abs() <= tolerance(decay),
                "{x}: {c} {want_c}"
            );
            assert!(
                (s as f64 - want_s).abs() <= tolerance(decay * x as f64),
                "{x}: {s} {want_s}"
            );
        }
        assert_eq!(butterworth(0.0, 1.0), (1.0, 0.0));
        assert_eq!(butterworth(-1.0, 1.0), (1.0, 0.0));
        assert_eq!(butterworth(0.01, 0.0), (0.0, 0.0));
        assert_eq!(butterworth(31.0, 1.0), (0.0, 0.0));
        assert_eq!(butterworth(f32::MAX, 1e-30), (0.0, 0.0));
        assert_eq!(butterworth(0.01, f32::INFINITY), (1.0, 0.0));
        assert!(butterworth(f32::NAN, 1.0).0.is_nan());
        assert!(butterworth(0.01, f32::NAN).1.is_nan());
    }

    /// A step through the low-pass: no overshoot beyond the Butterworth's
    /// 4.3 %, the same result at 100 Hz and at 1 kHz (the steps are exact
    /// for held inputs), and a steady drift lagged by `tau`.
    #[test]
    fn butterworth_step_response_and_lag() {
        let tau = 2.0;
        let run = |hz: f32, seconds: f32, input: &dyn Fn(f32) -> Cvec3| {
            let dt = 1.0 / hz;
            let (mut out, mut rate) = (Cvec3::ZERO, Cvec3::ZERO);
            let mut peak: f32 = 0.0;
            for i in 0..(seconds * hz).round() as u32 {
                (out, rate) =
                    butterworth_step(out, rate, input(i as f32 * dt), butterworth(dt, tau));
                peak = peak.max(out.x);
            }
            (out, peak)
        };
        let step = |_: f32| Cvec3::new(1.0, 0.0, 0.0);
        let (slow, peak) = run(100.0, 40.0, &step);
        let (fast, _) = run(1000.0, 40.0, &step);
        assert!((peak - 1.0 - 0.0432).abs() < 1e-3, "{peak}");
        assert!(
            (slow.x - 1.0).abs() < 1e-5 && (slow - fast).norm() < 1e-4,
            "{slow:?} {fast:?}"
        );
        let (one, _) = run(100.0, 1.0, &step);
        let (one_fast, _) = run(1000.0, 1.0, &step);
        assert!((one - one_fast).norm() < 1e-4, "{one:?} {one_fast:?}");
        // A ramp of slope 1 is followed tau behind (to within the step's
        // half sample of the held input).
        let (ramp, _) = run(100.0, 30.0, &|t| Cvec3::new(t, 0.0, 0.0));
        assert!((ramp.x - (30.0 - 0.01 - tau)).abs() < 0.01, "{ramp:?}");
    }

    #[test]
    fn low_pass_moves_the_fraction_alpha() {
        let once = low_pass(Cvec3::ZERO, Cvec3::new(4.0, -8.0, 2.0), 0.25);
        assert_eq!(once, Cvec3::new(1.0, -2.0, 0.5));
        assert_eq!(
            low_pass(once, Cvec3::new(3.0, 0.0, 0.0), 1.0),
            Cvec3::new(3.0, 0.0, 0.0)
        );
        assert_eq!(low_pass(once, once, 0.3), once, "a held input stays put");
    }
}
