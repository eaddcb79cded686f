//! The habits `columns!` gives both matrices, held against glam's `Mat3`
//! and `Mat4`: bit for bit where the arithmetic is the same (arrays, rows,
//! diagonals, sums, scaling, products), within the entry bound where glam
//! takes its rotations from the sine and cosine of the whole angle.

use super::{Matrix3, Matrix4};
use crate::{Cvec3, Cvec4, EulerRot, Quat};
use rand::{Rng, SeedableRng};

/// The same test of both matrices: `$m` against glam's `$g`, columns `$v`
/// against glam's `$gv`, and glam's names for the products and sums.
macro_rules! against_glam {
    (
        $everyday:ident, $rotations:ident: $m:ident ~ $g:ty, $v:ident ~ $gv:ty,
        $mul_m:ident, $mul_v:ident, $add_m:ident, $sub_m:ident, rows($($i:literal),*)
    ) => {
        #[test]
        fn $everyday() {
            let g = |m: $m| <$g>::from_cols_array(&m.to_cols_array());
            let bits = |m: $m| m.to_cols_array().map(f32::to_bits);
            let gbits = |m: $g| m.to_cols_array().map(f32::to_bits);
            let vbits = |v: $v, w: $gv| assert_eq!(v.to_array().map(f32::to_bits), w.to_array().map(f32::to_bits));
            let mut rng = rand::rngs::StdRng::seed_from_u64(40);
            let mut draw = || $m::from_cols_array(&core::array::from_fn(|_| rng.random_range(-4.0..4.0)));
            for _ in 0..10_000 {
                let (a, b, v) = (draw(), draw(), draw().col(1));
                let (ga, gb, gv) = (g(a), g(b), <$gv>::from_array(v.to_array()));
                let s = v.x;
                assert_eq!(bits(a + b), gbits(ga + gb));
                assert_eq!(bits(a - b), gbits(ga - gb));
                assert_eq!(bits(-a), gbits(-ga));
                assert_eq!(bits(a * s), gbits(ga * s));
                assert_eq!(bits(s * a), gbits(s * ga));
                assert_eq!(bits(a / s), gbits(ga / s));
                assert_eq!(bits(a.mul_scalar(s)), gbits(ga.mul_scalar(s)));
                assert_eq!(bits(a.div_scalar(s)), gbits(ga.div_scalar(s)));
                assert_eq!(bits(a.$mul_m(&b)), gbits(ga.$mul_m(&gb)));
                assert_eq!(bits(a.$add_m(&b)), gbits(ga.$add_m(&gb)));
                assert_eq!(bits(a.$sub_m(&b)), gbits(ga.$sub_m(&gb)));
                vbits(a.$mul_v(v), ga.$mul_v(gv));
                assert_eq!(bits(a.abs()), gbits(ga.abs()));
                assert_eq!(bits([a, b, a].into_iter().sum()), gbits([ga, gb, ga].into_iter().sum()));
                assert_eq!(bits([a, b].iter().sum()), gbits([ga, gb].iter().sum()));
                assert_eq!(bits([a, b, a].into_iter().product()), gbits([ga, gb, ga].into_iter().product()));
                let mut c = a;
                c += b;
                c -= a;
                c *= s;
                c /= 3.0;
                assert_eq!(c, (a + b - a) * s / 3.0);
                let rows = a.to_cols_array_2d();
                assert_eq!(rows, ga.to_cols_array_2d());
                assert_eq!(bits($m::from_cols_array_2d(&rows)), bits(a));
                assert_eq!(a.to_rows_array(), ga.to_rows_array());
                let array = a.to_cols_array();
                assert_eq!(bits($m::from_rows_array(&array)), gbits(<$g>::from_rows_array(&array)));
                assert_eq!(bits($m::from_diagonal(v)), gbits(<$g>::from_diagonal(gv)));
                vbits(a.diagonal(), ga.diagonal());
                match (a.try_inverse(), ga.try_inverse()) {
                    (Some(ours), Some(theirs)) => {
                        // Both within a few ulps times the condition number.
                        let largest = |m: $g| m.abs().to_cols_array().iter().fold(0f32, |x, y| x.max(*y));
                        let size = largest(theirs);
                        let tolerance = 1e-5 * size * size * largest(ga);
                        assert!(g(ours).abs_diff_eq(theirs, tolerance), "{a:?}");
                        assert_eq!(a.inverse_or_zero(), ours);
                    }
                    (None, _) => assert_eq!(a.inverse_or_zero(), $m::ZERO),
                    (Some(_), None) => panic!("glam finds no inverse of {a:?}"),
                }
            }
            let rows = [$(draw().col($i)),*];
            let theirs = rows.map(|r| <$gv>::from_array(r.to_array()));
            assert_eq!(bits($m::from_rows($(rows[$i]),*)), gbits(<$g>::from_rows($(theirs[$i]),*)));
            assert_eq!(bits($m::ZERO), gbits(<$g>::ZERO));
            assert!($m::NAN.is_nan() && <$g>::NAN.is_nan() && !$m::IDENTITY.is_nan());
            assert_eq!($m::ZERO.try_inverse(), None);
            assert_eq!($m::NAN.inverse_or_zero(), $m::ZERO);
        }

        #[test]
        fn $rotations() {
            let g = |m: $m| <$g>::from_cols_array(&m.to_cols_array());
            let close = |m: $m, theirs: $g| g(m).abs_diff_eq(theirs, 2.0 * crate::accuracy::MATRIX_ENTRY_ERROR);
            let mut rng = rand::rngs::StdRng::seed_from_u64(41);
            for _ in 0..10_000 {
                let angle = rng.random_range(-3.0..3.0f32);
                let axis = Cvec3::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)).normalize();
                let gaxis = glam::Vec3::from_array(axis.to_array());
                assert!(close($m::from_axis_angle(axis, angle), <$g>::from_axis_angle(gaxis, angle)));
                assert!(close($m::from_rotation_x(angle), <$g>::from_rotation_x(angle)));
                assert!(close($m::from_rotation_y(angle), <$g>::from_rotation_y(angle)));
                assert!(close($m::from_rotation_z(angle), <$g>::from_rotation_z(angle)));
                let q = Quat::from_axis_angle(axis, angle);
                assert_eq!($m::from(q), $m::from_quat(q));
                let (a, b, c) = (rng.random_range(-3.0..3.0), rng.random_range(-1.5..1.5), rng.random_range(-3.0..3.0));
                for (order, gorder) in [(EulerRot::ZYX, glam::EulerRot::ZYX), (EulerRot::XYZ, glam::EulerRot::XYZ), (EulerRot::YXZ, glam::EulerRot::YXZ)] {
                    let m = $m::from_euler(order, a, b, c);
                    assert!(close(m, <$g>::from_euler(gorder, a, b, c)));
                    let (x, y, z) = m.to_euler(order);
                    let (gx, gy, gz) = g(m).to_euler(gorder);
                    let back = Quat::from_euler(order, x, y, z);
                    let theirs = Quat::from_euler(order, gx, gy, gz);
                    let bound = crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR + crate::accuracy::EULER_MAX_ANGLE_ERROR;
                    assert!(back.angle_to(Quat::from_euler(order, a, b, c)) <= bound + crate::accuracy::MATRIX_ENTRY_ERROR * 4.0, "{order:?} {a} {b} {c}");
                    assert!(back.angle_to(theirs) < 1e-5, "{order:?} {a} {b} {c}");
                }
            }
        }
    };
}

against_glam!(
    matrix4_everyday_methods_are_glams_bit_for_bit,
    matrix4_rotations_agree_with_glams: Matrix4 ~ glam::Mat4, Cvec4 ~ glam::Vec4,
    mul_mat4, mul_vec4, add_mat4, sub_mat4, rows(0, 1, 2, 3)
);
against_glam!(
    matrix3_everyday_methods_are_glams_bit_for_bit,
    matrix3_rotations_agree_with_glams: Matrix3 ~ glam::Mat3, Cvec3 ~ glam::Vec3,
    mul_mat3, mul_vec3, add_mat3, sub_mat3, rows(0, 1, 2)
);

#[test]
fn minors_and_affine_blocks_are_glams() {
    let mut rng = rand::rngs::StdRng::seed_from_u64(42);
    for _ in 0..1000 {
        let m = Matrix4::from_cols_array(&core::array::from_fn(|_| rng.random()));
        let g = glam::Mat4::from_cols_array(&m.to_cols_array());
        for i in 0..4 {
            for j in 0..4 {
                let ours = Matrix3::from_mat4_minor(m, i, j).to_cols_array();
                assert_eq!(ours, glam::Mat3::from_mat4_minor(g, i, j).to_cols_array());
            }
        }
        let (block, t) = (
            Matrix3::from(m),
            Cvec3::new(rng.random(), rng.random(), rng.random()),
        );
        let theirs = glam::Mat4::from_mat3_translation(
            glam::Mat3::from_cols_array(&block.to_cols_array()),
            glam::Vec3::from_array(t.to_array()),
        );
        assert_eq!(
            Matrix4::from_mat3_translation(block, t).to_cols_array(),
            theirs.to_cols_array()
        );
    }
    for (i, j) in [(4, 0), (0, 4), (usize::MAX, usize::MAX)] {
        assert!(Matrix3::from_mat4_minor(Matrix4::IDENTITY, i, j)
            .to_cols_array()
            .iter()
            .all(|x| x.is_nan()));
    }
    assert_eq!(
        Matrix4::from_mat3_translation(Matrix3::ZERO, Cvec3::ONE).col(3),
        Cvec4::ONE
    );
}
