//! The largest error of a measurement, and the input that caused it.

/// The largest error seen, and the input that caused it; [`check`](Self::check)
/// prints it and fails if it exceeds a bound.
///
/// ```
/// let mut worst = rigtform_testkit::Worst::new("example");
/// worst.see(1e-7, || "a".into());
/// worst.see(3e-7, || "b".into());
/// worst.see(2e-7, || "c".into());
/// worst.check(4e-7); // prints "example  max 3.000e-7 ..."
/// ```
pub struct Worst {
    name: &'static str,
    error: f64,
    input: String,
}

impl Worst {
    /// No error seen yet, for the measurement called `name`.
    pub fn new(name: &'static str) -> Self {
        Self {
            name,
            error: 0.0,
            input: String::new(),
        }
    }

    /// Records `error`; `input` describes the input, and is formatted only
    /// for a new maximum. Panics on a NaN error.
    pub fn see(&mut self, error: f64, input: impl FnOnce() -> String) {
        assert!(!error.is_nan(), "{}: NaN error for {}", self.name, input());
        if error > self.error {
            self.error = error;
            self.input = input();
        }
    }

    /// Prints the maximum beside `bound`, and panics, naming the input, if
    /// the maximum exceeds it.
    pub fn check(&self, bound: f32) {
        println!(
            "{:<44} max {:.3e}  (bound {:.1e})",
            self.name, self.error, bound
        );
        assert!(
            self.error <= bound as f64,
            "{}: error {:e} exceeds the documented bound {:e}, at {}",
            self.name,
            self.error,
            bound,
            self.input
        );
    }
}
