//! The multisampled colour and depth buffers, cut into bands of rows that
//! threads fill independently, the depth test, and the resolve to an image.

use std::sync::OnceLock;

use crate::image::Image;
use crate::samples::Msaa;

/// Linear RGB colour and NDC depth for every sample of every pixel.
///
/// Samples of one pixel are stored together: sample `s` of pixel `(x, y)`
/// is at `(y * width + x) * samples + s`.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    samples: usize,
    color: Vec<[f32; 3]>,
    depth: Vec<f32>,
}

/// Rows `y0 .. y0 + rows` of a [`Framebuffer`], borrowed mutably so that
/// each band can be filled on its own thread.
#[derive(Debug)]
pub struct Band<'a> {
    y0: u32,
    rows: u32,
    width: u32,
    samples: usize,
    color: &'a mut [[f32; 3]],
    depth: &'a mut [f32],
}

impl Framebuffer {
    /// A framebuffer cleared to `background` and to the far plane (depth 1).
    ///
    /// ```
    /// use rigtform_render::{Framebuffer, Msaa};
    /// let fb = Framebuffer::new(4, 2, Msaa::X4, [0.0, 0.0, 1.0]);
    /// assert_eq!(fb.resolve().pixel(3, 1), [0, 0, 255]);
    /// ```
    #[must_use]
    pub fn new(width: u32, height: u32, msaa: Msaa, background: [f32; 3]) -> Self {
        let samples = msaa.samples();
        let n = width as usize * height as usize * samples;
        Self {
            width,
            height,
            samples,
            color: vec![background; n],
            depth: vec![1.0; n],
        }
    }

    /// The framebuffer cut into bands of `rows` rows (the last may be
    /// shorter), top to bottom. The cut depends only on the size, never on
    /// the number of threads.
    ///
    /// ```
    /// use rigtform_render::{Framebuffer, Msaa};
    /// let mut fb = Framebuffer::new(4, 10, Msaa::Off, [0.0; 3]);
    /// let ends: Vec<_> = fb.bands_mut(4).iter().map(|b| b.y_end()).collect();
    /// assert_eq!(ends, [4, 8, 10]);
    /// ```
    pub fn bands_mut(&mut self, rows: u32) -> Vec<Band<'_>> {
        let rows = rows.max(1);
        let per_band = rows as usize * self.width as usize * self.samples;
        let (width, samples, height) = (self.width, self.samples, self.height);
        self.color
            .chunks_mut(per_band.max(1))
            .zip(self.depth.chunks_mut(per_band.max(1)))
            .enumerate()
            .map(|(i, (color, depth))| {
                let y0 = i as u32 * rows;
                Band {
                    y0,
                    rows: rows.min(height - y0),
                    width,
                    samples,
                    color,
                    depth,
                }
            })
            .collect()
    }

    /// Averages each pixel's samples in linear light and encodes the result
    /// as 8-bit sRGB.
    #[must_use]
    pub fn resolve(&self) -> Image {
        let mut image = Image::new(self.width, self.height, [0; 3]);
        resolve_samples(&self.color, self.samples, image.pixels_mut());
        image
    }

    /// The depth of sample `s` of pixel `(x, y)` (1 where nothing was drawn).
    ///
    /// # Panics
    ///
    /// When the pixel or sample is out of range (a caller's bug).
    #[must_use]
    pub fn depth(&self, x: u32, y: u32, s: usize) -> f32 {
        self.depth[(y as usize * self.width as usize + x as usize) * self.samples + s]
    }
}

impl Band<'_> {
    /// The first row of the band.
    #[must_use]
    pub fn y0(&self) -> u32 {
        self.y0
    }

    /// One past the last row of the band.
    #[must_use]
    pub fn y_end(&self) -> u32 {
        self.y0 + self.rows
    }

    fn index(&self, x: u32, y: u32, s: usize) -> usize {
        ((y - self.y0) as usize * self.width as usize + x as usize) * self.samples + s
    }

    /// The depth test ("less"): `true`, and `z` stored, when `z` is nearer
    /// than what sample `s` of pixel `(x, y)` holds. NaN never passes.
    ///
    /// ```
    /// use rigtform_render::{Framebuffer, Msaa};
    /// let mut fb = Framebuffer::new(1, 1, Msaa::Off, [0.0; 3]);
    /// let mut bands = fb.bands_mut(1);
    /// assert!(bands[0].depth_test(0, 0, 0, 0.3));
    /// assert!(!bands[0].depth_test(0, 0, 0, 0.6)); // behind what is there
    /// ```
    pub fn depth_test(&mut self, x: u32, y: u32, s: usize, z: f32) -> bool {
        let i = self.index(x, y, s);
        if z < self.depth[i] {
            self.depth[i] = z;
            true
        } else {
            false
        }
    }

    /// Stores the colour of sample `s` of pixel `(x, y)`.
    pub fn set_color(&mut self, x: u32, y: u32, s: usize, color: [f32; 3]) {
        let i = self.index(x, y, s);
        self.color[i] = color;
    }

    /// Resolves the band's pixels (see [`Framebuffer::resolve`]) into
    /// `pixels`, its rows of the final image.
    ///
    /// # Panics
    ///
    /// If `pixels` does not hold exactly the band's pixels.
    pub fn resolve_into(&self, pixels: &mut [[u8; 3]]) {
        assert_eq!(
            pixels.len(),
            self.rows as usize * self.width as usize,
            "band size"
        );
        resolve_samples(self.color, self.samples, pixels);
    }
}

/// Averages each run of `samples` colours into one sRGB pixel.
fn resolve_samples(color: &[[f32; 3]], samples: usize, pixels: &mut [[u8; 3]]) {
    let table = srgb_table();
    let scale = 1.0 / samples as f32;
    let encode = |v: f32| table[srgb_index(v * scale)];
    for (pixel, samples) in pixels.iter_mut().zip(color.chunks_exact(samples)) {
        let mut sum = [0.0f32; 3];
        for c in samples {
            sum[0] += c[0];
            sum[1] += c[1];
            sum[2] += c[2];
        }
        *pixel = [encode(sum[0]), encode(sum[1]), encode(sum[2])];
    }
}

/// Steps of the sRGB table over [0, 1].
const SRGB_STEPS: usize = 4096;

/// The sRGB transfer function (IEC 61966-2-1) at `SRGB_STEPS + 1` points.
fn srgb_table() -> &'static [u8; SRGB_STEPS + 1] {
    static TABLE: OnceLock<[u8; SRGB_STEPS + 1]> = OnceLock::new();
    TABLE.get_or_init(|| {
        core::array::from_fn(|i| {
            let l = i as f64 / SRGB_STEPS as f64;
            let s = if l <= 0.003_130_8 {
                12.92 * l
            } else {
                1.055 * l.powf(1.0 / 2.4) - 0.055
            };
            (s * 255.0).round() as u8
        })
    })
}

/// The table index of a linear value: clamped to [0, 1] and rounded by
/// adding a half and truncating (`f32::round` is a library call on baseline
/// x86-64); NaN becomes 0 through the saturating cast.
fn srgb_index(v: f32) -> usize {
    ((v.clamp(0.0, 1.0) * SRGB_STEPS as f32 + 0.5) as usize).min(SRGB_STEPS)
}

/// Encodes a linear value in [0, 1] (clamped) as an 8-bit sRGB value, with
/// the sRGB transfer function (IEC 61966-2-1) tabulated at 4097 points.
///
/// ```
/// use rigtform_render::linear_to_srgb8;
/// assert_eq!(linear_to_srgb8(0.0), 0);
/// assert_eq!(linear_to_srgb8(1.0), 255);
/// assert_eq!(linear_to_srgb8(0.5), 188); // half the light is not half the code
/// ```
#[must_use]
pub fn linear_to_srgb8(v: f32) -> u8 {
    srgb_table()[srgb_index(v)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_cover_every_row_once() {
        let mut fb = Framebuffer::new(5, 37, Msaa::X4, [0.0; 3]);
        let bands = fb.bands_mut(8);
        let rows: Vec<_> = bands.iter().map(|b| (b.y0(), b.y_end())).collect();
        assert_eq!(rows, [(0, 8), (8, 16), (16, 24), (24, 32), (32, 37)]);
    }

    #[test]
    fn depth_test_keeps_the_nearest() {
        let mut fb = Framebuffer::new(3, 4, Msaa::X4, [0.0; 3]);
        let mut bands = fb.bands_mut(2);
        let band = &mut bands[1]; // rows 2 and 3
        assert!(band.depth_test(1, 3, 2, 0.5));
        assert!(!band.depth_test(1, 3, 2, 0.7));
        assert!(!band.depth_test(1, 3, 2, 0.5));
        assert!(band.depth_test(1, 3, 2, -0.2));
        assert!(!band.depth_test(1, 3, 2, f32::NAN));
        assert!(!band.depth_test(0, 2, 0, 1.5), "beyond the far plane");
        drop(bands);
        // Only that sample of that pixel changed.
        for y in 0..4 {
            for x in 0..3 {
                for s in 0..4 {
                    let expected = if (x, y, s) == (1, 3, 2) { -0.2 } else { 1.0 };
                    assert_eq!(fb.depth(x, y, s), expected, "({x}, {y}) sample {s}");
                }
            }
        }
    }

    #[test]
    fn resolve_averages_samples_in_linear_light() {
        let mut fb = Framebuffer::new(1, 1, Msaa::X4, [0.0; 3]);
        let mut bands = fb.bands_mut(1);
        bands[0].set_color(0, 0, 0, [1.0; 3]);
        bands[0].set_color(0, 0, 1, [1.0; 3]);
        drop(bands);
        // Half the samples white: linear 0.5, which sRGB encodes as 188.
        assert_eq!(fb.resolve().pixel(0, 0), [188; 3]);
    }

    #[test]
    fn srgb_encoding_is_monotonic_and_matches_the_standard() {
        let mut last = 0;
        for i in 0..=1000 {
            let v = linear_to_srgb8(i as f32 / 1000.0);
            assert!(v >= last);
            last = v;
        }
        assert_eq!(linear_to_srgb8(0.0025), 8); // the linear toe: 12.92 * 0.0025 * 255 = 8.2
        assert_eq!(linear_to_srgb8(-3.0), 0);
        assert_eq!(linear_to_srgb8(7.0), 255);
        assert_eq!(linear_to_srgb8(f32::NAN), 0);
    }
}
