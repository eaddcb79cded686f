//! The polynomials of slerp's f64 evaluation (`in_f64.rs`), on 64-bit
//! desktop targets (x86-64 and AArch64), where an f64 operation costs what
//! an f32 one does: one polynomial each, without the range reductions and
//! their selects that f32 needs for the same accuracy, and with rounding
//! errors far below an f32 ulp. Never compiled for the microcontrollers,
//! whose FPUs have no f64 (the f32 kernels serve them).
//!
//! [`ATAN`] gives `atan(t) / t = 1 + t^2 P(t^2)`, from which `Pair::arc`
//! takes `phi^2` and `phi / sin(phi)`; [`SIN`] gives
//! `sin(x) / x = 1 + x^2 Q(x^2)`, the `sinc` of slerp's coefficients.
//! `proofs/gappa/arc_f64.g` and `sinc_f64.g` (with their Sollya scripts)
//! prove the bounds of the accuracy constants
//! [`PHI_SQUARED_F64_MAX_REL_ERROR`](crate::accuracy::PHI_SQUARED_F64_MAX_REL_ERROR),
//! [`PHI_OVER_SINE_F64_MAX_REL_ERROR`](crate::accuracy::PHI_OVER_SINE_F64_MAX_REL_ERROR)
//! and [`SINC_F64_MAX_REL_ERROR`](crate::accuracy::SINC_F64_MAX_REL_ERROR)
//! for that evaluation; the tests below sweep them.

/// Minimax coefficients of `(atan(u) - u) / u^3` as a polynomial in `u^2`
/// on [0, 1], for relative error (`tools/minimax.py atan_f64`): the
/// approximation error is 1.7e-8 of the result.
pub(crate) const ATAN: [f64; 8] = [
    -0.333_331_527_378_383_06,
    0.199_937_728_817_470_77,
    -0.142_110_557_110_242_54,
    0.106_660_062_753_114_79,
    -0.075_522_178_037_118_6,
    0.043_211_902_355_727_805,
    -0.016_367_953_412_402_284,
    0.002_920_698_523_972_636,
];

/// Minimax coefficients of `(sin(x) - x) / x^3` as a polynomial in `x^2`
/// on [0, pi/2], for relative error (`tools/minimax.py sin_f64`): the
/// approximation error is 6.1e-9 of the result.
pub(crate) const SIN: [f64; 4] = [
    -0.166_666_595_504_268_43,
    0.008_333_066_246_154_522,
    -0.000_198_096_029_100_214_08,
    2.605_780_657_782_845e-6,
];

/// slerp's arc (`Pair::arc`): `(phi^2, phi / sin(phi))` from the squared
/// lengths `near = |a - cn(b)|^2` and `far = |a + cn(b)|^2` of a pair,
/// which `proofs/gappa/arc_quotient_f64.g` (their quotient) and
/// `arc_f64.g` (the rest) model.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_arc(near: f64, far: f64) -> (f64, f64) {
    let arc = super::in_f64::Arc::from_lengths(near, far);
    (arc.phi_squared, arc.phi_over_sine)
}

/// slerp's `sin(x) / x` from `s = x^2` (`in_f64.rs`'s `sinc`), which
/// `proofs/gappa/sinc_f64.g` models.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_sinc(s: f64) -> f64 {
    super::in_f64::sinc(s)
}

/// slerp's coefficients before their rounding to f32
/// (`Arc::coefficients`), `[c0, c1]`, from the arc's `phi^2` and
/// `phi / sin(phi)`, which `proofs/gappa/coefficient_rest_f64.g` (`c0`) and
/// `coefficient_f64.g` (`c1`) model.
#[cfg(any(kani, feature = "kernel-contracts"))]
#[must_use]
pub fn slerp_coefficients(phi_squared: f64, phi_over_sine: f64, alpha: f32) -> [f64; 2] {
    super::in_f64::Arc {
        phi_squared,
        phi_over_sine,
    }
    .coefficients(alpha)
}

#[cfg(test)]
mod tests {
    use super::super::in_f64::{sinc, Arc, Pair, SMALL_ANGLE_SQUARED_F64};
    use crate::accuracy::{
        PHI_OVER_SINE_F64_MAX_REL_ERROR, PHI_SQUARED_F64_MAX_REL_ERROR, SINC_F64_MAX_REL_ERROR,
        SLERP_COEFFICIENT_F64_MAX_REL_ERROR,
    };
    use crate::float::sweep::{floats, SAMPLE_STEP};
    use core::f32::consts::FRAC_PI_2;

    /// The largest relative error of `sinc(x^2)` over every `step`-th f32
    /// `x` of [2^-30, pi/2] (`x^2` exact in f64), against `std`'s f64
    /// `sin(x) / x`.
    fn sinc_sweep(step: usize) -> (f64, f32) {
        let mut worst = (0.0, 0.0);
        for x in floats(9.3e-10, FRAC_PI_2, step) {
            let x64 = f64::from(x);
            let exact = x64.sin() / x64;
            let err = ((sinc(x64 * x64) - exact) / exact).abs();
            if err > worst.0 {
                worst = (err, x);
            }
        }
        worst
    }

    /// The arc of the lengths whose quotient is `t2` exactly (`t2` over
    /// 1), and its exact `phi = 2 atan(sqrt(t2))` in
    /// `std`'s f64.
    fn right_angled(t2: f32) -> (f64, Arc) {
        let phi = 2.0 * f64::from(t2).sqrt().atan();
        (phi, Arc::from_lengths(f64::from(t2), 1.0))
    }

    /// The largest relative errors of the arc's `phi^2` and
    /// `phi / sin(phi)` over every `step`-th f32 `t2` of [2^-30, 1], as
    /// the tangent of the half angle squared (the lengths `t2` and 1, whose
    /// quotient is `t2` exactly), against `phi = 2 atan(sqrt(t2))` in `std`'s f64.
    fn arc_sweep(step: usize) -> [(f64, f32); 2] {
        let mut worst = [(0.0, 0.0); 2];
        for t2 in floats(9.3e-10, 1.0, step) {
            let (phi, arc) = right_angled(t2);
            let errors = [
                (arc.phi_squared - phi * phi) / (phi * phi),
                (arc.phi_over_sine - phi / phi.sin()) * phi.sin() / phi,
            ];
            for (w, e) in worst.iter_mut().zip(errors) {
                if e.abs() > w.0 {
                    *w = (e.abs(), t2);
                }
            }
        }
        worst
    }

    #[test]
    fn sinc_is_within_its_bound_on_a_sample() {
        let (err, x) = sinc_sweep(SAMPLE_STEP);
        assert!(err <= f64::from(SINC_F64_MAX_REL_ERROR), "{err:e} at {x}");
    }

    #[test]
    fn arc_is_within_its_bounds_on_a_sample() {
        let [(square, t), (ratio, u)] = arc_sweep(SAMPLE_STEP);
        assert!(
            square <= f64::from(PHI_SQUARED_F64_MAX_REL_ERROR),
            "phi^2: {square:e} at {t}"
        );
        assert!(
            ratio <= f64::from(PHI_OVER_SINE_F64_MAX_REL_ERROR),
            "phi / sin(phi): {ratio:e} at {u}"
        );
    }

    /// The largest relative error of slerp's coefficients before their
    /// rounding to f32, over every `step`-th f32 `t2` of [2^-25, 1] (the
    /// arc as in [`arc_sweep`], `phi^2` above 2^-24) and shares from the
    /// smallest f32 to 1, against `sin((1 - alpha) phi) / sin(phi)` and
    /// `sin(alpha phi) / sin(phi)` in `std`'s f64.
    fn coefficient_sweep(step: usize) -> (f64, f32, f32) {
        let alphas = [
            f32::from_bits(1),
            1e-30,
            1e-7,
            1e-3,
            0.1,
            0.25,
            1.0 / 3.0,
            0.5,
            0.7,
            0.9,
            0.999,
            1.0 - f32::EPSILON / 2.0,
            1.0,
        ];
        let mut worst = (0.0, 0.0, 0.0);
        for t2 in floats(2.9802322e-8, 1.0, step) {
            let (phi, arc) = right_angled(t2);
            for alpha in alphas {
                let [c0, c1] = arc.coefficients(alpha);
                let share = f64::from(alpha);
                let exact = [(1.0 - share) * phi, share * phi].map(|x| x.sin() / phi.sin());
                for (c, e) in [c0, c1].into_iter().zip(exact) {
                    let err = if e == 0.0 {
                        c.abs()
                    } else {
                        ((c - e) / e).abs()
                    };
                    if err > worst.0 {
                        worst = (err, t2, alpha);
                    }
                }
            }
        }
        worst
    }

    #[test]
    fn coefficients_are_within_their_bound_on_a_sample() {
        let (err, t2, alpha) = coefficient_sweep(16 * SAMPLE_STEP);
        assert!(
            err <= f64::from(SLERP_COEFFICIENT_F64_MAX_REL_ERROR),
            "{err:e} at t2 = {t2}, alpha = {alpha}"
        );
    }

    /// The hypothesis of `proofs/gappa/arc_f64.g`: the arc's quotient
    /// `t2 = |a - cn(b)|^2 / |a + cn(b)|^2` lies in [2^-170, 1] wherever slerp takes its result (`phi^2` above
    /// 2^-24), on random unit pairs, pairs at right angles (where it is 1)
    /// and pairs just past the small angles (where it is smallest).
    #[test]
    fn arc_quotient_stays_within_the_models_domain() {
        use crate::test_draws::unit_quat;
        use crate::Quat;
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(31);
        let (mut smallest, mut largest) = (f64::INFINITY, 0.0f64);
        for i in 0..200_000 {
            let a = unit_quat(&mut rng);
            let b = match i % 3 {
                // b less its part along a: a right angle.
                0 => {
                    let b = unit_quat(&mut rng);
                    let d = a.dot(b);
                    Quat::from_array(core::array::from_fn(|k| {
                        b.to_array()[k] - d * a.to_array()[k]
                    }))
                    .normalize()
                }
                // Turned by twice the small angle's bound, or a little more.
                1 => {
                    let turn = 2.0 * super::super::SMALL_ANGLE * rng.random_range(1.0..1.5f32);
                    a * Quat::from_rotation_z(turn)
                }
                _ => unit_quat(&mut rng),
            };
            let p = Pair::of(a, b);
            if !p.applies() || p.arc().phi_squared <= SMALL_ANGLE_SQUARED_F64 {
                continue;
            }
            let t2 = p.near() / p.far();
            (smallest, largest) = (smallest.min(t2), largest.max(t2));
        }
        assert!(largest > 0.999_99 && largest <= 1.0, "{largest}");
        assert!(
            smallest >= 2f64.powi(-170) && smallest < 2f64.powi(-25),
            "{smallest}"
        );
    }

    /// Every f32 of the ranges:
    /// `cargo test --release --lib -- --ignored exhaustive_kernel_sweep_f64`.
    #[test]
    #[ignore = "minutes in release: run by hand after changing a polynomial"]
    fn exhaustive_kernel_sweep_f64() {
        let (sinc_error, x) = sinc_sweep(1);
        let [(square, t), (ratio, u)] = arc_sweep(1);
        // Every 64th f32 `t2`: with 13 values of `alpha`, every f32
        // would take hours.
        let (coefficient, v, alpha) = coefficient_sweep(64);
        std::println!("coefficients: {coefficient:e} at t2 = {v}, alpha = {alpha}");
        std::println!(
            "sinc: {sinc_error:e} at {x}; phi^2: {square:e} at t2 = {t}; phi / sin(phi): {ratio:e} at t2 = {u}"
        );
        assert!(sinc_error <= f64::from(SINC_F64_MAX_REL_ERROR));
        assert!(square <= f64::from(PHI_SQUARED_F64_MAX_REL_ERROR));
        assert!(ratio <= f64::from(PHI_OVER_SINE_F64_MAX_REL_ERROR));
        assert!(coefficient <= f64::from(SLERP_COEFFICIENT_F64_MAX_REL_ERROR));
    }
}
