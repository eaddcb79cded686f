//! `Matrix4::inverse` and `normal_matrix` on raw bit patterns: `None` or
//! finite entries, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::Matrix4;
use rigtform_proofs::laws;

fuzz_target!(|entries: [f32; 16]| {
    laws::assert_holds(laws::matrix_inverse_is_none_or_finite(
        Matrix4::from_cols_array(&entries),
    ));
});
