//! VQF beside our filter, in the same run: `tools/vqf_broad.py` runs the
//! BROAD authors' VQF (the `vqf` package from PyPI) on the same CSV and
//! prints its estimates, which the binary scores with the same metric.

use std::path::{Path, PathBuf};
use std::process::Command;

use rigtform::Quat;
use rigtform_testkit::broad::data::BroadSample;
use rigtform_testkit::broad::metric::{self, Run};

/// The script's file name.
const SCRIPT: &str = "vqf_broad.py";

/// The environment variable that names the script.
pub const SCRIPT_VAR: &str = "RIGTFORM_VQF_SCRIPT";

/// Where the script is, found at run time: `given` (the `--vqf-script`
/// flag), else the file [`SCRIPT_VAR`] names, else `vqf_broad.py` next to
/// the binary, else `tools/vqf_broad.py` in the folder of the binary or
/// one above it (the repository, for a binary under `target/`).
pub fn find_script(given: Option<&Path>) -> Result<PathBuf, String> {
    if let Some(path) = given {
        return existing(path.to_path_buf(), "--vqf-script");
    }
    if let Some(path) = std::env::var_os(SCRIPT_VAR) {
        return existing(PathBuf::from(path), SCRIPT_VAR);
    }
    let exe = std::env::current_exe().map_err(|e| format!("cannot locate the binary: {e}"))?;
    let dir = exe.parent().unwrap_or(Path::new("."));
    let candidates: Vec<PathBuf> = std::iter::once(dir.join(SCRIPT))
        .chain(dir.ancestors().map(|d| d.join("tools").join(SCRIPT)))
        .collect();
    candidates.into_iter().find(|p| p.is_file()).ok_or_else(|| {
        format!(
            "cannot find {SCRIPT}, which runs VQF: put it next to the binary ({}), \
             or name it with --vqf-script PATH or {SCRIPT_VAR}=PATH \
             (it is tools/{SCRIPT} in the rigtform repository)",
            dir.join(SCRIPT).display()
        )
    })
}

/// `path` if it is a file; else an error naming `source`.
fn existing(path: PathBuf, source: &str) -> Result<PathBuf, String> {
    if path.is_file() {
        Ok(path)
    } else {
        Err(format!(
            "{source}: {} is not a file (it should be tools/{SCRIPT} of the rigtform repository)",
            path.display()
        ))
    }
}

/// VQF's 6D and 9D runs over the trial at `path`, scored against `samples`
/// (read from the same file). `python` is the interpreter that has `vqf`;
/// `script` is `tools/vqf_broad.py` ([`find_script`]).
pub fn run(
    python: &str,
    script: &Path,
    path: &Path,
    samples: &[BroadSample],
) -> Result<(Run, Run), String> {
    let shown = script.display();
    let output = Command::new(python)
        .arg(script)
        .arg(path)
        .output()
        .map_err(|e| format!("{python} {shown}: {e}"))?;
    if !output.status.success() {
        return Err(format!(
            "{python} {shown} {}: {}\n(VQF comes from PyPI: `{python} -m pip install vqf`)",
            path.display(),
            String::from_utf8_lossy(&output.stderr).trim()
        ));
    }
    let text = String::from_utf8(output.stdout).map_err(|e| format!("VQF output: {e}"))?;
    let (six, nine) = parse(&text)?;
    if six.len() != samples.len() {
        return Err(format!(
            "{}: VQF gave {} estimates for {} samples",
            path.display(),
            six.len(),
            samples.len()
        ));
    }
    let score = |estimates: Vec<Quat>| Run {
        rmse: metric::score(samples, &estimates),
        estimates,
    };
    Ok((score(six), score(nine)))
}

/// The script's output: a header, then `w6,x6,y6,z6,w9,x9,y9,z9` per sample.
fn parse(text: &str) -> Result<(Vec<Quat>, Vec<Quat>), String> {
    let mut lines = text.lines();
    if lines.next() != Some("w6,x6,y6,z6,w9,x9,y9,z9") {
        return Err("VQF output: unexpected header".into());
    }
    let (mut six, mut nine) = (Vec::new(), Vec::new());
    for (i, line) in lines.enumerate() {
        let v: Vec<f32> = line
            .split(',')
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map_err(|e| format!("VQF output line {}: {e}", i + 2))?;
        let [w6, x6, y6, z6, w9, x9, y9, z9] = v[..] else {
            return Err(format!("VQF output line {}: not 8 values", i + 2));
        };
        six.push(Quat::from_wxyz(w6, x6, y6, z6));
        nine.push(Quat::from_wxyz(w9, x9, y9, z9));
    }
    Ok((six, nine))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_scripts_lines_and_rejects_others() {
        let text = "w6,x6,y6,z6,w9,x9,y9,z9\n1,0,0,0,0.5,0.5,0.5,0.5\n";
        let (six, nine) = parse(text).unwrap();
        assert_eq!(six, [Quat::IDENTITY]);
        assert_eq!(nine, [Quat::from_wxyz(0.5, 0.5, 0.5, 0.5)]);
        assert!(parse("w,x,y,z\n1,0,0,0\n").is_err());
        assert!(parse("w6,x6,y6,z6,w9,x9,y9,z9\n1,0,0,0\n").is_err());
        assert!(parse("w6,x6,y6,z6,w9,x9,y9,z9\n1,0,0,0,1,0,0,x\n").is_err());
    }
}
