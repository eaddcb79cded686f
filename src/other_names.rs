//! glam's and nalgebra's names for what the notes name otherwise: the
//! [`renamed!`] macro, which each type's `other_names.rs` uses to write
//! the deprecated methods whose warning names the notes' word.

/// Each item given, with its doc comment, as a deprecated method whose
/// note is the one given (`note "..."; fn ...`), inlined and
/// `#[must_use]`, as every forwarder to the notes' name is.
macro_rules! renamed {
    ($( $(#[$doc:meta])* note $note:literal; $item:item )*) => {
        $(
            $(#[$doc])*
            #[deprecated(since = "0.1.0", note = $note)]
            #[inline]
            #[must_use]
            $item
        )*
    };
}

pub(crate) use renamed;
