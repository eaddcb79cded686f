//! The sample layout of a pixel: how many samples it has and where they
//! lie. Rasterization tests coverage at these positions, and the
//! framebuffer keeps one colour and one depth per sample.

/// The sample pattern of each pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Msaa {
    /// One sample at the pixel centre.
    Off,
    /// Four samples in a rotated grid (the common 4x pattern), each pixel
    /// shaded once and its colour stored in the covered samples that pass
    /// the depth test.
    #[default]
    X4,
}

impl Msaa {
    /// Samples per pixel.
    ///
    /// ```
    /// use rigtform_render::Msaa;
    /// assert_eq!(Msaa::X4.samples(), 4);
    /// ```
    #[must_use]
    pub fn samples(self) -> usize {
        self.offsets().len()
    }

    /// Sample positions inside the pixel, in 1/256 pixel from its top-left
    /// corner (the subpixel unit of [`raster`](crate::raster)); sample `s`
    /// is entry `s`.
    ///
    /// ```
    /// use rigtform_render::Msaa;
    /// assert_eq!(Msaa::Off.offsets(), [(128, 128)]); // the pixel centre
    /// ```
    #[must_use]
    pub fn offsets(self) -> &'static [(i64, i64)] {
        match self {
            Msaa::Off => &[(128, 128)],
            // (3/8, 1/8), (7/8, 3/8), (1/8, 5/8), (5/8, 7/8).
            Msaa::X4 => &[(96, 32), (224, 96), (32, 160), (160, 224)],
        }
    }
}
