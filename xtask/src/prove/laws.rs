//! The laws proven in Coq on top of the Gappa certificates
//! (`proofs/coq/*.v`).
//!
//! Gappa bounds one quantity at a time by interval arithmetic; a law such
//! as the norm of a result needs a step it cannot take (the rounding
//! errors of the components, weighted by the components, average to at
//! most one rounding). A law file `Require`s the certificates it builds
//! on (`Require Laws.MODEL.`, the certificate of `proofs/gappa/MODEL.g`
//! that this run checked), proves the hypotheses of their theorems and
//! their rewriting hints, and states its own theorem on the code's
//! arithmetic (Flocq's rounding, as the certificates write it). A law may
//! build on another law the same way (`Require Laws.LAW.`): it is
//! compiled after it.
//!
//! A law file says what it proves in a line
//! `(*! bound NAME THEOREM <= VALUE what *)`: the constant `NAME` of
//! `src/accuracy.rs` is at most `VALUE` because the theorem `THEOREM` of
//! the file, whose statement ends with `<= VALUE.`, is checked by coqc and
//! rests on no axiom beyond those of Coq's real numbers. `looser` in place
//! of `bound` says the same of one of the constant's operations only (the
//! constant then stays swept or measured), as a model's `#! looser` does. `VALUE` must not
//! appear elsewhere in the statement (as a hypothesis), and the file must
//! not admit anything.
//!
//! A law that takes another model's proven bound as a hypothesis (a
//! kernel's error, which no certificate it requires states) says so in a
//! line `(*! given MODEL WHAT <= VALUE what *)`: `MODEL` (a model of this
//! run, `NAME.g`) must have a claim whose proven value is at most `VALUE`,
//! and `VALUE` must appear in the law, or the run fails.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Context, Result};

use super::goals::Claim;
use super::{number, Proven};
use crate::tools::output;

/// The logical name under which the certificates and the laws are
/// compiled (`-Q WORK Laws`).
pub const PREFIX: &str = "Laws";

/// The axioms a law may rest on: those of Coq's classical real numbers
/// (the standard library's `Reals`), which Flocq and Gappa's library use.
const AXIOMS: [&str; 4] = [
    "ClassicalDedekindReals.sig_not_dec",
    "ClassicalDedekindReals.sig_forall_dec",
    "FunctionalExtensionality.functional_extensionality_dep",
    "Classical_Prop.classic",
];

/// The library of the laws, compiled first and in this order: what they
/// share (`Common`: the rounding and its error; `Tracked`: an error
/// carried through a straight-line computation).
const LIBRARY: [&str; 2] = ["Common", "Tracked"];

/// The law files of `dir` (`*.v` but the library), in order of name.
pub fn law_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .with_context(|| format!("{}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "v"))
        .filter(|p| {
            p.file_stem()
                .and_then(|s| s.to_str())
                .is_some_and(|s| !LIBRARY.contains(&s))
        })
        .collect();
    files.sort();
    Ok(files)
}

/// `files` ordered so that each law comes after the laws it requires
/// (`texts` holds their texts, in the same order), and otherwise in order
/// of name.
fn in_dependency_order(files: Vec<PathBuf>, texts: &[String]) -> Result<Vec<PathBuf>> {
    let stems: Vec<String> = files
        .iter()
        .map(|p| {
            p.file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or("")
                .to_owned()
        })
        .collect();
    let needs: Vec<Vec<usize>> = texts
        .iter()
        .map(|t| {
            required(t)
                .iter()
                .filter_map(|n| stems.iter().position(|s| s == n))
                .collect()
        })
        .collect();
    let mut done = vec![false; files.len()];
    let mut order = Vec::new();
    while order.len() < files.len() {
        let next = (0..files.len())
            .find(|&i| !done[i] && needs[i].iter().all(|&j| done[j]))
            .with_context(|| format!("the laws {stems:?} require each other in a circle"))?;
        done[next] = true;
        order.push(files[next].clone());
    }
    Ok(order)
}

/// A claim of a law file: `bound NAME THEOREM <= VALUE what`.
fn parse_claim(line: &str) -> Result<(Claim, String)> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let [kind, name, theorem, "<=", value, ..] = words[..] else {
        bail!("`(*!{line}*)` is not `bound NAME THEOREM <= VALUE what`");
    };
    if !matches!(kind, "bound" | "looser" | "law") {
        bail!("unknown claim `{kind}`");
    }
    let text = words[5..].join(" ");
    Ok((
        Claim {
            kind: kind.to_owned(),
            name: name.to_owned(),
            quantity: theorem.to_owned(),
            value: number(value)?,
            text,
        },
        value.to_owned(),
    ))
}

/// Checks `given MODEL WHAT <= VALUE what`: the law takes `VALUE` (which
/// it must contain) as a hypothesis, and `MODEL`, proven in this run, has
/// a claim whose value is at most `VALUE`.
fn check_given(text: &str, line: &str, models: &[Proven]) -> Result<()> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let ["given", model, what, "<=", value, ..] = words[..] else {
        bail!("`(*!{line}*)` is not `given MODEL WHAT <= VALUE what`");
    };
    let limit = number(value)?;
    let Some(proven) = models.iter().find(|p| p.model == model) else {
        bail!("it takes {what} <= {value} from {model}, which is not a model of this run");
    };
    let proves = |c: &Claim| matches!(c.kind.as_str(), "bound" | "looser" | "law");
    if !proven.claims.iter().any(|c| proves(c) && c.value <= limit) {
        bail!("it takes {what} <= {value} from {model}, whose claims prove no bound within it");
    }
    if text.matches(value).count() < 2 {
        bail!("it takes {what} <= {value} from {model}, but {value} appears in no hypothesis");
    }
    Ok(())
}

/// The statement of `Theorem NAME :` in `text`: what lies between the
/// colon and the `Proof.` after it.
fn statement<'a>(text: &'a str, theorem: &str) -> Result<&'a str> {
    let head = format!("Theorem {theorem} :");
    let at = text.find(&head).with_context(|| format!("no `{head}`"))?;
    let rest = &text[at + head.len()..];
    let end = rest
        .find("Proof.")
        .with_context(|| format!("{theorem} has no proof"))?;
    Ok(rest[..end].trim())
}

/// Checks a claim against the law's text: the theorem exists, its
/// statement ends with `<= VALUE.`, and `VALUE` appears nowhere else in it.
fn check_statement(text: &str, claim: &Claim, value: &str) -> Result<()> {
    let st = statement(text, &claim.quantity)?;
    let conclusion = format!("<= {value}.");
    if !st.ends_with(&conclusion) {
        bail!(
            "the statement of {} does not end with `{conclusion}`",
            claim.quantity
        );
    }
    if st.matches(value).count() != 1 {
        bail!(
            "{value} appears in the hypotheses of {}, not only as its bound",
            claim.quantity
        );
    }
    Ok(())
}

/// The modules of [`PREFIX`] a law names (`Laws.MODULE`), each once.
fn required(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for w in text.split(|c: char| c.is_whitespace() || c == '(' || c == ')') {
        if let Some(m) = w.strip_prefix(&format!("{PREFIX}.")) {
            let m = m.split('.').next().unwrap_or("").to_owned();
            if !m.is_empty() && !out.contains(&m) {
                out.push(m);
            }
        }
    }
    out
}

/// Runs coqc on `file` (already in `work`), with the certificates and the
/// laws of `work` under [`PREFIX`].
fn coqc(work: &Path, file: &Path) -> Result<String> {
    let out = output(
        Command::new("coqc")
            .arg("-Q")
            .arg(work)
            .arg(PREFIX)
            .arg(file)
            .current_dir(work),
    )
    .with_context(|| format!("coqc rejected {}", file.display()))?;
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The axioms `Print Assumptions` lists for `Laws.STEM.THEOREM`, or an
/// error naming any that is not one of [`AXIOMS`].
fn check_axioms(work: &Path, stem: &str, theorem: &str) -> Result<()> {
    let probe = work.join(format!("assumptions_{stem}_{theorem}.v"));
    std::fs::write(
        &probe,
        format!("Require {PREFIX}.{stem}.\nPrint Assumptions {PREFIX}.{stem}.{theorem}.\n"),
    )
    .with_context(|| format!("{}", probe.display()))?;
    let printed = coqc(work, &probe)?;
    if printed.contains("Closed under the global context") {
        return Ok(());
    }
    let Some((_, axioms)) = printed.split_once("Axioms:") else {
        bail!(
            "{stem}.v: Print Assumptions printed neither axioms nor a closed theorem:\n{printed}"
        );
    };
    for line in axioms.lines() {
        let Some((name, _)) = line.split_once(" :") else {
            continue;
        };
        if !line.starts_with(' ') && !AXIOMS.contains(&name.trim()) {
            bail!(
                "{stem}.v: {theorem} rests on `{}`, which is not an axiom of Coq's real numbers",
                name.trim()
            );
        }
    }
    Ok(())
}

/// Compiles the library and every law of `dir` in `work`, where the
/// certificates of this run are compiled (`models` names them), checks
/// each law's claims, and returns them as proven.
pub fn prove_laws(dir: &Path, work: &Path, proven_models: &[Proven]) -> Result<Vec<Proven>> {
    let models: Vec<String> = proven_models
        .iter()
        .map(|p| p.model.trim_end_matches(".g").to_owned())
        .collect();
    let models = models.as_slice();
    for name in LIBRARY {
        let library = dir.join(format!("{name}.v"));
        std::fs::copy(&library, work.join(format!("{name}.v")))
            .with_context(|| format!("{}", library.display()))?;
        coqc(work, &work.join(format!("{name}.v")))?;
    }
    let files = law_files(dir)?;
    let texts = files
        .iter()
        .map(|p| std::fs::read_to_string(p).with_context(|| format!("{}", p.display())))
        .collect::<Result<Vec<_>>>()?;
    let mut proven = Vec::new();
    for path in in_dependency_order(files, &texts)? {
        let start = Instant::now();
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .context("law name")?
            .to_owned();
        let text = std::fs::read_to_string(&path).with_context(|| format!("{}", path.display()))?;
        for word in [
            "Admitted",
            "admit",
            "Axiom",
            "Parameter",
            "Hypothesis",
            "Variable",
        ] {
            if text
                .split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|w| w == word)
            {
                bail!("{stem}.v: `{word}`: a law proves all it states");
            }
        }
        let needs = required(&text);
        for need in &needs {
            if !LIBRARY.contains(&need.as_str())
                && !models.contains(need)
                && !dir.join(format!("{need}.v")).exists()
            {
                bail!("{stem}.v requires {PREFIX}.{need}, which is neither a model of this run nor a law");
            }
        }
        let mut claims = Vec::new();
        for line in text.lines().filter_map(|l| l.trim().strip_prefix("(*!")) {
            let line = line.trim_end().trim_end_matches("*)");
            if line.trim_start().starts_with("given ") {
                check_given(&text, line, proven_models).with_context(|| format!("{stem}.v"))?;
                continue;
            }
            let (claim, value) = parse_claim(line).with_context(|| format!("{stem}.v"))?;
            check_statement(&text, &claim, &value).with_context(|| format!("{stem}.v"))?;
            claims.push(claim);
        }
        let copy = work.join(format!("{stem}.v"));
        std::fs::copy(&path, &copy).with_context(|| format!("{}", path.display()))?;
        coqc(work, &copy)?;
        for claim in &claims {
            check_axioms(work, &stem, &claim.quantity)?;
        }
        let time = start.elapsed();
        let certificates: Vec<_> = needs
            .iter()
            .filter(|n| models.contains(n))
            .map(|n| format!("{n}.g"))
            .collect();
        crate::tools::say(format!(
            "{stem}.v: checked by coqc{} ({:.1} s)",
            if certificates.is_empty() {
                String::new()
            } else {
                format!(" on the certificates of {}", certificates.join(", "))
            },
            time.as_secs_f64()
        ));
        proven.push(Proven {
            model: format!("{stem}.v"),
            claims,
            time,
            unchecked: false,
        });
    }
    Ok(proven)
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAW: &str = "(*! bound N thm <= 2.5e-7 the norm *)\nTheorem thm : forall x, 0 <= x <= 1 ->\n  Rabs (f x) <= 2.5e-7.\nProof. Qed.\n";

    #[test]
    fn a_claim_is_the_bound_its_theorem_states() {
        let (claim, value) = parse_claim(" bound N thm <= 2.5e-7 the norm ").expect("claim");
        assert_eq!((claim.name.as_str(), claim.value), ("N", 2.5e-7));
        assert!(check_statement(LAW, &claim, &value).is_ok());
        let (other, value) = parse_claim("bound N thm <= 2.4e-7 the norm").expect("claim");
        assert!(check_statement(LAW, &other, &value).is_err());
        let assumed = LAW.replace("0 <= x <= 1", "f x <= 2.5e-7");
        assert!(check_statement(&assumed, &claim, "2.5e-7").is_err());
    }

    #[test]
    fn a_hypothesis_taken_from_a_model_must_be_what_it_proves() {
        let kernel = Proven {
            model: "k.g".into(),
            claims: vec![Claim {
                kind: "law".into(),
                name: "-".into(),
                quantity: "e".into(),
                value: 1.0e-7,
                text: String::new(),
            }],
            time: std::time::Duration::ZERO,
            unchecked: false,
        };
        let law =
            "(*! given k.g e <= 1.05e-7 the kernel *)\nTheorem t : e <= 1.05e-7 -> x <= 3e-7.\n";
        let models = [kernel];
        assert!(check_given(law, " given k.g e <= 1.05e-7 the kernel ", &models).is_ok());
        let looser = law.replace("1.05e-7", "0.9e-7");
        assert!(check_given(&looser, " given k.g e <= 0.9e-7 the kernel ", &models).is_err());
        assert!(check_given(law, " given m.g e <= 1.05e-7 the kernel ", &models).is_err());
        let unused = "(*! given k.g e <= 1.05e-7 the kernel *)\nTheorem t : x <= 3e-7.\n";
        assert!(check_given(unused, " given k.g e <= 1.05e-7 the kernel ", &models).is_err());
    }

    #[test]
    fn a_law_is_compiled_after_the_laws_it_requires() {
        let files: Vec<PathBuf> = ["a.v", "b.v", "c.v"].iter().map(PathBuf::from).collect();
        let texts = ["Require Laws.c.\n", "", "Require Laws.b.\n"].map(String::from);
        let order = in_dependency_order(files.clone(), &texts).expect("order");
        assert_eq!(order, ["b.v", "c.v", "a.v"].map(PathBuf::from));
        let circle = ["Require Laws.b.\n", "Require Laws.a.\n", ""].map(String::from);
        assert!(in_dependency_order(files, &circle).is_err());
    }

    #[test]
    fn the_certificates_a_law_requires() {
        let law = "Require Import Laws.Common.\nRequire Laws.normalize.\n";
        let needs = required(law);
        assert_eq!(needs, ["Common", "normalize"]);
    }
}
