//! The trace counter: instructions executed between the two marker
//! functions in QEMU's exec log, paired with the rows the firmware
//! announced over semihosting.
//!
//! The protocol (written by `embedded/src/measure.rs`):
//!
//! - Before its brackets, the firmware prints one line per row,
//!   `measure <inputs>|<field>|<field>...` (the fields name the row: for the
//!   ops bench `operation|library|function`, for the attitude updates one
//!   name). Rows may be announced before their brackets or between them;
//!   only the order matters.
//! - For each row, in the order announced, and for each of its `inputs`
//!   inputs: an empty bracket (the calibration: the same call sequence with
//!   no work), then the bracket of the measured call.
//! - A bracket is the executed instructions from the entry of
//!   `measure_start` (not counted) to the entry of `measure_end` (not
//!   counted). The marker's own instructions are in both brackets of a pair
//!   and cancel out.
//! - After the last row the firmware prints `measure done <rows>`.
//!
//! A row's figure is the mean over its inputs of (measured bracket - empty
//! bracket), rounded to the nearest integer (ties to even).

use std::io::BufRead;

use anyhow::{bail, ensure, Context, Result};

/// The symbol of the marker that opens a bracket.
pub const START_SYMBOL: &str = "measure_start";
/// The symbol of the marker that closes a bracket.
pub const END_SYMBOL: &str = "measure_end";

/// What every announcement line of the firmware starts with.
const PREFIX: &str = "measure ";

/// The entry addresses of the two marker functions, Thumb bit cleared (as
/// QEMU's trace shows program counters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Markers {
    /// Entry of [`START_SYMBOL`].
    pub start: u64,
    /// Entry of [`END_SYMBOL`].
    pub end: u64,
}

/// One row the firmware announced: its name fields and how many inputs it
/// is measured on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The name fields, in the order the firmware printed them.
    pub fields: Vec<String>,
    /// Inputs, so `2 * inputs` brackets belong to this row.
    pub inputs: u32,
}

/// A row with its figure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Measured {
    /// The name fields of the row.
    pub fields: Vec<String>,
    /// Instructions per call: the mean over the inputs of (measured bracket
    /// - empty bracket), rounded to the nearest integer, ties to even.
    pub instructions: i64,
    /// The mean empty bracket (the calibration subtracted), rounded alike.
    pub empty: i64,
    /// The inputs the mean is over.
    pub inputs: u32,
}

/// The program counter of one line of QEMU's `-d exec` log, `None` for the
/// log's other lines. A line reads
/// `Trace 0: 0x7f3c2c000100 [00000000/00000408/00000000/ff200000] symbol`;
/// the second field between the brackets is the guest program counter.
pub fn program_counter(line: &str) -> Result<Option<u64>> {
    if !line.starts_with("Trace ") {
        return Ok(None);
    }
    let fields = line
        .split_once('[')
        .and_then(|(_, rest)| rest.split_once(']'))
        .map(|(inside, _)| inside)
        .with_context(|| format!("no [...] in the trace line {line:?}"))?;
    let pc = fields
        .split('/')
        .nth(1)
        .with_context(|| format!("no program counter in the trace line {line:?}"))?;
    u64::from_str_radix(pc, 16)
        .map(Some)
        .with_context(|| format!("program counter {pc:?} is not hexadecimal in {line:?}"))
}

/// The instructions executed inside each bracket of the trace, in order.
///
/// Errors, rather than a count of zero: a trace with no executed
/// instruction, no bracket at all, a `measure_start` while a bracket is
/// open, a `measure_end` with none open, and a bracket still open at the
/// end.
pub fn bracket_counts(trace: impl BufRead, markers: Markers) -> Result<Vec<u64>> {
    let mut counts = Vec::new();
    // The line where the open bracket opened, and its count so far.
    let mut open: Option<(usize, u64)> = None;
    let mut executed = 0_u64;
    for (index, line) in trace.lines().enumerate() {
        let number = index + 1;
        let line = line.with_context(|| format!("reading trace line {number}"))?;
        let Some(pc) = program_counter(&line).with_context(|| format!("trace line {number}"))?
        else {
            continue;
        };
        executed += 1;
        if pc == markers.start {
            if let Some((at, _)) = open {
                bail!(
                    "trace line {number}: {START_SYMBOL} again, but the bracket opened at \
                     line {at} never reached {END_SYMBOL}"
                );
            }
            open = Some((number, 0));
        } else if pc == markers.end {
            match open.take() {
                Some((_, n)) => counts.push(n),
                None => bail!("trace line {number}: {END_SYMBOL} with no {START_SYMBOL} before it"),
            }
        } else if let Some((_, n)) = open.as_mut() {
            *n += 1;
        }
    }
    ensure!(
        executed > 0,
        "the trace logs no executed instruction (not QEMU's `-d exec` log?)"
    );
    if let Some((at, _)) = open {
        bail!("the bracket opened at trace line {at} never reaches {END_SYMBOL}");
    }
    ensure!(
        !counts.is_empty(),
        "no bracket in the trace: {START_SYMBOL} (at {:#x}) was never executed",
        markers.start
    );
    Ok(counts)
}

/// The rows announced in the firmware's semihosting output, in order.
/// Fails unless the output ends its rows with `measure done <rows>` and the
/// number matches (a firmware that stopped early is an error).
pub fn announced_rows(output: &str) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for line in output.lines() {
        let Some(rest) = line.strip_prefix(PREFIX) else {
            continue;
        };
        if let Some(done) = rest.strip_prefix("done ") {
            let n: usize = done
                .trim()
                .parse()
                .with_context(|| format!("bad row count in {line:?}"))?;
            ensure!(
                n == rows.len(),
                "the firmware says it measured {n} rows but announced {}",
                rows.len()
            );
            ensure!(n > 0, "the firmware announced no row");
            return Ok(rows);
        }
        let mut parts = rest.split('|');
        let inputs = parts.next().unwrap_or_default();
        let inputs: u32 = inputs
            .parse()
            .with_context(|| format!("bad input count {inputs:?} in {line:?}"))?;
        ensure!(inputs > 0, "a row with no input: {line:?}");
        let fields: Vec<String> = parts.map(str::to_owned).collect();
        ensure!(
            !fields.is_empty() && fields.iter().all(|f| !f.is_empty()),
            "a row with an empty name: {line:?}"
        );
        rows.push(Row { fields, inputs });
    }
    bail!(
        "the firmware did not finish (no `measure done` line); it printed:\n{}",
        output.trim_end()
    )
}

/// Pairs the bracket counts with the rows: per row and input, the empty
/// bracket then the measured one. Fails unless there are exactly as many
/// brackets as the rows need.
pub fn measure(rows: &[Row], counts: &[u64]) -> Result<Vec<Measured>> {
    let needed: u64 = rows.iter().map(|r| 2 * u64::from(r.inputs)).sum();
    ensure!(
        counts.len() as u64 == needed,
        "{} brackets in the trace, but the {} announced rows need {needed}",
        counts.len(),
        rows.len()
    );
    let mut pairs = counts.chunks_exact(2);
    let measured = rows
        .iter()
        .map(|row| {
            let (mut work, mut empty) = (0_i64, 0_i64);
            for pair in pairs.by_ref().take(row.inputs as usize) {
                let (e, m) = (pair[0] as i64, pair[1] as i64);
                work += m - e;
                empty += e;
            }
            let n = i64::from(row.inputs);
            Measured {
                fields: row.fields.clone(),
                instructions: mean(work, n),
                empty: mean(empty, n),
                inputs: row.inputs,
            }
        })
        .collect();
    Ok(measured)
}

/// `sum / n` rounded to the nearest integer, ties to even (as C's
/// `printf("%.0f")` rounds), for `n > 0`.
pub fn mean(sum: i64, n: i64) -> i64 {
    let (q, r) = (sum.div_euclid(n), sum.rem_euclid(n));
    match (2 * r).cmp(&n) {
        std::cmp::Ordering::Less => q,
        std::cmp::Ordering::Greater => q + 1,
        std::cmp::Ordering::Equal => q + q.rem_euclid(2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MARKERS: Markers = Markers {
        start: 0x400,
        end: 0x410,
    };

    /// One trace line at `pc`, as QEMU 7.2 prints it.
    fn line(pc: u64) -> String {
        format!("Trace 0: 0x7f0000001000 [00000000/{pc:08x}/00000000/ff200000] f\n")
    }

    /// A trace: for each bracket, `start`, its marker body, `n` instructions
    /// of work, then `end` and its body; some code outside between.
    fn trace(brackets: &[u64]) -> String {
        let mut t = String::from("----------------\nIN: main\n");
        t += &line(0x200);
        for &n in brackets {
            t += &line(MARKERS.start);
            t += &line(MARKERS.start + 2); // the marker's body
            for i in 0..n {
                t += &line(0x800 + 2 * i);
            }
            t += &line(MARKERS.end);
            t += &line(MARKERS.end + 2);
            t += &line(0x300); // between brackets: not counted
        }
        t
    }

    fn row(inputs: u32, fields: &[&str]) -> Row {
        Row {
            fields: fields.iter().map(|s| s.to_string()).collect(),
            inputs,
        }
    }

    #[test]
    fn reads_the_program_counter_of_trace_lines_only() {
        assert_eq!(program_counter(&line(0x408)).unwrap(), Some(0x408));
        assert_eq!(
            program_counter("Trace 0: 0x7f [00000000/0000000000001a2c/00000000/ff200000] x")
                .unwrap(),
            Some(0x1a2c)
        );
        assert_eq!(program_counter("IN: main").unwrap(), None);
        assert!(program_counter("Trace 0: 0x7f no brackets").is_err());
        assert!(program_counter("Trace 0: 0x7f [00000000/zz/0/0]").is_err());
    }

    #[test]
    fn counts_the_instructions_inside_each_bracket() {
        // The marker's body (one line) is counted in every bracket alike.
        let counts = bracket_counts(trace(&[3, 10, 0]).as_bytes(), MARKERS).unwrap();
        assert_eq!(counts, [4, 11, 1]);
    }

    #[test]
    fn a_missing_end_marker_is_an_error() {
        let t = trace(&[3, 5]).replace(&line(MARKERS.end), &line(0x900));
        let e = bracket_counts(t.as_bytes(), MARKERS).unwrap_err();
        assert!(e.to_string().contains("never reached measure_end"), "{e:#}");
        // The last bracket left open.
        let t = trace(&[3]) + &line(MARKERS.start) + &line(0x800);
        let e = bracket_counts(t.as_bytes(), MARKERS).unwrap_err();
        assert!(e.to_string().contains("never reaches"), "{e:#}");
    }

    #[test]
    fn a_missing_start_marker_is_an_error() {
        let t = trace(&[3]).replace(&line(MARKERS.start), &line(0x900));
        let e = bracket_counts(t.as_bytes(), MARKERS).unwrap_err();
        assert!(e.to_string().contains("with no measure_start"), "{e:#}");
        // The error names the line of the trace, counted from 1: here the
        // end marker's, after two header lines, one of main, the start
        // replaced, its body and three of work.
        assert!(e.to_string().starts_with("trace line 9:"), "{e:#}");
        // Neither marker: no bracket at all, not a count of zero.
        let t = line(0x200) + &line(0x202);
        let e = bracket_counts(t.as_bytes(), MARKERS).unwrap_err();
        assert!(e.to_string().contains("never executed"), "{e:#}");
        // Not a trace at all.
        assert!(bracket_counts("IN: main\n".as_bytes(), MARKERS).is_err());
    }

    #[test]
    fn reads_the_announced_rows() {
        let out = "bench inputs\nmeasure 8|slerp|rigtform|rigtform_slerp\n\
                   measure 1|Quat::integrate\nmeasure done 2\n";
        let rows = announced_rows(out).unwrap();
        assert_eq!(
            rows,
            [
                row(8, &["slerp", "rigtform", "rigtform_slerp"]),
                row(1, &["Quat::integrate"])
            ]
        );
    }

    #[test]
    fn an_unfinished_or_inconsistent_announcement_is_an_error() {
        assert!(announced_rows("measure 8|slerp\n").is_err());
        assert!(announced_rows("measure 8|slerp\nmeasure done 2\n").is_err());
        assert!(announced_rows("measure done 0\n").is_err());
        assert!(announced_rows("measure x|slerp\nmeasure done 1\n").is_err());
        assert!(announced_rows("measure 0|slerp\nmeasure done 1\n").is_err());
        assert!(announced_rows("measure 2\nmeasure done 1\n").is_err());
    }

    #[test]
    fn subtracts_the_empty_bracket_and_takes_the_mean() {
        let rows = [row(2, &["a"]), row(1, &["b"])];
        // a: (20 - 4) and (27 - 4): mean 19.5, rounds to the even 20;
        // b: 9 - 5 = 4.
        let m = measure(&rows, &[4, 20, 4, 27, 5, 9]).unwrap();
        assert_eq!(m[0].instructions, 20);
        assert_eq!(m[0].empty, 4);
        assert_eq!(m[1].instructions, 4);
        assert_eq!(m[1].empty, 5);
        // The same figures from a synthetic trace, end to end.
        let counts = bracket_counts(trace(&[3, 19, 3, 26, 4, 8]).as_bytes(), MARKERS).unwrap();
        assert_eq!(measure(&rows, &counts).unwrap(), m);
    }

    #[test]
    fn brackets_that_do_not_match_the_rows_are_an_error() {
        let rows = [row(2, &["a"])];
        assert!(measure(&rows, &[4, 20, 4]).is_err());
        assert!(measure(&rows, &[4, 20, 4, 20, 4, 20]).is_err());
    }

    #[test]
    fn the_mean_rounds_to_nearest_ties_to_even() {
        assert_eq!(mean(16, 8), 2);
        assert_eq!(mean(17, 8), 2);
        assert_eq!(mean(20, 8), 2); // 2.5
        assert_eq!(mean(28, 8), 4); // 3.5
        assert_eq!(mean(21, 8), 3);
        assert_eq!(mean(-20, 8), -2); // -2.5
        assert_eq!(mean(-21, 8), -3);
        assert_eq!(mean(2949, 8), 369); // 368.625
    }
}
