//! What `cargo xtask prove` checks of a model beyond its certificate: that
//! its polynomial's coefficients are the ones its Sollya script bounds, and
//! that every side condition Gappa assumed is proven.

use anyhow::{bail, Result};

use super::goals::formula_text;
use super::number;

/// A hexadecimal literal starting at byte `i` of `s`, with its sign: a `-`
/// just before it (spaces aside) makes it negative, whether unary or the
/// subtraction of the literal.
fn hex_at(s: &str, i: usize) -> Option<(f64, usize)> {
    let rest = &s[i..];
    if !rest.starts_with("0x") {
        return None;
    }
    let len = rest
        .char_indices()
        .skip(2)
        .find(|&(j, c)| {
            !(c.is_ascii_hexdigit()
                || c == '.'
                || c == 'p'
                || c == 'P'
                || (matches!(c, '-' | '+') && matches!(rest.as_bytes()[j - 1], b'p' | b'P')))
        })
        .map_or(rest.len(), |(j, _)| j);
    let value = number(&rest[..len]).ok()?;
    let negative = s[..i].trim_end().ends_with('-');
    Some((if negative { -value } else { value }, len))
}

/// The hexadecimal literals of `s`, signed, in order.
fn hex_literals(s: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < s.len() {
        let at_word_start = i == 0 || !s.as_bytes()[i - 1].is_ascii_alphanumeric();
        match hex_at(s, i).filter(|_| at_word_start) {
            Some((v, len)) => {
                out.push(v);
                i += len;
            }
            None => i += 1,
        }
    }
    out
}

/// The coefficients a Sollya script assigns (`c0 = -0x1.55p-3;`), in order.
pub fn sollya_coefficients(script: &str) -> Vec<f64> {
    script
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .flat_map(|l| l.split(';'))
        .filter_map(|statement| {
            let (_, value) = statement.split_once('=')?;
            let value = value.trim();
            let v = hex_literals(value);
            (v.len() == 1 && value.trim_start_matches('-').starts_with("0x")).then(|| v[0])
        })
        .collect()
}

/// The constants of a model's rounded computation (its `rnd=` lines,
/// before the formula), each once, in the order they first appear.
pub fn model_coefficients(model: &str) -> Vec<f64> {
    let body = model.split('{').next().unwrap_or("");
    let mut out: Vec<f64> = Vec::new();
    for statement in body
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
        .split(';')
        .filter(|s| s.contains("rnd="))
    {
        let rhs = statement.split_once("rnd=").map_or("", |(_, r)| r);
        for v in hex_literals(rhs) {
            if !out.contains(&v) {
                out.push(v);
            }
        }
    }
    out
}

/// Fails unless the model computes with the coefficients its Sollya script
/// bounds, one for one and in the same order.
pub fn same_coefficients(model: &str, script_name: &str, script: &str) -> Result<()> {
    let (ours, theirs) = (model_coefficients(model), sollya_coefficients(script));
    if theirs.is_empty() {
        bail!("{script_name} assigns no hexadecimal coefficients to compare");
    }
    if ours.len() != theirs.len() {
        bail!(
            "the model computes with {} coefficients, {script_name} bounds a polynomial of {}",
            ours.len(),
            theirs.len()
        );
    }
    for (i, (a, b)) in ours.iter().zip(&theirs).enumerate() {
        if a != b {
            bail!("coefficient {i}: the model computes with {a:e}, {script_name} bounds {b:e}");
        }
    }
    Ok(())
}

/// The expressions Gappa assumed nonzero to check a rewriting hint (its
/// warning "the expression (X) has been assumed to be nonzero"), each once.
pub fn assumed_nonzero(messages: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for line in messages.lines() {
        let Some((_, rest)) = line.split_once("the expression ") else {
            continue;
        };
        let Some((expr, _)) = rest.split_once(" has been assumed to be nonzero") else {
            continue;
        };
        let expr = powers_as_products(expr.trim());
        if !out.contains(&expr) {
            out.push(expr);
        }
    }
    out
}

/// Gappa prints powers as `(x)^3`, which its input does not take: as
/// products, `((x) * (x) * (x))`.
fn powers_as_products(e: &str) -> String {
    let mut out = String::new();
    let mut rest = e;
    while let Some(at) = rest.find(")^") {
        let (before, after) = rest.split_at(at + 1);
        // The group that `^` applies to: back to its opening parenthesis.
        let mut depth = 0i32;
        let mut open = 0;
        for (i, c) in before.char_indices().rev() {
            match c {
                ')' => depth += 1,
                '(' => {
                    depth -= 1;
                    if depth == 0 {
                        open = i;
                        break;
                    }
                }
                _ => {}
            }
        }
        let digits: String = after[1..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        let k: usize = digits.parse().unwrap_or(1);
        let base = &before[open..];
        out.push_str(&before[..open]);
        out.push('(');
        out.push_str(&vec![base; k.max(1)].join(" * "));
        out.push(')');
        rest = &after[1 + digits.len()..];
    }
    out.push_str(rest);
    out
}

/// A model of the side conditions: the model's definitions and hypotheses,
/// and as goals that each expression is nonzero; no rewriting hint (so
/// that no side condition rests on a hint that assumed it), only the
/// model's case splits (`$` lines).
pub fn side_condition_model(model: &str, conditions: &[String]) -> Result<String> {
    let formula = formula_text(model)?;
    let hypotheses =
        super::goals::top_level_hypotheses(formula).unwrap_or_else(|| formula.trim().to_owned());
    let head = model.split('{').next().unwrap_or("");
    let splits: Vec<&str> = model
        .rsplit_once('}')
        .map_or("", |(_, tail)| tail)
        .lines()
        .filter(|l| l.trim_start().starts_with('$'))
        .collect();
    // Factorizations the model gives for its side conditions (`#! side`
    // lines): Gappa sees denominators expanded, where interval arithmetic
    // loses that `(1 - a)^2 p` is positive. The caller checks that these
    // hints assume nothing nonzero themselves.
    let side_hints: Vec<&str> = model
        .lines()
        .filter_map(|l| l.strip_prefix("#! side "))
        .map(str::trim)
        .collect();
    let goals: Vec<String> = conditions.iter().map(|c| format!("{c} <> 0")).collect();
    let mut tail = splits.join("\n");
    for h in side_hints {
        tail.push('\n');
        tail.push_str(h);
    }
    Ok(format!(
        "{head}{{ {hypotheses}\n  ->\n  {}\n}}\n{tail}\n",
        goals.join(" /\\\n  "),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_of_both_sides_are_read_in_order_with_their_signs() {
        let script = "c0 = -0x1.8p-1; c1 = 0x1p-3;\nc2 = 0x1.4p0; // c9 = 0x1p9;\np = 1 + x * c0;";
        assert_eq!(sollya_coefficients(script), [-0.75, 0.125, 1.25]);
        let model = "# 0x1p9 in a comment\np rnd= (-0x1.8p-1 + s * 0x1p-3) + s * s * (0x1.4p0 - 0x1p-3 * s);\nP = s * 0x1p5;\n{ s in [0, 1] -> p in ? }";
        assert_eq!(model_coefficients(model), [-0.75, 0.125, 1.25, -0.125]);
        assert!(same_coefficients(model, "s.sollya", script).is_err());
        let model = "p rnd= -0x1.8p-1 + s * (0x1p-3 + s * 0x1.4p0);\n{ s in [0, 1] -> p in ? }";
        assert!(same_coefficients(model, "s.sollya", script).is_ok());
        let changed = "p rnd= -0x1.8p-1 + s * (0x1p-3 + s * 0x1.5p0);\n{ s in [0, 1] -> p in ? }";
        let e = same_coefficients(changed, "s.sollya", script).expect_err("changed");
        assert!(e.to_string().starts_with("coefficient 2"), "{e}");
    }

    #[test]
    fn side_conditions_are_read_from_the_warnings_and_made_goals() {
        let messages = "Warning: the expression (At) has been assumed to be nonzero when checking a rewriting rule.\nWarning: the expression 4 * (t2) * (At)^2 has been assumed to be nonzero when checking a rewriting rule.\nWarning: the expression (At) has been assumed to be nonzero when checking a rewriting rule.\n";
        assert_eq!(
            assumed_nonzero(messages),
            ["(At)", "4 * (t2) * ((At) * (At))"]
        );
        let model = "x = rnd(X);\ny rnd= x * x;\n{ x in [1, 2] -> y - x * x in ? }\ny -> x * x;\n$ x in 4;\n";
        let side = side_condition_model(model, &["(x)".to_owned()]).expect("side model");
        assert_eq!(
            side,
            "x = rnd(X);\ny rnd= x * x;\n{ x in [1, 2]\n  ->\n  (x) <> 0\n}\n$ x in 4;\n"
        );
    }
}
