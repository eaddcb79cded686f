//! A fingerprint of the filter's estimates on a trial: the FNV-1a hash (64
//! bits) of the bits of every estimate, 6D and 9D, in sample order. Two
//! builds that print the same fingerprints gave every estimate of those
//! trials to the bit; the hash is over `f32::to_bits` of `w, x, y, z` in
//! little-endian bytes, so it does not depend on the host.

use std::hash::Hasher;

use fnv::FnvHasher;
use rigtform::attitude::FilterParams;
use rigtform::Quat;
use rigtform_testkit::broad::data::BroadSample;
use rigtform_testkit::broad::metric;

/// The FNV-1a hash of the bits of `estimates`.
pub fn hash(estimates: &[Quat]) -> u64 {
    let mut hasher = FnvHasher::default();
    for q in estimates {
        for c in q.to_wxyz() {
            hasher.write(&c.to_bits().to_le_bytes());
        }
    }
    hasher.finish()
}

/// One line for the trial `name`: the hashes of our 6D and 9D estimates
/// over `samples` with `params`.
pub fn line(name: &str, samples: &[BroadSample], params: FilterParams) -> String {
    let six = metric::run(samples, params, false);
    let nine = metric::run(samples, params, true);
    format!(
        "{name}: 6D {:016x}, 9D {:016x} ({} estimates each)",
        hash(&six.estimates),
        hash(&nine.estimates),
        samples.len()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hash of an empty run is FNV-1a's offset basis, and one bit of
    /// one component changes it.
    #[test]
    fn one_bit_changes_the_fingerprint() {
        assert_eq!(hash(&[]), 0xcbf2_9ce4_8422_2325);
        let q = Quat::from_rotation_x(0.3);
        let [w, x, y, z] = q.to_wxyz();
        let nudged = Quat::from_wxyz(w, x, f32::from_bits(y.to_bits() ^ 1), z);
        assert_ne!(hash(&[q, q]), hash(&[q, nudged]));
        assert_eq!(hash(&[q, q]), hash(&[q, q]));
    }
}
