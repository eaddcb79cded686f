//! The accuracy report: rigtform and its peers (glam, nalgebra, cgmath,
//! micromath) against an f64 reference, on random unit inputs and on the
//! edge classes of slerp, with NaN and panic counts per class, and the norm
//! drift of a million chained products.
//!
//! ```text
//! cargo run --release -p rigtform-compare --bin accuracy                      # 200,000 draws per class
//! cargo run --release -p rigtform-compare --bin accuracy -- 10000             # fewer (CI)
//! ```
//!
//! Errors are rotation angles in radians between the computed rotation and
//! the exact one (the notes' formulas evaluated in f64 on the same f32
//! inputs), compared as rotations (up to sign and scale). Panics are caught
//! with `catch_unwind` and counted (nalgebra's `slerp` panics on inputs
//! about 180 degrees apart, as its docs say). Prints Markdown tables.

use std::panic::{catch_unwind, AssertUnwindSafe};

use nalgebra as na;
use rigtform_compare::*;
use rigtform_testkit::{pow64, slerp64, Draws};

/// A slerp of some library, on arrays `[w, x, y, z]`.
type Slerp = fn([f32; 4], [f32; 4], f32) -> [f32; 4];

fn rigtform_slerp(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    rig_quat(a).slerp(rig_quat(b), t).to_wxyz()
}
fn glam_slerp(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    let q = glam_quat(a).slerp(glam_quat(b), t);
    [q.w, q.x, q.y, q.z]
}
fn nalgebra_slerp(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    let q = na_quat(a).slerp(&na_quat(b), t);
    [q.w, q.i, q.j, q.k]
}
fn cgmath_slerp(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    let q = cg_quat(a).slerp(cg_quat(b), t);
    [q.s, q.v.x, q.v.y, q.v.z]
}

/// The libraries compared, with the name the tables use.
fn slerps(rigtform_only: bool) -> Vec<(String, Slerp)> {
    let mut v: Vec<(String, Slerp)> = vec![(rigtform_name(), rigtform_slerp)];
    if !rigtform_only {
        v.push(("glam".into(), glam_slerp));
        v.push(("nalgebra".into(), nalgebra_slerp));
        v.push(("cgmath".into(), cgmath_slerp));
    }
    v
}

fn rigtform_name() -> String {
    "rigtform".into()
}

fn to64(q: [f32; 4]) -> na::Quaternion<f64> {
    rigtform_testkit::to_f64(rig_quat(q))
}

fn to32(q: na::Quaternion<f64>) -> [f32; 4] {
    rigtform_testkit::to_f32(q).to_wxyz()
}

/// The angle between two rotations given as f32 and f64 quaternions.
fn angle_error(got: [f32; 4], want: na::Quaternion<f64>) -> f64 {
    rigtform_testkit::angle_error(rig_quat(got), want)
}

/// Errors of one library on one class: every error, NaN and panic counts.
#[derive(Default)]
struct Tally {
    errors: Vec<f64>,
    nans: usize,
    panics: usize,
}

impl Tally {
    fn see(&mut self, result: std::thread::Result<[f32; 4]>, error: impl FnOnce([f32; 4]) -> f64) {
        match result {
            Err(_) => self.panics += 1,
            Ok(q) if q.iter().any(|c| c.is_nan()) => self.nans += 1,
            Ok(q) => self.errors.push(error(q)),
        }
    }

    /// One table cell: `max / p99`, and the NaN and panic counts if any.
    fn cell(&mut self) -> String {
        self.errors.sort_by(f64::total_cmp);
        let n = self.errors.len();
        let mut cell = if n == 0 {
            "-".to_string()
        } else {
            format!(
                "{:.2e} / {:.2e}",
                self.errors[n - 1],
                self.errors[(n * 99 / 100).min(n - 1)]
            )
        };
        if self.nans > 0 {
            cell += &format!(", {} NaN", self.nans);
        }
        if self.panics > 0 {
            cell += &format!(", {} panics", self.panics);
        }
        cell
    }
}

/// How a slerp class draws its two inputs and its parameter.
#[derive(Clone, Copy)]
enum Class {
    Random,
    Identical,
    Apart(f64),
    Antipodal,
    /// The rotation between the two is a half turn: `w = 0` in the
    /// transition quaternion, both ways are equally short.
    HalfTurn,
    /// Random pairs at a fixed parameter outside [0, 1].
    Extrapolate(f32),
    /// Random pairs with norms 1 +- 1e-3.
    NearUnit,
}

const CLASSES: [(&str, Class); 11] = [
    ("random pairs, t in [0, 1]", Class::Random),
    ("identical", Class::Identical),
    ("1e-3 rad apart", Class::Apart(1e-3)),
    ("1e-5 rad apart", Class::Apart(1e-5)),
    ("1e-7 rad apart", Class::Apart(1e-7)),
    ("antipodal (q, -q)", Class::Antipodal),
    (
        "pi - 1e-4 apart",
        Class::Apart(core::f64::consts::PI - 1e-4),
    ),
    ("half turn apart (w = 0)", Class::HalfTurn),
    ("t = -0.5", Class::Extrapolate(-0.5)),
    ("t = 1.5", Class::Extrapolate(1.5)),
    ("norm 1 +- 1e-3", Class::NearUnit),
];

/// One draw of a class: the two inputs and the parameter.
fn draw(class: Class, d: &mut Draws) -> ([f32; 4], [f32; 4], f32) {
    let a64 = d.unit_quat64();
    let t = match class {
        Class::Extrapolate(t) => t,
        _ => d.uniform(0.0, 1.0) as f32,
    };
    let b64 = match class {
        Class::Random | Class::Extrapolate(_) | Class::NearUnit => d.unit_quat64(),
        Class::Identical => a64,
        Class::Antipodal => -a64,
        Class::Apart(angle) => {
            let axis = na::Unit::new_normalize(d.unit_vec64());
            *na::UnitQuaternion::from_axis_angle(&axis, angle).as_ref() * a64
        }
        Class::HalfTurn => {
            let axis = d.unit_vec64();
            na::Quaternion::from_parts(0.0, axis) * a64
        }
    };
    let (mut a, mut b) = (to32(a64), to32(b64));
    if let Class::NearUnit = class {
        let (sa, sb) = (
            d.uniform(0.999, 1.001) as f32,
            d.uniform(0.999, 1.001) as f32,
        );
        a = a.map(|c| c * sa);
        b = b.map(|c| c * sb);
    }
    (a, b, t)
}

fn slerp_table(draws: usize, rigtform_only: bool) {
    let libraries = slerps(rigtform_only);
    println!(
        "slerp, angle error in rad (max / 99th percentile) against the notes' formula in f64:\n"
    );
    let names: Vec<&str> = libraries.iter().map(|(n, _)| n.as_str()).collect();
    println!("| class | {} |", names.join(" | "));
    println!("| --- |{}", " --- |".repeat(names.len()));
    for (seed, (name, class)) in CLASSES.iter().enumerate() {
        let mut tallies: Vec<Tally> = libraries.iter().map(|_| Tally::default()).collect();
        let mut d = Draws::new(100 + seed as u64);
        for _ in 0..draws {
            let (a, b, t) = draw(*class, &mut d);
            let want = slerp64(to64(a), to64(b), t as f64);
            // For a half turn either way is right: the error is the smaller.
            let other_way = {
                let (q0, q1) = (to64(a).normalize(), to64(b).normalize());
                let d = q1 * q0.conjugate();
                pow64(if d.w < 0.0 { d } else { -d }, t as f64) * q0
            };
            for ((_, f), tally) in libraries.iter().zip(&mut tallies) {
                let result = catch_unwind(AssertUnwindSafe(|| f(a, b, t)));
                tally.see(result, |q| match class {
                    Class::HalfTurn => angle_error(q, want).min(angle_error(q, other_way)),
                    _ => angle_error(q, want),
                });
            }
        }
        let cells: Vec<String> = tallies.iter_mut().map(Tally::cell).collect();
        println!("| {name} | {} |", cells.join(" | "));
    }
    println!();
}

/// The four measurements of the other operations: each draws its inputs,
/// calls one library's operation (given as a plain function on arrays) and
/// tallies the error.
fn product(d: &mut Draws, t: &mut Tally, f: fn([f32; 4], [f32; 4]) -> [f32; 4]) {
    let (a, b) = (d.unit_quat().into_array(), d.unit_quat().into_array());
    let want = to64(a) * to64(b);
    t.see(catch_unwind(|| f(a, b)), |q| angle_error(q, want));
}
fn power(d: &mut Draws, t: &mut Tally, f: fn([f32; 4], f32) -> [f32; 4]) {
    // For w < 0 the notes' pow turns the long way and nalgebra's the short
    // way: both are powers, so only w >= 0 is compared.
    let q = d.unit_quat().cn().into_array();
    let alpha = d.uniform(-2.0, 3.0);
    let want = pow64(to64(q), alpha);
    t.see(catch_unwind(|| f(q, alpha as f32)), |q| {
        angle_error(q, want)
    });
}
fn normalized(d: &mut Draws, t: &mut Tally, f: fn([f32; 4]) -> [f32; 4]) {
    let s = d.uniform(0.5, 2.0) as f32;
    let q = d.unit_quat().into_array().map(|c| c * s);
    t.see(catch_unwind(|| f(q)), |q| (to64(q).norm() - 1.0).abs());
}
fn rotated(d: &mut Draws, t: &mut Tally, f: fn([f32; 4], [f32; 3]) -> [f32; 3]) {
    let (q, v) = (d.unit_quat().into_array(), d.unit_vec64());
    let want = na::UnitQuaternion::new_normalize(to64(q)) * v;
    let got = catch_unwind(|| {
        let [x, y, z] = f(q, [v.x as f32, v.y as f32, v.z as f32]);
        [0.0, x, y, z]
    });
    t.see(got, |g| {
        (na::Vector3::new(g[1] as f64, g[2] as f64, g[3] as f64) - want).norm()
    });
}

/// How one operation of one library is measured.
enum Measure {
    Product(fn([f32; 4], [f32; 4]) -> [f32; 4]),
    Power(fn([f32; 4], f32) -> [f32; 4]),
    Normalize(fn([f32; 4]) -> [f32; 4]),
    Rotate(fn([f32; 4], [f32; 3]) -> [f32; 3]),
}

impl Measure {
    fn name(&self) -> &'static str {
        match self {
            Measure::Product(_) => "q * q (rad)",
            Measure::Power(_) => "pow of w >= 0, t in [-2, 3] (rad)",
            Measure::Normalize(_) => "normalize of norm 0.5 to 2: \\|norm - 1\\|",
            Measure::Rotate(_) => "rotate, error / \\|v\\|",
        }
    }
    fn once(&self, d: &mut Draws, t: &mut Tally) {
        match *self {
            Measure::Product(f) => product(d, t, f),
            Measure::Power(f) => power(d, t, f),
            Measure::Normalize(f) => normalized(d, t, f),
            Measure::Rotate(f) => rotated(d, t, f),
        }
    }
}

fn glam4(q: glam::Quat) -> [f32; 4] {
    [q.w, q.x, q.y, q.z]
}
fn na4(q: na::Quaternion<f32>) -> [f32; 4] {
    [q.w, q.i, q.j, q.k]
}

/// `q * q`, rotate, normalize and pow on random unit inputs.
fn other_ops_table(draws: usize, rigtform_only: bool) {
    println!("Other operations on random unit inputs (max / 99th percentile):\n");
    println!("| operation | library | error |");
    println!("| --- | --- | --- |");
    let mut ops: Vec<(&str, Measure)> = vec![
        (
            "rigtform",
            Measure::Product(|a, b| (rig_quat(a) * rig_quat(b)).into_array()),
        ),
        (
            "rigtform",
            Measure::Power(|q, t| rig_quat(q).pow(t).into_array()),
        ),
        (
            "rigtform",
            Measure::Normalize(|q| rig_quat(q).normalize().into_array()),
        ),
        (
            "rigtform",
            Measure::Rotate(|q, v| {
                let r = rig_quat(q) * rig_vec(v);
                [r.x, r.y, r.z]
            }),
        ),
    ];
    if !rigtform_only {
        ops.extend([
            (
                "glam",
                Measure::Product(|a, b| glam4(glam_quat(a) * glam_quat(b))),
            ),
            (
                "nalgebra",
                Measure::Product(|a, b| na4(*(na_quat(a) * na_quat(b)).as_ref())),
            ),
            (
                "micromath",
                Measure::Product(|a, b| (mm_quat(a) * mm_quat(b)).to_array()),
            ),
            (
                "nalgebra",
                Measure::Power(|q, t| na4(*na_quat(q).powf(t).as_ref())),
            ),
            (
                "glam",
                Measure::Normalize(|q| glam4(glam_quat(q).normalize())),
            ),
            (
                "nalgebra",
                Measure::Normalize(
                    |q| na4(na::Quaternion::new(q[0], q[1], q[2], q[3]).normalize()),
                ),
            ),
            (
                "micromath",
                Measure::Normalize(|q| mm_quat(q).normalize().to_array()),
            ),
            (
                "glam",
                Measure::Rotate(|q, v| (glam_quat(q) * glam_vec(v)).to_array()),
            ),
            (
                "nalgebra",
                Measure::Rotate(|q, v| {
                    let r = na_quat(q) * na_vec(v);
                    [r.x, r.y, r.z]
                }),
            ),
            (
                "micromath",
                Measure::Rotate(|q, v| {
                    let r = mm_quat(q).rotate(mm_vec(v));
                    [r.x, r.y, r.z]
                }),
            ),
        ]);
    }
    ops.sort_by_key(|(_, m)| m.name());
    for (library, measure) in ops {
        let (mut d, mut tally) = (Draws::new(7), Tally::default());
        for _ in 0..draws {
            measure.once(&mut d, &mut tally);
        }
        let library = if library == "rigtform" {
            rigtform_name()
        } else {
            library.into()
        };
        println!("| {} | {library} | {} |", measure.name(), tally.cell());
    }
    println!();
}

/// The norm drift of a long chain of products of small random rotations
/// (a gyro integrator's), for each library's plain product and for
/// rigtform's renormalizing one.
fn drift_table(products: usize, rigtform_only: bool) {
    let mut d = Draws::new(30);
    let steps: Vec<[f32; 4]> = (0..1000)
        .map(|_| {
            let axis = na::Unit::new_normalize(d.unit_vec64());
            to32(*na::UnitQuaternion::from_axis_angle(&axis, d.uniform(0.0, 0.1)).as_ref())
        })
        .collect();
    type Chain = fn(&[[f32; 4]], usize) -> [f32; 4];
    let mut chains: Vec<(String, Chain)> = vec![
        (format!("{} `a * b`", rigtform_name()), |s, n| {
            (0..n)
                .fold(rigtform::Quat::IDENTITY, |q, i| {
                    q * rig_quat(s[i % s.len()])
                })
                .into_array()
        }),
        (
            format!("{} `a.mul_renormalized(b)`", rigtform_name()),
            |s, n| {
                (0..n)
                    .fold(rigtform::Quat::IDENTITY, |q, i| {
                        q.mul_renormalized(rig_quat(s[i % s.len()]))
                    })
                    .into_array()
            },
        ),
    ];
    if !rigtform_only {
        chains.push(("glam".into(), |s, n| {
            let q = (0..n).fold(glam::Quat::IDENTITY, |q, i| q * glam_quat(s[i % s.len()]));
            [q.w, q.x, q.y, q.z]
        }));
        chains.push(("nalgebra".into(), |s, n| {
            let q = (0..n).fold(na::UnitQuaternion::identity(), |q, i| {
                q * na_quat(s[i % s.len()])
            });
            [q.w, q.i, q.j, q.k]
        }));
        chains.push(("cgmath".into(), |s, n| {
            let q = (0..n).fold(cg_quat([1.0, 0.0, 0.0, 0.0]), |q, i| {
                q * cg_quat(s[i % s.len()])
            });
            [q.s, q.v.x, q.v.y, q.v.z]
        }));
        chains.push(("micromath".into(), |s, n| {
            let q = (0..n).fold(micromath::Quaternion::IDENTITY, |q, i| {
                q * mm_quat(s[i % s.len()])
            });
            q.to_array()
        }));
    }
    println!("Norm drift, \\|norm - 1\\| after {products} chained products of small rotations:\n");
    println!("| library | \\|norm - 1\\| |");
    println!("| --- | --- |");
    for (name, chain) in chains {
        let q = chain(&steps, products);
        println!("| {name} | {:.2e} |", (to64(q).norm() - 1.0).abs());
    }
    println!();
}

/// `[w, x, y, z]` of a rigtform quaternion (and of a drawn one).
trait IntoArray {
    fn into_array(self) -> [f32; 4];
}
impl IntoArray for rigtform::Quat {
    fn into_array(self) -> [f32; 4] {
        self.to_wxyz()
    }
}

fn main() {
    let mut draws = 200_000;
    let mut rigtform_only = false;
    for arg in std::env::args().skip(1) {
        match arg.as_str() {
            "--rigtform-only" => rigtform_only = true,
            n => match n.replace('_', "").parse() {
                Ok(n) if n > 0 => draws = n,
                _ => {
                    eprintln!(
                        "error: unexpected argument {n:?}\nusage: accuracy [DRAWS] [--rigtform-only]"
                    );
                    std::process::exit(2);
                }
            },
        }
    }
    // Panics are counted, not printed.
    std::panic::set_hook(Box::new(|_| {}));
    println!("<!-- cargo run --release -p rigtform-compare --bin accuracy -- {draws} -->\n");
    println!("{draws} draws per class.\n");
    slerp_table(draws, rigtform_only);
    other_ops_table(draws, rigtform_only);
    drift_table(1_000_000, rigtform_only);
}
