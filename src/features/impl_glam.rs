//! Conversions to and from [glam](https://docs.rs/glam), one feature per
//! glam version, as nalgebra's `convert-glam0xx` features: `From` both ways
//! for [`Quat`] (`glam::Quat`), [`Cvec3`] (`glam::Vec3` and `glam::Vec3A`),
//! [`Cvec4`] (`glam::Vec4`), [`Matrix3`] (`glam::Mat3`) and [`Matrix4`]
//! (`glam::Mat4`), each exact, component by component; and [`RigTForm`] to
//! `glam::Affine3A`, and back from it or a `glam::Mat4` with `TryFrom`,
//! which checks that the map is rigid.
//!
//! | feature | glam | used by | Rust |
//! | --- | --- | --- | --- |
//! | `convert-glam030` | 0.30 | Bevy 0.17, 0.18 | 1.84 |
//! | `convert-glam032` | 0.32 | Bevy 0.19 | 1.84 |
//! | `convert-glam033` | 0.33 | Bevy 0.20 | 1.84 |
//! | `convert-glam034` (also `glam`) | 0.34 | | 1.85 |
//!
//! The conversions are written once, in the macro `glam_conversions!`, and
//! instanced for each version in a module of its own; each instance has its
//! own bit-exact round-trip tests against its glam.
//!
//! Both crates keep a quaternion as `x, y, z, w` and a matrix column by
//! column, so the conversions move components, never reorder them.
#![cfg_attr(
    feature = "convert-glam034",
    doc = r#"
With glam 0.34 (the other versions read the same):

```
use rigtform::{Cvec3, Quat, RigTForm};
let q = Quat::from_rotation_z(0.5);
let g: glam::Quat = q.into();
assert_eq!(g, glam::Quat::from_rotation_z(0.5));
assert_eq!(Quat::from(g), q);
let v: glam::Vec3 = (q * Cvec3::X).into();
assert!((v - g * glam::Vec3::X).length() < 1e-6);

let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), q);
let affine: glam::Affine3A = a.into();
let back = RigTForm::try_from(affine).unwrap();
assert_eq!(back.t, a.t);
assert!(back.r.angle_to(a.r) < 1e-6);
```
"#
)]

/// The conversions between the crate's types and those of the glam crate
/// named `$glam` (a dependency renamed per version: `glam030`, `glam032`,
/// `glam033`; 0.34 is `glam`), with
/// their tests; instanced once per glam version, each in its own module.
#[allow(unused_macros)] // without a glam feature
macro_rules! glam_conversions {
    ($glam:ident) => {
        use ::$glam as glam;

        use crate::{Cvec3, Cvec4, Matrix3, Matrix4, NotRigid, Quat, RigTForm};

        impl From<glam::Quat> for Quat {
            /// Component by component, exact.
            #[inline]
            fn from(q: glam::Quat) -> Self {
                Self::from_xyzw(q.x, q.y, q.z, q.w)
            }
        }

        impl From<Quat> for glam::Quat {
            /// Component by component, exact (no normalization).
            #[inline]
            fn from(q: Quat) -> Self {
                glam::Quat::from_xyzw(q.x, q.y, q.z, q.w)
            }
        }

        impl From<glam::Vec3> for Cvec3 {
            #[inline]
            fn from(v: glam::Vec3) -> Self {
                Self::new(v.x, v.y, v.z)
            }
        }

        impl From<Cvec3> for glam::Vec3 {
            #[inline]
            fn from(v: Cvec3) -> Self {
                glam::Vec3::new(v.x, v.y, v.z)
            }
        }

        impl From<glam::Vec3A> for Cvec3 {
            #[inline]
            fn from(v: glam::Vec3A) -> Self {
                Self::new(v.x, v.y, v.z)
            }
        }

        impl From<Cvec3> for glam::Vec3A {
            #[inline]
            fn from(v: Cvec3) -> Self {
                glam::Vec3A::new(v.x, v.y, v.z)
            }
        }

        impl From<glam::Vec4> for Cvec4 {
            #[inline]
            fn from(v: glam::Vec4) -> Self {
                Self::new(v.x, v.y, v.z, v.w)
            }
        }

        impl From<Cvec4> for glam::Vec4 {
            #[inline]
            fn from(v: Cvec4) -> Self {
                glam::Vec4::new(v.x, v.y, v.z, v.w)
            }
        }

        impl From<glam::Mat4> for Matrix4 {
            /// Column by column, exact.
            #[inline]
            fn from(m: glam::Mat4) -> Self {
                Self::from_cols_array(&m.to_cols_array())
            }
        }

        impl From<Matrix4> for glam::Mat4 {
            /// Column by column, exact.
            #[inline]
            fn from(m: Matrix4) -> Self {
                glam::Mat4::from_cols_array(&m.to_cols_array())
            }
        }

        impl From<glam::Mat3> for Matrix3 {
            /// Column by column, exact.
            #[inline]
            fn from(m: glam::Mat3) -> Self {
                Self::from_cols_array(&m.to_cols_array())
            }
        }

        impl From<Matrix3> for glam::Mat3 {
            /// Column by column, exact.
            #[inline]
            fn from(m: Matrix3) -> Self {
                glam::Mat3::from_cols_array(&m.to_cols_array())
            }
        }

        impl From<RigTForm> for glam::Affine3A {
            /// `x -> r x + t`, glam's `Affine3A::from_rotation_translation`: the
            /// rotation becomes a matrix (glam's formula), the translation is
            /// copied exactly.
            ///
            /// # Preconditions
            ///
            /// `a.r` is a unit quaternion.
            #[inline]
            fn from(a: RigTForm) -> Self {
                glam::Affine3A::from_rotation_translation(a.r.into(), a.t.into())
            }
        }

        impl TryFrom<glam::Affine3A> for RigTForm {
            type Error = NotRigid;

            /// The rigid body transform of an affine map whose 3x3 part is a
            /// rotation, as [`RigTForm::try_from`] a [`Matrix4`] takes it: columns
            /// orthonormal within
            /// [`accuracy::RIGID_TOLERANCE`](crate::accuracy::RIGID_TOLERANCE),
            /// determinant positive, else [`NotRigid`]. The translation is copied
            /// exactly; the rotation is [`Quat::from_matrix`]'s, within
            /// [`accuracy::FROM_MATRIX_MAX_ANGLE_ERROR`](crate::accuracy::FROM_MATRIX_MAX_ANGLE_ERROR).
            ///
            fn try_from(a: glam::Affine3A) -> Result<Self, NotRigid> {
                RigTForm::try_from(Matrix4::from(glam::Mat4::from(a)))
            }
        }

        impl TryFrom<glam::Mat4> for RigTForm {
            type Error = NotRigid;

            /// The rigid body transform of a matrix that holds one (a Bevy
            /// `GlobalTransform`'s matrix without scale, a view's inverse),
            /// as [`RigTForm::try_from`] a [`Matrix4`]: [`NotRigid`] for a
            /// scale, a shear, a mirror or a projection (glam's
            /// `Affine3A::from_mat4` keeps those; a `RigTForm` cannot).
            fn try_from(m: glam::Mat4) -> Result<Self, NotRigid> {
                RigTForm::try_from(Matrix4::from(m))
            }
        }

        #[cfg(test)]
        mod tests {
            use super::*;
            use rand::{Rng, SeedableRng};

            fn bits<const N: usize>(a: [f32; N]) -> [u32; N] {
                a.map(f32::to_bits)
            }

            use crate::test_draws::unit_quat as random_quat;

            /// The three spellings that turned rotations the wrong way while the
            /// crate kept `w` first: each now gives glam's rotation, bit for bit.
            #[test]
            fn arrays_casts_and_conversions_mean_what_they_mean_in_glam() {
                let g = glam::Quat::from_rotation_z(0.5);
                let from_array = Quat::from_array(g.to_array());
                let back_from_array: glam::Quat = glam::Quat::from_array(from_array.into());
                assert_eq!(bits(back_from_array.to_array()), bits(g.to_array()));
                assert_eq!(from_array, Quat::from(g));
                assert!(from_array.angle_to(Quat::from_rotation_z(0.5)) < 1e-6);
                let (x, y, z, w) = g.into();
                assert_eq!(Quat::from((x, y, z, w)), from_array);
                assert_eq!(<(f32, f32, f32, f32)>::from(from_array), (x, y, z, w));
                #[cfg(feature = "bytemuck")]
                {
                    let cast: Quat = bytemuck::cast(g.to_array());
                    assert_eq!(cast, from_array);
                    let slice: &[f32] = bytemuck::cast_slice(core::slice::from_ref(&from_array));
                    assert_eq!(slice, &g.to_array());
                }
            }

            #[test]
            fn round_trips_are_exact() {
                let mut rng = rand::rngs::StdRng::seed_from_u64(23);
                for _ in 0..10_000 {
                    // Any bits, NaN payloads and infinities included.
                    let c: [f32; 16] = core::array::from_fn(|_| f32::from_bits(rng.random()));
                    let (c3, c4): ([f32; 3], [f32; 4]) = (
                        core::array::from_fn(|i| c[i + 4]),
                        core::array::from_fn(|i| c[i]),
                    );
                    let c9: [f32; 9] = core::array::from_fn(|i| c[i + 7]);
                    // Each way, every component lands in the field of its
                    // name (both crates' arrays are x, y, z, w and column
                    // by column) ...
                    let q = Quat::from_array(c4);
                    assert_eq!(bits(glam::Quat::from(q).to_array()), bits(c4));
                    assert_eq!(
                        bits(Quat::from(glam::Quat::from_array(c4)).to_array()),
                        bits(c4)
                    );
                    let v = Cvec3::from(c3);
                    assert_eq!(bits(glam::Vec3::from(v).to_array()), bits(c3));
                    assert_eq!(bits(glam::Vec3A::from(v).to_array()), bits(c3));
                    assert_eq!(
                        bits(Cvec3::from(glam::Vec3::from_array(c3)).to_array()),
                        bits(c3)
                    );
                    assert_eq!(
                        bits(Cvec3::from(glam::Vec3A::from_array(c3)).to_array()),
                        bits(c3)
                    );
                    let p = Cvec4::from(c4);
                    assert_eq!(bits(glam::Vec4::from(p).to_array()), bits(c4));
                    assert_eq!(
                        bits(Cvec4::from(glam::Vec4::from_array(c4)).to_array()),
                        bits(c4)
                    );
                    let m = Matrix4::from_cols_array(&c);
                    assert_eq!(bits(glam::Mat4::from(m).to_cols_array()), bits(c));
                    let gm = glam::Mat4::from_cols_array(&c);
                    assert_eq!(bits(Matrix4::from(gm).to_cols_array()), bits(c));
                    let m3 = Matrix3::from_cols_array(&c9);
                    assert_eq!(bits(glam::Mat3::from(m3).to_cols_array()), bits(c9));
                    let gm3 = glam::Mat3::from_cols_array(&c9);
                    assert_eq!(bits(Matrix3::from(gm3).to_cols_array()), bits(c9));
                    // ... so there and back is the identity, bit for bit.
                    assert_eq!(bits(Quat::from(glam::Quat::from(q)).to_array()), bits(c4));
                    assert_eq!(bits(Cvec3::from(glam::Vec3::from(v)).to_array()), bits(c3));
                    assert_eq!(bits(Cvec3::from(glam::Vec3A::from(v)).to_array()), bits(c3));
                    assert_eq!(bits(Cvec4::from(glam::Vec4::from(p)).to_array()), bits(c4));
                    assert_eq!(
                        bits(Matrix4::from(glam::Mat4::from(m)).to_cols_array()),
                        bits(c)
                    );
                    assert_eq!(
                        bits(Matrix3::from(glam::Mat3::from(m3)).to_cols_array()),
                        bits(c9)
                    );
                }
            }

            /// Every operation both crates name gives the same result.
            #[test]
            fn shared_operations_agree_with_glam() {
                let mut rng = rand::rngs::StdRng::seed_from_u64(24);
                for _ in 0..10_000 {
                    let (a, b) = (random_quat(&mut rng), random_quat(&mut rng));
                    let (ga, gb) = (glam::Quat::from(a), glam::Quat::from(b));
                    let v = Cvec3::new(
                        rng.random_range(-10.0..10.0),
                        rng.random_range(-10.0..10.0),
                        rng.random_range(-10.0..10.0),
                    );
                    let gv = glam::Vec3::from(v);
                    assert!(Quat::from(ga * gb).angle_to(a * b) < 1e-6);
                    assert!((Cvec3::from(ga * gv) - a * v).norm() < 1e-5 * (1.0 + v.norm()));
                    assert!(Quat::from(ga.inverse()).angle_to(a.inv()) < 1e-6);
                    assert!((ga.dot(gb) - a.dot(b)).abs() < 1e-6);
                    let m = Matrix4::from(glam::Mat4::from_quat(ga));
                    let ours = Matrix4::from_quat(a).to_cols_array();
                    for (x, y) in m.to_cols_array().iter().zip(ours) {
                        assert!((x - y).abs() < 1e-6);
                    }
                    let t = rng.random_range(0.0..1.0);
                    // glam's slerp takes the short way too.
                    assert!(Quat::from(ga.slerp(gb, t)).angle_to(a.slerp(b, t)) < 1e-5);
                    for axis in [Cvec3::X, Cvec3::Y, Cvec3::Z] {
                        let angle = rng.random_range(-4.0..4.0);
                        let ours = Quat::from_axis_angle(axis, angle);
                        let theirs = glam::Quat::from_axis_angle(axis.into(), angle);
                        assert!(ours.angle_to(theirs.into()) < 1e-6);
                    }
                }
            }

            #[test]
            fn rig_tforms_go_to_affine_maps_and_back() {
                let mut rng = rand::rngs::StdRng::seed_from_u64(25);
                for _ in 0..10_000 {
                    let t = Cvec3::new(
                        rng.random_range(-100.0..100.0),
                        rng.random_range(-100.0..100.0),
                        rng.random_range(-100.0..100.0),
                    );
                    let a = RigTForm::new(t, random_quat(&mut rng));
                    let affine = glam::Affine3A::from(a);
                    let p = Cvec3::new(1.0, -2.0, 0.5);
                    let mapped = Cvec3::from(affine.transform_point3(p.into()));
                    assert!((mapped - a.transform_point(p)).norm() < 1e-4);
                    let back = RigTForm::try_from(affine).unwrap();
                    assert_eq!(bits(back.t.to_array()), bits(t.to_array()));
                    assert!(back.r.angle_to(a.r) < 1e-6);
                    let m = glam::Mat4::from_rotation_translation(a.r.into(), a.t.into());
                    assert_eq!(RigTForm::try_from(m), RigTForm::try_from(Matrix4::from(m)));
                    assert!(RigTForm::try_from(m).unwrap().r.angle_to(a.r) < 1e-6);
                }
            }

            #[test]
            fn affine_maps_that_are_not_rigid_are_refused() {
                let cases = [
                    glam::Affine3A::from_scale(glam::Vec3::new(1.0, 1.0, 1.01)),
                    glam::Affine3A::from_scale(glam::Vec3::new(1.0, 1.0, -1.0)),
                    glam::Affine3A::from_cols_array(&[
                        1.0, 0.0, 0.0, 0.1, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,
                    ]),
                    glam::Affine3A::from_cols_array(&[f32::NAN; 12]),
                    glam::Affine3A::ZERO,
                ];
                for affine in cases {
                    let e = RigTForm::try_from(affine).unwrap_err();
                    assert!(
                        e.deviation.is_nan() || e.deviation > crate::accuracy::RIGID_TOLERANCE,
                        "{affine:?}"
                    );
                    assert!(std::format!("{e}").starts_with("not a rigid body transform"));
                    let from_mat4 = RigTForm::try_from(glam::Mat4::from(affine)).unwrap_err();
                    assert_eq!(from_mat4.deviation.to_bits(), e.deviation.to_bits());
                }
                let mut projective = glam::Mat4::IDENTITY;
                projective.z_axis.w = -1.0;
                assert!(RigTForm::try_from(projective).is_err());
            }
        }
    };
}

/// glam 0.30 (`convert-glam030`): Bevy 0.17 and 0.18.
#[cfg(feature = "convert-glam030")]
mod glam030 {
    glam_conversions!(glam030);
}

/// glam 0.32 (`convert-glam032`): Bevy 0.19.
#[cfg(feature = "convert-glam032")]
mod glam032 {
    glam_conversions!(glam032);
}

/// glam 0.33 (`convert-glam033`): Bevy 0.20.
#[cfg(feature = "convert-glam033")]
mod glam033 {
    glam_conversions!(glam033);
}

/// glam 0.34 (`convert-glam034`, or `glam`).
#[cfg(feature = "convert-glam034")]
mod glam034 {
    glam_conversions!(glam);
}
