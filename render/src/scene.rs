//! A scene and its rendering: every draw through the vertex stage, clipping,
//! the viewport and triangle setup, then the bands of the framebuffer
//! filled in parallel with `rayon` (rasterization and the fragment stage),
//! and the resolve.
//!
//! The output does not depend on the number of threads: the triangles are
//! set up in submission order, each band is filled by one thread drawing
//! its triangles in that order, and every step is a pure function of its
//! inputs.

use rayon::prelude::*;
use rigtform::{Cvec3, Matrix4, RigTForm};

use crate::clip::clip_triangle;
use crate::fragment::fill_triangle;
use crate::framebuffer::Framebuffer;
use crate::image::Image;
use crate::mesh::Mesh;
use crate::raster::{Cull, Triangle};
use crate::samples::Msaa;
use crate::shade::Lighting;
use crate::vertex::{transform_vertices, Placement, Transforms};
use crate::viewport::to_screen;

/// Rows per band, the unit of parallel work.
pub const BAND_ROWS: u32 = 8;

/// How the camera maps the view to the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lens {
    /// Perspective (`Matrix4::perspective`): things shrink with distance.
    Perspective {
        /// Vertical field of view in radians.
        fovy: f32,
    },
    /// Orthographic (`Matrix4::orthographic`): parallel lines stay
    /// parallel and sizes do not change with distance.
    Orthographic {
        /// Height of the view in world units (its width follows the
        /// aspect ratio), centred on the line of sight.
        height: f32,
    },
}

/// The camera: the eye frame (looking down its -z axis, y up) and the lens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye frame, `e = w eyeRbt`.
    pub eye: RigTForm,
    /// Perspective or orthographic.
    pub lens: Lens,
    /// Distance to the near clipping plane (positive).
    pub near: f32,
    /// Distance to the far clipping plane (positive, beyond `near`).
    pub far: f32,
}

impl Camera {
    /// A perspective camera at `position` looking at `target` with a
    /// vertical field of view of `fovy` radians, its x axis kept horizontal
    /// (y is up): the eye frame of `RigTForm::look_at`.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// use rigtform_render::Camera;
    /// let cam = Camera::looking_at(Cvec3::new(0.0, 3.0, 4.0), Cvec3::ZERO, 0.8);
    /// // The target lies straight ahead, on the eye's -z axis, 5 away.
    /// let seen = cam.eye.inv().transform_point(Cvec3::ZERO);
    /// assert!((seen - Cvec3::new(0.0, 0.0, -5.0)).norm() < 1e-5);
    /// ```
    #[must_use]
    pub fn looking_at(position: Cvec3, target: Cvec3, fovy: f32) -> Self {
        Self {
            eye: RigTForm::look_at(position, target, Cvec3::Y),
            lens: Lens::Perspective { fovy },
            near: 0.1,
            far: 100.0,
        }
    }

    /// The same camera with an orthographic lens showing `height` world
    /// units from bottom to top.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// use rigtform_render::{Camera, Lens};
    /// let cam = Camera::looking_at(Cvec3::new(0.0, 0.0, 5.0), Cvec3::ZERO, 1.0).orthographic(4.0);
    /// assert_eq!(cam.lens, Lens::Orthographic { height: 4.0 });
    /// // The top of the view, 2 above the line of sight, at any distance.
    /// let top = cam.projection(1.0) * Cvec4::new(0.0, 2.0, -30.0, 1.0);
    /// assert!((top.y / top.w - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn orthographic(self, height: f32) -> Self {
        Self {
            lens: Lens::Orthographic { height },
            ..self
        }
    }

    /// The projection matrix for a viewport of the given aspect ratio.
    ///
    /// ```
    /// use rigtform::{Cvec3, Cvec4};
    /// use rigtform_render::Camera;
    /// let cam = Camera::looking_at(Cvec3::new(0.0, 0.0, 5.0), Cvec3::ZERO, 1.0);
    /// let p = cam.projection(1.5) * Cvec4::new(0.0, 0.0, -cam.near, 1.0);
    /// assert!((p.z / p.w + 1.0).abs() < 1e-5); // the near plane maps to NDC -1
    /// ```
    #[must_use]
    pub fn projection(&self, aspect: f32) -> Matrix4 {
        match self.lens {
            Lens::Perspective { fovy } => Matrix4::perspective(fovy, aspect, self.near, self.far),
            Lens::Orthographic { height } => {
                let (h, w) = (0.5 * height, 0.5 * height * aspect);
                Matrix4::orthographic(-w, w, -h, h, self.near, self.far)
            }
        }
    }
}

/// One mesh drawn at one place.
#[derive(Clone, Copy, Debug)]
pub struct Draw<'a> {
    /// The mesh, in object coordinates.
    pub mesh: &'a Mesh,
    /// Where the mesh is placed in the world.
    pub placement: Placement,
    /// Scale applied in object coordinates, before the placement.
    pub scale: Cvec3,
    /// Multiplies the mesh's vertex colours.
    pub tint: [f32; 3],
}

/// Everything in a picture.
#[derive(Clone, Debug)]
pub struct Scene<'a> {
    /// The camera.
    pub camera: Camera,
    /// World positions of the two lights.
    pub lights: [Cvec3; 2],
    /// Diffuse intensity of each light.
    pub intensity: [f32; 2],
    /// Linear RGB colour where nothing is drawn.
    pub background: [f32; 3],
    /// What to draw, in order.
    pub draws: Vec<Draw<'a>>,
}

/// How to render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The sample pattern.
    pub msaa: Msaa,
    /// Back-face culling.
    pub cull: Cull,
}

/// What a render did, for benchmarks and reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Triangles submitted (all draws' meshes).
    pub submitted: usize,
    /// Triangles set up for rasterization (after clipping and culling).
    pub rasterized: usize,
}

impl Scene<'_> {
    /// The triangles of every draw, set up for rasterization, in
    /// submission order.
    fn setup(&self, settings: &Settings) -> Vec<Triangle> {
        let aspect = settings.width as f32 / settings.height as f32;
        let projection = self.camera.projection(aspect);
        self.draws
            .par_iter()
            .map(|draw| {
                let Some(t) =
                    Transforms::new(self.camera.eye, draw.placement, draw.scale, projection)
                else {
                    return Vec::new();
                };
                let vertices = transform_vertices(draw.mesh, &t, draw.tint);
                let mut clipped = Vec::new();
                let mut out = Vec::with_capacity(draw.mesh.triangles.len());
                for tri in &draw.mesh.triangles {
                    let Some(tri) = tri
                        .iter()
                        .map(|&i| vertices.get(i as usize).copied())
                        .collect::<Option<Vec<_>>>()
                    else {
                        continue;
                    };
                    clipped.clear();
                    clip_triangle([tri[0], tri[1], tri[2]], &mut clipped);
                    for piece in &clipped {
                        let screen = piece.map(|v| to_screen(v, settings.width, settings.height));
                        if let Some(t) =
                            Triangle::setup(screen, settings.cull, settings.width, settings.height)
                        {
                            out.push(t);
                        }
                    }
                }
                out
            })
            .collect::<Vec<_>>()
            .concat()
    }

    /// Draws every band, in parallel on the current `rayon` thread pool,
    /// and resolves each into its rows of `image` when one is given.
    fn draw(&self, settings: &Settings, image: Option<&mut Image>) -> (Framebuffer, Stats) {
        assert!(settings.width > 0 && settings.height > 0, "empty viewport");
        let triangles = self.setup(settings);
        let lighting = Lighting::new(self.camera.eye, self.lights, self.intensity);
        let mut fb = Framebuffer::new(
            settings.width,
            settings.height,
            settings.msaa,
            self.background,
        );
        let mut bands = fb.bands_mut(BAND_ROWS);
        // Bin the triangles by band, keeping submission order in each bin.
        let mut bins: Vec<Vec<&Triangle>> = vec![Vec::new(); bands.len()];
        for t in &triangles {
            let (y0, y1) = t.rows();
            for bin in &mut bins[(y0 / BAND_ROWS) as usize..=(y1 / BAND_ROWS) as usize] {
                bin.push(t);
            }
        }
        let image_rows: Vec<Option<&mut [[u8; 3]]>> = match image {
            Some(image) => image
                .pixels_mut()
                .chunks_mut(BAND_ROWS as usize * settings.width as usize)
                .map(Some)
                .collect(),
            None => bands.iter().map(|_| None).collect(),
        };
        let shade = |a: &[f32; crate::vertex::ATTRIBUTES]| lighting.shade(a);
        bands
            .par_iter_mut()
            .zip(bins.par_iter())
            .zip(image_rows)
            .for_each(|((band, bin), rows)| {
                for t in bin {
                    fill_triangle(t, band, settings.msaa, &shade);
                }
                if let Some(rows) = rows {
                    band.resolve_into(rows);
                }
            });
        drop(bands);
        let stats = Stats {
            submitted: self.draws.iter().map(|d| d.mesh.triangles.len()).sum(),
            rasterized: triangles.len(),
        };
        (fb, stats)
    }

    /// Renders the scene into a framebuffer (unresolved), on the current
    /// `rayon` thread pool.
    ///
    /// # Panics
    ///
    /// If the size is zero.
    #[must_use]
    pub fn render_samples(&self, settings: &Settings) -> (Framebuffer, Stats) {
        self.draw(settings, None)
    }

    /// Renders the scene to an image, on the current `rayon` thread pool;
    /// each band is resolved by the thread that drew it.
    ///
    /// # Panics
    ///
    /// If the size is zero.
    #[must_use]
    pub fn render(&self, settings: &Settings) -> Image {
        let mut image = Image::new(settings.width, settings.height, [0; 3]);
        let _ = self.draw(settings, Some(&mut image));
        image
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rigtform::{Cvec4, Quat};

    fn settings(width: u32, height: u32) -> Settings {
        Settings {
            width,
            height,
            msaa: Msaa::Off,
            cull: Cull::Back,
        }
    }

    /// The pixels of a 101 x 101 picture that a tiny cube at `at` covers:
    /// 0.1 wide, half a pixel where 20 units span the picture, so it covers
    /// only the centre of the pixel its point falls in.
    fn pixels_of_a_marker(camera: Camera, at: Cvec3) -> Vec<(u32, u32)> {
        let marker = Mesh::cube(0.1, [1.0; 3]);
        let scene = Scene {
            camera,
            lights: [Cvec3::new(0.0, 0.0, 20.0); 2],
            intensity: [0.5, 0.5],
            background: [0.0; 3],
            draws: vec![Draw {
                mesh: &marker,
                placement: Placement::Rigid(RigTForm::from_translation(at)),
                scale: Cvec3::new(1.0, 1.0, 1.0),
                tint: [1.0; 3],
            }],
        };
        let (fb, _) = scene.render_samples(&settings(101, 101));
        (0..101)
            .flat_map(|y| (0..101).map(move |x| (x, y)))
            .filter(|&(x, y)| fb.depth(x, y, 0) < 1.0)
            .collect()
    }

    #[test]
    fn point_projects_onto_the_pixel_computed_by_hand() {
        // Eye at (0, 0, 10) looking down -z, 90 degree field of view, square
        // viewport of 101 pixels: the point (2, 1, 0) is 10 in front of the
        // eye, so at NDC (0.2, 0.1), i.e. pixel x = (0.2 + 1) / 2 * 101 =
        // 60.6, y = (1 - 0.1) / 2 * 101 = 45.45: pixel (60, 45).
        let camera = Camera {
            eye: RigTForm::from_translation(Cvec3::new(0.0, 0.0, 10.0)),
            lens: Lens::Perspective {
                fovy: core::f32::consts::FRAC_PI_2,
            },
            near: 0.5,
            far: 50.0,
        };
        assert_eq!(
            pixels_of_a_marker(camera, Cvec3::new(2.0, 1.0, 0.0)),
            [(60, 45)]
        );
        // The same by the matrices themselves.
        let p = camera.projection(1.0)
            * Matrix4::from(camera.eye.inv())
            * Cvec4::from_point(Cvec3::new(2.0, 1.0, 0.0));
        assert!((p.x / p.w - 0.2).abs() < 1e-6 && (p.y / p.w - 0.1).abs() < 1e-6);
    }

    #[test]
    fn orthographic_camera_puts_a_point_on_the_same_pixel_at_any_depth() {
        // 20 units high on 101 pixels, as the perspective test above sees
        // its point at distance 10: (2, 1) lands on pixel (60, 45) whether
        // it is 5 or 40 in front of the eye.
        let camera = Camera {
            eye: RigTForm::from_translation(Cvec3::new(0.0, 0.0, 10.0)),
            lens: Lens::Perspective { fovy: 1.0 },
            near: 0.5,
            far: 50.0,
        }
        .orthographic(20.0);
        for z in [5.0, -30.0] {
            let drawn = pixels_of_a_marker(camera, Cvec3::new(2.0, 1.0, z));
            assert_eq!(drawn, [(60, 45)], "z = {z}");
        }
    }

    #[test]
    fn triangle_through_the_near_plane_is_drawn_in_front_of_it() {
        // A ground plane under the camera reaches behind it; the part in
        // front must still be drawn, and fill the lower half of the view.
        let ground = Mesh::ground([-50.0, 50.0], [-50.0, 50.0], 1, [[1.0; 3]; 2]);
        let scene = Scene {
            camera: Camera::looking_at(Cvec3::new(0.0, 1.0, 0.0), Cvec3::new(0.0, 1.0, -1.0), 1.0),
            lights: [Cvec3::new(0.0, 10.0, 0.0); 2],
            intensity: [0.5, 0.5],
            background: [0.0; 3],
            draws: vec![Draw {
                mesh: &ground,
                placement: Placement::Rigid(RigTForm::IDENTITY),
                scale: Cvec3::new(1.0, 1.0, 1.0),
                tint: [1.0; 3],
            }],
        };
        let (fb, stats) = scene.render_samples(&settings(40, 40));
        assert_eq!(stats.submitted, 2);
        assert!(stats.rasterized > 2, "the crossing triangles were cut");
        for x in 0..40 {
            assert!(fb.depth(x, 39, 0) < 1.0, "bottom row drawn");
            assert!(fb.depth(x, 0, 0) == 1.0, "sky above the horizon");
        }
    }

    #[test]
    fn output_is_identical_whatever_the_thread_count() {
        let body = Mesh::axes(1.0);
        let sphere = Mesh::sphere(0.7, 24, 12, [0.9, 0.6, 0.2]);
        let draws = (0..6)
            .map(|i| Draw {
                mesh: if i % 2 == 0 { &body } else { &sphere },
                placement: Placement::Rigid(RigTForm::new(
                    Cvec3::new(i as f32 * 0.4 - 1.0, 0.0, -(i as f32) * 0.3),
                    Quat::from_axis_angle(Cvec3::new(1.0, 2.0, 0.5), i as f32),
                )),
                scale: Cvec3::new(1.0, 1.0, 1.0),
                tint: [1.0; 3],
            })
            .collect();
        let scene = Scene {
            camera: Camera::looking_at(Cvec3::new(0.5, 2.0, 5.0), Cvec3::ZERO, 0.9),
            lights: [Cvec3::new(4.0, 6.0, 5.0), Cvec3::new(-5.0, 3.0, 2.0)],
            intensity: [0.6, 0.3],
            background: [0.1, 0.2, 0.4],
            draws,
        };
        let s = Settings {
            width: 97,
            height: 61,
            msaa: Msaa::X4,
            cull: Cull::Back,
        };
        let render_with = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| scene.render(&s))
        };
        let one = render_with(1);
        assert_eq!(one, render_with(4));
        assert_eq!(one, render_with(3));
        // Resolving band by band gives what resolving the whole buffer gives.
        assert_eq!(one, scene.render_samples(&s).0.resolve());
        assert!(
            one.pixels().iter().any(|p| p[0] > 150),
            "something was drawn"
        );
    }
}
