//! The demo binary as a newcomer runs it: what it writes, and how it fails.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rigtform-render"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("the binary starts")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every file under `dir`, relative, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push(p.strip_prefix(dir).unwrap().display().to_string());
            }
        }
    }
    out.sort();
    out
}

#[test]
fn demo_writes_frames_gif_and_contact_sheet() {
    let dir = scratch("ok");
    let o = run(&[
        "--out",
        dir.to_str().unwrap(),
        "--size",
        "40x30",
        "--frames",
        "5",
        "--sheet-rows",
        "3",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        files(&dir),
        [
            "animation.gif",
            "contact_sheet.png",
            "frames/frame_000.png",
            "frames/frame_001.png",
            "frames/frame_002.png",
            "frames/frame_003.png",
            "frames/frame_004.png",
        ]
    );
    let frame = rigtform_render::output::read_png(&dir.join("frames/frame_002.png")).unwrap();
    // Five panels of 40 pixels with 4-pixel gaps, under the label bar.
    assert_eq!(frame.width(), 5 * 40 + 4 * 4);
    assert_eq!(frame.height(), 30 + rigtform_render::demo::LABEL_BAR);
    // A shorter run into the same folder leaves no stale frames behind.
    let o = run(&[
        "--out",
        dir.to_str().unwrap(),
        "--size",
        "40x30",
        "--frames",
        "2",
        "--sheet-rows",
        "2",
        "--no-gif",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        files(&dir),
        [
            "animation.gif",
            "contact_sheet.png",
            "frames/frame_000.png",
            "frames/frame_001.png"
        ]
    );
}

#[test]
fn output_is_identical_with_one_thread_and_with_four() {
    let (one, four) = (scratch("t1"), scratch("t4"));
    for (dir, threads) in [(&one, "1"), (&four, "4")] {
        let o = run(&[
            "--out",
            dir.to_str().unwrap(),
            "--size",
            "64x48",
            "--frames",
            "3",
            "--sheet-rows",
            "3",
            "--threads",
            threads,
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    for f in files(&one) {
        let (a, b) = (
            std::fs::read(one.join(&f)).unwrap(),
            std::fs::read(four.join(&f)).unwrap(),
        );
        assert!(a == b, "{f} differs between 1 and 4 threads");
    }
}

#[test]
fn bad_size_is_refused() {
    for size in ["10x10", "320", "axb", "5000x20", "0x0"] {
        let o = run(&["--size", size, "--out", scratch("size").to_str().unwrap()]);
        assert!(!o.status.success(), "{size} accepted");
        assert!(stderr(&o).contains("--size"), "{}", stderr(&o));
    }
    assert!(!scratch("size").exists(), "nothing written");
}

#[test]
fn missing_obj_is_refused_before_anything_is_written() {
    let dir = scratch("missing-obj");
    let o = run(&[
        "--obj",
        "/nonexistent/teapot.obj",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("/nonexistent/teapot.obj"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.exists());
}

#[test]
fn unreadable_obj_is_refused() {
    let dir = scratch("bad-obj");
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("bad.obj");
    std::fs::write(&obj, "v 1 2\nf 1 2 3 4 5\n").unwrap();
    let out = dir.join("out");
    let o = run(&[
        "--obj",
        obj.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("bad.obj"), "{}", stderr(&o));
    assert!(!out.exists());
}

#[test]
fn obj_file_is_animated() {
    let dir = scratch("obj");
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("tetra.obj");
    std::fs::write(
        &obj,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .unwrap();
    let out = dir.join("out");
    let o = run(&[
        "--obj",
        obj.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--size",
        "32x24",
        "--frames",
        "2",
        "--sheet-rows",
        "2",
        "--comparison",
        "slerp",
        "--no-gif",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.join("contact_sheet.png").exists());
}

#[test]
fn output_path_that_is_a_file_is_refused() {
    let dir = scratch("file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("not-a-folder");
    std::fs::write(&file, "x").unwrap();
    let o = run(&[
        "--out",
        file.to_str().unwrap(),
        "--frames",
        "2",
        "--sheet-rows",
        "2",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("not-a-folder"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&file).unwrap(), b"x");
}

#[test]
fn more_sheet_rows_than_frames_is_refused() {
    let o = run(&[
        "--frames",
        "3",
        "--sheet-rows",
        "4",
        "--out",
        scratch("rows").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("--sheet-rows"));
}
