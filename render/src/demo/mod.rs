//! The demo the binary renders: a comparison of ways to interpolate
//! keyframes, panel by panel, and the animation made of its frames.
//!
//! This file holds what every panel shares: the stage (the same sky camera
//! over a checkered ground, two lights), the body at the place the panel
//! gives it, the paths of its origin and axis tips marked, an animation
//! frame (the panels side by side under label bars), the contact sheet,
//! the GIF's sequence, and loading an OBJ file as the body. Of a panel it
//! uses the title, [`Panel::placement`] and [`Panel::caption`].
//!
//! - [`bad_ideas`]: the comparison, its keyframes, panels and captions:
//!   slerp against the notes' bad ideas, and in a turned world frame.
//! - [`interpolation`]: the methods the panels use (the Euler angles are
//!   the library's `EulerRot::ZYX`).
//! - [`spline`]: the keyframe comparison of `--spline`, with panels and a
//!   plot of its own: slerp key to key beside the Catmull-Rom spline.
//! - [`gltf`]: `--gltf`, a glTF file's animation played through the
//!   library's samplers.

pub mod bad_ideas;
pub mod gltf;
pub mod interpolation;
pub mod spline;

pub use bad_ideas::{keyframes, rotated_world, Comparison, Panel};

use rigtform::{Cvec3, Cvec4, RigTForm};

use crate::image::{Image, GLYPH_SIZE};
use crate::mesh::Mesh;
use crate::scene::{Camera, Draw, Scene, Settings};
use crate::vertex::Placement;

/// Length of the body's axes, and so where the tips are marked.
pub const ARM: f32 = 1.1;
/// Marks along each path, from `alpha = 0` to 1.
pub const TRAIL_MARKS: u32 = 16;

/// The demo: its meshes, panels and camera.
#[derive(Clone, Debug)]
pub struct Demo {
    body: Mesh,
    ground: Mesh,
    marker: Mesh,
    panels: Vec<Panel>,
    camera: Camera,
}

/// Colours of the path marks: origin, x tip, y tip, z tip.
const MARK_COLORS: [[f32; 3]; 4] = [
    [0.9, 0.8, 0.2],
    [0.9, 0.15, 0.1],
    [0.15, 0.75, 0.15],
    [0.15, 0.3, 0.95],
];
/// Points of the body, in its object coordinates, whose paths are marked.
const MARKED: [Cvec3; 4] = [
    Cvec3::ZERO,
    Cvec3::new(ARM, 0.0, 0.0),
    Cvec3::new(0.0, ARM, 0.0),
    Cvec3::new(0.0, 0.0, ARM),
];

/// Colour of label bars and gaps.
pub(crate) const BAR: [u8; 3] = [24, 24, 28];

/// Height of the two-line label bar above each panel.
pub const LABEL_BAR: u32 = 2 * GLYPH_SIZE + 8;

impl Demo {
    /// The demo with the panels of `comparison`, drawing `body` (by default
    /// the axes body, [`Mesh::axes`]) where each panel places it.
    #[must_use]
    pub fn new(comparison: Comparison, body: Option<Mesh>) -> Self {
        Self {
            body: body.unwrap_or_else(|| Mesh::axes(ARM)),
            ground: checkered_ground(),
            marker: Mesh::sphere(0.07, 10, 6, [1.0; 3]),
            panels: comparison.panels(),
            camera: Camera::looking_at(Cvec3::new(0.0, 3.0, 5.4), Cvec3::new(0.0, 1.1, -0.2), 0.8),
        }
    }

    /// The panels, left to right.
    #[must_use]
    pub fn panels(&self) -> &[Panel] {
        &self.panels
    }

    /// The interpolation parameter of frame `i` of `n`: 0 to 1 inclusive.
    #[must_use]
    pub fn alpha(i: u32, n: u32) -> f32 {
        if n < 2 {
            0.0
        } else {
            i as f32 / (n - 1) as f32
        }
    }

    /// The scene of one panel at `alpha`: ground, body, and path marks
    /// (coloured up to `alpha`, grey beyond).
    #[must_use]
    pub fn scene(&self, panel: &Panel, alpha: f32) -> Scene<'_> {
        let trail = (0..=TRAIL_MARKS).map(|k| {
            let a = k as f32 / TRAIL_MARKS as f32;
            (a, 1.0, panel.placement(a))
        });
        let stage = Stage {
            camera: self.camera,
            ground: &self.ground,
            marker: &self.marker,
            body: &self.body,
        };
        stage.scene(trail, alpha, panel.placement(alpha))
    }

    /// One frame of the animation: the panels side by side, each `width x
    /// height` under a label bar.
    ///
    /// ```
    /// use rigtform_render::demo::{Comparison, Demo, LABEL_BAR};
    /// use rigtform_render::{Cull, Msaa, Settings};
    /// let demo = Demo::new(Comparison::Interpolation, None);
    /// let settings = Settings { width: 32, height: 24, msaa: Msaa::Off, cull: Cull::Back };
    /// let frame = demo.render_frame(0.5, &settings);
    /// assert_eq!((frame.width(), frame.height()), (3 * 32 + 2 * 4, 24 + LABEL_BAR));
    /// ```
    #[must_use]
    pub fn render_frame(&self, alpha: f32, settings: &Settings) -> Image {
        let (w, h) = (settings.width, settings.height);
        let gap = 4;
        let n = self.panels.len() as u32;
        let mut frame = Image::new(n * w + (n - 1) * gap, h + LABEL_BAR, BAR);
        for (i, panel) in self.panels.iter().enumerate() {
            let x = i64::from(i as u32 * (w + gap));
            frame.blit(
                &self.scene(panel, alpha).render(settings),
                x,
                i64::from(LABEL_BAR),
            );
            // Labels are cut at the panel's edge.
            let mut label = Image::new(w, LABEL_BAR, BAR);
            label.draw_text(4, 3, panel.title, 1, [240, 240, 240]);
            let caption = panel.caption(alpha);
            label.draw_text(4, 5 + i64::from(GLYPH_SIZE), &caption, 1, [200, 200, 160]);
            frame.blit(&label, x, 0);
        }
        frame
    }
}

/// What every comparison draws in: the camera, the ground, the body and the
/// mark of its paths.
pub(crate) struct Stage<'a> {
    pub(crate) camera: Camera,
    pub(crate) ground: &'a Mesh,
    pub(crate) marker: &'a Mesh,
    pub(crate) body: &'a Mesh,
}

impl<'a> Stage<'a> {
    /// The ground, then the marks of the body's origin and axis tips at the
    /// placements of `trail` (`(time, size, placement)`: in colour up to
    /// `now`, smaller and grey beyond), then the body at `at`, under the two
    /// lights and the sky.
    pub(crate) fn scene(
        &self,
        trail: impl Iterator<Item = (f32, f32, Placement)>,
        now: f32,
        at: Placement,
    ) -> Scene<'a> {
        let mut draws = vec![Draw {
            mesh: self.ground,
            placement: Placement::Rigid(RigTForm::IDENTITY),
            scale: Cvec3::new(1.0, 1.0, 1.0),
            tint: [1.0; 3],
        }];
        for (time, size, placement) in trail {
            for (point, color) in MARKED.iter().zip(MARK_COLORS) {
                let p = apply(placement, *point);
                // Marks already passed in colour, those ahead small and grey.
                let (size, tint) = if time <= now + 1e-6 {
                    (size, color)
                } else {
                    (0.6 * size, [0.25; 3])
                };
                draws.push(Draw {
                    mesh: self.marker,
                    placement: Placement::Rigid(RigTForm::from_translation(p)),
                    scale: Cvec3::new(size, size, size),
                    tint,
                });
            }
        }
        draws.push(Draw {
            mesh: self.body,
            placement: at,
            scale: Cvec3::new(1.0, 1.0, 1.0),
            tint: [1.0; 3],
        });
        Scene {
            camera: self.camera,
            lights: [Cvec3::new(4.0, 8.0, 6.0), Cvec3::new(-6.0, 3.0, -2.0)],
            intensity: [0.75, 0.3],
            background: [0.42, 0.6, 0.85],
            draws,
        }
    }
}

/// The checkered ground both comparisons stand on.
pub(crate) fn checkered_ground() -> Mesh {
    Mesh::ground(
        [-8.0, 8.0],
        [-12.0, 4.0],
        16,
        [[0.32, 0.36, 0.3], [0.5, 0.54, 0.46]],
    )
}

/// Where `placement` puts the object's point `p`, in world coordinates.
fn apply(placement: Placement, p: Cvec3) -> Cvec3 {
    match placement {
        Placement::Rigid(r) => r.transform_point(p),
        Placement::Matrix(m) => (m * Cvec4::from_point(p)).xyz(),
    }
}

/// Which of `frames` frames the contact sheet shows in its `rows` rows:
/// evenly spaced, the first and the last included.
///
/// ```
/// use rigtform_render::demo::sheet_frames;
/// assert_eq!(sheet_frames(49, 5), [0, 12, 24, 36, 48]);
/// ```
#[must_use]
pub fn sheet_frames(frames: u32, rows: u32) -> Vec<u32> {
    if rows < 2 || frames < 2 {
        return vec![0];
    }
    (0..rows)
        .map(|r| ((frames - 1) * r + (rows - 1) / 2) / (rows - 1))
        .collect()
}

/// The animation's frame sequence: forward through `frames` frames, then
/// back, a loop without a jump; each entry is a frame index and its delay
/// in hundredths of a second, resting 0.8 s on each keyframe and showing
/// each frame between for `300 / frames` hundredths, clamped to 2 to 20
/// (about three seconds each way for 15 to 150 frames).
///
/// ```
/// use rigtform_render::demo::gif_sequence;
/// assert_eq!(gif_sequence(3), [(0, 80), (1, 20), (2, 80), (1, 20)]);
/// ```
#[must_use]
pub fn gif_sequence(frames: u32) -> Vec<(usize, u16)> {
    let delay = (300 / frames.max(1)).clamp(2, 20) as u16;
    let last = frames.saturating_sub(1) as usize;
    (0..=last)
        .chain((1..last).rev())
        .map(|i| (i, if i == 0 || i == last { 80 } else { delay }))
        .collect()
}

/// The size of the longest side of an OBJ body in the demo: as long as the
/// axes body is wide.
pub const BODY_SIZE: f32 = 2.0 * ARM;

/// Loads an OBJ file as the demo's body: centred, its longest side
/// [`BODY_SIZE`], coloured a warm orange.
///
/// # Errors
///
/// As [`Mesh::load_obj`].
pub fn load_body(path: &std::path::Path) -> Result<Mesh, String> {
    Mesh::load_obj(path, BODY_SIZE, [0.8, 0.62, 0.35])
}

/// Stacks frames into one picture, each row labelled with its `alpha` in
/// a margin on the left.
#[must_use]
pub fn contact_sheet(rows: &[(f32, &Image)]) -> Image {
    labelled_contact_sheet(rows, "alpha")
}

/// Stacks frames into one picture, each row labelled with `label` and its
/// value in a margin on the left.
#[must_use]
pub fn labelled_contact_sheet(rows: &[(f32, &Image)], label: &str) -> Image {
    let margin = 8 * 11 + 8;
    let gap = 4;
    let width = rows.iter().map(|(_, im)| im.width()).max().unwrap_or(0) + margin;
    let height = rows.iter().map(|(_, im)| im.height() + gap).sum::<u32>();
    let mut sheet = Image::new(width, height, BAR);
    let mut y = 0i64;
    for (alpha, image) in rows {
        sheet.blit(image, i64::from(margin), y);
        let mid = y + i64::from(image.height() / 2);
        sheet.draw_text(4, mid - 10, label, 1, [200, 200, 200]);
        sheet.draw_text(4, mid + 2, &format!("{alpha:.3}"), 2, [240, 240, 240]);
        y += i64::from(image.height() + gap);
    }
    sheet
}

#[cfg(test)]
mod tests {
    use super::interpolation::Method;
    use super::*;

    /// The demo's slerp motion read back from the frames it renders has the
    /// notes' properties: the origin moves on a straight line at constant
    /// speed, and the body turns about one fixed axis at constant angular
    /// velocity.
    #[test]
    fn demo_slerp_motion_is_straight_and_uniform() {
        let demo = Demo::new(Comparison::All, None);
        let panel = demo.panels()[2];
        assert_eq!(panel.method, Method::Slerp);
        let n = 24;
        let placements: Vec<RigTForm> = (0..n)
            .map(|i| match panel.placement(Demo::alpha(i, n)) {
                Placement::Rigid(r) => r,
                Placement::Matrix(_) => panic!("slerp places the body rigidly"),
            })
            .collect();
        let (k0, k1) = keyframes();
        let step = (k1.t - k0.t) * (1.0 / (n - 1) as f32);
        let (_, total) = (k1.r * k0.r.inv()).to_axis_angle();
        let (axis, _) = (k1.r * k0.r.inv()).to_axis_angle();
        for pair in placements.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            assert!(
                (b.t - a.t - step).norm() < 1e-5,
                "straight line, constant speed"
            );
            let (turn_axis, turn) = (b.r * a.r.inv()).to_axis_angle();
            assert!(
                (turn - total / (n - 1) as f32).abs() < 1e-4,
                "constant angular velocity"
            );
            assert!(turn_axis.dot(axis) > 1.0 - 1e-4, "one fixed axis");
        }
        assert!(placements[0].r.angle_to(k0.r) < 1e-6);
        assert!(placements[n as usize - 1].r.angle_to(k1.r) < 1e-5);
        assert!((total.to_degrees() - 150.0).abs() < 1e-3);
    }

    #[test]
    fn sheet_shows_evenly_spaced_frames_first_and_last_included() {
        assert_eq!(sheet_frames(5, 3), [0, 2, 4]);
        assert_eq!(sheet_frames(2, 2), [0, 1]);
        assert_eq!(sheet_frames(10, 4), [0, 3, 6, 9]);
        assert_eq!(sheet_frames(11, 3), [0, 5, 10]);
        assert_eq!(sheet_frames(7, 7), [0, 1, 2, 3, 4, 5, 6]);
    }

    #[test]
    fn gif_goes_there_and_back_resting_on_the_keyframes() {
        assert_eq!(gif_sequence(2), [(0, 80), (1, 80)]);
        let seq = gif_sequence(49);
        let order: Vec<usize> = seq.iter().map(|&(i, _)| i).collect();
        let expected: Vec<usize> = (0..49).chain((1..48).rev()).collect();
        assert_eq!(order, expected);
        assert!(seq
            .iter()
            .all(|&(i, d)| d == if i == 0 || i == 48 { 80 } else { 6 }));
        assert_eq!(gif_sequence(1000)[1].1, 2, "at least 2/100 s a frame");
    }

    #[test]
    fn obj_body_is_as_long_as_the_axes_body() {
        let dir = std::env::temp_dir().join(format!("rigtform-body-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("tri.obj");
        std::fs::write(&path, "v 0 0 0\nv 5 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        let body = load_body(&path).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let (lo, hi) = body.bounds();
        assert!((hi.x - lo.x - 2.0 * ARM).abs() < 1e-6);
        assert!((lo.x + ARM).abs() < 1e-6);
    }

    #[test]
    fn alpha_runs_from_zero_to_one() {
        assert_eq!(Demo::alpha(0, 5), 0.0);
        assert_eq!(Demo::alpha(2, 5), 0.5);
        assert_eq!(Demo::alpha(4, 5), 1.0);
        assert_eq!(Demo::alpha(0, 1), 0.0);
        assert_eq!(Demo::alpha(1, 2), 1.0);
    }

    #[test]
    fn contact_sheet_stacks_rows_under_each_other() {
        let a = Image::new(10, 40, [255, 0, 0]);
        let b = Image::new(10, 40, [0, 0, 255]);
        let sheet = contact_sheet(&[(0.0, &a), (1.0, &b)]);
        let margin = 8 * 11 + 8;
        assert_eq!((sheet.width(), sheet.height()), (10 + margin, 2 * (40 + 4)));
        assert_eq!(sheet.pixel(margin, 0), [255, 0, 0]);
        assert_eq!(sheet.pixel(margin, 44), [0, 0, 255]);
        assert_eq!(sheet.pixel(margin, 41), BAR, "the gap");
        // Each row's label sits in the margin beside the middle of its row:
        // "alpha" from 10 above the middle, the value (twice as large)
        // down to 18 below it.
        for y in 0..sheet.height() {
            let lit = (0..margin).any(|x| sheet.pixel(x, y) != BAR);
            let row_mid = 20 + 44 * (y / 44);
            let beside = y + 10 >= row_mid && y < row_mid + 18;
            assert!(!lit || beside, "label pixel at row {y}");
            if y + 9 == row_mid || y == row_mid + 8 {
                assert!(lit, "label missing at row {y}");
            }
        }
    }
}
