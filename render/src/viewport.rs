//! The perspective divide and the viewport transform: clip coordinates to
//! screen coordinates in pixels (x right, y down, pixel `(i, j)` covering
//! `[i, i + 1) x [j, j + 1)`), depth in NDC, and the attributes divided by
//! `w` for perspective-correct interpolation.

use crate::vertex::{ClipVertex, ATTRIBUTES};

/// A vertex on the screen, ready for triangle setup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenVertex {
    /// Horizontal position in pixels, from the left edge.
    pub x: f32,
    /// Vertical position in pixels, from the top edge.
    pub y: f32,
    /// NDC depth: -1 at the near plane, +1 at the far plane.
    pub z: f32,
    /// `1 / w`, which interpolates linearly across the screen.
    pub inv_w: f32,
    /// The attributes times `1 / w`, which also interpolate linearly.
    pub attrs_w: [f32; ATTRIBUTES],
}

/// Divides by `w` and maps NDC `[-1, 1]^2` onto a `width x height` viewport.
///
/// # Preconditions
///
/// `v.clip.w > 0`, which near-plane clipping guarantees.
///
/// ```
/// use rigtform::Cvec4;
/// use rigtform_render::{to_screen, ClipVertex};
/// let v = ClipVertex { clip: Cvec4::new(-2.0, 2.0, 0.0, 2.0), attrs: [4.0; 9] };
/// let s = to_screen(v, 640, 480);
/// assert_eq!((s.x, s.y), (0.0, 0.0)); // NDC (-1, 1) is the top-left corner
/// assert_eq!(s.attrs_w, [2.0; 9]);
/// ```
#[must_use]
pub fn to_screen(v: ClipVertex, width: u32, height: u32) -> ScreenVertex {
    let inv_w = 1.0 / v.clip.w;
    let (x, y, z) = (v.clip.x * inv_w, v.clip.y * inv_w, v.clip.z * inv_w);
    ScreenVertex {
        x: (x + 1.0) * 0.5 * width as f32,
        y: (1.0 - y) * 0.5 * height as f32,
        z,
        inv_w,
        attrs_w: v.attrs.map(|a| a * inv_w),
    }
}
