//! The Cortex-M4F table (instructions per call and flash bytes of every
//! operation of `embedded/src/ops.rs`), slerp's budget, and the attitude
//! filter's budget.

use std::fmt::Write;

use anyhow::{bail, ensure, Context, Result};

use crate::firmware::{self, EMPTY_OP};
use crate::tools::{self, say};

/// The opt-levels of the flash columns.
const OPT_LEVELS: [&str; 2] = ["s", "3"];

/// slerp's budget on the Cortex-M4F: instructions per call.
const SLERP_INSTRUCTIONS: i64 = 400;
/// slerp's budget: flash bytes at opt-level "s".
const SLERP_FLASH: u64 = 2048;

/// The orientation filter's budgets on the Cortex-M4F: instructions per 6D
/// update, per 9D update, and bytes of state.
const FILTER_6D_INSTRUCTIONS: i64 = 1600;
const FILTER_9D_INSTRUCTIONS: i64 = 2200;
const FILTER_STATE_BYTES: u64 = 256;

/// One operation of one library, as the bench announced it, with its count.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Op {
    /// The operation (the table's first column).
    pub operation: String,
    /// The library.
    pub library: String,
    /// Its function in `embedded/src/ops.rs`, which the size build links.
    pub function: String,
    /// Instructions per call: the mean over `inputs` inputs.
    pub instructions: i64,
    /// The inputs the bench measured it on.
    pub inputs: u32,
    /// Flash bytes at each of [`OPT_LEVELS`], once measured.
    pub flash: Option<[u64; 2]>,
}

/// The features of the bench and size firmware: the peers, and `extra`
/// (further Cargo features of rigtform) if given.
fn bench_features(extra: Option<&str>) -> String {
    match extra {
        Some(extra) => format!("peers,{extra}"),
        None => "peers".into(),
    }
}

/// Every operation's instruction count, from one run of `bin/bench.rs`
/// built with [`bench_features`]`(extra)`.
pub fn counts(extra: Option<&str>) -> Result<Vec<Op>> {
    firmware::count("bench", Some(&bench_features(extra)))?
        .into_iter()
        .map(|m| match <[String; 3]>::try_from(m.fields) {
            Ok([operation, library, function]) => Ok(Op {
                operation,
                library,
                function,
                instructions: m.instructions,
                inputs: m.inputs,
                flash: None,
            }),
            Err(fields) => {
                bail!("the bench announced {fields:?}; an operation is operation|library|function")
            }
        })
        .collect()
}

/// The number of inputs every operation was measured on (the performance page
/// says it); fails if they differ.
pub fn inputs(ops: &[Op]) -> Result<u32> {
    let first = ops.first().context("no operation")?.inputs;
    ensure!(
        ops.iter().all(|op| op.inputs == first),
        "the bench measured its operations on different numbers of inputs"
    );
    Ok(first)
}

/// The flash bytes that linking `function` adds to the size firmware at
/// `opt_level`: its size less `base`, the same firmware linking
/// `ops::empty` at that opt-level.
fn added_flash(
    llvm_tools: &std::path::Path,
    opt_level: &str,
    base: u64,
    function: &str,
    features: &str,
) -> Result<u64> {
    let bytes = firmware::flash(llvm_tools, opt_level, function, features)?;
    bytes
        .checked_sub(base)
        .with_context(|| format!("{function} is smaller ({bytes}) than {EMPTY_OP} ({base})"))
}

/// The counts, and the flash of every operation at each opt-level (two
/// builds per operation, one size build each), with the features of
/// [`bench_features`]`(extra)`.
pub fn with_flash(mut ops: Vec<Op>, extra: Option<&str>) -> Result<Vec<Op>> {
    let llvm_tools = tools::llvm_tools()?;
    let features = bench_features(extra);
    let mut flash = vec![[0; 2]; ops.len()];
    for (level, opt_level) in OPT_LEVELS.iter().enumerate() {
        let base = firmware::flash(&llvm_tools, opt_level, EMPTY_OP, &features)?;
        for (i, op) in ops.iter().enumerate() {
            say(format!(
                "flash at opt-level {opt_level:?}: {} of {}, {} ({})",
                i + 1,
                ops.len(),
                op.function,
                op.operation
            ));
            flash[i][level] = added_flash(&llvm_tools, opt_level, base, &op.function, &features)?;
        }
    }
    for (op, f) in ops.iter_mut().zip(flash) {
        op.flash = Some(f);
    }
    Ok(ops)
}

/// The Markdown table: one row per operation, `-` where flash was not
/// measured.
pub fn table(ops: &[Op]) -> String {
    let mut t = String::from(
        "| operation | library | instructions per call | flash bytes, opt-level \"s\" | \
         flash bytes, opt-level 3 |\n| --- | --- | --- | --- | --- |\n",
    );
    for op in ops {
        let (s, o3) = match op.flash {
            Some([s, o3]) => (s.to_string(), o3.to_string()),
            None => ("-".into(), "-".into()),
        };
        writeln!(
            t,
            "| {} | {} | {} | {s} | {o3} |",
            op.operation, op.library, op.instructions
        )
        .unwrap();
    }
    t
}

/// Counts every operation, then measures rigtform's slerp's flash at
/// opt-level "s"; prints the table and the budget line, and fails if slerp
/// is over either budget.
pub fn budget() -> Result<()> {
    let ops = counts(None)?;
    print!("{}", table(&ops));
    let slerp = ops
        .iter()
        .find(|op| op.operation == "slerp" && op.library == "rigtform")
        .context("the bench announced no slerp of rigtform")?;
    let llvm_tools = tools::llvm_tools()?;
    say(format!("flash of {} at opt-level \"s\"", slerp.function));
    let features = bench_features(None);
    let base = firmware::flash(&llvm_tools, "s", EMPTY_OP, &features)?;
    let bytes = added_flash(&llvm_tools, "s", base, &slerp.function, &features)?;
    println!("{}", budget_line(slerp.instructions, bytes));
    ensure!(
        slerp.instructions <= SLERP_INSTRUCTIONS && bytes <= SLERP_FLASH,
        "slerp is over its budget"
    );
    Ok(())
}

/// `cargo xtask filter-cost`: the rows of `embedded/src/bin/filter_cost.rs`
/// (instructions per call of the attitude updates, and the filter's state
/// size on the target), then the filter's budget; fails unless it holds.
pub fn filter_budget(features: Option<&str>) -> Result<()> {
    let rows = firmware::count("filter_cost", features)?;
    for m in &rows {
        println!(
            "{:<42} {:>6} instructions (less an empty bracket of {})",
            m.fields.join(" "),
            m.instructions,
            m.empty
        );
    }
    let instructions = |name: &str| -> Result<i64> {
        rows.iter()
            .find(|m| m.fields.first().is_some_and(|f| f == name))
            .map(|m| m.instructions)
            .with_context(|| format!("the firmware announced no row {name:?}"))
    };
    let six = instructions("OrientationFilter::update (6D)")?;
    let nine = instructions("OrientationFilter::update_with_mag (9D)")?;
    let state = rows
        .iter()
        .find_map(|m| state_bytes(&m.fields))
        .context("the firmware announced no state size")?;
    println!("{}", filter_budget_line(six, nine, state));
    ensure!(
        six <= FILTER_6D_INSTRUCTIONS
            && nine <= FILTER_9D_INSTRUCTIONS
            && state <= FILTER_STATE_BYTES,
        "the orientation filter is over its budget"
    );
    Ok(())
}

/// The state size a row names as `state <bytes> bytes`.
fn state_bytes(fields: &[String]) -> Option<u64> {
    let at = fields.iter().position(|f| f == "state")?;
    match fields.get(at + 1..at + 3)? {
        [n, unit] if unit == "bytes" => n.parse().ok(),
        _ => None,
    }
}

/// The filter budget's report line.
fn filter_budget_line(six: i64, nine: i64, state: u64) -> String {
    format!(
        "orientation filter on the Cortex-M4F: {six} instructions per 6D update (budget \
         {FILTER_6D_INSTRUCTIONS}), {nine} per 9D update (budget {FILTER_9D_INSTRUCTIONS}), \
         {state} bytes of state (budget {FILTER_STATE_BYTES})"
    )
}

/// The budget's report line.
fn budget_line(instructions: i64, bytes: u64) -> String {
    format!(
        "slerp on the Cortex-M4F: {instructions} instructions per call (budget \
         {SLERP_INSTRUCTIONS}), {bytes} bytes of flash at opt-level \"s\" (budget {SLERP_FLASH})"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_a_row_per_operation() {
        let op = |instructions, flash| Op {
            operation: "slerp".into(),
            library: "rigtform".into(),
            function: "rigtform_slerp".into(),
            instructions,
            inputs: 8,
            flash,
        };
        let t = table(&[op(368, Some([2044, 2572])), op(370, None)]);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 4);
        assert_eq!(lines[2], "| slerp | rigtform | 368 | 2044 | 2572 |");
        assert_eq!(lines[3], "| slerp | rigtform | 370 | - | - |");
        assert_eq!(
            budget_line(368, 2044),
            "slerp on the Cortex-M4F: 368 instructions per call (budget 400), \
             2044 bytes of flash at opt-level \"s\" (budget 2048)"
        );
    }

    #[test]
    fn the_filter_rows_name_the_state_size() {
        let fields = |f: &[&str]| f.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let row = fields(&["OrientationFilter::update (6D)", "state", "240", "bytes"]);
        assert_eq!(state_bytes(&row), Some(240));
        assert_eq!(state_bytes(&fields(&["Quat::integrate"])), None);
        assert_eq!(state_bytes(&fields(&["x", "state", "240"])), None);
        assert_eq!(state_bytes(&fields(&["x", "state", "many", "bytes"])), None);
        assert_eq!(
            filter_budget_line(1412, 1890, 240),
            "orientation filter on the Cortex-M4F: 1412 instructions per 6D update \
             (budget 1600), 1890 per 9D update (budget 2200), 240 bytes of state (budget 256)"
        );
    }
}
