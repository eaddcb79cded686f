//! `slerp_slice` and `interpolate_slice` raise no floating-point exception
//! that `slerp` on the same pairs does not: run with the exceptions
//! unmasked (`feenableexcept`), where one raised is a SIGFPE that ends the
//! test binary. Linux with glibc on x86-64, where the vector steps are.
#![cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
#![allow(unsafe_code)]

use rigtform::{Cvec3, Quat, RigTForm};

extern "C" {
    fn feenableexcept(excepts: i32) -> i32;
    fn fedisableexcept(excepts: i32) -> i32;
}

/// glibc's x86 bits: FE_INVALID and FE_DIVBYZERO.
const FE_INVALID: i32 = 0x01;
const FE_DIVBYZERO: i32 = 0x04;

/// Runs `f` with `excepts` unmasked on this thread (a SIGFPE if one is
/// raised), and masked again after.
fn trapping<R>(excepts: i32, f: impl FnOnce() -> R) -> R {
    // SAFETY: glibc's functions change this thread's floating-point
    // control registers only; they are restored below.
    let before = unsafe { feenableexcept(excepts) };
    assert_ne!(before, -1, "feenableexcept failed");
    let r = f();
    // SAFETY: as above.
    unsafe { fedisableexcept(excepts) };
    r
}

/// Pairs of every kind `slerp` meets on unit inputs: identical (the zero
/// wedge), antipodal, nearly identical, a quarter turn apart, and random.
fn pairs(n: usize) -> (Vec<Quat>, Vec<Quat>) {
    let kinds = |i: usize| {
        let a = Quat::from_axis_angle(Cvec3::new(1.0, 2.0, 3.0).normalize(), 0.1 * i as f32);
        match i % 5 {
            0 | 3 => (a, a),
            1 => (a, -a),
            2 => (a, a * Quat::from_rotation_z(1e-6)),
            _ => (a, Quat::from_rotation_y(0.7 + i as f32)),
        }
    };
    (0..n).map(kinds).unzip()
}

#[test]
fn slices_raise_no_exception_slerp_does_not() {
    // Every length up to 40: whole steps of 16 pairs and every tail.
    for n in 1..=40 {
        let (starts, ends) = pairs(n);
        let tforms = |qs: &[Quat]| -> Vec<RigTForm> {
            qs.iter()
                .map(|&r| RigTForm {
                    t: Cvec3::new(1.0, -2.0, 0.5),
                    r,
                })
                .collect()
        };
        let (ts, te) = (tforms(&starts), tforms(&ends));
        for alpha in [0.25, 0.5, 1.0, 1e-3] {
            let excepts = FE_DIVBYZERO | FE_INVALID;
            // The single calls first: the exceptions they raise are not
            // the slices' to avoid.
            let single: Vec<Quat> = trapping(excepts, || {
                starts
                    .iter()
                    .zip(&ends)
                    .map(|(a, b)| a.slerp(*b, alpha))
                    .collect()
            });
            let mut out = vec![Quat::IDENTITY; n];
            trapping(excepts, || {
                Quat::slerp_slice(&starts, &ends, alpha, &mut out)
            });
            assert_eq!(out, single, "length {n}, alpha {alpha}");
            let mut out = vec![RigTForm::IDENTITY; n];
            trapping(excepts, || {
                RigTForm::interpolate_slice(&ts, &te, alpha, &mut out)
            });
            let rotations: Vec<Quat> = out.iter().map(|t| t.r).collect();
            assert_eq!(rotations, single, "length {n}, alpha {alpha}");
        }
    }
}
