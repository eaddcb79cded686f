//! `--gltf`: a glTF file's animation, played through `rigtform::animation`'s
//! samplers ([`GltfScene`]) and drawn frame by frame from a camera that
//! keeps the whole motion in view.

use rigtform::Cvec3;

use crate::gltf_scene::GltfScene;
use crate::image::{Image, GLYPH_SIZE};
use crate::scene::{Camera, Draw, Scene, Settings};
use crate::vertex::Placement;

use super::{BAR, LABEL_BAR};

/// Frames over which the camera's view of the motion is measured.
const BOUND_SAMPLES: u32 = 64;

/// A loaded glTF animation with its camera and title.
#[derive(Clone, Debug)]
pub struct GltfDemo {
    scene: GltfScene,
    camera: Camera,
    title: String,
}

impl GltfDemo {
    /// The demo of `scene`, titled `title` (the file's name): the camera
    /// looks at the centre of the box around every drawn vertex over the
    /// animation, from above and in front, far enough to see all of it.
    #[must_use]
    pub fn new(scene: GltfScene, title: String) -> Self {
        let (start, end) = scene.span();
        let times: Vec<f32> = (0..=BOUND_SAMPLES)
            .map(|i| start + (end - start) * i as f32 / BOUND_SAMPLES as f32)
            .collect();
        let (lo, hi) = scene.bounds(&times);
        let centre = (lo + hi) * 0.5;
        let radius = ((hi - lo).norm() * 0.5).max(1e-3);
        let fovy = 0.8f32;
        let distance = radius / (0.5 * fovy).sin();
        let direction = Cvec3::new(0.55, 0.45, 1.0).normalize();
        let mut camera = Camera::looking_at(centre + direction * distance, centre, fovy);
        camera.near = (distance - 2.0 * radius).max(distance * 1e-3);
        camera.far = distance + 2.0 * radius;
        Self {
            scene,
            camera,
            title,
        }
    }

    /// The loaded scene.
    #[must_use]
    pub fn scene(&self) -> &GltfScene {
        &self.scene
    }

    /// The clock time of frame `i` of `n`: from the earliest key to the
    /// latest, both included.
    #[must_use]
    pub fn time(&self, i: u32, n: u32) -> f32 {
        let (start, end) = self.scene.span();
        start + (end - start) * super::Demo::alpha(i, n)
    }

    /// One frame at clock time `t`: the title and the time in a label bar
    /// over the scene.
    #[must_use]
    pub fn render_frame(&self, t: f32, settings: &Settings) -> Image {
        let pose = self.scene.pose(t);
        let draws = pose
            .iter()
            .filter_map(|&(m, world)| {
                Some(Draw {
                    mesh: self.scene.meshes.get(m)?,
                    placement: Placement::Matrix(world),
                    scale: Cvec3::new(1.0, 1.0, 1.0),
                    tint: [1.0; 3],
                })
            })
            .collect();
        let scene = Scene {
            camera: self.camera,
            lights: [
                self.camera.eye.transform_point(Cvec3::new(4.0, 6.0, 2.0)),
                self.camera.eye.transform_point(Cvec3::new(-6.0, -1.0, 0.0)),
            ],
            intensity: [0.75, 0.3],
            background: [0.42, 0.6, 0.85],
            draws,
        };
        let (w, h) = (settings.width, settings.height);
        let mut frame = Image::new(w, h + LABEL_BAR, BAR);
        frame.blit(&scene.render(settings), 0, i64::from(LABEL_BAR));
        frame.draw_text(4, 3, &self.title, 1, [240, 240, 240]);
        let (_, end) = self.scene.span();
        frame.draw_text(
            4,
            5 + i64::from(GLYPH_SIZE),
            &format!("t = {t:.3} s of {end:.3}"),
            1,
            [200, 200, 160],
        );
        frame
    }
}

/// The GIF's sequence for `frames` frames of an animation `seconds` long:
/// forward in real time (each frame shown for its share, at least 2
/// hundredths), resting 0.8 s on the last frame before it loops.
///
/// ```
/// use rigtform_render::demo::gltf::gif_sequence;
/// assert_eq!(gif_sequence(3, 1.0), [(0, 50), (1, 50), (2, 80)]);
/// ```
#[must_use]
pub fn gif_sequence(frames: u32, seconds: f32) -> Vec<(usize, u16)> {
    let step = if frames > 1 {
        seconds * 100.0 / (frames - 1) as f32
    } else {
        0.0
    };
    let delay = step.round().clamp(2.0, 1000.0) as u16;
    let last = frames.saturating_sub(1) as usize;
    (0..=last)
        .map(|i| (i, if i == last { 80 } else { delay }))
        .collect()
}
