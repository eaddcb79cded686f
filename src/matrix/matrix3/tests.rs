//! Matrix3's laws: products, transposes and conversions against glam.
//! Its inverse and determinant are checked against nalgebra in f64 in
//! tests/differential.rs.

use super::*;
use crate::Matrix4;
use rand::{Rng, SeedableRng};

fn to_glam(m: Matrix3) -> glam::Mat3 {
    glam::Mat3::from_cols_array(&m.to_cols_array())
}

#[test]
fn products_transpose_and_conversions_agree_with_glam() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(28);
    for _ in 0..1000 {
        let a = Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..=4.0)));
        let b = Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..=4.0)));
        let v = Cvec3::new(rng.random(), rng.random(), rng.random());
        let gv = glam::Vec3::new(v.x, v.y, v.z);
        let close = |x: glam::Mat3, y: glam::Mat3| x.abs_diff_eq(y, 1e-5);
        assert!(close(to_glam(a * b), to_glam(a) * to_glam(b)));
        assert!(
            ((to_glam(a) * gv).to_array().iter().zip((a * v).to_array()))
                .all(|(x, y)| (x - y).abs() <= 1e-5)
        );
        assert_eq!(to_glam(a.transpose()), to_glam(a).transpose());
        assert_eq!(a.determinant().signum(), to_glam(a).determinant().signum());
        for i in 0..3 {
            assert_eq!(a.col(i).to_array(), to_glam(a).col(i).to_array());
            assert_eq!(a.row(i).to_array(), to_glam(a).row(i).to_array());
        }
        let q = Quat::from_axis_angle(v + Cvec3::ONE, rng.random_range(-3.0..3.0));
        let gq = glam::Quat::from_xyzw(q.x, q.y, q.z, q.w);
        assert!(close(
            to_glam(Matrix3::from_quat(q)),
            glam::Mat3::from_quat(gq)
        ));
        let m4 = Matrix4::from_cols_array(&core::array::from_fn(|_| rng.random()));
        let g4 = glam::Mat4::from_cols_array(&m4.to_cols_array());
        assert_eq!(to_glam(Matrix3::from(m4)), glam::Mat3::from_mat4(g4));
        assert_eq!(Matrix3::from_mat4(m4), Matrix3::from(m4));
        assert_eq!(Matrix4::from_mat3(a), Matrix4::from(a));
        let back = Matrix4::from(a).to_cols_array();
        assert_eq!(back, glam::Mat4::from_mat3(to_glam(a)).to_cols_array());
        assert_eq!(Matrix3::from(<[f32; 9]>::from(a)), a);
    }
    assert!(Matrix3::IDENTITY.col(3).is_nan() && Matrix3::IDENTITY.row(usize::MAX).is_nan());
    assert_eq!(Matrix3::default(), Matrix3::IDENTITY);
    assert_eq!(to_glam(Matrix3::IDENTITY), glam::Mat3::IDENTITY);
    assert_eq!(to_glam(Matrix3::ZERO), glam::Mat3::ZERO);
    assert_eq!(
        std::format!(
            "{}",
            Matrix3::from_cols_array(&core::array::from_fn(|i| i as f32 * 0.5))
        ),
        std::format!(
            "{}",
            glam::Mat3::from_cols_array(&core::array::from_fn(|i| i as f32 * 0.5))
        )
    );
    let mut m = Matrix3::IDENTITY;
    m *= Matrix3::from_cols(Cvec3::X * 2.0, Cvec3::Y, Cvec3::Z);
    assert_eq!(m.determinant(), 2.0);
}

#[test]
fn singular_huge_and_non_finite_matrices_have_no_inverse() {
    let rank2 = Matrix3::from_cols(Cvec3::X, Cvec3::Y, Cvec3::X + Cvec3::Y);
    assert_eq!(rank2.inverse(), None);
    assert_eq!(Matrix3::NAN.inverse(), None);
    let mut inf = Matrix3::IDENTITY;
    inf.cols[2].z = f32::INFINITY;
    assert_eq!(inf.inverse(), None);
    // Minors of 2^86, beyond the 2^62 that keeps the determinant finite.
    let big = Matrix3::from_cols(Cvec3::X, Cvec3::Y, Cvec3::Z)
        * Matrix3::from_cols(
            Cvec3::X * 2f32.powi(43),
            Cvec3::Y * 2f32.powi(43),
            Cvec3::Z * 2f32.powi(43),
        );
    assert_eq!(big.inverse(), None);
    // 1 / det overflows for a tiny determinant.
    let tiny = Matrix3::from_cols(Cvec3::X * 1e-20, Cvec3::Y * 1e-20, Cvec3::Z);
    assert_eq!(tiny.inverse(), None);
    let huge = Matrix3::from_cols(Cvec3::X * 1e19, Cvec3::Y, Cvec3::Z);
    assert_eq!(huge.inverse(), None);
    assert!(Matrix3::NAN.determinant().is_nan());
}
