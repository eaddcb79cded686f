//! The firmware of `embedded/` (its own workspace, built for the
//! Cortex-M4F): built with cargo, run in QEMU with every executed
//! instruction traced, its markers found in the ELF, its flash measured
//! with `llvm-size`.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};
use object::{Object, ObjectSymbol};

use crate::tools::{self, say, TARGET};
use crate::trace::{self, Markers, Measured};

/// How long one emulation may take before it is taken for a hang (a
/// HardFault loops forever).
const QEMU_TIMEOUT: Duration = Duration::from_secs(300);

/// The function of `embedded/src/ops.rs` that `bin/size.rs` links for the
/// flash baseline (its default) and that `bin/bench.rs` calibrates with.
pub const EMPTY_OP: &str = "empty";

/// The `embedded/` directory.
fn embedded() -> Result<PathBuf> {
    Ok(tools::root()?.join("embedded"))
}

/// One release build of a binary of `embedded/`.
pub struct Build<'a> {
    /// The binary (`bench`, `filter_cost`, `size`).
    pub bin: &'a str,
    /// Cargo features, comma-separated, if any.
    pub features: Option<&'a str>,
    /// Extra environment (the size build's operation and opt-level).
    pub env: Vec<(&'a str, String)>,
    /// A target directory of its own (the size builds keep one per
    /// opt-level, so that they do not rebuild everything each time).
    pub target_dir: Option<PathBuf>,
}

impl<'a> Build<'a> {
    /// A plain release build of `bin` with `features`.
    pub fn new(bin: &'a str, features: Option<&'a str>) -> Self {
        Build {
            bin,
            features,
            env: Vec::new(),
            target_dir: None,
        }
    }

    /// Builds it (quietly: compiler errors and warnings still show) and
    /// returns the ELF's path, as cargo reports it.
    pub fn run(&self) -> Result<PathBuf> {
        let mut cmd = tools::cargo();
        cmd.current_dir(embedded()?).args([
            "build",
            "--quiet",
            "--release",
            "--target",
            TARGET,
            "--message-format=json-render-diagnostics",
            "--bin",
            self.bin,
        ]);
        if let Some(features) = self.features {
            cmd.args(["--features", features]);
        }
        if let Some(dir) = &self.target_dir {
            cmd.arg("--target-dir").arg(dir);
        }
        cmd.envs(self.env.iter().map(|(k, v)| (k, v)));
        let messages = tools::stdout_of(&mut cmd)
            .with_context(|| format!("building the firmware `{}`", self.bin))?;
        executable(&messages, self.bin)
    }
}

/// The executable of `bin` in cargo's JSON messages.
fn executable(messages: &str, bin: &str) -> Result<PathBuf> {
    for line in messages.lines() {
        let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if message["reason"] == "compiler-artifact" && message["target"]["name"] == bin {
            if let Some(path) = message["executable"].as_str() {
                return Ok(PathBuf::from(path));
            }
        }
    }
    bail!("cargo built no executable named {bin}")
}

/// Builds `bin` with `features`, runs it in QEMU with the exec trace, and
/// returns the rows it announced with their instruction counts.
pub fn count(bin: &str, features: Option<&str>) -> Result<Vec<Measured>> {
    count_build(Build::new(bin, features))
}

/// [`count`], the firmware built at `opt_level` instead of the release
/// profile's (in a target directory of its own).
pub fn count_at(bin: &str, features: Option<&str>, opt_level: &str) -> Result<Vec<Measured>> {
    count_build(Build {
        env: vec![("CARGO_PROFILE_RELEASE_OPT_LEVEL", opt_level.to_owned())],
        target_dir: Some(
            embedded()?
                .join("target")
                .join(format!("count-{opt_level}")),
        ),
        ..Build::new(bin, features)
    })
}

/// [`count`] of the firmware `build` makes.
fn count_build(build: Build) -> Result<Vec<Measured>> {
    tools::ensure_thumb_target()?;
    let qemu = tools::ensure_qemu()?;
    let bin = build.bin;
    say(format!(
        "building embedded/src/bin/{bin}.rs for {TARGET}{}{}",
        build
            .features
            .map(|f| format!(" with {f}"))
            .unwrap_or_default(),
        build
            .env
            .iter()
            .map(|(k, v)| format!(", {k}={v}"))
            .collect::<String>()
    ));
    let elf = build.run()?;
    let markers = markers(&elf)?;
    let work = tempfile::tempdir().context("creating a temporary directory for the trace")?;
    let (trace_path, stdout_path) = (work.path().join("trace.log"), work.path().join("stdout"));
    say(format!(
        "running {} in QEMU (mps2-an386), every executed instruction traced",
        elf.display()
    ));
    let mut qemu_cmd = Command::new("qemu-system-arm");
    qemu_cmd
        .args(["-cpu", "cortex-m4", "-machine", "mps2-an386", "-nographic"])
        .args([
            "-monitor",
            "none",
            "-semihosting-config",
            "enable=on,target=native",
        ])
        .args(tools::one_instruction_per_block(qemu))
        .args(["-d", "exec,nochain", "-D"])
        .arg(&trace_path)
        .arg("-kernel")
        .arg(&elf)
        .stdin(Stdio::null())
        .stdout(File::create(&stdout_path)?);
    wait_for(&mut qemu_cmd, QEMU_TIMEOUT)?;
    let output = std::fs::read_to_string(&stdout_path)?;
    let rows = trace::announced_rows(&output)?;
    say(format!(
        "counting the trace's brackets ({} rows)",
        rows.len()
    ));
    let trace = File::open(&trace_path).context("QEMU wrote no trace")?;
    let counts = trace::bracket_counts(BufReader::with_capacity(1 << 20, trace), markers)?;
    trace::measure(&rows, &counts)
}

/// Runs `cmd` to the end, killing it after `timeout`; fails unless it
/// exits with status 0.
fn wait_for(cmd: &mut Command, timeout: Duration) -> Result<()> {
    let mut child = cmd
        .spawn()
        .with_context(|| format!("could not run {cmd:?}"))?;
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait()? {
            if !status.success() {
                bail!("{cmd:?} failed ({status})");
            }
            return Ok(());
        }
        if started.elapsed() > timeout {
            child.kill().ok();
            child.wait().ok();
            bail!("{cmd:?} still ran after {} s: killed", timeout.as_secs());
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// The entry addresses of the two markers in `elf`, Thumb bit cleared.
fn markers(elf: &Path) -> Result<Markers> {
    let data = std::fs::read(elf).with_context(|| format!("reading {}", elf.display()))?;
    let file = object::File::parse(&*data).with_context(|| format!("parsing {}", elf.display()))?;
    let address = |name: &str| {
        file.symbols()
            .find(|s| s.name() == Ok(name))
            .map(|s| s.address() & !1)
            .with_context(|| {
                format!(
                    "{} has no symbol {name}: the firmware must bracket its calls with \
                     rigtform_embedded::measure",
                    elf.display()
                )
            })
    };
    Ok(Markers {
        start: address(trace::START_SYMBOL)?,
        end: address(trace::END_SYMBOL)?,
    })
}

/// The flash bytes (text + data, as `llvm-size` counts them) of the size
/// firmware linking `function` of `embedded/src/ops.rs`, at `opt_level`,
/// built with `features`.
pub fn flash(llvm_tools: &Path, opt_level: &str, function: &str, features: &str) -> Result<u64> {
    let build = Build {
        bin: "size",
        features: Some(features),
        env: vec![
            ("RIGTFORM_SIZE_OP", function.to_owned()),
            ("CARGO_PROFILE_RELEASE_OPT_LEVEL", opt_level.to_owned()),
        ],
        target_dir: Some(embedded()?.join("target").join(format!("size-{opt_level}"))),
    };
    let elf = build.run()?;
    let out = tools::stdout_of(Command::new(llvm_tools.join("llvm-size")).arg(&elf))?;
    berkeley_size(&out).with_context(|| format!("llvm-size of {}", elf.display()))
}

/// text + data from `llvm-size`'s Berkeley format (a header line, then
/// `text data bss dec hex filename`).
pub fn berkeley_size(out: &str) -> Result<u64> {
    let line = out.lines().nth(1).context("no size line")?;
    let numbers: Vec<u64> = line
        .split_whitespace()
        .take(2)
        .map(str::parse)
        .collect::<Result<_, _>>()
        .with_context(|| format!("no text and data sizes in {line:?}"))?;
    match numbers[..] {
        [text, data] => Ok(text + data),
        _ => bail!("no text and data sizes in {line:?}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_text_plus_data() {
        let out = "   text\t   data\t    bss\t    dec\t    hex\tfilename\n   \
                   3072\t      8\t   1032\t   4112\t   1010\ttarget/size\n";
        assert_eq!(berkeley_size(out).unwrap(), 3080);
        assert!(berkeley_size("   text\n").is_err());
        assert!(berkeley_size("h\nerror: no such file\n").is_err());
    }

    #[test]
    fn finds_the_executable_in_cargo_messages() {
        let messages = concat!(
            r#"{"reason":"compiler-artifact","target":{"name":"rigtform"},"executable":null}"#,
            "\n",
            r#"{"reason":"compiler-artifact","target":{"name":"bench"},"executable":"/t/bench"}"#,
            "\n",
            r#"{"reason":"build-finished","success":true}"#,
            "\n"
        );
        assert_eq!(
            executable(messages, "bench").unwrap(),
            PathBuf::from("/t/bench")
        );
        assert!(executable(messages, "size").is_err());
    }
}
