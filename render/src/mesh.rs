//! Triangle meshes: the built-in cube, sphere, ground plane and axes body,
//! generated in code, and OBJ files loaded with `tobj`.

use std::fs::File;
use std::io::Read;
use std::ops::Range;
use std::path::Path;

use rigtform::Cvec3;

/// An indexed triangle mesh in object coordinates.
///
/// Every vertex carries a position, a unit normal and a linear RGB colour;
/// `triangles` index them three at a time, counter-clockwise seen from the
/// outside (OpenGL's front faces).
///
/// ```
/// use rigtform_render::Mesh;
/// let cube = Mesh::cube(1.0, [0.8, 0.8, 0.8]);
/// assert_eq!(cube.triangles.len(), 12);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<Cvec3>,
    /// Unit vertex normals, one per position.
    pub normals: Vec<Cvec3>,
    /// Linear RGB vertex colours in [0, 1], one per position.
    pub colors: Vec<[f32; 3]>,
    /// Counter-clockwise triangles, as indices into the vertex arrays.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Appends a vertex and returns its index.
    fn push_vertex(&mut self, p: Cvec3, n: Cvec3, color: [f32; 3]) -> u32 {
        let index = self.positions.len() as u32;
        self.positions.push(p);
        self.normals.push(n);
        self.colors.push(color);
        index
    }

    /// Appends the quad `a, b, c, d` (counter-clockwise) as two triangles with
    /// the flat normal `n`.
    fn push_quad(&mut self, [a, b, c, d]: [Cvec3; 4], n: Cvec3, color: [f32; 3]) {
        let i = [a, b, c, d].map(|p| self.push_vertex(p, n, color));
        self.triangles.push([i[0], i[1], i[2]]);
        self.triangles.push([i[0], i[2], i[3]]);
    }

    /// An axis-aligned box centred on the origin with the given half extents,
    /// flat shaded (24 vertices, 12 triangles).
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// use rigtform_render::Mesh;
    /// let b = Mesh::cuboid(Cvec3::new(1.0, 0.5, 0.25), [1.0, 0.0, 0.0]);
    /// assert!(b.positions.iter().all(|p| p.x.abs() == 1.0 && p.y.abs() == 0.5));
    /// ```
    #[must_use]
    pub fn cuboid(half: Cvec3, color: [f32; 3]) -> Self {
        let mut mesh = Self::default();
        // For each face: its outward normal and two in-face axes u, v with
        // u x v = normal, so that the corners below run counter-clockwise.
        let faces = [
            (Cvec3::X, Cvec3::Y, Cvec3::Z),
            (-Cvec3::X, Cvec3::Z, Cvec3::Y),
            (Cvec3::Y, Cvec3::Z, Cvec3::X),
            (-Cvec3::Y, Cvec3::X, Cvec3::Z),
            (Cvec3::Z, Cvec3::X, Cvec3::Y),
            (-Cvec3::Z, Cvec3::Y, Cvec3::X),
        ];
        let scale = |v: Cvec3| Cvec3::new(v.x * half.x, v.y * half.y, v.z * half.z);
        for (n, u, v) in faces {
            let corners = [n - u - v, n + u - v, n + u + v, n - u + v].map(scale);
            mesh.push_quad(corners, n, color);
        }
        mesh
    }

    /// A cube of edge length `size` centred on the origin.
    #[must_use]
    pub fn cube(size: f32, color: [f32; 3]) -> Self {
        let h = size * 0.5;
        Self::cuboid(Cvec3::new(h, h, h), color)
    }

    /// A UV sphere of the given radius centred on the origin, smooth shaded,
    /// with `slices` segments around the y axis and `stacks` from pole to pole.
    ///
    /// # Preconditions
    ///
    /// `slices >= 3` and `stacks >= 2`; smaller counts are raised to these.
    ///
    /// ```
    /// use rigtform_render::Mesh;
    /// let s = Mesh::sphere(2.0, 16, 8, [1.0; 3]);
    /// assert!(s.positions.iter().all(|p| (p.norm() - 2.0).abs() < 1e-5));
    /// ```
    #[must_use]
    pub fn sphere(radius: f32, slices: u32, stacks: u32, color: [f32; 3]) -> Self {
        let (slices, stacks) = (slices.max(3), stacks.max(2));
        let mut mesh = Self::default();
        for i in 0..=stacks {
            let theta = core::f32::consts::PI * i as f32 / stacks as f32;
            for j in 0..=slices {
                let phi = core::f32::consts::TAU * j as f32 / slices as f32;
                let n = Cvec3::new(
                    theta.sin() * phi.sin(),
                    theta.cos(),
                    theta.sin() * phi.cos(),
                );
                mesh.push_vertex(n * radius, n, color);
            }
        }
        let row = slices + 1;
        for i in 0..stacks {
            for j in 0..slices {
                let (a, b) = (i * row + j, (i + 1) * row + j);
                // Skip the triangles that collapse to a point at the poles.
                if i != 0 {
                    mesh.triangles.push([a, b, a + 1]);
                }
                if i + 1 != stacks {
                    mesh.triangles.push([a + 1, b, b + 1]);
                }
            }
        }
        mesh
    }

    /// A checkerboard ground plane at `y = 0` over `[x0, x1] x [z0, z1]`,
    /// facing up, with `cells` squares along x (square cells, as many along z
    /// as fit) alternating between the two colours.
    ///
    /// ```
    /// use rigtform_render::Mesh;
    /// let g = Mesh::ground([-2.0, 2.0], [-1.0, 1.0], 4, [[0.2; 3], [0.8; 3]]);
    /// assert_eq!(g.triangles.len(), 4 * 2 * 2);
    /// assert!(g.normals.iter().all(|n| n.y == 1.0));
    /// ```
    #[must_use]
    pub fn ground(x: [f32; 2], z: [f32; 2], cells: u32, colors: [[f32; 3]; 2]) -> Self {
        let mut mesh = Self::default();
        let cells_x = cells.max(1);
        let cell = (x[1] - x[0]) / cells_x as f32;
        let cells_z = (((z[1] - z[0]) / cell).round() as u32).max(1);
        let cell_z = (z[1] - z[0]) / cells_z as f32;
        for i in 0..cells_x {
            for k in 0..cells_z {
                let (xa, xb) = (x[0] + cell * i as f32, x[0] + cell * (i + 1) as f32);
                let (za, zb) = (z[0] + cell_z * k as f32, z[0] + cell_z * (k + 1) as f32);
                let corners = [
                    Cvec3::new(xa, 0.0, zb),
                    Cvec3::new(xb, 0.0, zb),
                    Cvec3::new(xb, 0.0, za),
                    Cvec3::new(xa, 0.0, za),
                ];
                mesh.push_quad(corners, Cvec3::Y, colors[((i + k) % 2) as usize]);
            }
        }
        mesh
    }

    /// The body that shows its own axes: a grey cube at the origin and three arms
    /// along its +x (red), +y (green) and +z (blue) axes, `length` long.
    ///
    /// ```
    /// use rigtform_render::Mesh;
    /// let body = Mesh::axes(1.5);
    /// let reach = body.positions.iter().map(|p| p.x).fold(f32::MIN, f32::max);
    /// assert!((reach - 1.5).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn axes(length: f32) -> Self {
        let thick = 0.09 * length;
        let mut body = Self::cube(4.0 * thick, [0.75, 0.75, 0.72]);
        let half = (length - thick) * 0.5;
        let arms = [
            (Cvec3::X, Cvec3::new(half, thick, thick), [0.85, 0.08, 0.06]),
            (Cvec3::Y, Cvec3::new(thick, half, thick), [0.1, 0.7, 0.1]),
            (Cvec3::Z, Cvec3::new(thick, thick, half), [0.08, 0.2, 0.9]),
        ];
        for (axis, extent, color) in arms {
            body.append(&Self::cuboid(extent, color).translated(axis * (half + thick)));
        }
        body
    }

    /// The same mesh moved by `offset`.
    #[must_use]
    pub fn translated(mut self, offset: Cvec3) -> Self {
        for p in &mut self.positions {
            *p += offset;
        }
        self
    }

    /// Appends the vertices and triangles of `other`.
    ///
    /// ```
    /// use rigtform::Cvec3;
    /// use rigtform_render::Mesh;
    /// let mut two = Mesh::cube(1.0, [1.0; 3]);
    /// two.append(&Mesh::cube(1.0, [1.0; 3]).translated(Cvec3::X * 3.0));
    /// assert_eq!(two.triangles.len(), 24);
    /// assert_eq!(two.bounds().1.x, 3.5);
    /// ```
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        self.normals.extend_from_slice(&other.normals);
        self.colors.extend_from_slice(&other.colors);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }

    /// Loads every model of an OBJ file (with `tobj`, triangulated), coloured
    /// `color`, centred on its bounding box and scaled so that its largest
    /// extent is `size`. Vertices without normals get the area-weighted
    /// average of their faces' normals (any unit normal where the faces
    /// have no area). Material libraries are not read. At most
    /// [`MAX_OBJ_BYTES`](Self::MAX_OBJ_BYTES) are read from the file, so
    /// a device or pipe without end (`/dev/zero`) is an error, not an
    /// endless read.
    ///
    /// # Errors
    ///
    /// A message naming the file when it cannot be read or parsed, is
    /// longer than [`MAX_OBJ_BYTES`](Self::MAX_OBJ_BYTES), holds no
    /// triangle, or has a coordinate that is not finite or that centring
    /// and scaling would take out of the finite floats (its extent
    /// overflows, about 1.7e38 and more, or is so small that `size`
    /// divided by it does).
    ///
    /// ```
    /// use rigtform_render::Mesh;
    /// let dir = std::env::temp_dir().join(format!("rigtform-doc-obj-{}", std::process::id()));
    /// std::fs::create_dir_all(&dir).unwrap();
    /// let path = dir.join("tri.obj");
    /// std::fs::write(&path, "v 0 0 0\nv 4 0 0\nv 0 2 0\nf 1 2 3\n").unwrap();
    /// let mesh = Mesh::load_obj(&path, 1.0, [1.0; 3]).unwrap();
    /// assert_eq!(mesh.bounds().1.x, 0.5); // centred, the longest side now 1
    /// std::fs::remove_dir_all(&dir).unwrap();
    /// ```
    pub fn load_obj(path: &Path, size: f32, color: [f32; 3]) -> Result<Self, String> {
        let named = |e: String| format!("OBJ file {}: {e}", path.display());
        let file = File::open(path)
            .map_err(|e| format!("cannot load OBJ file {}: {e}", path.display()))?;
        let mut text = Vec::new();
        file.take(Self::MAX_OBJ_BYTES + 1)
            .read_to_end(&mut text)
            .map_err(|e| format!("cannot load OBJ file {}: {e}", path.display()))?;
        if text.len() as u64 > Self::MAX_OBJ_BYTES {
            return Err(named(format!(
                "longer than {} MiB, the most this reads",
                Self::MAX_OBJ_BYTES >> 20
            )));
        }
        Self::parse_obj(&text, size, color).map_err(named)
    }

    /// The most [`load_obj`](Self::load_obj) reads of a file: 64 MiB, some
    /// two million vertices.
    pub const MAX_OBJ_BYTES: u64 = 64 << 20;

    /// [`load_obj`](Self::load_obj) of OBJ text held in memory.
    ///
    /// # Errors
    ///
    /// As [`load_obj`](Self::load_obj), without the file's name.
    ///
    /// ```
    /// use rigtform_render::Mesh;
    /// let mesh = Mesh::parse_obj(b"v 0 0 0\nv 4 0 0\nv 0 2 0\nf 1 2 3\n", 1.0, [1.0; 3]).unwrap();
    /// assert_eq!(mesh.bounds().0.x, -0.5);
    /// // An extent of 4e38 overflows f32:
    /// assert!(Mesh::parse_obj(b"v -2e38 0 0\nv 2e38 0 0\nv 0 1 0\nf 1 2 3\n", 1.0, [1.0; 3]).is_err());
    /// ```
    pub fn parse_obj(text: &[u8], size: f32, color: [f32; 3]) -> Result<Self, String> {
        let text = std::str::from_utf8(text).map_err(|e| format!("not UTF-8 text: {e}"))?;
        check_face_indices(text)?;
        let (models, _materials) =
            tobj::load_obj_buf(&mut text.as_bytes(), &tobj::GPU_LOAD_OPTIONS, |_| {
                Err(tobj::LoadError::OpenFileFailed)
            })
            .map_err(|e| format!("cannot parse: {e}"))?;
        let mut mesh = Self::default();
        // The parts whose normals are computed, once the mesh is scaled:
        // their vertices and triangles.
        let mut computed = Vec::new();
        for model in &models {
            let m = &model.mesh;
            let positions: Vec<Cvec3> = m
                .positions
                .chunks_exact(3)
                .map(|p| Cvec3::new(p[0], p[1], p[2]))
                .collect();
            let count = positions.len();
            let triangles: Vec<[u32; 3]> = m
                .indices
                .chunks_exact(3)
                .map(|t| [t[0], t[1], t[2]])
                .collect();
            if triangles.iter().flatten().any(|&i| i as usize >= count) {
                return Err("a face refers to a vertex that is not there".to_string());
            }
            let has_normals = m.normals.len() == m.positions.len();
            let normals = if has_normals {
                m.normals
                    .chunks_exact(3)
                    .map(|n| unit_or_up(Cvec3::new(n[0], n[1], n[2])))
                    .collect()
            } else {
                vec![Cvec3::ZERO; count]
            };
            let (v0, t0) = (mesh.positions.len(), mesh.triangles.len());
            mesh.append(&Self {
                normals,
                colors: vec![color; count],
                triangles,
                positions,
            });
            if !has_normals {
                computed.push((v0..mesh.positions.len(), t0..mesh.triangles.len()));
            }
        }
        if mesh.triangles.is_empty() {
            return Err("holds no triangle".to_string());
        }
        if !mesh.positions.iter().all(|p| p.is_finite()) {
            return Err("has a non-finite coordinate".to_string());
        }
        let (lo, hi) = mesh.bounds();
        let extent = (hi - lo).to_array().into_iter().fold(0.0f32, f32::max);
        let scale = if extent > 0.0 { size / extent } else { 1.0 };
        // Halves first: lo + hi may overflow where their mean does not.
        let centre = lo * 0.5 + hi * 0.5;
        for p in &mut mesh.positions {
            *p = (*p - centre) * scale;
        }
        if !extent.is_finite() || !mesh.positions.iter().all(|p| p.is_finite()) {
            return Err(format!(
                "its extent {extent:e} cannot be centred and scaled to {size} in f32 \
                 (coordinates too far apart, or too close together)"
            ));
        }
        for (vertices, triangles) in computed {
            mesh.face_averaged_normals(vertices, triangles);
        }
        Ok(mesh)
    }

    /// Area-weighted vertex normals of the triangles `triangles` (the cross
    /// product of two edges is twice the area times the unit normal), for
    /// the `vertices` they use.
    /// A triangle that names a vertex outside `vertices` adds nothing.
    fn face_averaged_normals(&mut self, vertices: Range<usize>, triangles: Range<usize>) {
        let first = vertices.start;
        let mut sums = vec![Cvec3::ZERO; vertices.len()];
        for t in self.triangles.get(triangles).unwrap_or_default() {
            let corners = t.map(|i| self.positions.get(i as usize).copied());
            let slots = t.map(|i| (i as usize).checked_sub(first).filter(|&k| k < sums.len()));
            if let ([Some(a), Some(b), Some(c)], [Some(i), Some(j), Some(k)]) = (corners, slots) {
                let n = (b - a).cross(c - a);
                for s in [i, j, k] {
                    sums[s] += n;
                }
            }
        }
        for (normal, sum) in self.normals[vertices].iter_mut().zip(sums) {
            *normal = unit_or_up(sum);
        }
    }

    /// Area-weighted normals of every vertex, for a mesh read without them
    /// (a glTF primitive with no NORMAL attribute).
    pub(crate) fn with_face_averaged_normals(mut self) -> Self {
        self.normals = vec![Cvec3::Y; self.positions.len()];
        self.face_averaged_normals(0..self.positions.len(), 0..self.triangles.len());
        self
    }

    /// The corners of the axis-aligned bounding box (zero for no vertex).
    #[must_use]
    pub fn bounds(&self) -> (Cvec3, Cvec3) {
        let Some(&first) = self.positions.first() else {
            return (Cvec3::ZERO, Cvec3::ZERO);
        };
        self.positions.iter().fold((first, first), |(lo, hi), p| {
            (
                Cvec3::new(lo.x.min(p.x), lo.y.min(p.y), lo.z.min(p.z)),
                Cvec3::new(hi.x.max(p.x), hi.y.max(p.y), hi.z.max(p.z)),
            )
        })
    }
}

/// Refuses the face (`f`) and line (`l`) indices that `tobj` would turn
/// into an arithmetic overflow (a panic in builds with overflow checks, a
/// wrapped index without): a relative (negative) index reaching before the
/// first position, texture coordinate or normal, and an index larger than
/// the text is long (no file has that many elements). Lines are counted as
/// `tobj` counts them.
fn check_face_indices(text: &str) -> Result<(), String> {
    let mut counts = [0usize; 3];
    for (number, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f" | "l") => {
                for word in words {
                    for (kind, part) in word.split('/').enumerate().take(3) {
                        let Ok(index) = part.parse::<isize>() else {
                            continue;
                        };
                        let reach = index.unsigned_abs();
                        let fits = if index < 0 {
                            reach <= counts[kind]
                        } else {
                            reach <= text.len()
                        };
                        if !fits {
                            return Err(format!(
                                "line {}: index {index} refers to no {}",
                                number + 1,
                                ["position", "texture coordinate", "normal"][kind]
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// `v` normalized, or +y where it has no direction (a face without area).
fn unit_or_up(v: Cvec3) -> Cvec3 {
    v.try_normalize().unwrap_or(Cvec3::Y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed volume enclosed, from the divergence theorem: only a
    /// closed, consistently outward-wound mesh gives the solid's volume.
    fn enclosed_volume(mesh: &Mesh) -> f32 {
        mesh.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn cube_is_closed_and_wound_outward() {
        let v = enclosed_volume(&Mesh::cube(2.0, [1.0; 3]));
        assert!((v - 8.0).abs() < 1e-5, "volume {v}");
    }

    #[test]
    fn cube_face_normals_agree_with_winding() {
        let cube = Mesh::cube(1.0, [1.0; 3]);
        for t in &cube.triangles {
            let [a, b, c] = t.map(|i| cube.positions[i as usize]);
            let n = (b - a).cross(c - a).normalize();
            assert!((n - cube.normals[t[0] as usize]).norm() < 1e-6);
        }
    }

    #[test]
    fn sphere_is_closed_and_wound_outward() {
        let v = enclosed_volume(&Mesh::sphere(1.0, 64, 32, [1.0; 3]));
        let exact = 4.0 / 3.0 * core::f32::consts::PI;
        assert!(v > 0.98 * exact && v < exact, "volume {v}");
    }

    #[test]
    fn sphere_has_no_degenerate_triangles_at_the_poles() {
        let (slices, stacks) = (12, 7);
        let s = Mesh::sphere(1.0, slices, stacks, [1.0; 3]);
        assert_eq!(s.triangles.len() as u32, slices * (2 * stacks - 2));
        for t in &s.triangles {
            let [a, b, c] = t.map(|i| s.positions[i as usize]);
            assert!((b - a).cross(c - a).norm() > 1e-4, "{t:?}");
        }
    }

    #[test]
    fn ground_faces_up() {
        let g = Mesh::ground([-1.0, 1.0], [-1.0, 1.0], 2, [[0.0; 3], [1.0; 3]]);
        for t in &g.triangles {
            let [a, b, c] = t.map(|i| g.positions[i as usize]);
            assert!((b - a).cross(c - a).y > 0.0);
        }
    }

    #[test]
    fn axes_body_is_closed_and_reaches_its_length() {
        let body = Mesh::axes(2.0);
        assert!(enclosed_volume(&body) > 0.0);
        let (lo, hi) = body.bounds();
        assert!((hi - Cvec3::new(2.0, 2.0, 2.0)).norm() < 1e-6);
        assert!(lo.x < 0.0 && lo.x > -0.5);
    }

    /// Loads OBJ text through a temporary file.
    fn load_obj_text(name: &str, text: &str, size: f32) -> Result<Mesh, String> {
        let dir = std::env::temp_dir().join(format!("rigtform-obj-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!("{name}.obj"));
        std::fs::write(&path, text).unwrap();
        let mesh = Mesh::load_obj(&path, size, [1.0; 3]);
        std::fs::remove_dir_all(&dir).unwrap();
        mesh
    }

    #[test]
    fn obj_loads_centred_and_scaled_with_computed_normals() {
        // A tetrahedron spanning x in [10, 14], y in [-3, 1], z in [2, 6].
        let text =
            "v 10 -3 2\nv 14 -3 2\nv 10 1 2\nv 10 -3 6\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        let mesh = load_obj_text("tetra", text, 2.0).unwrap();
        let (lo, hi) = mesh.bounds();
        assert_eq!(
            (lo, hi),
            (Cvec3::new(-1.0, -1.0, -1.0), Cvec3::new(1.0, 1.0, 1.0))
        );
        assert!(enclosed_volume(&mesh) > 0.0);
        assert!(mesh.normals.iter().all(|n| (n.norm() - 1.0).abs() < 1e-5));
        // The corner's normal averages its three faces' outward normals.
        let corner = mesh.normals[0];
        assert!(
            (corner - Cvec3::new(-1.0, -1.0, -1.0).normalize()).norm() < 1e-5,
            "{corner:?}"
        );
    }

    #[test]
    fn obj_normals_from_the_file_are_kept() {
        // Not the face's own normal (+z), so that computing it would show.
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 2 0\nf 1//1 2//1 3//1\n";
        let mesh = load_obj_text("normals", text, 1.0).unwrap();
        assert_eq!(mesh.normals, vec![Cvec3::Y; 3]);
    }

    #[test]
    fn obj_collapsed_to_a_point_stays_finite() {
        let mesh = load_obj_text("point", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n", 1.0).unwrap();
        assert_eq!(mesh.positions, vec![Cvec3::ZERO; 3]);
        assert!(mesh.normals.iter().all(|n| n.norm() == 1.0), "{mesh:?}");
    }

    /// Every position and normal finite, every normal of unit length.
    fn assert_finite(mesh: &Mesh) {
        assert!(mesh.positions.iter().all(|p| p.is_finite()), "{mesh:?}");
        assert!(
            mesh.normals.iter().all(|n| (n.norm() - 1.0).abs() < 1e-5),
            "{mesh:?}"
        );
    }

    #[test]
    fn obj_whose_centring_or_scaling_overflows_is_refused() {
        // Finite coordinates whose extent (4e38) or size / extent overflows.
        for (name, text) in [
            ("far", "v -2e38 0 0\nv 2e38 0 0\nv 0 1 0\nf 1 2 3\n"),
            (
                "max",
                "v -3.4e38 -3.4e38 0\nv 3.4e38 0 0\nv 0 3.4e38 0\nf 1 2 3\n",
            ),
            ("tiny", "v 0 0 0\nv 1e-45 0 0\nv 0 1e-45 0\nf 1 2 3\n"),
        ] {
            let err = load_obj_text(name, text, 2.0).unwrap_err();
            assert!(err.contains("centred and scaled"), "{name}: {err}");
            assert!(err.contains(&format!("{name}.obj")), "{err}");
        }
    }

    #[test]
    fn obj_with_large_coordinates_gets_finite_normals() {
        // 1e20 centres and scales, but the raw edges' cross product (1e40)
        // would overflow: the normals come from the scaled mesh.
        let text = "v 1e20 0 0\nv 3e20 0 0\nv 1e20 2e20 0\nf 1 2 3\n";
        let mesh = load_obj_text("large", text, 2.0).unwrap();
        assert_finite(&mesh);
        assert_eq!(mesh.normals[0], Cvec3::Z);
        // Two models, the first with normals from the file, the second
        // computed: each keeps its own.
        let text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\n\
                    o b\nv 0 0 1\nv 0 1 1\nv 1 0 1\nf 4 5 6\n";
        let mesh = load_obj_text("two", text, 2.0).unwrap();
        assert_finite(&mesh);
        assert_eq!(mesh.normals[..3], [Cvec3::X; 3]);
        assert_eq!(mesh.normals[3..], [-Cvec3::Z; 3]);
    }

    #[test]
    fn obj_read_is_bounded() {
        let err = Mesh::load_obj(Path::new("/dev/zero"), 1.0, [1.0; 3]).unwrap_err();
        assert!(err.contains("/dev/zero") && err.contains("64 MiB"), "{err}");
    }

    #[test]
    fn obj_indices_that_would_overflow_are_refused() {
        // A normal index far beyond the file, and a relative texture
        // coordinate index before the first: tobj's index arithmetic
        // overflowed on both (a panic with overflow checks).
        for (name, text) in [
            (
                "normal",
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7000000000000000000\n",
            ),
            (
                "texture",
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-2 2/1 3/1\n",
            ),
        ] {
            let err = load_obj_text(name, text, 1.0).unwrap_err();
            assert!(err.contains("line 5: index"), "{name}: {err}");
        }
        // Relative indices within the file are fine.
        let mesh =
            load_obj_text("relative", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", 1.0).unwrap();
        assert_eq!(mesh.triangles.len(), 1);
    }

    #[test]
    fn obj_face_without_its_vertex_is_refused() {
        let err = load_obj_text("faces", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", 1.0).unwrap_err();
        assert!(err.contains("faces.obj"), "{err}");
    }

    #[test]
    fn obj_errors_name_the_file() {
        let missing = Path::new("/nonexistent/model.obj");
        let err = Mesh::load_obj(missing, 1.0, [1.0; 3]).unwrap_err();
        assert!(err.contains("/nonexistent/model.obj"), "{err}");
    }
}
