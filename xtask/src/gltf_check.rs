//! `cargo xtask gltf-check`: rigtform's glTF samplers against three.js.
//!
//! 1. `npm ci` in `tools/gltf-check/` installs three.js at the version of
//!    its `package-lock.json` (node and npm must be on the path).
//! 2. `rigtform-gltf-samples` (render/src/bin/gltf-samples.rs) writes a
//!    glTF file of random channels (every interpolation, for translations,
//!    rotations and scales), loads it and the committed BoxAnimated asset
//!    with the renderer's reader, and writes their channels and
//!    `rigtform::animation::Sampler`'s samples as JSON.
//! 3. `tools/gltf-check/check.mjs` loads the same two files with three.js's
//!    `GLTFLoader`, checks it read the same keys, evaluates each track's
//!    interpolant at the same times, prints the agreement line and fails
//!    above 1e-6 rad or 1e-6.

use anyhow::{bail, Context, Result};
use std::process::Command;

use crate::tools::{cargo, root, run, say};

/// Runs the comparison; fails if npm, node or either side fails, or if the
/// samples differ by more than 1e-6.
pub fn gltf_check() -> Result<()> {
    let root = root()?;
    let tool = root.join("tools/gltf-check");
    say("npm ci in tools/gltf-check (three.js)");
    run(Command::new("npm")
        .args(["ci", "--no-audit", "--no-fund", "--loglevel=error"])
        .current_dir(&tool))
    .context("npm ci failed: are node and npm installed (apt-get install nodejs npm)?")?;
    let scratch = tempfile::tempdir().context("cannot make a temporary folder")?;
    let random = scratch.path().join("random.gltf");
    let samples = scratch.path().join("samples.json");
    say("rigtform's samples (rigtform-gltf-samples)");
    run(cargo()
        .args([
            "run",
            "--quiet",
            "--release",
            "-p",
            "rigtform-render",
            "--bin",
            "gltf-samples",
            "--",
        ])
        .arg(root.join("render/assets/BoxAnimated/BoxAnimated.gltf"))
        .arg(&random)
        .arg(&samples)
        .current_dir(&root))?;
    say("three.js's samples of the same channels (tools/gltf-check/check.mjs)");
    let status = Command::new("node")
        .arg(tool.join("check.mjs"))
        .arg(&samples)
        .current_dir(&root)
        .status()
        .context("cannot run node")?;
    if !status.success() {
        bail!("three.js and rigtform disagree, or three.js could not load the files (above)");
    }
    Ok(())
}
