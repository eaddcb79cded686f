//! `rigtform-render --gltf`: the committed BoxAnimated asset played, and
//! every kind of bad file refused with a message, a non-zero exit and no
//! output at all.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rigtform::Quat;
use rigtform_render::gltf_scene::{GltfScene, Values};
use rigtform_render::output::read_png;

fn asset() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/BoxAnimated/BoxAnimated.gltf")
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("gltf-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn render(file: &Path, out: &Path, args: &str) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rigtform-render"))
        .arg("--gltf")
        .arg(file)
        .arg("--out")
        .arg(out)
        .args(args.split_whitespace())
        .output()
        .expect("the binary starts")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn box_animated_is_played_into_frames_a_sheet_and_a_gif() {
    let dir = scratch("box");
    let out = dir.join("out");
    let o = render(&asset(), &out, "--size 48x36 --frames 9 --sheet-rows 3");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("2 channel(s), 0.000 s to 3.708 s"));
    for i in 0..9 {
        let frame = read_png(&out.join(format!("frames/frame_{i:03}.png"))).unwrap();
        assert_eq!(
            (frame.width(), frame.height()),
            (48, 36 + rigtform_render::demo::LABEL_BAR)
        );
    }
    assert!(out.join("contact_sheet.png").exists() && out.join("animation.gif").exists());
    // The inner box moves: the first and middle frames differ.
    let a = read_png(&out.join("frames/frame_000.png")).unwrap();
    let b = read_png(&out.join("frames/frame_004.png")).unwrap();
    assert_ne!(a.pixels(), b.pixels());
}

#[test]
fn box_animated_channels_are_read_as_the_file_holds_them() {
    let scene = GltfScene::load(&asset()).unwrap();
    assert_eq!(scene.span(), (0.0, 3.708_33));
    assert!(scene.unsupported.is_empty());
    assert_eq!(scene.channels.len(), 2);
    // Two channels of different lengths: a rotation of node 2 over 1.25 s
    // to 2.5 s, a translation of node 0 over 0 s to 3.708 s.
    let rotation = &scene.channels[0];
    assert_eq!(
        (rotation.node, rotation.times.as_slice()),
        (2, [1.25f32, 2.5].as_slice())
    );
    let Values::Rotation(keys) = &rotation.values else {
        panic!("channel 0 drives a rotation");
    };
    // Stored as x, y, z, w: -identity, then a half turn about x.
    assert_eq!(
        keys[0],
        Quat {
            x: -0.0,
            y: -0.0,
            z: -0.0,
            w: -1.0
        }
    );
    assert!(keys[1].angle_to(Quat::from_rotation_x(core::f32::consts::PI)) < 1e-6);
    let translation = &scene.channels[1];
    assert_eq!((translation.node, translation.times.len()), (0, 4));
    // Before its first key the rotation holds it; the translation has
    // reached its second key (2.52 up) at 1.25 s.
    let local = scene.local_transforms(1.25);
    assert!(local[2].r.angle_to(Quat::IDENTITY) < 1e-6);
    assert!((local[0].t.y - 2.52).abs() < 1e-6);
    // Halfway through the rotation: a quarter turn about x.
    let mid = scene.local_transforms(1.875)[2].r;
    assert!(mid.angle_to(Quat::from_rotation_x(core::f32::consts::FRAC_PI_2)) < 1e-5);
}

/// Writes `text` as a file in a fresh scratch folder, renders it, and
/// checks the run failed with a message containing `expected` and wrote
/// nothing.
fn refused(name: &str, text: &[u8], expected: &str) {
    let dir = scratch(name);
    let file = dir.join(format!("{name}.gltf"));
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let o = render(&file, &out, "--size 32x24 --frames 3 --sheet-rows 2");
    assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
    assert!(stderr(&o).contains(expected), "{name}: {}", stderr(&o));
    assert!(!out.exists(), "{name}: output written");
}

fn box_json() -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(asset()).unwrap()).unwrap()
}

#[test]
fn missing_file_is_refused() {
    let dir = scratch("missing");
    let out = dir.join("out");
    let o = render(&dir.join("nothing.gltf"), &out, "");
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("cannot read"), "{}", stderr(&o));
    assert!(!out.exists());
}

#[test]
fn a_file_that_is_not_gltf_is_refused() {
    refused("text", b"v 0 0 0\nf 1 2 3\n", "not a valid glTF file");
    refused("json", br#"{"hello": "world"}"#, "not a valid glTF file");
}

#[test]
fn truncated_json_is_refused() {
    let full = std::fs::read(asset()).unwrap();
    refused(
        "truncated",
        &full[..full.len() / 2],
        "not a valid glTF file",
    );
}

#[test]
fn a_file_without_animation_is_refused() {
    let mut json = box_json();
    json.as_object_mut().unwrap().remove("animations");
    refused("still", json.to_string().as_bytes(), "no animation");
}

#[test]
fn broken_accessors_are_refused() {
    // More key times than the buffer view holds.
    let mut json = box_json();
    json["accessors"][8]["count"] = 40.into();
    refused(
        "count",
        json.to_string().as_bytes(),
        "do not fit in buffer view",
    );
    // A buffer view past the end of its buffer.
    let mut json = box_json();
    json["bufferViews"][2]["byteLength"] = 100_000.into();
    refused(
        "view",
        json.to_string().as_bytes(),
        "runs past the end of buffer",
    );
    // Key times as vectors.
    let mut json = box_json();
    json["accessors"][6]["type"] = "VEC3".into();
    refused(
        "kind",
        json.to_string().as_bytes(),
        "expected one of [Scalar]",
    );
    // An accessor that does not exist (the gltf crate's validation).
    let mut json = box_json();
    json["animations"][0]["samplers"][0]["output"] = 99.into();
    refused(
        "index",
        json.to_string().as_bytes(),
        "not a valid glTF file",
    );
    // Key times out of order: the rotation's two times read from one
    // float later in their view, 2.5 and then the translation's first
    // time, 0.0.
    let mut json = box_json();
    json["accessors"][6]["byteOffset"] = 4.into();
    refused(
        "order",
        json.to_string().as_bytes(),
        "is not greater than the one before it",
    );
    // A base64 buffer cut short.
    let mut json = box_json();
    let uri = json["buffers"][0]["uri"].as_str().unwrap().to_owned();
    json["buffers"][0]["uri"] = uri[..uri.len() / 2].into();
    refused("short", json.to_string().as_bytes(), "buffer 0");
}

#[test]
fn skins_and_morph_targets_are_named() {
    // BoxAnimated with a morph target on its inner box's primitive (its
    // own normals as the target's positions) and a skin of one joint on
    // the inner box's node: loaded, drawn without them, and notes say so.
    let mut json = box_json();
    json["meshes"][0]["primitives"][0]["targets"] = serde_json::json!([{ "POSITION": 1 }]);
    json["skins"] = serde_json::json!([{ "joints": [1] }]);
    json["nodes"][2]["skin"] = 0.into();
    let dir = scratch("morph");
    let file = dir.join("morph.gltf");
    std::fs::write(&file, json.to_string()).unwrap();
    let out = dir.join("out");
    let o = render(
        &file,
        &out,
        "--size 32x24 --frames 3 --sheet-rows 2 --no-gif",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("morph targets are not applied"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains("1 skin(s): meshes are drawn unskinned"),
        "{}",
        stderr(&o)
    );
}
