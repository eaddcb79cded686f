//! `approx`'s [`AbsDiffEq`], [`RelativeEq`] and [`UlpsEq`] (feature
//! `approx`) for [`Cvec3`], [`Cvec4`], [`Quat`], [`RigTForm`] and
//! [`Matrix4`], component by component as glam does, with `f32`
//! tolerances and `f32`'s defaults (`f32::EPSILON`, 4 ulps). Two values are
//! equal when every pair of components is.
//!
//! For rotations this is the wrong question: `q` and `-q` are the same
//! rotation, yet no component-wise tolerance calls them equal. Compare
//! rotations by their angle, with [`Quat::angle_to`] (for a [`RigTForm`],
//! its `t` with these traits and its `r` with `angle_to`).
//!
//! ```
//! use approx::assert_relative_eq;
//! use rigtform::{Cvec3, Quat};
//! let v = Quat::from_rotation_z(core::f32::consts::FRAC_PI_2) * Cvec3::X;
//! assert_relative_eq!(v, Cvec3::Y, epsilon = 1e-6);
//!
//! let q = Quat::from_rotation_x(0.5);
//! assert!(approx::abs_diff_ne!(q, -q)); // components differ...
//! assert!(q.angle_to(-q) < 1e-6); // ...but the rotation is the same
//! ```

use crate::{Cvec3, Cvec4, Matrix3, Matrix4, Quat, RigTForm};
use approx::{AbsDiffEq, RelativeEq, UlpsEq};

/// The components of each type, in field order, as `approx` compares them.
trait Components {
    /// The array of components.
    type Array: AsRef<[f32]>;
    /// The components in field order.
    fn components(&self) -> Self::Array;
}

impl Components for Cvec3 {
    type Array = [f32; 3];
    fn components(&self) -> [f32; 3] {
        self.to_array()
    }
}

impl Components for Cvec4 {
    type Array = [f32; 4];
    fn components(&self) -> [f32; 4] {
        self.to_array()
    }
}

impl Components for Quat {
    type Array = [f32; 4];
    fn components(&self) -> [f32; 4] {
        self.to_array()
    }
}

impl Components for RigTForm {
    type Array = [f32; 7];
    fn components(&self) -> [f32; 7] {
        let ([x, y, z], [i, j, k, w]) = (self.t.to_array(), self.r.to_array());
        [x, y, z, i, j, k, w]
    }
}

impl Components for Matrix3 {
    type Array = [f32; 9];
    fn components(&self) -> [f32; 9] {
        self.to_cols_array()
    }
}

impl Components for Matrix4 {
    type Array = [f32; 16];
    fn components(&self) -> [f32; 16] {
        self.to_cols_array()
    }
}

/// Whether `pred` holds for every pair of components of `a` and `b`.
fn all_pairs<T: Components>(a: &T, b: &T, pred: impl Fn(&f32, &f32) -> bool) -> bool {
    let (a, b) = (a.components(), b.components());
    a.as_ref().iter().zip(b.as_ref()).all(|(x, y)| pred(x, y))
}

macro_rules! impl_approx {
    ($($t:ty),*) => {$(
        impl AbsDiffEq for $t {
            type Epsilon = f32;

            fn default_epsilon() -> f32 {
                f32::default_epsilon()
            }

            fn abs_diff_eq(&self, other: &Self, epsilon: f32) -> bool {
                all_pairs(self, other, |a, b| a.abs_diff_eq(b, epsilon))
            }
        }

        impl RelativeEq for $t {
            fn default_max_relative() -> f32 {
                f32::default_max_relative()
            }

            fn relative_eq(&self, other: &Self, epsilon: f32, max_relative: f32) -> bool {
                all_pairs(self, other, |a, b| a.relative_eq(b, epsilon, max_relative))
            }
        }

        impl UlpsEq for $t {
            fn default_max_ulps() -> u32 {
                f32::default_max_ulps()
            }

            fn ulps_eq(&self, other: &Self, epsilon: f32, max_ulps: u32) -> bool {
                all_pairs(self, other, |a, b| a.ulps_eq(b, epsilon, max_ulps))
            }
        }
    )*};
}

impl_approx!(Cvec3, Cvec4, Quat, RigTForm, Matrix3, Matrix4);

#[cfg(test)]
mod tests {
    use super::*;
    use approx::{AbsDiffEq, RelativeEq, UlpsEq};

    /// `v` with component `k` moved by `d`; `make` builds a `T` from its
    /// components.
    fn nudged<T: Components>(v: &T, k: usize, d: f32, make: fn(&[f32]) -> T) -> T {
        let c = v.components();
        let mut a = [0.0f32; 16];
        let n = c.as_ref().len();
        a[..n].copy_from_slice(c.as_ref());
        a[k] += d;
        make(&a[..n])
    }

    fn every_component_counts<T>(v: T, make: fn(&[f32]) -> T)
    where
        T: Components + Copy + RelativeEq + UlpsEq<Epsilon = f32> + core::fmt::Debug,
    {
        let n = v.components().as_ref().len();
        assert!(v.abs_diff_eq(&v, 0.0) && v.relative_eq(&v, 0.0, 0.0) && v.ulps_eq(&v, 0.0, 0));
        for k in 0..n {
            let w = nudged(&v, k, 1e-3, make);
            assert!(v.abs_diff_eq(&w, 2e-3), "{v:?} {w:?}");
            assert!(
                !v.abs_diff_eq(&w, 5e-4),
                "component {k} of {v:?} is compared"
            );
            assert!(v.relative_eq(&w, 0.0, 1.0) && !v.relative_eq(&w, 0.0, 1e-6));
            assert!(!v.ulps_eq(&w, 0.0, 4), "component {k} of {v:?} is compared");
        }
    }

    /// Every component of every type takes part in each comparison, and
    /// each tolerance is the one passed.
    #[test]
    fn every_component_of_every_type_is_compared() {
        every_component_counts(Cvec3::new(1.0, -2.0, 3.0), |a| Cvec3::new(a[0], a[1], a[2]));
        every_component_counts(Cvec4::new(1.0, -2.0, 3.0, 0.5), |a| {
            Cvec4::new(a[0], a[1], a[2], a[3])
        });
        every_component_counts(Quat::from_xyzw(0.5, -0.5, 0.5, 0.5), |a| {
            Quat::from_array([a[0], a[1], a[2], a[3]])
        });
        every_component_counts(
            RigTForm::new(
                Cvec3::new(1.0, 2.0, 3.0),
                Quat::from_wxyz(0.5, -0.5, 0.5, 0.5),
            ),
            |a| {
                RigTForm::new(
                    Cvec3::new(a[0], a[1], a[2]),
                    Quat::from_xyzw(a[3], a[4], a[5], a[6]),
                )
            },
        );
        every_component_counts(
            Matrix3::from_cols_array(&core::array::from_fn(|i| 1.0 + i as f32)),
            |a| Matrix3::from_cols_array(&core::array::from_fn(|i| a[i])),
        );
        every_component_counts(
            Matrix4::from_cols_array(&core::array::from_fn(|i| 1.0 + i as f32)),
            |a| Matrix4::from_cols_array(&core::array::from_fn(|i| a[i])),
        );
    }

    #[test]
    fn defaults_are_those_of_f32() {
        let one_ulp = f32::from_bits(1.0f32.to_bits() + 1);
        let a = Cvec3::new(1.0, 1.0, 1.0);
        let b = Cvec3::new(1.0, one_ulp, 1.0);
        approx::assert_ulps_eq!(a, b);
        approx::assert_relative_eq!(a, b);
        approx::assert_abs_diff_eq!(a, b);
        assert_eq!(Quat::default_epsilon(), f32::EPSILON);
        assert_eq!(Matrix4::default_max_ulps(), 4);
        assert!(approx::abs_diff_ne!(a, Cvec3::new(1.0, 1.0 + 1e-5, 1.0)));
    }

    /// NaN equals nothing, itself included, as for `f32`.
    #[test]
    fn nan_is_never_equal() {
        assert!(approx::relative_ne!(Quat::NAN, Quat::NAN));
        assert!(approx::ulps_ne!(Cvec4::NAN, Cvec4::NAN));
    }
}
