//! What the kernels' tests share: errors in ulps against an f64 reference,
//! the arguments they sweep, and the largest error of a sweep checked
//! against its bound (as libm tests its own kernels).

/// The ulp of `want` rounded to f32: the gap above its magnitude.
pub(crate) fn ulp(want: f64) -> f64 {
    let w = (want as f32).abs();
    (f32::from_bits(w.to_bits() + 1) - w) as f64
}

/// Distance from `got` to the exact `want`, in ulps of `want` rounded to f32.
pub(crate) fn ulps(got: f32, want: f64) -> f64 {
    (got as f64 - want).abs() / ulp(want)
}

/// `n` points evenly spread over [lo, hi], endpoints included.
pub(crate) fn spread(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f32> {
    (0..=n).map(move |i| (lo + (hi - lo) * i as f64 / n as f64) as f32)
}

/// The step of the kernel sweeps every test run does: every 997th f32 of
/// a range (about a million arguments per range). The exhaustive sweeps,
/// run by hand, take every f32 (step 1).
pub(crate) const SAMPLE_STEP: usize = 997;

/// Every `step`-th f32 from `lo` to `hi` (both included, both >= 0).
pub(crate) fn floats(lo: f32, hi: f32, step: usize) -> impl Iterator<Item = f32> {
    (lo.to_bits()..=hi.to_bits())
        .step_by(step)
        .chain([hi.to_bits()])
        .map(f32::from_bits)
}

/// The largest ulp error of one kernel over a sweep, with the argument that
/// reached it, and the bound it must stay within.
pub(crate) struct Worst {
    what: &'static str,
    ulps: f64,
    at: f32,
    bound: f32,
}

impl Worst {
    /// No error seen yet for the sweep `what`, bounded by `bound` ulps.
    pub(crate) fn new(what: &'static str, bound: f32) -> Self {
        Self {
            what,
            ulps: 0.0,
            at: 0.0,
            bound,
        }
    }

    /// Records the error `ulps` at the argument `at` (a NaN error counts as
    /// the worst).
    pub(crate) fn see(&mut self, ulps: f64, at: f32) {
        if ulps > self.ulps || ulps.is_nan() {
            self.ulps = ulps;
            self.at = at;
        }
    }

    /// Prints the maximum, and fails if it exceeds the bound.
    pub(crate) fn check(&self) {
        std::println!(
            "{:<44} max {:.3} ulp at {:e}",
            self.what,
            self.ulps,
            self.at
        );
        assert!(
            self.ulps <= self.bound as f64,
            "{} exceeds {} ulp at {:e}",
            self.what,
            self.bound,
            self.at
        );
    }
}

/// The two tests of a kernel's sweep function `$sweep(step)`:
/// `kernel_is_within_its_ulp_bounds_on_a_sample`, every [`SAMPLE_STEP`]-th
/// f32 of its ranges in every test run, and `exhaustive_kernel_sweep`,
/// every f32, run by hand after changing a kernel
/// (`cargo test --release --lib -- --ignored exhaustive_kernel_sweep`,
/// minutes in release).
macro_rules! sweep_tests {
    ($sweep:ident) => {
        #[test]
        fn kernel_is_within_its_ulp_bounds_on_a_sample() {
            $sweep($crate::float::sweep::SAMPLE_STEP);
        }

        #[test]
        #[ignore = "minutes in release: run by hand after changing a kernel"]
        fn exhaustive_kernel_sweep() {
            $sweep(1);
        }
    };
}

pub(crate) use sweep_tests;
