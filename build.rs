//! Names the library's build conditions once. Each `cfg` the source tests
//! that combines the target's architecture, its features and Kani is
//! decided here, from what Cargo says of the target (`CARGO_CFG_*`), and
//! handed to the compiler as one plain name (`--cfg NAME`): the source says
//! `#[cfg(x86_sse_lanes)]`, never the conditions behind it.
//!
//! Kani: `cargo kani` compiles this script with `cfg(kani)` and the crate
//! with `--cfg kani`; the Kani mock stage of CI passes `--cfg kani` in
//! `RUSTFLAGS`, which Cargo reports as `CARGO_CFG_KANI`. Either way the
//! names that need code Kani cannot read (intrinsics, inline assembly) are
//! off under Kani.

use std::env;

/// The names, in the order `holds` defines them.
const NAMES: [&str; 7] = [
    "desktop64",
    "x86_sse_lanes",
    "x86_avx_lanes",
    "portable_lanes",
    "arm_fpu_sqrt",
    "vector_unit_sqrt",
    "kernels_exported",
];

/// What Cargo says of the target being built.
struct Target {
    arch: String,
    abi: String,
    features: Vec<String>,
    kani: bool,
    kernel_contracts: bool,
}

impl Target {
    fn from_env() -> Self {
        let var = |name: &str| env::var(name).unwrap_or_default();
        Target {
            arch: var("CARGO_CFG_TARGET_ARCH"),
            abi: var("CARGO_CFG_TARGET_ABI"),
            features: var("CARGO_CFG_TARGET_FEATURE")
                .split(',')
                .map(str::to_owned)
                .collect(),
            kani: cfg!(kani) || env::var_os("CARGO_CFG_KANI").is_some(),
            kernel_contracts: env::var_os("CARGO_FEATURE_KERNEL_CONTRACTS").is_some(),
        }
    }

    fn has(&self, feature: &str) -> bool {
        self.features.iter().any(|f| f == feature)
    }

    /// Whether the name holds for this target.
    fn holds(&self, name: &str) -> bool {
        let x86_64 = self.arch == "x86_64";
        let aarch64 = self.arch == "aarch64";
        match name {
            // f64 costs what f32 does (slerp evaluates in f64), and the
            // public operations inline across crates.
            "desktop64" => x86_64 || aarch64,
            // The quaternion product and the slice steps in SSE registers,
            // through core::arch's intrinsics, which Kani cannot read.
            "x86_sse_lanes" => x86_64 && self.has("sse2") && !self.kani,
            // The slice steps in AVX registers.
            "x86_avx_lanes" => x86_64 && self.has("avx") && !self.kani,
            // The slices in blocks the compiler vectorizes.
            "portable_lanes" => self.holds("desktop64") && !self.holds("x86_sse_lanes"),
            // The square root is the FPU's `vsqrt.f32` (inline assembly).
            "arm_fpu_sqrt" => self.arch == "arm" && self.abi == "eabihf" && !self.kani,
            // The square root is the vector unit's, through an intrinsic
            // a loop vectorizes.
            "vector_unit_sqrt" => {
                ((x86_64 && self.has("sse")) || (aarch64 && self.has("neon"))) && !self.kani
            }
            // The float kernels re-exported (`rigtform::kani_kernels`) for
            // the proofs crate's stubs and contract tests.
            "kernels_exported" => self.kani || self.kernel_contracts,
            _ => unreachable!("a name without a condition: {name}"),
        }
    }
}

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    let target = Target::from_env();
    for name in NAMES {
        println!("cargo::rustc-check-cfg=cfg({name})");
        if target.holds(name) {
            println!("cargo::rustc-cfg={name}");
        }
    }
}
