//! Every public operation of rigtform, timed in the same run as the same
//! operation of glam (its default SIMD build and its `scalar-math` build),
//! nalgebra, micromath and cgmath, where each has it, on the same
//! pre-generated inputs.
//!
//! Each benchmark runs the operation over 1,024 inputs per iteration: the
//! input slice is hidden behind `black_box` (nothing is known about it at
//! compile time) and so is every result (nothing is vectorized across
//! inputs or left out); criterion reports the time per iteration, and the
//! README's table divides its median by 1,024.
//!
//! `cargo bench --bench ops` runs them all; `cargo bench --bench ops -- slerp`
//! only the slerp group.

#[path = "inputs.rs"]
mod inputs;

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion, Throughput};
use inputs::*;
use rigtform::{Cvec4, Matrix4, Quat, RigTForm};

/// Inputs per iteration.
const N: usize = 1024;

type Group<'a> = BenchmarkGroup<'a, criterion::measurement::WallTime>;

/// Times `f` over every element of `inputs` (converted beforehand, outside the timing).
fn run<I: Copy, O>(group: &mut Group<'_>, library: &str, inputs: &[I], f: impl Fn(I) -> O) {
    group.bench_function(library, |b| {
        b.iter(|| {
            for &x in black_box(inputs) {
                black_box(f(x));
            }
        })
    });
}

/// The inputs zipped into pairs of some library's types.
fn pairs<A, B>(
    a: &[[f32; 4]],
    b: &[[f32; 4]],
    fa: impl Fn([f32; 4]) -> A,
    fb: impl Fn([f32; 4]) -> B,
) -> Vec<(A, B)> {
    a.iter().zip(b).map(|(&x, &y)| (fa(x), fb(y))).collect()
}

fn group<'a>(c: &'a mut Criterion, name: &str) -> Group<'a> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(N as u64));
    g
}

/// The glam benchmarks, for both of its builds (same API, different crate).
macro_rules! glam_benches {
    ($c:ident, $inp:ident, $glam:ident, $name:literal, $quat:ident, $vec:ident) => {{
        let q: Vec<_> = $inp.a.iter().map(|&q| $quat(q)).collect();
        let qq = pairs(&$inp.a, &$inp.b, $quat, $quat);
        let qv: Vec<_> = $inp
            .a
            .iter()
            .zip(&$inp.v)
            .map(|(&q, &v)| ($quat(q), $vec(v)))
            .collect();
        let qqa: Vec<_> = qq
            .iter()
            .zip(&$inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        // A rigid body transform as glam users write it: a (translation, rotation) pair.
        let tf = |t: [f32; 3], r: [f32; 4]| ($vec(t), $quat(r));
        let tfs: Vec<_> = $inp
            .v
            .iter()
            .zip(&$inp.a)
            .map(|(&t, &r)| tf(t, r))
            .collect();
        let tf2: Vec<_> = tfs
            .iter()
            .zip($inp.u.iter().zip(&$inp.b))
            .map(|(&a, (&t, &r))| (a, tf(t, r)))
            .collect();
        let tfp: Vec<_> = tfs
            .iter()
            .zip(&$inp.u)
            .map(|(&a, &p)| (a, $vec(p)))
            .collect();
        let tfa: Vec<_> = tf2
            .iter()
            .zip(&$inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();

        run(&mut group($c, "q*q"), $name, &qq, |(a, b)| a * b);
        run(&mut group($c, "rotate Cvec3"), $name, &qv, |(q, v)| q * v);
        run(&mut group($c, "inv"), $name, &q, |q| q.inverse());
        run(&mut group($c, "normalize"), $name, &q, |q| q.normalize());
        run(&mut group($c, "slerp"), $name, &qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group($c, "nlerp"), $name, &qqa, |(a, b, t)| {
            a.lerp(b, t)
        });
        run(
            &mut group($c, "RigTForm * RigTForm"),
            $name,
            &tf2,
            |((t1, r1), (t2, r2))| (t1 + r1 * t2, r1 * r2),
        );
        run(&mut group($c, "RigTForm inv"), $name, &tfs, |(t, r)| {
            let ri = r.inverse();
            (-(ri * t), ri)
        });
        run(
            &mut group($c, "RigTForm * point"),
            $name,
            &tfp,
            |((t, r), p)| r * p + t,
        );
        run(
            &mut group($c, "RigTForm interpolate"),
            $name,
            &tfa,
            |((t1, r1), (t2, r2), a)| (t1.lerp(t2, a), r1.slerp(r2, a)),
        );
        run(
            &mut group($c, "Matrix4 from RigTForm"),
            $name,
            &tfs,
            |(t, r)| $glam::Mat4::from_rotation_translation(r, t),
        );
        let mats: Vec<_> = tfs
            .iter()
            .map(|&(t, r)| $glam::Mat4::from_rotation_translation(r, t))
            .collect();
        run(&mut group($c, "normal_matrix"), $name, &mats, |m| {
            $glam::Mat3::from_mat4(m).inverse().transpose()
        });
    }};
}

fn quat_ops(c: &mut Criterion) {
    let inp = Inputs::new(N, 1);

    // rigtform
    {
        let q: Vec<_> = inp.a.iter().map(|&q| rig_quat(q)).collect();
        let qq = pairs(&inp.a, &inp.b, rig_quat, rig_quat);
        let qv: Vec<_> = inp
            .a
            .iter()
            .zip(&inp.v)
            .map(|(&q, &v)| (rig_quat(q), rig_vec(v)))
            .collect();
        let qc: Vec<_> = qv.iter().map(|&(q, v)| (q, Cvec4::from_point(v))).collect();
        let qa: Vec<_> = q.iter().zip(&inp.alpha).map(|(&q, &t)| (q, t)).collect();
        let qqa: Vec<_> = qq
            .iter()
            .zip(&inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        let blend4: Vec<_> = (0..N)
            .map(|i| {
                let t = inp.alpha[i];
                [
                    (q[i], 1.0 - t),
                    (rig_quat(inp.b[i]), t),
                    (q[(i + 1) % N], 0.5),
                    (rig_quat(inp.b[(i + 1) % N]), 0.25),
                ]
            })
            .collect();
        let tfs: Vec<_> = inp
            .v
            .iter()
            .zip(&inp.a)
            .map(|(&t, &r)| rig_tform(t, r))
            .collect();
        let tf2: Vec<_> = tfs
            .iter()
            .zip(inp.u.iter().zip(&inp.b))
            .map(|(&a, (&t, &r))| (a, rig_tform(t, r)))
            .collect();
        let tfp: Vec<_> = tfs
            .iter()
            .zip(&inp.u)
            .map(|(&a, &p)| (a, Cvec4::from_point(rig_vec(p))))
            .collect();
        let tfa: Vec<_> = tf2
            .iter()
            .zip(&inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        let mats: Vec<_> = tfs.iter().map(|&a| Matrix4::from(a)).collect();
        let name = if cfg!(feature = "fast-math") {
            "rigtform (fast-math)"
        } else {
            "rigtform"
        };

        run(&mut group(c, "q*q"), name, &qq, |(a, b)| a * b);
        run(&mut group(c, "q*q renormalized"), name, &qq, |(a, b)| {
            a.mul_renormalized(b)
        });
        run(&mut group(c, "rotate Cvec3"), name, &qv, |(q, v)| q * v);
        run(&mut group(c, "rotate Cvec4"), name, &qc, |(q, v)| q * v);
        run(&mut group(c, "inv"), name, &q, Quat::inv);
        run(&mut group(c, "normalize"), name, &q, Quat::normalize);
        run(&mut group(c, "pow"), name, &qa, |(q, t)| q.pow(t));
        run(&mut group(c, "slerp"), name, &qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group(c, "nlerp"), name, &qqa, |(a, b, t)| {
            a.nlerp(b, t)
        });
        run(&mut group(c, "blend of 4"), name, &blend4, |e| {
            Quat::blend(&e)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &tf2,
            |(a, b)| a * b,
        );
        run(&mut group(c, "RigTForm inv"), name, &tfs, RigTForm::inv);
        run(&mut group(c, "RigTForm * point"), name, &tfp, |(a, p)| {
            a * p
        });
        run(
            &mut group(c, "RigTForm interpolate"),
            name,
            &tfa,
            |(a, b, t)| a.interpolate(b, t),
        );
        run(
            &mut group(c, "Matrix4 from RigTForm"),
            name,
            &tfs,
            Matrix4::from,
        );
        run(
            &mut group(c, "normal_matrix"),
            name,
            &mats,
            Matrix4::normal_matrix,
        );
    }

    glam_benches!(c, inp, glam, "glam (SIMD)", glam_quat, glam_vec);
    glam_benches!(
        c,
        inp,
        glam_scalar,
        "glam (scalar-math)",
        glam_scalar_quat,
        glam_scalar_vec
    );

    // nalgebra: UnitQuaternion and Isometry3, f32.
    {
        let q: Vec<_> = inp.a.iter().map(|&q| na_quat(q)).collect();
        let qq = pairs(&inp.a, &inp.b, na_quat, na_quat);
        let qv: Vec<_> = inp
            .a
            .iter()
            .zip(&inp.v)
            .map(|(&q, &v)| (na_quat(q), na_vec(v)))
            .collect();
        let qa: Vec<_> = q.iter().zip(&inp.alpha).map(|(&q, &t)| (q, t)).collect();
        let qqa: Vec<_> = qq
            .iter()
            .zip(&inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        let tfs: Vec<_> = inp
            .v
            .iter()
            .zip(&inp.a)
            .map(|(&t, &r)| na_iso(t, r))
            .collect();
        let tf2: Vec<_> = tfs
            .iter()
            .zip(inp.u.iter().zip(&inp.b))
            .map(|(&a, (&t, &r))| (a, na_iso(t, r)))
            .collect();
        let tfp: Vec<_> = tfs
            .iter()
            .zip(&inp.u)
            .map(|(&a, &p)| (a, nalgebra::Point3::from(na_vec(p))))
            .collect();
        let tfa: Vec<_> = tf2
            .iter()
            .zip(&inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        let mats: Vec<_> = tfs.iter().map(|a| a.to_homogeneous()).collect();
        let name = "nalgebra";

        run(&mut group(c, "q*q"), name, &qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &qv, |(q, v)| q * v);
        run(&mut group(c, "inv"), name, &q, |q| q.inverse());
        run(&mut group(c, "normalize"), name, &q, |q| {
            q.into_inner().normalize()
        });
        run(&mut group(c, "pow"), name, &qa, |(q, t)| q.powf(t));
        run(&mut group(c, "slerp"), name, &qqa, |(a, b, t)| {
            a.slerp(&b, t)
        });
        run(&mut group(c, "nlerp"), name, &qqa, |(a, b, t)| {
            a.nlerp(&b, t)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &tf2,
            |(a, b)| a * b,
        );
        run(&mut group(c, "RigTForm inv"), name, &tfs, |a| a.inverse());
        run(&mut group(c, "RigTForm * point"), name, &tfp, |(a, p)| {
            a * p
        });
        run(
            &mut group(c, "RigTForm interpolate"),
            name,
            &tfa,
            |(a, b, t)| a.lerp_slerp(&b, t),
        );
        run(&mut group(c, "Matrix4 from RigTForm"), name, &tfs, |a| {
            a.to_homogeneous()
        });
        run(&mut group(c, "normal_matrix"), name, &mats, |m| {
            m.fixed_view::<3, 3>(0, 0)
                .into_owned()
                .try_inverse()
                .map(|m| m.transpose())
        });
    }

    // micromath: Quaternion (no slerp, pow or transforms).
    {
        let q: Vec<_> = inp.a.iter().map(|&q| mm_quat(q)).collect();
        let qq = pairs(&inp.a, &inp.b, mm_quat, mm_quat);
        let qv: Vec<_> = inp
            .a
            .iter()
            .zip(&inp.v)
            .map(|(&q, &v)| (mm_quat(q), mm_vec(v)))
            .collect();
        let name = "micromath";

        run(&mut group(c, "q*q"), name, &qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &qv, |(q, v)| {
            q.rotate(v)
        });
        run(&mut group(c, "inv"), name, &q, |q| q.conj());
        run(&mut group(c, "normalize"), name, &q, |q| q.normalize());
    }

    // cgmath: Quaternion and Decomposed (no pow, no interpolation of transforms).
    {
        use cgmath::{EuclideanSpace, InnerSpace, Matrix, Rotation, SquareMatrix, Transform};
        let q: Vec<_> = inp.a.iter().map(|&q| cg_quat(q)).collect();
        let qq = pairs(&inp.a, &inp.b, cg_quat, cg_quat);
        let qv: Vec<_> = inp
            .a
            .iter()
            .zip(&inp.v)
            .map(|(&q, &v)| (cg_quat(q), cg_vec(v)))
            .collect();
        let qqa: Vec<_> = qq
            .iter()
            .zip(&inp.alpha)
            .map(|(&(a, b), &t)| (a, b, t))
            .collect();
        let tfs: Vec<_> = inp
            .v
            .iter()
            .zip(&inp.a)
            .map(|(&t, &r)| cg_decomposed(t, r))
            .collect();
        let tf2: Vec<_> = tfs
            .iter()
            .zip(inp.u.iter().zip(&inp.b))
            .map(|(&a, (&t, &r))| (a, cg_decomposed(t, r)))
            .collect();
        let tfp: Vec<_> = tfs
            .iter()
            .zip(&inp.u)
            .map(|(&a, &p)| (a, cgmath::Point3::from_vec(cg_vec(p))))
            .collect();
        let mats: Vec<_> = tfs.iter().map(|&a| cgmath::Matrix4::from(a)).collect();
        let name = "cgmath";

        run(&mut group(c, "q*q"), name, &qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &qv, |(q, v)| {
            q.rotate_vector(v)
        });
        run(&mut group(c, "inv"), name, &q, |q| q.invert());
        run(&mut group(c, "normalize"), name, &q, |q| q.normalize());
        run(&mut group(c, "slerp"), name, &qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group(c, "nlerp"), name, &qqa, |(a, b, t)| {
            a.nlerp(b, t)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &tf2,
            |(a, b)| a.concat(&b),
        );
        run(&mut group(c, "RigTForm inv"), name, &tfs, |a| {
            a.inverse_transform()
        });
        run(&mut group(c, "RigTForm * point"), name, &tfp, |(a, p)| {
            a.transform_point(p)
        });
        run(
            &mut group(c, "Matrix4 from RigTForm"),
            name,
            &tfs,
            cgmath::Matrix4::from,
        );
        run(&mut group(c, "normal_matrix"), name, &mats, |m| {
            let m3 = cgmath::Matrix3::from_cols(m.x.truncate(), m.y.truncate(), m.z.truncate());
            m3.invert().map(|m| m.transpose())
        });
    }
}

fn config() -> Criterion {
    // Short runs: 20 operations times 6 libraries. Medians over 30 samples
    // of 1,024 calls each are stable enough for ratios on a shared machine.
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(1))
}

criterion_group! {
    name = benches;
    config = config();
    targets = quat_ops
}
criterion_main!(benches);
