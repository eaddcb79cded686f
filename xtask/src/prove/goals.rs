//! A model's logical formula (the part between `{` and `}`), read far
//! enough to tell what it assumes from what it proves, and the claims
//! (`#!` lines) checked against it.
//!
//! Gappa's formula is `hypotheses -> goals`, built from `/\`, `\/`, `not`,
//! parentheses and atoms such as `e in [a, b]` or `e <= a`; an implication
//! may nest inside the goals (a goal under a condition). An atom is a
//! *goal* where it stands on the right of every implication above it, and
//! a *hypothesis* anywhere else.

use anyhow::{bail, Context, Result};

use super::number;

/// One atom of the formula: its text, and for `e in [a, b]` the
/// quantity and the two ends as written.
#[derive(Clone, Debug, PartialEq)]
pub struct Atom {
    pub text: String,
    pub interval: Option<(String, String, String)>,
}

/// The atoms of a formula, split into what it assumes and what it proves.
#[derive(Debug, Default)]
pub struct Formula {
    pub hypotheses: Vec<Atom>,
    pub goals: Vec<Atom>,
}

/// The text between the model's first `{` and its matching `}`.
pub fn formula_text(model: &str) -> Result<&str> {
    let start = model
        .find('{')
        .context("no `{`: the model has no formula")?;
    let mut depth = 0usize;
    for (i, c) in model[start..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Ok(&model[start + 1..start + i]);
                }
            }
            _ => {}
        }
    }
    bail!("the formula's `{{` is never closed")
}

/// `s` without spaces, tabs and newlines: how two quantities are compared.
pub fn squeeze(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// The position of the first `op` in `s` outside parentheses and brackets.
fn top_level(s: &str, op: &str) -> Option<usize> {
    let mut depth = 0i32;
    let bytes = s.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'(' | b'[' => depth += 1,
            b')' | b']' => depth -= 1,
            _ if depth == 0 && s[i..].starts_with(op) => return Some(i),
            _ => {}
        }
    }
    None
}

/// Whether `s` is one parenthesized group, `( ... )`, as a whole.
fn wrapped(s: &str) -> bool {
    if !s.starts_with('(') || !s.ends_with(')') {
        return false;
    }
    let mut depth = 0i32;
    for (i, c) in s.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 && i + 1 < s.len() {
                    return false;
                }
            }
            _ => {}
        }
    }
    true
}

/// Whether `s`, inside a group, is a formula (it has a connective or a
/// relation at its top level) rather than the start of an expression.
fn is_formula(s: &str) -> bool {
    ["->", "/\\", "\\/", " in ", "<=", ">=", "<>"]
        .iter()
        .any(|op| top_level(s, op).is_some())
        || s.trim_start().starts_with("not ")
}

fn atom(s: &str) -> Atom {
    let text = s.trim().to_owned();
    let interval = top_level(&text, " in ").and_then(|at| {
        let quantity = text[..at].trim().to_owned();
        let rest = text[at + 4..].trim();
        let inner = rest.strip_prefix('[')?.strip_suffix(']')?;
        let (lo, hi) = inner.split_once(',')?;
        Some((quantity, lo.trim().to_owned(), hi.trim().to_owned()))
    });
    Atom { text, interval }
}

/// Adds the atoms of `s` to `out`: as goals if `goal`, else as hypotheses.
fn walk(s: &str, goal: bool, out: &mut Formula) {
    let s = s.trim();
    if let Some(at) = top_level(s, "->") {
        walk(&s[..at], false, out);
        walk(&s[at + 2..], goal, out);
    } else if let Some(at) = top_level(s, "\\/") {
        walk(&s[..at], goal, out);
        walk(&s[at + 2..], goal, out);
    } else if let Some(at) = top_level(s, "/\\") {
        walk(&s[..at], goal, out);
        walk(&s[at + 2..], goal, out);
    } else if let Some(rest) = s.strip_prefix("not ") {
        walk(rest, false, out);
    } else if wrapped(s) && is_formula(&s[1..s.len() - 1]) {
        walk(&s[1..s.len() - 1], goal, out);
    } else if !s.is_empty() {
        let a = atom(s);
        if goal {
            out.goals.push(a);
        } else {
            out.hypotheses.push(a);
        }
    }
}

/// The hypotheses of a formula as written: the text left of its top-level
/// `->` (`None` for a formula without one).
pub fn top_level_hypotheses(formula: &str) -> Option<String> {
    let text: String = formula
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join(" ");
    top_level(&text, "->").map(|at| text[..at].trim().to_owned())
}

/// The atoms of a model's formula.
pub fn formula(model: &str) -> Result<Formula> {
    let text: String = formula_text(model)?
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join(" ");
    let mut out = Formula::default();
    walk(&text, true, &mut out);
    Ok(out)
}

/// What a model's `#!` line claims: that the goal `quantity in [lo, hi]`
/// of the model bounds the constant `name` (or a law, `-`) by `value`, the
/// larger magnitude of the two ends.
#[derive(Clone, Debug)]
pub struct Claim {
    pub kind: String,
    pub name: String,
    pub quantity: String,
    pub value: f64,
    pub text: String,
}

/// Reads a claim line (after `#!`): `KIND NAME QUANTITY in [LO, HI] what`.
pub fn parse_claim(line: &str) -> Result<(Claim, String, String)> {
    let line = line.trim();
    let (kind, rest) = line.split_once(' ').context("a claim without a name")?;
    let (name, rest) = rest
        .trim_start()
        .split_once(' ')
        .context("a claim without its goal")?;
    let at = top_level(rest, " in [")
        .context("the claim does not name a goal `QUANTITY in [LO, HI]`")?;
    let quantity = rest[..at].trim().to_owned();
    let after = &rest[at + 5..];
    let close = after
        .find(']')
        .context("the claim's interval is not closed")?;
    let (lo, hi) = after[..close]
        .split_once(',')
        .context("the claim's interval has no comma")?;
    let (lo, hi) = (lo.trim().to_owned(), hi.trim().to_owned());
    let value = number(&lo)?.abs().max(number(&hi)?.abs());
    Ok((
        Claim {
            kind: kind.to_owned(),
            name: name.to_owned(),
            quantity,
            value,
            text: after[close + 1..].trim().to_owned(),
        },
        lo,
        hi,
    ))
}

/// Checks a claim against the formula: the goal it names must be one of
/// the formula's goals, with the same interval, and its bound must not be
/// a bound the formula assumes.
pub fn check_claim(line: &str, f: &Formula) -> Result<Claim> {
    let (claim, lo, hi) = parse_claim(line)?;
    let wanted = (squeeze(&claim.quantity), squeeze(&lo), squeeze(&hi));
    let is_it = |a: &Atom| {
        a.interval
            .as_ref()
            .is_some_and(|(q, l, h)| (squeeze(q), squeeze(l), squeeze(h)) == wanted)
    };
    if !f.goals.iter().any(is_it) {
        if f.hypotheses.iter().any(is_it) {
            bail!(
                "`{} in [{lo}, {hi}]` is a hypothesis of the model, not a goal it proves",
                claim.quantity
            );
        }
        bail!(
            "`{} in [{lo}, {hi}]` is not a goal of the model",
            claim.quantity
        );
    }
    for h in &f.hypotheses {
        if let Some((_, l, u)) = &h.interval {
            for end in [l, u] {
                if number(end).is_ok_and(|v| v.abs() == claim.value) {
                    bail!(
                        "the claimed bound {} is a bound the model assumes (`{}`)",
                        claim.value,
                        h.text
                    );
                }
            }
        }
    }
    Ok(claim)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MODEL: &str = "x = rnd(X);\n{ x in [1, 2] /\\ (H - A) / A in [-1b-20, 1b-20]\n  -> y - x in [-1b-24, 1b-24] /\\\n  (x in [1, 1.5] -> (y - A) * 1b24 in [-0.85, 0.85]) }\ny -> x;";

    #[test]
    fn goals_and_hypotheses_are_told_apart() {
        let f = formula(MODEL).expect("formula");
        let goals: Vec<_> = f.goals.iter().map(|a| a.text.as_str()).collect();
        let hyps: Vec<_> = f.hypotheses.iter().map(|a| a.text.as_str()).collect();
        assert_eq!(
            goals,
            [
                "y - x in [-1b-24, 1b-24]",
                "(y - A) * 1b24 in [-0.85, 0.85]"
            ]
        );
        assert_eq!(
            hyps,
            [
                "x in [1, 2]",
                "(H - A) / A in [-1b-20, 1b-20]",
                "x in [1, 1.5]"
            ]
        );
    }

    #[test]
    fn a_claim_names_a_goal_and_its_interval() {
        let f = formula(MODEL).expect("formula");
        let c = check_claim("bound B y - x in [-1b-24, 1b-24] what", &f).expect("claim");
        assert_eq!(
            (c.name.as_str(), c.value, c.text.as_str()),
            ("B", 2f64.powi(-24), "what")
        );
        let c = check_claim("looser B (y - A)*1b24 in [-0.85, 0.85] ulps", &f).expect("claim");
        assert_eq!(c.value, 0.85);
        // Another interval, another quantity, or no goal at all.
        assert!(check_claim("bound B y - x in [-1b-23, 1b-23] what", &f).is_err());
        assert!(check_claim("bound B y in [-1b-24, 1b-24] what", &f).is_err());
        assert!(check_claim("bound B 1b-24 what", &f).is_err());
    }

    #[test]
    fn a_claim_on_what_the_model_assumes_fails() {
        let f = formula(MODEL).expect("formula");
        let e = check_claim("bound B (H - A) / A in [-1b-20, 1b-20] what", &f)
            .expect_err("a hypothesis");
        assert!(e.to_string().contains("is a hypothesis"), "{e}");
        // A goal that restates an assumed bound.
        let restated = "{ x in [1, 2] /\\ e in [-1b-20, 1b-20] -> e in [-1b-20, 1b-20] }";
        let f = formula(restated).expect("formula");
        let e = check_claim("bound B e in [-1b-20, 1b-20] what", &f).expect_err("assumed");
        assert!(e.to_string().contains("a bound the model assumes"), "{e}");
    }
}
