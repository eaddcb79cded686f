//! Every public operation of rigtform, timed in the same run as the same
//! operation of glam (its default SIMD build and its `scalar-math` build),
//! nalgebra, micromath and cgmath, where each has it, on the same
//! pre-generated inputs.
//!
//! Each benchmark runs the operation over 1,024 inputs per iteration: the
//! input slice is hidden behind `black_box` (nothing is known about it at
//! compile time) and so is every result (nothing is vectorized across
//! inputs or left out); criterion reports the time per iteration, and the
//! performance page's table (docs/performance.md) divides its median by
//! 1,024.
//!
//! The plain-loop benchmarks (`slerp`, `RigTForm interpolate`, `nlerp` and
//! `q*q`, each `, plain loop`) time the single call as a user's loop calls
//! it: over a `Vec` of pairs, a different `alpha` for each, the results
//! stored in an output `Vec` (hidden behind `black_box` once per pass, not
//! per call). The same four `, through memory` pass each quaternion or
//! transform through `black_box` on its way to the call: stored and loaded
//! back, as a value passed by value to a function that is not inlined is
//! (a 28-byte `RigTForm` goes by memory in the x86-64 ABI).
//!
//! The two slice benchmarks (`slerp slice`, `RigTForm interpolate slice`)
//! time rigtform's slice APIs over all 1,024 pairs with one `alpha` against
//! a loop of each peer's single call over the same pairs.
//!
//! `cargo bench -p rigtform-compare --bench ops` runs them all, operation by
//! operation; `cargo bench -p rigtform-compare --bench ops -- slerp` only the
//! slerp group.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion, Throughput};
use rigtform::animation::{Interpolation, Sampler};
use rigtform::{Cvec4, Matrix4, Quat, RigTForm};
use rigtform_compare::*;

/// Inputs per iteration.
const N: usize = 1024;

type Group<'a> = BenchmarkGroup<'a, criterion::measurement::WallTime>;

/// One benchmark, to be run later: every library's benchmarks are set up
/// first and then run operation by operation, so that a burst of load from
/// elsewhere on the machine hits the libraries of one operation alike.
type Job = (&'static str, Box<dyn Fn(&mut Criterion)>);

/// Adds the benchmark of `f` over every element of `inputs` (converted
/// beforehand, outside the timing) to `jobs`.
fn run<I: Copy + 'static, O>(
    jobs: &mut Vec<Job>,
    op: &'static str,
    library: &'static str,
    inputs: &'static [I],
    f: impl Fn(I) -> O + 'static,
) {
    let job = move |c: &mut Criterion| {
        group(c, op).bench_function(library, |b| {
            b.iter(|| {
                for &x in black_box(inputs) {
                    black_box(f(x));
                }
            })
        });
    };
    jobs.push((op, Box::new(job)));
}

/// Adds the benchmark of `f` over every element of `inputs` written as a
/// user writes it: a plain loop over the elements (each with its own
/// `alpha`) that stores each result in an output slice of the same length,
/// hidden behind `black_box` once after the loop rather than call by call.
fn run_loop<I: Copy + 'static, O: Copy + 'static>(
    jobs: &mut Vec<Job>,
    op: &'static str,
    library: &'static str,
    inputs: &'static [I],
    init: O,
    f: impl Fn(I) -> O + 'static,
) {
    let job = move |c: &mut Criterion| {
        let mut out = vec![init; inputs.len()];
        group(c, op).bench_function(library, |b| {
            b.iter(|| {
                for (o, &x) in out.iter_mut().zip(black_box(inputs)) {
                    *o = f(x);
                }
                black_box(&mut out);
            })
        });
    };
    jobs.push((op, Box::new(job)));
}

/// An input whose quaternions or transforms pass through memory on their
/// way to the call: each through `black_box`, stored and loaded back, as a
/// value passed by value to a function that is not inlined is.
trait ThroughMemory: Copy {
    fn through_memory(self) -> Self;
}

impl<A: Copy> ThroughMemory for (A, A) {
    fn through_memory(self) -> Self {
        (black_box(self.0), black_box(self.1))
    }
}

impl<A: Copy> ThroughMemory for (A, A, f32) {
    fn through_memory(self) -> Self {
        (black_box(self.0), black_box(self.1), self.2)
    }
}

/// [`run_loop`] of `f` twice, under the names `ops`: as the inputs are,
/// and with each quaternion or transform passed through memory first.
fn run_loops<I: ThroughMemory + 'static, O: Copy + 'static>(
    jobs: &mut Vec<Job>,
    [plain, through_memory]: [&'static str; 2],
    library: &'static str,
    inputs: &'static [I],
    init: O,
    f: impl Fn(I) -> O + Copy + 'static,
) {
    run_loop(jobs, plain, library, inputs, init, f);
    run_loop(jobs, through_memory, library, inputs, init, move |x: I| {
        f(x.through_memory())
    });
}

/// The names of the user's-loop benchmarks of each operation: the plain
/// loop, and the loop whose values went through memory.
const SLERP_LOOPS: [&str; 2] = ["slerp, plain loop", "slerp, through memory"];
const INTERPOLATE_LOOPS: [&str; 2] = [
    "RigTForm interpolate, plain loop",
    "RigTForm interpolate, through memory",
];
const NLERP_LOOPS: [&str; 2] = ["nlerp, plain loop", "nlerp, through memory"];
const PRODUCT_LOOPS: [&str; 2] = ["q*q, plain loop", "q*q, through memory"];

/// The one `alpha` of the slice benchmarks (hidden behind `black_box`).
const SLICE_ALPHA: f32 = 0.37;

/// Adds the benchmark of `f` over the whole of `starts` and `ends` at once
/// (a slice API, or a loop of single calls) into an output slice of the same
/// length, with [`SLICE_ALPHA`], to `jobs`.
fn run_slice<I: Copy + 'static, O: Copy + 'static>(
    jobs: &mut Vec<Job>,
    op: &'static str,
    library: &'static str,
    (starts, ends): (&'static [I], &'static [I]),
    init: O,
    f: impl Fn(&[I], &[I], f32, &mut [O]) + 'static,
) {
    let job = move |c: &mut Criterion| {
        let mut out = vec![init; starts.len()];
        group(c, op).bench_function(library, |b| {
            b.iter(|| {
                f(
                    black_box(starts),
                    black_box(ends),
                    black_box(SLICE_ALPHA),
                    &mut out,
                );
                black_box(&mut out);
            })
        });
    };
    jobs.push((op, Box::new(job)));
}

/// A loop of `f` over the pairs of a slice benchmark: what a peer without
/// a slice API is called as.
fn each_pair<I: Copy, O>(f: impl Fn(I, I, f32) -> O) -> impl Fn(&[I], &[I], f32, &mut [O]) {
    move |starts, ends, alpha, out| {
        for ((&a, &b), o) in starts.iter().zip(ends).zip(out.iter_mut()) {
            *o = f(a, b, alpha);
        }
    }
}

/// A glTF rotation channel for the sampler benchmarks, kept: eight key
/// times 0.5 to 1.5 s apart, the keys (`qs`), the CUBICSPLINE values (the
/// keys with in- and out-tangents from `tangents`), and a time for every
/// input, spread over the channel by `alphas`.
#[allow(clippy::type_complexity)]
fn channel<Q: Copy + 'static>(
    qs: &[Q],
    tangents: &[Q],
    alphas: &[f32],
) -> (&'static [f32], &'static [Q], &'static [Q], &'static [f32]) {
    let times: Vec<f32> = (0..8).map(|i| i as f32 + 0.5 * alphas[i]).collect();
    let keys: Vec<Q> = qs[..8].to_vec();
    let cubic: Vec<Q> = (0..24)
        .map(|i| if i % 3 == 1 { qs[i / 3] } else { tangents[i] })
        .collect();
    let span = times[7] - times[0];
    let at: Vec<f32> = alphas.iter().map(|a| times[0] + a * span).collect();
    (
        keep(times).as_slice(),
        keep(keys).as_slice(),
        keep(cubic).as_slice(),
        keep(at).as_slice(),
    )
}

/// `value`, kept for the rest of the process (the jobs refer to it).
fn keep<T>(value: T) -> &'static T {
    Box::leak(Box::new(value))
}

fn group<'a>(c: &'a mut Criterion, name: &str) -> Group<'a> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(N as u64));
    g
}

/// The shared inputs in one library's types: quaternions `Q`, vectors `V`
/// and rigid body transforms `T` (whatever the library has for them).
struct Prepared<Q, V, T> {
    q: Vec<Q>,
    b: Vec<Q>,
    qq: Vec<(Q, Q)>,
    qv: Vec<(Q, V)>,
    qa: Vec<(Q, f32)>,
    qqa: Vec<(Q, Q, f32)>,
    /// Four rotations (the keys of a spline, or the control points of its
    /// segment) and a parameter in [0, 1].
    q4a: Vec<([Q; 4], f32)>,
    tf: Vec<T>,
    tf_b: Vec<T>,
    tf2: Vec<(T, T)>,
    tfv: Vec<(T, V)>,
    tfa: Vec<(T, T, f32)>,
}

impl<Q: Copy, V: Copy, T: Copy> Prepared<Q, V, T> {
    fn new(
        inp: &Inputs,
        quat: impl Fn([f32; 4]) -> Q,
        vec: impl Fn([f32; 3]) -> V,
        tform: impl Fn([f32; 3], [f32; 4]) -> T,
    ) -> Self {
        let q: Vec<Q> = inp.a.iter().map(|&a| quat(a)).collect();
        let b: Vec<Q> = inp.b.iter().map(|&b| quat(b)).collect();
        let tf: Vec<T> = inp
            .v
            .iter()
            .zip(&inp.a)
            .map(|(&t, &r)| tform(t, r))
            .collect();
        let tf_b: Vec<T> = inp
            .u
            .iter()
            .zip(&inp.b)
            .map(|(&t, &r)| tform(t, r))
            .collect();
        let v: Vec<V> = inp.v.iter().map(|&v| vec(v)).collect();
        let u: Vec<V> = inp.u.iter().map(|&u| vec(u)).collect();
        let t = &inp.alpha;
        Self {
            qq: q.iter().zip(&b).map(|(&a, &b)| (a, b)).collect(),
            qv: q.iter().zip(&v).map(|(&a, &v)| (a, v)).collect(),
            qa: q.iter().zip(t).map(|(&a, &t)| (a, t)).collect(),
            qqa: (0..N).map(|i| (q[i], b[i], t[i])).collect(),
            q4a: (0..N)
                .map(|i| {
                    let j = (i + 1) % N;
                    ([q[i], b[i], q[j], b[j]], t[i])
                })
                .collect(),
            tf2: tf.iter().zip(&tf_b).map(|(&a, &b)| (a, b)).collect(),
            tfv: tf.iter().zip(&u).map(|(&a, &u)| (a, u)).collect(),
            tfa: (0..N).map(|i| (tf[i], tf_b[i], t[i])).collect(),
            q,
            b,
            tf,
            tf_b,
        }
    }
}

/// The glam benchmarks, for both of its builds (same API, different crate).
/// A rigid body transform is what glam users write for one: a
/// (translation, rotation) pair.
macro_rules! glam_benches {
    ($c:ident, $inp:ident, $glam:ident, $name:expr, $quat:ident, $vec:ident) => {{
        let p = keep(Prepared::new($inp, $quat, $vec, |t, r| ($vec(t), $quat(r))));
        let mats: &'static [_] = keep::<Vec<_>>(
            p.tf.iter()
                .map(|&(t, r)| $glam::Mat4::from_rotation_translation(r, t))
                .collect(),
        );
        let name = $name;
        run($c, "q*q", name, &p.qq, |(a, b)| a * b);
        run($c, "rotate Cvec3", name, &p.qv, |(q, v)| q * v);
        run($c, "inv", name, &p.q, |q| q.inverse());
        run($c, "normalize", name, &p.q, |q| q.normalize());
        run($c, "slerp", name, &p.qqa, |(a, b, t)| a.slerp(b, t));
        run($c, "nlerp", name, &p.qqa, |(a, b, t)| a.lerp(b, t));
        // No spline in glam: the nearest equivalent is de Casteljau's six
        // slerps over four control points, without making them from keys.
        run($c, "catmull_rom", name, &p.q4a, |([p0, p1, p2, p3], u)| {
            let (a, b, c) = (p0.slerp(p1, u), p1.slerp(p2, u), p2.slerp(p3, u));
            a.slerp(b, u).slerp(b.slerp(c, u), u)
        });
        // No sampler in glam: what a glam user writes for one, the key
        // found by the same search, then glam's slerp, or the Hermite sum
        // on Vec4s and a normalize.
        {
            let (times, keys, cubic, at) = channel(&p.q, &p.b, &$inp.alpha);
            let segment = move |t: f32| {
                let k1 = times.partition_point(|&k| k <= t).clamp(1, times.len() - 1);
                let (t0, t1) = (times[k1 - 1], times[k1]);
                (k1, t1 - t0, ((t - t0) / (t1 - t0)).clamp(0.0, 1.0))
            };
            run($c, "glTF LINEAR rotation, 8 keys", name, at, move |t| {
                let (k1, _, u) = segment(t);
                keys[k1 - 1].slerp(keys[k1], u)
            });
            run(
                $c,
                "glTF CUBICSPLINE rotation, 8 keys",
                name,
                at,
                move |t| {
                    let (k1, td, u) = segment(t);
                    let v = |i: usize| $glam::Vec4::from(cubic[i].to_array());
                    let (uu, uuu) = (u * u, u * u * u);
                    let s2 = -2.0 * uuu + 3.0 * uu;
                    let s3 = uuu - uu;
                    let sum = v(3 * k1 - 2) * (1.0 - s2)
                        + v(3 * k1 - 1) * (td * (s3 - uu + u))
                        + v(3 * k1 + 1) * s2
                        + v(3 * k1) * (td * s3);
                    $glam::Quat::from_vec4(sum.normalize())
                },
            );
        }
        run(
            $c,
            "RigTForm * RigTForm",
            name,
            &p.tf2,
            |((t1, r1), (t2, r2))| (t1 + r1 * t2, r1 * r2),
        );
        run($c, "RigTForm inv", name, &p.tf, |(t, r)| {
            let ri = r.inverse();
            (-(ri * t), ri)
        });
        run($c, "RigTForm * point", name, &p.tfv, |((t, r), v)| {
            r * v + t
        });
        run(
            $c,
            "RigTForm interpolate",
            name,
            &p.tfa,
            |((t1, r1), (t2, r2), a)| (t1.lerp(t2, a), r1.slerp(r2, a)),
        );
        run_loops(
            $c,
            SLERP_LOOPS,
            name,
            &p.qqa,
            $glam::Quat::IDENTITY,
            |(a, b, t)| a.slerp(b, t),
        );
        run_loops(
            $c,
            INTERPOLATE_LOOPS,
            name,
            &p.tfa,
            ($glam::Vec3::ZERO, $glam::Quat::IDENTITY),
            |((t1, r1), (t2, r2), a)| (t1.lerp(t2, a), r1.slerp(r2, a)),
        );
        run_loops(
            $c,
            NLERP_LOOPS,
            name,
            &p.qqa,
            $glam::Quat::IDENTITY,
            |(a, b, t)| a.lerp(b, t),
        );
        run_loops(
            $c,
            PRODUCT_LOOPS,
            name,
            &p.qq,
            $glam::Quat::IDENTITY,
            |(a, b)| a * b,
        );
        run_slice(
            $c,
            "slerp slice",
            name,
            (&p.q, &p.b),
            $glam::Quat::IDENTITY,
            each_pair(|a: $glam::Quat, b, t| a.slerp(b, t)),
        );
        run_slice(
            $c,
            "RigTForm interpolate slice",
            name,
            (&p.tf, &p.tf_b),
            ($glam::Vec3::ZERO, $glam::Quat::IDENTITY),
            each_pair(|(t1, r1): ($glam::Vec3, $glam::Quat), (t2, r2), a| {
                (t1.lerp(t2, a), r1.slerp(r2, a))
            }),
        );
        run($c, "Matrix4 from RigTForm", name, &p.tf, |(t, r)| {
            $glam::Mat4::from_rotation_translation(r, t)
        });
        run($c, "normal_matrix", name, mats, |m| {
            $glam::Mat3::from_mat4(m).inverse().transpose()
        });
    }};
}

fn quat_ops(c: &mut Criterion) {
    let inp = Inputs::new(N, 1);
    let jobs = &mut Vec::new();

    // rigtform, under the name of its backend.
    {
        let p = keep(Prepared::new(&inp, rig_quat, rig_vec, rig_tform));
        let qc: &'static [_] = keep::<Vec<_>>(
            p.qv.iter()
                .map(|&(q, v)| (q, Cvec4::from_point(v)))
                .collect(),
        );
        let tfc: &'static [_] = keep::<Vec<_>>(
            p.tfv
                .iter()
                .map(|&(a, v)| (a, Cvec4::from_point(v)))
                .collect(),
        );
        let blend4: &'static [_] = keep::<Vec<_>>(
            (0..N)
                .map(|i| {
                    let (a, b, t) = p.qqa[i];
                    let (c, d, _) = p.qqa[(i + 1) % N];
                    [(a, 1.0 - t), (b, t), (c, 0.5), (d, 0.25)]
                })
                .collect(),
        );
        let mats: &'static [_] = keep::<Vec<_>>(p.tf.iter().map(|&a| Matrix4::from(a)).collect());
        let name = "rigtform";

        run(jobs, "q*q", name, &p.qq, |(a, b)| a * b);
        run(jobs, "q*q renormalized", name, &p.qq, |(a, b)| {
            a.mul_renormalized(b)
        });
        run(jobs, "rotate Cvec3", name, &p.qv, |(q, v)| q * v);
        run(jobs, "rotate Cvec4", name, qc, |(q, v)| q * v);
        run(jobs, "inv", name, &p.q, Quat::inv);
        run(jobs, "normalize", name, &p.q, Quat::normalize);
        run(jobs, "pow", name, &p.qa, |(q, t)| q.pow(t));
        run(jobs, "slerp", name, &p.qqa, |(a, b, t)| a.slerp(b, t));
        run(jobs, "nlerp", name, &p.qqa, |(a, b, t)| a.nlerp(b, t));
        run(jobs, "blend of 4", name, blend4, |e| Quat::blend(&e));
        // In the middle segment of the four keys, with four neighbours.
        run(jobs, "catmull_rom", name, &p.q4a, |(keys, t)| {
            Quat::catmull_rom(&keys, 1.0 + t)
        });
        // A glTF rotation channel of eight keys sampled at times spread
        // over it: the sampler made once, each call a search and a slerp
        // (LINEAR) or a Hermite sum and a normalize (CUBICSPLINE).
        let (times, keys, cubic, at) = channel(&p.q, &p.b, &inp.alpha);
        let linear =
            keep(Sampler::new(Interpolation::Linear, times, keys).expect("a valid channel"));
        let spline =
            keep(Sampler::new(Interpolation::CubicSpline, times, cubic).expect("a valid channel"));
        run(jobs, "glTF LINEAR rotation, 8 keys", name, at, |t| {
            linear.sample(t)
        });
        run(jobs, "glTF CUBICSPLINE rotation, 8 keys", name, at, |t| {
            spline.sample(t)
        });
        run(jobs, "RigTForm * RigTForm", name, &p.tf2, |(a, b)| a * b);
        run(jobs, "RigTForm inv", name, &p.tf, RigTForm::inv);
        run(jobs, "RigTForm * point", name, tfc, |(a, p)| a * p);
        run(jobs, "RigTForm interpolate", name, &p.tfa, |(a, b, t)| {
            a.interpolate(b, t)
        });
        run_loops(
            jobs,
            SLERP_LOOPS,
            name,
            &p.qqa,
            Quat::IDENTITY,
            |(a, b, t)| a.slerp(b, t),
        );
        run_loops(
            jobs,
            INTERPOLATE_LOOPS,
            name,
            &p.tfa,
            RigTForm::IDENTITY,
            |(a, b, t)| a.interpolate(b, t),
        );
        run_loops(
            jobs,
            NLERP_LOOPS,
            name,
            &p.qqa,
            Quat::IDENTITY,
            |(a, b, t)| a.nlerp(b, t),
        );
        run_loops(
            jobs,
            PRODUCT_LOOPS,
            name,
            &p.qq,
            Quat::IDENTITY,
            |(a, b)| a * b,
        );
        run_slice(
            jobs,
            "slerp slice",
            name,
            (&p.q, &p.b),
            Quat::IDENTITY,
            Quat::slerp_slice,
        );
        run_slice(
            jobs,
            "RigTForm interpolate slice",
            name,
            (&p.tf, &p.tf_b),
            RigTForm::IDENTITY,
            RigTForm::interpolate_slice,
        );
        run(jobs, "Matrix4 from RigTForm", name, &p.tf, Matrix4::from);
        run(jobs, "normal_matrix", name, mats, Matrix4::normal_matrix);
    }
    peers(jobs, &inp);
    // Operation by operation, in the order of the performance page's table (a stable
    // sort keeps rigtform first within each).
    jobs.sort_by_key(|&(op, _)| OPS.iter().position(|&o| o == op));
    for (_, job) in jobs.iter() {
        job(c);
    }
}

/// The operations, in the order they are run and tabulated (`cargo xtask
/// perf-report` takes the performance page's rows in the order `--list` prints
/// them).
const OPS: [&str; 29] = [
    "q*q",
    "q*q renormalized",
    "rotate Cvec3",
    "rotate Cvec4",
    "inv",
    "normalize",
    "pow",
    "slerp",
    "nlerp",
    "blend of 4",
    "catmull_rom",
    "glTF LINEAR rotation, 8 keys",
    "glTF CUBICSPLINE rotation, 8 keys",
    "RigTForm * RigTForm",
    "RigTForm inv",
    "RigTForm * point",
    "RigTForm interpolate",
    "slerp, plain loop",
    "RigTForm interpolate, plain loop",
    "slerp, through memory",
    "RigTForm interpolate, through memory",
    "nlerp, plain loop",
    "nlerp, through memory",
    "q*q, plain loop",
    "q*q, through memory",
    "slerp slice",
    "RigTForm interpolate slice",
    "Matrix4 from RigTForm",
    "normal_matrix",
];

/// The peers' benchmarks.
fn peers(jobs: &mut Vec<Job>, inp: &Inputs) {
    glam_benches!(jobs, inp, glam, "glam (SIMD)", glam_quat, glam_vec);
    glam_benches!(
        jobs,
        inp,
        glam_scalar,
        "glam (scalar-math)",
        glam_scalar_quat,
        glam_scalar_vec
    );

    // nalgebra: UnitQuaternion and Isometry3, f32.
    {
        let p = keep(Prepared::new(inp, na_quat, na_vec, na_iso));
        let mats: &'static [_] = keep::<Vec<_>>(p.tf.iter().map(|a| a.to_homogeneous()).collect());
        let name = "nalgebra";
        run(jobs, "q*q", name, &p.qq, |(a, b)| a * b);
        run(jobs, "rotate Cvec3", name, &p.qv, |(q, v)| q * v);
        run(jobs, "inv", name, &p.q, |q| q.inverse());
        run(jobs, "normalize", name, &p.q, |q| {
            q.into_inner().normalize()
        });
        run(jobs, "pow", name, &p.qa, |(q, t)| q.powf(t));
        run(jobs, "slerp", name, &p.qqa, |(a, b, t)| a.slerp(&b, t));
        run(jobs, "nlerp", name, &p.qqa, |(a, b, t)| a.nlerp(&b, t));
        // No spline either: de Casteljau's six slerps, as for glam.
        run(
            jobs,
            "catmull_rom",
            name,
            &p.q4a,
            |([p0, p1, p2, p3], u)| {
                let (a, b, c) = (p0.slerp(&p1, u), p1.slerp(&p2, u), p2.slerp(&p3, u));
                let (ab, bc) = (a.slerp(&b, u), b.slerp(&c, u));
                ab.slerp(&bc, u)
            },
        );
        run(jobs, "RigTForm * RigTForm", name, &p.tf2, |(a, b)| a * b);
        run(jobs, "RigTForm inv", name, &p.tf, |a| a.inverse());
        run(jobs, "RigTForm * point", name, &p.tfv, |(a, v)| {
            a * nalgebra::Point3::from(v)
        });
        run(jobs, "RigTForm interpolate", name, &p.tfa, |(a, b, t)| {
            a.lerp_slerp(&b, t)
        });
        let identity = nalgebra::UnitQuaternion::identity();
        run_loops(jobs, SLERP_LOOPS, name, &p.qqa, identity, |(a, b, t)| {
            a.slerp(&b, t)
        });
        run_loops(
            jobs,
            INTERPOLATE_LOOPS,
            name,
            &p.tfa,
            nalgebra::Isometry3::identity(),
            |(a, b, t)| a.lerp_slerp(&b, t),
        );
        run_loops(jobs, NLERP_LOOPS, name, &p.qqa, identity, |(a, b, t)| {
            a.nlerp(&b, t)
        });
        run_loops(jobs, PRODUCT_LOOPS, name, &p.qq, identity, |(a, b)| a * b);
        run_slice(
            jobs,
            "slerp slice",
            name,
            (&p.q, &p.b),
            nalgebra::UnitQuaternion::identity(),
            each_pair(|a: nalgebra::UnitQuaternion<f32>, b, t| a.slerp(&b, t)),
        );
        run_slice(
            jobs,
            "RigTForm interpolate slice",
            name,
            (&p.tf, &p.tf_b),
            nalgebra::Isometry3::identity(),
            each_pair(|a: nalgebra::Isometry3<f32>, b, t| a.lerp_slerp(&b, t)),
        );
        run(jobs, "Matrix4 from RigTForm", name, &p.tf, |a| {
            a.to_homogeneous()
        });
        run(jobs, "normal_matrix", name, mats, |m| {
            m.fixed_view::<3, 3>(0, 0)
                .into_owned()
                .try_inverse()
                .map(|m| m.transpose())
        });
    }

    // micromath: Quaternion (no slerp, pow or transforms).
    {
        let p = keep(Prepared::new(inp, mm_quat, mm_vec, |_, _| ()));
        let name = "micromath";
        run(jobs, "q*q", name, &p.qq, |(a, b)| a * b);
        run(jobs, "rotate Cvec3", name, &p.qv, |(q, v)| q.rotate(v));
        run(jobs, "inv", name, &p.q, |q| q.conj());
        run(jobs, "normalize", name, &p.q, |q| q.normalize());
    }

    // cgmath: Quaternion and Decomposed (no pow, no interpolation of transforms).
    {
        use cgmath::{EuclideanSpace, InnerSpace, Matrix, Rotation, SquareMatrix, Transform};
        let p = keep(Prepared::new(inp, cg_quat, cg_vec, cg_decomposed));
        let mats: &'static [_] =
            keep::<Vec<_>>(p.tf.iter().map(|&a| cgmath::Matrix4::from(a)).collect());
        let name = "cgmath";
        run(jobs, "q*q", name, &p.qq, |(a, b)| a * b);
        run(jobs, "rotate Cvec3", name, &p.qv, |(q, v)| {
            q.rotate_vector(v)
        });
        run(jobs, "inv", name, &p.q, |q| q.invert());
        run(jobs, "normalize", name, &p.q, |q| q.normalize());
        run(jobs, "slerp", name, &p.qqa, |(a, b, t)| a.slerp(b, t));
        run(jobs, "nlerp", name, &p.qqa, |(a, b, t)| a.nlerp(b, t));
        run(jobs, "RigTForm * RigTForm", name, &p.tf2, |(a, b)| {
            a.concat(&b)
        });
        run(jobs, "RigTForm inv", name, &p.tf, |a| a.inverse_transform());
        run(jobs, "RigTForm * point", name, &p.tfv, |(a, v)| {
            a.transform_point(cgmath::Point3::from_vec(v))
        });
        run(
            jobs,
            "Matrix4 from RigTForm",
            name,
            &p.tf,
            cgmath::Matrix4::from,
        );
        run(jobs, "normal_matrix", name, mats, |m| {
            let m3 = cgmath::Matrix3::from_cols(m.x.truncate(), m.y.truncate(), m.z.truncate());
            m3.invert().map(|m| m.transpose())
        });
    }
}

fn config() -> Criterion {
    // 19 operations, up to 6 libraries each, about 3 s per benchmark: the
    // median of 30 samples of 1,024 calls, for ratios on a shared machine.
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = quat_ops
}
criterion_main!(benches);
