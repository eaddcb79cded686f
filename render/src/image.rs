//! 8-bit sRGB images: what the framebuffer resolves to, what panels and
//! contact sheets are assembled from, and what the writers encode.

use font8x8::UnicodeFonts;

/// An RGB image, 8 bits per channel (sRGB), rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    width: u32,
    height: u32,
    pixels: Vec<[u8; 3]>,
}

/// Height in pixels of a line of [`Image::draw_text`] at scale 1.
pub const GLYPH_SIZE: u32 = 8;

impl Image {
    /// A `width x height` image filled with `color`.
    ///
    /// ```
    /// use rigtform_render::Image;
    /// let im = Image::new(3, 2, [10, 20, 30]);
    /// assert_eq!(im.pixel(2, 1), [10, 20, 30]);
    /// ```
    #[must_use]
    pub fn new(width: u32, height: u32, color: [u8; 3]) -> Self {
        Self {
            width,
            height,
            pixels: vec![color; width as usize * height as usize],
        }
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The pixels, row by row.
    #[must_use]
    pub fn pixels(&self) -> &[[u8; 3]] {
        &self.pixels
    }

    /// The pixels, row by row, to write.
    pub fn pixels_mut(&mut self) -> &mut [[u8; 3]] {
        &mut self.pixels
    }

    /// The pixels as packed RGB bytes.
    #[must_use]
    pub fn to_rgb_bytes(&self) -> Vec<u8> {
        self.pixels.iter().flatten().copied().collect()
    }

    /// Builds an image from packed RGB bytes; `None` when the length is not
    /// `3 * width * height`.
    #[must_use]
    pub fn from_rgb_bytes(width: u32, height: u32, bytes: &[u8]) -> Option<Self> {
        (bytes.len() == 3 * width as usize * height as usize).then(|| Self {
            width,
            height,
            pixels: bytes.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect(),
        })
    }

    /// The pixel at `(x, y)`.
    ///
    /// # Panics
    ///
    /// When `(x, y)` is outside the image (a caller's bug).
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Sets the pixel at `(x, y)`; does nothing outside the image.
    pub fn set_pixel(&mut self, x: i64, y: i64, color: [u8; 3]) {
        if x >= 0 && y >= 0 && x < i64::from(self.width) && y < i64::from(self.height) {
            self.pixels[y as usize * self.width as usize + x as usize] = color;
        }
    }

    /// Copies `other` with its top-left corner at `(x, y)`, clipped to this
    /// image.
    ///
    /// ```
    /// use rigtform_render::Image;
    /// let mut big = Image::new(4, 4, [0; 3]);
    /// big.blit(&Image::new(2, 2, [9; 3]), 3, 3); // only one pixel lands inside
    /// assert_eq!(big.pixels().iter().filter(|p| **p == [9; 3]).count(), 1);
    /// ```
    pub fn blit(&mut self, other: &Image, x: i64, y: i64) {
        for j in 0..other.height {
            for i in 0..other.width {
                self.set_pixel(x + i64::from(i), y + i64::from(j), other.pixel(i, j));
            }
        }
    }

    /// Fills the rectangle with top-left corner `(x, y)`, clipped to the
    /// image.
    pub fn fill_rect(&mut self, x: i64, y: i64, w: u32, h: u32, color: [u8; 3]) {
        for j in 0..i64::from(h) {
            for i in 0..i64::from(w) {
                self.set_pixel(x + i, y + j, color);
            }
        }
    }

    /// Draws `text` in the public-domain 8x8 font of the `font8x8` crate,
    /// each font pixel a `scale x scale` square, its top-left corner at
    /// `(x, y)`. Characters the font lacks are drawn as blanks.
    ///
    /// ```
    /// use rigtform_render::Image;
    /// let mut im = Image::new(Image::text_width("Hi", 2), 16, [0; 3]);
    /// im.draw_text(0, 0, "Hi", 2, [255; 3]);
    /// assert!(im.pixels().contains(&[255; 3]));
    /// ```
    pub fn draw_text(&mut self, x: i64, y: i64, text: &str, scale: u32, color: [u8; 3]) {
        let s = i64::from(scale.max(1));
        for (n, ch) in text.chars().enumerate() {
            let glyph = font8x8::BASIC_FONTS.get(ch).unwrap_or([0; 8]);
            let left = x + n as i64 * 8 * s;
            for (row, bits) in glyph.iter().enumerate() {
                for col in 0..8 {
                    if bits & (1 << col) != 0 {
                        self.fill_rect(
                            left + col * s,
                            y + row as i64 * s,
                            s as u32,
                            s as u32,
                            color,
                        );
                    }
                }
            }
        }
    }

    /// Width in pixels of `text` drawn at `scale`.
    #[must_use]
    pub fn text_width(text: &str, scale: u32) -> u32 {
        text.chars().count() as u32 * 8 * scale.max(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blit_is_clipped_to_the_image() {
        let mut a = Image::new(4, 4, [0; 3]);
        a.blit(&Image::new(3, 3, [9; 3]), 2, -1);
        assert_eq!(a.pixel(3, 1), [9; 3]);
        assert_eq!(a.pixel(1, 1), [0; 3]);
        assert_eq!(a.pixel(2, 2), [0; 3]);
    }

    #[test]
    fn text_draws_the_glyphs() {
        let mut a = Image::new(16, 8, [0; 3]);
        a.draw_text(0, 0, "I ", 1, [255; 3]);
        let lit = |x0: u32, x1: u32| {
            (x0..x1)
                .flat_map(|x| (0..8).map(move |y| (x, y)))
                .filter(|&(x, y)| a.pixel(x, y) == [255; 3])
                .count()
        };
        assert!(lit(0, 8) > 8, "the I is drawn");
        assert_eq!(lit(8, 16), 0, "the space is blank");
    }

    #[test]
    fn fill_rect_covers_exactly_its_rectangle() {
        let mut a = Image::new(6, 5, [0; 3]);
        a.fill_rect(1, 2, 3, 2, [7; 3]);
        for y in 0..5 {
            for x in 0..6 {
                let inside = (1..4).contains(&x) && (2..4).contains(&y);
                assert_eq!(a.pixel(x, y) == [7; 3], inside, "({x}, {y})");
            }
        }
    }

    #[test]
    fn scaled_text_is_scaled_glyphs_side_by_side() {
        let glyphs = |text: &str, scale: u32| {
            let mut im = Image::new(Image::text_width(text, scale), GLYPH_SIZE * scale, [0; 3]);
            im.draw_text(0, 0, text, scale, [255; 3]);
            im
        };
        assert_eq!(Image::text_width("abc", 3), 72);
        let (one, three) = (glyphs("T7", 1), glyphs("T7", 3));
        for y in 0..3 * GLYPH_SIZE {
            for x in 0..Image::text_width("T7", 3) {
                assert_eq!(three.pixel(x, y), one.pixel(x / 3, y / 3), "({x}, {y})");
            }
        }
        // Drawn at an offset, the same pixels move with it.
        let mut shifted = Image::new(40, 30, [0; 3]);
        shifted.draw_text(5, 4, "T7", 2, [255; 3]);
        let two = glyphs("T7", 2);
        for y in 0..2 * GLYPH_SIZE {
            for x in 0..Image::text_width("T7", 2) {
                assert_eq!(shifted.pixel(x + 5, y + 4), two.pixel(x, y));
            }
        }
    }

    #[test]
    fn rgb_bytes_round_trip() {
        let mut a = Image::new(2, 1, [1, 2, 3]);
        a.set_pixel(1, 0, [4, 5, 6]);
        let bytes = a.to_rgb_bytes();
        assert_eq!(bytes, [1, 2, 3, 4, 5, 6]);
        assert_eq!(Image::from_rgb_bytes(2, 1, &bytes), Some(a));
        assert_eq!(Image::from_rgb_bytes(2, 2, &bytes), None);
    }
}
