//! glam's free constructor functions (`vec3`, `vec4`, `quat`, `mat3`,
//! `mat4`), with which a glam user's first lines are written: here
//! deprecated, each naming the constructor of the crate's type.

use crate::matrix::{Matrix3, Matrix4};
use crate::other_names::renamed;
use crate::quat::Quat;
use crate::vec::{Cvec3, Cvec4};

/// Each glam function `name(args) -> T` as a deprecated function of the
/// same arguments that returns the crate's `T::constructor(args)`, its
/// example the two called with `example`'s arguments.
macro_rules! glam_constructors {
    ($(
        $name:ident($($arg:ident: $ty:ty),*) -> $t:ident::$new:ident, e.g. ($($ex:expr),*),
        note $note:literal;
    )*) => {
        $(
            renamed! {
                #[doc = concat!(
                    "glam's `", stringify!($name), "(", stringify!($($arg),*), ")`: here [`",
                    stringify!($t), "::", stringify!($new), "`]."
                )]
                ///
                /// ```
                /// # #![allow(deprecated)]
                /// use rigtform::*;
                #[doc = concat!(
                    "assert_eq!(", stringify!($name), "(", stringify!($($ex),*), "), ",
                    stringify!($t), "::", stringify!($new), "(", stringify!($($ex),*), "));"
                )]
                /// ```
                note $note;
                pub const fn $name($($arg: $ty),*) -> $t {
                    $t::$new($($arg),*)
                }
            }
        )*
    };
}

glam_constructors! {
    vec3(x: f32, y: f32, z: f32) -> Cvec3::new, e.g. (1.0, 2.0, 3.0),
        note "the notes' 3-vector is `Cvec3`: use `Cvec3::new(x, y, z)`";
    vec4(x: f32, y: f32, z: f32, w: f32) -> Cvec4::new, e.g. (1.0, 2.0, 3.0, 1.0),
        note "the notes' 4-vector is `Cvec4`: use `Cvec4::new(x, y, z, w)` (or `Cvec4::from_point(p)`)";
    quat(x: f32, y: f32, z: f32, w: f32) -> Quat::from_xyzw, e.g. (0.0, 0.0, 0.6, 0.8),
        note "use `Quat::from_xyzw(x, y, z, w)`, which names its order";
    mat3(x_axis: Cvec3, y_axis: Cvec3, z_axis: Cvec3) -> Matrix3::from_cols,
        e.g. (Cvec3::Y, -Cvec3::X, Cvec3::Z),
        note "use `Matrix3::from_cols(x_axis, y_axis, z_axis)`";
    mat4(x_axis: Cvec4, y_axis: Cvec4, z_axis: Cvec4, w_axis: Cvec4) -> Matrix4::from_cols,
        e.g. (Cvec4::X, Cvec4::Y, Cvec4::Z, Cvec4::new(1.0, 2.0, 3.0, 1.0)),
        note "use `Matrix4::from_cols(x_axis, y_axis, z_axis, w_axis)`";
}

#[cfg(test)]
#[allow(deprecated)]
mod tests {
    use super::*;

    /// Each builds what glam's function of that name builds, bit for bit.
    #[test]
    fn glams_free_constructors_build_what_glams_build() {
        let (x, y, z, w) = (1.5, -0.0, f32::NAN, 4.0);
        let bits = |a: &[f32]| a.iter().map(|v| v.to_bits()).collect::<std::vec::Vec<_>>();
        assert_eq!(
            bits(&vec3(x, y, z).to_array()),
            bits(&glam::vec3(x, y, z).to_array())
        );
        let v = vec4(x, y, z, w);
        assert_eq!(
            bits(&v.to_array()),
            bits(&glam::vec4(x, y, z, w).to_array())
        );
        assert_eq!(
            bits(&quat(x, y, z, w).to_array()),
            bits(&glam::quat(x, y, z, w).to_array())
        );
        let (a, b, c) = (vec3(x, y, z), vec3(w, x, y), vec3(z, w, x));
        let (ga, gb, gc) = (
            a.to_array().into(),
            b.to_array().into(),
            c.to_array().into(),
        );
        let theirs = glam::mat3(ga, gb, gc).to_cols_array();
        assert_eq!(bits(&mat3(a, b, c).to_cols_array()), bits(&theirs));
        let gv = glam::Vec4::from_array(v.to_array());
        let theirs = glam::mat4(gv, gv * 2.0, -gv, gv).to_cols_array();
        assert_eq!(
            bits(&mat4(v, v * 2.0, -v, v).to_cols_array()),
            bits(&theirs)
        );
    }
}
