//! The peers that come from PyPI, in the same run: a script of `tools/`
//! runs one on the same CSV and prints its estimates, which the binary
//! scores with the same metric. `tools/vqf_broad.py` runs the BROAD
//! authors' VQF (the `vqf` package), `tools/fusion_broad.py` x-io's Fusion
//! (the `imufusion` package).

use std::path::{Path, PathBuf};
use std::process::Command;

use rigtform::Quat;
use rigtform_testkit::broad::data::BroadSample;
use rigtform_testkit::broad::metric::{self, Run};

/// A peer run by a Python script of `tools/`.
pub struct Peer {
    /// Its name in the tables.
    pub name: &'static str,
    /// The script's file name.
    pub script: &'static str,
    /// The PyPI package the script imports.
    pub package: &'static str,
    /// The command-line flag that names the script.
    pub flag: &'static str,
    /// The environment variable that names the script.
    pub var: &'static str,
}

/// VQF, the `vqf` package.
pub const VQF: Peer = Peer {
    name: "VQF (PyPI)",
    script: "vqf_broad.py",
    package: "vqf",
    flag: "--vqf-script",
    var: "RIGTFORM_VQF_SCRIPT",
};

/// x-io's Fusion, the `imufusion` package.
pub const FUSION: Peer = Peer {
    name: "Fusion (PyPI)",
    script: "fusion_broad.py",
    package: "imufusion",
    flag: "--fusion-script",
    var: "RIGTFORM_FUSION_SCRIPT",
};

impl Peer {
    /// Where the script is: `given` (the peer's flag), else the file its
    /// environment variable names, else `<tools>/<script>`, where `tools`
    /// is the `--tools` folder (by default `tools` of the current folder:
    /// the repository's, when run from its root). Never guessed from where
    /// the binary is, which says nothing of the checkout (the target folder
    /// may be anywhere).
    pub fn find_script(&self, given: Option<&Path>, tools: &Path) -> Result<PathBuf, String> {
        let script = self.script;
        if let Some(path) = given {
            return existing(path.to_path_buf(), self.flag, script);
        }
        if let Some(path) = std::env::var_os(self.var) {
            return existing(PathBuf::from(path), self.var, script);
        }
        let path = tools.join(script);
        if path.is_file() {
            return Ok(path);
        }
        Err(format!(
            "cannot find {script}, which runs {}: {} is not a file; run from the \
             repository's root, or name its tools/ folder with --tools DIR, or the \
             script with {} PATH or {}=PATH",
            self.name,
            path.display(),
            self.flag,
            self.var,
        ))
    }

    /// The peer's 6D and 9D runs over the trial at `path`, scored against
    /// `samples` (read from the same file). `python` is the interpreter
    /// that has the package; `script` is from [`Peer::find_script`].
    pub fn run(
        &self,
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
                "{python} {shown} {}: {}\n(the script needs `{}` from PyPI: `{python} -m pip install {}`)",
                path.display(),
                String::from_utf8_lossy(&output.stderr).trim(),
                self.package,
                self.package,
            ));
        }
        let text =
            String::from_utf8(output.stdout).map_err(|e| format!("{} output: {e}", self.name))?;
        let (six, nine) = parse(&text).map_err(|e| format!("{} output: {e}", self.name))?;
        if six.len() != samples.len() {
            return Err(format!(
                "{}: {} gave {} estimates for {} samples",
                path.display(),
                self.name,
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
}

/// `path` if it is a file; else an error naming `source`.
fn existing(path: PathBuf, source: &str, script: &str) -> Result<PathBuf, String> {
    if path.is_file() {
        Ok(path)
    } else {
        Err(format!(
            "{source}: {} is not a file (it should be tools/{script} of the rigtform repository)",
            path.display()
        ))
    }
}

/// The script's output: a header, then `w6,x6,y6,z6,w9,x9,y9,z9` per sample.
fn parse(text: &str) -> Result<(Vec<Quat>, Vec<Quat>), String> {
    let mut lines = text.lines();
    if lines.next() != Some("w6,x6,y6,z6,w9,x9,y9,z9") {
        return Err("unexpected header".into());
    }
    let (mut six, mut nine) = (Vec::new(), Vec::new());
    for (i, line) in lines.enumerate() {
        let v: Vec<f32> = line
            .split(',')
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map_err(|e| format!("line {}: {e}", i + 2))?;
        let [w6, x6, y6, z6, w9, x9, y9, z9] = v[..] else {
            return Err(format!("line {}: not 8 values", i + 2));
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
