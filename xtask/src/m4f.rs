//! The Cortex-M4F table (instructions per call and flash bytes of every
//! operation of `embedded/src/ops.rs`), slerp's budget, and the attitude
//! filter's budget and its table beside uf-ahrs's filters.

use std::fmt::Write;

use anyhow::{bail, ensure, Context, Result};

use crate::firmware::{self, EMPTY_OP};
use crate::page;
use crate::tools::{self, say};
use crate::trace::Measured;

/// The performance page, from the repository's root.
pub const PAGE: &str = "docs/performance.md";

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

/// The embedded feature that adds uf-ahrs's filters to
/// `bin/filter_cost.rs` and their updates to `ops.rs`.
const ATTITUDE_PEERS: &str = "attitude-peers";

/// One filter of the attitude table: its name, the rows of
/// `bin/filter_cost.rs` that count its 6D and 9D updates (the 6D row names
/// its state size), and the functions of `ops.rs` that the flash builds
/// link for each.
struct Filter {
    name: &'static str,
    six: &'static str,
    nine: &'static str,
    flash_six: &'static str,
    flash_nine: &'static str,
}

/// Ours, then uf-ahrs's three.
const FILTERS: [Filter; 4] = [
    Filter {
        name: "rigtform OrientationFilter",
        six: "OrientationFilter::update (6D)",
        nine: "OrientationFilter::update_with_mag (9D)",
        flash_six: "rigtform_filter_6d",
        flash_nine: "rigtform_filter_9d",
    },
    Filter {
        name: "uf-ahrs Vqf",
        six: "uf-ahrs Vqf::update_imu (6D)",
        nine: "uf-ahrs Vqf::update (9D)",
        flash_six: "uf_ahrs_vqf_6d",
        flash_nine: "uf_ahrs_vqf_9d",
    },
    Filter {
        name: "uf-ahrs Mahony",
        six: "uf-ahrs Mahony::update_imu (6D)",
        nine: "uf-ahrs Mahony::update (9D)",
        flash_six: "uf_ahrs_mahony_6d",
        flash_nine: "uf_ahrs_mahony_9d",
    },
    Filter {
        name: "uf-ahrs Madgwick",
        six: "uf-ahrs Madgwick::update_imu (6D)",
        nine: "uf-ahrs Madgwick::update (9D)",
        flash_six: "uf_ahrs_madgwick_6d",
        flash_nine: "uf_ahrs_madgwick_9d",
    },
];

/// One filter's measured cost.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FilterCost {
    /// The filter (the table's first column).
    pub name: String,
    /// Instructions per 6D and per 9D update, built at each of
    /// [`OPT_LEVELS`].
    pub six: [i64; 2],
    pub nine: [i64; 2],
    /// `size_of` the filter on the target.
    pub state: u64,
    /// Flash bytes at opt-level "s" of a firmware making the filter and
    /// calling its 6D, or its 9D, update (less the empty firmware).
    pub flash: [u64; 2],
}

/// The row named `name` (its first field).
fn row<'a>(rows: &'a [Measured], name: &str) -> Result<&'a Measured> {
    rows.iter()
        .find(|m| m.fields.first().is_some_and(|f| f == name))
        .with_context(|| format!("the firmware announced no row {name:?}"))
}

/// `features` with `more` added.
fn with_feature(features: Option<&str>, more: &str) -> String {
    match features {
        Some(f) => format!("{f},{more}"),
        None => more.into(),
    }
}

/// The attitude table's costs: every filter of [`FILTERS`] from `rows`
/// (one run of `bin/filter_cost.rs` with the peers at each of
/// [`OPT_LEVELS`]), and its flash from the size builds at opt-level "s"
/// (with `features` besides the peers).
fn filter_costs(rows: [&[Measured]; 2], features: Option<&str>) -> Result<Vec<FilterCost>> {
    let llvm_tools = tools::llvm_tools()?;
    let features = bench_features(Some(&with_feature(features, ATTITUDE_PEERS)));
    let base = firmware::flash(&llvm_tools, "s", EMPTY_OP, &features)?;
    FILTERS
        .iter()
        .map(|f| {
            let state = state_bytes(&row(rows[0], f.six)?.fields)
                .with_context(|| format!("the row {:?} names no state size", f.six))?;
            let count = |name: &str| -> Result<[i64; 2]> {
                Ok([
                    row(rows[0], name)?.instructions,
                    row(rows[1], name)?.instructions,
                ])
            };
            let mut flash = [0; 2];
            for (bytes, function) in flash.iter_mut().zip([f.flash_six, f.flash_nine]) {
                say(format!("flash at opt-level \"s\": {function}"));
                *bytes = added_flash(&llvm_tools, "s", base, function, &features)?;
            }
            Ok(FilterCost {
                name: f.name.into(),
                six: count(f.six)?,
                nine: count(f.nine)?,
                state,
                flash,
            })
        })
        .collect()
}

/// The attitude table (Markdown), then how ours compares with uf-ahrs's
/// VQF.
pub fn filter_table(costs: &[FilterCost]) -> String {
    let mut t = String::from(
        "| filter | instructions per 6D update, opt-level \"s\" | per 9D update, \"s\" | \
         per 6D update, opt-level 3 | per 9D update, 3 | state bytes | flash bytes, 6D | \
         flash bytes, 9D |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for c in costs {
        writeln!(
            t,
            "| {} | {} | {} | {} | {} | {} | {} | {} |",
            c.name, c.six[0], c.nine[0], c.six[1], c.nine[1], c.state, c.flash[0], c.flash[1]
        )
        .unwrap();
    }
    if let [ours, vqf, ..] = costs {
        let ratio = |a: i64, b: i64| a as f64 / b as f64;
        writeln!(
            t,
            "\n{} takes {:.2} times the instructions of {} per 6D update and {:.2} times per 9D \
             update (at opt-level 3: {:.2} and {:.2}).",
            ours.name,
            ratio(ours.six[0], vqf.six[0]),
            vqf.name,
            ratio(ours.nine[0], vqf.nine[0]),
            ratio(ours.six[1], vqf.six[1]),
            ratio(ours.nine[1], vqf.nine[1]),
        )
        .unwrap();
    }
    t
}

/// The page's attitude block: what was measured, how, and the table.
pub fn filter_section(costs: &[FilterCost], date: &str) -> String {
    let mut s = String::new();
    writeln!(
        s,
        "{} (generated by cargo xtask filter-cost --peers on {date}; do not edit by hand) -->\n",
        page::ATTITUDE.begin
    )
    .unwrap();
    s += "Cortex-M4F (QEMU `mps2-an386`, `thumbv7em-none-eabihf`, LTO, one codegen unit):\n\
          instructions executed by one update of a filter warmed up on 1,200 samples of a\n\
          tilted sensor turning at 0.3 rad/s with a gyro bias (`embedded/src/bin/filter_cost.rs`,\n\
          the same samples and the same input for every filter), at the firmware's opt-level\n\
          \"s\" (the budgets' measure) and at opt-level 3 (uf-ahrs's release profile); the\n\
          filter's `size_of`; and the flash bytes, at opt-level \"s\", that making the filter\n\
          and calling its 6D or its 9D update adds to a firmware (`embedded/src/ops/attitude.rs`,\n\
          less the empty firmware). uf-ahrs's filters run as its README shows:\n\
          `new(3.5 ms, default parameters)`, `update_imu` (6D) and `update` (9D).\n\n";
    s += &filter_table(costs);
    s += page::ATTITUDE.end;
    s += "\n";
    s
}

/// The page's attitude block from one run of the firmware with the peers
/// and their flash builds (perf-report's).
pub fn attitude_section(date: &str) -> Result<String> {
    let rows = firmware::count("filter_cost", Some(ATTITUDE_PEERS))?;
    let rows3 = firmware::count_at("filter_cost", Some(ATTITUDE_PEERS), OPT_LEVELS[1])?;
    Ok(filter_section(&filter_costs([&rows, &rows3], None)?, date))
}

/// `cargo xtask filter-cost`: the rows of `embedded/src/bin/filter_cost.rs`
/// (instructions per call of the attitude updates, and the filter's state
/// size on the target), then the filter's budget; fails unless it holds.
/// With `peers`, the firmware also counts uf-ahrs's filters, and the
/// attitude table follows (with each filter's flash); with `write_page`
/// too, the table goes into the performance page's attitude block.
pub fn filter_budget(features: Option<&str>, peers: bool, write_page: bool) -> Result<()> {
    let root = tools::root()?;
    let page_path = root.join(PAGE);
    if write_page {
        // Fail now, not after the builds, if the block is not there.
        page::splice(&std::fs::read_to_string(&page_path)?, page::ATTITUDE, "")?;
    }
    let firmware_features = peers.then(|| with_feature(features, ATTITUDE_PEERS));
    let rows = firmware::count("filter_cost", firmware_features.as_deref().or(features))?;
    for m in &rows {
        println!(
            "{:<42} {:>6} instructions (less an empty bracket of {})",
            m.fields.join(" "),
            m.instructions,
            m.empty
        );
    }
    let ours = &FILTERS[0];
    let six = row(&rows, ours.six)?;
    let state = state_bytes(&six.fields).context("the firmware announced no state size")?;
    let (six, nine) = (six.instructions, row(&rows, ours.nine)?.instructions);
    let late = row(&rows, NINE_WITH_MAG_DELAY)?.instructions;
    println!("{}", filter_budget_line(six, nine, late, state));
    if peers {
        let rows3 = firmware::count_at("filter_cost", firmware_features.as_deref(), OPT_LEVELS[1])?;
        let costs = filter_costs([&rows, &rows3], features)?;
        print!("\n{}", filter_table(&costs));
        if write_page {
            let old = std::fs::read_to_string(&page_path)?;
            let section = filter_section(&costs, &page::today());
            page::write_whole(&page_path, &page::splice(&old, page::ATTITUDE, &section)?)?;
            say(format!("{PAGE}: the attitude block is regenerated"));
        }
    }
    ensure!(
        six <= FILTER_6D_INSTRUCTIONS
            && nine <= FILTER_9D_INSTRUCTIONS
            && late <= FILTER_9D_INSTRUCTIONS
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

/// The row of `bin/filter_cost.rs` that counts our 9D update with
/// `FilterParams::mag_delay` set, its longest path; the 9D budget holds
/// for it too.
const NINE_WITH_MAG_DELAY: &str = "OrientationFilter::update_with_mag (9D, mag_delay set)";

/// The filter budget's report line.
fn filter_budget_line(six: i64, nine: i64, late: i64, state: u64) -> String {
    format!(
        "orientation filter on the Cortex-M4F: {six} instructions per 6D update (budget \
         {FILTER_6D_INSTRUCTIONS}), {nine} per 9D update ({late} with mag_delay set; budget \
         {FILTER_9D_INSTRUCTIONS}), {state} bytes of state (budget {FILTER_STATE_BYTES})"
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
    fn the_attitude_table_has_a_row_per_filter_and_compares_with_vqf() {
        let cost = |name: &str, six, nine| FilterCost {
            name: name.into(),
            six,
            nine,
            state: 256,
            flash: [8000, 10000],
        };
        let t = filter_table(&[
            cost("ours", [1000, 900], [2000, 1800]),
            cost("vqf", [4000, 3000], [8000, 6000]),
        ]);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 6, "{t}");
        assert_eq!(
            lines[2],
            "| ours | 1000 | 2000 | 900 | 1800 | 256 | 8000 | 10000 |"
        );
        assert_eq!(
            lines[5],
            "ours takes 0.25 times the instructions of vqf per 6D update and 0.25 times per \
             9D update (at opt-level 3: 0.30 and 0.30)."
        );
        let section = filter_section(&[cost("ours", [1, 1], [1, 1])], "2026-01-01");
        assert!(section.starts_with(page::ATTITUDE.begin), "{section}");
        assert!(section.ends_with(&format!("{}\n", page::ATTITUDE.end)));
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
            filter_budget_line(1412, 1890, 1920, 240),
            "orientation filter on the Cortex-M4F: 1412 instructions per 6D update \
             (budget 1600), 1890 per 9D update (1920 with mag_delay set; budget 2200), 240 bytes \
             of state (budget 256)"
        );
    }
}
