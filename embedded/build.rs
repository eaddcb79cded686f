//! Puts the memory map of the emulated board that matches the target on
//! the linker's search path as `memory.x` (cortex-m-rt's `link.x` includes it),
//! and names the one operation `bin/size.rs` links (`RIGTFORM_SIZE_OP`, a
//! function of `src/ops.rs`; `empty` by default).

use std::{env, fs, path::PathBuf};

fn main() {
    let target = env::var("TARGET").unwrap_or_default();
    let board = if target.starts_with("thumbv6m") {
        "memory/microbit.x"
    } else {
        "memory/mps2-an386.x"
    };
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy(board, out.join("memory.x")).expect("the memory map is in the repository");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed={board}");

    let op = env::var("RIGTFORM_SIZE_OP").unwrap_or_else(|_| "empty".into());
    assert!(
        op.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'),
        "RIGTFORM_SIZE_OP must name a function of src/ops.rs, not {op:?}"
    );
    fs::write(
        out.join("size_op.rs"),
        format!("const OP: rigtform_embedded::ops::Op = rigtform_embedded::ops::{op};\n"),
    )
    .expect("OUT_DIR is writable");
    println!("cargo:rerun-if-env-changed=RIGTFORM_SIZE_OP");
    println!("cargo:rerun-if-changed=build.rs");
}
