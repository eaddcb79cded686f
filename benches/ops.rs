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

fn group<'a>(c: &'a mut Criterion, name: &str) -> Group<'a> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(N as u64));
    g
}

/// The shared inputs in one library's types: quaternions `Q`, vectors `V`
/// and rigid body transforms `T` (whatever the library has for them).
struct Prepared<Q, V, T> {
    q: Vec<Q>,
    qq: Vec<(Q, Q)>,
    qv: Vec<(Q, V)>,
    qa: Vec<(Q, f32)>,
    qqa: Vec<(Q, Q, f32)>,
    tf: Vec<T>,
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
            tf2: tf.iter().zip(&tf_b).map(|(&a, &b)| (a, b)).collect(),
            tfv: tf.iter().zip(&u).map(|(&a, &u)| (a, u)).collect(),
            tfa: (0..N).map(|i| (tf[i], tf_b[i], t[i])).collect(),
            q,
            tf,
        }
    }
}

/// The glam benchmarks, for both of its builds (same API, different crate).
/// A rigid body transform is what glam users write for one: a
/// (translation, rotation) pair.
macro_rules! glam_benches {
    ($c:ident, $inp:ident, $glam:ident, $name:expr, $quat:ident, $vec:ident) => {{
        let p = Prepared::new(&$inp, $quat, $vec, |t, r| ($vec(t), $quat(r)));
        let mats: Vec<_> =
            p.tf.iter()
                .map(|&(t, r)| $glam::Mat4::from_rotation_translation(r, t))
                .collect();
        let name = $name;
        run(&mut group($c, "q*q"), name, &p.qq, |(a, b)| a * b);
        run(&mut group($c, "rotate Cvec3"), name, &p.qv, |(q, v)| q * v);
        run(&mut group($c, "inv"), name, &p.q, |q| q.inverse());
        run(&mut group($c, "normalize"), name, &p.q, |q| q.normalize());
        run(&mut group($c, "slerp"), name, &p.qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group($c, "nlerp"), name, &p.qqa, |(a, b, t)| {
            a.lerp(b, t)
        });
        run(
            &mut group($c, "RigTForm * RigTForm"),
            name,
            &p.tf2,
            |((t1, r1), (t2, r2))| (t1 + r1 * t2, r1 * r2),
        );
        run(&mut group($c, "RigTForm inv"), name, &p.tf, |(t, r)| {
            let ri = r.inverse();
            (-(ri * t), ri)
        });
        run(
            &mut group($c, "RigTForm * point"),
            name,
            &p.tfv,
            |((t, r), v)| r * v + t,
        );
        run(
            &mut group($c, "RigTForm interpolate"),
            name,
            &p.tfa,
            |((t1, r1), (t2, r2), a)| (t1.lerp(t2, a), r1.slerp(r2, a)),
        );
        run(
            &mut group($c, "Matrix4 from RigTForm"),
            name,
            &p.tf,
            |(t, r)| $glam::Mat4::from_rotation_translation(r, t),
        );
        run(&mut group($c, "normal_matrix"), name, &mats, |m| {
            $glam::Mat3::from_mat4(m).inverse().transpose()
        });
    }};
}

fn quat_ops(c: &mut Criterion) {
    let inp = Inputs::new(N, 1);

    // rigtform, under the name of its backend.
    {
        let p = Prepared::new(&inp, rig_quat, rig_vec, rig_tform);
        let qc: Vec<_> =
            p.qv.iter()
                .map(|&(q, v)| (q, Cvec4::from_point(v)))
                .collect();
        let tfc: Vec<_> = p
            .tfv
            .iter()
            .map(|&(a, v)| (a, Cvec4::from_point(v)))
            .collect();
        let blend4: Vec<_> = (0..N)
            .map(|i| {
                let (a, b, t) = p.qqa[i];
                let (c, d, _) = p.qqa[(i + 1) % N];
                [(a, 1.0 - t), (b, t), (c, 0.5), (d, 0.25)]
            })
            .collect();
        let mats: Vec<_> = p.tf.iter().map(|&a| Matrix4::from(a)).collect();
        let name = if cfg!(feature = "fast-math") {
            "rigtform (fast-math)"
        } else {
            "rigtform"
        };

        run(&mut group(c, "q*q"), name, &p.qq, |(a, b)| a * b);
        run(&mut group(c, "q*q renormalized"), name, &p.qq, |(a, b)| {
            a.mul_renormalized(b)
        });
        run(&mut group(c, "rotate Cvec3"), name, &p.qv, |(q, v)| q * v);
        run(&mut group(c, "rotate Cvec4"), name, &qc, |(q, v)| q * v);
        run(&mut group(c, "inv"), name, &p.q, Quat::inv);
        run(&mut group(c, "normalize"), name, &p.q, Quat::normalize);
        run(&mut group(c, "pow"), name, &p.qa, |(q, t)| q.pow(t));
        run(&mut group(c, "slerp"), name, &p.qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group(c, "nlerp"), name, &p.qqa, |(a, b, t)| {
            a.nlerp(b, t)
        });
        run(&mut group(c, "blend of 4"), name, &blend4, |e| {
            Quat::blend(&e)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &p.tf2,
            |(a, b)| a * b,
        );
        run(&mut group(c, "RigTForm inv"), name, &p.tf, RigTForm::inv);
        run(&mut group(c, "RigTForm * point"), name, &tfc, |(a, p)| {
            a * p
        });
        run(
            &mut group(c, "RigTForm interpolate"),
            name,
            &p.tfa,
            |(a, b, t)| a.interpolate(b, t),
        );
        run(
            &mut group(c, "Matrix4 from RigTForm"),
            name,
            &p.tf,
            Matrix4::from,
        );
        run(
            &mut group(c, "normal_matrix"),
            name,
            &mats,
            Matrix4::normal_matrix,
        );
    }
    // With fast-math only rigtform is measured again (the peers do not change).
    if cfg!(feature = "fast-math") {
        return;
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
        let p = Prepared::new(&inp, na_quat, na_vec, na_iso);
        let mats: Vec<_> = p.tf.iter().map(|a| a.to_homogeneous()).collect();
        let name = "nalgebra";
        run(&mut group(c, "q*q"), name, &p.qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &p.qv, |(q, v)| q * v);
        run(&mut group(c, "inv"), name, &p.q, |q| q.inverse());
        run(&mut group(c, "normalize"), name, &p.q, |q| {
            q.into_inner().normalize()
        });
        run(&mut group(c, "pow"), name, &p.qa, |(q, t)| q.powf(t));
        run(&mut group(c, "slerp"), name, &p.qqa, |(a, b, t)| {
            a.slerp(&b, t)
        });
        run(&mut group(c, "nlerp"), name, &p.qqa, |(a, b, t)| {
            a.nlerp(&b, t)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &p.tf2,
            |(a, b)| a * b,
        );
        run(&mut group(c, "RigTForm inv"), name, &p.tf, |a| a.inverse());
        run(&mut group(c, "RigTForm * point"), name, &p.tfv, |(a, v)| {
            a * nalgebra::Point3::from(v)
        });
        run(
            &mut group(c, "RigTForm interpolate"),
            name,
            &p.tfa,
            |(a, b, t)| a.lerp_slerp(&b, t),
        );
        run(&mut group(c, "Matrix4 from RigTForm"), name, &p.tf, |a| {
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
        let p = Prepared::new(&inp, mm_quat, mm_vec, |_, _| ());
        let name = "micromath";
        run(&mut group(c, "q*q"), name, &p.qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &p.qv, |(q, v)| {
            q.rotate(v)
        });
        run(&mut group(c, "inv"), name, &p.q, |q| q.conj());
        run(&mut group(c, "normalize"), name, &p.q, |q| q.normalize());
    }

    // cgmath: Quaternion and Decomposed (no pow, no interpolation of transforms).
    {
        use cgmath::{EuclideanSpace, InnerSpace, Matrix, Rotation, SquareMatrix, Transform};
        let p = Prepared::new(&inp, cg_quat, cg_vec, cg_decomposed);
        let mats: Vec<_> = p.tf.iter().map(|&a| cgmath::Matrix4::from(a)).collect();
        let name = "cgmath";
        run(&mut group(c, "q*q"), name, &p.qq, |(a, b)| a * b);
        run(&mut group(c, "rotate Cvec3"), name, &p.qv, |(q, v)| {
            q.rotate_vector(v)
        });
        run(&mut group(c, "inv"), name, &p.q, |q| q.invert());
        run(&mut group(c, "normalize"), name, &p.q, |q| q.normalize());
        run(&mut group(c, "slerp"), name, &p.qqa, |(a, b, t)| {
            a.slerp(b, t)
        });
        run(&mut group(c, "nlerp"), name, &p.qqa, |(a, b, t)| {
            a.nlerp(b, t)
        });
        run(
            &mut group(c, "RigTForm * RigTForm"),
            name,
            &p.tf2,
            |(a, b)| a.concat(&b),
        );
        run(&mut group(c, "RigTForm inv"), name, &p.tf, |a| {
            a.inverse_transform()
        });
        run(&mut group(c, "RigTForm * point"), name, &p.tfv, |(a, v)| {
            a.transform_point(cgmath::Point3::from_vec(v))
        });
        run(
            &mut group(c, "Matrix4 from RigTForm"),
            name,
            &p.tf,
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
