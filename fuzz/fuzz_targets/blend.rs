//! `Quat::blend` over the whole range of finite weights, from subnormal to
//! `f32::MAX`: unit (or the identity, for weights that cancel) for unit
//! inputs and finite weights, NaN for a NaN or infinite input or weight,
//! the identity for no entry, and the same result, bit for bit, with every
//! weight scaled by a power of two that keeps them exact.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rigtform::Quat;
use rigtform_proofs::laws::{self, assert_holds};

/// The entries last, so that `arbitrary` reads them from the rest of the
/// bytes, entry after entry (the seeds' layout).
#[derive(arbitrary::Arbitrary, Debug)]
struct Input {
    /// Whether the quaternions are normalized first.
    normalize: bool,
    /// The power of two for the scaled blend, -63 to 63.
    power: i8,
    entries: Vec<([f32; 4], f32)>,
}

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat { w, x, y, z }
}

fn same_bits(a: Quat, b: Quat) -> bool {
    [a.w, a.x, a.y, a.z]
        .iter()
        .zip([b.w, b.x, b.y, b.z])
        .all(|(x, y)| x.to_bits() == y.to_bits())
}

fuzz_target!(|input: Input| {
    let entries: Vec<(Quat, f32)> = input
        .entries
        .iter()
        .take(8)
        .map(|&(q, w)| {
            let q = quat(q);
            let q = if input.normalize {
                q.try_normalize().unwrap_or(q)
            } else {
                q
            };
            (q, w)
        })
        .collect();
    let r = Quat::blend(&entries);
    if entries.is_empty() {
        assert_eq!(r, Quat::IDENTITY);
        return;
    }
    if entries
        .iter()
        .any(|(q, w)| !(q.is_finite() && w.is_finite()))
    {
        assert!(r.is_nan(), "{entries:?}: {r:?}");
        return;
    }
    let unit = |q: &Quat| (q.norm() - 1.0).abs() <= 1e-6;
    if !entries.iter().all(|(q, _)| unit(q)) {
        // Outside the precondition: no panic is all there is to check.
        return;
    }
    assert_holds(laws::blend_is_unit_or_identity(&entries));
    // The weights times 2^power, where every one stays exact (finite, and
    // back to itself when divided again): the same blend, bit for bit,
    // where every product of a weight and a component is normal in both
    // (nonzero components at least 2^-60, nonzero weights at least 2^-60 of
    // the largest): rounding to a subnormal product is not scale-free.
    let largest = entries.iter().fold(0.0f32, |m, e| m.max(e.1.abs()));
    let normal_products = entries.iter().all(|(q, w)| {
        let tiny = 2.0f32.powi(-60);
        [q.w, q.x, q.y, q.z]
            .iter()
            .all(|c| *c == 0.0 || c.abs() >= tiny)
            && (*w == 0.0 || w.abs() >= largest * tiny)
    });
    let scale = 2.0f32.powi(i32::from(input.power % 64));
    let scaled: Vec<(Quat, f32)> = entries.iter().map(|&(q, w)| (q, w * scale)).collect();
    let exact = scaled
        .iter()
        .zip(&entries)
        .all(|(s, e)| s.1.is_finite() && s.1 / scale == e.1 && (s.1 == 0.0 || s.1.is_normal()))
        && entries.iter().all(|e| e.1 == 0.0 || e.1.is_normal());
    if exact && normal_products {
        let again = Quat::blend(&scaled);
        assert!(
            same_bits(again, r),
            "{entries:?} by {scale}: {again:?} against {r:?}"
        );
    }
});
