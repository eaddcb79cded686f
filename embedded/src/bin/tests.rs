//! The no_std subset of `rigtform`'s tests, run on an emulated Cortex-M4F
//! (`cargo test-m4f`) or Cortex-M0 (`cargo test-m0`): every law of
//! `rigtform_proofs::laws::registry::LAWS` on seeded draws (random values,
//! edge values and the slerp edge classes), the attitude checks, and the
//! accuracy this backend reaches on this core against an `f64` reference.

#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::hprintln;
use panic_semihosting as _;
use rigtform::accuracy::{POW_MAX_ANGLE_ERROR, SLERP_MAX_ANGLE_ERROR, UNIT_NORM_ERROR};
use rigtform_embedded::{each, Tally};
use rigtform_proofs::draw::Draws;
use rigtform_proofs::laws::registry::LAWS;
use rigtform_proofs::laws::Violation;
use rigtform_proofs::reference::Quat64;

/// Random draws per law (the host runs far more; this keeps the slowest
/// configuration, soft-float on the M0, to seconds).
const DRAWS: u32 = 2_000;

/// The largest `pow` and `slerp` angle errors per radian turned, and the
/// largest `|norm - 1|`, over random unit inputs and alphas in [-2, 3].
struct Accuracy {
    pow: f64,
    slerp: f64,
    norm: f64,
}

fn measure_accuracy() -> Accuracy {
    let mut d = Draws::new(99);
    let mut worst = Accuracy {
        pow: 0.0,
        slerp: 0.0,
        norm: 0.0,
    };
    for _ in 0..DRAWS {
        let (a, b) = (d.unit_quat(), d.unit_quat());
        let alpha = d.uniform(-2.0, 3.0);
        let (a64, b64) = (Quat64::from(a), Quat64::from(b));
        let turn = |angle: f64| (f64::from(alpha) * angle).abs().max(1.0);

        let p = a.pow(alpha);
        let p64 = a64.pow(alpha.into());
        let half_angle = libm::atan2(
            libm::sqrt(a64.x * a64.x + a64.y * a64.y + a64.z * a64.z),
            a64.w,
        );
        worst.pow = worst
            .pow
            .max(Quat64::angle_between(p.into(), p64) / turn(2.0 * half_angle));

        let s = a.slerp(b, alpha);
        let s64 = Quat64::slerp(a64, b64, alpha.into());
        let theta = Quat64::angle_between(a64, b64);
        worst.slerp = worst
            .slerp
            .max(Quat64::angle_between(s.into(), s64) / turn(theta));

        for q in [p, s, a * b] {
            let n = libm::sqrt((Quat64::from(q) * Quat64::from(q).conj()).w);
            worst.norm = worst.norm.max(libm::fabs(n - 1.0));
        }
    }
    worst
}

fn bounded(law: &'static str, measured: f64, bound: f32) -> Result<u32, Violation> {
    if measured <= f64::from(bound) {
        Ok(DRAWS)
    } else {
        Err(Violation {
            law,
            measured,
            bound: bound.into(),
        })
    }
}

#[entry]
fn main() -> ! {
    let mut t = Tally::default();
    hprintln!("rigtform on-target tests");

    // Every law of the registry, each on its own seeded draws.
    for (seed, law) in (0u64..).zip(LAWS) {
        t.check(law.name, || {
            let mut d = Draws::new(seed);
            each(0..DRAWS, |_| (law.case)(&mut d))
        });
    }

    rigtform_embedded::attitude::check_all(&mut t, DRAWS);

    let accuracy = measure_accuracy();
    hprintln!(
        "accuracy on this core: pow {:.3e} rad per radian turned, slerp {:.3e}, |norm - 1| {:.3e} ({} draws)",
        accuracy.pow,
        accuracy.slerp,
        accuracy.norm,
        DRAWS
    );
    t.check("pow within accuracy::POW_MAX_ANGLE_ERROR", || {
        bounded("pow accuracy", accuracy.pow, POW_MAX_ANGLE_ERROR)
    });
    t.check("slerp within accuracy::SLERP_MAX_ANGLE_ERROR", || {
        bounded("slerp accuracy", accuracy.slerp, SLERP_MAX_ANGLE_ERROR)
    });
    t.check("unit norm within accuracy::UNIT_NORM_ERROR", || {
        bounded("unit norm", accuracy.norm, UNIT_NORM_ERROR)
    });

    t.finish()
}
