//! `cargo xtask prove`: the accuracy constants that provers establish.
//!
//! Every model of `proofs/gappa/` (`*.g`) is run through Gappa, which
//! writes its proof as a Coq script (`gappa -Bcoq`), and `coqc` checks the
//! script against Flocq and Gappa's Coq library, as many models at once as
//! there are cores. A model's Sollya scripts
//! (`#! sollya FILE HYPOTHESIS`) bound a polynomial's approximation error
//! (`supnorm`), which must not exceed the hypothesis the Gappa model takes
//! it as. Then the correspondence test
//! (`proofs/tests/gappa_correspondence.rs`) checks that the models compute
//! what the library computes, bit for bit.
//!
//! A model says what it proves in `#!` lines:
//!
//! - `#! bound NAME VALUE what`: the constant `NAME` of `src/accuracy.rs`,
//!   over its whole domain, or over the part of it that this model's
//!   branch of the code takes, is at most `VALUE` (with several models,
//!   the constant's proven bound is the largest of theirs);
//! - `#! looser NAME VALUE what`: the quantity `NAME` bounds, on part of
//!   its domain or for one of its operations, is at most `VALUE`, which
//!   is above the constant or covers only that part (the constant is then
//!   only measured);
//! - `#! law - VALUE what`: a law of the contract without a constant.
//!
//! `VALUE` must be the upper end of one of the model's goals, written the
//! same way (`, VALUE]`), so that the certificate proves that very number.
//!
//! A model's rewriting hints (`a -> b;`) enter its certificate as
//! hypotheses: Coq checks the proof given them, and Gappa checks that each
//! is an identity of the reals. Where Gappa cannot (its warning "not
//! trivially equal"), a `bound` claim fails, and the model's looser bounds
//! and laws are printed as given that hint. A certificate that names a rule
//! Gappa has no Coq proof for (`UNKNOWN_...`) fails.
//!
//! Then the laws of `proofs/coq/` (`laws`): Coq files that require the
//! certificates just checked and prove what interval arithmetic cannot
//! (a weighted average of rounding errors); a law's claim
//! `(*! bound NAME THEOREM <= VALUE what *)` counts when coqc has checked
//! the theorem, whose statement ends with that bound.
//!
//! Each constant's doc comment in `src/accuracy.rs` says how it is known, in
//! a line `Known: proven ...`, `Known: swept ...` (every f32 of its domain,
//! by an exhaustive test) or `Known: measured ...`. This fails when a
//! model or certificate fails, when Sollya's bound exceeds its hypothesis,
//! when the correspondence fails, when a constant said proven has no model
//! that proves it or a proven bound above it, when a model proves a
//! constant that does not say so, and when a constant does not say how it
//! is known.

mod checks;
mod goals;
mod laws;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};

use crate::tools::{cargo, output, root, say};
use goals::Claim;

/// A model that Gappa proved and Coq checked.
#[derive(Debug)]
struct Proven {
    model: String,
    claims: Vec<Claim>,
    time: Duration,
    /// Whether some rewriting hint was not checked by Gappa (and so is a
    /// hypothesis of the model's laws and looser bounds).
    unchecked: bool,
}

/// How `src/accuracy.rs` says a constant is known.
#[derive(Debug)]
struct Constant {
    name: String,
    value: f64,
    known: String,
}

/// A number as the models write it: decimal, `NbE` (N 2^E) or hexadecimal.
fn number(t: &str) -> Result<f64> {
    let (negative, t) = match t.trim().strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, t.trim()),
    };
    let sign = if negative { -1.0 } else { 1.0 };
    if let Some(hex) = t.strip_prefix("0x") {
        let (mantissa, exponent) = hex.split_once(['p', 'P']).unwrap_or((hex, "0"));
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let m = u64::from_str_radix(&format!("{int}{frac}"), 16)
            .with_context(|| format!("{t}: not a number"))?;
        let e: i32 = exponent
            .parse()
            .with_context(|| format!("{t}: not a number"))?;
        return Ok(sign * m as f64 * 2f64.powi(e - 4 * frac.len() as i32));
    }
    if let Some((m, e)) = t.split_once('b') {
        let m: i64 = m.parse().with_context(|| format!("{t}: not a number"))?;
        let e: i32 = e.parse().with_context(|| format!("{t}: not a number"))?;
        return Ok(sign * m as f64 * 2f64.powi(e));
    }
    t.parse::<f64>()
        .map(|v| sign * v)
        .with_context(|| format!("{t}: not a number"))
}

/// A model's Sollya scripts, each with the hypothesis its bound must meet.
type SollyaScripts = Vec<(String, String)>;

/// The `#!` claims of a model, each checked against the model's formula
/// (`goals::check_claim`), and its Sollya scripts, whose bound must be the
/// end of one of the model's hypotheses and whose coefficients the model's
/// own.
fn claims(path: &Path, text: &str) -> Result<(Vec<Claim>, SollyaScripts)> {
    let formula = goals::formula(text).with_context(|| format!("{}", path.display()))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut claims = Vec::new();
    let mut sollya = Vec::new();
    for line in text.lines().filter_map(|l| l.strip_prefix("#!")) {
        let kind = line.split_whitespace().next().unwrap_or("");
        if kind == "side" {
            continue;
        }
        if kind == "sollya" {
            let words: Vec<&str> = line.split_whitespace().collect();
            let (file, value) = (
                words.get(1).copied().unwrap_or(""),
                words.get(2).copied().unwrap_or(""),
            );
            let assumed = formula.hypotheses.iter().any(|h| {
                h.interval.as_ref().is_some_and(|(_, lo, hi)| {
                    goals::squeeze(hi) == value && goals::squeeze(lo) == format!("-{value}")
                })
            });
            if !assumed {
                bail!(
                    "{}: the Sollya bound {value} is not the bound of a hypothesis of the model",
                    path.display()
                );
            }
            let script = std::fs::read_to_string(dir.join(file))
                .with_context(|| format!("{}: {file}", path.display()))?;
            checks::same_coefficients(text, file, &script)
                .with_context(|| format!("{}: the polynomial is not {file}'s", path.display()))?;
            sollya.push((file.to_owned(), value.to_owned()));
            continue;
        }
        if !matches!(kind, "bound" | "looser" | "law") {
            bail!("{}: unknown claim `#!{line}`", path.display());
        }
        claims.push(
            goals::check_claim(line, &formula)
                .with_context(|| format!("{}: `#!{line}`", path.display()))?,
        );
    }
    Ok((claims, sollya))
}

/// Sollya's bound: the last line it prints.
fn run_sollya(dir: &Path, file: &str) -> Result<f64> {
    let out = output(
        Command::new("sollya")
            .arg("--warnonstderr")
            .arg(dir.join(file)),
    )
    .context("sollya (Debian: apt-get install sollya)")?;
    let text = String::from_utf8_lossy(&out.stdout);
    let last = text
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("");
    last.trim()
        .parse()
        .with_context(|| format!("{file}: Sollya printed {last:?}, not a bound"))
}

/// Gappa on a model, its certificate written as Coq (`-Bcoq`): its stdout
/// (the certificate) and stderr (warnings, or the error). Gappa orders its
/// proof by where its objects lie in memory, so it runs with the address
/// space laid out the same each time (`setarch -R`, where there is one)
/// and with no environment but `PATH`: a preloaded library (`LD_PRELOAD`,
/// as `stdbuf` and sanitizers set it) or malloc's tunables move its heap
/// and change the proof it finds. The same model then gives the same
/// certificate, byte for byte, which the laws of `proofs/coq/` rely on
/// (they name the certificate's lemmas).
fn run_gappa(path: &Path) -> Result<(bool, String, String)> {
    let mut cmd = if Command::new("setarch").arg("--version").output().is_ok() {
        let mut c = Command::new("setarch");
        c.args(["-R", "gappa"]);
        c
    } else {
        Command::new("gappa")
    };
    cmd.env_clear();
    if let Some(path) = std::env::var_os("PATH") {
        cmd.env("PATH", path);
    }
    let out = cmd
        .arg("-Bcoq")
        .arg(path)
        .output()
        .context("could not run gappa (Debian: apt-get install gappa)")?;
    Ok((
        out.status.success(),
        String::from_utf8(out.stdout).context("gappa's certificate")?,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    ))
}

/// Gappa's error, without the warnings before it.
fn gappa_error(messages: &str) -> String {
    messages
        .lines()
        .skip_while(|l| !l.starts_with("Error"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Where checked certificates are kept between runs: a certificate that
/// coqc has checked is stored under its hash, and an identical one (the
/// same bytes, compared in full) is not checked again.
fn cache_dir() -> Result<PathBuf> {
    let target = match std::env::var_os("CARGO_TARGET_DIR") {
        Some(dir) => PathBuf::from(dir),
        None => root()?.join("target"),
    };
    Ok(target.join("proofs-cache"))
}

/// Checks a certificate with coqc, unless the same certificate was checked
/// before (`cache_dir`). Returns whether coqc ran. Either way the compiled
/// certificate (`STEM.vo`, logical name `Laws.STEM`) is left in `work`,
/// where the laws of `proofs/coq/` require it: the cache keeps it beside
/// the certificate it was compiled from.
fn check_certificate(stem: &str, script: &str, work: &Path) -> Result<bool> {
    if script.contains("Admitted") || script.contains("Axiom") || script.contains("UNKNOWN") {
        bail!("{stem}: the certificate admits something, or uses a rule without a Coq proof");
    }
    let coq = Command::new("coqc")
        .arg("--version")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
        .unwrap_or_default();
    let mut h = std::hash::DefaultHasher::new();
    (script, &coq).hash(&mut h);
    let cache = cache_dir()?;
    let cached = cache.join(format!("{stem}-{:016x}.v", h.finish()));
    let cached_vo = cached.with_extension("vo");
    let vo = work.join(format!("{stem}.vo"));
    if std::fs::read_to_string(&cached).is_ok_and(|c| c == script)
        && std::fs::copy(&cached_vo, &vo).is_ok()
    {
        return Ok(false);
    }
    let v = work.join(format!("{stem}.v"));
    std::fs::write(&v, script).with_context(|| format!("{}", v.display()))?;
    output(
        Command::new("coqc")
            .arg("-Q")
            .arg(work)
            .arg(laws::PREFIX)
            .arg(&v)
            .current_dir(work),
    )
    .with_context(|| format!("coqc rejected the certificate of {stem}.g (Debian: apt-get install coq libcoq-flocq libcoq-gappa)"))?;
    // A cache that cannot be written only costs time next run.
    let _ = std::fs::create_dir_all(&cache)
        .and_then(|()| std::fs::copy(&vo, &cached_vo))
        .and_then(|_| std::fs::write(&cached, script));
    Ok(true)
}

/// Runs one model: its Sollya scripts, Gappa, its side conditions, and Coq
/// on the certificates.
fn prove(path: &Path, work: &Path) -> Result<Proven> {
    let start = Instant::now();
    let text = std::fs::read_to_string(path).with_context(|| format!("{}", path.display()))?;
    let (claims, sollya) = claims(path, &text)?;
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .context("model name")?
        .to_owned();
    let dir = path.parent().context("model directory")?;
    for (file, hypothesis) in sollya {
        let bound = run_sollya(dir, &file)?;
        let hyp = number(&hypothesis)?;
        if bound > hyp {
            bail!("{file}: Sollya bounds the approximation error by {bound:e}, above the {hyp:e} that {stem}.g assumes");
        }
        say(format!(
            "{file}: approximation error at most {bound:.6e} (<= {hypothesis})"
        ));
    }
    let (ok, script, messages) = run_gappa(path)?;
    if !ok || messages.contains("Error") {
        bail!(
            "gappa did not prove {}:\n{}",
            path.display(),
            gappa_error(&messages)
        );
    }
    // A rewriting hint enters the certificate as a hypothesis; Gappa checks
    // that it is an identity of the reals, and says so where it cannot.
    let unchecked = unchecked_hints(&messages);
    if !unchecked.is_empty() && claims.iter().any(|c| c.kind == "bound") {
        bail!(
            "{stem}: claims a bound, but Gappa could not check these hints (they would be hypotheses of the proof):\n{}",
            unchecked.join("\n")
        );
    }
    // Gappa checks a hint as an identity assuming its denominators are not
    // zero: each such side condition is proven here by a model of its own,
    // without the hints.
    let conditions = checks::assumed_nonzero(&messages);
    if !conditions.is_empty() {
        let side = checks::side_condition_model(&text, &conditions)?;
        let side_path = work.join(format!("{stem}_side.g"));
        std::fs::write(&side_path, &side).with_context(|| format!("{}", side_path.display()))?;
        let (ok, side_script, side_messages) = run_gappa(&side_path)?;
        let assumed = checks::assumed_nonzero(&side_messages);
        if !assumed.is_empty() {
            bail!(
                "{stem}: the side conditions' own hints (`#! side`) assume these nonzero:\n  {}",
                assumed.join("\n  ")
            );
        }
        if !ok || side_messages.contains("Error") {
            bail!(
                "{stem}: Gappa assumed these nonzero to check the hints, and no proof without the hints shows it:\n  {}\n{}",
                conditions.join("\n  "),
                gappa_error(&side_messages)
            );
        }
        check_certificate(&format!("{stem}_side"), &side_script, work)?;
    }
    let checked = check_certificate(&stem, &script, work)?;
    let time = start.elapsed();
    say(format!(
        "{stem}.g: proven; certificate of {} lines {}, {} side condition{} proven ({:.1} s)",
        script.lines().count(),
        if checked {
            "checked by coqc"
        } else {
            "checked by coqc before (cached)"
        },
        conditions.len(),
        if conditions.len() == 1 { "" } else { "s" },
        time.as_secs_f64()
    ));
    for hint in &unchecked {
        say(format!(
            "{stem}.g: a hint Gappa could not check, a hypothesis of its laws: {hint}"
        ));
    }
    Ok(Proven {
        model: format!("{stem}.g"),
        claims,
        time,
        unchecked: !unchecked.is_empty(),
    })
}

/// The rewriting hints Gappa could not verify as identities (its warning
/// `A and B are not trivially equal`), one line each.
fn unchecked_hints(messages: &str) -> Vec<String> {
    messages
        .lines()
        .filter(|l| l.contains("are not trivially equal"))
        .map(|l| l.trim_start_matches("Warning: ").trim().to_owned())
        .collect()
}

/// The constants of `src/accuracy.rs` (the default backend's values) and
/// how each says it is known.
fn constants(text: &str) -> Result<Vec<Constant>> {
    let backend = text
        .split_once("\nmod backend {")
        .and_then(|(_, b)| b.split_once("\n}"))
        .map(|(b, _)| b)
        .context("src/accuracy.rs: no default backend module")?;
    let value_of = |expr: &str| -> Result<f64> {
        match expr.strip_prefix("backend::") {
            Some(name) => {
                let line = backend
                    .lines()
                    .find(|l| {
                        l.trim_start()
                            .starts_with(&format!("pub const {name}: f32 = "))
                    })
                    .with_context(|| format!("backend::{name} not found"))?;
                let v = line.split_once(" = ").map(|(_, v)| v).unwrap_or("");
                let v = v.split(';').next().unwrap_or("").trim();
                v.parse::<f32>()
                    .map(f64::from)
                    .with_context(|| format!("{name} = {v}"))
            }
            None => expr
                .parse::<f32>()
                .map(f64::from)
                .with_context(|| format!("{expr}: not a number")),
        }
    };
    let mut out = Vec::new();
    let mut doc = String::new();
    for line in text.lines() {
        if let Some(d) = line.strip_prefix("///") {
            doc.push_str(d);
            doc.push('\n');
            continue;
        }
        if let Some(rest) = line.strip_prefix("pub const ") {
            let (name, rest) = rest.split_once(':').context("constant")?;
            let expr = rest
                .split_once(" = ")
                .map(|(_, v)| v)
                .unwrap_or("")
                .split(';')
                .next()
                .unwrap_or("")
                .trim();
            let known = doc
                .split_once("Known:")
                .map(|(_, k)| {
                    k.split_whitespace()
                        .next()
                        .unwrap_or("")
                        .trim_end_matches([':', '.', ','])
                })
                .unwrap_or("")
                .to_owned();
            out.push(Constant {
                name: name.to_owned(),
                value: value_of(expr)?,
                known,
            });
        }
        if !line.trim().is_empty() {
            doc.clear();
        }
    }
    Ok(out)
}

/// Runs [`prove`] on every model, as many at once as there are cores
/// (Coq checks one certificate per process, so this is where the time
/// goes), and returns the results in the models' order, or the first
/// model's error in that order. After a failure no further model starts.
fn prove_in_parallel(models: &[std::path::PathBuf], work: &Path) -> Result<Vec<Proven>> {
    let jobs = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, models.len().max(1));
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let results: Vec<Mutex<Option<Result<Proven>>>> =
        models.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| loop {
                if failed.load(Ordering::Relaxed) {
                    break;
                }
                // Models start in order, so every model before a failed one
                // has started and finishes.
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(model) = models.get(i) else { break };
                let result = prove(model, work);
                if result.is_err() {
                    failed.store(true, Ordering::Relaxed);
                }
                if let Ok(mut slot) = results[i].lock() {
                    *slot = Some(result);
                }
            });
        }
    });
    results
        .into_iter()
        .zip(models)
        .map(|(slot, model)| {
            slot.into_inner()
                .ok()
                .flatten()
                .unwrap_or_else(|| bail!("{}: no result", model.display()))
        })
        .collect()
}

/// What a model's claims rest on beyond its certificate.
fn given(p: &Proven) -> &'static str {
    if p.unchecked {
        " (given a hint Gappa could not check)"
    } else {
        ""
    }
}

/// The correspondence test (`proofs/tests/gappa_correspondence.rs`): the
/// models compute the code's bits, and round every operation to the
/// code's type. `dir` is the models' directory (the test reads it from
/// `RIGTFORM_GAPPA_DIR`).
fn correspondence(root: &Path, dir: &Path) -> Result<()> {
    say("the correspondence of models and code, and their formats (cargo test -p rigtform-proofs --test gappa_correspondence)");
    let test = cargo()
        .args([
            "test",
            "-q",
            "-p",
            "rigtform-proofs",
            "--test",
            "gappa_correspondence",
        ])
        .env("RIGTFORM_GAPPA_DIR", dir)
        .current_dir(root)
        .output()
        .context("could not run cargo test")?;
    if !test.status.success() {
        let out = String::from_utf8_lossy(&test.stdout);
        let failures: Vec<_> = out
            .lines()
            .filter(|l| {
                l.contains("panicked at")
                    || l.contains(" in the model, ")
                    || l.contains("the code computes in")
            })
            .collect();
        bail!(
            "the models and the code no longer compute the same thing:\n{}\n{}",
            failures.join("\n"),
            String::from_utf8_lossy(&test.stderr).trim_end()
        );
    }
    Ok(())
}

/// The models of `dir` (`*.g`), in order of name.
fn models_in(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut models: Vec<_> = std::fs::read_dir(dir)
        .with_context(|| format!("{}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "g"))
        .collect();
    models.sort();
    if models.is_empty() {
        bail!("no models in {}", dir.display());
    }
    Ok(models)
}

/// Runs the checks on the models of `dir` alone (the correspondence test
/// first, then each model), without the table of constants: what
/// `cargo xtask prove --models DIR` does, and how the deliberately wrong
/// models of [`refuse_wrong`] are shown to fail.
pub fn prove_dir(dir: &Path) -> Result<()> {
    let root = root()?;
    let models = models_in(dir)?;
    correspondence(&root, dir)?;
    let work = tempfile::tempdir().context("a directory for the certificates")?;
    for p in prove_in_parallel(&models, work.path())? {
        for c in &p.claims {
            println!("{}: {} {} <= {:e}", p.model, c.kind, c.name, c.value);
        }
    }
    Ok(())
}

/// A deliberately wrong variant of a model: made from the model and the
/// files it reads by one change, and the reason the checker must give.
struct Wrong {
    case: &'static str,
    files: &'static [&'static str],
    file: &'static str,
    change: (&'static str, &'static str),
    reason: &'static str,
}

/// The four wrong claims that must not pass: a claim of a bound the model
/// assumes (the approximation error of arc_f64.g, which Sollya bounds), a
/// Sollya script whose polynomial is not the model's (one coefficient
/// changed), a hint whose side condition nothing proves (sinc_f64.g
/// without its hypothesis that sin(x) / x is in [0.63, 1], so that it may
/// be 0 where a hint divides by it), and a model more precise than the
/// code (one rounding of the product in f64).
const WRONG: [Wrong; 4] = [
    Wrong {
        case: "a claim of a bound the model assumes",
        files: &["arc_f64.g", "atan_f64.sollya"],
        file: "arc_f64.g",
        change: (
            "#! bound PHI_OVER_SINE",
            "#! bound PHI_SQUARED_F64_MAX_REL_ERROR (H - At) / At in [-1.6959e-8, 1.6959e-8] the polynomial's error\n#! bound PHI_OVER_SINE",
        ),
        reason: "is a hypothesis of the model, not a goal it proves",
    },
    Wrong {
        case: "a changed coefficient",
        files: &["sinc_f64.g", "sinc_f64.sollya"],
        file: "sinc_f64.sollya",
        change: ("s1 = 0x1.110ed38056595p-7", "s1 = 0x1.110ed38056596p-7"),
        reason: "coefficient 1: the model computes with",
    },
    Wrong {
        case: "a side condition nothing proves",
        files: &["sinc_f64.g", "sinc_f64.sollya"],
        file: "sinc_f64.g",
        change: (" Sc in [0.63, 1] /\\", ""),
        reason: "Gappa assumed these nonzero to check the hints, and no proof without the hints shows it",
    },
    Wrong {
        case: "a model more precise than the code",
        files: &["mul.g"],
        file: "mul.g",
        change: ("px rnd=", "px wide=\n"),
        reason: "px rounds to ieee_64, but the code computes in f32",
    },
];

/// Runs [`prove_dir`] on each deliberately wrong model (made in a
/// temporary directory from the models of `proofs/gappa/`) and fails
/// unless each fails, for its own reason.
pub fn refuse_wrong() -> Result<()> {
    let models = root()?.join("proofs/gappa");
    for w in WRONG {
        let dir = tempfile::tempdir().context("a directory for the wrong model")?;
        for f in w.files {
            let mut text =
                std::fs::read_to_string(models.join(f)).with_context(|| f.to_string())?;
            if *f == w.file {
                if !text.contains(w.change.0) {
                    bail!(
                        "{f} no longer contains {:?}: update the wrong model",
                        w.change.0
                    );
                }
                text = text.replacen(w.change.0, w.change.1, 1);
                if w.change.1.starts_with("px wide=") {
                    text = text.replacen(
                        "@rnd = float<ieee_32, ne>;",
                        "@rnd = float<ieee_32, ne>;\n@wide = float<ieee_64, ne>;",
                        1,
                    );
                }
            }
            std::fs::write(dir.path().join(f), text).with_context(|| f.to_string())?;
        }
        say(format!("a deliberately wrong model: {}", w.case));
        match prove_dir(dir.path()) {
            Ok(()) => bail!("{}: the checker accepted it", w.case),
            Err(e) => {
                let message = format!("{e:#}");
                if !message.contains(w.reason) {
                    bail!(
                        "{}: refused, but not because {:?}:\n{message}",
                        w.case,
                        w.reason
                    );
                }
                println!("refused, as it must be: {}:", w.case);
                for line in message.lines().take(5) {
                    println!("    {}", line.chars().take(200).collect::<String>());
                }
            }
        }
    }
    println!("the checker refused all {} wrong models", WRONG.len());
    Ok(())
}

/// Runs everything; prints one line per constant and the count.
pub fn prove_all() -> Result<()> {
    let root = root()?;
    let dir = root.join("proofs/gappa");
    let models = models_in(&dir)?;
    correspondence(&root, &dir)?;
    let work = tempfile::tempdir().context("a directory for the certificates")?;
    let mut proven = prove_in_parallel(&models, work.path())?;
    // The laws proven in Coq on the certificates just checked.
    let laws = laws::prove_laws(&root.join("proofs/coq"), work.path(), &proven)?;
    proven.extend(laws);

    let accuracy =
        std::fs::read_to_string(root.join("src/accuracy.rs")).context("src/accuracy.rs")?;
    let constants = constants(&accuracy)?;
    let mut by_name: BTreeMap<&str, Vec<(&Proven, &Claim)>> = BTreeMap::new();
    for p in &proven {
        for c in &p.claims {
            by_name.entry(c.name.as_str()).or_default().push((p, c));
        }
    }
    for name in by_name.keys().filter(|n| **n != "-") {
        if !constants.iter().any(|c| c.name == *name) {
            bail!("a model claims {name}, which src/accuracy.rs does not define");
        }
    }

    let mut table = String::new();
    let mut errors = Vec::new();
    let (mut p, mut s, mut m) = (0, 0, 0);
    // Not error bounds: chosen tolerances and figures measured on a
    // benchmark recording, counted apart.
    let (mut tolerances, mut benchmarks) = (0, 0);
    let _ = writeln!(
        table,
        "{:<38} {:>11} {:>10}  {:<9} {:<28} {:>7}",
        "constant", "proven", "constant", "known", "model", "time"
    );
    for c in &constants {
        let claims = by_name
            .get(c.name.as_str())
            .map(Vec::as_slice)
            .unwrap_or(&[]);
        // A constant's domain may be split among models (one per branch of
        // the code): its proven bound is the largest of theirs.
        let bounds: Vec<_> = claims.iter().filter(|(_, cl)| cl.kind == "bound").collect();
        let bound = bounds
            .iter()
            .copied()
            .max_by(|a, b| a.1.value.total_cmp(&b.1.value));
        // Several models may each prove a looser bound for one of the
        // constant's operations: the table shows the largest (what holds
        // for all of them) and names every model.
        let loosers: Vec<_> = claims
            .iter()
            .filter(|(_, cl)| cl.kind == "looser")
            .collect();
        let looser = loosers
            .iter()
            .copied()
            .max_by(|a, b| a.1.value.total_cmp(&b.1.value));
        match c.known.as_str() {
            "proven" => {
                p += 1;
                match bound {
                    None => errors.push(format!(
                        "{} says it is proven, but no model proves it",
                        c.name
                    )),
                    Some((_, cl)) if cl.value > c.value => errors.push(format!(
                        "{}: the proven bound {:e} exceeds the constant {:e}",
                        c.name, cl.value, c.value
                    )),
                    Some(_) => {}
                }
            }
            "swept" => s += 1,
            "measured" => m += 1,
            "tolerance" => tolerances += 1,
            "benchmark" => benchmarks += 1,
            "" => errors.push(format!(
                "{}: its doc does not say how it is known (`Known:`)",
                c.name
            )),
            other => errors.push(format!(
                "{}: `Known: {other}` is not proven, swept, measured, tolerance or benchmark",
                c.name
            )),
        }
        if bound.is_some() && c.known != "proven" {
            errors.push(format!(
                "{} is proven by a model, but its doc says `Known: {}`",
                c.name, c.known
            ));
        }
        // The models behind a figure, joined, and their time together.
        let models_and_time = |claims: &[&(&Proven, &Claim)]| {
            let names: Vec<_> = claims.iter().map(|(pr, _)| pr.model.as_str()).collect();
            let seconds: f64 = claims.iter().map(|(pr, _)| pr.time.as_secs_f64()).sum();
            (names.join("+"), format!("{seconds:.1} s"))
        };
        let (proof, model, time) = match (bound, looser) {
            (Some((_, cl)), _) => {
                let (model, time) = models_and_time(&bounds);
                (format!("{:.3e}", cl.value), model, time)
            }
            (None, Some((_, cl))) => {
                let (model, time) = models_and_time(&loosers);
                (format!("{:.3e}*", cl.value), model, time)
            }
            (None, None) => ("-".into(), "-".into(), "-".into()),
        };
        let _ = writeln!(
            table,
            "{:<38} {:>11} {:>10.3e}  {:<9} {:<28} {:>7}",
            c.name, proof, c.value, c.known, model, time
        );
    }
    println!("{table}");
    println!("* a proven bound on part of the constant's domain or above it (with several models, the largest); the constant itself is swept or measured");
    println!();
    println!("looser bounds, per model:");
    for pr in &proven {
        for cl in pr.claims.iter().filter(|c| c.kind == "looser") {
            println!(
                "  {:<19} {:.3e}  {}: {}{}",
                pr.model,
                cl.value,
                cl.name,
                cl.text,
                given(pr)
            );
        }
    }
    println!();
    println!("laws proven without a constant:");
    for pr in &proven {
        for cl in pr.claims.iter().filter(|c| c.kind == "law") {
            println!(
                "  {:<19} {:.3e}  {}{}",
                pr.model,
                cl.value,
                cl.text,
                given(pr)
            );
        }
    }
    println!();
    println!(
        "not error bounds: {tolerances} tolerance{}, {benchmarks} benchmark figure{}",
        if tolerances == 1 { "" } else { "s" },
        if benchmarks == 1 { "" } else { "s" }
    );
    println!("accuracy constants: {p} proven, {s} swept, {m} measured only");
    if !errors.is_empty() {
        bail!("{}", errors.join("\n"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_the_models_notations() {
        assert_eq!(number("7b-24").ok(), Some(7.0 * 2f64.powi(-24)));
        assert_eq!(number("0x1.8p-1").ok(), Some(0.75));
        assert_eq!(number("6.057e-9").ok(), Some(6.057e-9));
        assert_eq!(number("-0x1.8p-1").ok(), Some(-0.75));
        assert!(number("x").is_err());
    }

    #[test]
    fn a_claim_must_be_a_goal_of_its_model() {
        let model = "#! bound A y in [0, 1b-3] what\n{ x in [0, 1] -> y in [0, 1b-3] }";
        let (c, _) = claims(Path::new("m.g"), model).expect("claim");
        assert_eq!((c[0].name.as_str(), c[0].value), ("A", 0.125));
        let wrong = "#! bound A y in [0, 1b-4] what\n{ x in [0, 1] -> y in [0, 1b-3] }";
        assert!(claims(Path::new("m.g"), wrong).is_err());
        let assumed = "#! bound A x in [0, 1] what\n{ x in [0, 1] -> y in [0, 1b-3] }";
        assert!(claims(Path::new("m.g"), assumed).is_err());
    }

    #[test]
    fn hints_gappa_could_not_check_are_found() {
        let messages = "Warning: no need for the rewriting at line 3\nWarning: a and b * c are not trivially equal.\n         Difference: a - b * c\n";
        assert_eq!(
            unchecked_hints(messages),
            ["a and b * c are not trivially equal."]
        );
        assert!(unchecked_hints("Warning: no need for the rewriting").is_empty());
    }

    #[test]
    fn constants_and_how_they_are_known() {
        let text = "\nmod backend {\n    pub const B: f32 = 2.5e-7; // x\n}\n\n/// B's doc.\n/// Known: measured over draws.\npub const B: f32 = backend::B;\n/// A's doc.\n/// Known: proven: a.g.\npub const A: f32 = 1.0; // y\npub const C: f32 = 3.0;\n";
        let c = constants(text).expect("constants");
        let got: Vec<_> = c
            .iter()
            .map(|c| (c.name.as_str(), c.value, c.known.as_str()))
            .collect();
        assert_eq!(
            got,
            [
                ("B", 2.5e-7f32 as f64, "measured"),
                ("A", 1.0, "proven"),
                ("C", 3.0, "")
            ]
        );
    }
}
