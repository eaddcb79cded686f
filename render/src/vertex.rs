//! The vertex stage: the notes' drawing code. The model-view matrix is
//! `MVM = Matrix4::from(inv(eyeRbt) * objRbt)` with the object's scale
//! multiplied on the right, the normal matrix is `NMVM = normal_matrix(MVM)`,
//! and clip coordinates are `projection * MVM * p`.

use rigtform::{Cvec3, Cvec4, Matrix4, RigTForm};

use crate::mesh::Mesh;

/// How many floats a vertex hands on to the fragment stage: its eye-space
/// position (3), eye-space normal (3) and linear RGB colour (3).
pub const ATTRIBUTES: usize = 9;

/// A vertex after the vertex stage: clip-space position and the attributes
/// that are interpolated across the triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Homogeneous clip coordinates, `projection * MVM * p`.
    pub clip: Cvec4,
    /// Eye-space position, eye-space normal, colour (see [`ATTRIBUTES`]).
    pub attrs: [f32; ATTRIBUTES],
}

impl ClipVertex {
    /// The point `self + (other - self) * t` on the segment to `other`, in
    /// clip space, where attributes interpolate linearly (before the divide).
    #[must_use]
    pub fn lerp(self, other: Self, t: f32) -> Self {
        let mut attrs = self.attrs;
        for (a, b) in attrs.iter_mut().zip(other.attrs) {
            *a += (b - *a) * t;
        }
        Self {
            clip: self.clip.lerp(other.clip, t),
            attrs,
        }
    }
}

/// Where an object is placed in the world: by a rigid body transform (the
/// notes' way), or by a general 4x4 matrix (only for showing what lerping
/// matrices does).
///
/// ```
/// use rigtform::{Cvec3, Cvec4, Matrix4, RigTForm};
/// use rigtform_render::Placement;
/// let rigid = Placement::Rigid(RigTForm::from_translation(Cvec3::X));
/// let matrix = Placement::Matrix(Matrix4::from_translation(Cvec3::X));
/// let (Placement::Rigid(r), Placement::Matrix(m)) = (rigid, matrix) else { unreachable!() };
/// assert_eq!(r * Cvec4::from_point(Cvec3::ZERO), m * Cvec4::from_point(Cvec3::ZERO));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Placement {
    /// The object's `objRbt`: its object frame is `o = w objRbt`.
    Rigid(RigTForm),
    /// An object matrix that need not be rigid: `o = w M`.
    Matrix(Matrix4),
}

/// The three matrices the notes send to the shaders.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transforms {
    /// Model-view matrix: object coordinates to eye coordinates.
    pub mvm: Matrix4,
    /// Normal matrix: the inverse transpose of the MVM's 3x3 block.
    pub nmvm: Matrix4,
    /// `projection * mvm`: object coordinates to clip coordinates.
    pub mvp: Matrix4,
}

impl Transforms {
    /// The MVM, NMVM and MVP of an object at `placement` scaled by `scale`
    /// (applied first, on the right), seen from `eye`.
    ///
    /// `None` when the MVM is singular (a zero scale, or a lerped matrix that
    /// collapsed), since no normal matrix exists then.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4, Matrix4, RigTForm};
    /// use rigtform_render::{Placement, Transforms};
    /// let eye = RigTForm::from_translation(Cvec3::new(0.0, 0.0, 5.0));
    /// let obj = Placement::Rigid(RigTForm::from_translation(Cvec3::X));
    /// let proj = Matrix4::perspective(1.0, 1.0, 0.1, 100.0);
    /// let t = Transforms::new(eye, obj, Cvec3::new(2.0, 2.0, 2.0), proj).unwrap();
    /// let p = t.mvm * Cvec4::from_point(Cvec3::X);
    /// assert_eq!(p, Cvec4::new(3.0, 0.0, -5.0, 1.0));
    /// ```
    #[must_use]
    pub fn new(
        eye: RigTForm,
        placement: Placement,
        scale: Cvec3,
        projection: Matrix4,
    ) -> Option<Self> {
        let object_to_eye = match placement {
            Placement::Rigid(obj) => Matrix4::from(eye.inv() * obj),
            Placement::Matrix(m) => Matrix4::from(eye.inv()) * m,
        };
        let mvm = object_to_eye * Matrix4::from_scale(scale);
        let nmvm = mvm.normal_matrix()?;
        Some(Self {
            mvm,
            nmvm,
            mvp: projection * mvm,
        })
    }
}

/// Runs the vertex stage over every vertex of `mesh`, its colours multiplied
/// by `tint`.
///
/// ```
/// use rigtform::{Cvec3, Matrix4, RigTForm};
/// use rigtform_render::{transform_vertices, Mesh, Placement, Transforms};
/// let eye = RigTForm::from_translation(Cvec3::new(0.0, 0.0, 3.0));
/// let proj = Matrix4::perspective(1.0, 1.0, 0.1, 10.0);
/// let t = Transforms::new(eye, Placement::Rigid(RigTForm::IDENTITY), Cvec3::new(1.0, 1.0, 1.0), proj).unwrap();
/// let v = transform_vertices(&Mesh::cube(1.0, [1.0; 3]), &t, [1.0; 3]);
/// assert_eq!(v.len(), 24);
/// assert!(v.iter().all(|c| c.clip.w > 2.0)); // w is the distance in front of the eye
/// ```
#[must_use]
pub fn transform_vertices(mesh: &Mesh, t: &Transforms, tint: [f32; 3]) -> Vec<ClipVertex> {
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .zip(&mesh.colors)
        .map(|((&p, &n), c)| {
            let p4 = Cvec4::from_point(p);
            let eye = (t.mvm * p4).xyz();
            let normal: Cvec3 = (t.nmvm * Cvec4::from_vector(n)).xyz();
            ClipVertex {
                clip: t.mvp * p4,
                attrs: [
                    eye.x,
                    eye.y,
                    eye.z,
                    normal.x,
                    normal.y,
                    normal.z,
                    c[0] * tint[0],
                    c[1] * tint[1],
                    c[2] * tint[2],
                ],
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rigtform::Quat;

    #[test]
    fn normals_stay_perpendicular_under_non_uniform_scale() {
        let eye = RigTForm::IDENTITY;
        let obj = Placement::Rigid(RigTForm::from_rotation(Quat::from_rotation_z(0.7)));
        let scale = Cvec3::new(3.0, 0.5, 1.0);
        let proj = Matrix4::perspective(1.0, 1.0, 0.1, 10.0);
        let t = Transforms::new(eye, obj, scale, proj).unwrap();
        // The plane x + y = 1 in object space, with its normal (1, 1, 0).
        let mesh = Mesh {
            positions: vec![Cvec3::new(1.0, 0.0, 0.0), Cvec3::new(0.0, 1.0, 0.0)],
            normals: vec![Cvec3::new(1.0, 1.0, 0.0); 2],
            colors: vec![[1.0; 3]; 2],
            triangles: vec![],
        };
        let v = transform_vertices(&mesh, &t, [1.0; 3]);
        let along = Cvec3::new(
            v[1].attrs[0] - v[0].attrs[0],
            v[1].attrs[1] - v[0].attrs[1],
            0.0,
        );
        let normal = Cvec3::new(v[0].attrs[3], v[0].attrs[4], v[0].attrs[5]);
        assert!(along.dot(normal).abs() < 1e-5 * along.norm() * normal.norm());
    }

    #[test]
    fn collapsed_matrix_has_no_transforms() {
        let flat = Matrix4::from_scale(Cvec3::new(1.0, 0.0, 1.0));
        let proj = Matrix4::perspective(1.0, 1.0, 0.1, 10.0);
        assert!(Transforms::new(
            RigTForm::IDENTITY,
            Placement::Matrix(flat),
            Cvec3::new(1.0, 1.0, 1.0),
            proj
        )
        .is_none());
    }

    #[test]
    fn tint_multiplies_vertex_colours() {
        let mesh = Mesh::cube(1.0, [0.5, 1.0, 0.25]);
        let proj = Matrix4::perspective(1.0, 1.0, 0.1, 10.0);
        let t = Transforms::new(
            RigTForm::IDENTITY,
            Placement::Rigid(RigTForm::IDENTITY),
            Cvec3::new(1.0, 1.0, 1.0),
            proj,
        )
        .unwrap();
        let v = transform_vertices(&mesh, &t, [0.5, 0.5, 2.0]);
        assert_eq!(&v[0].attrs[6..], &[0.25, 0.5, 0.5]);
    }
}
