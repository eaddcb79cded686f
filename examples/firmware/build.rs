//! Puts the memory map of the board for the target on the linker's search
//! path as `memory.x`, which cortex-m-rt's `link.x` includes: the micro:bit
//! v2 (nRF52833) for the Cortex-M4F, the micro:bit v1 (nRF51822) for the
//! Cortex-M0. The MPU-6050 firmware (feature `microbit-v2`) also links
//! defmt's linker script, which places its log strings.

use std::{env, fs, path::PathBuf};

fn main() {
    let target = env::var("TARGET").unwrap_or_default();
    let board = if target.starts_with("thumbv6m") {
        "memory/microbit.x"
    } else {
        "memory/microbit-v2.x"
    };
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy(board, out.join("memory.x")).expect("the memory map is in the repository");
    println!("cargo:rustc-link-search={}", out.display());
    if env::var_os("CARGO_FEATURE_MICROBIT_V2").is_some() {
        println!("cargo:rustc-link-arg-bin=imu-mpu6050=-Tdefmt.x");
    }
    println!("cargo:rerun-if-changed={board}");
    println!("cargo:rerun-if-changed=build.rs");
}
