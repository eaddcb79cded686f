//! `rigtform-gltf-samples`: the Rust side of `cargo xtask gltf-check`.
//!
//! Usage: `rigtform-gltf-samples ASSET RANDOM_GLTF SAMPLES_JSON`.
//!
//! Writes `RANDOM_GLTF`, a glTF file of random animation channels of all
//! three interpolations for translations, rotations and scales (seeded, so
//! the same every run); then loads it and `ASSET` with the renderer's
//! reader ([`GltfScene::load`]), samples every channel with
//! `rigtform::animation::Sampler` at its key times, between them and
//! beyond both ends, and writes the channels and the samples to
//! `SAMPLES_JSON` for `tools/gltf-check/check.mjs`, which loads the same
//! files with three.js's `GLTFLoader` and compares.

use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;

use base64::Engine as _;
use rigtform::animation::{Interpolation, Sampler};
use rigtform::{Cvec3, Quat};
use rigtform_render::gltf_scene::{Channel, GltfScene, Values};
use rigtform_render::output::write_atomically;

/// xorshift64*: a small seeded generator, so the random channels are the
/// same on every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// Uniform in [lo, hi).
    fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * unit
    }

    fn unit_quat(&mut self) -> Quat {
        loop {
            let q = Quat {
                x: self.uniform(-1.0, 1.0),
                y: self.uniform(-1.0, 1.0),
                z: self.uniform(-1.0, 1.0),
                w: self.uniform(-1.0, 1.0),
            };
            let n = q.norm();
            if (0.1..=1.0).contains(&n) {
                return q.normalize();
            }
        }
    }

    fn vec3(&mut self, r: f32) -> Cvec3 {
        Cvec3::new(
            self.uniform(-r, r),
            self.uniform(-r, r),
            self.uniform(-r, r),
        )
    }
}

/// The components of a channel's values, flat, in glTF's order.
fn flat(values: &Values) -> Vec<f32> {
    match values {
        Values::Translation(v) | Values::Scale(v) => {
            v.iter().flat_map(|c| [c.x, c.y, c.z]).collect()
        }
        Values::Rotation(v) => v.iter().flat_map(|q| [q.x, q.y, q.z, q.w]).collect(),
    }
}

fn interpolation_name(i: Interpolation) -> &'static str {
    match i {
        Interpolation::Step => "STEP",
        Interpolation::Linear => "LINEAR",
        Interpolation::CubicSpline => "CUBICSPLINE",
    }
}

/// Random channels: for each property and interpolation, `PER_KIND`
/// channels of 2 to 7 keys, intervals of 0.05 to 1 s. STEP and LINEAR
/// rotations are uniform over the rotations (so neighbours are often
/// stored more than a half turn apart); CUBICSPLINE rotations walk by up
/// to 1 rad a key, stored on the same side as their neighbour, with
/// tangents near the finite difference of the neighbours (as exporters
/// write them), so that no Hermite sum nearly cancels. Translations and
/// scales, and their tangents, have components in [-1, 1].
fn random_channels(rng: &mut Rng) -> Vec<(Interpolation, Vec<f32>, Values)> {
    const PER_KIND: usize = 4;
    let kinds = [
        Interpolation::Step,
        Interpolation::Linear,
        Interpolation::CubicSpline,
    ];
    let mut out = Vec::new();
    for property in 0..3 {
        for kind in kinds {
            for _ in 0..PER_KIND {
                let n = 2 + (rng.next() % 6) as usize;
                let mut t = rng.uniform(0.0, 1.0);
                let times: Vec<f32> = (0..n)
                    .map(|_| {
                        let now = t;
                        t += rng.uniform(0.05, 1.0);
                        now
                    })
                    .collect();
                let values = if property == 1 {
                    let keys: Vec<Quat> = if kind == Interpolation::CubicSpline {
                        let mut q = rng.unit_quat();
                        (0..n)
                            .map(|_| {
                                let key = q;
                                let turn = Quat::from_axis_angle(
                                    rng.vec3(1.0).normalize(),
                                    rng.uniform(0.0, 1.0),
                                );
                                q = (turn * q).normalize();
                                if q.dot(key) < 0.0 {
                                    q = -q;
                                }
                                key
                            })
                            .collect()
                    } else {
                        (0..n).map(|_| rng.unit_quat()).collect()
                    };
                    if kind == Interpolation::CubicSpline {
                        let mut v = Vec::new();
                        for k in 0..n {
                            let (a, b) = (k.saturating_sub(1), (k + 1).min(n - 1));
                            let (qa, qb) = (keys[a], keys[b]);
                            let d = Quat {
                                x: qb.x - qa.x,
                                y: qb.y - qa.y,
                                z: qb.z - qa.z,
                                w: qb.w - qa.w,
                            };
                            let slope = 1.0 / (times[b] - times[a]);
                            let mut tangent = || Quat {
                                x: d.x * slope + rng.uniform(-0.2, 0.2),
                                y: d.y * slope + rng.uniform(-0.2, 0.2),
                                z: d.z * slope + rng.uniform(-0.2, 0.2),
                                w: d.w * slope + rng.uniform(-0.2, 0.2),
                            };
                            let (inward, outward) = (tangent(), tangent());
                            v.extend([inward, keys[k], outward]);
                        }
                        Values::Rotation(v)
                    } else {
                        Values::Rotation(keys)
                    }
                } else {
                    let count = n * kind.values_per_key();
                    let v: Vec<Cvec3> = (0..count).map(|_| rng.vec3(1.0)).collect();
                    if property == 0 {
                        Values::Translation(v)
                    } else {
                        Values::Scale(v)
                    }
                };
                out.push((kind, times, values));
            }
        }
    }
    out
}

/// A glTF file animating one node per channel, its buffer a data URI.
fn random_gltf(channels: &[(Interpolation, Vec<f32>, Values)]) -> String {
    let mut buffer: Vec<u8> = Vec::new();
    let (mut views, mut accessors, mut samplers, mut targets, mut nodes) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (i, (kind, times, values)) in channels.iter().enumerate() {
        let (path, kind_name) = match values {
            Values::Translation(_) => ("translation", "VEC3"),
            Values::Rotation(_) => ("rotation", "VEC4"),
            Values::Scale(_) => ("scale", "VEC3"),
        };
        let comps = if kind_name == "VEC4" { 4 } else { 3 };
        let data = flat(values);
        for (floats, ty) in [(times.as_slice(), "SCALAR"), (data.as_slice(), kind_name)] {
            let offset = buffer.len();
            buffer.extend(floats.iter().flat_map(|f| f.to_le_bytes()));
            views.push(format!(
                r#"{{"buffer":0,"byteOffset":{offset},"byteLength":{}}}"#,
                4 * floats.len()
            ));
            let count = if ty == "SCALAR" {
                floats.len()
            } else {
                floats.len() / comps
            };
            let bounds = if ty == "SCALAR" {
                let (lo, hi) = (times[0], times[times.len() - 1]);
                format!(r#","min":[{lo:?}],"max":[{hi:?}]"#)
            } else {
                String::new()
            };
            accessors.push(format!(
                r#"{{"bufferView":{},"componentType":5126,"count":{count},"type":"{ty}"{bounds}}}"#,
                views.len() - 1
            ));
        }
        samplers.push(format!(
            r#"{{"input":{},"output":{},"interpolation":"{}"}}"#,
            accessors.len() - 2,
            accessors.len() - 1,
            interpolation_name(*kind)
        ));
        targets.push(format!(
            r#"{{"sampler":{i},"target":{{"node":{i},"path":"{path}"}}}}"#
        ));
        nodes.push(format!(r#"{{"name":"track{i}"}}"#));
    }
    let uri = base64::engine::general_purpose::STANDARD.encode(&buffer);
    format!(
        r#"{{"asset":{{"version":"2.0","generator":"rigtform-gltf-samples"}},"scene":0,"scenes":[{{"nodes":[{}]}}],"nodes":[{}],"animations":[{{"channels":[{}],"samplers":[{}]}}],"accessors":[{}],"bufferViews":[{}],"buffers":[{{"byteLength":{},"uri":"data:application/octet-stream;base64,{uri}"}}]}}
"#,
        (0..nodes.len())
            .map(|i| i.to_string())
            .collect::<Vec<_>>()
            .join(","),
        nodes.join(","),
        targets.join(","),
        samplers.join(","),
        accessors.join(","),
        views.join(","),
        buffer.len()
    )
}

/// Where a channel is sampled: each key time, the quarter points of every
/// interval, 0.25 and 1 s beyond both ends, and 16 random times from 0.5 s
/// before the first key to 0.5 s after the last.
fn sample_times(times: &[f32], rng: &mut Rng) -> Vec<f32> {
    let (first, last) = (times[0], times[times.len() - 1]);
    let mut ts = vec![first - 1.0, first - 0.25, last + 0.25, last + 1.0];
    for (k, &t) in times.iter().enumerate() {
        ts.push(t);
        if let Some(&next) = times.get(k + 1) {
            ts.extend([0.25, 0.5, 0.75].map(|f| t + f * (next - t)));
        }
    }
    ts.extend((0..16).map(|_| rng.uniform(first - 0.5, last + 0.5)));
    ts
}

fn samples(c: &Channel, ts: &[f32]) -> Result<Vec<f32>, String> {
    let error = |e| format!("channel of node {}: {e}", c.node);
    Ok(match &c.values {
        Values::Translation(v) | Values::Scale(v) => {
            let s = Sampler::new(c.interpolation, &c.times, v).map_err(error)?;
            ts.iter().flat_map(|&t| s.sample(t).to_array()).collect()
        }
        Values::Rotation(v) => {
            let s = Sampler::new(c.interpolation, &c.times, v).map_err(error)?;
            ts.iter()
                .flat_map(|&t| {
                    let q = s.sample(t);
                    [q.x, q.y, q.z, q.w]
                })
                .collect()
        }
    })
}

fn numbers(out: &mut String, values: &[f32]) {
    out.push('[');
    for (i, v) in values.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        // The shortest decimal that reads back as this f32.
        let _ = write!(out, "{v:?}");
    }
    out.push(']');
}

fn run(asset: &Path, random: &Path, json: &Path) -> Result<String, String> {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let channels = random_channels(&mut rng);
    let text = random_gltf(&channels);
    write_atomically(random, |out| {
        std::io::Write::write_all(out, text.as_bytes())
    })
    .map_err(|e| e.to_string())?;
    let mut out = String::from("{\"files\":[");
    let mut total = (0, 0);
    for (f, path) in [asset, random].into_iter().enumerate() {
        let scene = GltfScene::load(path)?;
        if f > 0 {
            out.push(',');
        }
        let _ = write!(
            out,
            "{{\"path\":{:?},\"channels\":[",
            path.display().to_string()
        );
        // Channel index within its animation, as three.js's clips order
        // their tracks.
        let mut within = std::collections::HashMap::new();
        for (i, c) in scene.channels.iter().enumerate() {
            let index: &mut usize = within.entry(c.animation).or_default();
            let ts = sample_times(&c.times, &mut rng);
            let v = samples(c, &ts)?;
            if i > 0 {
                out.push(',');
            }
            let _ = write!(
                out,
                "{{\"animation\":{},\"track\":{},\"node\":{},\"path\":\"{}\",\"interpolation\":\"{}\",\"times\":",
                c.animation,
                *index,
                c.node,
                c.path(),
                interpolation_name(c.interpolation)
            );
            *index += 1;
            numbers(&mut out, &c.times);
            out.push_str(",\"values\":");
            numbers(&mut out, &flat(&c.values));
            out.push_str(",\"t\":");
            numbers(&mut out, &ts);
            out.push_str(",\"samples\":");
            numbers(&mut out, &v);
            out.push('}');
            total = (total.0 + ts.len(), total.1 + 1);
        }
        out.push_str("]}");
    }
    out.push_str("]}\n");
    write_atomically(json, |w| std::io::Write::write_all(w, out.as_bytes()))
        .map_err(|e| e.to_string())?;
    Ok(format!(
        "rigtform: {} samples of {} channels written to {}",
        total.0,
        total.1,
        json.display()
    ))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [asset, random, json] = args.as_slice() else {
        eprintln!("usage: rigtform-gltf-samples ASSET RANDOM_GLTF SAMPLES_JSON");
        return ExitCode::from(2);
    };
    match run(Path::new(asset), Path::new(random), Path::new(json)) {
        Ok(summary) => {
            println!("{summary}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
