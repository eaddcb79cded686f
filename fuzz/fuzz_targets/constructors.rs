//! The ways to build a rotation, on raw bit patterns: Euler angles both
//! ways (every order), `from_matrix` of `from_quat`, `from_rotation_arc`
//! and `look_at`. No panic on anything; the laws where their
//! preconditions hold.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::{Cvec3, EulerRot, Matrix4, Quat, RigTForm};
use rigtform_proofs::laws::{self, assert_holds};

#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    q: [f32; 4],
    angles: [f32; 3],
    order: u8,
    from: [f32; 3],
    to: [f32; 3],
    up: [f32; 3],
    matrix: [f32; 16],
}

/// Squared lengths in [2^-40, 2^80]: the arc law's precondition.
fn moderate(v: Cvec3) -> bool {
    v.is_finite() && (9.094947e-13..=1.2089258e24).contains(&v.norm_squared())
}

fuzz_target!(|input: Input| {
    let order = EulerRot::ALL[usize::from(input.order) % EulerRot::ALL.len()];
    let [w, x, y, z] = input.q;
    let q = Quat::from_wxyz(w, x, y, z);
    let [a, b, c] = input.angles;
    let (from, to, up) = (
        Cvec3::from_array(input.from),
        Cvec3::from_array(input.to),
        Cvec3::from_array(input.up),
    );
    let m = Matrix4::from(input.matrix);

    // No panic on anything, and NaN out for NaN in.
    let built = Quat::from_euler(order, a, b, c);
    assert_eq!(
        built.is_nan(),
        !(a.is_finite() && b.is_finite() && c.is_finite())
    );
    let (x, y, z) = q.to_euler(order);
    assert_eq!(x.is_nan() && y.is_nan() && z.is_nan(), !q.is_finite());
    let _ = (Quat::from_matrix(m), m.determinant(), q.is_normalized());
    let _ = (
        Quat::from_rotation_arc(from, to),
        RigTForm::look_at(from, to, up),
    );

    if let Some(unit) = q.try_normalize() {
        assert_holds(laws::euler_angles_give_back_the_rotation(unit, order));
        assert_holds(laws::from_matrix_inverts_from_quat(unit));
    }
    if moderate(from) && moderate(to) {
        assert_holds(laws::rotation_arc_takes_from_to_to(from, to));
    }
});
