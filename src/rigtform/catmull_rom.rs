//! Catmull-Rom splines of rigid body transforms: [`RigTForm::catmull_rom`],
//! the translation by the cubic Catmull-Rom curve in R^3, the rotation by
//! [`Quat::catmull_rom`]'s construction.

use super::RigTForm;
use crate::quat::catmull_rom::{neighbours, place, Place};
use crate::quat::Quat;
use crate::vec::Cvec3;

impl RigTForm {
    /// The Catmull-Rom spline through the frames `keys`, key `i` at `t = i`:
    /// the rotation as [`Quat::catmull_rom`], the translation by the same
    /// construction in R^3. Between keys `c_i` and `c_{i+1}` the origin
    /// follows the cubic Bezier curve with inner control points
    /// `d_i+ = c_i + (c_{i+1} - c_{i-1}) / 6` and
    /// `d_{i+1}- = c_{i+1} - (c_{i+2} - c_i) / 6` (a missing neighbour at
    /// the first or last key is the key itself), evaluated by de
    /// Casteljau's algorithm with lerps. Position and velocity are
    /// continuous across the keys, where [`interpolate`](Self::interpolate)
    /// key to key changes velocity abruptly.
    ///
    /// At a whole `t` the result is that key, exactly; `t` outside
    /// `[0, keys.len() - 1]` is clamped; one key gives that key. Left
    /// invariant, up to rounding and the sign of the rotation, as
    /// [`interpolate`](Self::interpolate) is.
    ///
    /// # Preconditions
    ///
    /// Unit rotations. An empty slice gives [`RigTForm::IDENTITY`]; a NaN
    /// `t` gives NaN in every component, and so does a NaN or infinite
    /// component of a key used between two keys. No allocation, no panic,
    /// for any input bits.
    ///
    /// # Accuracy
    ///
    /// Rotation as [`Quat::catmull_rom`]. The translation is the cubic in
    /// R^3 to within a few roundings of the keys' magnitude
    /// (`tests/properties.rs` compares it with the Bernstein form in f64).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::{Cvec3, Quat, RigTForm};
    /// let keys = [
    ///     RigTForm::IDENTITY,
    ///     RigTForm::new(Cvec3::new(1.0, 0.0, 0.0), Quat::from_rotation_z(0.5)),
    ///     RigTForm::new(Cvec3::new(1.0, 1.0, 0.0), Quat::from_rotation_z(1.0)),
    /// ];
    /// assert_eq!(RigTForm::catmull_rom(&keys, 1.0), keys[1]);
    /// let mid = RigTForm::catmull_rom(&keys, 0.5);
    /// // Heading for the third key, the origin swings out below y = 0 first.
    /// assert!((mid.t.x - 0.5).abs() < 1e-6 && (mid.t.y + 1.0 / 16.0).abs() < 1e-6);
    /// assert_eq!(RigTForm::catmull_rom(&[], 0.5), RigTForm::IDENTITY);
    /// ```
    #[doc(alias = "spline")]
    #[must_use]
    pub fn catmull_rom(keys: &[RigTForm], t: f32) -> Self {
        let nan = Self::new(Cvec3::new(f32::NAN, f32::NAN, f32::NAN), Quat::NAN);
        match place(keys.len(), t) {
            Place::Empty => Self::IDENTITY,
            Place::Nan => nan,
            Place::Key(i) => keys.get(i).copied().unwrap_or(nan),
            Place::Between(i, u) => {
                let [before, from, to, after] = neighbours(keys, i, nan);
                Self::new(
                    cubic(before.t, from.t, to.t, after.t, u),
                    Quat::catmull_rom_segment(before.r, from.r, to.r, after.r, u),
                )
            }
        }
    }
}

/// The Catmull-Rom segment of translations from `from` to `to`, with
/// their neighbours, at `u`: the cubic Bezier curve of the control points
/// of [`RigTForm::catmull_rom`] by de Casteljau's algorithm.
fn cubic(before: Cvec3, from: Cvec3, to: Cvec3, after: Cvec3, u: f32) -> Cvec3 {
    let out_of_from = from + (to - before) / 6.0;
    let into_to = to - (after - from) / 6.0;
    let a = from.lerp(out_of_from, u);
    let b = out_of_from.lerp(into_to, u);
    let c = into_to.lerp(to, u);
    a.lerp(b, u).lerp(b.lerp(c, u), u)
}
