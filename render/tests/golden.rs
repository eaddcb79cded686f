//! Golden images: small frames of the demo compared with references in
//! `tests/golden/`.
//!
//! A frame passes when no channel of any pixel is more than
//! `MAX_CHANNEL_DIFF` off and at most `MAX_DIFFERING` of its pixels differ at
//! all: the renderer is deterministic, and the tolerance only absorbs the
//! last-bit differences of the platform's `sin`/`cos`, which may move a
//! vertex across a subpixel boundary. On failure the rendered frame and an
//! amplified difference image are written beside the test binary's
//! scratch folder (the message gives the paths).
//!
//! After an intended change of the pictures, regenerate the references with
//! `BLESS=1 cargo test -p rigtform-render --test golden` and look at them
//! before committing.

use std::path::{Path, PathBuf};

use rigtform::{Cvec3, Quat, RigTForm};
use rigtform_render::demo::{Comparison, Demo};
use rigtform_render::output::{read_png, write_png};
use rigtform_render::{Camera, Cull, Draw, Image, Mesh, Msaa, Placement, Scene, Settings};

/// Largest difference of one channel, in 8-bit steps.
const MAX_CHANNEL_DIFF: u8 = 24;
/// Largest fraction of pixels that may differ at all.
const MAX_DIFFERING: f64 = 0.002;

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden")
}

fn check(name: &str, image: &Image) {
    let reference = golden_dir().join(format!("{name}.png"));
    if std::env::var_os("BLESS").is_some() {
        write_png(&reference, image).unwrap();
        return;
    }
    let expected = read_png(&reference)
        .unwrap_or_else(|e| panic!("{e}: regenerate with BLESS=1 (see the module docs)"));
    assert_eq!(
        (image.width(), image.height()),
        (expected.width(), expected.height()),
        "{name}: size"
    );
    let mut diff = Image::new(image.width(), image.height(), [0; 3]);
    let (mut differing, mut worst) = (0usize, 0u8);
    for (i, (a, b)) in image.pixels().iter().zip(expected.pixels()).enumerate() {
        let d = (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0);
        if d > 0 {
            differing += 1;
            worst = worst.max(d);
            let (x, y) = (i as u32 % image.width(), i as u32 / image.width());
            diff.set_pixel(i64::from(x), i64::from(y), [255, d.saturating_mul(8), 0]);
        }
    }
    let fraction = differing as f64 / image.pixels().len() as f64;
    if worst > MAX_CHANNEL_DIFF || fraction > MAX_DIFFERING {
        let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("golden");
        std::fs::create_dir_all(&out).unwrap();
        let (actual_path, diff_path) = (
            out.join(format!("{name}.png")),
            out.join(format!("{name}-diff.png")),
        );
        write_png(&actual_path, image).unwrap();
        write_png(&diff_path, &diff).unwrap();
        panic!(
            "{name}: {differing} pixels differ ({:.3}%), worst by {worst}; rendered {}, difference {}",
            100.0 * fraction,
            actual_path.display(),
            diff_path.display()
        );
    }
}

fn small(msaa: Msaa) -> Settings {
    Settings {
        width: 96,
        height: 72,
        msaa,
        cull: Cull::Back,
    }
}

#[test]
fn golden_interpolation_halfway() {
    let demo = Demo::new(Comparison::Interpolation, None);
    check(
        "interpolation-0.5",
        &demo.render_frame(0.5, &small(Msaa::X4)),
    );
}

#[test]
fn golden_invariance_at_a_quarter() {
    let demo = Demo::new(Comparison::Invariance, None);
    check(
        "invariance-0.25",
        &demo.render_frame(0.25, &small(Msaa::X4)),
    );
}

#[test]
fn golden_shapes_without_antialiasing() {
    let cube = Mesh::cube(1.0, [0.9, 0.4, 0.1]);
    let sphere = Mesh::sphere(0.6, 20, 10, [0.2, 0.5, 0.9]);
    let ground = Mesh::ground([-3.0, 3.0], [-3.0, 3.0], 6, [[0.3; 3], [0.6; 3]]);
    let rigid = |t: Cvec3, r: Quat| Placement::Rigid(RigTForm::new(t, r));
    let one = Cvec3::new(1.0, 1.0, 1.0);
    let scene = Scene {
        camera: Camera::looking_at(Cvec3::new(1.0, 2.5, 4.0), Cvec3::new(0.0, 0.4, 0.0), 0.9),
        lights: [Cvec3::new(3.0, 5.0, 4.0), Cvec3::new(-4.0, 2.0, -1.0)],
        intensity: [0.7, 0.3],
        background: [0.4, 0.6, 0.85],
        draws: vec![
            Draw {
                mesh: &ground,
                placement: rigid(Cvec3::ZERO, Quat::IDENTITY),
                scale: one,
                tint: [1.0; 3],
            },
            Draw {
                mesh: &cube,
                placement: rigid(Cvec3::new(-0.6, 0.5, 0.0), Quat::from_rotation_y(0.6)),
                scale: Cvec3::new(1.0, 1.0, 0.5),
                tint: [1.0; 3],
            },
            Draw {
                mesh: &sphere,
                placement: rigid(Cvec3::new(0.7, 0.6, 0.3), Quat::IDENTITY),
                scale: one,
                tint: [1.0; 3],
            },
        ],
    };
    check("shapes-no-msaa", &scene.render(&small(Msaa::Off)));
}
