//! The programs the measurements need, found or installed: the thumb
//! target and rustup's `llvm-tools` (added with rustup), `qemu-system-arm`
//! (installed with apt-get when run as root on Debian or Ubuntu, otherwise
//! the error says how), and small helpers to run commands.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::OnceLock;

use anyhow::{bail, Context, Result};

/// The target of the emulated Cortex-M4F (QEMU `mps2-an386`).
pub const TARGET: &str = "thumbv7em-none-eabihf";

/// Prints what is being done, on stderr (stdout carries the tables).
pub fn say(what: impl std::fmt::Display) {
    eprintln!("xtask: {what}");
}

/// The root of the repository this runs in, found at run time from the
/// current folder ([`workspace_root_of`]), never from where the xtask was
/// built: one target folder may serve several checkouts, and cargo then
/// runs the xtask another checkout built.
pub fn root() -> Result<PathBuf> {
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    if let Some(root) = ROOT.get() {
        return Ok(root.clone());
    }
    let here = std::env::current_dir().context("cannot read the current folder")?;
    let root = workspace_root_of(&here)?;
    Ok(ROOT.get_or_init(|| root).clone())
}

/// The folder of the cargo workspace that `dir` is in
/// (`cargo locate-project --workspace`), if it is rigtform's (it has
/// `xtask/Cargo.toml`).
pub fn workspace_root_of(dir: &Path) -> Result<PathBuf> {
    let manifest = stdout_of(cargo().current_dir(dir).args([
        "locate-project",
        "--workspace",
        "--message-format",
        "plain",
    ]))
    .with_context(|| {
        format!(
            "{} is in no cargo workspace: run cargo xtask inside the rigtform repository",
            dir.display()
        )
    })?;
    let root = Path::new(manifest.trim())
        .parent()
        .with_context(|| format!("cargo named the manifest {manifest:?}"))?;
    if !root.join("xtask/Cargo.toml").is_file() {
        bail!(
            "the workspace of {} ({}) is not rigtform's (it has no xtask/): \
             run cargo xtask inside the rigtform repository",
            dir.display(),
            root.display()
        );
    }
    Ok(root.to_path_buf())
}

/// The cargo that runs the xtask (`$CARGO`), or the one on the path.
pub fn cargo() -> Command {
    Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
}

/// Runs `cmd` with its stderr shown, and returns its stdout; fails with the
/// command line if it fails to start or exits with an error.
pub fn stdout_of(cmd: &mut Command) -> Result<String> {
    let out = output(cmd.stderr(Stdio::inherit()))?;
    String::from_utf8(out.stdout).with_context(|| format!("{cmd:?} printed something not UTF-8"))
}

/// Runs `cmd` to completion; fails if it does not start or exits with an
/// error, printing its stderr if it was captured.
pub fn output(cmd: &mut Command) -> Result<Output> {
    let out = cmd
        .output()
        .with_context(|| format!("could not run {cmd:?}"))?;
    if !out.status.success() {
        bail!(
            "{cmd:?} failed ({}){}",
            out.status,
            if out.stderr.is_empty() {
                String::new()
            } else {
                format!(":\n{}", String::from_utf8_lossy(&out.stderr).trim_end())
            }
        );
    }
    Ok(out)
}

/// Runs `cmd`, output shown as it comes; fails if it exits with an error.
pub fn run(cmd: &mut Command) -> Result<()> {
    let status = cmd
        .status()
        .with_context(|| format!("could not run {cmd:?}"))?;
    if !status.success() {
        bail!("{cmd:?} failed ({status})");
    }
    Ok(())
}

/// rustc's sysroot and host triple.
fn rustc_sysroot_and_host() -> Result<(PathBuf, String)> {
    let rustc = || Command::new(std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into()));
    let sysroot = stdout_of(rustc().args(["--print", "sysroot"]))?;
    let version = stdout_of(rustc().arg("-vV"))?;
    let host = version
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .context("`rustc -vV` names no host")?;
    Ok((PathBuf::from(sysroot.trim()), host.to_owned()))
}

/// Adds the thumb target with rustup unless the toolchain has it.
pub fn ensure_thumb_target() -> Result<()> {
    let (sysroot, _) = rustc_sysroot_and_host()?;
    if sysroot.join("lib/rustlib").join(TARGET).is_dir() {
        return Ok(());
    }
    say(format!(
        "adding the {TARGET} target (rustup target add {TARGET})"
    ));
    run(Command::new("rustup").args(["target", "add", TARGET])).with_context(|| {
        format!("no {TARGET} target: install it with `rustup target add {TARGET}`")
    })
}

/// The directory of rustup's `llvm-tools` (llvm-size), added with rustup
/// if it is missing.
pub fn llvm_tools() -> Result<PathBuf> {
    let (sysroot, host) = rustc_sysroot_and_host()?;
    let dir = sysroot.join("lib/rustlib").join(host).join("bin");
    if !dir.join("llvm-size").is_file() {
        say("adding rustup's llvm-tools (rustup component add llvm-tools)");
        run(Command::new("rustup").args(["component", "add", "llvm-tools"]))
            .context("llvm-size is missing: install it with `rustup component add llvm-tools`")?;
    }
    if !dir.join("llvm-size").is_file() {
        bail!("no llvm-size in {} after adding llvm-tools", dir.display());
    }
    Ok(dir)
}

/// The version of `qemu-system-arm` (major, minor), installing it with
/// apt-get when it is missing and this runs as root.
pub fn ensure_qemu() -> Result<(u32, u32)> {
    if let Some(version) = qemu_version() {
        return Ok(version);
    }
    let root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| o.stdout.trim_ascii() == b"0");
    if root && Path::new("/usr/bin/apt-get").exists() {
        say("installing qemu-system-arm (apt-get install qemu-system-arm)");
        run(Command::new("apt-get").args(["update", "-qq"]))?;
        run(Command::new("apt-get")
            .args(["install", "-y", "-qq", "qemu-system-arm"])
            .env("DEBIAN_FRONTEND", "noninteractive"))?;
        if let Some(version) = qemu_version() {
            return Ok(version);
        }
    }
    bail!(
        "qemu-system-arm is not installed: install it (Debian or Ubuntu: \
         `sudo apt-get install qemu-system-arm`) and run this again"
    )
}

/// `qemu-system-arm --version`'s (major, minor), `None` if it does not run.
fn qemu_version() -> Option<(u32, u32)> {
    let out = Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .ok()?;
    parse_qemu_version(&String::from_utf8_lossy(&out.stdout))
}

/// (major, minor) from `QEMU emulator version 7.2.22 (Debian ...)`.
pub fn parse_qemu_version(text: &str) -> Option<(u32, u32)> {
    let version = text.split("version ").nth(1)?.split_whitespace().next()?;
    let mut parts = version.split('.').map(|p| p.parse::<u32>().ok());
    Some((parts.next()??, parts.next()??))
}

/// QEMU's flag for one guest instruction per translation block: `-singlestep`,
/// which QEMU 8.1 renamed to `-accel tcg,one-insn-per-tb=on`.
pub fn one_instruction_per_block(version: (u32, u32)) -> &'static [&'static str] {
    if version >= (8, 1) {
        &["-accel", "tcg,one-insn-per-tb=on"]
    } else {
        &["-singlestep"]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_workspace_is_the_one_the_current_folder_is_in() {
        // Tests run in the crate's folder, xtask/ of this checkout.
        let here = Path::new(env!("CARGO_MANIFEST_DIR"));
        let root = workspace_root_of(here).unwrap();
        assert_eq!(root, here.parent().unwrap());
        assert_eq!(workspace_root_of(&root.join("src")).unwrap(), root);
        // A folder in no workspace, and a workspace that is not rigtform's.
        let outside = tempfile::tempdir().unwrap();
        let err = workspace_root_of(outside.path()).unwrap_err();
        assert!(
            format!("{err:#}").contains("in no cargo workspace"),
            "{err:#}"
        );
        std::fs::write(
            outside.path().join("Cargo.toml"),
            "[workspace]\nmembers = []\n",
        )
        .unwrap();
        let err = workspace_root_of(outside.path()).unwrap_err();
        assert!(format!("{err:#}").contains("is not rigtform's"), "{err:#}");
    }

    #[test]
    fn reads_qemu_versions() {
        let text = "QEMU emulator version 7.2.22 (Debian 1:7.2+dfsg-7+deb12u18+b3)\nCopyright";
        assert_eq!(parse_qemu_version(text), Some((7, 2)));
        assert_eq!(
            parse_qemu_version("QEMU emulator version 10.0.0\n"),
            Some((10, 0))
        );
        assert_eq!(parse_qemu_version("something else"), None);
        assert_eq!(one_instruction_per_block((7, 2)), ["-singlestep"]);
        assert_eq!(one_instruction_per_block((8, 1))[0], "-accel");
    }
}
