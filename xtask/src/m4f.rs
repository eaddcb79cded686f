//! The Cortex-M4F table (instructions per call and flash bytes of every
//! operation of `embedded/src/ops.rs`) and slerp's budget.

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

/// Every operation's instruction count, from one run of `bin/bench.rs`.
pub fn counts() -> Result<Vec<Op>> {
    firmware::count("bench", Some("peers"))?
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
) -> Result<u64> {
    let bytes = firmware::flash(llvm_tools, opt_level, function)?;
    bytes
        .checked_sub(base)
        .with_context(|| format!("{function} is smaller ({bytes}) than {EMPTY_OP} ({base})"))
}

/// The counts, and the flash of every operation at each opt-level (two
/// builds per operation, one size build each).
pub fn with_flash(mut ops: Vec<Op>) -> Result<Vec<Op>> {
    let llvm_tools = tools::llvm_tools()?;
    let mut flash = vec![[0; 2]; ops.len()];
    for (level, opt_level) in OPT_LEVELS.iter().enumerate() {
        let base = firmware::flash(&llvm_tools, opt_level, EMPTY_OP)?;
        for (i, op) in ops.iter().enumerate() {
            say(format!(
                "flash at opt-level {opt_level:?}: {} of {}, {} ({})",
                i + 1,
                ops.len(),
                op.function,
                op.operation
            ));
            flash[i][level] = added_flash(&llvm_tools, opt_level, base, &op.function)?;
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
    let ops = counts()?;
    print!("{}", table(&ops));
    let slerp = ops
        .iter()
        .find(|op| op.operation == "slerp" && op.library == "rigtform")
        .context("the bench announced no slerp of rigtform")?;
    let llvm_tools = tools::llvm_tools()?;
    say(format!("flash of {} at opt-level \"s\"", slerp.function));
    let base = firmware::flash(&llvm_tools, "s", EMPTY_OP)?;
    let bytes = added_flash(&llvm_tools, "s", base, &slerp.function)?;
    println!("{}", budget_line(slerp.instructions, bytes));
    ensure!(
        slerp.instructions <= SLERP_INSTRUCTIONS && bytes <= SLERP_FLASH,
        "slerp is over its budget"
    );
    Ok(())
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
}
