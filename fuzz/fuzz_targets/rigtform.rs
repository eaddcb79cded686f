//! `RigTForm` on raw bit patterns: product with the inverse, inverse of the
//! inverse, agreement with `Matrix4::inverse` and with the matrix's action
//! on points and vectors, interpolation exact at zero, `interpolate_slice`
//! equal to `interpolate` bit for bit, the spline's translation as the
//! cubic, and no panic on anything.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::{Cvec3, Cvec4, Matrix4, Quat, RigTForm};
use rigtform_proofs::laws::{self, assert_holds};

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    t: [f32; 3],
    r: [f32; 4],
    t2: [f32; 3],
    r2: [f32; 4],
    alpha: f32,
    point: [f32; 3],
    is_point: bool,
}

/// 2^20: the laws' bound on translations for the matrix comparison.
const LIMIT: f32 = 1_048_576.0;
/// 2^100: the spline's translation law's bound on translations.
const SPLINE_LIMIT: f32 = 1.267_650_6e30;

fn vec3([x, y, z]: [f32; 3]) -> Cvec3 {
    Cvec3::new(x, y, z)
}

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat::from_wxyz(w, x, y, z)
}

fn within_limit(v: Cvec3) -> bool {
    [v.x, v.y, v.z].iter().all(|c| c.abs() <= LIMIT)
}

fuzz_target!(|input: Input| {
    let a = RigTForm::new(vec3(input.t), quat(input.r));
    let b = RigTForm::new(vec3(input.t2), quat(input.r2));
    let p = vec3(input.point);
    let c = if input.is_point {
        Cvec4::from_point(p)
    } else {
        Cvec4::from_vector(p)
    };

    // No panic on anything.
    let _ = (a * b, a.inv(), a.interpolate(b, input.alpha), a * c);
    let _ = Matrix4::from(a).inverse();
    assert_holds(laws::interpolate_slice_is_interpolate_bit_for_bit(
        &[a, b, a],
        &[b, a, a],
        input.alpha,
    ));
    let _ = RigTForm::catmull_rom(&[a, b, a * b], input.alpha);
    let spline_ok = |v: Cvec3| [v.x, v.y, v.z].iter().all(|c| c.abs() <= SPLINE_LIMIT);
    if input.alpha.is_finite() && [a.t, b.t, p].into_iter().all(spline_ok) {
        let keys = [a, b, RigTForm::new(p, b.r)];
        assert_holds(laws::catmull_rom_translation_is_the_cubic(
            &keys,
            input.alpha,
        ));
    }

    let zero = Quat::from_wxyz(0.0, 0.0, 0.0, 0.0);
    if !(a.r.is_finite() && a.r != zero && within_limit(a.t) && within_limit(b.t)) {
        return;
    }
    let a = RigTForm::new(a.t, a.r.normalize());
    assert_holds(laws::rigid_product_with_inverse_is_identity(a));
    assert_holds(laws::rigid_inverse_is_an_involution(a));
    assert_holds(laws::rigid_inverse_matches_matrix_inverse(a));
    if within_limit(p) {
        assert_holds(laws::rigid_matrix_moves_points_as_the_transform(a, c));
    }
    if b.r.is_finite() && [b.r.w, b.r.x, b.r.y, b.r.z].iter().all(|c| c.abs() <= 1e18) {
        assert_holds(laws::interpolate_is_exact_at_zero(a, b));
    }
});
