//! `Display` for every public type: the components in brackets, in the
//! order of `to_array` (a quaternion scalar last, as glam prints it, a matrix column by
//! column), each printed with the formatter's options, so `{:.3}` gives
//! three decimals throughout.

use core::fmt::{self, Display, Formatter};

use crate::matrix::Matrix3;
use crate::matrix::Matrix4;
use crate::quat::{EulerRot, Quat};
use crate::rigtform::RigTForm;
use crate::vec::{Cvec3, Cvec4};

/// `[a, b, ...]`, each item with `f`'s width and precision.
fn list<T: Display>(f: &mut Formatter<'_>, items: &[T]) -> fmt::Result {
    f.write_str("[")?;
    for (i, c) in items.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        Display::fmt(c, f)?;
    }
    f.write_str("]")
}

impl Display for Cvec3 {
    /// `[x, y, z]`.
    ///
    /// ```
    /// assert_eq!(format!("{:.1}", rigtform::Cvec3::new(1.0, -2.0, 0.25)), "[1.0, -2.0, 0.2]");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        list(f, &self.to_array())
    }
}

impl Display for Cvec4 {
    /// `[x, y, z, w]`.
    ///
    /// ```
    /// let p = rigtform::Cvec4::new(1.0, 2.0, 3.0, 1.0);
    /// assert_eq!(p.to_string(), "[1, 2, 3, 1]");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        list(f, &self.to_array())
    }
}

impl Display for Quat {
    /// `[x, y, z, w]`, scalar last, as [`Quat::to_array`].
    ///
    /// ```
    /// let q = rigtform::Quat::from_wxyz(0.5, -0.5, 0.5, 0.25);
    /// assert_eq!(format!("{q:.2}"), "[-0.50, 0.50, 0.25, 0.50]");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        list(f, &self.to_array())
    }
}

impl Display for RigTForm {
    /// `{t: [x, y, z], r: [x, y, z, w]}`.
    ///
    /// ```
    /// use rigtform::{Cvec3, RigTForm};
    /// let a = RigTForm::from_translation(Cvec3::new(1.0, 2.0, 3.0));
    /// assert_eq!(a.to_string(), "{t: [1, 2, 3], r: [0, 0, 0, 1]}");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str("{t: ")?;
        Display::fmt(&self.t, f)?;
        f.write_str(", r: ")?;
        Display::fmt(&self.r, f)?;
        f.write_str("}")
    }
}

impl Display for Matrix4 {
    /// The four columns, `[[c0], [c1], [c2], [c3]]`, as glam prints its
    /// matrices (the translation is the last column).
    ///
    /// ```
    /// use rigtform::{Cvec3, Matrix4};
    /// let m = Matrix4::from_translation(Cvec3::new(7.0, 8.0, 9.0));
    /// assert_eq!(
    ///     m.to_string(),
    ///     "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [7, 8, 9, 1]]"
    /// );
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        list(f, &self.cols)
    }
}

impl Display for Matrix3 {
    /// The three columns, `[[c0], [c1], [c2]]`, as glam prints its
    /// matrices.
    ///
    /// ```
    /// use rigtform::Matrix3;
    /// assert_eq!(Matrix3::IDENTITY.to_string(), "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        list(f, &self.cols)
    }
}

impl Display for EulerRot {
    /// The name of the order, as in the source: `ZYX`.
    ///
    /// ```
    /// assert_eq!(rigtform::EulerRot::ZYX.to_string(), "ZYX");
    /// ```
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;

    #[test]
    fn every_type_prints_its_components_in_array_order_with_the_options() {
        assert_eq!(format!("{}", Cvec3::new(1.0, -2.5, 3.0)), "[1, -2.5, 3]");
        assert_eq!(
            format!("{:.1}", Cvec4::new(0.25, 1.0, 2.0, 1.0)),
            "[0.2, 1.0, 2.0, 1.0]"
        );
        assert_eq!(
            format!("{:.2}", Quat::from_wxyz(0.5, -0.5, 0.25, 0.5)),
            "[-0.50, 0.25, 0.50, 0.50]"
        );
        let a = RigTForm::new(Cvec3::new(1.0, 2.0, 3.0), Quat::IDENTITY);
        assert_eq!(format!("{a}"), "{t: [1, 2, 3], r: [0, 0, 0, 1]}");
        let m = Matrix4::from_translation(Cvec3::new(7.0, 8.0, 9.0));
        assert_eq!(
            format!("{m:.0}"),
            "[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [7, 8, 9, 1]]"
        );
        assert_eq!(format!("{}", EulerRot::YXZ), "YXZ");
    }
}
