//! Searches for the worst cases of the norm and rotation laws, of the
//! product's angle (`product_angle_search`), of the vector sampler's
//! bound (`vector_sampler_search`), of `RigTForm`'s inverse identities
//! (`rigid_inverse_search`), of the projections (`projection_search`)
//! and of slerp's norm on its f64 path (`slerp_f64_norm_search`): from seeded
//! starting points, each climbs towards the inputs with the largest error,
//! changing one input's last bits at a time (`climb`), or one or two
//! inputs' (`climb_wide`), and keeping a step only if it makes the error
//! larger. The product's norm and the rotation climb on their own error
//! over both inputs at once (the quaternions through `normalize`, so that
//! they stay in the proofs' domain), first by up to 4096 units in the last
//! place, then 64, then 4. Errors are measured in f64 from the f32
//! results (squares of f32 values are exact there; the sums round by about
//! 1e-16, far below the errors sought).
//!
//! The default run is a short search; `cargo test --release -p
//! rigtform-proofs --test worst_cases -- --ignored --nocapture` runs the
//! deep one whose figures `src/accuracy.rs` quotes. Each asserts that what
//! it finds stays within the published constant, and within the bound that
//! composes the constants for the results of `normalize` (whose norm is
//! off by up to `NORMALIZE_MAX_NORM_ERROR`, which the product and the
//! rotation carry through).

use rigtform::accuracy::{
    MUL_MAX_ANGLE_ERROR, NORMALIZE_MAX_NORM_ERROR, RENORMALIZED_CHAIN_NORM_ERROR,
    ROTATE_MAX_REL_ERROR, SAMPLER_VEC3_MAX_REL_ERROR, UNIT_NORM_ERROR,
};
use rigtform::{Cvec3, Quat, RigTForm};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::reference::leibniz_expansion;

/// The four components in f64, w first.
fn q64(q: Quat) -> [f64; 4] {
    [q.w, q.x, q.y, q.z].map(f64::from)
}

fn norm64(q: Quat) -> f64 {
    q64(q).iter().map(|c| c * c).sum::<f64>().sqrt()
}

/// `c` moved by 1 to `reach` units in the last place, either way.
fn nudge(d: &mut Draws, c: f32, reach: usize) -> f32 {
    let k = 1 + d.below(reach) as i32;
    let k = if d.below(2) == 0 { k } else { -k };
    f32::from_bits((c.to_bits() as i32).wrapping_add(k) as u32)
}

/// Hill climbing from `start`: `steps` nudges of one input each, kept when
/// `error` grows.
fn climb<const N: usize>(
    d: &mut Draws,
    start: [f32; N],
    steps: usize,
    error: &impl Fn([f32; N]) -> f64,
) -> ([f32; N], f64) {
    let mut best = (start, error(start));
    for _ in 0..steps {
        let mut x = best.0;
        let i = d.below(N);
        x[i] = nudge(d, x[i], 4);
        let e = error(x);
        if e > best.1 {
            best = (x, e);
        }
    }
    best
}

/// Hill climbing as [`climb`], with nudges of up to `reach` units in the
/// last place, of one input or two at once.
fn climb_wide<const N: usize>(
    d: &mut Draws,
    start: [f32; N],
    steps: usize,
    reach: usize,
    error: &impl Fn([f32; N]) -> f64,
) -> ([f32; N], f64) {
    let mut best = (start, error(start));
    for _ in 0..steps {
        let mut x = best.0;
        for _ in 0..=d.below(2) {
            let i = d.below(N);
            x[i] = nudge(d, x[i], reach);
        }
        let e = error(x);
        if e > best.1 {
            best = (x, e);
        }
    }
    best
}

/// [`climb_wide`] from a start uniform in [-1, 1], a third of `steps` each with
/// reaches 4096, 64 and 4: the largest `error` it ends on.
fn climb_far<const N: usize>(d: &mut Draws, steps: usize, error: &impl Fn([f32; N]) -> f64) -> f64 {
    let mut x: [f32; N] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
    let mut e = 0.0;
    for reach in [4096, 64, 4] {
        (x, e) = climb_wide(d, x, steps / 3, reach, error);
    }
    e
}

/// `|normalize(v)| - 1` (signed; 0 where the result is not finite).
fn normalize_deviation(v: [f32; 4]) -> f64 {
    let q = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    if q.is_finite() {
        norm64(q) - 1.0
    } else {
        0.0
    }
}

/// The results of `normalize` the climbs end on, with the largest norm
/// errors of either sign first: `climbs` climbs from components uniform
/// in [-1, 1].
fn normalized_pool(climbs: usize, seed: u64) -> (Vec<Quat>, f64) {
    let mut d = Draws::new(seed);
    let mut found: Vec<(Quat, f64)> = Vec::new();
    for _ in 0..climbs {
        let start: [f32; 4] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        let (x, _) = climb_wide(&mut d, start, 300, 4, &|v| normalize_deviation(v).abs());
        let q = Quat::from_wxyz(x[0], x[1], x[2], x[3]).normalize();
        found.push((q, norm64(q) - 1.0));
    }
    found.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
    let worst = found.first().map_or(0.0, |f| f.1.abs());
    (found.into_iter().map(|(q, _)| q).collect(), worst)
}

/// `| |a b| / (|a| |b|) - 1 |` for `a`, `b` the results of `normalize` on
/// the first and the last four inputs (0 where one is not finite).
fn product_deviation(v: [f32; 8]) -> f64 {
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]).normalize();
    let n = norm64(a * b) / (norm64(a) * norm64(b)) - 1.0;
    if n.is_finite() {
        n.abs()
    } else {
        0.0
    }
}

/// `| |a b| / (|a| |b|) - 1 |` for `a` the first four inputs and `b` the
/// last four as they are (0 where `|a|^2` or `|b|^2` is not within 2^-20
/// of 1, the domain of the product's proof).
fn product_deviation_raw(v: [f32; 8]) -> f64 {
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]);
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]);
    let (na, nb) = (norm64(a), norm64(b));
    let near = |n: f64| (n * n - 1.0).abs() <= 2f64.powi(-20);
    if !near(na) || !near(nb) {
        return 0.0;
    }
    (norm64(a * b) / (na * nb) - 1.0).abs()
}

/// The product's terms, component by component (w, x, y, z), in the order
/// the code sums them: the sign and the indices (w, x, y, z = 0 to 3) of
/// the factors of `a` and `b`.
const PRODUCT_TERMS: [[(f64, usize, usize); 4]; 4] = [
    [(1.0, 0, 0), (-1.0, 1, 1), (-1.0, 2, 2), (-1.0, 3, 3)],
    [(1.0, 0, 1), (1.0, 1, 0), (1.0, 2, 3), (-1.0, 3, 2)],
    [(1.0, 0, 2), (-1.0, 1, 3), (1.0, 2, 0), (1.0, 3, 1)],
    [(1.0, 0, 3), (1.0, 1, 2), (-1.0, 2, 1), (1.0, 3, 0)],
];

/// Half an ulp of `x` as an f32, over 2^-24 (the largest rounding error
/// of `x`, as a multiple of 2^-24).
fn half_ulp(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        2f64.powi(x.abs().log2().floor() as i32)
    }
}

/// The product's norm error if every rounding were half an ulp of its
/// result with the sign that moves the norm most, to first order, in units
/// of 2^-24: each component's half ulps of its terms and partial sums,
/// weighted by the component, over `|a b|^2`, for `a` and `b` the first
/// and last four of `x` made unit.
fn aligned_roundings(x: [f64; 8]) -> f64 {
    let unit = |v: &[f64]| {
        let n = v.iter().map(|c| c * c).sum::<f64>().sqrt();
        [v[0] / n, v[1] / n, v[2] / n, v[3] / n]
    };
    let (a, b) = (unit(&x[..4]), unit(&x[4..]));
    let (mut weighted, mut squares) = (0.0, 0.0);
    for terms in PRODUCT_TERMS {
        let t = terms.map(|(s, j, k)| s * a[j] * b[k]);
        let sums = [t[0] + t[1], t[0] + t[1] + t[2], t[0] + t[1] + t[2] + t[3]];
        let p = sums[2];
        let halves: f64 = t.iter().chain(&sums).map(|&v| half_ulp(v)).sum();
        weighted += p.abs() * halves;
        squares += p * p;
    }
    weighted / squares
}

/// A targeted search for the product's worst case: where the roundings
/// can align. Climbs on [`aligned_roundings`] (in f64, shrinking steps)
/// give `starts` structured pairs; the best few are rounded to f32
/// through `normalize`, each perturbed `restarts` times and climbed on the
/// product's own error; around the best, the inputs themselves (not
/// through `normalize`, within the proof's domain) are climbed last.
fn targeted_product_search(d: &mut Draws, starts: usize, restarts: usize, steps: usize) -> f64 {
    let mut found: Vec<(f64, [f64; 8])> = Vec::new();
    for _ in 0..starts {
        let mut x: [f64; 8] = core::array::from_fn(|_| f64::from(d.uniform(-1.0, 1.0)));
        let mut e = aligned_roundings(x);
        let mut step = 0.3;
        for i in 0..6_000 {
            let mut y = x;
            y[d.below(8)] += step * f64::from(d.uniform(-1.0, 1.0));
            let f = aligned_roundings(y);
            if f > e {
                (x, e) = (y, f);
            }
            if i % 600 == 599 {
                step *= 0.5;
            }
        }
        found.push((e, x));
    }
    found.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut best = ([0f32; 8], 0.0);
    for (_, x) in found.iter().take(4) {
        for _ in 0..restarts {
            let start: [f32; 8] = core::array::from_fn(|j| {
                (x[j] * (1.0 + 1e-3 * f64::from(d.uniform(-1.0, 1.0)))) as f32
            });
            let (mut y, mut e) = (start, 0.0);
            for reach in [256, 8] {
                (y, e) = climb_wide(d, y, steps / 2, reach, &product_deviation);
            }
            if e > best.1 {
                best = (y, e);
            }
        }
    }
    let a = Quat::from_wxyz(best.0[0], best.0[1], best.0[2], best.0[3]).normalize();
    let b = Quat::from_wxyz(best.0[4], best.0[5], best.0[6], best.0[7]).normalize();
    let unit = [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z];
    let mut worst = best.1.max(product_deviation_raw(unit));
    for _ in 0..restarts {
        let start = unit.map(|c| nudge(d, c, 3));
        let (mut y, mut e) = (start, 0.0);
        for reach in [16, 2] {
            (y, e) = climb_wide(d, y, steps / 2, reach, &product_deviation_raw);
        }
        worst = worst.max(e);
    }
    worst
}

/// `|q v - F(v)| / |v|` ([`rotation_errors`]) for `q` the result of
/// `normalize` on the first four inputs and `v` the last three (0 where
/// they are not finite or `v` is 0).
fn rotation_deviation(x: [f32; 7]) -> f64 {
    let q = Quat::from_wxyz(x[0], x[1], x[2], x[3]).normalize();
    let v = Cvec3::new(x[4], x[5], x[6]);
    if !q.is_finite() || v.norm() == 0.0 {
        return 0.0;
    }
    let (f, _) = rotation_errors(q, v);
    if f.is_finite() {
        f
    } else {
        0.0
    }
}

/// The largest deviation of `(1 + n)^2 (1 + u) - 1`: the norm of a
/// product of two quaternions each off unit norm by `n`, the product
/// adding `u` of its own.
fn composed(n: f64, u: f64) -> f64 {
    (1.0 + n).powi(2) * (1.0 + u) - 1.0
}

/// `|q v - F(v)| / |v|` with `F(v) = v + 2 w (u x v) + 2 u x (u x v)`, the
/// formula `q * v` evaluates, in exact arithmetic, and `|q v - R(v)| / |v|`
/// with `R` the rotation by `q / |q|`: `F(v) = |q|^2 R(v) + (1 - |q|^2) v`.
fn rotation_errors(q: Quat, v: Cvec3) -> (f64, f64) {
    let [w, x, y, z] = q64(q);
    let n2 = w * w + x * x + y * y + z * z;
    let vv = [v.x, v.y, v.z].map(f64::from);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = [x, y, z];
    let t = cross(u, vv).map(|c| 2.0 * c);
    let ut = cross(u, t);
    let f = [0, 1, 2].map(|i| vv[i] + w * t[i] + ut[i]);
    let r = [0, 1, 2].map(|i| (f[i] - (1.0 - n2) * vv[i]) / n2);
    let got = q * v;
    let g = [got.x, got.y, got.z].map(f64::from);
    let len = vv.iter().map(|c| c * c).sum::<f64>().sqrt();
    let dist = |a: [f64; 3]| (0..3).map(|i| (g[i] - a[i]).powi(2)).sum::<f64>().sqrt() / len;
    (dist(f), dist(r))
}

struct Found {
    normalize: f64,
    product_own: f64,
    product_to_unit: f64,
    rotation_formula: f64,
    rotation_exact: f64,
}

/// The searches: `normalize` from `climbs` climbs; the products of every
/// pair of the `pair` results of `normalize` with the largest norm errors
/// of one sign (where the errors add); the rotations of random vectors by
/// the first `pair` of them; `climbs / 10` climbs of `steps` steps on
/// the product's and the rotation's own errors; and the targeted search
/// of the product ([`targeted_product_search`], `climbs / 16` restarts).
fn search(climbs: usize, pair: usize, steps: usize, seed: u64) -> Found {
    let (pool, normalize) = normalized_pool(climbs, seed);
    let (low, high): (Vec<Quat>, Vec<Quat>) = pool.iter().partition(|q| norm64(**q) < 1.0);
    let (mut product_own, mut product_to_unit) = (0f64, 0f64);
    for side in [&low, &high] {
        let top = &side[..side.len().min(pair)];
        for a in top {
            for b in top {
                let n = norm64(*a * *b);
                product_to_unit = product_to_unit.max((n - 1.0).abs());
                product_own = product_own.max((n / (norm64(*a) * norm64(*b)) - 1.0).abs());
            }
        }
    }
    let mut d = Draws::new(seed ^ 0x5eed);
    let (mut rotation_formula, mut rotation_exact) = (0f64, 0f64);
    for q in pool.iter().take(pair) {
        for _ in 0..100 {
            let (f, r) = rotation_errors(*q, d.vec3(1.0));
            rotation_formula = rotation_formula.max(f);
            rotation_exact = rotation_exact.max(r);
        }
    }
    let mut d = Draws::new(seed ^ 0xc11b);
    for _ in 0..climbs / 10 {
        product_own = product_own.max(climb_far(&mut d, steps, &product_deviation));
        rotation_formula = rotation_formula.max(climb_far(&mut d, steps, &rotation_deviation));
    }
    product_own = product_own.max(targeted_product_search(&mut d, 200, climbs / 16, steps));
    Found {
        normalize,
        product_own,
        product_to_unit,
        rotation_formula,
        rotation_exact,
    }
}

fn check(f: &Found) {
    let n = f64::from(NORMALIZE_MAX_NORM_ERROR);
    let u = f64::from(UNIT_NORM_ERROR);
    let rotate = f64::from(ROTATE_MAX_REL_ERROR);
    println!(
        "| |normalize(q)| - 1 |: {:.4e} (NORMALIZE_MAX_NORM_ERROR {n:e})",
        f.normalize
    );
    println!(
        "| |a b| / (|a| |b|) - 1 |, a, b within 2^-20 of unit norm: {:.4e} (UNIT_NORM_ERROR {u:e})",
        f.product_own
    );
    println!(
        "| |a b| - 1 |, a, b results of normalize: {:.4e} (composed: {:.4e})",
        f.product_to_unit,
        composed(n, u)
    );
    println!(
        "|q v - F(v)| / |v|, q a result of normalize: {:.4e} (ROTATE_MAX_REL_ERROR {rotate:e})",
        f.rotation_formula
    );
    let off = (1.0 + n).powi(2) - 1.0;
    println!(
        "|q v - R(v)| / |v|, the same: {:.4e} (with 2 | |q|^2 - 1 |: {:.4e})",
        f.rotation_exact,
        rotate + 2.0 * off
    );
    assert!(f.normalize <= n);
    assert!(f.product_own <= u);
    assert!(f.product_to_unit <= composed(n, u));
    assert!(f.rotation_formula <= rotate);
    assert!(f.rotation_exact <= rotate + 2.0 * off);
}

#[test]
fn worst_cases_found_stay_within_the_constants() {
    check(&search(2_000, 300, 1_500, 1));
}

#[test]
#[ignore = "a minute in release: the search the constants' docs quote"]
fn deep_search_for_worst_cases() {
    check(&search(400_000, 3_000, 3_000, 1));
}

/// A CUBICSPLINE or LINEAR Cvec3 sampler of one segment, at `t`, against
/// the exact evaluation of the same f32 values, times and tangents,
/// relative to the largest term, as `SAMPLER_VEC3_MAX_REL_ERROR` measures
/// it: `[p0, b0, p1, a1, t0, t1, t]` in x (the other components 0), 0
/// outside the constant's domain (components up to 100, intervals from
/// 0.01 to 2 starting in [0, 18]).
fn sampler_error(v: [f32; 7]) -> f64 {
    use rigtform::animation::{Interpolation, Sampler};
    let [p0, b0, p1, a1, t0, t1, t] = v;
    let inside = (0.0..=18.0).contains(&t0)
        && (0.01..=2.0).contains(&(t1 - t0))
        && t0 < t
        && t < t1
        && [p0, b0, p1, a1].iter().all(|c| c.abs() <= 100.0);
    if !inside {
        return 0.0;
    }
    let x = |c: f32| Cvec3::new(c, 0.0, 0.0);
    let values = [x(0.0), x(p0), x(b0), x(a1), x(p1), x(0.0)];
    let times = [t0, t1];
    let sample = |kind, values: &[Cvec3]| {
        Sampler::new(kind, &times, values).map_or(f64::NAN, |s| f64::from(s.sample(t).x))
    };
    let td = f64::from(t1) - f64::from(t0);
    let u = (f64::from(t) - f64::from(t0)) / td;
    let (uu, uuu) = (u * u, u * u * u);
    let basis = [
        2.0 * uuu - 3.0 * uu + 1.0,
        uuu - 2.0 * uu + u,
        -2.0 * uuu + 3.0 * uu,
        uuu - uu,
    ];
    let terms = [p0, b0, p1, a1].map(f64::from);
    let terms = [terms[0], terms[1] * td, terms[2], terms[3] * td];
    let exact: f64 = (0..4).map(|i| basis[i] * terms[i]).sum();
    let largest = terms.iter().fold(0f64, |m, c| m.max(c.abs()));
    let cubic = (sample(Interpolation::CubicSpline, &values) - exact).abs() / largest;
    let line = f64::from(p0) * (1.0 - u) + f64::from(p1) * u;
    let linear = (sample(Interpolation::Linear, &[x(p0), x(p1)]) - line).abs()
        / f64::from(p0.abs().max(p1.abs()));
    cubic.max(linear)
}

/// The largest of `climbs` climbs of `sampler_error` (relative to the
/// largest term), from values of either sign up to 100, half of them with the two values opposite (where
/// the Hermite weights' errors add) and tangents 0 or up to 100.
fn vector_sampler_search(climbs: usize, seed: u64) -> f64 {
    let mut d = Draws::new(seed);
    let mut worst = 0f64;
    for _ in 0..climbs {
        let t0 = d.uniform(0.0, 10.0);
        let t1 = t0 + d.uniform(0.01, 2.0);
        let t = d.uniform(t0, t1);
        let p0 = d.uniform(-100.0, 100.0);
        let p1 = if d.below(2) == 0 {
            -p0
        } else {
            d.uniform(-100.0, 100.0)
        };
        let mut tangent = || {
            if d.below(2) == 0 {
                0.0
            } else {
                d.uniform(-100.0, 100.0)
            }
        };
        let start = [p0, tangent(), p1, tangent(), t0, t1, t];
        worst = worst.max(climb(&mut d, start, 400, &sampler_error).1);
    }
    worst
}

/// Prints what a search found beside its constant, and fails if it
/// exceeds it.
fn within(what: &str, found: f64, name: &str, constant: f32) {
    println!("{what}: {found:.4e} ({name} {constant:e})");
    assert!(found <= f64::from(constant), "{what}: {found:e}");
}

#[test]
fn product_angle_and_vector_sampler_found_stay_within_their_constants() {
    let angle = product_angle_search(500, 7);
    within(
        "angle of a * b",
        angle,
        "MUL_MAX_ANGLE_ERROR",
        MUL_MAX_ANGLE_ERROR,
    );
    let sampler = vector_sampler_search(500, 9);
    within(
        "vector sampler",
        sampler,
        "SAMPLER_VEC3_MAX_REL_ERROR",
        SAMPLER_VEC3_MAX_REL_ERROR,
    );
}

#[test]
#[ignore = "seconds in release: the search the constant's doc quotes"]
fn deep_vector_sampler_search() {
    let found = vector_sampler_search(100_000, 9);
    within(
        "vector sampler",
        found,
        "SAMPLER_VEC3_MAX_REL_ERROR",
        SAMPLER_VEC3_MAX_REL_ERROR,
    );
}

/// The angle between `a * b` and the exact product of the same inputs, as
/// rotations: twice the angle between them as 4-vectors, from the error's
/// part across the exact product. 0 outside `MUL_MAX_ANGLE_ERROR`'s domain
/// (components in [-1, 1], squared norms within 2^-20 of 1).
fn product_angle(v: [f32; 8]) -> f64 {
    let (a, b) = (
        Quat::from_wxyz(v[0], v[1], v[2], v[3]),
        Quat::from_wxyz(v[4], v[5], v[6], v[7]),
    );
    let inside = |q: Quat| {
        (norm64(q).powi(2) - 1.0).abs() <= 2f64.powi(-20) && q64(q).iter().all(|c| c.abs() <= 1.0)
    };
    if !(inside(a) && inside(b)) {
        return 0.0;
    }
    let (x, y) = (q64(a), q64(b));
    let exact = [
        x[0] * y[0] - x[1] * y[1] - x[2] * y[2] - x[3] * y[3],
        x[0] * y[1] + x[1] * y[0] + x[2] * y[3] - x[3] * y[2],
        x[0] * y[2] - x[1] * y[3] + x[2] * y[0] + x[3] * y[1],
        x[0] * y[3] + x[1] * y[2] - x[2] * y[1] + x[3] * y[0],
    ];
    let got = q64(a * b);
    let length = |v: &[f64; 4]| v.iter().map(|c| c * c).sum::<f64>().sqrt();
    let e: [f64; 4] = core::array::from_fn(|i| got[i] - exact[i]);
    let along = (0..4).map(|i| e[i] * exact[i]).sum::<f64>() / length(&exact);
    let across: [f64; 4] = core::array::from_fn(|i| e[i] - along * exact[i] / length(&exact));
    2.0 * (length(&across) / length(&got)).asin()
}

/// The largest of `climbs` climbs of `product_angle` from pairs of f32
/// roundings of unit quaternions.
fn product_angle_search(climbs: usize, seed: u64) -> f64 {
    let mut d = Draws::new(seed);
    let mut worst = 0f64;
    for _ in 0..climbs {
        let (a, b) = (d.unit_quat(), d.unit_quat());
        let start = [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z];
        worst = worst.max(climb(&mut d, start, 400, &product_angle).1);
    }
    worst
}

#[test]
#[ignore = "seconds in release: the search the constant's doc quotes"]
fn deep_product_angle_search() {
    let found = product_angle_search(50_000, 7);
    within(
        "angle of a * b",
        found,
        "MUL_MAX_ANGLE_ERROR",
        MUL_MAX_ANGLE_ERROR,
    );
}

/// `|det - exact| / T` for a matrix's f32 determinant (0 where `T` is 0
/// or the determinant is not finite).
fn determinant_error<const N: usize>(v: [f32; N]) -> f64 {
    let (got, n) = match N {
        9 => {
            let m: [f32; 9] = core::array::from_fn(|i| v[i]);
            (rigtform::Matrix3::from_cols_array(&m).determinant(), 3)
        }
        _ => {
            let m: [f32; 16] = core::array::from_fn(|i| v[i]);
            (rigtform::Matrix4::from_cols_array(&m).determinant(), 4)
        }
    };
    let (exact, total) = leibniz_expansion(&v.map(f64::from), n);
    if total == 0.0 || !got.is_finite() {
        return 0.0;
    }
    (f64::from(got) - exact).abs() / total
}

/// The largest of `climbs` climbs of `determinant_error` from matrices
/// with entries in [-1, 1], half of them nearly singular (the last column
/// a combination of the others, where the terms cancel).
fn determinant_search<const N: usize>(climbs: usize, seed: u64) -> f64 {
    let n = if N == 9 { 3 } else { 4 };
    let mut d = Draws::new(seed);
    let mut worst = 0f64;
    for k in 0..climbs {
        let mut start: [f32; N] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        if k % 2 == 0 {
            let (p, q) = (d.uniform(-1.0, 1.0), d.uniform(-1.0, 1.0));
            for r in 0..n {
                start[(n - 1) * n + r] = p * start[r] + q * start[n + r];
            }
        }
        worst = worst.max(climb(&mut d, start, 400, &determinant_error).1);
    }
    worst
}

/// The determinants' searches, `climbs` climbs each, against their
/// constants.
fn determinants_within_their_constants(climbs: usize) {
    use rigtform::accuracy::{DETERMINANT_MAX_REL_ERROR, MATRIX3_DETERMINANT_MAX_REL_ERROR};
    within(
        "Matrix3::determinant, relative to the terms",
        determinant_search::<9>(climbs, 11),
        "MATRIX3_DETERMINANT_MAX_REL_ERROR",
        MATRIX3_DETERMINANT_MAX_REL_ERROR,
    );
    within(
        "Matrix4::determinant, relative to the terms",
        determinant_search::<16>(climbs / 2, 12),
        "DETERMINANT_MAX_REL_ERROR",
        DETERMINANT_MAX_REL_ERROR,
    );
}

#[test]
fn determinants_found_stay_within_their_constants() {
    // The expansion's magnitudes and sign, on a matrix whose terms are known.
    let (det, total) = leibniz_expansion(&[2.0, 1.0, 0.0, 1.0, 3.0, 0.0, 0.0, 0.0, 4.0], 3);
    assert_eq!((det, total), (20.0, 28.0));
    determinants_within_their_constants(600);
}

#[test]
#[ignore = "seconds in release: the search the constants' docs quote"]
fn deep_determinant_search() {
    determinants_within_their_constants(100_000);
}

/// The rotation angle between the f32 quaternion `got` and the unit
/// 4-vector `exact`: twice the angle between their lines, `4 asin(d / 2)`
/// with `d` the distance of `got / |got|` from the nearer of `exact`,
/// `-exact`.
fn rotation_angle(got: Quat, exact: [f64; 4]) -> f64 {
    let g = q64(got);
    let n = norm64(got);
    let d = |sign: f64| {
        (0..4)
            .map(|i| (g[i] / n - sign * exact[i]).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    4.0 * (d(1.0).min(d(-1.0)) / 2.0).asin()
}

/// The polar form of `q` in f64: its angle `phi = atan2(|v|, w)` (half
/// the rotation's angle) and its unit axis.
fn polar64(q: Quat) -> (f64, [f64; 3]) {
    let [w, x, y, z] = q64(q);
    let beta = (x * x + y * y + z * z).sqrt();
    (beta.atan2(w), [x / beta, y / beta, z / beta])
}

/// The errors of the polar maps at `[w, x, y, z, alpha]`, in the forms of
/// their constants: `q.pow(alpha)`'s angle error over `max(1, |alpha|
/// theta)` and `to_axis_angle`'s angle error over `max(1, theta)` (its
/// `theta` that of `q.cn()`, at most pi)
/// (`POW_MAX_ANGLE_ERROR`), and `|to_scaled_axis - theta k| / theta`
/// (`TO_SCALED_AXIS_MAX_REL_ERROR`), `theta = 2 phi` the angle of `q`. 0
/// outside the constants' domain (unit `q`: squared norm within 2^-20 of
/// 1, no component beyond 1; `alpha` up to 1000) and where `q` has no axis.
fn polar_errors(v: [f32; 5]) -> [f64; 3] {
    let q = Quat::from_wxyz(v[0], v[1], v[2], v[3]);
    let alpha = v[4];
    let unit =
        (norm64(q).powi(2) - 1.0).abs() <= 2f64.powi(-20) && q64(q).iter().all(|c| c.abs() <= 1.0);
    if !unit || alpha.is_nan() || alpha.abs() > 1000.0 || (q.x, q.y, q.z) == (0.0, 0.0, 0.0) {
        return [0.0; 3];
    }
    let (phi, k) = polar64(q);
    let theta = 2.0 * phi;
    let turn = f64::from(alpha) * phi;
    let (s, c) = turn.sin_cos();
    let exact = [c, s * k[0], s * k[1], s * k[2]];
    let pow = rotation_angle(q.pow(alpha), exact) / (f64::from(alpha).abs() * theta).max(1.0);
    // to_axis_angle takes the short way: the angle of q.cn(), w >= 0.
    let short = 2.0 * polar64(q.cn()).0;
    let (_, angle) = q.to_axis_angle();
    let axis_angle = (f64::from(angle) - short).abs() / short.max(1.0);
    let r = q.to_scaled_axis();
    let got = [r.x, r.y, r.z].map(f64::from);
    let scaled = (0..3)
        .map(|i| (got[i] - theta * k[i]).powi(2))
        .sum::<f64>()
        .sqrt()
        / theta;
    [pow, axis_angle, scaled]
}

/// The largest of `climbs` climbs of each of `polar_errors` from f32
/// roundings of unit quaternions (a quarter of them turned by less than
/// 1e-3 rad, a quarter nearly half a turn, where atan2's relative error
/// and the axis's weight change) and `alpha` uniform in [-2, 3].
fn polar_search(climbs: usize, seed: u64) -> [f64; 3] {
    let mut d = Draws::new(seed);
    let mut worst = [0f64; 3];
    for k in 0..climbs {
        let mut q = d.unit_quat();
        match k % 4 {
            0 => q = Quat::from_wxyz(1.0, q.x * 1e-3, q.y * 1e-3, q.z * 1e-3).normalize(),
            1 => q = Quat::from_wxyz(q.w * 1e-3, q.x, q.y, q.z).normalize(),
            _ => {}
        }
        let start = [q.w, q.x, q.y, q.z, d.uniform(-2.0, 3.0)];
        for (i, w) in worst.iter_mut().enumerate() {
            *w = w.max(climb(&mut d, start, 400, &|v| polar_errors(v)[i]).1);
        }
    }
    worst
}

/// The largest error of an entry of `Matrix3::inverse`, over the nine,
/// as `MATRIX3_INVERSE_MAX_REL_ERROR` measures it: `|entry - M / D|`
/// over `(Am + |M| T / |D|) / |D|`, with `M` the entry's minor, `Am` the
/// magnitudes of its two products, `D` the determinant and `T` the
/// magnitudes of its expansion's six products (the minors and `D` in
/// f64, where a product of two or three f32 is exact or rounds by 2^-53).
/// 0 outside the constant's domain (`T` above 4096 `|D|`) or where there
/// is no inverse.
fn matrix3_inverse_error(v: [f32; 9]) -> f64 {
    let (det, total) = leibniz_expansion(&v.map(f64::from), 3);
    if total > 4096.0 * det.abs() {
        return 0.0;
    }
    let Some(inv) = rigtform::Matrix3::from_cols_array(&v).inverse() else {
        return 0.0;
    };
    let got = inv.to_cols_array();
    let col = |c: usize| [v[3 * c], v[3 * c + 1], v[3 * c + 2]].map(f64::from);
    let mut worst = 0f64;
    // Row i of the inverse: the cross product of the columns after i.
    for i in 0..3 {
        let (p, q) = (col((i + 1) % 3), col((i + 2) % 3));
        for j in 0..3 {
            let (k, l) = ((j + 1) % 3, (j + 2) % 3);
            let minor = p[k] * q[l] - p[l] * q[k];
            let terms = (p[k] * q[l]).abs() + (p[l] * q[k]).abs();
            let scale = (terms + minor.abs() * total / det.abs()) / det.abs();
            let error = (f64::from(got[3 * j + i]) - minor / det).abs();
            worst = worst.max(error / scale);
        }
    }
    worst
}

/// The polar maps' searches against their constants.
fn polar_maps_within_their_constants(climbs: usize) {
    use rigtform::accuracy::{POW_MAX_ANGLE_ERROR, TO_SCALED_AXIS_MAX_REL_ERROR};
    let [pow, axis_angle, scaled] = polar_search(climbs, 13);
    within(
        "angle of q.pow(alpha), per max(1, |alpha| theta)",
        pow,
        "POW_MAX_ANGLE_ERROR",
        POW_MAX_ANGLE_ERROR,
    );
    within(
        "angle of q.to_axis_angle(), per max(1, theta)",
        axis_angle,
        "POW_MAX_ANGLE_ERROR",
        POW_MAX_ANGLE_ERROR,
    );
    within(
        "q.to_scaled_axis(), relative",
        scaled,
        "TO_SCALED_AXIS_MAX_REL_ERROR",
        TO_SCALED_AXIS_MAX_REL_ERROR,
    );
}

/// The largest of `climbs` climbs of `matrix3_inverse_error` from
/// matrices with entries in [-1, 1], most of them nearly singular (the
/// last column a combination of the others plus a small part of its own,
/// so that the expansion cancels by up to the domain's 2^12).
fn matrix3_inverse_search(climbs: usize, seed: u64) -> f64 {
    let mut d = Draws::new(seed);
    let mut worst = 0f64;
    for k in 0..climbs {
        let mut start: [f32; 9] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        if k % 4 != 0 {
            let (p, q) = (d.uniform(-1.0, 1.0), d.uniform(-1.0, 1.0));
            let own = 2f32.powi(-(d.below(11) as i32));
            for r in 0..3 {
                start[6 + r] = p * start[r] + q * start[3 + r] + own * start[6 + r];
            }
        }
        worst = worst.max(climb(&mut d, start, 400, &matrix3_inverse_error).1);
    }
    worst
}

#[test]
fn matrix3_inverse_found_stays_within_its_constant() {
    use rigtform::accuracy::MATRIX3_INVERSE_MAX_REL_ERROR;
    within(
        "Matrix3::inverse, per entry",
        matrix3_inverse_search(400, 13),
        "MATRIX3_INVERSE_MAX_REL_ERROR",
        MATRIX3_INVERSE_MAX_REL_ERROR,
    );
}

#[test]
fn polar_maps_found_stay_within_their_constants() {
    polar_maps_within_their_constants(300);
}

#[test]
#[ignore = "seconds in release: the search the constants' docs quote"]
fn deep_polar_search() {
    polar_maps_within_their_constants(30_000);
}

#[test]
#[ignore = "seconds in release: the search the constant's doc quotes"]
fn deep_matrix3_inverse_search() {
    use rigtform::accuracy::MATRIX3_INVERSE_MAX_REL_ERROR;
    within(
        "Matrix3::inverse, per entry",
        matrix3_inverse_search(100_000, 13),
        "MATRIX3_INVERSE_MAX_REL_ERROR",
        MATRIX3_INVERSE_MAX_REL_ERROR,
    );
}

/// The errors of the inverse identities of `RigTForm`, relative to `|t|`:
/// the translation of `a * a.inv()` (exactly 0 for exact arithmetic and a
/// unit `r`) and `a.inv().inv().t - t`, for `a = (t, r)` with `r` the
/// result of `normalize` on the first four inputs and `t` the last three
/// (both 0 where `r` is not finite or `t` is 0). Every translation is an
/// f32 result, measured in f64.
fn rigid_inverse_errors(x: [f32; 7]) -> [f64; 2] {
    let r = Quat::from_wxyz(x[0], x[1], x[2], x[3]).normalize();
    let t = Cvec3::new(x[4], x[5], x[6]);
    if !r.is_finite() || t.norm() == 0.0 {
        return [0.0; 2];
    }
    let a = RigTForm::new(t, r);
    let t64 = [t.x, t.y, t.z].map(f64::from);
    let len = |v: [f64; 3]| v.iter().map(|c| c * c).sum::<f64>().sqrt();
    let product = (a * a.inv()).t;
    let back = a.inv().inv().t;
    let back = [back.x, back.y, back.z].map(f64::from);
    [
        len([product.x, product.y, product.z].map(f64::from)) / len(t64),
        len(core::array::from_fn(|i| back[i] - t64[i])) / len(t64),
    ]
}

/// The bound the inverse identities compose from the constants, relative
/// to `|t|`, for `r` a result of `normalize` (`|r|^2 = 1 + delta`): the
/// first rotation's error `e |t|`, turned by the exact formula (which
/// lengthens by at most `1 + 2 |delta|`), the second rotation's error
/// `e |r^-1 t|`, and the exact formulas' own departure from `t`,
/// `F_r(F_{r^-1}(t)) - t = -4 delta k x (k x t)` (`k` the vector part of
/// `r`), at most `4 |delta| |r|^2 |t|`; the product's last sum rounds
/// once more.
fn rigid_inverse_bound() -> [f64; 2] {
    let n = f64::from(NORMALIZE_MAX_NORM_ERROR);
    let e = f64::from(ROTATE_MAX_REL_ERROR);
    let delta = (1.0 + n).powi(2) - 1.0;
    let back = e * (1.0 + 2.0 * delta + e) + (1.0 + 2.0 * delta) * e + 4.0 * delta * (1.0 + delta);
    [back * (1.0 + 2f64.powi(-24)), back]
}

/// The worst cases of [`rigid_inverse_errors`]: `draws` uniform rotations
/// and translations first; then `climbs` climbs of `normalize`'s norm error
/// from rotations near half a turn (`w` within 0.02 of 0, where
/// `2 t - R t - R^-1 t` is largest: `4 t` for `t` across the axis), and
/// from the `pair` with the largest norm errors, with `t` across the axis,
/// climbs of `steps` steps over the rotation's and the translation's
/// inputs on each error. Returns the largest errors of the draws and of
/// the search.
fn rigid_inverse_search(
    draws: usize,
    climbs: usize,
    pair: usize,
    steps: usize,
    seed: u64,
) -> ([f64; 2], [f64; 2]) {
    let mut d = Draws::new(seed);
    let mut random = [0f64; 2];
    for _ in 0..draws {
        let (r, t) = (d.unit_quat(), d.vec3(1.0));
        let e = rigid_inverse_errors([r.w, r.x, r.y, r.z, t.x, t.y, t.z]);
        random = [0, 1].map(|i| random[i].max(e[i]));
    }
    let mut pool: Vec<([f32; 4], f64)> = (0..climbs)
        .map(|_| {
            let start = [
                d.uniform(-0.02, 0.02),
                d.uniform(-1.0, 1.0),
                d.uniform(-1.0, 1.0),
                d.uniform(-1.0, 1.0),
            ];
            climb_wide(&mut d, start, 300, 4, &|v| normalize_deviation(v).abs())
        })
        .collect();
    pool.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut found = [0f64; 2];
    for (q, _) in pool.iter().take(pair) {
        let axis = Cvec3::new(q[1], q[2], q[3]);
        let t = axis.cross(d.vec3(1.0));
        let start = [q[0], q[1], q[2], q[3], t.x, t.y, t.z];
        for (i, f) in found.iter_mut().enumerate() {
            let (_, e) = climb(&mut d, start, steps, &|x| rigid_inverse_errors(x)[i]);
            *f = f.max(e);
        }
    }
    (random, found)
}

/// Prints what the draws and the search find beside the composed bound,
/// and fails if either exceeds it.
fn rigid_inverse_within(draws: usize, climbs: usize, pair: usize, steps: usize) {
    let (random, found) = rigid_inverse_search(draws, climbs, pair, steps, 17);
    let bound = rigid_inverse_bound();
    for (i, what) in ["|(a * a.inv()).t| / |t|", "|a.inv().inv().t - t| / |t|"]
        .iter()
        .enumerate()
    {
        println!(
            "{what}, r a result of normalize: {:.4e} ({draws} draws), {:.4e} (search) (composed: {:.4e})",
            random[i], found[i], bound[i]
        );
        assert!(
            random[i].max(found[i]) <= bound[i],
            "{what}: {:e}",
            found[i]
        );
    }
}

#[test]
fn rigid_inverse_identities_found_stay_within_the_composed_bound() {
    rigid_inverse_within(20_000, 2_000, 50, 400);
}

#[test]
#[ignore = "seconds in release: the search the laws' docs quote"]
fn deep_rigid_inverse_search() {
    rigid_inverse_within(1_000_000, 100_000, 1_000, 2_000);
}

/// The largest error of an entry of `Matrix4::inverse`, over the
/// sixteen, as `INVERSE_MAX_REL_ERROR` measures it: `|entry - C / D|`
/// over `(Ac + |C| T / |D|) / |D|`, with `C` the entry's cofactor (the
/// signed determinant of the matrix without the entry's column's row and
/// row's column), `Ac` the magnitudes of the cofactor's six products, `D`
/// the determinant and `T` the magnitudes of its expansion's 24 products
/// (in f64, where a product of three or four f32 rounds by 2^-53). 0
/// outside the constant's domain (`T` above 4096 `|D|`) or where there is
/// no inverse.
fn matrix4_inverse_error(v: [f32; 16]) -> f64 {
    let (det, total) = leibniz_expansion(&v.map(f64::from), 4);
    if total > 4096.0 * det.abs() {
        return 0.0;
    }
    let Some(inv) = rigtform::Matrix4::from_cols_array(&v).inverse() else {
        return 0.0;
    };
    let got = inv.to_cols_array();
    let mut worst = 0f64;
    for row in 0..4 {
        for col in 0..4 {
            // Entry (row, col) of the inverse is the cofactor of the
            // matrix's entry (col, row) over the determinant: the matrix
            // without column `row` and row `col`, column-major.
            let sub: Vec<f64> = (0..4)
                .filter(|&c| c != row)
                .flat_map(|c| {
                    (0..4)
                        .filter(|&r| r != col)
                        .map(move |r| f64::from(v[4 * c + r]))
                })
                .collect();
            let (minor, terms) = leibniz_expansion(&sub, 3);
            let cofactor = if (row + col) % 2 == 0 { minor } else { -minor };
            let scale = (terms + cofactor.abs() * total / det.abs()) / det.abs();
            let error = (f64::from(got[4 * col + row]) - cofactor / det).abs();
            worst = worst.max(error / scale);
        }
    }
    worst
}

/// The largest of `climbs` climbs of `matrix4_inverse_error` from
/// matrices with entries in [-1, 1], most of them nearly singular (the
/// last column a combination of the others plus a small part of its own,
/// so that the expansion cancels by up to the domain's 2^12).
fn matrix4_inverse_search(climbs: usize, seed: u64) -> f64 {
    let mut d = Draws::new(seed);
    let mut worst = 0f64;
    for k in 0..climbs {
        let mut start: [f32; 16] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        if k % 4 != 0 {
            let p: [f32; 3] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
            let own = 2f32.powi(-(d.below(12) as i32));
            for r in 0..4 {
                start[12 + r] = p[0] * start[r]
                    + p[1] * start[4 + r]
                    + p[2] * start[8 + r]
                    + own * start[12 + r];
            }
        }
        worst = worst.max(climb(&mut d, start, 400, &matrix4_inverse_error).1);
    }
    worst
}

#[test]
fn matrix4_inverse_found_stays_within_its_constant() {
    use rigtform::accuracy::INVERSE_MAX_REL_ERROR;
    // The measure on a matrix whose inverse is exact in f32 and not its
    // own transpose: 1 + 2 E01 (row 0, column 1) inverts to 1 - 2 E01, so
    // an entry read from the wrong place would show.
    let mut sheared = [0f32; 16];
    for i in 0..4 {
        sheared[5 * i] = 1.0;
    }
    sheared[4] = 2.0;
    assert_eq!(matrix4_inverse_error(sheared), 0.0);
    within(
        "Matrix4::inverse, per entry",
        matrix4_inverse_search(200, 14),
        "INVERSE_MAX_REL_ERROR",
        INVERSE_MAX_REL_ERROR,
    );
}

#[test]
#[ignore = "a minute in release: the search the constant's doc quotes"]
fn deep_matrix4_inverse_search() {
    use rigtform::accuracy::INVERSE_MAX_REL_ERROR;
    within(
        "Matrix4::inverse, per entry",
        matrix4_inverse_search(50_000, 14),
        "INVERSE_MAX_REL_ERROR",
        INVERSE_MAX_REL_ERROR,
    );
}

/// The errors of `project_onto` and `reject_from` against the exact
/// projection `(a . b / |b|^2) b` of the same f32 vectors and its
/// rejection `a - P`, relative to `|a|`, as `PROJECT_MAX_REL_ERROR`
/// measures them: `Cvec3` for `N = 6` (`a` the first three inputs, `b` the
/// last three), `Cvec4` for `N = 8`. Both 0 where `a` or `b` is zero or a
/// result is not finite. The exact values are f64: the products of f32
/// values are exact there, and the sums and the quotient round by about
/// 1e-16, far below the errors sought.
fn projection_errors<const N: usize>(v: [f32; N]) -> [f64; 2] {
    let k = N / 2;
    let (p, r) = if N == 6 {
        let a = Cvec3::new(v[0], v[1], v[2]);
        let b = Cvec3::new(v[3], v[4], v[5]);
        let (p, r) = (a.project_onto(b), a.reject_from(b));
        ([p.x, p.y, p.z, 0.0], [r.x, r.y, r.z, 0.0])
    } else {
        let a = rigtform::Cvec4::new(v[0], v[1], v[2], v[3]);
        let b = rigtform::Cvec4::new(v[4], v[5], v[6], v[7]);
        (a.project_onto(b).to_array(), a.reject_from(b).to_array())
    };
    let a: Vec<f64> = v[..k].iter().map(|&c| f64::from(c)).collect();
    let b: Vec<f64> = v[k..].iter().map(|&c| f64::from(c)).collect();
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(x, y)| x * y).sum::<f64>();
    let (aa, bb) = (dot(&a, &a), dot(&b, &b));
    let finite = p.iter().chain(&r).all(|c| c.is_finite());
    if aa == 0.0 || bb == 0.0 || !finite {
        return [0.0; 2];
    }
    let q = dot(&a, &b) / bb;
    let (mut ep, mut er) = (0f64, 0f64);
    for i in 0..k {
        let exact = q * b[i];
        ep += (f64::from(p[i]) - exact).powi(2);
        er += (f64::from(r[i]) - (a[i] - exact)).powi(2);
    }
    [ep.sqrt() / aa.sqrt(), er.sqrt() / aa.sqrt()]
}

/// The largest errors of `project_onto` and `reject_from` that `climbs`
/// climbs each find, for `N` inputs as [`projection_errors`]: from random
/// pairs with components in [-1, 1], from pairs near parallel (`b` along
/// `a`, up to 1e-3 off, at any length and either way) and from pairs near
/// orthogonal (`b` across `a`, up to 1e-3 off), a third each; each climbs
/// on each of the two errors.
fn projection_search<const N: usize>(climbs: usize, seed: u64) -> [f64; 2] {
    let k = N / 2;
    let mut d = Draws::new(seed);
    let mut found = [0f64; 2];
    for c in 0..climbs {
        let mut start: [f32; N] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        let off = d.uniform(-1e-3, 1e-3);
        let scale = d.uniform(-4.0, 4.0);
        match c % 3 {
            1 => {
                for i in 0..k {
                    start[k + i] = (start[i] + off * start[k + i]) * scale;
                }
            }
            2 => {
                // b minus its part along a, plus a little of a.
                let (a, b) = (&start[..k], &start[k..]);
                let ab: f32 = a.iter().zip(b).map(|(x, y)| x * y).sum();
                let aa: f32 = a.iter().map(|x| x * x).sum();
                let across: Vec<f32> = (0..k).map(|i| b[i] - ab / aa * a[i] + off * a[i]).collect();
                start[k..].copy_from_slice(&across);
            }
            _ => {}
        }
        for (i, f) in found.iter_mut().enumerate() {
            let (_, e) = climb(&mut d, start, 400, &|x| projection_errors(x)[i]);
            *f = f.max(e);
        }
    }
    found
}

/// The projections' searches, `climbs` climbs each for `Cvec3` and
/// `Cvec4`, against `PROJECT_MAX_REL_ERROR`.
fn projections_within_their_constant(climbs: usize) {
    use rigtform::accuracy::PROJECT_MAX_REL_ERROR;
    let three = projection_search::<6>(climbs, 19);
    let four = projection_search::<8>(climbs, 23);
    for (what, found) in [
        ("Cvec3::project_onto, relative to |self|", three[0]),
        ("Cvec3::reject_from, relative to |self|", three[1]),
        ("Cvec4::project_onto, relative to |self|", four[0]),
        ("Cvec4::reject_from, relative to |self|", four[1]),
    ] {
        println!("{what}: {found:.4e} ({climbs} climbs)");
    }
    let worst = three.into_iter().chain(four).fold(0f64, f64::max);
    within(
        "project_onto and reject_from",
        worst,
        "PROJECT_MAX_REL_ERROR",
        PROJECT_MAX_REL_ERROR,
    );
}

#[test]
fn projections_found_stay_within_their_constant() {
    // A projection whose exact value is known: (3, 4, 0) onto the x axis.
    let e = projection_errors([3.0, 4.0, 0.0, 2.0, 0.0, 0.0]);
    assert_eq!(e, [0.0, 0.0]);
    projections_within_their_constant(300);
}

#[test]
#[ignore = "seconds in release: the search the constant's doc quotes"]
fn deep_projection_search() {
    projections_within_their_constant(100_000);
}

/// The proven relative errors of the sine and cosine polynomials with
/// their tail (`sin_poly_tail.g`, `cos_poly_tail.g`, the `#! law` goals).
const SIN_POLY_TAIL_LAW: f64 = 1.0e-7;
const COS_POLY_TAIL_LAW: f64 = 8e-8;

/// The largest relative errors of the kernel's sine and cosine polynomials
/// against sin and cos of `r + t` (the exact sum of the head and tail they
/// receive), over every `step`-th f32 `a` of [0, 3 pi/4]: `(a, 0)` up to
/// pi/4, beyond it the head and tail of `pi/2 - a` as the kernel computes
/// them, whose cosine is the kernel's sine. Measured in f64, where `r + t`
/// is exact and sin and cos are within 2^-52.
fn polynomial_tail_errors(step: usize) -> (f64, f64) {
    use rigtform_proofs::reference::narrow_head_and_tail;
    let three_quarters = 2.356_194_3f32;
    let (mut sin_worst, mut cos_worst) = (0f64, 0f64);
    for bits in (1..=three_quarters.to_bits()).step_by(step) {
        let a = f32::from_bits(bits);
        let (s, c) = rigtform::kani_kernels::sin_cos(a);
        let (r, t, swapped) = narrow_head_and_tail(a);
        let (of_sin, of_cos) = if swapped { (c, s) } else { (s, c) };
        let y = f64::from(r) + f64::from(t);
        let rel = |got: f32, want: f64| ((f64::from(got) - want) / want).abs();
        sin_worst = sin_worst.max(rel(of_sin, y.sin()));
        cos_worst = cos_worst.max(rel(of_cos, y.cos()));
    }
    (sin_worst, cos_worst)
}

/// Fails unless the errors found stay within the proven laws, and the laws
/// within 4 times what is found (a proof far above the worst case would
/// say little).
fn polynomial_tail_within_the_laws(step: usize) {
    let (sin, cos) = polynomial_tail_errors(step);
    println!("sin_poly(r, t), relative to sin(r + t): {sin:.4e} (law {SIN_POLY_TAIL_LAW:e})");
    println!("cos_poly(r, t), relative to cos(r + t): {cos:.4e} (law {COS_POLY_TAIL_LAW:e})");
    assert!(sin <= SIN_POLY_TAIL_LAW && cos <= COS_POLY_TAIL_LAW);
    assert!(SIN_POLY_TAIL_LAW <= 4.0 * sin && COS_POLY_TAIL_LAW <= 4.0 * cos);
}

#[test]
fn polynomials_with_their_tail_stay_within_their_laws() {
    polynomial_tail_within_the_laws(997);
}

#[test]
#[ignore = "a minute in release: every f32 of [0, 3 pi/4]"]
fn every_polynomial_tail_within_its_law() {
    polynomial_tail_within_the_laws(1);
}

/// The proven relative error of the atan2 kernel's arctangent polynomial
/// (`atan_poly.g` and `atan_poly_tiny.g`, the `#! law` goals).
const ATAN_POLY_LAW: f64 = 8.8e-8;

/// The largest relative error of the kernel's arctangent polynomial against
/// atan(u), over every `step`-th positive f32 `u` up to tan(1/2), and the
/// `u` where it is: through `atan2(u, 1)`, whose lower branch is
/// `atan_poly(u)` there (`arctangent_polynomial_is_atan_poly_g` in the
/// correspondence test). Measured in f64, where atan is within 2^-52.
fn atan_poly_error(step: usize) -> (f64, f32) {
    let tan_half = 0.546_302_5f32;
    let mut worst = (0f64, 0f32);
    for bits in (1..=tan_half.to_bits()).step_by(step) {
        let u = f32::from_bits(bits);
        let want = f64::from(u).atan();
        let got = f64::from(rigtform::kani_kernels::atan2(u, 1.0));
        let rel = ((got - want) / want).abs();
        if rel > worst.0 {
            worst = (rel, u);
        }
    }
    worst
}

/// Fails unless the error found stays within the proven law, and the law
/// within 4 times what is found.
fn atan_poly_within_the_law(step: usize) {
    let (found, u) = atan_poly_error(step);
    println!("atan_poly(u), relative to atan(u): {found:.4e} at u = {u:e} (law {ATAN_POLY_LAW:e})");
    assert!(found <= ATAN_POLY_LAW && ATAN_POLY_LAW <= 4.0 * found);
}

#[test]
fn arctangent_polynomial_stays_within_its_law() {
    atan_poly_within_the_law(997);
}

#[test]
#[ignore = "a minute in release: every f32 of [0, tan(1/2)]"]
fn every_arctangent_polynomial_within_its_law() {
    atan_poly_within_the_law(1);
}

/// The atan2 kernel's proven absolute error: the largest goal of
/// `atan2_outer.g` and `atan2_middle.g` (`#! bound ATAN2_MAX_ABS_ERROR`).
const ATAN2_PROVEN: f64 = 3.16e-7;

/// The largest absolute error of the atan2 kernel against the f64 atan2 of
/// its arguments over `draws` random pairs of every scale, sign and branch
/// (one argument over the other in [0, 1.9], either way round), then
/// climbing from the worst of them one argument's last bits at a time.
fn atan2_search(draws: usize, seed: u64) -> (f64, [f32; 2]) {
    let error = |v: [f32; 2]| {
        let got = f64::from(rigtform::kani_kernels::atan2(v[0], v[1]));
        let e = (got - f64::from(v[0]).atan2(f64::from(v[1]))).abs();
        if e.is_finite() {
            e
        } else {
            0.0
        }
    };
    let mut d = Draws::new(seed);
    let mut worst = (0f64, [0f32; 2]);
    for i in 0..draws {
        let a = 2f32.powi(d.below(200) as i32 - 100) * d.uniform(1.0, 2.0);
        let b = a * d.uniform(0.0, 1.9);
        let (y, x) = if i % 2 == 0 { (b, a) } else { (a, b) };
        let v = [y, if d.below(2) == 0 { x } else { -x }];
        let e = error(v);
        if e > worst.0 {
            worst = (e, v);
        }
    }
    let (v, e) = climb(&mut d, worst.1, 4000, &error);
    if e > worst.0 {
        worst = (e, v);
    }
    worst
}

/// Fails unless the error found stays within the proven bound (and the
/// constant), and the bound within 4 times what is found.
fn atan2_within_the_bound(draws: usize) {
    use rigtform::accuracy::ATAN2_MAX_ABS_ERROR;
    let (found, at) = atan2_search(draws, 41);
    println!("atan2 kernel, absolute: {found:.4e} at {at:?} (proven {ATAN2_PROVEN:e})");
    assert!(found <= ATAN2_PROVEN && ATAN2_PROVEN <= f64::from(ATAN2_MAX_ABS_ERROR));
    assert!(ATAN2_PROVEN <= 4.0 * found);
}

#[test]
fn atan2_found_stays_within_the_proven_bound() {
    atan2_within_the_bound(200_000);
}

#[test]
#[ignore = "seconds in release: the search the laws' docs quote"]
fn deep_atan2_search() {
    atan2_within_the_bound(20_000_000);
}

/// `| |from_axis_angle(axis, angle)| - 1 |` at `[x, y, z, angle]` (0 where
/// the result is not finite).
fn axis_angle_deviation(v: [f32; 4]) -> f64 {
    let q = Quat::from_axis_angle(Cvec3::new(v[0], v[1], v[2]), v[3]);
    if q.is_finite() {
        (norm64(q) - 1.0).abs()
    } else {
        0.0
    }
}

/// `| |q.pow(alpha)| - 1 |` at `[w, x, y, z, alpha]`, for `|alpha| <=
/// f32::MAX / 4` (the branch without the closing `normalize`; 0 beyond it
/// and where the result is not finite).
fn pow_deviation(v: [f32; 5]) -> f64 {
    if v[4].abs() > f32::MAX / 4.0 {
        return 0.0;
    }
    let q = Quat::from_wxyz(v[0], v[1], v[2], v[3]).pow(v[4]);
    if q.is_finite() {
        (norm64(q) - 1.0).abs()
    } else {
        0.0
    }
}

/// `| |normalize(v)| - 1 |` for a three-vector: the axis of
/// `from_axis_angle` and `pow`, the same sum of squares (with a fourth
/// square 0), root and quotients as `Quat::normalize`.
fn axis_deviation(v: [f32; 3]) -> f64 {
    let k = Cvec3::new(v[0], v[1], v[2]).normalize();
    let n = [k.x, k.y, k.z]
        .map(f64::from)
        .iter()
        .map(|c| c * c)
        .sum::<f64>();
    if n.is_finite() {
        (n.sqrt() - 1.0).abs()
    } else {
        0.0
    }
}

/// The norm laws of `from_axis_angle` and `pow` (the axis normalized as
/// `normalize` does, then the sine and cosine kernel's results and the
/// products `k s`): `climbs` climbs of `normalize`'s own norm error on
/// three-vectors (the part the axis contributes); the `climbs / 50` axes
/// with the largest are each tried with `tries` angles (for `pow`, `tries`
/// exponents `alpha` on a scalar part `w` uniform in [-1, 1]), half of them
/// turning the half angle within 0.01 of pi/2, where the sine is near 1
/// and the axis's error weighs in full, a quarter within 0.5 of it and a
/// quarter anywhere in [-5, 5], so that the kernel's and the products'
/// roundings fall with the axis's error; the best of them is climbed last,
/// over the axis and the angle together. Returns the largest deviations
/// found, `[from_axis_angle, pow]`.
fn axis_angle_and_pow_search(climbs: usize, tries: usize, seed: u64) -> [f64; 2] {
    use core::f32::consts::PI;
    let mut d = Draws::new(seed);
    let mut axes: Vec<([f32; 3], f64)> = (0..climbs)
        .map(|_| {
            let start: [f32; 3] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
            climb_wide(&mut d, start, 600, 4, &axis_deviation)
        })
        .collect();
    axes.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut worst = [0f64; 2];
    for (k, _) in axes.iter().take((climbs / 50).max(1)) {
        let w = d.uniform(-1.0, 1.0);
        let beta = k.iter().map(|c| f64::from(*c).powi(2)).sum::<f64>().sqrt();
        let phi = beta.atan2(f64::from(w)) as f32;
        let mut best_angle = ([0f32; 4], 0f64);
        let mut best_pow = ([0f32; 5], 0f64);
        for t in 0..tries {
            let half = match t % 4 {
                0 => PI / 2.0 + d.uniform(-0.5, 0.5),
                3 => d.uniform(-5.0, 5.0),
                _ => PI / 2.0 + d.uniform(-0.01, 0.01),
            };
            let x = [k[0], k[1], k[2], 2.0 * half];
            let e = axis_angle_deviation(x);
            if e > best_angle.1 {
                best_angle = (x, e);
            }
            let x = [w, k[0], k[1], k[2], half / phi.max(1e-3)];
            let e = pow_deviation(x);
            if e > best_pow.1 {
                best_pow = (x, e);
            }
        }
        let (x, _) = climb_wide(&mut d, best_angle.0, 1_000, 64, &axis_angle_deviation);
        worst[0] = worst[0].max(climb_wide(&mut d, x, 1_000, 4, &axis_angle_deviation).1);
        let (x, _) = climb_wide(&mut d, best_pow.0, 1_000, 64, &pow_deviation);
        worst[1] = worst[1].max(climb_wide(&mut d, x, 1_000, 4, &pow_deviation).1);
    }
    worst
}

fn axis_angle_and_pow_within_their_constant(climbs: usize) {
    let [axis_angle, pow] = axis_angle_and_pow_search(climbs, 20_000, 29);
    within(
        &format!("| |from_axis_angle(axis, angle)| - 1 | ({climbs} climbs)"),
        axis_angle,
        "UNIT_NORM_ERROR",
        UNIT_NORM_ERROR,
    );
    within(
        &format!("| |q.pow(alpha)| - 1 |, |alpha| <= f32::MAX / 4 ({climbs} climbs)"),
        pow,
        "UNIT_NORM_ERROR",
        UNIT_NORM_ERROR,
    );
}

#[test]
fn axis_angle_and_pow_found_stay_within_their_constant() {
    // An exact case: the x axis turned by 0 is the identity.
    assert_eq!(axis_angle_deviation([1.0, 0.0, 0.0, 0.0]), 0.0);
    axis_angle_and_pow_within_their_constant(300);
}

#[test]
#[ignore = "a minute in release: the search the constant's doc quotes"]
fn deep_axis_angle_and_pow_search() {
    axis_angle_and_pow_within_their_constant(30_000);
}

/// `[| |r| / n - 1 |, | |r| / m - 1 |]` for `r` slerp's f32 evaluation
/// (the whole of slerp on targets without the f64 one, and what the f64
/// one leaves) of `a` and `b` the results of `normalize` on the first and
/// the next four inputs, at `alpha` the last: the first the constant's
/// quantity (`n` the nearest norm to `|r|` between `|a|` and `|b|`), the second what slerp adds to the inputs' own norms, with
/// `m = w0 |a| + w1 |b|` for `alpha` in [0, 1] (the weights `w0 = C0
/// cos(alpha phi)`, `w1 = C1 cos((1 - alpha) phi)` of the exact
/// coefficients, which sum to 1) and `m = |a|` extrapolating (a turn of
/// `a`); 0 where `alpha` is outside `range` or a result is not finite.
fn slerp_f32_deviations(v: [f32; 9], range: (f32, f32)) -> [f64; 2] {
    use rigtform::kani_kernels::slerp_in_f32;
    let alpha = v[8];
    if !(range.0..=range.1).contains(&alpha) {
        return [0.0; 2];
    }
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]).normalize();
    let r = slerp_in_f32(a, b, alpha);
    if !(a.is_finite() && b.is_finite() && r.is_finite()) {
        return [0.0; 2];
    }
    let (na, nb, n) = (norm64(a), norm64(b), norm64(r));
    let m = if (0.0..=1.0).contains(&alpha) {
        let (pa, pb) = (q64(a), q64(b));
        let dot: f64 = pa.iter().zip(&pb).map(|(x, y)| x * y).sum();
        let len = |s: f64| {
            pa.iter()
                .zip(&pb)
                .map(|(x, y)| (x / na + s * dot.signum() * y / nb).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let phi = 2.0 * len(-1.0).atan2(len(1.0));
        let al = f64::from(alpha);
        if phi.sin() == 0.0 {
            na
        } else {
            let (c0, c1) = (
                ((1.0 - al) * phi).sin() / phi.sin(),
                (al * phi).sin() / phi.sin(),
            );
            c0 * (al * phi).cos() * na + c1 * ((1.0 - al) * phi).cos() * nb
        }
    } else {
        na
    };
    // The nearest norm between the inputs' (UNIT_NORM_ERROR's measure).
    let nearest = n.clamp(na.min(nb), na.max(nb));
    [(n / nearest - 1.0).abs(), (n / m - 1.0).abs()]
}

/// The largest of slerp's f32 norm errors ([`slerp_f32_deviations`], both
/// quantities) for `alpha` in [0, 1] and for `alpha` in [-2^20, 2^20]
/// outside it: every pair of the `pair` results of `normalize` with the
/// largest norm errors of opposite signs (where `|b| / |a|` is farthest
/// from 1) at `alpha` near 1, 1/2 and random; then `climbs` climbs on
/// each error over both inputs and `alpha`, from random pairs, pairs a
/// few ulps to 2^-4 apart (the small-angle branch among them), pairs near
/// a right angle, and pairs of the pool, with `alpha` random or near the
/// ends. `[[in [0, 1], extrapolated]; 2]`, relative to the nearest norm between the inputs', then `m`.
fn slerp_f32_search(climbs: usize, pair: usize, steps: usize, seed: u64) -> [[f64; 2]; 2] {
    let (pool, _) = normalized_pool(climbs.max(200), seed);
    let (low, high): (Vec<Quat>, Vec<Quat>) = pool.iter().partition(|q| norm64(**q) < 1.0);
    let mut d = Draws::new(seed ^ 0x51e4);
    let ranges = [(0.0, 1.0), (-1_048_576.0, 1_048_576.0)];
    let mut found = [[0f64; 2]; 2];
    let flat = |a: Quat, b: Quat, alpha: f32| [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z, alpha];
    let see = |found: &mut [[f64; 2]; 2], i: usize, e: [f64; 2]| {
        for (f, e) in found.iter_mut().zip(e) {
            f[i] = f[i].max(e);
        }
    };
    for (lo, hi) in [(&low, &high), (&high, &low)] {
        for a in lo.iter().take(pair) {
            for b in hi.iter().take(pair) {
                for alpha in [1.0, 0.999_999_94, 0.5, d.uniform(0.0, 1.0)] {
                    see(
                        &mut found,
                        0,
                        slerp_f32_deviations(flat(*a, *b, alpha), ranges[0]),
                    );
                }
                let alpha = d.uniform(-3.0, 4.0);
                see(
                    &mut found,
                    1,
                    slerp_f32_deviations(flat(*a, *b, alpha), ranges[1]),
                );
            }
        }
    }
    for c in 0..climbs {
        let a = d.unit_quat();
        let b = match c % 4 {
            0 => d.unit_quat(),
            1 => nearby(&mut d, a, 20),
            2 => right_angled_to(&mut d, a),
            _ => pool[d.below(pool.len().min(pair.max(1)))],
        };
        let a = if c % 4 == 3 {
            pool[d.below(pool.len())]
        } else {
            a
        };
        for (i, range) in ranges.iter().enumerate() {
            let alpha = match (i, d.below(3)) {
                (0, 0) => 1.0,
                (0, 1) => d.uniform(0.0, 1.0),
                (0, _) => d.uniform(0.9, 1.0),
                (_, 0) => d.uniform(-2.0, 0.0),
                (_, 1) => d.uniform(1.0, 3.0),
                (_, _) => d.uniform(-1000.0, 1000.0),
            };
            for (k, f) in found.iter_mut().enumerate() {
                let (_, e) = climb(&mut d, flat(a, b, alpha), steps, &|x| {
                    slerp_f32_deviations(x, *range)[k]
                });
                f[i] = f[i].max(e);
            }
        }
    }
    found
}

/// `| |slerp(a, b, 1)| / |b| - 1 |` on slerp's f32 evaluation, for `a`
/// and `b` the results of `normalize` on the first and the last four
/// inputs more than 2^-11 rad apart (the branch of
/// `proofs/coq/slerp_endpoint_norm_f32.v`, `phi > 2^-12`, with a margin);
/// 0 elsewhere.
fn slerp_f32_endpoint_deviation(v: [f32; 8]) -> f64 {
    use rigtform::kani_kernels::slerp_in_f32;
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]).normalize();
    if !(a.is_finite() && b.is_finite()) {
        return 0.0;
    }
    let (pa, pb) = (q64(a), q64(b));
    let cos: f64 = pa.iter().zip(&pb).map(|(x, y)| x * y).sum::<f64>() / (norm64(a) * norm64(b));
    if cos
        .abs()
        .min(1.0)
        .acos()
        .min(std::f64::consts::PI - cos.abs().min(1.0).acos())
        <= 1.0 / 2048.0
    {
        return 0.0;
    }
    let r = slerp_in_f32(a, b, 1.0);
    (norm64(r) / norm64(b) - 1.0).abs()
}

/// slerp's f32 searches, against `UNIT_NORM_ERROR`, and the endpoint's
/// against the proven bound of `proofs/coq/slerp_endpoint_norm_f32.v`.
fn slerp_f32_within_the_constant(climbs: usize, pair: usize, steps: usize) {
    let [[in_plane, extrapolated], [in_plane_mean, _]] = slerp_f32_search(climbs, pair, steps, 29);
    println!("| |slerp(a, b, alpha)| / n - 1 |, n the nearest norm between |a| and |b|, f32 path, alpha in [0, 1]: {in_plane:.4e}");
    println!(
        "| |slerp(a, b, alpha)| / n - 1 |, f32 path, |alpha| <= 2^20 outside [0, 1]: {extrapolated:.4e}"
    );
    println!(
        "| |slerp(a, b, alpha)| / m - 1 |, m the weighted mean of |a| and |b|, f32 path, alpha in [0, 1]: {in_plane_mean:.4e}"
    );
    let mut d = Draws::new(31);
    let endpoint = (0..climbs / 10)
        .map(|_| climb_far(&mut d, steps, &slerp_f32_endpoint_deviation))
        .fold(0f64, f64::max);
    println!(
        "| |slerp(a, b, 1)| / |b| - 1 |, f32 path, more than 2^-11 rad apart: {endpoint:.4e} ({} climbs; 1.193e-7 proven)",
        climbs / 10
    );
    assert!(endpoint <= 1.193e-7, "{endpoint:e}");
    within(
        "slerp's f32 path",
        in_plane.max(extrapolated),
        "UNIT_NORM_ERROR",
        UNIT_NORM_ERROR,
    );
}

#[test]
fn slerp_f32_found_stays_within_the_constant() {
    slerp_f32_within_the_constant(200, 20, 300);
}

#[test]
#[ignore = "a minute in release: the search the constant's doc quotes"]
fn deep_slerp_f32_search() {
    slerp_f32_within_the_constant(100_000, 300, 600);
}

/// [`slerp_f32_deviations`] on the main branch of slerp's f32 path in the
/// plane (`proofs/coq/slerp_plane_f32.v`'s domain): `alpha` in (0, 1), the
/// inputs more than 2^-11 rad apart (`phi > 2^-12` with a margin) and the
/// endpoint factor not applied (`|n2 - on2| <= 1e-6 on2` as the code
/// computes it); 0 elsewhere.
fn slerp_f32_plane_deviations(v: [f32; 9]) -> [f64; 2] {
    let alpha = v[8];
    if !(alpha > 0.0 && alpha < 1.0) {
        return [0.0; 2];
    }
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]).normalize();
    if !(a.is_finite() && b.is_finite()) {
        return [0.0; 2];
    }
    let (n2, on2) = (a.norm_squared(), b.norm_squared());
    if (n2 - on2).abs() > 1e-6 * on2 {
        return [0.0; 2];
    }
    let (pa, pb) = (q64(a), q64(b));
    let cos = pa.iter().zip(&pb).map(|(x, y)| x * y).sum::<f64>() / (norm64(a) * norm64(b));
    if cos.abs().min(1.0).acos() <= 1.0 / 2048.0 {
        return [0.0; 2];
    }
    slerp_f32_deviations(v, (0.0, 1.0))
}

/// A start for slerp's searches: `a` moved by up to `2^-k` per component,
/// `k` from 4 to `3 + binades`.
fn nearby(d: &mut Draws, a: Quat, binades: usize) -> Quat {
    let s = 2f32.powi(-(d.below(binades) as i32) - 4);
    Quat::from_wxyz(
        a.w + s * d.uniform(-1.0, 1.0),
        a.x + s * d.uniform(-1.0, 1.0),
        a.y + s * d.uniform(-1.0, 1.0),
        a.z + s * d.uniform(-1.0, 1.0),
    )
}

/// A start for slerp's searches near a right angle to `a`: a random unit
/// quaternion minus its part along `a`.
fn right_angled_to(d: &mut Draws, a: Quat) -> Quat {
    let b = d.unit_quat();
    let ab = a.dot(b);
    Quat::from_wxyz(
        b.w - ab * a.w,
        b.x - ab * a.x,
        b.y - ab * a.y,
        b.z - ab * a.z,
    )
}

/// The largest errors of [`slerp_f32_plane_deviations`] that `climbs`
/// climbs find, from random pairs, pairs 2^-10 to 2^-4 apart, pairs near
/// a right angle and pairs of the results of `normalize` farthest from
/// unit norm, with `alpha` near 1/2, random or near 1.
fn slerp_f32_plane_search(climbs: usize, steps: usize, seed: u64) -> [f64; 2] {
    let (pool, _) = normalized_pool(climbs.max(200), seed);
    let mut d = Draws::new(seed ^ 0x91a4e);
    let mut found = [0f64; 2];
    let flat = |a: Quat, b: Quat, alpha: f32| [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z, alpha];
    for c in 0..climbs {
        let a = if c % 4 == 3 {
            pool[d.below(pool.len())]
        } else {
            d.unit_quat()
        };
        let b = match c % 4 {
            0 => d.unit_quat(),
            1 => nearby(&mut d, a, 7),
            2 => right_angled_to(&mut d, a),
            _ => pool[d.below(pool.len())],
        };
        let alpha = match d.below(3) {
            0 => d.uniform(0.45, 0.55),
            1 => d.uniform(0.0, 1.0),
            _ => d.uniform(0.9, 1.0),
        };
        for (k, f) in found.iter_mut().enumerate() {
            let (_, e) = climb(&mut d, flat(a, b, alpha), steps, &|x| {
                slerp_f32_plane_deviations(x)[k]
            });
            *f = f.max(e);
        }
    }
    found
}

/// The search of the plane's main branch, against the constant.
fn slerp_f32_plane_within_the_constant(climbs: usize, steps: usize) {
    let [nearest, mean] = slerp_f32_plane_search(climbs, steps, 37);
    println!("| |slerp(a, b, alpha)| / n - 1 |, n the nearest norm between |a| and |b|, f32 path in the plane, alpha in (0, 1), phi > 2^-11, no endpoint factor: {nearest:.4e} ({climbs} climbs)");
    println!("| |slerp(a, b, alpha)| / m - 1 |, m the weighted mean of |a| and |b|, same domain: {mean:.4e}");
    within(
        "slerp's f32 path in the plane",
        nearest,
        "UNIT_NORM_ERROR",
        UNIT_NORM_ERROR,
    );
}

#[test]
fn slerp_f32_plane_found_stays_within_the_constant() {
    slerp_f32_plane_within_the_constant(200, 300);
}

#[test]
#[ignore = "a minute in release: the search of the plane's main branch"]
fn deep_slerp_f32_plane_search() {
    slerp_f32_plane_within_the_constant(100_000, 600);
}

/// slerp's norm on its f64 path (x86-64 and AArch64: `alpha` in (0, 1],
/// inputs more than 2^-12 rad apart and not at a right angle), for `a`
/// and `b` the results of `normalize` on the first and the next four
/// inputs, `alpha` the last (0 outside that path): `[| |r| / n - 1 |,
/// | |r| / m - 1 |]`, the first the constant's (`n` the nearest norm to
/// `|r|` between `|a|` and `|b|`), the second
/// `proofs/coq/slerp_norm_f64.v`'s, with `m = w0 |a| + w1 |b|` the mean of
/// the inputs' norms with the weights `w0 = C0 cos(alpha phi)`, `w1 = C1
/// cos((1 - alpha) phi)` of the exact coefficients `C0`, `C1` (`m = |a|`
/// for inputs of equal norms).
fn slerp_f64_norm_errors(v: [f32; 9]) -> [f64; 2] {
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]).normalize();
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]).normalize();
    let alpha = v[8];
    if !(a.is_finite() && b.is_finite() && alpha > 0.0 && alpha <= 1.0) {
        return [0.0; 2];
    }
    let (pa, pb) = (q64(a), q64(b));
    let dot: f64 = pa.iter().zip(&pb).map(|(x, y)| x * y).sum();
    let (na, nb) = (norm64(a), norm64(b));
    // The angle between the directions of a and cn(b).
    let sign = dot.signum();
    let len = |s: f64| {
        pa.iter()
            .zip(&pb)
            .map(|(x, y)| (x / na + s * sign * y / nb).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    let phi = 2.0 * len(-1.0).atan2(len(1.0));
    // The f32 path takes angles up to 2^-12 and right angles to f64's
    // precision; 2^-11 and 1e-9 leave a margin.
    if phi <= 1.0 / 2048.0 || dot.abs() < 1e-9 {
        return [0.0; 2];
    }
    let al = f64::from(alpha);
    let (c0, c1) = (
        ((1.0 - al) * phi).sin() / phi.sin(),
        (al * phi).sin() / phi.sin(),
    );
    let (w0, w1) = (c0 * (al * phi).cos(), c1 * ((1.0 - al) * phi).cos());
    let n = norm64(a.slerp(b, alpha));
    // The nearest norm between the inputs' (UNIT_NORM_ERROR's measure).
    let nearest = n.clamp(na.min(nb), na.max(nb));
    [
        (n / nearest - 1.0).abs(),
        (n / (w0 * na + w1 * nb) - 1.0).abs(),
    ]
}

/// The largest errors of [`slerp_f64_norm_errors`] that `climbs` climbs
/// each find, from pairs with components uniform in [-1, 1] and `alpha`
/// uniform in (0, 1], a quarter of them with `alpha` near 1/2 and a
/// quarter near 1, climbing each error by up to 4096, 64 and 4 units in
/// the last place.
fn slerp_f64_norm_search(climbs: usize, seed: u64) -> [f64; 2] {
    let mut d = Draws::new(seed);
    let mut found = [0f64; 2];
    for c in 0..climbs {
        let mut x: [f32; 9] = core::array::from_fn(|_| d.uniform(-1.0, 1.0));
        x[8] = match c % 4 {
            1 => d.uniform(0.45, 0.55),
            2 => d.uniform(0.95, 1.0),
            3 => {
                // Far apart (1.2 to 1.55 rad), where the coefficients'
                // sum, and so the rounding of the weighted sum, is
                // largest: b = cos(phi) a + sin(phi) u, u across a.
                let a = q64(Quat::from_wxyz(x[0], x[1], x[2], x[3]).normalize());
                let v = x[4..8].iter().map(|c| f64::from(*c));
                let av: f64 = a.iter().zip(v.clone()).map(|(p, q)| p * q).sum();
                let across: Vec<f64> = a.iter().zip(v).map(|(p, q)| q - av * p).collect();
                let len = across.iter().map(|c| c * c).sum::<f64>().sqrt();
                let phi = f64::from(d.uniform(1.2, 1.55));
                for (i, (p, q)) in a.iter().zip(&across).enumerate() {
                    x[i] = *p as f32;
                    x[4 + i] = (phi.cos() * p + phi.sin() * q / len) as f32;
                }
                d.uniform(0.4, 0.6)
            }
            _ => d.uniform(0.0, 1.0).max(f32::MIN_POSITIVE),
        };
        for (i, f) in found.iter_mut().enumerate() {
            let mut start = (x, 0.0);
            for reach in [4096, 64, 4] {
                start = climb_wide(&mut d, start.0, 300, reach, &|v| {
                    slerp_f64_norm_errors(v)[i]
                });
            }
            *f = f.max(start.1);
        }
    }
    found
}

/// The bound `proofs/coq/slerp_norm_f64.v` proves of `| |r| / m - 1 |`.
const SLERP_F64_NORM_PROVEN: f64 = 2.2e-7;

/// slerp's f64 path's searches, `climbs` climbs each, printed: the norm
/// against the range of the inputs' norms and `UNIT_NORM_ERROR`, and relative to the
/// weighted mean of the inputs' norms against the proven bound of
/// `proofs/coq/slerp_norm_f64.v`.
fn slerp_f64_norm_within(climbs: usize) {
    let [own, mean] = slerp_f64_norm_search(climbs, 29);
    within(
        &format!("slerp, f64 path, | |r| / n - 1 |, n the nearest norm between |a| and |b|, results of normalize ({climbs} climbs)"),
        own,
        "UNIT_NORM_ERROR",
        UNIT_NORM_ERROR,
    );
    println!(
        "slerp, f64 path, | |r| / m - 1 |, m the weighted mean of |a| and |b|: {mean:.4e} (proven {SLERP_F64_NORM_PROVEN:e}, ratio {:.3})",
        SLERP_F64_NORM_PROVEN / mean
    );
    assert!(mean <= SLERP_F64_NORM_PROVEN, "{mean:e}");
}

#[test]
fn slerp_f64_norm_found_stays_within_the_proven_bound() {
    slerp_f64_norm_within(60);
}

#[test]
#[ignore = "a minute in release: the search the constant's doc quotes"]
fn deep_slerp_f64_norm_search() {
    slerp_f64_norm_within(40_000);
}

/// The bound `proofs/coq/renormalized_norm.v` proves for one
/// `mul_renormalized` step from its domain.
const RENORMALIZED_NORM_PROVEN: f64 = 1.947e-7;

/// Whether `q` lies in the domain of `proofs/coq/renormalized_norm.v`:
/// `|q|^2` within 2^-20 of 1, whatever its components (one may exceed 1).
fn in_product_domain(q: Quat) -> bool {
    (norm64(q).powi(2) - 1.0).abs() <= 2f64.powi(-20)
}

/// `| |a.mul_renormalized(b)| - 1 |` for `a` the first four inputs and `b`
/// the last four as they are (0 outside the law's domain, and for `chain`
/// outside the invariant's: `|a|` within 1.947e-7 of 1, `|b|` within
/// 2.391e-7, a step's).
fn renormalized_deviation(v: [f32; 8], chain: bool) -> f64 {
    let a = Quat::from_wxyz(v[0], v[1], v[2], v[3]);
    let b = Quat::from_wxyz(v[4], v[5], v[6], v[7]);
    if !in_product_domain(a) || !in_product_domain(b) {
        return 0.0;
    }
    if chain && ((norm64(a) - 1.0).abs() > 1.947e-7 || (norm64(b) - 1.0).abs() > 2.391e-7) {
        return 0.0;
    }
    (norm64(a.mul_renormalized(b)) - 1.0).abs()
}

/// The largest [`renormalized_deviation`], and its inputs, over `climbs` climbs (reaches
/// 4096, 64 and 4, `steps` nudges in all), adversarial three ways: half of
/// them with `b` the identity, where the product is `a` itself and the
/// climb moves the squares and partial sums of `norm_squared` directly
/// (the start's squares near 1/2, 1/4, 1/8, 1/8 in some order, each just
/// above its power of two where its rounding is largest, for one climb in
/// four); the other half over both inputs, from results of `normalize`;
/// and `a` scaled to the edges of the invariant (`|a|` off unit norm by
/// 1.9e-7, either way) for two starts in three.
fn renormalized_search(climbs: usize, steps: usize, seed: u64, chain: bool) -> (f64, [f32; 8]) {
    let error = |v: [f32; 8]| renormalized_deviation(v, chain);
    let mut d = Draws::new(seed);
    let mut worst = (0f64, [0f32; 8]);
    for i in 0..climbs {
        let scale = [1.0, 1.0 + 1.9e-7, 1.0 - 1.9e-7][i % 3];
        let mut a = Quat::from_array(d.unit_quat().to_array().map(|c| c * scale));
        if i % 8 == 0 {
            let mut v = [0.5f64, 0.25, 0.125, 0.125].map(|s| (s * (1.0 + 1e-6)).sqrt() as f32);
            for k in (1..4).rev() {
                v.swap(k, d.below(k + 1));
            }
            a = Quat::from_array(v.map(|c| if d.below(2) == 0 { c } else { -c }));
        }
        let found = if i % 2 == 0 {
            let alone = |v: [f32; 4]| error([v[0], v[1], v[2], v[3], 1.0, 0.0, 0.0, 0.0]);
            let mut x = [a.w, a.x, a.y, a.z];
            let mut e = 0.0;
            for reach in [4096, 64, 4] {
                (x, e) = climb_wide(&mut d, x, steps / 3, reach, &alone);
            }
            (e, [x[0], x[1], x[2], x[3], 1.0, 0.0, 0.0, 0.0])
        } else {
            let b = d.unit_quat().normalize();
            let mut x = [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z];
            let mut e = 0.0;
            for reach in [4096, 64, 4] {
                (x, e) = climb_wide(&mut d, x, steps / 3, reach, &error);
            }
            (e, x)
        };
        if found.0 > worst.0 {
            worst = found;
        }
    }
    worst
}

/// The search, `climbs` climbs in the law's domain and as many in the
/// invariant's, printed against the proven bound and the constant, neither
/// of which it may pass.
fn renormalized_within(climbs: usize) {
    let off = |v: &[f32]| norm64(Quat::from_wxyz(v[0], v[1], v[2], v[3])) - 1.0;
    for (chain, domain) in [
        (false, "a, b within 2^-20 of unit norm"),
        (true, "|a| - 1 within 1.947e-7, |b| - 1 within 2.391e-7"),
    ] {
        let (found, x) = renormalized_search(climbs, 3_000, 31, chain);
        println!(
            "| |a.mul_renormalized(b)| - 1 |, {domain} ({climbs} climbs): {found:.4e} (proven {RENORMALIZED_NORM_PROVEN:e}, ratio {:.3}; RENORMALIZED_CHAIN_NORM_ERROR {:e}), at |a| - 1 = {:.3e}, |b| - 1 = {:.3e}: {x:?}",
            RENORMALIZED_NORM_PROVEN / found,
            RENORMALIZED_CHAIN_NORM_ERROR,
            off(&x[..4]),
            off(&x[4..]),
        );
        assert!(found <= RENORMALIZED_NORM_PROVEN, "{found:e}");
        assert!(
            found <= f64::from(RENORMALIZED_CHAIN_NORM_ERROR),
            "{found:e}"
        );
    }
}

#[test]
fn renormalized_found_stays_within_the_proven_bound() {
    // An exact case: the identity times itself.
    assert_eq!(
        renormalized_deviation([1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0], true),
        0.0
    );
    // A chain state with a component above 1 (the f32 after 1): inside
    // the law's domain and the invariant's.
    let above = f32::from_bits(1f32.to_bits() + 1);
    let step = Quat::from_wxyz(0.6, 0.8, 0.0, 0.0);
    assert!(in_product_domain(Quat::from_wxyz(above, 0.0, 0.0, 0.0)) && in_product_domain(step));
    assert!((norm64(step) - 1.0).abs() <= 2.391e-7);
    let d = renormalized_deviation([above, 0.0, 0.0, 0.0, 0.6, 0.8, 0.0, 0.0], true);
    assert!(d <= RENORMALIZED_NORM_PROVEN, "{d:e}");
    renormalized_within(100);
}

#[test]
#[ignore = "a minute in release: the search the constant's doc quotes"]
fn deep_renormalized_search() {
    renormalized_within(20_000);
}

/// The error of the scale that `to_scale_rotation_translation` takes back
/// from `from_scale_rotation_translation((s, |s|, |s|), q, 0)`, relative
/// to the input scale, the largest of the three columns, for `v = (w, x,
/// y, z, s)`: 0 outside the domain `SRT_SCALE_MAX_REL_ERROR`'s proof
/// covers (`|q|^2` within 1.2e-7 of 1, exactly; `|s|` in [1e-3, 1e3]).
fn srt_scale_error(v: [f32; 5]) -> f64 {
    let q = Quat::from_wxyz(v[0], v[1], v[2], v[3]);
    let s = v[4];
    let q2: f64 = q64(q).iter().map(|c| c * c).sum();
    if (q2 - 1.0).abs() > 1.2e-7 || !(1e-3..=1e3).contains(&s.abs()) {
        return 0.0;
    }
    let input = Cvec3::new(s, s.abs(), s.abs());
    let (got, _, _) = rigtform::Matrix4::from_scale_rotation_translation(input, q, Cvec3::ZERO)
        .to_scale_rotation_translation();
    [(got.x, input.x), (got.y, input.y), (got.z, input.z)]
        .iter()
        .map(|&(g, i)| ((f64::from(g) - f64::from(i)) / f64::from(i)).abs())
        .fold(0.0, f64::max)
}

/// The largest scale error that `climbs` climbs find, from unit
/// quaternions of the proof's domain (a third of them turned by nearly a
/// half turn about an axis in the y-z plane, a third about one in the
/// x-y plane, where a column of the rotation is nearly the negated axis
/// and its diagonal entry rounds the most) and scales of magnitude 1e-3
/// to 1e3 of either sign.
fn srt_scale_search(climbs: usize, seed: u64) -> f64 {
    let mut d = Draws::new(seed);
    let mut found = 0f64;
    for c in 0..climbs {
        let start = loop {
            let mut q = d.unit_quat();
            let small = d.uniform(-0.05, 0.05);
            match c % 3 {
                1 => (q.w, q.x) = (q.w * small, q.x * small),
                2 => (q.w, q.z) = (q.w * small, q.z * small),
                _ => {}
            }
            let q = q.normalize();
            let magnitude = 10f32.powf(d.uniform(-3.0, 3.0));
            let s = if d.below(2) == 0 {
                magnitude
            } else {
                -magnitude
            };
            let v = [q.w, q.x, q.y, q.z, s];
            if srt_scale_error(v) > 0.0 {
                break v;
            }
        };
        let (x, _) = climb_wide(&mut d, start, 300, 16, &srt_scale_error);
        let (_, e) = climb_wide(&mut d, x, 300, 2, &srt_scale_error);
        found = found.max(e);
    }
    found
}

#[test]
fn srt_scale_found_stays_within_its_constant() {
    use rigtform::accuracy::SRT_SCALE_MAX_REL_ERROR;
    // Outside the proof's domain the error function answers 0.
    assert_eq!(srt_scale_error([1.0, 0.0, 0.0, 0.0, 1e-4]), 0.0);
    assert_eq!(srt_scale_error([1.001, 0.0, 0.0, 0.0, 1.0]), 0.0);
    within(
        "to_scale_rotation_translation's scale, relative",
        srt_scale_search(300, 29),
        "SRT_SCALE_MAX_REL_ERROR",
        SRT_SCALE_MAX_REL_ERROR,
    );
}

#[test]
#[ignore = "seconds in release: the search the constant's doc quotes"]
fn deep_srt_scale_search() {
    use rigtform::accuracy::SRT_SCALE_MAX_REL_ERROR;
    within(
        "to_scale_rotation_translation's scale, relative",
        srt_scale_search(200_000, 31),
        "SRT_SCALE_MAX_REL_ERROR",
        SRT_SCALE_MAX_REL_ERROR,
    );
}
