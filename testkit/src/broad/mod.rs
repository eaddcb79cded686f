//! The BROAD benchmark's recordings and error metric (Laidig, Caruso,
//! Cereatti, Seel, *BROAD — A Benchmark for Robust Inertial Orientation
//! Estimation*, Data 6(7):72, 2021), and x-io's Fusion sample log.
//!
//! [`data`] reads the recordings (plain or gzipped CSV), [`metric`] scores
//! a filter run exactly as the benchmark does. Trial 16 is shipped in this
//! crate's `data/` folder, with its attribution; [`trial_16`] gives its path.

pub mod data;
pub mod metric;

use std::path::PathBuf;

/// The path of BROAD trial 16 ("undisturbed fast translation"), shipped
/// gzipped in `data/` (attribution and changes in `data/README.md`).
///
/// ```
/// assert!(rigtform_testkit::broad::trial_16().is_file());
/// ```
pub fn trial_16() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data/broad_16_undisturbed_fast_translation_B.csv.gz")
}
