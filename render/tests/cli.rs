//! The demo binary as a newcomer runs it: what it writes, and how it fails.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rigtform_render::output::read_png;

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs the binary with `--out out` and the whitespace-separated `args`
/// (paths in `paths` are appended after them, since they may hold spaces).
fn run(out: &Path, args: &str, paths: &[&Path]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rigtform-render"))
        .arg("--out")
        .arg(out)
        .args(args.split_whitespace())
        .args(paths)
        .output()
        .expect("the binary starts")
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

/// Writes an OBJ file with the given text into a fresh scratch folder and
/// returns its path and the output folder to render into.
fn obj_file(name: &str, text: &str) -> (PathBuf, PathBuf) {
    let dir = scratch(name);
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join(format!("{name}.obj"));
    std::fs::write(&obj, text).unwrap();
    (obj, dir.join("out"))
}

#[test]
fn demo_writes_frames_gif_and_contact_sheet() {
    let dir = scratch("ok");
    let o = run(&dir, "--size 40x30 --frames 5 --sheet-rows 3", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let frames: Vec<String> = (0..5).map(|i| format!("frames/frame_00{i}.png")).collect();
    let mut expected = vec!["animation.gif".to_string(), "contact_sheet.png".to_string()];
    expected.extend(frames);
    assert_eq!(files(&dir), expected);
    let frame = read_png(&dir.join("frames/frame_002.png")).unwrap();
    // Five panels of 40 pixels with 4-pixel gaps, under the label bar.
    assert_eq!(frame.width(), 5 * 40 + 4 * 4);
    assert_eq!(frame.height(), 30 + rigtform_render::demo::LABEL_BAR);
    // A shorter run into the same folder leaves no stale frames behind,
    // nor the GIF of the earlier run, and leaves other files alone.
    std::fs::write(dir.join("frames/notes.png"), "mine").unwrap();
    std::fs::write(dir.join("frames/frame_list.txt"), "mine").unwrap();
    let o = run(&dir, "--size 40x30 --frames 2 --sheet-rows 2 --no-gif", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut expected = expected[1..4].to_vec();
    expected.extend([
        "frames/frame_list.txt".to_string(),
        "frames/notes.png".to_string(),
    ]);
    expected.sort();
    assert_eq!(files(&dir), expected);
}

#[test]
fn output_is_identical_with_one_thread_and_with_four() {
    let (one, four) = (scratch("t1"), scratch("t4"));
    for (dir, threads) in [(&one, "1"), (&four, "4")] {
        let args = format!("--size 64x48 --frames 3 --sheet-rows 3 --threads {threads}");
        let o = run(dir, &args, &[]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let written = files(&one);
    assert_eq!(written.len(), 5);
    for f in written {
        let (a, b) = (
            std::fs::read(one.join(&f)).unwrap(),
            std::fs::read(four.join(&f)).unwrap(),
        );
        assert!(a == b, "{f} differs between 1 and 4 threads");
    }
}

#[test]
fn msaa_is_on_by_default_and_can_be_turned_off() {
    let (four, default, one) = (scratch("msaa4"), scratch("msaa-default"), scratch("msaa1"));
    let base = "--size 48x36 --frames 2 --sheet-rows 2 --no-gif";
    for (dir, extra) in [(&four, " --msaa 4"), (&default, ""), (&one, " --msaa 1")] {
        let o = run(dir, &format!("{base}{extra}"), &[]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let frame = |dir: &Path| read_png(&dir.join("frames/frame_001.png")).unwrap();
    assert_eq!(frame(&four), frame(&default));
    assert_ne!(frame(&four), frame(&one));
    let o = run(&scratch("msaa2"), "--msaa 2", &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("1 or 4"), "{}", stderr(&o));
}

#[test]
fn bad_size_is_refused() {
    let dir = scratch("size");
    for size in ["10x10", "320", "axb", "5000x20", "0x0"] {
        let o = run(&dir, &format!("--size {size}"), &[]);
        assert_eq!(o.status.code(), Some(2), "{size} accepted");
        assert!(stderr(&o).contains("--size"), "{}", stderr(&o));
    }
    assert!(!dir.exists(), "nothing written");
}

#[test]
fn missing_obj_is_refused_before_anything_is_written() {
    let dir = scratch("missing-obj");
    let o = run(&dir, "--obj", &[Path::new("/nonexistent/teapot.obj")]);
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
    let (obj, out) = obj_file("bad", "v 1 2\nf 1 2 3 4 5\n");
    let o = run(&out, "--obj", &[&obj]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("bad.obj"), "{}", stderr(&o));
    assert!(!out.exists());
}

#[test]
fn obj_file_with_quad_faces_is_animated() {
    // A unit cube with quadrilateral faces, which tobj triangulates.
    let cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let (obj, out) = obj_file("cube", cube);
    let args = "--size 32x24 --frames 2 --sheet-rows 2 --comparison slerp --no-gif --obj";
    let o = run(&out, args, &[&obj]);
    assert!(o.status.success(), "{}", stderr(&o));
    let frame = read_png(&out.join("frames/frame_000.png")).unwrap();
    // The orange cube is in the picture.
    let orange = |p: &[u8; 3]| u16::from(p[0]) > u16::from(p[2]) + 60;
    assert!(frame.pixels().iter().any(orange), "no cube drawn");
}

#[test]
fn output_path_that_is_a_file_is_refused() {
    let dir = scratch("file");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("not-a-folder");
    std::fs::write(&file, "x").unwrap();
    let o = run(&file, "--frames 2 --sheet-rows 2", &[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("not-a-folder"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&file).unwrap(), b"x");
}

#[test]
fn more_sheet_rows_than_frames_is_refused() {
    let dir = scratch("rows");
    let o = run(&dir, "--frames 3 --sheet-rows 4", &[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("--sheet-rows"));
    assert!(!dir.exists());
}

#[test]
fn spline_comparison_writes_two_panels_and_the_speed_plot() {
    let dir = scratch("spline");
    let o = run(
        &dir,
        "--spline --size 40x30 --frames 3 --sheet-rows 3 --no-gif",
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let expected = [
        "angular_speed.png",
        "contact_sheet.png",
        "frames/frame_000.png",
        "frames/frame_001.png",
        "frames/frame_002.png",
    ];
    assert_eq!(files(&dir), expected);
    let frame = read_png(&dir.join("frames/frame_001.png")).unwrap();
    // Two panels of 40 pixels with a 4-pixel gap, under the label bar.
    assert_eq!(frame.width(), 2 * 40 + 4);
    assert_eq!(frame.height(), 30 + rigtform_render::demo::LABEL_BAR);
    let plot = read_png(&dir.join("angular_speed.png")).unwrap();
    assert_eq!((plot.width(), plot.height()), (640, 320));
    // Both jumps reported, slerp's in radians per second, the spline's
    // orders of magnitude smaller.
    let stdout = String::from_utf8_lossy(&o.stdout);
    let jumps: Vec<f32> = stdout
        .lines()
        .filter_map(|l| l.split("at a key ").nth(1))
        .filter_map(|rest| rest.split_whitespace().next()?.parse().ok())
        .collect();
    assert_eq!(jumps.len(), 2, "{stdout}");
    assert!(jumps[0] > 1.0 && jumps[1] < 1e-2, "{stdout}");
    // It picks its own panels: a comparison as well is refused.
    let o = run(&scratch("spline-both"), "--spline --comparison slerp", &[]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn few_frames_work_with_the_default_sheet() {
    for frames in 2..=4 {
        let dir = scratch(&format!("few-{frames}"));
        let o = run(
            &dir,
            &format!("--size 32x24 --frames {frames} --no-gif"),
            &[],
        );
        assert!(o.status.success(), "--frames {frames}: {}", stderr(&o));
        let sheet = read_png(&dir.join("contact_sheet.png")).unwrap();
        // One row per frame: the panel height and the label bar, and a gap.
        let row = 24 + rigtform_render::demo::LABEL_BAR + 4;
        assert_eq!(sheet.height(), frames * row, "--frames {frames}");
    }
}

#[test]
fn settings_that_need_too_much_memory_are_refused_before_rendering() {
    let dir = scratch("memory");
    let o = run(&dir, "--size 4096x4096 --frames 1000", &[]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("--memory-limit 4096 MiB"), "{err}");
    assert!(
        err.contains("--size 4096x4096 with --frames 1000 needs about"),
        "{err}"
    );
    // Two frames at 4096x4096 with every panel: each frame 20496 x 4120,
    // 253 MB, and a 4x multisampled framebuffer of 1 GiB per thread.
    let o = run(
        &dir,
        "--size 4096x4096 --frames 2 --threads 2 --memory-limit 2048",
        &[],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(!dir.exists(), "nothing written");
    // A raised limit lets a small run through, a low one refuses it.
    let o = run(
        &dir,
        "--size 64x48 --frames 2 --no-gif --memory-limit 64",
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run(
        &dir,
        "--size 4096x4096 --frames 2 --no-gif --msaa 1 --threads 1 --memory-limit 64",
        &[],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
}

#[test]
fn endless_obj_is_refused() {
    let dir = scratch("dev-zero");
    let o = run(&dir, "--obj", &[Path::new("/dev/zero")]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("/dev/zero"), "{}", stderr(&o));
    assert!(!dir.exists());
}

#[test]
fn obj_too_large_to_centre_is_refused() {
    let (obj, out) = obj_file("huge", "v -2e38 0 0\nv 2e38 0 0\nv 0 1 0\nf 1 2 3\n");
    let o = run(&out, "--frames 2 --obj", &[&obj]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("huge.obj"), "{}", stderr(&o));
    assert!(!out.exists());
}
