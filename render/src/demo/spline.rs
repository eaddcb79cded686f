//! The keyframe comparison (`--spline`): one body through five keyframes,
//! by [`RigTForm::interpolate`] from key to key and by
//! [`RigTForm::catmull_rom`], side by side, and a plot of the angular
//! speed of both over time. Key to key, the body turns at a constant rate
//! about a fixed axis between two keys and changes rate and axis at once
//! at each key; the spline's angular velocity is continuous there.
//!
//! Time runs one second per key: `t` in [0, 4], key `i` at `t = i`.

use rigtform::{Cvec3, Quat, RigTForm};

use crate::demo::{checkered_ground, Stage, ARM, BAR, LABEL_BAR};
use crate::image::{Image, GLYPH_SIZE};
use crate::mesh::Mesh;
use crate::scene::{Camera, Scene, Settings};
use crate::vertex::Placement;

/// The five keyframes: the body crosses the ground from left to right,
/// turning about a different axis between each pair of keys, by turns of
/// 0.7, 1.8, 0.6 and 1.6 rad, so that slerp key to key changes both the
/// axis and the rate at each key.
///
/// ```
/// let keys = rigtform_render::demo::spline::keyframes();
/// assert!((keys[1].r.angle_to(keys[2].r) - 1.8).abs() < 1e-5);
/// ```
#[must_use]
pub fn keyframes() -> [RigTForm; 5] {
    let r0 = Quat::from_rotation_y(0.4) * Quat::from_rotation_x(-0.25);
    let r1 = Quat::from_rotation_z(0.7) * r0;
    let r2 = Quat::from_rotation_x(1.8) * r1;
    let r3 = Quat::from_rotation_y(0.6) * r2;
    let r4 = Quat::from_axis_angle(Cvec3::new(1.0, 0.0, 1.0), -1.6) * r3;
    [
        RigTForm::new(Cvec3::new(-2.2, 1.2, 0.3), r0),
        RigTForm::new(Cvec3::new(-1.1, 1.7, -0.7), r1),
        RigTForm::new(Cvec3::new(0.0, 1.0, 0.1), r2),
        RigTForm::new(Cvec3::new(1.1, 1.7, -0.8), r3),
        RigTForm::new(Cvec3::new(2.2, 1.2, 0.3), r4),
    ]
}

/// The last key's `t`: the animation runs over `[0, DURATION]`.
pub const DURATION: f32 = 4.0;

/// How the body goes through the keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keyed {
    /// [`RigTForm::interpolate`] between each key and the next.
    KeyToKey,
    /// [`RigTForm::catmull_rom`] through all of them.
    Spline,
}

impl Keyed {
    /// Both, in the order of the panels.
    pub const BOTH: [Keyed; 2] = [Keyed::KeyToKey, Keyed::Spline];

    /// The panel's title.
    #[must_use]
    pub fn title(self) -> &'static str {
        match self {
            Keyed::KeyToKey => "SLERP KEY TO KEY",
            Keyed::Spline => "CATMULL-ROM SPLINE",
        }
    }

    /// The plot's colour of this method.
    #[must_use]
    pub fn color(self) -> [u8; 3] {
        match self {
            Keyed::KeyToKey => [240, 140, 40],
            Keyed::Spline => [70, 200, 240],
        }
    }

    /// Where the method puts the body at `t`, `t` clamped to the keys.
    ///
    /// ```
    /// use rigtform_render::demo::spline::{keyframes, Keyed};
    /// let keys = keyframes();
    /// for method in Keyed::BOTH {
    ///     assert_eq!(method.at(&keys, 2.0), keys[2]);
    /// }
    /// ```
    #[must_use]
    pub fn at(self, keys: &[RigTForm], t: f32) -> RigTForm {
        match self {
            Keyed::Spline => RigTForm::catmull_rom(keys, t),
            Keyed::KeyToKey => {
                let last = keys.len().saturating_sub(1);
                let t = t.clamp(0.0, last as f32);
                let i = (t as usize).min(last.saturating_sub(1));
                match (keys.get(i), keys.get(i + 1)) {
                    (Some(&a), Some(&b)) => a.interpolate(b, t - i as f32),
                    (Some(&a), None) => a,
                    _ => RigTForm::IDENTITY,
                }
            }
        }
    }
}

/// Step of the one-sided differences: 1/256 s, exact in f32 beside whole
/// seconds.
const STEP: f32 = 1.0 / 256.0;

/// The angular velocity, in rad/s in the world frame, of `method`'s body
/// as it leaves `t` in the direction `dir` (+1 after `t`, -1 before), by a
/// one-sided second-order difference of rotation vectors: with
/// `L(x) = log(r(t + dir x) r(t)^-1)`, `dir (4 L(h) - L(2 h)) / (2 h)`.
#[must_use]
pub fn angular_velocity(method: Keyed, keys: &[RigTForm], t: f32, dir: f32) -> Cvec3 {
    let at = method.at(keys, t).r;
    let log = |x: f32| {
        (method.at(keys, t + dir * x).r * at.inv())
            .cn()
            .to_scaled_axis()
    };
    (log(STEP) * 4.0 - log(2.0 * STEP)) * (dir / (2.0 * STEP))
}

/// The largest jump of angular velocity at a key, in rad/s, and that key:
/// the two one-sided velocities apart, over the keys between the first
/// and the last.
///
/// ```
/// use rigtform_render::demo::spline::{keyframes, largest_jump, Keyed};
/// let keys = keyframes();
/// assert!(largest_jump(Keyed::KeyToKey, &keys).0 > 1.0);
/// assert!(largest_jump(Keyed::Spline, &keys).0 < 1e-2);
/// ```
#[must_use]
pub fn largest_jump(method: Keyed, keys: &[RigTForm]) -> (f32, usize) {
    (1..keys.len().saturating_sub(1))
        .map(|i| {
            let t = i as f32;
            let before = angular_velocity(method, keys, t, -1.0);
            let after = angular_velocity(method, keys, t, 1.0);
            ((after - before).norm(), i)
        })
        .fold((0.0, 0), |best, x| if x.0 > best.0 { x } else { best })
}

/// The angular speed, in rad/s, of `method`'s body at `t`: as it leaves
/// `t`, or as it arrives there where the difference would reach past the
/// next key (or the last), so that it never straddles a key.
#[must_use]
pub fn angular_speed(method: Keyed, keys: &[RigTForm], t: f32) -> f32 {
    let reach = t + 2.0 * STEP;
    let dir = if reach <= t.floor() + 1.0 && reach <= DURATION {
        1.0
    } else {
        -1.0
    };
    angular_velocity(method, keys, t, dir).norm()
}

/// Marks along each path: eight a second.
const MARKS_PER_KEY: u32 = 8;

/// The comparison: its meshes, keyframes and camera.
#[derive(Clone, Debug)]
pub struct SplineDemo {
    body: Mesh,
    ground: Mesh,
    marker: Mesh,
    keys: [RigTForm; 5],
    camera: Camera,
}

impl SplineDemo {
    /// The comparison, drawing `body` (by default the axes body).
    #[must_use]
    pub fn new(body: Option<Mesh>) -> Self {
        Self {
            body: body.unwrap_or_else(|| Mesh::axes(ARM)),
            ground: checkered_ground(),
            marker: Mesh::sphere(0.06, 10, 6, [1.0; 3]),
            keys: keyframes(),
            camera: Camera::looking_at(Cvec3::new(0.0, 3.4, 6.2), Cvec3::new(0.0, 1.2, -0.2), 0.8),
        }
    }

    /// The time of `alpha` in [0, 1]: `alpha * DURATION` seconds.
    #[must_use]
    pub fn time(alpha: f32) -> f32 {
        alpha * DURATION
    }

    /// The scene of `method` at `t`: ground, body, and the marks of its
    /// path (coloured up to `t`, grey beyond, larger at the keys).
    #[must_use]
    pub fn scene(&self, method: Keyed, t: f32) -> Scene<'_> {
        let marks = MARKS_PER_KEY * DURATION as u32;
        let trail = (0..=marks).map(|k| {
            let at = k as f32 / MARKS_PER_KEY as f32;
            let size = if k % MARKS_PER_KEY == 0 { 1.6 } else { 1.0 };
            (at, size, Placement::Rigid(method.at(&self.keys, at)))
        });
        let stage = Stage {
            camera: self.camera,
            ground: &self.ground,
            marker: &self.marker,
            body: &self.body,
        };
        stage.scene(trail, t, Placement::Rigid(method.at(&self.keys, t)))
    }

    /// One frame at `alpha` in [0, 1] (time `alpha * DURATION`): the two
    /// panels side by side, each `width x height` under a label bar with
    /// the time and the angular speed.
    ///
    /// ```
    /// use rigtform_render::demo::spline::SplineDemo;
    /// use rigtform_render::demo::LABEL_BAR;
    /// use rigtform_render::{Cull, Msaa, Settings};
    /// let settings = Settings { width: 32, height: 24, msaa: Msaa::Off, cull: Cull::Back };
    /// let frame = SplineDemo::new(None).render_frame(0.5, &settings);
    /// assert_eq!((frame.width(), frame.height()), (2 * 32 + 4, 24 + LABEL_BAR));
    /// ```
    #[must_use]
    pub fn render_frame(&self, alpha: f32, settings: &Settings) -> Image {
        let (w, h) = (settings.width, settings.height);
        let gap = 4;
        let t = Self::time(alpha);
        let mut frame = Image::new(2 * w + gap, h + LABEL_BAR, BAR);
        for (i, method) in Keyed::BOTH.into_iter().enumerate() {
            let x = i64::from(i as u32 * (w + gap));
            frame.blit(
                &self.scene(method, t).render(settings),
                x,
                i64::from(LABEL_BAR),
            );
            let mut label = Image::new(w, LABEL_BAR, BAR);
            label.draw_text(4, 3, method.title(), 1, [240, 240, 240]);
            let speed = angular_speed(method, &self.keys, t).to_degrees();
            let caption = format!("t {t:4.2} s {speed:3.0} deg/s");
            label.draw_text(4, 5 + i64::from(GLYPH_SIZE), &caption, 1, [200, 200, 160]);
            frame.blit(&label, x, 0);
        }
        frame
    }

    /// The keyframes.
    #[must_use]
    pub fn keys(&self) -> &[RigTForm] {
        &self.keys
    }
}

/// A `width x height` plot of the angular speed over time of both
/// methods through `keys`, in deg/s: one curve per method in its colour,
/// a vertical line at each key, a line every 30 deg/s, and in the legend
/// each method's largest jump of angular velocity at a key (which the
/// speed shows only in part: slerp key to key also turns the axis there).
///
/// ```
/// use rigtform_render::demo::spline::{keyframes, speed_plot, Keyed};
/// let plot = speed_plot(&keyframes(), 320, 160);
/// assert_eq!((plot.width(), plot.height()), (320, 160));
/// for method in Keyed::BOTH {
///     assert!(plot.pixels().contains(&method.color()));
/// }
/// ```
#[must_use]
pub fn speed_plot(keys: &[RigTForm], width: u32, height: u32) -> Image {
    let background = [250, 250, 247];
    let grid = [215, 215, 210];
    let ink = [40, 40, 40];
    let mut plot = Image::new(width, height, background);
    // The plotting area, inside margins for the labels.
    let (left, top) = (56i64, 52i64);
    let (right, bottom) = (i64::from(width) - 12, i64::from(height) - 30);
    let (pw, ph) = ((right - left).max(1), (bottom - top).max(1));
    let samples: Vec<[f32; 2]> = (0..=pw)
        .map(|x| {
            let t = DURATION * x as f32 / pw as f32;
            Keyed::BOTH.map(|m| angular_speed(m, keys, t).to_degrees())
        })
        .collect();
    let top_speed = samples.iter().flatten().fold(0.0f32, |a, &b| a.max(b));
    let scale = 30.0 * ((top_speed * 1.1 / 30.0).ceil()).max(1.0);
    let y_of = |deg: f32| bottom - (deg / scale * ph as f32).round() as i64;
    let mut level = 0.0;
    while level <= scale {
        let y = y_of(level);
        plot.fill_rect(left, y, pw as u32 + 1, 1, grid);
        let label = format!("{level:3.0}");
        plot.draw_text(
            left - 8 - i64::from(Image::text_width(&label, 1)),
            y - 4,
            &label,
            1,
            ink,
        );
        level += 30.0;
    }
    for key in 0..=DURATION as u32 {
        let x = left + (i64::from(key) * pw) / DURATION as i64;
        plot.fill_rect(x, top, 1, ph as u32 + 1, grid);
        let label = format!("{key} s");
        let half = i64::from(Image::text_width(&label, 1) / 2);
        plot.draw_text(x - half, bottom + 8, &label, 1, ink);
    }
    plot.fill_rect(left, top, 1, ph as u32 + 1, ink);
    plot.fill_rect(left, bottom, pw as u32 + 1, 1, ink);
    for (m, method) in Keyed::BOTH.into_iter().enumerate() {
        let color = method.color();
        for (x, pair) in samples.windows(2).enumerate() {
            // A vertical run from one sample's height to the next: a jump
            // shows as a vertical stroke.
            let (y0, y1) = (y_of(pair[0][m]), y_of(pair[1][m]));
            let x = left + x as i64;
            for y in y0.min(y1)..=y0.max(y1) {
                plot.fill_rect(x, y - 1, 2, 3, color);
            }
        }
    }
    plot.draw_text(left, 4, "angular speed, deg/s (one key a second)", 1, ink);
    for (line, method) in Keyed::BOTH.into_iter().enumerate() {
        let y = 18 + 14 * line as i64;
        let (jump, _) = largest_jump(method, keys);
        plot.fill_rect(left, y + 3, 16, 3, method.color());
        let text = format!(
            "{}: velocity jumps by up to {:.1} deg/s at a key",
            method.title(),
            jump.to_degrees()
        );
        plot.draw_text(left + 22, y, &text, 1, ink);
    }
    plot
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_methods_pass_through_every_key() {
        let keys = keyframes();
        for method in Keyed::BOTH {
            for (i, key) in keys.iter().enumerate() {
                let at = method.at(&keys, i as f32);
                assert!(at.r.angle_to(key.r) < 1e-6 && (at.t - key.t).norm() < 1e-6);
            }
        }
    }

    #[test]
    fn key_to_key_turns_at_a_constant_rate_between_keys() {
        let keys = keyframes();
        for i in 0..4 {
            let expected = keys[i].r.angle_to(keys[i + 1].r);
            for t in [0.25, 0.5, 0.75] {
                let speed = angular_speed(Keyed::KeyToKey, &keys, i as f32 + t);
                assert!(
                    (speed - expected).abs() < 1e-3,
                    "{i} {t}: {speed} {expected}"
                );
            }
        }
    }

    #[test]
    fn key_to_key_jumps_at_the_keys_and_the_spline_does_not() {
        let keys = keyframes();
        let (slerp, _) = largest_jump(Keyed::KeyToKey, &keys);
        let (spline, _) = largest_jump(Keyed::Spline, &keys);
        // Each key turns the axis by a large angle: jumps of radians per
        // second against the differences' own error.
        assert!(slerp > 1.0, "{slerp}");
        assert!(spline < 1e-2, "{spline}");
    }
}
