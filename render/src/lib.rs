//! A host-side software rasterizer for `rigtform`, and the demo it renders:
//! keyframe animation of [`RigTForm`](rigtform::RigTForm)s, slerp against
//! the lecture notes' "bad ideas" (lerping matrices, lerping Euler angles).
//!
//! One file per pipeline stage, in the order a triangle meets them:
//!
//! 1. [`mesh`]: built-in meshes (cube, sphere, ground, axes body) and OBJ
//!    files (with `tobj`).
//! 2. [`vertex`]: `MVM = Matrix4::from(inv(eyeRbt) * objRbt) * scale`,
//!    `NMVM = normal_matrix(MVM)`, clip = `projection * MVM * p`.
//! 3. [`clip`]: the near plane (and a guard band), in clip space.
//! 4. [`viewport`]: perspective divide and viewport.
//! 5. [`raster`]: triangle setup, back-face culling, exact fixed-point edge
//!    functions with a top-left fill rule, 4x MSAA coverage, depth and
//!    perspective-correct attributes across the triangle.
//! 6. [`fragment`]: each covered pixel: the depth test per sample, one
//!    shading, the colour stored in the samples that passed.
//! 7. [`shade`]: the shading the fragment stage calls, per-pixel diffuse
//!    and specular lighting (the CS175 model).
//! 8. [`framebuffer`]: colour and depth samples, bands for threads, resolve.
//! 9. [`image`] and [`output`]: images, labels, PNG and GIF files written
//!    atomically.
//!
//! The sample layout of a pixel ([`samples`]: how many, where) is a module
//! of its own, which the rasterizer, the fragment stage and the framebuffer
//! use alike.
//!
//! [`scene`] runs the stages, in parallel with `rayon` and with the same
//! bytes out whatever the number of threads. [`demo`] builds the demo's
//! animation and pictures on top of it: the staging every panel shares,
//! the comparison of [`demo::bad_ideas`] and its
//! [`interpolation`](demo::interpolation) methods. [`gltf_scene`] reads
//! glTF files (with the `gltf` crate) and plays their animations through
//! `rigtform::animation`'s samplers, for [`demo::gltf`].
//!
//! A *frame* is one picture of the animation (`frames/frame_000.png`).
//! Where an object is in the world is its [`Placement`]; coordinate frames
//! keep the notes' names: the world frame `w`, the eye frame
//! `e = w eyeRbt`, an object frame `o = w objRbt`.
//!
//! ```
//! use rigtform::{Cvec3, Quat, RigTForm};
//! use rigtform_render::{Camera, Cull, Draw, Mesh, Msaa, Placement, Scene, Settings};
//!
//! let cube = Mesh::cube(1.0, [0.8, 0.3, 0.1]);
//! let scene = Scene {
//!     camera: Camera::looking_at(Cvec3::new(2.0, 2.0, 4.0), Cvec3::ZERO, 0.8),
//!     lights: [Cvec3::new(3.0, 5.0, 4.0), Cvec3::new(-4.0, 2.0, 1.0)],
//!     intensity: [0.7, 0.3],
//!     background: [0.5, 0.7, 0.9],
//!     draws: vec![Draw {
//!         mesh: &cube,
//!         placement: Placement::Rigid(RigTForm::from_rotation(Quat::from_rotation_y(0.5))),
//!         scale: Cvec3::new(1.0, 1.0, 1.0),
//!         tint: [1.0; 3],
//!     }],
//! };
//! let image = scene.render(&Settings { width: 64, height: 48, msaa: Msaa::X4, cull: Cull::Back });
//! assert_ne!(image.pixel(32, 24), image.pixel(0, 0)); // the cube is in the middle
//! ```

pub mod clip;
pub mod demo;
pub mod fragment;
pub mod framebuffer;
pub mod gltf_scene;
pub mod image;
pub mod mesh;
pub mod output;
pub mod raster;
pub mod samples;
pub mod scene;
pub mod shade;
pub mod vertex;
pub mod viewport;

pub use clip::clip_triangle;
pub use fragment::fill_triangle;
pub use framebuffer::{linear_to_srgb8, Band, Framebuffer};
pub use image::Image;
pub use mesh::Mesh;
pub use raster::{Cull, DepthPlane, Triangle, MAX_COORDINATE};
pub use samples::Msaa;
pub use scene::{Camera, Draw, Lens, Scene, Settings, Stats};
pub use shade::Lighting;
pub use vertex::{transform_vertices, ClipVertex, Placement, Transforms, ATTRIBUTES};
pub use viewport::{to_screen, ScreenVertex};
