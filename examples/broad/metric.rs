//! BROAD's error metric, exactly as the benchmark defines it, and the
//! filter runs it scores. Shared with `tests/broad.rs`.
//!
//! Error quaternion `e = estimate * inverse(truth)`, in the earth frame;
//! total error `2 acos(|w|)`, heading error `2 atan(|z / w|)`, inclination
//! error `2 acos(sqrt(w^2 + z^2))`; RMSE over the samples marked
//! `movement`, skipping those without ground truth; no alignment, no time
//! shift; the filter starts at the first sample.

use rigtform::attitude::{FilterParams, OrientationFilter};
use rigtform::Quat;

use crate::data::{BroadSample, BROAD_DT};

/// The three errors of one sample, in degrees.
#[derive(Clone, Copy, Debug)]
pub struct SampleError {
    pub inclination: f64,
    pub heading: f64,
    pub total: f64,
}

/// BROAD's errors of `estimate` against `truth` (scalar first), in degrees,
/// evaluated in f64.
pub fn sample_error(estimate: Quat, truth: [f64; 4]) -> SampleError {
    let e = [estimate.w, estimate.x, estimate.y, estimate.z].map(f64::from);
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
    pub inclination: f64,
    pub heading: f64,
    pub total: f64,
    /// How many samples were scored.
    pub samples: usize,
}

/// A filter run over a trial: the estimate at every sample, and its score.
pub struct Run {
    pub estimates: Vec<Quat>,
    pub rmse: Rmse,
}

/// Runs the filter over `samples` from the first one, 6D or with the
/// magnetometer, and scores it.
pub fn run(samples: &[BroadSample], params: FilterParams, with_mag: bool) -> Run {
    let mut filter = OrientationFilter::new(params);
    let estimates: Vec<Quat> = samples
        .iter()
        .map(|s| {
            if with_mag {
                filter.update_with_mag(s.gyr, s.acc, s.mag, BROAD_DT)
            } else {
                filter.update(s.gyr, s.acc, BROAD_DT)
            }
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
