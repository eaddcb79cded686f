//! Matrix3's laws: products, transposes and conversions against glam,
//! inverses and determinants against nalgebra in f64.

use super::*;
use crate::Matrix4;
use rand::{Rng, SeedableRng};

fn to_glam(m: Matrix3) -> glam::Mat3 {
    glam::Mat3::from_cols_array(&m.to_cols_array())
}

fn to_f64(m: Matrix3) -> nalgebra::Matrix3<f64> {
    nalgebra::Matrix3::from_column_slice(&m.to_cols_array().map(f64::from))
}

use crate::test_draws::count as draws;

#[test]
fn inverse_and_determinant_are_within_their_bounds_of_nalgebra_in_f64() {
    use crate::accuracy::{MATRIX3_DETERMINANT_MAX_REL_ERROR, MATRIX3_INVERSE_MAX_REL_ERROR};
    let mut rng = rand::rngs::StdRng::seed_from_u64(27);
    let (mut worst_inv, mut worst_det, mut seen) = (0f64, 0f64, 0);
    for _ in 0..draws() {
        let m = Matrix3::from_cols_array(&core::array::from_fn(|_| rng.random_range(-1.0..=1.0)));
        let m64 = to_f64(m);
        let Some(inv64) = m64.try_inverse() else {
            continue;
        };
        let cond = m64.norm() * inv64.norm();
        if cond > 1e4 {
            continue;
        }
        seen += 1;
        let inv = m.inverse().expect("invertible");
        // The determinant's error, relative to the sum of its expansion's
        // magnitudes (the bound's measure, which needs no condition).
        let c = m.to_cols_array().map(f64::from);
        let terms = rigtform_proofs::reference::leibniz_expansion(&c, 3).1;
        let det = m64.determinant();
        let e_det = (f64::from(m.determinant()) - det).abs() / terms;
        // Each entry's error, relative to its minor's products and the
        // determinant's error carried through 1 / det, where the
        // expansion cancels by at most 2^12 (the bound's domain).
        let got = inv.to_cols_array();
        let mut e_inv = 0f64;
        if terms <= 4096.0 * det.abs() {
            for (i, j) in (0..3).flat_map(|i| (0..3).map(move |j| (i, j))) {
                let (p, q) = (3 * ((i + 1) % 3), 3 * ((i + 2) % 3));
                let (k, l) = ((j + 1) % 3, (j + 2) % 3);
                let minor = c[p + k] * c[q + l] - c[p + l] * c[q + k];
                let am = (c[p + k] * c[q + l]).abs() + (c[p + l] * c[q + k]).abs();
                let scale = (am + minor.abs() * terms / det.abs()) / det.abs();
                let error = (f64::from(got[3 * j + i]) - minor / det).abs();
                e_inv = e_inv.max(error / scale);
            }
        }
        worst_inv = worst_inv.max(e_inv);
        worst_det = worst_det.max(e_det);
        assert!(
            e_inv <= f64::from(MATRIX3_INVERSE_MAX_REL_ERROR),
            "{m:?}: {e_inv:e}"
        );
        assert!(
            e_det <= f64::from(MATRIX3_DETERMINANT_MAX_REL_ERROR),
            "{m:?}: {e_det:e}"
        );
        // glam's inverse (cofactors too) agrees, within both errors.
        let g = to_glam(m).inverse();
        let size = g.to_cols_array().iter().fold(0f32, |a, b| a.max(b.abs()));
        assert!(g.abs_diff_eq(to_glam(inv), 1e-5 * cond as f32 * size));
    }
    std::println!(
        "Matrix3 over {seen} draws (condition <= 1e4): inverse {worst_inv:.3e} (per entry, relative to its minor and the determinant's cancellation), determinant {worst_det:.3e} (relative to the expansion's terms)"
    );
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
