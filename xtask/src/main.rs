//! `cargo xtask`: rigtform's measurements (`.cargo/config.toml` aliases
//! `cargo xtask` to `cargo run --package xtask --`).
//!
//! - `cargo xtask m4f [--count-only]`: the Cortex-M4F table. Instructions
//!   executed per call of every operation of `embedded/src/ops.rs` (rigtform
//!   and its peers), on QEMU's `mps2-an386`, and the flash bytes one call
//!   adds to a firmware at opt-level "s" and 3 (`embedded/src/bin/size.rs`
//!   built once per operation and opt-level, `llvm-size` text + data, less
//!   the same firmware calling `ops::empty`; LTO, one codegen unit).
//!   `--count-only` skips the flash builds (a minute instead of several).
//! - `cargo xtask budget`: the counts, then slerp's flash at opt-level "s";
//!   fails unless rigtform's slerp takes at most 400 instructions per call
//!   and 2048 bytes. CI runs it.
//! - `cargo xtask filter-cost [--features F] [--peers [--write-page]]`:
//!   instructions per call of the attitude updates
//!   (`embedded/src/bin/filter_cost.rs`) and the filter's state size on the
//!   target; fails unless a 6D update takes at most 1,600 instructions, a
//!   9D update at most 2,200, and the state at most 256 bytes. CI runs it.
//!   `--peers` counts uf-ahrs's VQF, Mahony and Madgwick in the same run,
//!   on the same samples, and measures each filter's flash at opt-level
//!   "s" (`embedded/src/ops/attitude.rs`): the table of the performance
//!   page's attitude block, which `--write-page` rewrites.
//! - `cargo xtask gltf-check`: rigtform's glTF keyframe samplers against
//!   three.js's interpolants, on BoxAnimated and on random channels
//!   ([`gltf_check`]); fails above 1e-6 rad or 1e-6. CI runs it.
//! - `cargo xtask perf-report [--draws N]`: the tables of the performance
//!   page, `docs/performance.md`: criterion's medians on the host (`cargo bench -p
//!   rigtform-compare --bench ops`), the Cortex-M4F table, and the
//!   accuracy report on 1,000,000 draws per class, written between the
//!   page's `perf-report` markers; the attitude table of `filter-cost
//!   --peers` between its `attitude-cost` markers; the page replaced only
//!   when all of it succeeded.
//! - `cargo xtask prove`: the accuracy constants that provers establish.
//!   Runs every Gappa model of `proofs/gappa/` (and its Sollya scripts),
//!   checks each certificate with `coqc`, runs the test that the models
//!   compute what the code computes, and prints one line per constant of
//!   `src/accuracy.rs` (its proven bound, its value, how it is known, the
//!   model, the time), then `accuracy constants: P proven, S swept, M
//!   measured only` ([`prove`]). Needs Debian's gappa, sollya, coq,
//!   libcoq-flocq and libcoq-gappa. CI runs it.
//!
//! How an instruction count is made: the firmware (`embedded/src/bin/`)
//! calls the two marker functions of `embedded/src/measure.rs` around each
//! measured call and around an empty call just before it, and announces its
//! rows over semihosting (`measure <inputs>|<name>...`, then `measure
//! done <rows>`). QEMU runs it with one instruction per translation block
//! and logs each one executed (`-singlestep -d exec,nochain`); the xtask
//! reads the markers' addresses from the ELF and counts the instructions
//! between them ([`trace`]): per row, the mean over its inputs of the
//! measured bracket less the empty one. The rows, and the functions the
//! flash builds link, come from the firmware's announcement; the host
//! table's rows and columns from the bench's own `--list`.
//!
//! Each subcommand adds what it needs where it can (the thumb target and
//! rustup's `llvm-tools` with rustup, `qemu-system-arm` with apt-get when
//! run as root) and otherwise says how. Progress goes to stderr, tables to
//! stdout; any failure exits with status 1 and a message.

mod criterion;
mod firmware;
mod gltf_check;
mod m4f;
mod page;
mod prove;
mod report;
mod tools;
mod trace;

use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};

/// The command line.
#[derive(Parser)]
#[command(
    name = "cargo xtask",
    bin_name = "cargo xtask",
    about = "rigtform's measurements"
)]
struct Cli {
    #[command(subcommand)]
    command: Cmd,
}

/// The subcommands (see the module documentation).
#[derive(Subcommand)]
enum Cmd {
    /// Cortex-M4F table: instructions per call and flash bytes at opt-level
    /// "s" and 3 of every operation, beside the peers
    M4f {
        /// Only the instruction counts, no flash builds
        #[arg(long)]
        count_only: bool,
        /// rigtform's Cargo features besides the peers
        #[arg(long)]
        features: Option<String>,
    },
    /// Fails unless slerp keeps to 400 instructions per call and 2048 bytes
    /// of flash at opt-level "s" on the Cortex-M4F
    Budget,
    /// Instructions per call of the attitude updates on the Cortex-M4F;
    /// fails unless they and the filter's state keep to their budgets
    FilterCost {
        /// Cargo features of rigtform in the firmware
        #[arg(long)]
        features: Option<String>,
        /// Also counts uf-ahrs's VQF, Mahony and Madgwick on the same
        /// input, and measures every filter's flash
        #[arg(long)]
        peers: bool,
        /// With --peers: writes the table into docs/performance.md's
        /// attitude block
        #[arg(long, requires = "peers")]
        write_page: bool,
    },
    /// rigtform's glTF samplers against three.js's interpolants (npm ci of
    /// tools/gltf-check, then node); fails above 1e-6
    GltfCheck,
    /// Regenerates the tables of docs/performance.md (about 10 minutes)
    PerfReport {
        /// Draws per class of the accuracy report
        #[arg(long, default_value_t = 1_000_000)]
        draws: u64,
    },
    /// Runs the Gappa and Sollya proofs of the accuracy constants, checks
    /// their Coq certificates and the models' correspondence with the code
    Prove {
        /// Only the models of this directory, without the table of
        /// constants (the correspondence test reads its models from it).
        #[arg(long)]
        models: Option<std::path::PathBuf>,
        /// Show that four deliberately wrong variants of the models (a claim of
        /// an assumed bound, a changed coefficient, an unproven side condition,
        /// more precision than the code) each fail, for their own reason.
        #[arg(long, conflicts_with = "models")]
        refuse_wrong: bool,
    },
}

fn main() -> ExitCode {
    match run(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(command: Cmd) -> Result<()> {
    match command {
        Cmd::M4f {
            count_only,
            features,
        } => {
            let ops = m4f::counts(features.as_deref())?;
            let ops = if count_only {
                ops
            } else {
                m4f::with_flash(ops, features.as_deref())?
            };
            print!("{}", m4f::table(&ops));
        }
        Cmd::Budget => m4f::budget()?,
        Cmd::FilterCost {
            features,
            peers,
            write_page,
        } => m4f::filter_budget(features.as_deref(), peers, write_page)?,
        Cmd::PerfReport { draws } => report::perf_report(draws)?,
        Cmd::GltfCheck => gltf_check::gltf_check()?,
        Cmd::Prove {
            models,
            refuse_wrong,
        } => match (models, refuse_wrong) {
            (Some(dir), _) => prove::prove_dir(&dir)?,
            (None, true) => prove::refuse_wrong()?,
            (None, false) => prove::prove_all()?,
        },
    }
    Ok(())
}
