//! The host table from criterion's results: the benchmark ids come from
//! the ops bench's own `--list` (in the order it registers and runs them),
//! the timings from the `benchmark.json` and `estimates.json` criterion
//! writes for each benchmark under `target/criterion/`.

use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

use anyhow::{bail, Context, Result};
use serde::Deserialize;

/// The library whose time the last column compares with the fastest peer.
const RIGTFORM: &str = "rigtform";

/// `benchmark.json`: which benchmark a directory holds.
#[derive(Deserialize)]
struct BenchmarkFile {
    group_id: String,
    function_id: Option<String>,
    full_id: String,
    throughput: Option<Throughput>,
}

/// criterion's `Throughput`, of which the bench sets `Elements`: calls per
/// iteration.
#[derive(Deserialize)]
struct Throughput {
    #[serde(rename = "Elements")]
    elements: Option<u64>,
}

/// `estimates.json`: the statistics of one benchmark's samples.
#[derive(Deserialize)]
struct Estimates {
    median: Estimate,
}

#[derive(Deserialize)]
struct Estimate {
    point_estimate: f64,
}

/// One benchmark's median time per call.
#[derive(Clone, Debug, PartialEq)]
pub struct Timing {
    /// The full id, `group/function`, as `--list` prints it.
    pub id: String,
    /// The group: the operation.
    pub group: String,
    /// The function: the library.
    pub library: String,
    /// The median time per iteration over the calls per iteration, in ns.
    pub ns_per_call: f64,
}

/// Reads the timing in one benchmark's directory of criterion's output
/// (`benchmark.json` and `estimates.json`).
pub fn read_timing(dir: &Path) -> Result<Timing> {
    let read = |name: &str| {
        let path = dir.join(name);
        std::fs::read_to_string(&path).with_context(|| format!("reading {}", path.display()))
    };
    let bench: BenchmarkFile = serde_json::from_str(&read("benchmark.json")?)
        .with_context(|| format!("parsing {}/benchmark.json", dir.display()))?;
    let estimates: Estimates = serde_json::from_str(&read("estimates.json")?)
        .with_context(|| format!("parsing {}/estimates.json", dir.display()))?;
    let calls = bench
        .throughput
        .and_then(|t| t.elements)
        .filter(|&n| n > 0)
        .with_context(|| {
            format!(
                "{}: no Elements throughput (calls per iteration) in benchmark.json",
                bench.full_id
            )
        })?;
    Ok(Timing {
        library: bench
            .function_id
            .with_context(|| format!("{}: a benchmark outside a group", bench.full_id))?,
        id: bench.full_id,
        group: bench.group_id,
        ns_per_call: estimates.median.point_estimate / calls as f64,
    })
}

/// Every timing under criterion's output directory
/// (`<group>/<function>/new/`).
pub fn read_all(criterion_dir: &Path) -> Result<Vec<Timing>> {
    let mut timings = Vec::new();
    let entries =
        |dir: &Path| std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()));
    for group in entries(criterion_dir)? {
        let group = group?.path();
        if !group.is_dir() {
            continue;
        }
        for function in entries(&group)? {
            let new = function?.path().join("new");
            if new.join("benchmark.json").is_file() {
                timings.push(read_timing(&new)?);
            }
        }
    }
    Ok(timings)
}

/// The benchmark ids in the output of the bench's `--list`, in order.
pub fn listed(output: &str) -> Vec<String> {
    output
        .lines()
        .filter_map(|l| l.strip_suffix(": benchmark"))
        .map(str::to_owned)
        .collect()
}

/// The Markdown table: a row per group (operation) in the order the ids
/// are listed, a column per library (rigtform's builds first, then the
/// peers, each in the order listed), ns per call to two decimals or `-`,
/// and rigtform's time over the fastest peer's. Every listed id must have a
/// timing.
pub fn host_table(listed: &[String], timings: &[Timing]) -> Result<String> {
    let by_id: HashMap<&str, &Timing> = timings.iter().map(|t| (t.id.as_str(), t)).collect();
    let mut groups: Vec<&str> = Vec::new();
    let mut libraries: Vec<&str> = Vec::new();
    let mut ns: HashMap<(&str, &str), f64> = HashMap::new();
    for id in listed {
        let Some(t) = by_id.get(id.as_str()) else {
            bail!("no result for the benchmark {id:?} under target/criterion (did it run?)");
        };
        if !groups.contains(&t.group.as_str()) {
            groups.push(&t.group);
        }
        if !libraries.contains(&t.library.as_str()) {
            libraries.push(&t.library);
        }
        ns.insert((&t.group, &t.library), t.ns_per_call);
    }
    if groups.is_empty() {
        bail!("the bench listed no benchmark");
    }
    let is_ours = |l: &str| l.starts_with(RIGTFORM);
    let (mut columns, peers): (Vec<&str>, Vec<&str>) = libraries.iter().partition(|l| is_ours(l));
    columns.extend(&peers);

    let mut t = String::from("| operation |");
    for c in &columns {
        write!(t, " {c} |").unwrap();
    }
    writeln!(t, " {RIGTFORM} / fastest peer |").unwrap();
    t += "|";
    t += &" --- |".repeat(columns.len() + 2);
    t += "\n";
    for g in &groups {
        write!(t, "| {g} |").unwrap();
        for c in &columns {
            match ns.get(&(g, c)) {
                Some(v) => write!(t, " {v:.2} |").unwrap(),
                None => t += " - |",
            }
        }
        let fastest = peers
            .iter()
            .filter_map(|p| ns.get(&(g, p)).copied())
            .min_by(f64::total_cmp);
        match (ns.get(&(g, RIGTFORM)), fastest) {
            (Some(ours), Some(best)) => writeln!(t, " {:.2} |", ours / best).unwrap(),
            _ => t += " - |\n",
        }
    }
    Ok(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write_result(dir: &Path, group: &str, function: &str, median: f64) {
        let d = dir
            .join(group.replace(['*', '/'], "_"))
            .join(function)
            .join("new");
        std::fs::create_dir_all(&d).unwrap();
        let bench = format!(
            r#"{{"group_id":"{group}","function_id":"{function}","value_str":null,"throughput":{{"Elements":1024}},"full_id":"{group}/{function}","directory_name":"x","title":"{group}/{function}"}}"#
        );
        std::fs::write(d.join("benchmark.json"), bench).unwrap();
        let e = |v: f64| {
            format!(
                r#"{{"confidence_interval":{{"confidence_level":0.95,"lower_bound":{l},"upper_bound":{u}}},"point_estimate":{v},"standard_error":1.5}}"#,
                l = v - 1.0,
                u = v + 1.0
            )
        };
        let estimates = format!(
            r#"{{"mean":{},"median":{},"median_abs_dev":{},"slope":null,"std_dev":{}}}"#,
            e(median + 100.0),
            e(median),
            e(3.0),
            e(4.0)
        );
        std::fs::write(d.join("estimates.json"), estimates).unwrap();
    }

    #[test]
    fn reads_the_median_per_call() {
        let dir = tempfile::tempdir().unwrap();
        write_result(dir.path(), "q*q", "glam (SIMD)", 2048.0);
        let timings = read_all(dir.path()).unwrap();
        assert_eq!(
            timings,
            [Timing {
                id: "q*q/glam (SIMD)".into(),
                group: "q*q".into(),
                library: "glam (SIMD)".into(),
                ns_per_call: 2.0,
            }]
        );
    }

    #[test]
    fn a_result_without_calls_per_iteration_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        write_result(dir.path(), "slerp", "glam", 100.0);
        let file = dir.path().join("slerp/glam/new/benchmark.json");
        let text = std::fs::read_to_string(&file).unwrap();
        std::fs::write(&file, text.replace(r#"{"Elements":1024}"#, "null")).unwrap();
        assert!(read_all(dir.path()).is_err());
        // Zero calls per iteration would divide by zero.
        std::fs::write(
            &file,
            text.replace(r#"{"Elements":1024}"#, r#"{"Elements":0}"#),
        )
        .unwrap();
        assert!(read_all(dir.path()).is_err());
    }

    #[test]
    fn reads_the_listed_ids() {
        let out = "Gnuplot not found\nq*q/rigtform: benchmark\nq*q/glam (SIMD): benchmark\n";
        assert_eq!(listed(out), ["q*q/rigtform", "q*q/glam (SIMD)"]);
    }

    fn timing(group: &str, library: &str, ns: f64) -> Timing {
        Timing {
            id: format!("{group}/{library}"),
            group: group.into(),
            library: library.into(),
            ns_per_call: ns,
        }
    }

    #[test]
    fn rows_and_columns_follow_the_list() {
        let timings = [
            timing("slerp", "glam", 20.0),
            timing("slerp", "nalgebra", 25.0),
            timing("q*q", "rigtform", 2.0),
            timing("q*q", "glam", 1.0),
            timing("slerp", "rigtform", 50.0),
            // Faster than every peer: still not a peer.
            timing("slerp", "rigtform (x86-64-v3)", 10.0),
            timing("pow", "rigtform", 3.0),
            timing("stale", "rigtform", 1.0),
        ];
        let list: Vec<String> = [
            "q*q/rigtform",
            "q*q/glam",
            "slerp/rigtform",
            "slerp/glam",
            "slerp/nalgebra",
            "pow/rigtform",
            "slerp/rigtform (x86-64-v3)",
        ]
        .map(String::from)
        .to_vec();
        let t = host_table(&list, &timings).unwrap();
        let expected = "\
| operation | rigtform | rigtform (x86-64-v3) | glam | nalgebra | rigtform / fastest peer |
| --- | --- | --- | --- | --- | --- |
| q*q | 2.00 | - | 1.00 | - | 2.00 |
| slerp | 50.00 | 10.00 | 20.00 | 25.00 | 2.50 |
| pow | 3.00 | - | - | - | - |
";
        assert_eq!(t, expected);
    }

    #[test]
    fn a_listed_benchmark_without_a_result_is_an_error() {
        let list = vec!["q*q/rigtform".to_string(), "q*q/glam".to_string()];
        let e = host_table(&list, &[timing("q*q", "rigtform", 2.0)]).unwrap_err();
        assert!(e.to_string().contains("q*q/glam"), "{e:#}");
        assert!(host_table(&[], &[]).is_err());
    }
}
