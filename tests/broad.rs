//! The orientation filter on a real recording with optical ground truth:
//! BROAD trial 16 (fast translation), shipped gzipped in `tests/data/`
//! (attribution and changes in `tests/data/README.md`), scored with BROAD's
//! metric by the same code as `examples/broad`.

#[path = "../examples/broad/data.rs"]
#[allow(dead_code)] // the example also reads x-io's log
mod data;
#[path = "../examples/broad/metric.rs"]
mod metric;

use std::path::Path;

use rigtform::accuracy;
use rigtform::attitude::FilterParams;
use rigtform::Quat;

const TRIAL_16: &str = "tests/data/broad_16_undisturbed_fast_translation_B.csv.gz";

fn trial_16() -> Vec<data::BroadSample> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(TRIAL_16);
    match data::read(&path) {
        Ok(data::Recording::Broad(samples)) => samples,
        Ok(_) => panic!("{TRIAL_16} is not a BROAD trial"),
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn broad_16_inclination_and_total_rmse_stay_within_their_bounds() {
    let samples = trial_16();
    assert_eq!(samples.len(), 53_392);
    let six = metric::run(&samples, FilterParams::DEFAULT, false);
    let nine = metric::run(&samples, FilterParams::DEFAULT, true);
    println!("BROAD 16, 6D: {:?}", six.rmse);
    println!("BROAD 16, 9D: {:?}", nine.rmse);
    assert_eq!(
        six.rmse.samples, 32_073,
        "scored samples: movement phase, ground truth present"
    );
    for run in [&six, &nine] {
        assert!(run.estimates.iter().all(|q| q.is_finite()));
        // Per sample, neither part of the error exceeds the whole.
        let r = run.rmse;
        assert!(r.heading <= r.total && r.inclination <= r.total, "{r:?}");
    }
    assert!(six.rmse.inclination <= accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG as f64);
    assert!(nine.rmse.inclination <= accuracy::FILTER_BROAD_16_INCLINATION_RMSE_DEG as f64);
    assert!(nine.rmse.total <= accuracy::FILTER_BROAD_16_TOTAL_RMSE_DEG as f64);
}

/// The rotation by `angle` about the unit `axis`, from f64 trigonometry
/// (this tests the metric, not the crate's kernels).
fn rotation(axis: [f64; 3], angle: f64) -> Quat {
    let (s, c) = (angle / 2.0).sin_cos();
    Quat::new(
        c as f32,
        (s * axis[0]) as f32,
        (s * axis[1]) as f32,
        (s * axis[2]) as f32,
    )
}

#[test]
fn metric_splits_heading_from_inclination() {
    let truth = rotation([1.0, 0.0, 0.0], 0.3);
    let t = [truth.w, truth.x, truth.y, truth.z].map(f64::from);
    // An error about earth's vertical is all heading...
    let e = metric::sample_error(rotation([0.0, 0.0, 1.0], 0.1) * truth, t);
    assert!((e.heading - 0.1f64.to_degrees()).abs() < 1e-4, "{e:?}");
    assert!(
        e.inclination < 1e-2 && (e.total - e.heading).abs() < 1e-4,
        "{e:?}"
    );
    // ... one about a horizontal axis all inclination, whatever the sign.
    let e = metric::sample_error(-(rotation([0.0, 1.0, 0.0], -0.2) * truth), t);
    assert!((e.inclination - 0.2f64.to_degrees()).abs() < 1e-4, "{e:?}");
    assert!(e.heading < 1e-2, "{e:?}");
    // Ground truth rows without markers do not count.
    let mut samples = trial_16()[..2000].to_vec();
    for s in &mut samples {
        s.movement = true;
    }
    samples[0].truth = [f64::NAN; 4];
    let estimates = vec![truth; samples.len()];
    assert_eq!(
        metric::score(&samples, &estimates).samples,
        1999 - samples
            .iter()
            .skip(1)
            .filter(|s| s.truth[0].is_nan())
            .count()
    );
}

#[test]
fn bad_rows_are_reported_with_their_line_number() {
    let header = data::BROAD_HEADER;
    let good = "0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,1";
    let cases = [
        (
            format!("{header}\n{good}\n0.1,0,0,x,0,9.81,0,16,-41,1,0,0,0,1\n"),
            "line 3, column 4",
        ),
        (
            format!("{header}\n{good}\n0.1,0,0\n"),
            "line 3: 14 columns expected, found 3",
        ),
        (
            format!("{header}\n{good},7\n"),
            "line 2: more than 14 columns",
        ),
        (
            format!("{header}\n0.1,0,0,0,0,9.81,0,16,-41,1,0,0,0,2\n"),
            "line 2: movement must be 0 or 1",
        ),
        ("a,b\n1,2\n".to_string(), "line 1: unknown header"),
    ];
    for (text, want) in cases {
        match data::parse(&text) {
            Err(e) => assert!(e.contains(want), "{e:?} should say {want:?}"),
            Ok(_) => panic!("{text:?} parsed"),
        }
    }
    assert!(
        matches!(data::parse(&format!("{header}\n{good}\n")), Ok(data::Recording::Broad(s)) if s.len() == 1)
    );
}
