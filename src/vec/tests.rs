//! The vector types' laws: operators, indexing and arrays, and glam's
//! everyday methods against glam; projections and angles against
//! nalgebra in f64.

use super::{Cvec3, Cvec4};

#[test]
fn indexing_follows_the_fields_and_clamps_past_the_end() {
    let mut v = Cvec3::new(1.0, 2.0, 3.0);
    assert_eq!(
        [v[0], v[1], v[2], v[3], v[usize::MAX]],
        [1.0, 2.0, 3.0, 3.0, 3.0]
    );
    v[1] = 5.0;
    v[9] = 7.0;
    assert_eq!(v, Cvec3::new(1.0, 5.0, 7.0));
    let mut c = Cvec4::new(1.0, 2.0, 3.0, 4.0);
    c[2] = -1.0;
    c[4] = 0.0;
    assert_eq!(c, Cvec4::new(1.0, 2.0, -1.0, 0.0));
    assert_eq!((c[0], c[1], c[7]), (1.0, 2.0, 0.0));
}

#[test]
fn compound_assignment_matches_the_operators_and_arrays_round_trip() {
    let v = Cvec4::new(1.0, -2.0, 3.0, 0.5);
    let mut m = v;
    m *= 3.0;
    assert_eq!(m, v * 3.0);
    m /= 7.0;
    assert_eq!(m, v * 3.0 / 7.0);
    let mut u = Cvec3::new(1.0, 2.0, 4.0);
    u *= 0.5;
    u /= 0.25;
    assert_eq!(u, Cvec3::new(2.0, 4.0, 8.0));
    let a: [f32; 3] = u.into();
    assert_eq!(Cvec3::from(a), u);
    let b: [f32; 4] = v.into();
    assert_eq!((b, Cvec4::from(b)), ([1.0, -2.0, 3.0, 0.5], v));
}

#[test]
fn cross_is_right_handed_and_anticommutative() {
    assert_eq!(Cvec3::X.cross(Cvec3::Y), Cvec3::Z);
    assert_eq!(Cvec3::Z.cross(Cvec3::X), Cvec3::Y);
    let a = Cvec3::new(1.0, -2.0, 0.5);
    let b = Cvec3::new(0.25, 3.0, -1.0);
    assert_eq!(a.cross(b), -b.cross(a));
    assert_eq!(a.cross(b).dot(a), 0.0);
}

#[test]
fn operators_act_per_component() {
    let a = Cvec4::new(1.0, 2.0, 3.0, 4.0);
    let b = Cvec4::new(0.5, -1.0, 2.0, 0.0);
    assert_eq!(a + b, Cvec4::new(1.5, 1.0, 5.0, 4.0));
    assert_eq!(a - b, Cvec4::new(0.5, 3.0, 1.0, 4.0));
    assert_eq!(2.0 * a, a * 2.0);
    assert_eq!(a / 2.0, Cvec4::new(0.5, 1.0, 1.5, 2.0));
    let mut c = a;
    c += b;
    c -= b;
    assert_eq!(c, a);
}

#[test]
fn normalize_of_degenerate_vectors_is_nan_not_a_panic() {
    assert!(Cvec3::ZERO.normalize().x.is_nan());
    assert!(Cvec3::new(f32::INFINITY, 0.0, 0.0).normalize().y.is_nan());
    assert!(Cvec4::ZERO.normalize().w.is_nan());
    assert_eq!(Cvec3::new(f32::MAX, 0.0, 0.0).normalize(), Cvec3::X);
    // As documented for norm: lengths beyond f32::MAX round to infinity.
    assert_eq!(Cvec3::new(f32::MAX, f32::MAX, 0.0).norm(), f32::INFINITY);
    assert_eq!(Cvec4::new(f32::MAX, 0.0, 0.0, 0.0).norm(), f32::MAX);
}

#[test]
fn arrays_hold_the_coordinates_in_order() {
    assert_eq!(Cvec3::new(1.0, 2.0, 3.0).to_array(), [1.0, 2.0, 3.0]);
    let v = Cvec4::new(1.0, 2.0, 3.0, 4.0);
    assert_eq!(Cvec4::from_array(v.to_array()), v);
    assert_eq!(v.norm_squared(), 30.0);
    assert_eq!(Cvec3::new(2.0, 3.0, 6.0).norm_squared(), 49.0);
}

#[test]
fn cvec4_products_norms_and_lerp_use_all_four_coordinates() {
    let a = Cvec4::new(1.0, 2.0, 3.0, 4.0);
    let b = Cvec4::new(-2.0, 0.5, 4.0, -1.5);
    assert_eq!(a.dot(b), -2.0 + 1.0 + 12.0 - 6.0);
    assert_eq!(Cvec4::new(1.0, 1.0, 1.0, 1.0).norm(), 2.0);
    assert_eq!(Cvec4::new(0.0, 0.0, 0.0, 5.0).norm(), 5.0);
    assert_eq!(
        Cvec4::new(0.0, 0.0, 3.0, 4.0).try_normalize(),
        Some(Cvec4::new(0.0, 0.0, 0.6, 0.8))
    );
    assert_eq!(a.lerp(b, 0.0), a);
    assert_eq!(a.lerp(b, 1.0), b);
    assert_eq!(a.lerp(b, 0.5), Cvec4::new(-0.5, 1.25, 3.5, 1.25));
    assert_eq!(a.lerp(b, -1.0), Cvec4::new(4.0, 3.5, 2.0, 9.5));
}

#[test]
fn lerp_is_exact_at_both_ends() {
    let a = Cvec3::new(0.1, 0.2, 0.3);
    let b = Cvec3::new(-7.0, 1e-3, 5.0);
    assert_eq!(a.lerp(b, 0.0), a);
    assert_eq!(a.lerp(b, 1.0), b);
    assert_eq!(a.lerp(b, 2.0), Cvec3::new(-14.1, -0.198, 9.7));
}
/// glam's `Vec3` of the same components.
fn g3(v: Cvec3) -> glam::Vec3 {
    glam::Vec3::new(v.x, v.y, v.z)
}

/// nalgebra's f64 vector of the same components.
fn n3(v: Cvec3) -> nalgebra::Vector3<f64> {
    nalgebra::Vector3::new(v.x.into(), v.y.into(), v.z.into())
}

/// A random vector with components in [-1, 1] times 2^e, e in
/// [-40, 40], so that the draws cover tiny and huge scales.
fn draw(rng: &mut impl rand::Rng) -> Cvec3 {
    let scale = 2f32.powi(rng.random_range(-40..=40));
    Cvec3::new(
        rng.random_range(-1.0..=1.0),
        rng.random_range(-1.0..=1.0),
        rng.random_range(-1.0..=1.0),
    ) * scale
}

use crate::test_draws::count as draws;

#[test]
fn everyday_methods_agree_with_glam() {
    use rand::SeedableRng;
    let mut rng = rand::rngs::StdRng::seed_from_u64(23);
    for _ in 0..draws() {
        let (a, b) = (draw(&mut rng), draw(&mut rng));
        let (ga, gb) = (g3(a), g3(b));
        assert_eq!(g3(a.min(b)), ga.min(gb));
        assert_eq!(g3(a.max(b)), ga.max(gb));
        assert_eq!(g3(a.abs()), ga.abs());
        assert_eq!(a.min_element(), ga.min_element());
        assert_eq!(a.max_element(), ga.max_element());
        assert_eq!(g3(a * b), ga * gb);
        if b.x * b.y * b.z != 0.0 {
            assert_eq!(g3(a / b), ga / gb);
        }
        assert_eq!(a.distance_squared(b), ga.distance_squared(gb));
        assert_eq!(a.length_squared(), ga.length_squared());
        assert_eq!(g3(Cvec3::splat(a.x)), glam::Vec3::splat(a.x));
        assert_eq!(<(f32, f32, f32)>::from(a), <(f32, f32, f32)>::from(ga));
        assert_eq!(Cvec3::from(<(f32, f32, f32)>::from(ga)), a);
        // glam's length squares without rescaling: compare where its
        // squares neither overflow nor underflow.
        if a.norm_squared().is_normal() && ga.length_squared() < 1e30 {
            let (ours, theirs) = (a.length(), ga.length());
            assert!((ours - theirs).abs() <= 4.0 * f32::EPSILON * theirs);
        }
        let d = (a - b).norm_squared();
        if d.is_normal() && d < 1e30 {
            let (ours, theirs) = (a.distance(b), ga.distance(gb));
            assert!((ours - theirs).abs() <= 4.0 * f32::EPSILON * theirs);
        }
        let unit = a.normalize_or_zero();
        let theirs = ga.normalize_or_zero();
        assert!((g3(unit) - theirs).length() < 4.0 * f32::EPSILON || theirs == glam::Vec3::ZERO);
        let mut c = a;
        c *= b;
        c /= b;
        let same = |x: f32, y: f32| x == y || (x.is_nan() && y.is_nan());
        let theirs = (ga * gb / gb).to_array();
        assert!((0..3).all(|i| same(c[i], theirs[i])), "{c:?} vs {theirs:?}");
    }
    assert_eq!(g3(Cvec3::ONE), glam::Vec3::ONE);
    assert_eq!(
        [Cvec3::NEG_X, Cvec3::NEG_Y, Cvec3::NEG_Z].map(g3),
        [glam::Vec3::NEG_X, glam::Vec3::NEG_Y, glam::Vec3::NEG_Z]
    );
    let v = Cvec4::new(1.0, -2.0, 3.0, -4.0);
    let gv = glam::Vec4::new(1.0, -2.0, 3.0, -4.0);
    let g4 = |c: Cvec4| glam::Vec4::from_array(c.to_array());
    assert_eq!(g4(v.abs()), gv.abs());
    assert_eq!(g4(v * v / Cvec4::splat(2.0)), gv * gv / 2.0);
    assert_eq!(g4(v.min(Cvec4::ONE)), gv.min(glam::Vec4::ONE));
    assert_eq!(g4(v.max(Cvec4::ONE)), gv.max(glam::Vec4::ONE));
    assert_eq!(
        (v.min_element(), v.max_element()),
        (gv.min_element(), gv.max_element())
    );
    assert_eq!(v.length(), gv.length());
    assert_eq!(v.distance(Cvec4::ONE), gv.distance(glam::Vec4::ONE));
    assert!((g4(v.normalize_or_zero()) - gv.normalize_or_zero()).length() < 4.0 * f32::EPSILON);
    assert_eq!(
        [Cvec4::X, Cvec4::Y, Cvec4::Z, Cvec4::W, Cvec4::NEG_W].map(g4),
        [
            glam::Vec4::X,
            glam::Vec4::Y,
            glam::Vec4::Z,
            glam::Vec4::W,
            glam::Vec4::NEG_W
        ]
    );
    assert_eq!(
        Cvec4::from((1.0, 2.0, 3.0, 4.0)),
        Cvec4::new(1.0, 2.0, 3.0, 4.0)
    );
}

/// The exact angle between the f32 inputs, in f64, by nalgebra.
fn angle64(a: Cvec3, b: Cvec3) -> f64 {
    let (a, b) = (n3(a).normalize(), n3(b).normalize());
    a.cross(&b).norm().atan2(a.dot(&b))
}

#[test]
fn angle_between_is_within_its_bound_of_nalgebra_in_f64_and_near_glam() {
    use crate::accuracy::ANGLE_BETWEEN_MAX_ERROR;
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(24);
    let mut worst = 0f64;
    for i in 0..draws() {
        let a = draw(&mut rng);
        // A third random, a third nearly parallel, a third nearly
        // opposite, 1e-7 to 1e-1 rad apart.
        let tilt = 10f32.powf(rng.random_range(-7.0..-1.0));
        let b = match i % 3 {
            0 => draw(&mut rng),
            k => {
                let off = draw(&mut rng).reject_from(a).normalize_or_zero() * a.norm() * tilt;
                let b = a + off;
                if k == 1 {
                    b * 3.0
                } else {
                    -b * 0.25
                }
            }
        };
        if !b.is_finite() || b == Cvec3::ZERO {
            continue;
        }
        let got = a.angle_between(b);
        let err = (f64::from(got) - angle64(a, b)).abs();
        worst = worst.max(err);
        assert!(
            err <= f64::from(ANGLE_BETWEEN_MAX_ERROR),
            "{a:?} {b:?}: {got} err {err:e}"
        );
        if i % 3 == 0 && (a.norm_squared() * b.norm_squared()).is_normal() {
            // glam's arccosine loses digits near 0 and pi only.
            let theirs = g3(a).angle_between(g3(b));
            assert!(
                (got - theirs).abs() < 2e-3 + ANGLE_BETWEEN_MAX_ERROR,
                "{got} vs glam {theirs}"
            );
        }
    }
    std::println!(
        "angle_between: worst error {worst:.3e} rad over {} draws",
        draws()
    );
    assert!(Cvec3::ZERO.angle_between(Cvec3::X).is_nan());
    assert!(Cvec3::X.angle_between(Cvec3::NAN).is_nan());
    assert!(Cvec3::X
        .angle_between(Cvec3::new(f32::INFINITY, 0.0, 0.0))
        .is_nan());
    assert_eq!(Cvec3::X.angle_between(-Cvec3::X), core::f32::consts::PI);
    assert_eq!(
        Cvec3::new(1e-30, 0.0, 0.0).angle_between(Cvec3::X * 1e30),
        0.0
    );
}

#[test]
fn project_onto_and_reject_from_are_within_their_bound_of_nalgebra_in_f64() {
    use crate::accuracy::PROJECT_MAX_REL_ERROR;
    use rand::SeedableRng;
    let mut rng = rand::rngs::StdRng::seed_from_u64(25);
    let (mut worst_p, mut worst_r) = (0f64, 0f64);
    for _ in 0..draws() {
        let (a, b) = (draw(&mut rng), draw(&mut rng));
        let (na, nb) = (n3(a), n3(b));
        let p64 = nb * (na.dot(&nb) / nb.dot(&nb));
        let r64 = na - p64;
        let size = na.norm();
        let ep = (n3(a.project_onto(b)) - p64).norm() / size;
        let er = (n3(a.reject_from(b)) - r64).norm() / size;
        worst_p = worst_p.max(ep);
        worst_r = worst_r.max(er);
        assert!(
            ep.max(er) <= f64::from(PROJECT_MAX_REL_ERROR),
            "{a:?} {b:?}: {ep:e} {er:e}"
        );
        if a.norm_squared().is_normal() && b.norm_squared().is_normal() {
            let scale = a.norm();
            let theirs = g3(a).project_onto(g3(b));
            assert!((g3(a.project_onto(b)) - theirs).length() < 1e-6 * scale);
            let theirs = g3(a).reject_from(g3(b));
            assert!((g3(a.reject_from(b)) - theirs).length() < 1e-6 * scale);
        }
    }
    std::println!(
        "project_onto {worst_p:.3e}, reject_from {worst_r:.3e} (relative to |self|) over {} draws",
        draws()
    );
    assert!(Cvec3::X.project_onto(Cvec3::ZERO).is_nan());
    assert!(Cvec3::X.reject_from(Cvec3::NAN).is_nan());
}

#[test]
fn cvec4_project_onto_reject_from_and_project_agree_with_nalgebra_and_glam() {
    use crate::accuracy::PROJECT_MAX_REL_ERROR;
    use rand::SeedableRng;
    let mut rng = rand::rngs::StdRng::seed_from_u64(33);
    let n4 = |v: Cvec4| nalgebra::Vector4::from(v.to_array().map(f64::from));
    let g4 = |v: Cvec4| glam::Vec4::from_array(v.to_array());
    let mut worst = 0f64;
    for _ in 0..draws() {
        let (a3, b3) = (draw(&mut rng), draw(&mut rng));
        let a = a3.extend(a3.y * 0.5 - a3.x);
        let b = b3.extend(b3.z * 2.0 + b3.x);
        let (na, nb) = (n4(a), n4(b));
        let p64 = nb * (na.dot(&nb) / nb.dot(&nb));
        let size = na.norm();
        let ep = (n4(a.project_onto(b)) - p64).norm() / size;
        let er = (n4(a.reject_from(b)) - (na - p64)).norm() / size;
        worst = worst.max(ep).max(er);
        assert!(
            ep.max(er) <= f64::from(PROJECT_MAX_REL_ERROR),
            "{a:?} {b:?}: {ep:e} {er:e}"
        );
        if a.norm_squared().is_normal() && b.norm_squared().is_normal() {
            let scale = a.norm();
            assert!((g4(a.project_onto(b)) - g4(a).project_onto(g4(b))).length() < 1e-6 * scale);
            assert!((g4(a.reject_from(b)) - g4(a).reject_from(g4(b))).length() < 1e-6 * scale);
            assert_eq!(g3(a.project()), g4(a).project());
        }
    }
    std::println!(
        "Cvec4 project_onto / reject_from: {worst:.3e} (relative to |self|) over {} draws",
        draws()
    );
    assert!(Cvec4::X.project_onto(Cvec4::ZERO).is_nan());
    assert!(!Cvec4::X.project().is_finite());
}

#[test]
fn sums_clamp_and_nan_in_agree_with_glam_or_give_nan() {
    let vs = [Cvec3::X, Cvec3::Y * 2.0, Cvec3::Z * 3.0];
    assert_eq!(vs.iter().sum::<Cvec3>(), Cvec3::new(1.0, 2.0, 3.0));
    assert_eq!(vs.into_iter().sum::<Cvec3>(), Cvec3::new(1.0, 2.0, 3.0));
    assert_eq!(core::iter::empty::<Cvec4>().sum::<Cvec4>(), Cvec4::ZERO);
    let g: glam::Vec3 = vs.iter().map(|v| g3(*v)).sum();
    assert_eq!(g3(vs.iter().sum()), g);
    let n = Cvec3::new(f32::NAN, 1.0, 2.0);
    assert!(n.is_nan() && !Cvec3::ONE.is_nan());
    for v in [n, Cvec3::ONE, Cvec3::new(1.0, 2.0, f32::NAN), Cvec3::ZERO] {
        assert_eq!(v.is_nan(), g3(v).is_nan());
        assert_eq!(
            g3(v.normalize_or(Cvec3::Z)),
            g3(v).normalize_or(glam::Vec3::Z)
        );
    }
    assert!(n.min(Cvec3::ONE).x.is_nan() && Cvec3::ONE.max(n).x.is_nan());
    assert!(n.min_element().is_nan() && n.max_element().is_nan());
    assert_eq!(n.normalize_or(Cvec3::X), Cvec3::X);
    assert_eq!(
        Cvec3::new(f32::INFINITY, 0.0, 0.0).normalize_or_zero(),
        Cvec3::ZERO
    );
    assert_eq!(Cvec3::new(0.0, 1e-40, 0.0).normalize_or_zero(), Cvec3::Y);
    assert_eq!(2.0 * Cvec3::ONE, Cvec3::splat(2.0));
    let v = Cvec3::new(-2.0, 0.5, 9.0);
    let g = g3(v).clamp(glam::Vec3::ZERO, glam::Vec3::ONE);
    assert_eq!(g3(v.clamp(Cvec3::ZERO, Cvec3::ONE)), g);
    assert!(n.clamp(Cvec3::ZERO, Cvec3::ONE).x.is_nan());
    assert_eq!(Cvec3::ONE.clamp(Cvec3::ONE, Cvec3::ZERO), Cvec3::ZERO);
    assert_eq!(
        Cvec4::from_array(g3(v).extend(2.0).to_array()),
        v.extend(2.0)
    );
    #[allow(deprecated)]
    {
        assert_eq!(v.extend(1.0).truncate(), v);
        assert_eq!(
            (v.magnitude(), v.magnitude_squared()),
            (v.norm(), v.norm_squared())
        );
        let w = Cvec4::new(1.0, 2.0, 2.0, 4.0);
        assert_eq!((w.magnitude(), w.magnitude_squared()), (5.0, 25.0));
    }
}

/// glam's spellings give glam's results: bit for bit where the
/// operations are the same, within a few ulps where glam orders them
/// otherwise.
#[test]
fn element_sum_product_midpoint_reflect_and_with_as_glam() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(36);
    for _ in 0..10_000 {
        let mut c = || rng.random_range(-10.0f32..10.0);
        let (a, b) = (Cvec3::new(c(), c(), c()), Cvec3::new(c(), c(), c()));
        let (ga, gb) = (
            glam::Vec3::from_array(a.to_array()),
            glam::Vec3::from_array(b.to_array()),
        );
        assert_eq!(a.element_sum(), ga.element_sum());
        assert_eq!(a.element_product(), ga.element_product());
        assert!((a.midpoint(b) - Cvec3::from_array(ga.midpoint(gb).to_array())).norm() <= 1e-5);
        let n = b.normalize();
        let gn = glam::Vec3::from_array(n.to_array());
        assert!((a.reflect(n) - Cvec3::from_array(ga.reflect(gn).to_array())).norm() <= 1e-5);
        assert!((a.length_recip() - ga.length_recip()).abs() <= 1e-6 * ga.length_recip());
        assert_eq!(n.is_normalized(), gn.is_normalized());
        assert_eq!(a.with_x(1.5).to_array(), ga.with_x(1.5).to_array());
        assert_eq!(a.with_y(1.5).to_array(), ga.with_y(1.5).to_array());
        assert_eq!(a.with_z(1.5).to_array(), ga.with_z(1.5).to_array());
        let (p, q) = (
            Cvec4::new(c(), c(), c(), c()),
            Cvec4::new(c(), c(), c(), c()),
        );
        let (gp, gq) = (
            glam::Vec4::from_array(p.to_array()),
            glam::Vec4::from_array(q.to_array()),
        );
        // glam's Vec4 adds and multiplies its lanes pairwise.
        let scale = p.abs().element_sum();
        assert!((p.element_sum() - gp.element_sum()).abs() <= 4.0 * f32::EPSILON * scale);
        let product = p.element_product();
        assert!((product - gp.element_product()).abs() <= 4.0 * f32::EPSILON * product.abs());
        assert!((p.midpoint(q) - Cvec4::from_array(gp.midpoint(gq).to_array())).norm() <= 1e-5);
    }
    assert!(!Cvec3::NAN.is_normalized());
    assert_eq!(Cvec3::ZERO.length_recip(), f32::INFINITY);
}

/// glam's length and direction helpers, the same on both vector types:
/// each within a few ulps of glam's of that name (glam's `Vec4` adds its
/// lanes pairwise, its lengths square without rescaling), and the
/// clamped lengths within their bound.
macro_rules! lengths_agree_with_glam {
    ($name:ident: $t:ident ~ $g:ty) => {
        #[test]
        fn $name() {
            use crate::accuracy::NORMALIZE_MAX_NORM_ERROR;
            use rand::{Rng, SeedableRng};
            let g = |v: $t| <$g>::from_array(v.to_array());
            let close = |v: $t, w: $g, scale: f32| {
                (v - $t::from_array(w.to_array())).norm() <= 8.0 * f32::EPSILON * scale
            };
            let mut rng = rand::rngs::StdRng::seed_from_u64(47);
            let mut draw =
                || $t::from_array(core::array::from_fn(|_| rng.random_range(-10.0..10.0)));
            for _ in 0..10_000 {
                let (a, b, n) = (draw(), draw(), draw().normalize());
                let (ga, gb, gn) = (g(a), g(b), g(n));
                let (lo, hi) = (b.x.abs().min(b.y.abs()), b.x.abs().max(b.y.abs()));
                let size = a.norm();
                let clamped = a.clamp_length(lo, hi);
                assert!(close(clamped, ga.clamp_length(lo, hi), size + hi));
                let length = clamped.norm();
                let bound = (NORMALIZE_MAX_NORM_ERROR + f32::EPSILON) * hi;
                assert!(
                    length >= lo - bound && length <= hi + bound,
                    "{a:?} {lo} {hi}"
                );
                assert!(close(a.clamp_length_max(lo), ga.clamp_length_max(lo), size));
                assert!(close(a.clamp_length_min(hi), ga.clamp_length_min(hi), hi));
                let d = b.z.abs();
                assert!(close(
                    a.move_towards(b, d),
                    ga.move_towards(gb, d),
                    size + b.norm()
                ));
                assert!(close(
                    a.move_towards(b, -d),
                    ga.move_towards(gb, -d),
                    size + b.norm()
                ));
                assert!(close(
                    a.project_onto_normalized(n),
                    ga.project_onto_normalized(gn),
                    size
                ));
                assert!(close(
                    a.reject_from_normalized(n),
                    ga.reject_from_normalized(gn),
                    size
                ));
                let (unit, length) = a.normalize_and_length();
                let (gunit, glength) = ga.normalize_and_length();
                assert!(
                    close(unit, gunit, 1.0)
                        && (length - glength).abs() <= 4.0 * f32::EPSILON * glength
                );
                let ray = a.normalize();
                let facing = if ray.dot(n) > 0.0 { -n } else { n };
                let eta = 0.5 + b.z.abs() * 0.15;
                // Near grazing (k near 0) the root magnifies the dot
                // product's last bits; the two agree as k allows.
                let cos = facing.dot(ray);
                let k = 1.0 - eta * eta * (1.0 - cos * cos);
                if k.abs() > 1e-3 {
                    let theirs = g(ray).refract(g(facing), eta);
                    assert!(close(ray.refract(facing, eta), theirs, 2.0 + 1.0 / k.abs()));
                }
            }
            for v in [$t::ZERO, $t::NAN, $t::X * f32::INFINITY] {
                assert_eq!(v.normalize_and_length(), ($t::X, 0.0));
                assert_eq!(g(v).normalize_and_length(), (<$g>::X, 0.0));
            }
            // Beyond glam's squares: the direction is still found.
            let (unit, length) = ($t::X * 1e30).normalize_and_length();
            assert_eq!((unit, length), ($t::X, 1e30));
            assert!($t::ZERO.clamp_length_min(1.0).is_nan());
            assert_eq!($t::ZERO.move_towards($t::X * 5e-5, 1e-9), $t::X * 5e-5);
            // Total internal reflection, and NaN in, NaN out.
            assert_eq!(($t::X + $t::Y).normalize().refract($t::Y, 2.0), $t::ZERO);
            assert!($t::NAN.refract($t::Y, 1.5).is_nan());
        }
    };
}

lengths_agree_with_glam!(cvec3_lengths_agree_with_glam: Cvec3 ~ glam::Vec3);
lengths_agree_with_glam!(cvec4_lengths_agree_with_glam: Cvec4 ~ glam::Vec4);

/// Cvec3's own glam helpers and `Vec4::from((v, w))`, bit for bit: the
/// same formulas, the same order of operations.
#[test]
#[allow(deprecated)]
fn cvec3_helpers_and_homogeneous_forms_are_glams_bit_for_bit() {
    use rand::{Rng, SeedableRng};
    let bits = |v: Cvec3, w: glam::Vec3| {
        assert_eq!(
            v.to_array().map(f32::to_bits),
            w.to_array().map(f32::to_bits)
        )
    };
    let mut rng = rand::rngs::StdRng::seed_from_u64(48);
    for _ in 0..10_000 {
        let mut c = || rng.random_range(-10.0f32..10.0);
        let (a, n, w) = (
            Cvec3::new(c(), c(), c()),
            Cvec3::new(c(), c(), c()).normalize(),
            c(),
        );
        let (ga, gn) = (g3(a), g3(n));
        bits(a.any_orthogonal_vector(), ga.any_orthogonal_vector());
        assert_eq!(a.any_orthogonal_vector().dot(a), 0.0);
        let ((p, q), (gp, gq)) = (n.any_orthonormal_pair(), gn.any_orthonormal_pair());
        bits(p, gp);
        bits(q, gq);
        bits(n.any_orthonormal_vector(), gn.any_orthonormal_vector());
        assert!((p.cross(q) - n).norm() < 1e-6 && p.dot(n).abs() < 1e-6);
        bits(a.project_onto_normalized(n), ga.project_onto_normalized(gn));
        bits(a.reject_from_normalized(n), ga.reject_from_normalized(gn));
        let ray = a.normalize();
        let facing = if ray.dot(n) > 0.0 { -n } else { n };
        bits(ray.refract(facing, 1.33), g3(ray).refract(g3(facing), 1.33));
        let h = Cvec4::from((a, w));
        assert_eq!(h.to_array(), glam::Vec4::from((ga, w)).to_array());
        assert_eq!(
            a.to_homogeneous().to_array(),
            ga.to_homogeneous().to_array()
        );
        let back = Cvec3::from_homogeneous(h);
        bits(
            back,
            glam::Vec3::from_homogeneous(glam::Vec4::from((ga, w))),
        );
    }
    // Where |x| = |y|, glam takes the cross product with X.
    let tie = Cvec3::new(1.0, -1.0, 2.0);
    bits(tie.any_orthogonal_vector(), g3(tie).any_orthogonal_vector());
}
