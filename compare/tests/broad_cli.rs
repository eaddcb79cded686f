//! The `broad` binary and `tools/vqf_broad.py` on the files a user may
//! hand them: both read a CSV alike, a trial without a scored sample is an
//! error, and the scripts are found where the command line says, wherever
//! the binary was built.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rigtform_testkit::broad::data::{self, Recording, BROAD_HEADER};

/// The repository's `tools/`, from this crate's folder (the test is built
/// from the checkout it tests; the binary may be anywhere).
const TOOLS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tools");

/// A fresh folder outside the repository (so that no `tools/` folder is
/// in it).
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rigtform-broad-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The binary run in `cwd` with `args`, the scripts' variables unset.
fn broad_in(cwd: &Path, args: &[&std::ffi::OsStr]) -> Output {
    Command::new(EXE)
        .args(args)
        .current_dir(cwd)
        .env_remove("RIGTFORM_VQF_SCRIPT")
        .env_remove("RIGTFORM_FUSION_SCRIPT")
        .output()
        .expect("the binary starts")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

const EXE: &str = env!("CARGO_BIN_EXE_broad");

/// A scored sample at rest, level, with its ground truth.
const ROW: &str = "0,0,0,0,0,9.81,0,16,-41,1,0,0,0,1";

#[test]
fn trial_without_a_scored_sample_is_an_error() {
    let dir = scratch("unscored");
    let still = "0,0,0,0,0,9.81,0,16,-41,1,0,0,0,0";
    let hidden = "0,0,0,0,0,9.81,0,16,-41,nan,nan,nan,nan,1";
    for (name, rows) in [("rest", [still; 3]), ("hidden", [hidden; 3])] {
        let path = dir.join(format!("broad_{name}.csv"));
        std::fs::write(&path, format!("{BROAD_HEADER}\n{}\n", rows.join("\n"))).unwrap();
        let o = broad_in(
            &dir,
            &["--tools".as_ref(), TOOLS.as_ref(), path.as_os_str()],
        );
        assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
        assert!(stderr(&o).contains("no sample is scored"), "{}", stderr(&o));
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(!stdout.contains("NaN"), "{stdout}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn scripts_are_found_in_the_tools_folder_the_command_line_names() {
    let dir = scratch("tools");
    let trial = dir.join("broad_99.csv");
    std::fs::write(&trial, format!("{BROAD_HEADER}\n{ROW}\n{ROW}\n")).unwrap();
    // Run where there is no tools/ folder: the message names the file it
    // looked for and the options that name another.
    let o = broad_in(&dir, &[trial.as_os_str()]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("cannot find vqf_broad.py"), "{err}");
    assert!(
        err.contains(
            &Path::new("tools")
                .join("vqf_broad.py")
                .display()
                .to_string()
        ),
        "{err}"
    );
    assert!(err.contains("--tools DIR"), "{err}");
    // A tools/ folder in the current folder is the default: this script,
    // for `sh`, prints the identity for both of VQF's runs. Fusion's
    // script is looked for in the same folder, and the message names it.
    let tools = dir.join("tools");
    std::fs::create_dir(&tools).unwrap();
    let script = "echo w6,x6,y6,z6,w9,x9,y9,z9\nfor i in 1 2; do echo 1,0,0,0,1,0,0,0; done\n";
    std::fs::write(tools.join("vqf_broad.py"), script).unwrap();
    let o = broad_in(
        &dir,
        &["--python".as_ref(), "sh".as_ref(), trial.as_os_str()],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("cannot find fusion_broad.py"), "{err}");
    std::fs::write(tools.join("fusion_broad.py"), script).unwrap();
    // From any other folder, --tools names it.
    let elsewhere = scratch("elsewhere");
    for (cwd, args) in [
        (&dir, vec![]),
        (&elsewhere, vec!["--tools".as_ref(), tools.as_os_str()]),
    ] {
        let mut args: Vec<&std::ffi::OsStr> = args;
        args.extend(["--python".as_ref(), "sh".as_ref(), trial.as_os_str()]);
        let o = broad_in(cwd, &args);
        assert!(o.status.success(), "{}", stderr(&o));
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(
            stdout.contains("broad_99.csv: 2 samples, 2 scored"),
            "{stdout}"
        );
    }
    // A script named by the flag or the variable must exist.
    let missing = dir.join("nowhere.py");
    let o = broad_in(
        &dir,
        &[
            "--vqf-script".as_ref(),
            missing.as_os_str(),
            trial.as_os_str(),
        ],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("nowhere.py is not a file"),
        "{}",
        stderr(&o)
    );
    let o = Command::new(EXE)
        .arg(&trial)
        .current_dir(&dir)
        .env("RIGTFORM_VQF_SCRIPT", &missing)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("RIGTFORM_VQF_SCRIPT"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_dir_all(&elsewhere).unwrap();
}

/// How many samples `tools/vqf_broad.py`'s reader finds in `path`, or its
/// error.
fn python_reads(path: &Path) -> Result<usize, String> {
    let code = "import sys\nsys.path.insert(0, sys.argv[1])\nfrom vqf_broad import read_trial\n\
                try:\n    print(len(read_trial(sys.argv[2])))\n\
                except ValueError as e:\n    sys.exit(str(e))\n";
    let o = Command::new("python3")
        .args(["-c", code, TOOLS])
        .arg(path)
        .output()
        .expect("python3 starts");
    if o.status.success() {
        Ok(String::from_utf8_lossy(&o.stdout).trim().parse().unwrap())
    } else {
        let err = stderr(&o);
        assert!(!err.contains("Traceback"), "{err}");
        Err(err)
    }
}

/// How many samples the binary's reader finds in `path` (an empty trial
/// is refused by the binary).
fn rust_reads(path: &Path) -> Result<usize, String> {
    match data::read(path)? {
        Recording::Broad(s) if s.is_empty() => Err("no samples".into()),
        Recording::Broad(s) => Ok(s.len()),
        Recording::Fusion(_) => Err("a Fusion log".into()),
    }
}

#[test]
fn rust_and_python_read_every_csv_alike() {
    let dir = scratch("csv");
    let h = BROAD_HEADER;
    let cases = [
        ("plain", format!("{h}\n{ROW}\n{ROW}\n"), Some(2)),
        ("bom", format!("\u{feff}{h}\n{ROW}\n"), Some(1)),
        ("blank", format!("{h}\n\n{ROW}\n\n{ROW}\n\n"), Some(2)),
        ("crlf", format!("{h}\r\n{ROW}\r\n\r\n{ROW}\r\n"), Some(2)),
        (
            "spaces",
            format!("\u{feff}{h}\n{ROW}\n   \n{ROW}\n"),
            Some(2),
        ),
        ("header-only", format!("{h}\n\n"), None),
        (
            "text",
            format!("{h}\n{ROW}\n0,0,x,0,0,9.81,0,16,-41,1,0,0,0,1\n"),
            None,
        ),
        ("short", format!("{h}\n{ROW}\n0,0,0\n"), None),
        ("empty", String::new(), None),
    ];
    for (name, text, want) in cases {
        let path = dir.join(format!("{name}.csv"));
        std::fs::write(&path, text).unwrap();
        let (rust, python) = (rust_reads(&path), python_reads(&path));
        match want {
            Some(n) => {
                assert_eq!(rust, Ok(n), "{name}: Rust");
                assert_eq!(python, Ok(n), "{name}: Python");
            }
            None => {
                assert!(rust.is_err(), "{name}: Rust read {rust:?}");
                assert!(python.is_err(), "{name}: Python read {python:?}");
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
