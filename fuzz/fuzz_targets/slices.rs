//! `Quat::slerp_slice` and `RigTForm::interpolate_slice` on slices of every
//! length up to 40: whole steps of sixteen pairs of the x86-64 vector
//! lanes, and every tail. Each element is the single call's result, bit
//! for bit (a NaN where that is NaN), and the elements of `out` past the
//! inputs are left as they were. The pairs mix raw bits with unit inputs,
//! identical, opposite and one-ulp-apart pairs, so that the vector
//! evaluation takes some lanes and leaves others.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::{Cvec3, Quat, RigTForm};

#[derive(arbitrary::Arbitrary, Debug)]
struct Element {
    a: [f32; 4],
    b: [f32; 4],
    t: [f32; 3],
    kind: u8,
}

/// The slices last, so that `arbitrary` reads them from the rest of the
/// bytes, element after element (the seeds' layout).
#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    alpha: f32,
    /// Whether `alpha` is taken into (0, 1], where the vector lanes work.
    alpha_in_unit: bool,
    /// How many elements of `out` beyond the inputs (0 to 3).
    extra: u8,
    elements: Vec<Element>,
}

/// The longest slice: two steps of sixteen pairs and a tail of eight.
const LONGEST: usize = 40;

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat { w, x, y, z }
}

fn unit(q: Quat) -> Quat {
    q.try_normalize().unwrap_or(Quat::IDENTITY)
}

/// `q` with one component one ulp away (the component and direction from
/// `kind`).
fn nudged(q: Quat, kind: u8) -> Quat {
    let step = |c: f32| {
        let bits = if kind & 0x10 == 0 {
            c.to_bits().wrapping_add(1)
        } else {
            c.to_bits().wrapping_sub(1)
        };
        f32::from_bits(bits)
    };
    let mut q = q;
    match (kind >> 5) % 4 {
        0 => q.w = step(q.w),
        1 => q.x = step(q.x),
        2 => q.y = step(q.y),
        _ => q.z = step(q.z),
    }
    q
}

/// The pair an element stands for.
fn pair(e: &Element) -> (Quat, Quat) {
    let (a, b) = (quat(e.a), quat(e.b));
    match e.kind % 6 {
        0 => (a, b),
        1 => (unit(a), unit(b)),
        2 => (unit(a), unit(a)),
        3 => (unit(a), -unit(a)),
        4 => (unit(a), nudged(unit(a), e.kind)),
        _ => (a, a),
    }
}

/// Equal bits, or NaN in the same components (Rust leaves a NaN's sign and
/// payload unspecified).
fn same<const N: usize>(x: [f32; N], y: [f32; N]) -> bool {
    x.iter()
        .zip(&y)
        .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
}

fn floats(q: Quat) -> [f32; 4] {
    [q.w, q.x, q.y, q.z]
}

fuzz_target!(|input: Input| {
    let alpha = if input.alpha_in_unit {
        let f = input.alpha.abs().fract();
        if f > 0.0 {
            f
        } else {
            1.0
        }
    } else {
        input.alpha
    };
    let elements = &input.elements[..input.elements.len().min(LONGEST)];
    let (starts, ends): (Vec<Quat>, Vec<Quat>) = elements.iter().map(pair).unzip();
    let n = starts.len();
    let extra = usize::from(input.extra % 4);
    // A sentinel that no result has: a NaN with a payload.
    let sentinel = Quat {
        w: f32::from_bits(0x7fc0_1234),
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };

    let mut out = vec![sentinel; n + extra];
    Quat::slerp_slice(&starts, &ends, alpha, &mut out);
    for (i, ((a, b), o)) in starts.iter().zip(&ends).zip(&out).enumerate() {
        let want = a.slerp(*b, alpha);
        assert!(
            same(floats(*o), floats(want)),
            "pair {i} of {n}: {a:?} {b:?} {alpha}: {o:?} against {want:?}"
        );
    }
    assert!(out[n..]
        .iter()
        .all(|q| q.w.to_bits() == sentinel.w.to_bits()));

    let tform = |(e, r): (&Element, Quat)| RigTForm {
        t: Cvec3::new(e.t[0], e.t[1], e.t[2]),
        r,
    };
    let ts: Vec<RigTForm> = elements
        .iter()
        .zip(starts.iter().copied())
        .map(tform)
        .collect();
    let te: Vec<RigTForm> = elements
        .iter()
        .zip(ends.iter().copied())
        .map(tform)
        .collect();
    let mut out = vec![RigTForm::IDENTITY; n + extra];
    RigTForm::interpolate_slice(&ts, &te, alpha, &mut out);
    let all = |a: RigTForm| [a.t.x, a.t.y, a.t.z, a.r.w, a.r.x, a.r.y, a.r.z];
    for (i, ((a, b), o)) in ts.iter().zip(&te).zip(&out).enumerate() {
        let want = a.interpolate(*b, alpha);
        assert!(
            same(all(*o), all(want)),
            "element {i} of {n}: {o:?} against {want:?}"
        );
    }
    assert!(out[n..].iter().all(|t| *t == RigTForm::IDENTITY));
});
