//! The Gappa models of `proofs/gappa/` and the library compute the same
//! thing: this evaluates each model's rounded definitions (its `x rnd= e;`
//! and `x = rnd(e);` lines) exactly as written, every operation rounded to
//! the model's format (f32 or f64, to nearest even), and compares the bits
//! with the library's function on random and edge inputs. A proof is about
//! the model; this is what ties it to the code. Changing the order of
//! evaluation in either (a sum regrouped, a product's factors reassociated)
//! changes the bits on some of these inputs and fails the test until the
//! other follows.
//!
//! The evaluator reads the subset of Gappa the models use: `@rnd =
//! float<ieee_32, ne>;` (or `ieee_64`), inputs `a = rnd(A);` (the name in
//! capitals a free real), rounded definitions, exact definitions (ignored,
//! they are the proofs' reference), numbers in decimal, `NbE` (N 2^E) and
//! hexadecimal, `+ - * /`, unary minus and `sqrt`. Everything after the
//! first `{` (the goals and the hints) is the proofs' business. An f32
//! operation is evaluated in f64 and rounded to f32, which is the correctly
//! rounded f32 result for these operations (53 >= 2 * 24 + 2).

use std::collections::BTreeMap;

use rigtform::kani_kernels;
use rigtform::{Cvec3, Quat, RigTForm};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::edge::EDGE_F32;

/// Draws per model.
const DRAWS: usize = 200_000;

#[derive(Clone, Debug, PartialEq)]
enum Expr {
    Num(f64),
    Var(String),
    Neg(Box<Expr>),
    Bin(char, Box<Expr>, Box<Expr>),
    Sqrt(Box<Expr>),
}

/// A model's rounded computation: its format, its inputs, and its rounded
/// definitions in order.
#[derive(Debug)]
struct Model {
    name: &'static str,
    inputs: Vec<String>,
    defs: Vec<Def>,
}

/// A rounded definition: `name fmt= expr` rounds every operation to the
/// format (`every_op`), `name = fmt(expr)` rounds the exact value of one
/// operation once.
#[derive(Debug)]
struct Def {
    name: String,
    expr: Expr,
    single: bool,
    every_op: bool,
}

/// Counts the operations of an expression (negation is exact, not one).
fn operations(e: &Expr) -> usize {
    match e {
        Expr::Num(_) | Expr::Var(_) => 0,
        Expr::Neg(a) => operations(a),
        Expr::Sqrt(a) => 1 + operations(a),
        Expr::Bin(_, a, b) => 1 + operations(a) + operations(b),
    }
}

fn tokens(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let c: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        if ch.is_whitespace() {
            i += 1;
        } else if ch.is_ascii_digit()
            || (ch == '.' && c.get(i + 1).is_some_and(|d| d.is_ascii_digit()))
        {
            let start = i;
            let hex = ch == '0' && matches!(c.get(i + 1), Some('x') | Some('X'));
            if hex {
                i += 2;
            }
            while i < c.len() {
                let d = c[i];
                let exponent_sign = (d == '-' || d == '+')
                    && matches!(c[i - 1], 'e' | 'E' | 'b' | 'p' | 'P')
                    && !(hex && matches!(c[i - 1], 'e' | 'E' | 'b'));
                if d.is_ascii_alphanumeric() || d == '.' || exponent_sign {
                    i += 1;
                } else {
                    break;
                }
            }
            out.push(c[start..i].iter().collect());
        } else if ch.is_ascii_alphabetic() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_ascii_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(c[start..i].iter().collect());
        } else {
            out.push(ch.to_string());
            i += 1;
        }
    }
    out
}

/// A number in one of Gappa's notations.
fn number(t: &str) -> f64 {
    if let Some(hex) = t.strip_prefix("0x") {
        let (mantissa, exponent) = hex.split_once(['p', 'P']).unwrap_or((hex, "0"));
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits = format!("{int}{frac}");
        let m = u64::from_str_radix(&digits, 16).unwrap_or_else(|e| panic!("{t}: {e}"));
        let e: i32 = exponent.parse().unwrap_or_else(|e| panic!("{t}: {e}"));
        // m has at most 53 significant bits in the models; scaling by a
        // power of two is exact.
        assert!(m < 1 << 53, "{t}: more than 53 bits");
        return m as f64 * 2f64.powi(e - 4 * frac.len() as i32);
    }
    if let Some((m, e)) = t.split_once('b') {
        let m: i64 = m.parse().unwrap_or_else(|e| panic!("{t}: {e}"));
        let e: i32 = e.parse().unwrap_or_else(|e| panic!("{t}: {e}"));
        return m as f64 * 2f64.powi(e);
    }
    t.parse().unwrap_or_else(|e| panic!("{t}: {e}"))
}

struct Parser {
    t: Vec<String>,
    i: usize,
}

impl Parser {
    fn peek(&self) -> Option<&str> {
        self.t.get(self.i).map(String::as_str)
    }
    fn next(&mut self) -> String {
        let t = self.t.get(self.i).cloned().unwrap_or_default();
        self.i += 1;
        t
    }
    fn expect(&mut self, s: &str) {
        let t = self.next();
        assert_eq!(t, s, "expected {s:?} in {:?}", self.t);
    }
    fn expr(&mut self) -> Expr {
        let mut e = self.term();
        while let Some(op @ ("+" | "-")) = self.peek() {
            let op = op.chars().next().unwrap_or('+');
            self.i += 1;
            e = Expr::Bin(op, Box::new(e), Box::new(self.term()));
        }
        e
    }
    fn term(&mut self) -> Expr {
        let mut e = self.unary();
        while let Some(op @ ("*" | "/")) = self.peek() {
            let op = op.chars().next().unwrap_or('*');
            self.i += 1;
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary()));
        }
        e
    }
    fn unary(&mut self) -> Expr {
        if self.peek() == Some("-") {
            self.i += 1;
            return Expr::Neg(Box::new(self.unary()));
        }
        self.primary()
    }
    fn primary(&mut self) -> Expr {
        let t = self.next();
        match t.as_str() {
            "(" => {
                let e = self.expr();
                self.expect(")");
                e
            }
            "sqrt" => {
                self.expect("(");
                let e = self.expr();
                self.expect(")");
                Expr::Sqrt(Box::new(e))
            }
            _ if t.starts_with(|c: char| c.is_ascii_digit() || c == '.') => Expr::Num(number(&t)),
            _ if t.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') => Expr::Var(t),
            _ => panic!("unexpected {t:?} in {:?}", self.t),
        }
    }
}

fn parse(name: &'static str, text: &str) -> Model {
    let body: String = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let body = body.split('{').next().unwrap_or("");
    let mut model = Model {
        name,
        inputs: Vec::new(),
        defs: Vec::new(),
    };
    // Format name -> whether it is f32 (else f64).
    let mut formats: BTreeMap<String, bool> = BTreeMap::new();
    let expression = |s: &str| {
        let mut p = Parser { t: tokens(s), i: 0 };
        let e = p.expr();
        assert_eq!(p.i, p.t.len(), "{name}: trailing tokens in {s}");
        e
    };
    for statement in body.split(';').map(str::trim).filter(|s| !s.is_empty()) {
        if let Some(rest) = statement.strip_prefix('@') {
            let (format, kind) = rest
                .split_once('=')
                .unwrap_or_else(|| panic!("{name}: {rest}"));
            assert!(
                kind.contains("ieee_32") || kind.contains("ieee_64"),
                "{name}: {rest}"
            );
            assert!(kind.contains("ne>"), "{name}: only round to nearest even");
            formats.insert(format.trim().to_string(), kind.contains("ieee_32"));
            continue;
        }
        let (lhs, rhs) = statement
            .split_once('=')
            .unwrap_or_else(|| panic!("{name}: {statement}"));
        let lhs: Vec<&str> = lhs.split_whitespace().collect();
        if let [var, format] = lhs[..] {
            let single = *formats
                .get(format)
                .unwrap_or_else(|| panic!("{name}: format {format}"));
            model.defs.push(Def {
                name: var.to_string(),
                expr: expression(rhs),
                single,
                every_op: true,
            });
            continue;
        }
        let [var] = lhs[..] else {
            panic!("{name}: {statement}")
        };
        let rhs = rhs.trim();
        let rounded = rhs.split_once('(').and_then(|(f, inner)| {
            let single = formats.get(f.trim())?;
            Some((*single, inner.strip_suffix(')')?))
        });
        if let Some((single, inner)) = rounded {
            match expression(inner) {
                Expr::Var(v) if v.starts_with(|c: char| c.is_ascii_uppercase()) => {
                    model.inputs.push(var.to_string())
                }
                e => {
                    assert!(
                        operations(&e) <= 1,
                        "{name}: {var} rounds more than one operation once"
                    );
                    model.defs.push(Def {
                        name: var.to_string(),
                        expr: e,
                        single,
                        every_op: false,
                    });
                }
            }
        }
        // Anything else is an exact definition: the proofs' reference.
    }
    assert!(!formats.is_empty(), "{name}: no format");
    model
}

impl Model {
    /// `e` with every operation rounded to f32 (`single`) or f64.
    fn eval(&self, e: &Expr, env: &BTreeMap<String, f64>, single: bool) -> f64 {
        let round = |x: f64| if single { x as f32 as f64 } else { x };
        match e {
            Expr::Num(v) => {
                assert_eq!(round(*v), *v, "{}: {v} is not in the format", self.name);
                *v
            }
            Expr::Var(v) => *env
                .get(v)
                .unwrap_or_else(|| panic!("{}: {v} undefined", self.name)),
            Expr::Neg(a) => -self.eval(a, env, single),
            Expr::Sqrt(a) => round(self.eval(a, env, single).sqrt()),
            Expr::Bin(op, a, b) => {
                let (a, b) = (self.eval(a, env, single), self.eval(b, env, single));
                round(match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    _ => a / b,
                })
            }
        }
    }

    /// Every rounded definition, for these inputs (in the order of the
    /// model's input lines).
    fn run(&self, inputs: &[f64]) -> BTreeMap<String, f64> {
        assert_eq!(inputs.len(), self.inputs.len(), "{}: inputs", self.name);
        let mut env: BTreeMap<String, f64> = self
            .inputs
            .iter()
            .cloned()
            .zip(inputs.iter().copied())
            .collect();
        for d in &self.defs {
            let v = if d.every_op {
                self.eval(&d.expr, &env, d.single)
            } else {
                // One operation, exact to f64's rounding, then rounded to
                // the format: the correctly rounded result.
                let v = self.eval(&d.expr, &env, false);
                if d.single {
                    v as f32 as f64
                } else {
                    v
                }
            };
            env.insert(d.name.clone(), v);
        }
        env
    }
}

/// The code's float type, which every rounded operation of its model must
/// use: a model that rounds one operation to f64 where the code rounds it
/// to f32 is more precise than the code, and proves a bound of something
/// else. (Inputs may be of another format: slerp's f64 evaluation takes an
/// f32 `alpha`.)
#[derive(Clone, Copy, Debug, PartialEq)]
enum Code {
    F32,
    F64,
}

/// The directory of the models: `proofs/gappa/`, or `RIGTFORM_GAPPA_DIR`
/// (`cargo xtask prove --models DIR`), where a model the directory does not
/// hold is not checked.
fn model_dir() -> (String, bool) {
    match std::env::var("RIGTFORM_GAPPA_DIR") {
        Ok(dir) if !dir.is_empty() => (dir, true),
        _ => (format!("{}/gappa", env!("CARGO_MANIFEST_DIR")), false),
    }
}

/// The model `name` of the models' directory, its operations checked to
/// round to the code's type; `None` where another directory is checked
/// and lacks it.
fn model(name: &'static str, code: Code) -> Option<Model> {
    let (dir, other) = model_dir();
    let path = format!("{dir}/{name}.g");
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(_) if other => return None,
        Err(e) => panic!("{path}: {e}"),
    };
    let m = parse(name, &text);
    if let Err(e) = formats_are(&m, code) {
        panic!("{e}");
    }
    Some(m)
}

/// Whether every rounded operation of `m` rounds to the code's type.
fn formats_are(m: &Model, code: Code) -> Result<(), String> {
    match m.defs.iter().find(|d| d.single != (code == Code::F32)) {
        None => Ok(()),
        Some(d) => Err(format!(
            "{}: {} rounds to {}, but the code computes in {}",
            m.name,
            d.name,
            if d.single { "ieee_32" } else { "ieee_64" },
            if code == Code::F32 { "f32" } else { "f64" }
        )),
    }
}

/// One operation of the product's model rounded to f64 instead of f32: the
/// model is more precise than the code, and the check refuses it before
/// any prover runs.
#[test]
fn a_model_more_precise_than_the_code_is_refused() {
    let text = std::fs::read_to_string(format!("{}/gappa/mul.g", env!("CARGO_MANIFEST_DIR")))
        .expect("mul.g");
    assert!(formats_are(&parse("mul", &text), Code::F32).is_ok());
    let wide = text
        .replacen(
            "@rnd = float<ieee_32, ne>;",
            "@rnd = float<ieee_32, ne>;\n@wide = float<ieee_64, ne>;",
            1,
        )
        .replacen("px rnd=", "px wide=", 1);
    let e = formats_are(&parse("mul", &wide), Code::F32).expect_err("f64 rounding");
    assert_eq!(e, "mul: px rounds to ieee_64, but the code computes in f32");
}

/// Both NaN, or the same bits.
fn same(model: f64, code: f32) -> bool {
    (model.is_nan() && code.is_nan()) || (model as f32).to_bits() == code.to_bits()
}

fn check(model: &Model, out: &BTreeMap<String, f64>, name: &str, code: f32, inputs: &[f32]) {
    let m = out[name];
    assert!(
        same(m, code),
        "{}: {name} = {m:e} in the model, {code:e} in the code, for inputs {inputs:?}",
        model.name
    );
}

/// A component for the four-component models: from the mixture of edge,
/// moderate and raw values, or in [-1, 1] (the proofs' domain).
fn component(d: &mut Draws) -> f32 {
    if d.below(2) == 0 {
        d.f32_mixed()
    } else {
        d.uniform(-1.0, 1.0)
    }
}

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat { w, x, y, z }
}

fn draws() -> impl Iterator<Item = (usize, Draws)> {
    (0..DRAWS).map(|i| (i, Draws::new(0x9a99a ^ i as u64)))
}

#[test]
fn product_is_mul_g() {
    product_is("mul");
}

/// mul_angle.g computes what mul.g does, with another goal.
#[test]
fn product_is_mul_angle_g() {
    product_is("mul_angle");
}

/// The model `name` computes the Hamilton product's bits.
fn product_is(name: &'static str) {
    let Some(m) = model(name, Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["aw", "ax", "ay", "az", "bw", "bx", "by", "bz"]);
    for (i, mut d) in draws() {
        let v: [f32; 8] = if i % 3 == 0 {
            let (a, b) = (d.unit_quat(), d.unit_quat());
            [a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z]
        } else {
            core::array::from_fn(|_| component(&mut d))
        };
        let p = quat([v[0], v[1], v[2], v[3]]) * quat([v[4], v[5], v[6], v[7]]);
        let out = m.run(&v.map(f64::from));
        for (name, c) in [("pw", p.w), ("px", p.x), ("py", p.y), ("pz", p.z)] {
            check(&m, &out, name, c, &v);
        }
    }
}

/// renormalize.g on the product as the code computes it: its `n2` is the
/// product's `norm_squared`, and `mul_renormalized`'s result is each
/// component of the product times the model's `s`, rounded once
/// (`proofs/coq/renormalized_norm.v`'s last step).
#[test]
fn renormalized_product_is_renormalize_g() {
    let Some(m) = model("renormalize", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["pw", "px", "py", "pz"]);
    for (i, mut d) in draws() {
        let (a, b) = if i % 3 == 0 {
            (d.unit_quat(), d.unit_quat())
        } else {
            (
                quat(core::array::from_fn(|_| component(&mut d))),
                quat(core::array::from_fn(|_| component(&mut d))),
            )
        };
        let p = a * b;
        let v = [p.w, p.x, p.y, p.z];
        let out = m.run(&v.map(f64::from));
        check(&m, &out, "n2", p.norm_squared(), &v);
        let s = out["s"] as f32;
        let r = a.mul_renormalized(b);
        for (c, rc) in [(p.w, r.w), (p.x, r.x), (p.y, r.y), (p.z, r.z)] {
            assert!(
                same(f64::from(c * s), rc),
                "renormalize: {c:e} * {s:e} is {:e}, the code gives {rc:e}, for a = {a:?}, b = {b:?}",
                c * s
            );
        }
    }
}

/// normalize.g on the components as scale_for_squares leaves them: as they
/// are when their sum of squares (the model's `s`) lies in [2^-100,
/// f32::MAX], otherwise scaled as normalize_scale.g (by 2^-66 when it
/// overflowed, else by 2^100). The choice of branch is the code's, written
/// out here; the arithmetic of each branch is the models'.
#[test]
fn normalize_is_normalize_g_in_each_branch() {
    let Some(m) = model("normalize", Code::F32) else {
        return;
    };
    let Some(scale) = model("normalize_scale", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["a", "b", "c", "d"]);
    let mut branches = [0usize; 3];
    for (i, mut d) in draws() {
        // Every scale: the exponent drawn from the whole range.
        let v: [f32; 4] = core::array::from_fn(|_| {
            let c = d.uniform(-1.0, 1.0);
            let e = if i % 2 == 0 {
                d.below(280) as i32 - 150
            } else {
                0
            };
            let c = c * 2f32.powi(e.clamp(-126, 127)) * 2f32.powi((e + 126).min(0));
            if d.below(8) == 0 {
                0.0
            } else {
                c
            }
        });
        if !v.iter().all(|c| c.is_finite()) || v.iter().all(|&c| c == 0.0) {
            continue;
        }
        let s = m.run(&v.map(f64::from))["s"];
        let scaled = if (2f64.powi(-100)..=f64::from(f32::MAX)).contains(&s) {
            branches[0] += 1;
            v.map(f64::from)
        } else {
            let name = if s.is_infinite() { "down" } else { "up" };
            branches[if s.is_infinite() { 1 } else { 2 }] += 1;
            v.map(|c| scale.run(&[f64::from(c)])[name])
        };
        let out = m.run(&scaled);
        // The code sums the squares in the order of `to_array`, x, y, z, w:
        // the model's a, b, c, d.
        let n = Quat::from_array(v).normalize();
        for (name, c) in [("ca", n.x), ("cb", n.y), ("cc", n.z), ("cd", n.w)] {
            check(&m, &out, name, c, &v);
        }
    }
    assert!(
        branches.iter().all(|&b| b > 1000),
        "branches drawn: {branches:?}"
    );
}

#[test]
fn rotation_is_rotate_g() {
    let Some(m) = model("rotate", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["w", "x", "y", "z", "vx", "vy", "vz"]);
    law_terms_are_the_models("rotate_error", &m);
    for (i, mut d) in draws() {
        let v: [f32; 7] = if i % 3 == 0 {
            let (q, p) = (d.unit_quat(), d.vec3(10.0));
            [q.w, q.x, q.y, q.z, p.x, p.y, p.z]
        } else {
            core::array::from_fn(|_| component(&mut d))
        };
        let r = quat([v[0], v[1], v[2], v[3]]) * Cvec3::new(v[4], v[5], v[6]);
        let out = m.run(&v.map(f64::from));
        for (name, c) in [("rx", r.x), ("ry", r.y), ("rz", r.z)] {
            check(&m, &out, name, c, &v);
        }
    }
}

/// matrix_entry.g's two entries, renamed and with `w` negated, are all
/// nine entries of the rotation block of `Matrix4::from_quat`.
#[test]
fn rotation_matrix_is_matrix_entry_g() {
    let Some(m) = model("matrix_entry", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["w", "x", "y", "z"]);
    for (i, mut d) in draws() {
        let [w, x, y, z]: [f32; 4] = if i % 2 == 0 {
            let q = d.unit_quat();
            [q.w, q.x, q.y, q.z]
        } else {
            core::array::from_fn(|_| component(&mut d))
        };
        let cols = rigtform::Matrix4::from_quat(quat([w, x, y, z])).cols;
        // (column, row) of the code's matrix, the model's output, and the
        // model's inputs w, x, y, z.
        let entries = [
            (0, 0, "d", [w, x, y, z]),
            (1, 1, "d", [w, y, x, z]),
            (2, 2, "d", [w, z, x, y]),
            (0, 1, "o", [w, x, y, z]),
            (1, 0, "o", [-w, x, y, z]),
            (0, 2, "o", [-w, x, z, y]),
            (2, 0, "o", [w, x, z, y]),
            (1, 2, "o", [w, y, z, x]),
            (2, 1, "o", [-w, y, z, x]),
        ];
        for (c, r, name, v) in entries {
            let code = cols[c].to_array()[r];
            check(&m, &m.run(&v.map(f64::from)), name, code, &v);
        }
    }
}

/// srt_scale.g's norms, the first column's `n` and, renamed, the second's
/// `n` and the third's `nz`, are the magnitudes of the scale that
/// `Matrix4::to_scale_rotation_translation` takes back from
/// `Matrix4::from_scale_rotation_translation`.
#[test]
fn srt_scale_is_srt_scale_g() {
    let Some(m) = model("srt_scale", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["w", "x", "y", "z", "s"]);
    law_terms_are_the_models("srt_scale_bound", &m);
    for (i, mut d) in draws() {
        let [w, x, y, z]: [f32; 4] = if i % 2 == 0 {
            let q = d.unit_quat();
            [q.w, q.x, q.y, q.z]
        } else {
            core::array::from_fn(|_| d.uniform(-1.0, 1.0))
        };
        let scale: [f32; 3] = core::array::from_fn(|_| {
            let magnitude = 10f32.powf(d.uniform(-3.0, 3.0));
            if d.below(2) == 0 {
                magnitude
            } else {
                -magnitude
            }
        });
        let [sx, sy, sz] = scale;
        let (got, _, _) = rigtform::Matrix4::from_scale_rotation_translation(
            Cvec3::new(sx, sy, sz),
            quat([w, x, y, z]),
            Cvec3::ZERO,
        )
        .to_scale_rotation_translation();
        // (the code's scale, the model's output, its inputs w, x, y, z, s)
        let columns = [
            (got.x, "n", [w, x, y, z, sx]),
            (got.y, "n", [-w, y, x, z, sy]),
            (got.z, "nz", [w, z, x, y, sz]),
        ];
        for (code, name, v) in columns {
            let out = m.run(&v.map(f64::from));
            // The model is the branch of the norm without rescaling.
            let sum = if name == "n" { out["q"] } else { out["qz"] };
            if !(2f64.powi(-100)..=f64::from(f32::MAX)).contains(&sum) {
                continue;
            }
            check(&m, &out, name, code.abs(), &v);
        }
    }
}

/// sampler_linear.g and sampler_cubic.g, component by component, against
/// a Cvec3 `Sampler` of one segment at a time inside it. The segment's
/// `td = t1 - t0` and `u = (t - t0) / td`, which the models take as
/// inputs, are the sampler's glue, written out here; the result's bits are
/// the library's.
#[test]
fn vector_samplers_are_sampler_linear_g_and_sampler_cubic_g() {
    use rigtform::animation::{Interpolation, Sampler};
    let (Some(linear), Some(cubic)) = (
        model("sampler_linear", Code::F32),
        model("sampler_cubic", Code::F32),
    ) else {
        return;
    };
    assert_eq!(linear.inputs, ["a", "b", "u"]);
    assert_eq!(cubic.inputs, ["p0", "b0", "p1", "a1", "u", "td"]);
    for (i, mut d) in draws() {
        let t0 = if i % 7 == 0 {
            0.0
        } else {
            d.uniform(0.0, 10.0)
        };
        let t1 = t0 + d.uniform(0.01, 2.0);
        let t = d.uniform(t0, t1);
        if !(t0 < t && t < t1) {
            continue;
        }
        // The sampler takes finite values only.
        let finite = |c: f32| if c.is_finite() { c } else { 1.5 };
        let vector = |d: &mut Draws| {
            let raw = finite(component(d));
            Cvec3::new(d.uniform(-100.0, 100.0), raw, d.uniform(-1.0, 1.0))
        };
        let values: [Cvec3; 6] = core::array::from_fn(|_| vector(&mut d));
        let times = [t0, t1];
        let (td, u) = (t1 - t0, (t - t0) / (t1 - t0));
        let line = Sampler::new(Interpolation::Linear, &times, &values[..2])
            .expect("two keys")
            .sample(t);
        let spline = Sampler::new(Interpolation::CubicSpline, &times, &values)
            .expect("two keys")
            .sample(t);
        let [_, p0, b0, a1, p1, _] = values.map(|v| v.to_array());
        for c in 0..3 {
            let v = [values[0].to_array()[c], values[1].to_array()[c], u];
            check(
                &linear,
                &linear.run(&v.map(f64::from)),
                "r",
                line.to_array()[c],
                &v,
            );
            let v = [p0[c], b0[c], p1[c], a1[c], u, td];
            let code = spline.to_array()[c];
            check(&cubic, &cubic.run(&v.map(f64::from)), "c", code, &v);
        }
    }
}

#[test]
fn product_with_the_inverse_is_quat_inv_g() {
    let Some(m) = model("quat_inv", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["w", "x", "y", "z"]);
    for (i, mut d) in draws() {
        let v: [f32; 4] = if i % 2 == 0 {
            let q = d.unit_quat();
            [q.w, q.x, q.y, q.z]
        } else {
            core::array::from_fn(|_| component(&mut d))
        };
        let q = quat(v);
        let p = q * q.inv();
        let out = m.run(&v.map(f64::from));
        for (name, c) in [("pw", p.w), ("px", p.x), ("py", p.y), ("pz", p.z)] {
            check(&m, &out, name, c, &v);
        }
        // The x component's terms cancel in adjacent pairs: exactly zero
        // for finite inputs whose products do not overflow.
        if v.iter().all(|c| c.abs() < 1e19) {
            assert_eq!(p.x, 0.0, "{v:?}: {p:?}");
        }
    }
}

/// inv_inv.g: negating twice, on raw bit patterns too (the model's
/// roundings of a negation are exact, as the code's sign flips are).
#[test]
fn inverse_of_the_inverse_is_inv_inv_g() {
    let Some(m) = model("inv_inv", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["x", "y", "z"]);
    for (_, mut d) in draws() {
        let v: [f32; 3] = core::array::from_fn(|_| component(&mut d));
        let q = Quat::from_xyzw(v[0], v[1], v[2], d.f32_mixed());
        let back = q.inv().inv();
        let out = m.run(&v.map(f64::from));
        for (name, c) in [("iix", back.x), ("iiy", back.y), ("iiz", back.z)] {
            check(&m, &out, name, c, &v);
        }
        assert_eq!(back.w.to_bits(), q.w.to_bits());
    }
}

#[test]
fn rig_tform_inverse_identities_are_rigtform_inv_g() {
    let Some(m) = model("rigtform_inv", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["w", "x", "y", "z", "t1", "t2", "t3"]);
    law_terms_are_the_models("rigtform_inverse", &m);
    for (i, mut d) in draws() {
        let v: [f32; 7] = if i % 3 == 0 {
            let (q, t) = (d.unit_quat(), d.vec3(100.0));
            [q.w, q.x, q.y, q.z, t.x, t.y, t.z]
        } else {
            core::array::from_fn(|_| component(&mut d))
        };
        let a = RigTForm::new(Cvec3::new(v[4], v[5], v[6]), quat([v[0], v[1], v[2], v[3]]));
        let out = m.run(&v.map(f64::from));
        let e = (a * a.inv()).t;
        for (name, c) in [("ex", e.x), ("ey", e.y), ("ez", e.z)] {
            check(&m, &out, name, c, &v);
        }
        let back = a.inv().inv().t;
        for (name, c) in [("gx", back.x), ("gy", back.y), ("gz", back.z)] {
            check(&m, &out, name, -c, &v);
        }
    }
}

/// The draws of `pow`'s correspondence tests: a quaternion (unit, or
/// with mixed components) and `alpha`, kept where `scale_for_squares`
/// leaves the vector part as it is (its sum of squares, the model's `q`
/// with the first three of `width` inputs set, in [2^-100, f32::MAX]; the
/// other branches are normalize_scale.g's) and `|alpha| <= f32::MAX / 4`.
/// `each` gets `q`, `alpha` and what pow's glue makes of them with the
/// library's kernels: the angle `phi = atan2(beta, w)` and the sine and
/// cosine of the f32 product `alpha phi`. Most draws must be kept.
fn pow_cases(m: &Model, width: usize, mut each: impl FnMut(Quat, f32, f32, f32, f32)) {
    let mut kept = 0;
    for (i, mut d) in draws() {
        let q = if i % 2 == 0 {
            d.unit_quat()
        } else {
            quat(core::array::from_fn(|_| component(&mut d)))
        };
        let alpha = match i % 5 {
            0 => d.f32_mixed(),
            1 => d.uniform(-1e6, 1e6),
            _ => d.uniform(-4.0, 4.0),
        };
        if !(q.is_finite() && alpha.is_finite()) || alpha.abs() > f32::MAX / 4.0 {
            continue;
        }
        let mut inputs = vec![0.0; width];
        inputs[..3].copy_from_slice(&[q.x, q.y, q.z].map(f64::from));
        let beta_sq = m.run(&inputs)["q"];
        if !(2f64.powi(-100)..=f64::from(f32::MAX)).contains(&beta_sq) {
            continue;
        }
        let beta = kani_kernels::sqrt(beta_sq as f32);
        let phi = kani_kernels::atan2(beta, q.w * 1.0);
        let (s, c) = kani_kernels::sin_cos(alpha * phi);
        each(q, alpha, phi, s, c);
        kept += 1;
    }
    assert!(
        kept > DRAWS / 2,
        "{kept} of {DRAWS} draws in the model's branch"
    );
}

/// axis_angle.g, on [`pow_cases`] and on axes and angles drawn as
/// [`component`]s and from [-1e4, 1e4] and [-7, 7]. The model takes the
/// kernel's sine and cosine as inputs; the result's bits are the
/// library's `pow` and `from_axis_angle`, and the terms of the norm's law
/// (axis_angle_norm.v) are the model's.
#[test]
fn axis_angle_and_power_are_axis_angle_g() {
    let Some(m) = model("axis_angle", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["x", "y", "z", "s", "c"]);
    law_terms_are_the_models("axis_angle_norm", &m);
    pow_cases(&m, 5, |q, alpha, _, s, c| {
        let v = [q.x, q.y, q.z, s, c];
        let out = m.run(&v.map(f64::from));
        let p = q.pow(alpha);
        assert_eq!(
            p.w.to_bits(),
            c.to_bits(),
            "axis_angle: w for {q:?}, {alpha}"
        );
        for (name, code) in [("rx", p.x), ("ry", p.y), ("rz", p.z)] {
            check(&m, &out, name, code, &v);
        }
    });
    let mut kept = 0;
    for (i, mut d) in draws() {
        let axis: [f32; 3] = core::array::from_fn(|_| component(&mut d));
        let angle = match i % 3 {
            0 => d.f32_mixed(),
            1 => d.uniform(-1e4, 1e4),
            _ => d.uniform(-7.0, 7.0),
        };
        if !(angle.is_finite() && axis.iter().all(|a| a.is_finite())) {
            continue;
        }
        let (s, c) = kani_kernels::sin_cos(angle * 0.5);
        let v = [axis[0], axis[1], axis[2], s, c];
        let out = m.run(&v.map(f64::from));
        if !(2f64.powi(-100)..=f64::from(f32::MAX)).contains(&out["q"]) {
            continue;
        }
        let r = Quat::from_axis_angle(Cvec3::new(axis[0], axis[1], axis[2]), angle);
        assert_eq!(
            r.w.to_bits(),
            c.to_bits(),
            "axis_angle: w for {axis:?}, {angle}"
        );
        for (name, code) in [("rx", r.x), ("ry", r.y), ("rz", r.z)] {
            check(&m, &out, name, code, &v);
        }
        kept += 1;
    }
    assert!(
        kept > DRAWS / 2,
        "{kept} of {DRAWS} draws in the model's branch"
    );
}

/// polar_angle.g, on [`pow_cases`]: `pow`'s vector part, `to_scaled_axis`
/// and the angle of `to_axis_angle` (x's component; y and z are the same
/// operations), with `ph`, `s` and `c` the library's kernels on the
/// arguments the code hands them.
#[test]
fn polar_maps_are_polar_angle_g() {
    let Some(m) = model("polar_angle", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["x", "y", "z", "ph", "al", "s", "c"]);
    pow_cases(&m, 7, |q, alpha, phi, s, c| {
        let v = [q.x, q.y, q.z, phi, alpha, s, c];
        let out = m.run(&v.map(f64::from));
        let p = q.pow(alpha);
        assert_eq!(
            p.w.to_bits(),
            c.to_bits(),
            "polar_angle: w for {q:?}, {alpha}"
        );
        check(&m, &out, "rx", p.x, &v);
        check(&m, &out, "vx", q.to_scaled_axis().x, &v);
        // to_axis_angle turns q.cn(), which is q where w >= 0.
        if q.w >= 0.0 {
            check(&m, &out, "t", q.to_axis_angle().1, &v);
        }
    });
}

/// cos_poly.g: the kernel's cosine for every argument in [0, pi/4], where
/// it is the polynomial with the tail 0 (random arguments, raw bit
/// patterns of the range, and its ends).
#[test]
fn cosine_polynomial_is_cos_poly_g() {
    let Some(m) = model("cos_poly", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["r", "t"]);
    let quarter = core::f32::consts::FRAC_PI_4;
    let mut d = Draws::new(17);
    let ends = [
        0.0,
        f32::from_bits(1),
        f32::MIN_POSITIVE,
        2f32.powi(-12),
        quarter,
    ];
    let drawn = (0..DRAWS).map(|i| {
        if i % 2 == 0 {
            d.uniform(0.0, quarter)
        } else {
            f32::from_bits(d.next_u32() % (quarter.to_bits() + 1))
        }
    });
    for r in ends.into_iter().chain(drawn) {
        let out = m.run(&[f64::from(r), 0.0]);
        check(&m, &out, "y", kani_kernels::sin_cos(r).1, &[r, 0.0]);
    }
}

/// sin_poly_tail.g and cos_poly_tail.g: both polynomials with a tail, as
/// the kernel evaluates them for every argument in [0, 3 pi/4]: `(a, 0)`
/// up to pi/4 (sine and cosine), and beyond it the head and tail of
/// `pi/2 - a`, computed here as the kernel does, whose cosine is the
/// kernel's sine and whose sine its cosine (random arguments, raw bit
/// patterns of the range, and its ends).
#[test]
fn polynomials_with_their_tail_are_sin_and_cos_poly_tail_g() {
    let (Some(sin), Some(cos)) = (
        model("sin_poly_tail", Code::F32),
        model("cos_poly_tail", Code::F32),
    ) else {
        return;
    };
    assert_eq!(sin.inputs, ["r", "t"]);
    assert_eq!(cos.inputs, ["r", "t"]);
    use rigtform_proofs::reference::narrow_head_and_tail;
    let (quarter, half) = (core::f32::consts::FRAC_PI_4, core::f32::consts::FRAC_PI_2);
    let three_quarters = 2.356_194_3f32;
    let mut d = Draws::new(23);
    let ends = [
        0.0,
        f32::from_bits(1),
        f32::MIN_POSITIVE,
        quarter,
        f32::from_bits(quarter.to_bits() + 1),
        half,
        three_quarters,
    ];
    let drawn = (0..DRAWS).map(|i| {
        if i % 2 == 0 {
            d.uniform(0.0, three_quarters)
        } else {
            f32::from_bits(d.next_u32() % (three_quarters.to_bits() + 1))
        }
    });
    for a in ends.into_iter().chain(drawn) {
        let (s, c) = kani_kernels::sin_cos(a);
        let (r, t, swapped) = narrow_head_and_tail(a);
        let (of_sin, of_cos) = if swapped { (c, s) } else { (s, c) };
        let inputs = [f64::from(r), f64::from(t)];
        check(&sin, &sin.run(&inputs), "y", of_sin, &[r, t]);
        check(&cos, &cos.run(&inputs), "y", of_cos, &[r, t]);
    }
}

/// atan_poly.g and atan_poly_tiny.g (one computation, its domain split
/// between the two): the arctangent polynomial as the atan2 kernel
/// evaluates it, through `atan2(u, 1)`, whose lower branch takes every
/// `u` in [0, tan(1/2)] (the quotient `u / 1` is `u`, and the head and
/// tail added are 0), so that the kernel's result is `atan_poly(u)` (raw
/// bit patterns of each model's range, uniform draws, and the ends).
#[test]
fn arctangent_polynomial_is_atan_poly_g() {
    let tan_half = 0.546_302_5f32;
    let tiny = 2f32.powi(-40);
    for (name, lo, hi) in [("atan_poly", tiny, tan_half), ("atan_poly_tiny", 0.0, tiny)] {
        let Some(m) = model(name, Code::F32) else {
            continue;
        };
        assert_eq!(m.inputs, ["u"]);
        let mut d = Draws::new(29);
        let ends = [
            lo,
            hi,
            f32::from_bits(hi.to_bits() - 1),
            f32::from_bits(1),
            f32::MIN_POSITIVE,
        ];
        let drawn = (0..DRAWS / 2).map(|i| {
            if i % 2 == 0 {
                d.uniform(lo, hi)
            } else {
                f32::from_bits(lo.to_bits() + d.next_u32() % (hi.to_bits() - lo.to_bits() + 1))
            }
        });
        for u in ends
            .into_iter()
            .filter(|u| (lo..=hi).contains(u))
            .chain(drawn)
        {
            let out = m.run(&[f64::from(u)]);
            check(&m, &out, "y", kani_kernels::atan2(u, 1.0), &[u]);
        }
    }
}

/// The atan2 kernel's branch for `b = |y|`, `a = |x|` (0 lower, 1 upper,
/// 2 middle), its scaled arguments and its quotient, as
/// `src/float/atan2.rs` computes them for finite, nonzero arguments.
fn atan2_branch(b: f32, a: f32) -> (u8, f32, f32, f32) {
    let tan_half = 0.546_302_5f32;
    let scale = if b > 1.0 { 0.25 } else { 2f32.powi(60) };
    let (qb, qa) = (b * scale, a * scale);
    if qb <= qa * tan_half {
        (0, qb, qa, b / a)
    } else if qa <= qb * tan_half {
        (1, qb, qa, -a / b)
    } else {
        (2, qb, qa, (qb - qa) / (qb + qa))
    }
}

/// `atan_poly(u)` for `|u| <= tan(1/2)`: the kernel's lower branch,
/// `atan2(|u|, 1)` (`arctangent_polynomial_is_atan_poly_g`), with the sign
/// of `u` (the polynomial is odd, bit for bit).
fn atan_poly_of(u: f32) -> f32 {
    kani_kernels::atan2(u.abs(), 1.0).copysign(u)
}

/// Pairs `(b, a)` of positive f32 at every scale, one over the other drawn
/// in [0, 1.9] and either way round, so that every branch is taken.
fn atan2_pairs(seed: u64) -> impl Iterator<Item = (f32, f32)> {
    let mut d = Draws::new(seed);
    (0..DRAWS).map(move |i| {
        let a = 2f32.powi(d.below(200) as i32 - 100) * d.uniform(1.0, 2.0);
        let b = a * d.uniform(0.0, 1.9);
        if i % 2 == 0 {
            (b, a)
        } else {
            (a, b)
        }
    })
}

/// atan2_outer.g: the kernel's lower and upper branches, each result and
/// its negative-`x` counterpart, from the quotient and the polynomial's
/// result (random pairs of every scale in either branch).
#[test]
fn atan2_outer_branches_are_atan2_outer_g() {
    let Some(m) = model("atan2_outer", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["ul", "yl", "uh", "yh"]);
    let mut seen = [0usize; 2];
    for (b, a) in atan2_pairs(31) {
        let (branch, _, _, u) = atan2_branch(b, a);
        if branch == 2 || u.abs() > 0.546_302_5 || b == 0.0 {
            continue;
        }
        seen[usize::from(branch)] += 1;
        let y = atan_poly_of(u);
        let (pos, neg) = (kani_kernels::atan2(b, a), kani_kernels::atan2(b, -a));
        let (u, y) = (f64::from(u), f64::from(y));
        if branch == 0 {
            let out = m.run(&[u, y, -0.5, -0.5]);
            check(&m, &out, "pl", pos, &[b, a]);
            check(&m, &out, "rl", neg, &[b, -a]);
        } else {
            let out = m.run(&[0.5, 0.5, u, y]);
            check(&m, &out, "ph", pos, &[b, a]);
            check(&m, &out, "rh", neg, &[b, -a]);
        }
    }
    assert!(seen.iter().all(|&n| n > DRAWS / 10), "{seen:?}");
}

/// atan2_middle.g: the kernel's middle branch, each result and its
/// negative-`x` counterpart, from the exact difference, the rounded sum
/// and the polynomial's result, for `b > a` (its p variables) and `b < a`
/// (its n variables).
#[test]
fn atan2_middle_branch_is_atan2_middle_g() {
    let Some(m) = model("atan2_middle", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["dp", "ep", "yp", "dn", "en", "yn"]);
    let mut seen = [0usize; 2];
    for (b, a) in atan2_pairs(37) {
        let (branch, qb, qa, u) = atan2_branch(b, a);
        if branch != 2 || qb == qa {
            continue;
        }
        let (d, e, y) = (
            f64::from(qb - qa),
            f64::from(qb + qa),
            f64::from(atan_poly_of(u)),
        );
        let (pos, neg) = (kani_kernels::atan2(b, a), kani_kernels::atan2(b, -a));
        if d > 0.0 {
            seen[0] += 1;
            let out = m.run(&[d, e, y, -1.0, 4.0, -0.25]);
            check(&m, &out, "pp", pos, &[b, a]);
            check(&m, &out, "rp", neg, &[b, -a]);
        } else {
            seen[1] += 1;
            let out = m.run(&[1.0, 4.0, 0.25, d, e, y]);
            check(&m, &out, "pn", pos, &[b, a]);
            check(&m, &out, "rn", neg, &[b, -a]);
        }
    }
    assert!(seen.iter().all(|&n| n > DRAWS / 10), "{seen:?}");
}

/// sin_poly_hi.g, sin_poly_mid.g and sin_poly_low.g (one computation, its
/// binades split among three models): the kernel's sine for every argument
/// in [0, pi/4], where it is the polynomial with the tail 0.
#[test]
fn sine_polynomial_is_sin_poly_g() {
    let quarter = core::f32::consts::FRAC_PI_4;
    for name in ["sin_poly_hi", "sin_poly_mid", "sin_poly_low"] {
        let Some(m) = model(name, Code::F32) else {
            continue;
        };
        assert_eq!(m.inputs, ["r"]);
        let mut d = Draws::new(19);
        let ends = [
            0.0,
            f32::from_bits(1),
            f32::MIN_POSITIVE,
            2f32.powi(-9),
            quarter,
        ];
        let drawn = (0..DRAWS / 2).map(|i| {
            if i % 2 == 0 {
                d.uniform(0.0, quarter)
            } else {
                f32::from_bits(d.next_u32() % (quarter.to_bits() + 1))
            }
        });
        for r in ends.into_iter().chain(drawn) {
            let out = m.run(&[f64::from(r)]);
            check(&m, &out, "y", kani_kernels::sin_cos(r).0, &[r]);
        }
    }
}

#[test]
fn square_root_is_sqrt_g() {
    let Some(m) = model("sqrt", Code::F32) else {
        return;
    };
    assert_eq!(m.inputs, ["x"]);
    let mut d = Draws::new(5);
    let raw = (0..DRAWS).map(|_| f32::from_bits(d.next_u32() & 0x7fff_ffff));
    for x in EDGE_F32.into_iter().chain(raw) {
        check(
            &m,
            &m.run(&[f64::from(x)]),
            "r",
            kani_kernels::sqrt(x),
            &[x],
        );
    }
}

/// Bits of two f64 results, or both NaN.
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
fn same_f64(model: f64, code: f64) -> bool {
    model.to_bits() == code.to_bits() || (model.is_nan() && code.is_nan())
}

#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
#[test]
fn f64_sinc_is_sinc_f64_g() {
    let Some(m) = model("sinc_f64", Code::F64) else {
        return;
    };
    assert_eq!(m.inputs, ["s"]);
    let mut d = Draws::new(11);
    let edges = [0.0, 1e-300, 2f64.powi(-60), 1.0, 2.4674011002723395, 2.4676];
    let drawn = (0..DRAWS).map(|i| {
        // Squares of f32 arguments (as the sweep), and f64 ones as slerp
        // computes them (the share squared times phi^2).
        if i % 2 == 0 {
            let x = f64::from(d.uniform(0.0, core::f32::consts::FRAC_PI_2));
            x * x
        } else {
            let share = f64::from(d.uniform(0.0, 1.0));
            let phi = f64::from_bits(d.next_u64()).abs() % core::f64::consts::FRAC_PI_2;
            (share * share) * (phi * phi)
        }
    });
    for s in edges.into_iter().chain(drawn) {
        let model = m.run(&[s])["g"];
        let code = kani_kernels::slerp_sinc(s);
        assert!(
            same_f64(model, code),
            "sinc_f64: {model:e} in the model, {code:e} in the code, at {s:e}"
        );
    }
}

/// `|a - cn(b)|^2` and `|a + cn(b)|^2` of a pair, in f64 as slerp takes
/// them: `|a|^2 + |b|^2 -+ 2 |a . b|`, each sum as `(x x' + z z') + (y y'
/// + w w')`.
fn lengths(a: Quat, b: Quat) -> [f64; 2] {
    let dot = |p: Quat, q: Quat| {
        let c = |u: f32, v: f32| f64::from(u) * f64::from(v);
        (c(p.x, q.x) + c(p.z, q.z)) + (c(p.y, q.y) + c(p.w, q.w))
    };
    let (sum, twice) = (dot(a, a) + dot(b, b), 2.0 * dot(a, b).abs());
    [sum - twice, sum + twice]
}

/// arc_quotient_f64.g and then arc_f64.g on its `t2`, on the squared
/// lengths `near` and `far` of unit pairs, of pairs at every scale the
/// evaluation takes (squared norms up to 2^32), and of raw values.
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
#[test]
fn f64_arc_is_arc_quotient_f64_g_then_arc_f64_g() {
    let Some(quotient) = model("arc_quotient_f64", Code::F64) else {
        return;
    };
    let Some(m) = model("arc_f64", Code::F64) else {
        return;
    };
    assert_eq!(quotient.inputs, ["near", "far"]);
    assert_eq!(m.inputs, ["t2"]);
    for (i, mut d) in draws() {
        let [near, far] = match i % 3 {
            0 => lengths(d.unit_quat(), d.unit_quat()),
            1 => {
                let scale = 2f32.powi(d.below(33) as i32 - 16);
                let (a, b) = (d.unit_quat(), d.unit_quat());
                let scaled = |q: Quat| quat([q.w, q.x, q.y, q.z].map(|c| c * scale));
                lengths(scaled(a), scaled(b))
            }
            _ => {
                let v = f64::from(d.uniform(0.0, 1.0)) * 2f64.powi(-(d.below(290) as i32));
                [v.max(2f64.powi(-298)), f64::from(d.uniform(1e-3, 4.0))]
            }
        };
        if near <= 0.0 || near >= far {
            continue;
        }
        let t2 = quotient.run(&[near, far])["t2"];
        let out = m.run(&[t2]);
        let (phi_squared, phi_over_sine) = kani_kernels::slerp_arc(near, far);
        for (name, code) in [("phi2", phi_squared), ("pos", phi_over_sine)] {
            assert!(
                same_f64(out[name], code),
                "arc_f64: {name} = {:e} in the model, {code:e} in the code, for {:?}",
                out[name],
                [near, far]
            );
        }
    }
}

/// coefficient_rest_f64.g (`c0`) and coefficient_f64.g (`c1`) on the arcs
/// of drawn pairs (arc_quotient_f64.g's and arc_f64.g's outputs, so that
/// the chain from the pair to the coefficients is the models' throughout)
/// and on raw arcs, with `alpha` drawn in (0, 1] and at its edges.
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
#[test]
fn f64_coefficients_are_coefficient_f64_g() {
    let Some(quotient) = model("arc_quotient_f64", Code::F64) else {
        return;
    };
    let Some(arc) = model("arc_f64", Code::F64) else {
        return;
    };
    let Some(share) = model("coefficient_f64", Code::F64) else {
        return;
    };
    let Some(rest) = model("coefficient_rest_f64", Code::F64) else {
        return;
    };
    for m in [&share, &rest] {
        assert_eq!(m.inputs, ["alpha", "phi2", "pos"]);
    }
    let edges = [
        f32::from_bits(1),
        1e-30,
        1e-7,
        0.5,
        1.0 - f32::EPSILON / 2.0,
        1.0,
    ];
    for (i, mut d) in draws() {
        let (phi2, pos) = if i % 2 == 0 {
            let [near, far] = lengths(d.unit_quat(), d.unit_quat());
            let t2 = quotient.run(&[near, far])["t2"];
            let out = arc.run(&[t2]);
            (out["phi2"], out["pos"])
        } else {
            let phi = f64::from(d.uniform(0.0, core::f32::consts::FRAC_PI_2));
            let phi2 = phi * phi + f64::from(d.uniform(-1e-9, 1e-9));
            (phi2, phi / phi.sin().max(1e-9))
        };
        let alpha = if i % 5 == 0 {
            edges[d.below(edges.len())]
        } else {
            d.uniform(0.0, 1.0)
        };
        let inputs = [f64::from(alpha), phi2, pos];
        let [c0, c1] = kani_kernels::slerp_coefficients(phi2, pos, alpha);
        for (m, code) in [(&rest, c0), (&share, c1)] {
            let model = m.run(&inputs)["c"];
            assert!(
                same_f64(model, code),
                "{}: {model:e} in the model, {code:e} in the code, for {inputs:?}",
                m.name
            );
        }
    }
}

/// The evaluator itself: its notations and its rounding.
#[test]
fn evaluator_reads_the_notations_and_rounds_each_operation() {
    assert_eq!(number("7b-24"), 7.0 * 2f64.powi(-24));
    assert_eq!(number("0x1p100"), 2f64.powi(100));
    assert_eq!(number("-0x1.8p-1".trim_start_matches('-')), 0.75);
    assert_eq!(number("9.29e-10"), 9.29e-10);
    let m = parse(
        "t",
        "@rnd = float<ieee_32, ne>;\na = rnd(A); b = rnd(B);\ns rnd= a + b - a;\nS = a + b - a;\n{ a in [0, 1] -> s in ? }",
    );
    assert_eq!(m.inputs, ["a", "b"]);
    assert_eq!(m.defs.len(), 1);
    assert!(m.defs[0].single && m.defs[0].every_op);
    // (1 + 2^-30) - 1 rounds the sum to 1 in f32 first: 0, not 2^-30.
    assert_eq!(m.run(&[1.0, 2f64.powi(-30)])["s"], 0.0);
    let m = parse(
        "u",
        "@rnd = float<ieee_64, ne>;\na = rnd(A); b = rnd(B);\ns rnd= a + b - a;",
    );
    assert_eq!(m.run(&[1.0, 2f64.powi(-30)])["s"], 2f64.powi(-30));
}

/// A rounded expression as text, each operation in parentheses and each
/// rounding `r(...)`: how a model's definition and a law's Coq term are
/// compared.
fn rounded_text(e: &Expr, every_op: bool) -> String {
    let round = |s: String| if every_op { format!("r{s}") } else { s };
    match e {
        Expr::Num(v) => format!("{v:e}"),
        Expr::Var(v) => v.clone(),
        Expr::Neg(a) => format!("(-{})", rounded_text(a, every_op)),
        Expr::Sqrt(a) => round(format!("(sqrt {})", rounded_text(a, every_op))),
        Expr::Bin(op, a, b) => round(format!(
            "({} {op} {})",
            rounded_text(a, every_op),
            rounded_text(b, every_op)
        )),
    }
}

/// Reads a Coq term of the laws (`rnd (rnd (a * b) - c)`: `rnd` applied
/// to a group or a name, other functions applied to a group, `+ - * /`,
/// names, numbers) into the text of [`rounded_text`].
impl Parser {
    /// Operands of `next` joined by `ops`, left to right.
    fn coq_chain(&mut self, ops: [&str; 2], next: fn(&mut Self) -> String) -> String {
        let mut e = next(self);
        while let Some(op) = self.peek().filter(|t| ops.contains(t)).map(str::to_owned) {
            self.i += 1;
            e = format!("({e} {op} {})", next(self));
        }
        e
    }
    fn coq_expr(&mut self) -> String {
        self.coq_chain(["+", "-"], Self::coq_term)
    }
    fn coq_term(&mut self) -> String {
        self.coq_chain(["*", "/"], Self::coq_unary)
    }
    fn coq_unary(&mut self) -> String {
        match self.peek() {
            Some("-") => {
                self.i += 1;
                format!("(-{})", self.coq_unary())
            }
            Some("rnd") => {
                self.i += 1;
                let inner = self.coq_primary();
                if inner.starts_with('(') {
                    format!("r{inner}")
                } else {
                    format!("r({inner})")
                }
            }
            Some(f)
                if f.starts_with(|c: char| c.is_ascii_alphabetic())
                    && self.t.get(self.i + 1).is_some_and(|n| n == "(") =>
            {
                let f = f.to_owned();
                self.i += 1;
                format!("({f} {})", self.coq_primary())
            }
            _ => self.coq_primary(),
        }
    }
    fn coq_primary(&mut self) -> String {
        let t = self.t.get(self.i).cloned().unwrap_or_default();
        self.i += 1;
        if t == "(" {
            let e = self.coq_expr();
            assert_eq!(self.peek(), Some(")"), "a law's term: {:?}", self.t);
            self.i += 1;
            return e;
        }
        if t.starts_with(|c: char| c.is_ascii_digit()) {
            return format!("{:e}", number(&t));
        }
        t
    }
}

/// The `let NAME := TERM in` definitions of a law's theorem, each term in
/// the text of [`rounded_text`].
fn law_terms(law: &str) -> Vec<(String, String)> {
    let body: String = law
        .split("(*")
        .enumerate()
        .map(|(i, part)| {
            if i == 0 {
                part
            } else {
                part.split_once("*)").map_or("", |(_, rest)| rest)
            }
        })
        .collect();
    let t = tokens(&body);
    let mut out = Vec::new();
    let mut i = 0;
    while i + 3 < t.len() {
        if t[i] == "let" && t[i + 2] == ":" && t[i + 3] == "=" {
            let name = t[i + 1].clone();
            let mut j = i + 4;
            let mut depth = 0i32;
            while j < t.len() && !(depth == 0 && t[j] == "in") {
                depth += match t[j].as_str() {
                    "(" => 1,
                    ")" => -1,
                    _ => 0,
                };
                j += 1;
            }
            let mut p = Parser {
                t: t[i + 4..j].to_vec(),
                i: 0,
            };
            let e = p.coq_expr();
            assert_eq!(p.i, p.t.len(), "the law's term {name}: {:?}", p.t);
            out.push((name, e));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

/// The law `proofs/coq/LAW.v` states its theorem on the model's rounded
/// computation: every term it defines under the name of one of the
/// model's rounded definitions is that definition, rounding for rounding
/// and in the same order of operations, and it defines the model's result
/// (its last definition). So the law is about the code's arithmetic, as
/// the model is.
fn law_terms_are_the_models(law: &str, m: &Model) {
    let path = format!("{}/coq/{law}.v", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let terms = law_terms(&text);
    let mut matched = 0;
    for (name, term) in &terms {
        let Some(def) = m.defs.iter().find(|d| &d.name == name) else {
            continue;
        };
        let expected = if def.every_op {
            rounded_text(&def.expr, true)
        } else {
            let inner = rounded_text(&def.expr, false);
            if inner.starts_with('(') {
                format!("r{inner}")
            } else {
                format!("r({inner})")
            }
        };
        assert_eq!(
            term, &expected,
            "{law}.v: {name} is not {}.g's {name}",
            m.name
        );
        matched += 1;
    }
    let last = m.defs.last().map(|d| d.name.as_str());
    assert!(
        terms.iter().any(|(n, _)| Some(n.as_str()) == last),
        "{law}.v does not define {}.g's result {last:?}",
        m.name
    );
    assert!(matched > 0, "{law}.v shares no term with {}.g", m.name);
}

#[test]
fn law_terms_are_read_as_the_models_rounded_definitions() {
    let m = parse(
        "t",
        "@rnd = float<ieee_32, ne>;\na = rnd(A); b = rnd(B); c = rnd(C);\nx rnd= a * b - c;\ny = rnd(a / x);\n{ a in [0, 1] -> y in ? }",
    );
    let law = "(* let x := rnd (a * b) in *)\nTheorem t : forall a b c : R,\n  let x := rnd (rnd (a * b) - c) in\n  let y := rnd (a / x) in y <= 1.";
    let terms = law_terms(law);
    assert_eq!(terms.len(), 2);
    assert_eq!(terms[0].1, rounded_text(&m.defs[0].expr, true));
    assert_eq!(terms[0].1, "r(r(a * b) - c)");
    assert_eq!(terms[1].1, "r(a / x)");
    // Another order of operations is another term.
    let regrouped = law_terms("let x := rnd (a * rnd (b - c)) in x");
    assert_ne!(regrouped[0].1, terms[0].1);
}

#[test]
fn determinant_of_matrix3_is_matrix3_determinant_g() {
    let Some(m) = model("matrix3_determinant", Code::F32) else {
        return;
    };
    assert_eq!(
        m.inputs,
        ["a0", "a1", "a2", "b0", "b1", "b2", "c0", "c1", "c2"]
    );
    law_terms_are_the_models("matrix3_determinant_bound", &m);
    for (_, mut d) in draws() {
        let v: [f32; 9] = core::array::from_fn(|_| component(&mut d));
        let det = rigtform::Matrix3::from_cols_array(&v).determinant();
        check(&m, &m.run(&v.map(f64::from)), "d", det, &v);
    }
}

/// The columns, column-major, of the 4x4 models' inputs `a0 a1 a2 b0 ...
/// d2 x y z w`: (a0, a1, a2, x), (b0, b1, b2, y), (c0, c1, c2, z), (d0,
/// d1, d2, w).
fn matrix4_columns(v: &[f32; 16]) -> [f32; 16] {
    core::array::from_fn(|i| {
        if i % 4 == 3 {
            v[12 + i / 4]
        } else {
            v[3 * (i / 4) + i % 4]
        }
    })
}

#[test]
fn determinant_of_matrix4_is_matrix4_determinant_g() {
    let Some(m) = model("matrix4_determinant", Code::F32) else {
        return;
    };
    let names = [
        "a0", "a1", "a2", "b0", "b1", "b2", "c0", "c1", "c2", "d0", "d1", "d2", "x", "y", "z", "w",
    ];
    assert_eq!(m.inputs, names);
    law_terms_are_the_models("matrix4_determinant_bound", &m);
    for (_, mut d) in draws() {
        let v: [f32; 16] = core::array::from_fn(|_| component(&mut d));
        let cols = matrix4_columns(&v);
        let det = rigtform::Matrix4::from_cols_array(&cols).determinant();
        check(&m, &m.run(&v.map(f64::from)), "det", det, &v);
    }
}

/// The minor of a cross product's component `i`, `p[j] q[k] - p[k] q[j]`
/// with `(j, k)` the next two indices, as the model's `f0 g1 - f1 g0`:
/// `[f0, f1, g0, g1]`.
fn cross_minor(p: [f32; 3], q: [f32; 3], i: usize) -> [f32; 4] {
    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
    [p[j], p[k], q[j], q[k]]
}

#[test]
fn inverse_of_matrix3_is_matrix3_inverse_g() {
    let Some(m) = model("matrix3_inverse", Code::F32) else {
        return;
    };
    assert_eq!(
        m.inputs,
        ["a0", "a1", "a2", "b0", "b1", "b2", "c0", "c1", "c2", "f0", "f1", "g0", "g1"]
    );
    law_terms_are_the_models("matrix3_inverse_bound", &m);
    let mut seen = 0;
    for (_, mut d) in draws() {
        let v: [f32; 9] = core::array::from_fn(|_| component(&mut d));
        let Some(inv) = rigtform::Matrix3::from_cols_array(&v).inverse() else {
            continue;
        };
        seen += 1;
        let col = |c: usize| [v[3 * c], v[3 * c + 1], v[3 * c + 2]];
        // Row i of the inverse is the cross product of the columns after
        // column i (b x c, c x a, a x b), times 1 / det.
        let entries = inv.to_cols_array();
        for i in 0..3 {
            let (p, q) = (col((i + 1) % 3), col((i + 2) % 3));
            for j in 0..3 {
                let inputs: Vec<f64> = v
                    .iter()
                    .chain(&cross_minor(p, q, j))
                    .map(|&c| f64::from(c))
                    .collect();
                let all: Vec<f32> = inputs.iter().map(|&c| c as f32).collect();
                check(&m, &m.run(&inputs), "e", entries[3 * j + i], &all);
            }
        }
    }
    assert!(seen > DRAWS / 4, "{seen} invertible draws");
}

/// The 2x2 minors of `Matrix4::inverse` as the model's `g0 g1 - g2 g3`,
/// `[g0, g1, g2, g3]`, for the columns' first three coordinates `a, b,
/// c, d` and last `x, y, z, w`: `s = a x b`, `t = c x d`, `u = a y - b x`,
/// `v = c w - d z`, component `i`.
struct Minors4 {
    a: [f32; 3],
    b: [f32; 3],
    c: [f32; 3],
    d: [f32; 3],
    x: f32,
    y: f32,
    z: f32,
    w: f32,
}

impl Minors4 {
    fn s(&self, i: usize) -> [f32; 4] {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        [self.a[j], self.b[k], self.a[k], self.b[j]]
    }
    fn t(&self, i: usize) -> [f32; 4] {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        [self.c[j], self.d[k], self.c[k], self.d[j]]
    }
    fn u(&self, i: usize) -> [f32; 4] {
        [self.a[i], self.y, self.b[i], self.x]
    }
    fn v(&self, i: usize) -> [f32; 4] {
        [self.c[i], self.w, self.d[i], self.z]
    }

    /// Row `row`, column `i` of the inverse as the model's entry: the
    /// three entries `f`, the three minors, and the sign by which the
    /// model's `e` is the code's entry. Rows 0 to 3 are `b x v + t y`,
    /// `v x a - t x`, `d x u + s w`, `u x c - s z` in their first three
    /// columns (a cross product's second product and a subtracted term
    /// are a negated entry's) and `-b . t`, `a . t`, `-d . s`, `c . s` in
    /// the last.
    fn entry(&self, row: usize, i: usize) -> ([f32; 3], [[f32; 4]; 3], f32) {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        if i == 3 {
            let (f, minor, sign) = match row {
                0 => (b, [self.t(0), self.t(1), self.t(2)], -1.0),
                1 => (a, [self.t(0), self.t(1), self.t(2)], 1.0),
                2 => (d, [self.s(0), self.s(1), self.s(2)], -1.0),
                _ => (c, [self.s(0), self.s(1), self.s(2)], 1.0),
            };
            return (f, minor, sign);
        }
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let (f, minor) = match row {
            0 => ([b[j], -b[k], self.y], [self.v(k), self.v(j), self.t(i)]),
            1 => ([a[k], -a[j], -self.x], [self.v(j), self.v(k), self.t(i)]),
            2 => ([d[j], -d[k], self.w], [self.u(k), self.u(j), self.s(i)]),
            _ => ([c[k], -c[j], -self.z], [self.u(j), self.u(k), self.s(i)]),
        };
        (f, minor, 1.0)
    }
}

#[test]
fn inverse_of_matrix4_is_matrix4_inverse_g() {
    let Some(m) = model("matrix4_inverse", Code::F32) else {
        return;
    };
    let names = [
        "a0", "a1", "a2", "b0", "b1", "b2", "c0", "c1", "c2", "d0", "d1", "d2", "x", "y", "z", "w",
        "f0", "f1", "f2", "g0", "g1", "g2", "g3", "h0", "h1", "h2", "h3", "k0", "k1", "k2", "k3",
    ];
    assert_eq!(m.inputs, names);
    law_terms_are_the_models("matrix4_inverse_bound", &m);
    let mut seen = 0;
    for (_, mut d) in draws() {
        let v: [f32; 16] = core::array::from_fn(|_| component(&mut d));
        let cols = matrix4_columns(&v);
        let Some(inv) = rigtform::Matrix4::from_cols_array(&cols).inverse() else {
            continue;
        };
        seen += 1;
        let three = |k: usize| [v[3 * k], v[3 * k + 1], v[3 * k + 2]];
        let minors = Minors4 {
            a: three(0),
            b: three(1),
            c: three(2),
            d: three(3),
            x: v[12],
            y: v[13],
            z: v[14],
            w: v[15],
        };
        let entries = inv.to_cols_array();
        for row in 0..4 {
            for i in 0..4 {
                let (f, minor, sign) = minors.entry(row, i);
                let all: Vec<f32> = v
                    .iter()
                    .chain(&f)
                    .chain(minor.iter().flatten())
                    .copied()
                    .collect();
                let inputs: Vec<f64> = all.iter().map(|&c| f64::from(c)).collect();
                check(&m, &m.run(&inputs), "e", sign * entries[4 * i + row], &all);
            }
        }
    }
    // Sixteen components, half of them from the mixture of edge values:
    // most draws hold an infinity, a NaN or an entry beyond the limits.
    assert!(seen > DRAWS / 8, "{seen} invertible draws");
}

/// `project_onto` and `reject_from` of `Cvec4` and `Cvec3` are project4.g
/// and project3.g (and the laws' terms are the models'), where
/// `scale_for_squares` takes the branch without rescaling: the model's
/// sum of squares `s` in [2^-100, f32::MAX]. The other branches scale `b`
/// by a power of two first (normalize_is_normalize_g_in_each_branch), and
/// a zero, infinite or NaN `b` gives NaN.
#[test]
fn projections_are_project4_g_and_project3_g() {
    let (Some(m4), Some(m3)) = (model("project4", Code::F32), model("project3", Code::F32)) else {
        return;
    };
    assert_eq!(m4.inputs, ["a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3"]);
    assert_eq!(m3.inputs, ["a0", "a1", "a2", "b0", "b1", "b2"]);
    law_terms_are_the_models("project4_bound", &m4);
    law_terms_are_the_models("project3_bound", &m3);
    let unscaled = |s: f64| (2f64.powi(-100)..=f64::from(f32::MAX)).contains(&s);
    let mut seen = [0usize; 2];
    for (i, mut d) in draws() {
        let mut v: [f32; 8] = core::array::from_fn(|_| component(&mut d));
        if i % 3 == 0 {
            // b nearly along a, where the projection is most of a.
            for k in 0..4 {
                v[4 + k] = v[k] * 3.0 + d.uniform(-1e-3, 1e-3);
            }
        }
        let out = m4.run(&v.map(f64::from));
        if unscaled(out["s"]) {
            seen[0] += 1;
            let a = rigtform::Cvec4::new(v[0], v[1], v[2], v[3]);
            let b = rigtform::Cvec4::new(v[4], v[5], v[6], v[7]);
            let (p, r) = (a.project_onto(b).to_array(), a.reject_from(b).to_array());
            for k in 0..4 {
                check(&m4, &out, &format!("p{k}"), p[k], &v);
                check(&m4, &out, &format!("r{k}"), r[k], &v);
            }
        }
        let w = [v[0], v[1], v[2], v[4], v[5], v[6]];
        let out = m3.run(&w.map(f64::from));
        if unscaled(out["s"]) {
            seen[1] += 1;
            let (a, b) = (Cvec3::new(w[0], w[1], w[2]), Cvec3::new(w[3], w[4], w[5]));
            let (p, r) = (a.project_onto(b), a.reject_from(b));
            for (k, (p, r)) in [(p.x, r.x), (p.y, r.y), (p.z, r.z)].into_iter().enumerate() {
                check(&m3, &out, &format!("p{k}"), p, &w);
                check(&m3, &out, &format!("r{k}"), r, &w);
            }
        }
    }
    assert!(
        seen.iter().all(|&s| s > DRAWS / 2),
        "unscaled draws: {seen:?}"
    );
}

/// slerp_endpoint_f32.g: slerp's f32 evaluation at `alpha = 1`
/// (`kani_kernels::slerp_in_f32`, on every target), in the branch the
/// model takes (`phi > 2^-12`, squared norms within 1e-6 of each other).
/// The angle is computed as the code computes it, written out here (the
/// part of `b` orthogonal to `a`, its length, atan2), so that the model's
/// input `s` is the sine kernel's `sin(phi)`; `s0` is `sin(0) = 0`.
#[test]
fn f32_slerp_at_one_is_slerp_endpoint_f32_g() {
    let Some(m) = model("slerp_endpoint_f32", Code::F32) else {
        return;
    };
    let names = ["s0", "s", "a0", "a1", "a2", "a3", "b0", "b1", "b2", "b3"];
    assert_eq!(m.inputs, names);
    law_terms_are_the_models("slerp_endpoint_norm_f32", &m);
    let mut kept = 0;
    for (i, mut d) in draws() {
        let a = d.unit_quat();
        let other = match i % 3 {
            0 => d.unit_quat(),
            1 => {
                // Near a, or near -a: small angles and the flip.
                let s = 2f32.powi(-(d.below(12) as i32) - 1);
                let sign = if d.below(2) == 0 { 1.0 } else { -1.0 };
                quat([a.w, a.x, a.y, a.z].map(|c| sign * (c + s * d.uniform(-1.0, 1.0))))
                    .normalize()
            }
            _ => quat(core::array::from_fn(|_| component(&mut d))).normalize(),
        };
        let (n2, on2) = (a.norm_squared(), other.norm_squared());
        if !(other.is_finite() && (n2 - on2).abs() <= 1e-6 * on2) {
            continue;
        }
        let dot = a.dot(other);
        let flip = 1.0f32.copysign(dot);
        let b = quat([other.w, other.x, other.y, other.z].map(|c| c * flip));
        let dot = dot * flip;
        let u = [b.x, b.y, b.z, b.w]
            .iter()
            .zip([a.x, a.y, a.z, a.w])
            .map(|(o, s)| n2 * o + -dot * s)
            .collect::<Vec<f32>>();
        let sum = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + u[3] * u[3];
        if !(2f32.powi(-100)..=f32::MAX).contains(&sum) {
            continue;
        }
        let phi = kani_kernels::atan2(kani_kernels::sqrt(sum), kani_kernels::sqrt(n2) * dot * 1.0);
        if phi <= 1.0 / 4096.0 {
            continue;
        }
        let s = kani_kernels::sin_cos(phi).0;
        let inputs = [0.0, s, a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z];
        let out = m.run(&inputs.map(f64::from));
        let r = kani_kernels::slerp_in_f32(a, other, 1.0);
        for (name, c) in [("q0", r.w), ("q1", r.x), ("q2", r.y), ("q3", r.z)] {
            check(&m, &out, name, c, &inputs);
        }
        kept += 1;
    }
    assert!(
        kept > DRAWS / 2,
        "{kept} of {DRAWS} draws in the model's branch"
    );
}

/// slerp_angle_f64.g on the pairs a single call takes: unit pairs, pairs
/// near each other and near a right angle, with `b` turned to the side
/// where `a . b >= 0` (the model's `cn(b)`: the code takes `|a . b|`,
/// which is the same sums negated).
#[cfg(any(target_arch = "x86_64", target_arch = "aarch64"))]
#[test]
fn f64_pair_is_slerp_angle_f64_g() {
    let Some(m) = model("slerp_angle_f64", Code::F64) else {
        return;
    };
    assert_eq!(m.inputs, ["aw", "ax", "ay", "az", "bw", "bx", "by", "bz"]);
    for (i, mut d) in draws() {
        let a = d.unit_quat();
        let b = match i % 3 {
            0 => d.unit_quat(),
            1 => quat([a.w, a.x, a.y, a.z].map(|c| c + d.uniform(-1e-3, 1e-3))).normalize(),
            _ => quat([-a.x, a.w, -a.z, a.y].map(|c| c + d.uniform(-1e-3, 1e-3))).normalize(),
        };
        let Some([near, far, t2]) = kani_kernels::slerp_pair(a, b) else {
            continue;
        };
        let cn = if a.dot(b) < 0.0 { -b } else { b };
        let inputs = [a.w, a.x, a.y, a.z, cn.w, cn.x, cn.y, cn.z];
        let out = m.run(&inputs.map(f64::from));
        for (name, code) in [("near", near), ("far", far), ("t2", t2)] {
            assert!(
                same_f64(out[name], code),
                "slerp_angle_f64: {name} = {:e} in the model, {code:e} in the code, for {inputs:?}",
                out[name]
            );
        }
    }
}
