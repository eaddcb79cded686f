//! glTF 2.0 files as animated scenes: the node hierarchy, its meshes and
//! its animations, read with the `gltf` crate and played through
//! `rigtform::animation`'s samplers.
//!
//! [`GltfScene::load`] reads a `.gltf` (JSON, its buffers inline as data
//! URIs or in files beside it) or `.glb` file, checks every accessor it
//! will read and every animation channel (with
//! [`Sampler::new`](rigtform::animation::Sampler::new)), and keeps the data
//! in memory; nothing after it fails. [`GltfScene::pose`] gives every
//! node's world matrix at a time: every channel of every animation is
//! sampled at that one time (one clock, from the earliest key to the
//! latest; a channel outside its own keys holds its first or last value),
//! the channel's translation, rotation or scale replaces the node's own,
//! and the local `T R S` matrices compose down the hierarchy.
//!
//! What is not played: skins (joints) and morph targets. A file that has
//! them loads, is drawn without them, and [`GltfScene::unsupported`] says
//! so, for the binary to print.

use std::path::{Path, PathBuf};

use base64::Engine as _;
use gltf::animation::util::ReadOutputs;
use gltf::animation::Property;
use gltf::mesh::Mode;
use rigtform::animation::{Interpolation, Sampler};
use rigtform::{Cvec3, Cvec4, Matrix4, Quat};

use crate::mesh::Mesh;

/// Which of a node's properties a channel drives, with its key values.
#[derive(Clone, Debug, PartialEq)]
pub enum Values {
    /// Translations.
    Translation(Vec<Cvec3>),
    /// Rotations (read from glTF's x, y, z, w).
    Rotation(Vec<Quat>),
    /// Scales.
    Scale(Vec<Cvec3>),
}

/// One animation channel: a node, its key times and its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// Which animation of the file it belongs to.
    pub animation: usize,
    /// The node it drives.
    pub node: usize,
    /// glTF's interpolation.
    pub interpolation: Interpolation,
    /// Key times, seconds.
    pub times: Vec<f32>,
    /// Key values (three per key for CUBICSPLINE).
    pub values: Values,
}

impl Channel {
    /// What the channel drives: "translation", "rotation" or "scale".
    #[must_use]
    pub fn path(&self) -> &'static str {
        match self.values {
            Values::Translation(_) => "translation",
            Values::Rotation(_) => "rotation",
            Values::Scale(_) => "scale",
        }
    }
}

/// A node's own transform, as glTF's translation, rotation and scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trs {
    /// Translation.
    pub t: Cvec3,
    /// Rotation.
    pub r: Quat,
    /// Scale.
    pub s: Cvec3,
}

impl Trs {
    /// `T R S` as one matrix.
    #[must_use]
    pub fn matrix(&self) -> Matrix4 {
        Matrix4::from_translation(self.t) * Matrix4::from_quat(self.r) * Matrix4::from_scale(self.s)
    }
}

/// One node of the hierarchy.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Its name in the file, or `node N`.
    pub name: String,
    /// Its own transform when no channel drives it.
    pub rest: Trs,
    /// Its children's indices.
    pub children: Vec<usize>,
    /// Index into [`GltfScene::meshes`] of the mesh it draws.
    pub mesh: Option<usize>,
}

/// A glTF file loaded for playing: nodes, meshes, the scene's root nodes
/// and the animation channels.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfScene {
    /// Every node of the file.
    pub nodes: Vec<Node>,
    /// One mesh per glTF mesh (its triangle primitives together, coloured
    /// by their materials' base colour).
    pub meshes: Vec<Mesh>,
    /// The nodes of the scene shown (the file's default scene, or its first).
    pub roots: Vec<usize>,
    /// Every channel of every animation, checked.
    pub channels: Vec<Channel>,
    /// What the file has that is not played (skins, morph targets), one
    /// line each.
    pub unsupported: Vec<String>,
}

/// The buffer data of a file: GLB's binary chunk, data URIs, or files
/// beside the glTF file.
fn load_buffers(
    doc: &gltf::Document,
    blob: Option<Vec<u8>>,
    base: &Path,
) -> Result<Vec<Vec<u8>>, String> {
    let mut blob = blob;
    doc.buffers()
        .map(|buffer| {
            let data = match buffer.source() {
                gltf::buffer::Source::Bin => blob.take().ok_or_else(|| {
                    format!(
                        "buffer {} refers to a GLB binary chunk the file does not have",
                        buffer.index()
                    )
                })?,
                gltf::buffer::Source::Uri(uri) => {
                    if let Some(rest) = uri.strip_prefix("data:") {
                        let (_, encoded) = rest.split_once(";base64,").ok_or_else(|| {
                            format!(
                                "buffer {}: only base64 data URIs are supported",
                                buffer.index()
                            )
                        })?;
                        base64::engine::general_purpose::STANDARD
                            .decode(encoded)
                            .map_err(|e| {
                                format!(
                                    "buffer {}: its data URI is not valid base64: {e}",
                                    buffer.index()
                                )
                            })?
                    } else {
                        let path: PathBuf = base.join(uri);
                        std::fs::read(&path).map_err(|e| {
                            format!(
                                "buffer {}: cannot read {}: {e}",
                                buffer.index(),
                                path.display()
                            )
                        })?
                    }
                }
            };
            if data.len() < buffer.length() {
                return Err(format!(
                    "buffer {} holds {} bytes, but the file declares {}",
                    buffer.index(),
                    data.len(),
                    buffer.length()
                ));
            }
            Ok(data)
        })
        .collect()
}

/// Checks that an accessor's elements lie inside its buffer view and the
/// view inside its buffer, and that it is of the expected kind, before
/// the `gltf` crate's reader reads it.
fn check_accessor(
    accessor: &gltf::Accessor,
    buffers: &[Vec<u8>],
    what: &str,
    dimensions: &[gltf::accessor::Dimensions],
) -> Result<(), String> {
    let name = format!("accessor {} ({what})", accessor.index());
    if !dimensions.contains(&accessor.dimensions()) {
        return Err(format!(
            "{name} is {:?}, expected one of {dimensions:?}",
            accessor.dimensions()
        ));
    }
    if accessor.count() == 0 {
        return Err(format!("{name} has no elements"));
    }
    if accessor.sparse().is_some() {
        return Err(format!("{name} is sparse, which is not supported"));
    }
    let Some(view) = accessor.view() else {
        return Err(format!("{name} has no buffer view"));
    };
    let buffer_len = buffers.get(view.buffer().index()).map_or(0, Vec::len);
    let view_end = view.offset().checked_add(view.length());
    if view_end.is_none_or(|end| end > buffer_len) {
        return Err(format!(
            "{name}: buffer view {} (bytes {} to {:?}) runs past the end of buffer {} ({buffer_len} bytes)",
            view.index(),
            view.offset(),
            view_end,
            view.buffer().index()
        ));
    }
    let element = accessor.size();
    let stride = view.stride().unwrap_or(element);
    let end = (accessor.count() - 1)
        .checked_mul(stride)
        .and_then(|n| n.checked_add(accessor.offset()))
        .and_then(|n| n.checked_add(element));
    if end.is_none_or(|end| end > view.length()) {
        return Err(format!(
            "{name}: {} elements of {element} bytes from byte {} do not fit in buffer view {} ({} bytes)",
            accessor.count(),
            accessor.offset(),
            view.index(),
            view.length()
        ));
    }
    Ok(())
}

fn vec3(a: [f32; 3]) -> Cvec3 {
    Cvec3::new(a[0], a[1], a[2])
}

/// A rotation from glTF's x, y, z, w.
fn quat(a: [f32; 4]) -> Quat {
    Quat {
        x: a[0],
        y: a[1],
        z: a[2],
        w: a[3],
    }
}

fn read_mesh(
    mesh: &gltf::Mesh,
    buffers: &[Vec<u8>],
    unsupported: &mut Vec<String>,
) -> Result<Mesh, String> {
    use gltf::accessor::Dimensions::{Scalar, Vec3};
    let get = |b: gltf::Buffer| buffers.get(b.index()).map(Vec::as_slice);
    let mut out = Mesh::default();
    for primitive in mesh.primitives() {
        let what = format!("mesh {} primitive {}", mesh.index(), primitive.index());
        if primitive.mode() != Mode::Triangles {
            unsupported.push(format!(
                "{what}: {:?} primitives are not drawn (triangles only)",
                primitive.mode()
            ));
            continue;
        }
        if primitive.morph_targets().next().is_some() {
            unsupported.push(format!("{what}: morph targets are not applied"));
        }
        let Some(positions) = primitive.get(&gltf::Semantic::Positions) else {
            return Err(format!("{what} has no POSITION attribute"));
        };
        check_accessor(&positions, buffers, &format!("{what} POSITION"), &[Vec3])?;
        if let Some(normals) = primitive.get(&gltf::Semantic::Normals) {
            check_accessor(&normals, buffers, &format!("{what} NORMAL"), &[Vec3])?;
        }
        if let Some(indices) = primitive.indices() {
            check_accessor(&indices, buffers, &format!("{what} indices"), &[Scalar])?;
        }
        let reader = primitive.reader(get);
        let positions: Vec<Cvec3> = reader
            .read_positions()
            .ok_or_else(|| format!("{what}: cannot read POSITION"))?
            .map(vec3)
            .collect();
        let n = positions.len();
        let triangles: Vec<[u32; 3]> = match reader.read_indices() {
            Some(indices) => {
                let flat: Vec<u32> = indices.into_u32().collect();
                if let Some(bad) = flat.iter().find(|&&i| i as usize >= n) {
                    return Err(format!("{what}: index {bad} beyond its {n} vertices"));
                }
                flat.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect()
            }
            None => (0..n as u32 / 3)
                .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
                .collect(),
        };
        let color = {
            let c = primitive
                .material()
                .pbr_metallic_roughness()
                .base_color_factor();
            [c[0], c[1], c[2]]
        };
        let part = Mesh {
            normals: Vec::new(),
            colors: vec![color; n],
            triangles,
            positions,
        };
        let part = match reader.read_normals() {
            Some(normals) => Mesh {
                normals: normals.map(|v| vec3(v).normalize()).collect(),
                ..part
            },
            None => part.with_face_averaged_normals(),
        };
        if part.normals.len() != n {
            return Err(format!("{what}: NORMAL and POSITION have different counts"));
        }
        if !part
            .positions
            .iter()
            .chain(&part.normals)
            .all(|p| p.is_finite())
        {
            return Err(format!("{what}: a position or normal is not finite"));
        }
        out.append(&part);
    }
    Ok(out)
}

fn read_channels(
    doc: &gltf::Document,
    buffers: &[Vec<u8>],
    node_count: usize,
    unsupported: &mut Vec<String>,
) -> Result<Vec<Channel>, String> {
    use gltf::accessor::Dimensions::{Scalar, Vec3, Vec4};
    let get = |b: gltf::Buffer| buffers.get(b.index()).map(Vec::as_slice);
    let mut channels = Vec::new();
    for animation in doc.animations() {
        for channel in animation.channels() {
            let node = channel.target().node().index();
            let what = format!(
                "animation {} channel {} (node {node})",
                animation.index(),
                channel.index()
            );
            let sampler = channel.sampler();
            let interpolation = match sampler.interpolation() {
                gltf::animation::Interpolation::Step => Interpolation::Step,
                gltf::animation::Interpolation::Linear => Interpolation::Linear,
                gltf::animation::Interpolation::CubicSpline => Interpolation::CubicSpline,
            };
            let dims: &[gltf::accessor::Dimensions] = match channel.target().property() {
                Property::MorphTargetWeights => {
                    unsupported.push(format!("{what}: morph target weights are not animated"));
                    continue;
                }
                Property::Rotation => &[Vec4],
                Property::Translation | Property::Scale => &[Vec3],
            };
            check_accessor(
                &sampler.input(),
                buffers,
                &format!("{what} key times"),
                &[Scalar],
            )?;
            check_accessor(
                &sampler.output(),
                buffers,
                &format!("{what} key values"),
                dims,
            )?;
            if node >= node_count {
                return Err(format!("{what}: no node {node}"));
            }
            let reader = channel.reader(get);
            let times: Vec<f32> = reader
                .read_inputs()
                .ok_or_else(|| format!("{what}: cannot read its key times"))?
                .collect();
            let values = match reader
                .read_outputs()
                .ok_or_else(|| format!("{what}: cannot read its key values"))?
            {
                ReadOutputs::Translations(v) => Values::Translation(v.map(vec3).collect()),
                ReadOutputs::Rotations(v) => Values::Rotation(v.into_f32().map(quat).collect()),
                ReadOutputs::Scales(v) => Values::Scale(v.map(vec3).collect()),
                ReadOutputs::MorphTargetWeights(_) => continue,
            };
            let checked = match &values {
                Values::Translation(v) | Values::Scale(v) => {
                    Sampler::new(interpolation, &times, v).map(|_| ())
                }
                Values::Rotation(v) => Sampler::new(interpolation, &times, v).map(|_| ()),
            };
            checked.map_err(|e| format!("{what}: {e}"))?;
            channels.push(Channel {
                animation: animation.index(),
                node,
                interpolation,
                times,
                values,
            });
        }
    }
    Ok(channels)
}

impl GltfScene {
    /// Loads and checks a `.gltf` or `.glb` file.
    ///
    /// # Errors
    ///
    /// A message naming the file and what is wrong: it cannot be read, is
    /// not glTF (the `gltf` crate's parse and validation), has a buffer
    /// that cannot be loaded, an accessor outside its buffer or of the
    /// wrong kind, no animation, or a channel [`Sampler::new`] rejects.
    pub fn load(path: &Path) -> Result<Self, String> {
        let bytes =
            std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let in_file = |e: String| format!("{}: {e}", path.display());
        let gltf = gltf::Gltf::from_slice(&bytes)
            .map_err(|e| in_file(format!("not a valid glTF file: {e}")))?;
        let base = path.parent().unwrap_or(Path::new("."));
        let doc = gltf.document;
        let buffers = load_buffers(&doc, gltf.blob, base).map_err(in_file)?;
        let mut unsupported = Vec::new();
        let skins = doc.skins().count();
        if skins > 0 {
            unsupported.push(format!(
                "{skins} skin(s): meshes are drawn unskinned, in their bind pose"
            ));
        }
        let meshes = doc
            .meshes()
            .map(|m| read_mesh(&m, &buffers, &mut unsupported))
            .collect::<Result<Vec<_>, _>>()
            .map_err(in_file)?;
        let nodes: Vec<Node> = doc
            .nodes()
            .map(|n| {
                let (t, r, s) = n.transform().decomposed();
                Node {
                    name: n
                        .name()
                        .map_or_else(|| format!("node {}", n.index()), str::to_owned),
                    rest: Trs {
                        t: vec3(t),
                        r: quat(r),
                        s: vec3(s),
                    },
                    children: n.children().map(|c| c.index()).collect(),
                    mesh: n.mesh().map(|m| m.index()),
                }
            })
            .collect();
        if doc.animations().count() == 0 {
            return Err(in_file("the file has no animation to play".into()));
        }
        let channels =
            read_channels(&doc, &buffers, nodes.len(), &mut unsupported).map_err(in_file)?;
        if channels.is_empty() {
            return Err(in_file(
                "the file's animations have no channel this renderer plays (translation, rotation, scale)".into(),
            ));
        }
        let scene = doc.default_scene().or_else(|| doc.scenes().next());
        let roots = match scene {
            Some(s) => s.nodes().map(|n| n.index()).collect(),
            // No scene: every node that is nobody's child.
            None => (0..nodes.len())
                .filter(|&i| !nodes.iter().any(|n| n.children.contains(&i)))
                .collect(),
        };
        Ok(Self {
            nodes,
            meshes,
            roots,
            channels,
            unsupported,
        })
    }

    /// The clock's span: the earliest and the latest key time of all
    /// channels.
    #[must_use]
    pub fn span(&self) -> (f32, f32) {
        let firsts = self.channels.iter().filter_map(|c| c.times.first());
        let lasts = self.channels.iter().filter_map(|c| c.times.last());
        let start = firsts.fold(f32::INFINITY, |a, &b| a.min(b));
        let end = lasts.fold(f32::NEG_INFINITY, |a, &b| a.max(b));
        if start <= end {
            (start, end)
        } else {
            (0.0, 0.0)
        }
    }

    /// Every node's own transform at time `t`: its rest transform with the
    /// channels' samples in place of the properties they drive.
    #[must_use]
    pub fn local_transforms(&self, t: f32) -> Vec<Trs> {
        let mut local: Vec<Trs> = self.nodes.iter().map(|n| n.rest).collect();
        for c in &self.channels {
            let Some(trs) = local.get_mut(c.node) else {
                continue;
            };
            // The channels were checked when loaded; a sampler that were
            // rejected now would leave the property at rest.
            match &c.values {
                Values::Translation(v) => {
                    if let Ok(s) = Sampler::new(c.interpolation, &c.times, v) {
                        trs.t = s.sample(t);
                    }
                }
                Values::Rotation(v) => {
                    if let Ok(s) = Sampler::new(c.interpolation, &c.times, v) {
                        trs.r = s.sample(t);
                    }
                }
                Values::Scale(v) => {
                    if let Ok(s) = Sampler::new(c.interpolation, &c.times, v) {
                        trs.s = s.sample(t);
                    }
                }
            }
        }
        local
    }

    /// The world matrix of every node of the shown scene at time `t`, with
    /// the mesh it draws: `(mesh index, world matrix)`.
    #[must_use]
    pub fn pose(&self, t: f32) -> Vec<(usize, Matrix4)> {
        let local = self.local_transforms(t);
        let mut out = Vec::new();
        // Depth first; a node reached twice (a malformed file's cycle) is
        // not walked again.
        let mut seen = vec![false; self.nodes.len()];
        let mut stack: Vec<(usize, Matrix4)> = self
            .roots
            .iter()
            .rev()
            .map(|&r| (r, Matrix4::IDENTITY))
            .collect();
        while let Some((i, parent)) = stack.pop() {
            let (Some(node), Some(trs)) = (self.nodes.get(i), local.get(i)) else {
                continue;
            };
            if std::mem::replace(&mut seen[i], true) {
                continue;
            }
            let world = parent * trs.matrix();
            if let Some(m) = node.mesh {
                out.push((m, world));
            }
            stack.extend(node.children.iter().rev().map(|&c| (c, world)));
        }
        out
    }

    /// The corners of the box around every drawn vertex at the times `ts`.
    #[must_use]
    pub fn bounds(&self, ts: &[f32]) -> (Cvec3, Cvec3) {
        let mut lo = Cvec3::new(f32::INFINITY, f32::INFINITY, f32::INFINITY);
        let mut hi = Cvec3::new(f32::NEG_INFINITY, f32::NEG_INFINITY, f32::NEG_INFINITY);
        for &t in ts {
            for (m, world) in self.pose(t) {
                let Some(mesh) = self.meshes.get(m) else {
                    continue;
                };
                for p in &mesh.positions {
                    let q = (world * Cvec4::from_point(*p)).xyz();
                    lo = Cvec3::new(lo.x.min(q.x), lo.y.min(q.y), lo.z.min(q.z));
                    hi = Cvec3::new(hi.x.max(q.x), hi.y.max(q.y), hi.z.max(q.z));
                }
            }
        }
        if lo.x <= hi.x {
            (lo, hi)
        } else {
            (Cvec3::ZERO, Cvec3::ZERO)
        }
    }
}
