//! BROAD's error metric, exactly as the benchmark defines it, and the
//! filter runs it scores.
//!
//! Error quaternion `e = estimate * inverse(truth)`, in the earth frame;
//! total error `2 acos(|w|)`, heading error `2 atan(|z / w|)`, inclination
//! error `2 acos(sqrt(w^2 + z^2))`; RMSE over the samples marked
//! `movement`, skipping those without ground truth; no alignment, no time
//! shift; the filter starts at the first sample.

use rigtform::attitude::{FilterParams, OrientationFilter};
use rigtform::Quat;

use super::data::{BroadSample, BROAD_DT};

/// The three errors of one sample, in degrees.
#[derive(Clone, Copy, Debug)]
pub struct SampleError {
    /// The error's part that tilts the vertical: `2 acos(sqrt(w^2 + z^2))`.
    pub inclination: f64,
    /// The error's part about the vertical: `2 atan(|z / w|)`.
    pub heading: f64,
    /// The whole error angle: `2 acos(|w|)`.
    pub total: f64,
}

/// BROAD's errors of `estimate` against `truth` (scalar first), in degrees,
/// evaluated in f64.
pub fn sample_error(estimate: Quat, truth: [f64; 4]) -> SampleError {
    let e = estimate.to_wxyz().map(f64::from);
    let n = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]).sqrt();
    let e = e.map(|c| c / n);
    // estimate * conj(truth)
    let [aw, ax, ay, az] = e;
    let [bw, bx, by, bz] = [truth[0], -truth[1], -truth[2], -truth[3]];
    let w = aw * bw - ax * bx - ay * by - az * bz;
    let z = aw * bz + ax * by - ay * bx + az * bw;
    SampleError {
        total: (2.0 * w.abs().min(1.0).acos()).to_degrees(),
        heading: (2.0 * (z / w).abs().atan()).to_degrees(),
        inclination: (2.0 * (w * w + z * z).sqrt().min(1.0).acos()).to_degrees(),
    }
}

/// Root mean square errors over the scored samples, in degrees.
#[derive(Clone, Copy, Debug)]
pub struct Rmse {
    /// RMSE of the inclination error.
    pub inclination: f64,
    /// RMSE of the heading error.
    pub heading: f64,
    /// RMSE of the total error.
    pub total: f64,
    /// How many samples were scored.
    pub samples: usize,
}

/// A filter run over a trial: the estimate at every sample, and its score.
pub struct Run {
    /// The filter's estimate after each sample.
    pub estimates: Vec<Quat>,
    /// The score of the estimates.
    pub rmse: Rmse,
}

/// Runs the filter over `samples` from the first one, 6D or with the
/// magnetometer, and scores it.
pub fn run(samples: &[BroadSample], params: FilterParams, with_mag: bool) -> Run {
    run_observed(samples, params, with_mag, |_, _, _| {})
}

/// [`run`], calling `observe` after each update with the sample's index,
/// the sample and the filter (for its diagnostics and outputs).
pub fn run_observed(
    samples: &[BroadSample],
    params: FilterParams,
    with_mag: bool,
    mut observe: impl FnMut(usize, &BroadSample, &OrientationFilter),
) -> Run {
    let mut filter = OrientationFilter::new(params);
    let estimates: Vec<Quat> = samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let q = if with_mag {
                filter.update_with_mag(s.gyr, s.acc, s.mag, BROAD_DT)
            } else {
                filter.update(s.gyr, s.acc, BROAD_DT)
            };
            observe(i, s, &filter);
            q
        })
        .collect();
    let rmse = score(samples, &estimates);
    Run { estimates, rmse }
}

/// BROAD's RMSE of `estimates` over the scored samples.
pub fn score(samples: &[BroadSample], estimates: &[Quat]) -> Rmse {
    let (mut incl, mut head, mut total, mut n) = (0.0, 0.0, 0.0, 0usize);
    for (s, &q) in samples.iter().zip(estimates) {
        if !s.movement || s.truth.iter().any(|c| c.is_nan()) {
            continue;
        }
        let e = sample_error(q, s.truth);
        incl += e.inclination * e.inclination;
        head += e.heading * e.heading;
        total += e.total * e.total;
        n += 1;
    }
    let rms = |sum: f64| (sum / n as f64).sqrt();
    Rmse {
        inclination: rms(incl),
        heading: rms(head),
        total: rms(total),
        samples: n,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad::data::{read, Recording};

    fn trial_16_samples() -> Vec<BroadSample> {
        match read(&crate::broad::trial_16()) {
            Ok(Recording::Broad(samples)) => samples,
            _ => panic!("trial 16 is a readable BROAD trial"),
        }
    }

    /// The rotation by `angle` about the unit `axis`, from f64 trigonometry
    /// (this tests the metric, not the crate's kernels).
    fn rotation(axis: [f64; 3], angle: f64) -> Quat {
        let (s, c) = (angle / 2.0).sin_cos();
        Quat::from_wxyz(
            c as f32,
            (s * axis[0]) as f32,
            (s * axis[1]) as f32,
            (s * axis[2]) as f32,
        )
    }

    #[test]
    fn metric_splits_heading_from_inclination() {
        let truth = rotation([1.0, 0.0, 0.0], 0.3);
        let t = truth.to_wxyz().map(f64::from);
        // An error about earth's vertical is all heading...
        let e = sample_error(rotation([0.0, 0.0, 1.0], 0.1) * truth, t);
        assert!((e.heading - 0.1f64.to_degrees()).abs() < 1e-4, "{e:?}");
        assert!(
            e.inclination < 1e-2 && (e.total - e.heading).abs() < 1e-4,
            "{e:?}"
        );
        // ... one about a horizontal axis all inclination, whatever the sign.
        let e = sample_error(-(rotation([0.0, 1.0, 0.0], -0.2) * truth), t);
        assert!((e.inclination - 0.2f64.to_degrees()).abs() < 1e-4, "{e:?}");
        assert!(e.heading < 1e-2, "{e:?}");
        // Ground truth rows without markers do not count.
        let mut samples = trial_16_samples()[..2000].to_vec();
        for s in &mut samples {
            s.movement = true;
        }
        samples[0].truth = [f64::NAN; 4];
        let estimates = vec![truth; samples.len()];
        assert_eq!(
            score(&samples, &estimates).samples,
            1999 - samples
                .iter()
                .skip(1)
                .filter(|s| s.truth[0].is_nan())
                .count()
        );
    }
}
