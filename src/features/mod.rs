//! Optional integrations, one file each.

#[cfg(feature = "approx")]
mod impl_approx;
#[cfg(feature = "bytemuck")]
mod impl_bytemuck;
// Each glam version's module inside has its feature's cfg, which docs.rs
// shows as that feature's badge.
mod impl_glam;
#[cfg(feature = "mint")]
mod impl_mint;
#[cfg(feature = "nalgebra")]
mod impl_nalgebra;
#[cfg(feature = "serde")]
mod impl_serde;

#[cfg(all(test, feature = "defmt"))]
mod defmt_tests {
    use crate::{Cvec3, Cvec4, Matrix3, Matrix4, Quat, RigTForm};

    fn implements_format<T: defmt::Format>() {}

    /// Fails to compile if a public type loses its `defmt::Format`.
    #[test]
    fn every_public_type_implements_format() {
        implements_format::<Cvec3>();
        implements_format::<Cvec4>();
        implements_format::<Quat>();
        implements_format::<RigTForm>();
        implements_format::<Matrix3>();
        implements_format::<Matrix4>();
    }
}
