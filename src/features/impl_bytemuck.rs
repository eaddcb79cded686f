//! `bytemuck::Pod` and `bytemuck::Zeroable` (feature `bytemuck`) for
//! [`Cvec3`], [`Cvec4`], [`Quat`], [`RigTForm`], [`Matrix3`], [`Matrix4`],
//! [`Smoother`], [`FilterParams`], [`InertialCalibration`] and
//! [`MagneticCalibration`]: slices of them cast to bytes or to `f32`s
//! without a copy, for GPU uploads, wire formats and calibration blobs in
//! flash.
//!
//! Each type is `#[repr(C)]` and made only of `f32`s, so its bytes are its
//! components in field order, without padding: `Quat` is `x, y, z, w`
//! (scalar last, as glam's `Quat`, glTF and shaders), `RigTForm` is `t` then
//! `r` (7 floats), `Matrix3` and `Matrix4` are 9 and 16 floats, column-major.
//! [`OrientationFilter`](crate::attitude::OrientationFilter) and
//! [`Diagnostics`](crate::attitude::Diagnostics) are not `Pod`: they hold
//! `bool`s, as [`AxesAlignment`](crate::attitude::AxesAlignment) holds an
//! enum.
//!
//! # Safety, and the crate's `unsafe` rule
//!
//! The crate has no `unsafe` code of its own but the processor's square
//! root instruction and, on x86-64, the quaternion product in SSE
//! registers and the slice APIs' vector lanes.
//! The `unsafe impl`s of these two traits are written by bytemuck's
//! derive macros, which refuse to compile unless the type is `repr(C)`,
//! has no padding and has only `Pod` fields; the crate's `unsafe_code`
//! lint (`forbid`, or `deny` where those need `unsafe`) does not fire on
//! code that a derive macro generates.
//!
//! ```
//! use rigtform::{Cvec3, Matrix4, Quat};
//! let q = Quat::from_xyzw(1.0, 2.0, 3.0, 4.0);
//! let f: &[f32; 4] = bytemuck::cast_ref(&q);
//! assert_eq!(f, &[1.0, 2.0, 3.0, 4.0]);
//! assert_eq!(bytemuck::cast::<Quat, [f32; 4]>(Quat::IDENTITY), [0.0, 0.0, 0.0, 1.0]);
//! let points = [Cvec3::X, Cvec3::Y];
//! let bytes: &[u8] = bytemuck::cast_slice(&points);
//! assert_eq!(bytes.len(), 24);
//! let m: &[f32; 16] = bytemuck::cast_ref(&Matrix4::IDENTITY);
//! assert_eq!((m[0], m[1], m[5], m[15]), (1.0, 0.0, 1.0, 1.0));
//! ```

#[cfg(test)]
mod tests {
    use crate::attitude::{FilterParams, InertialCalibration, MagneticCalibration, Smoother};
    use crate::{Cvec3, Cvec4, Matrix3, Matrix4, Quat, RigTForm};

    /// The floats of one value, without a copy (fails to compile if `T`
    /// loses `Pod`).
    fn floats<T: bytemuck::Pod>(value: &T) -> &[f32] {
        bytemuck::cast_slice(core::slice::from_ref(value))
    }

    /// Fails to compile if a type loses `Zeroable`; its zeroed value has
    /// every bit clear.
    fn zeroed_bits<T: bytemuck::Pod>() -> bool {
        bytemuck::bytes_of(&T::zeroed()).iter().all(|&b| b == 0)
    }

    #[test]
    fn every_type_is_its_floats_in_field_order() {
        assert_eq!(floats(&Cvec3::new(1.0, 2.0, 3.0)), [1.0, 2.0, 3.0]);
        assert_eq!(
            floats(&Cvec4::new(1.0, 2.0, 3.0, 4.0)),
            [1.0, 2.0, 3.0, 4.0]
        );
        assert_eq!(
            floats(&Quat::from_wxyz(1.0, 2.0, 3.0, 4.0)),
            [2.0, 3.0, 4.0, 1.0]
        );
        let r = RigTForm::new(
            Cvec3::new(1.0, 2.0, 3.0),
            Quat::from_xyzw(4.0, 5.0, 6.0, 7.0),
        );
        assert_eq!(floats(&r), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
        let m = Matrix4::from_cols_array(&core::array::from_fn(|i| i as f32));
        let want: [f32; 16] = core::array::from_fn(|i| i as f32);
        assert_eq!(floats(&m), want, "column-major");
        let m3 = Matrix3::from_cols_array(&core::array::from_fn(|i| i as f32));
        let want: [f32; 9] = core::array::from_fn(|i| i as f32);
        assert_eq!(floats(&m3), want, "column-major");
        let s = Smoother::new(Quat::from_wxyz(1.0, 2.0, 3.0, 4.0), 5.0);
        assert_eq!(floats(&s), [2.0, 3.0, 4.0, 1.0, 5.0]);
        let p = FilterParams::DEFAULT;
        let f = floats(&p);
        assert_eq!((f[0], f[1]), (p.gravity, p.tau_acc));
        assert_eq!(f.len() * 4, core::mem::size_of::<FilterParams>());
        let mag = MagneticCalibration {
            hard_iron: Cvec3::new(12.0, -3.0, 40.0),
            ..MagneticCalibration::IDENTITY
        };
        let f = floats(&mag);
        assert_eq!(
            (f.len(), f[0], f[4], &f[9..]),
            (12, 1.0, 1.0, &[12.0, -3.0, 40.0][..])
        );
        let gyro = InertialCalibration::IDENTITY;
        assert_eq!(floats(&gyro).len(), 15);
    }

    #[test]
    fn every_type_is_zeroable() {
        assert!(zeroed_bits::<Cvec3>() && zeroed_bits::<Cvec4>() && zeroed_bits::<Quat>());
        assert!(zeroed_bits::<RigTForm>() && zeroed_bits::<Matrix3>() && zeroed_bits::<Matrix4>());
        assert!(zeroed_bits::<Smoother>() && zeroed_bits::<FilterParams>());
        assert!(zeroed_bits::<InertialCalibration>() && zeroed_bits::<MagneticCalibration>());
        let q: Quat = bytemuck::Zeroable::zeroed();
        assert_eq!(q, Quat::from_wxyz(0.0, 0.0, 0.0, 0.0));
    }

    /// Bytes written by one side (say, a GPU buffer or a radio packet) read
    /// back as the same values, whatever their alignment.
    #[test]
    fn bytes_read_back_unaligned() {
        let qs = [Quat::from_rotation_x(0.5), Quat::from_rotation_z(-2.0)];
        let mut buf = [0u8; 33];
        buf[1..].copy_from_slice(bytemuck::cast_slice(&qs));
        let back: Quat = bytemuck::pod_read_unaligned(&buf[17..]);
        assert_eq!(back, qs[1]);
    }
}
