//! The orientation filter on a real recording with optical ground truth:
//! BROAD trial 16 (fast translation), shipped gzipped in the testkit's
//! `data/` (attribution and changes in its `README.md`), scored with BROAD's
//! metric by the same code as the comparison binary `broad`.

use rigtform::accuracy;
use rigtform::attitude::FilterParams;
use rigtform_testkit::broad::{data, metric, trial_16};

fn samples() -> Vec<data::BroadSample> {
    match data::read(&trial_16()) {
        Ok(data::Recording::Broad(samples)) => samples,
        Ok(_) => panic!("{} is not a BROAD trial", trial_16().display()),
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn broad_16_inclination_and_total_rmse_stay_within_their_bounds() {
    let samples = samples();
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
