//! Every input the fuzzers found (`fuzz/regressions/<target>/`) replayed
//! through the laws its target checks (`rigtform_proofs::fuzz_laws`), decoded
//! as `arbitrary` 1.5 decodes the target's input: `f32`s as four
//! little-endian bytes each, fields in declaration order, missing bytes
//! zero, and the last element of a trailing array read again from the bytes
//! after the array.

use rigtform::Quat;
use rigtform_proofs::fuzz_laws;
use std::fs;
use std::path::{Path, PathBuf};

/// The bytes of one input, read in order as `arbitrary` reads them.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn f32(&mut self) -> f32 {
        let mut buf = [0u8; 4];
        let n = buf.len().min(self.0.len());
        buf[..n].copy_from_slice(&self.0[..n]);
        self.0 = &self.0[n..];
        f32::from_le_bytes(buf)
    }

    fn array<const N: usize>(&mut self) -> [f32; N] {
        core::array::from_fn(|_| self.f32())
    }

    /// A trailing array: its last element is read once more.
    fn trailing_array<const N: usize>(&mut self) -> [f32; N] {
        let mut values = self.array::<N>();
        if let Some(last) = values.last_mut() {
            *last = self.f32();
        }
        values
    }
}

fn regressions() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/regressions")
}

/// The files of `dir`, sorted.
fn files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("a directory entry").path())
        .collect();
    files.sort();
    files
}

/// Replays `input` of `target` through the target's laws; false if no
/// decoder knows the target.
fn replay(target: &str, input: &[u8]) -> bool {
    let mut bytes = Bytes(input);
    match target {
        "pow" => {
            let q = bytes.array::<4>();
            let alpha = bytes.f32();
            fuzz_laws::pow(q, alpha);
        }
        "slerp" => {
            let (a, b, c) = (bytes.array::<4>(), bytes.array::<4>(), bytes.array::<4>());
            let alpha = bytes.f32();
            let weights = bytes.trailing_array::<3>();
            fuzz_laws::slerp(a, b, c, alpha, weights);
        }
        "sampler" => {
            let (times, values) = (bytes.array::<4>(), bytes.array::<48>());
            let (selector, t) = (bytes.f32(), bytes.f32());
            fuzz_laws::sampler(times, values, selector, t);
        }
        _ => return false,
    }
    true
}

#[test]
fn every_fuzz_regression_keeps_its_targets_laws() {
    let mut replayed = 0;
    for dir in files(&regressions()) {
        let target = dir
            .file_name()
            .and_then(|n| n.to_str())
            .expect("a target's folder name")
            .to_owned();
        for file in files(&dir) {
            let input = fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
            assert!(
                replay(&target, &input),
                "{}: no decoder for the target {target}; add it to replay()",
                file.display()
            );
            replayed += 1;
        }
    }
    // The pow input and the three pairs pi apart, at least.
    assert!(replayed >= 4, "only {replayed} regressions found");
}

/// The `pow` regression has `alpha = -1e30`, beyond the `|alpha| <= 4` of
/// `pow_turns_as_the_notes_define`, so its replay checks the norm and not
/// the angle. What holds for it, and is checked here on the file itself:
/// the result is finite and unit.
#[test]
fn pow_of_a_huge_w_to_a_huge_power_is_finite_and_unit() {
    let file = regressions().join("pow/huge-w-tiny-vector-alpha-minus-1e30");
    let input = fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let mut bytes = Bytes(&input);
    let q = wxyz(bytes.array::<4>());
    let alpha = bytes.f32();
    assert_eq!(
        (q.to_wxyz(), alpha),
        ([2.7e10, 1.0e-26, -9.6e-35, 2.5e-30], -1e30)
    );
    let r = q.pow(alpha);
    assert!(r.is_finite(), "{r:?}");
    let n = r
        .to_array()
        .map(f64::from)
        .iter()
        .map(|c| c * c)
        .sum::<f64>();
    assert!(
        (n - 1.0).abs() <= rigtform_proofs::laws::ONE_STEP_NORM_TOL,
        "{n}"
    );
}

/// The slerp pairs pi apart: a . b is exactly zero in each.
#[test]
fn the_slerp_pairs_are_exactly_pi_apart() {
    for name in [
        "pi-apart-half-way",
        "pi-apart-extrapolated",
        "pi-apart-far-extrapolated",
    ] {
        let file = regressions().join("slerp").join(name);
        let input = fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let mut bytes = Bytes(&input);
        let (a, b) = (wxyz(bytes.array::<4>()), wxyz(bytes.array::<4>()));
        assert_eq!(a.dot(b), 0.0, "{name}");
        assert_eq!((a.norm_squared(), b.norm_squared()), (1.0, 1.0), "{name}");
    }
}

/// Four floats of a regression, scalar first, as the fuzz targets read them.
fn wxyz([w, x, y, z]: [f32; 4]) -> Quat {
    Quat::from_wxyz(w, x, y, z)
}

/// The sampler target's committed seeds (`fuzz/seeds/sampler/`: every
/// interpolation and key count beside edge times and values) keep its laws
/// here too, where CI runs them without a fuzzer.
#[test]
fn sampler_seeds_keep_the_targets_laws() {
    let dir = regressions().join("../seeds/sampler");
    let seeds = files(&dir);
    assert!(seeds.len() >= 100, "only {} sampler seeds", seeds.len());
    for file in seeds {
        let input = fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        assert!(replay("sampler", &input));
    }
}
