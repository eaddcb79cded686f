//! VQF beside our filter, in the same run: `tools/vqf_broad.py` runs the
//! BROAD authors' VQF (the `vqf` package from PyPI) on the same CSV and
//! prints its estimates, which the binary scores with the same metric.

use std::path::Path;
use std::process::Command;

use rigtform::Quat;
use rigtform_testkit::broad::data::BroadSample;
use rigtform_testkit::broad::metric::{self, Run};

/// The script, beside the workspace's other tools.
const SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tools/vqf_broad.py");

/// VQF's 6D and 9D runs over the trial at `path`, scored against `samples`
/// (read from the same file). `python` is the interpreter that has `vqf`.
pub fn run(python: &str, path: &Path, samples: &[BroadSample]) -> Result<(Run, Run), String> {
    let output = Command::new(python)
        .arg(SCRIPT)
        .arg(path)
        .output()
        .map_err(|e| format!("{python} {SCRIPT}: {e}"))?;
    if !output.status.success() {
        return Err(format!(
            "{python} {SCRIPT} {}: {}\n(VQF comes from PyPI: `{python} -m pip install vqf`)",
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
