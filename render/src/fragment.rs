//! The fragment stage: what becomes of each pixel a triangle covers. Every
//! covered sample gets the depth test; if any passes, the pixel is shaded
//! once, at its shading point with perspective-correct attributes, and the
//! colour is stored in the samples that passed.
//!
//! Coverage, depth and attributes come from [`raster`](crate::raster), the
//! colour from the shading function the caller hands in (the scene's
//! [`Lighting::shade`](crate::shade::Lighting::shade)), and the samples are
//! a [`Band`] of the framebuffer.

use crate::framebuffer::Band;
use crate::raster::Triangle;
use crate::samples::Msaa;
use crate::vertex::ATTRIBUTES;

/// Draws the part of `triangle` inside `band`: the depth test on every
/// covered sample, then, if any passed, `shade` once at the pixel centre
/// (or at the first covered sample when the centre is outside) with
/// perspective-correct attributes, its colour stored in the samples that
/// passed.
///
/// ```
/// use rigtform_render::{fill_triangle, Cull, Framebuffer, Msaa, ScreenVertex, Triangle};
/// let v = |x, y| ScreenVertex { x, y, z: 0.0, inv_w: 1.0, attrs_w: [1.0; 9] };
/// let t = Triangle::setup([v(0.0, 0.0), v(0.0, 8.0), v(8.0, 0.0)], Cull::Back, 8, 8).unwrap();
/// let mut fb = Framebuffer::new(8, 8, Msaa::X4, [0.0; 3]);
/// for mut band in fb.bands_mut(4) {
///     fill_triangle(&t, &mut band, Msaa::X4, &|a| [a[6], 0.0, 0.0]);
/// }
/// assert_eq!(fb.resolve().pixel(1, 1), [255, 0, 0]); // inside
/// assert_eq!(fb.resolve().pixel(7, 7), [0, 0, 0]); // beyond the long edge
/// ```
// One call per triangle and band, out of line, with the per-pixel steps of
// raster.rs and shade.rs (`#[inline]` there) inlined into it, and the depth
// plane taken once per call, so that it stays in registers: inlined into
// the band loop instead, or with the depth read through the triangle at
// every sample, the demo renders 5 to 8 % slower.
#[inline(never)]
pub fn fill_triangle(
    triangle: &Triangle,
    band: &mut Band<'_>,
    msaa: Msaa,
    shade: &impl Fn(&[f32; ATTRIBUTES]) -> [f32; 3],
) {
    let y_end = band.y_end();
    if y_end == 0 {
        return;
    }
    let depth = triangle.depth_plane();
    triangle.for_each_covered(msaa, band.y0(), y_end - 1, |x, y, mask, e| {
        let mut passed = 0u32;
        for (s, es) in e.iter().enumerate().take(msaa.samples()) {
            if mask & (1 << s) == 0 {
                continue;
            }
            if band.depth_test(x, y, s, depth.at(es)) {
                passed |= 1 << s;
            }
        }
        if passed == 0 {
            return;
        }
        let weights = triangle.shading_weights(x, y, mask, e);
        let attrs = triangle.interpolate(weights);
        let color = shade(&attrs);
        for s in 0..msaa.samples() {
            if passed & (1 << s) != 0 {
                band.set_color(x, y, s, color);
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::Framebuffer;
    use crate::raster::Cull;
    use crate::viewport::ScreenVertex;

    fn flat(z: f32, corners: [(f32, f32); 3], color: f32) -> [ScreenVertex; 3] {
        corners.map(|(x, y)| ScreenVertex {
            x,
            y,
            z,
            inv_w: 1.0,
            attrs_w: [color; ATTRIBUTES],
        })
    }

    #[test]
    fn depth_test_keeps_the_nearer_triangle_in_either_order() {
        let big = [(0.0, 0.0), (0.0, 8.0), (8.0, 0.0)];
        let near = flat(-0.5, big, 1.0);
        let far = flat(0.5, big, 0.25);
        for order in [[near, far], [far, near]] {
            let mut fb = Framebuffer::new(8, 8, Msaa::X4, [0.0; 3]);
            for tri in order {
                let t = Triangle::setup(tri, Cull::Back, 8, 8).unwrap();
                for mut band in fb.bands_mut(3) {
                    fill_triangle(&t, &mut band, Msaa::X4, &|a| [a[0]; 3]);
                }
            }
            let image = fb.resolve();
            assert_eq!(image.pixel(1, 1), [255; 3]);
            assert_eq!(fb.depth(1, 1, 0), -0.5);
        }
    }
}
