//! Catmull-Rom splines of rotations: [`Quat::catmull_rom`], a curve
//! through any number of keyframes whose angular velocity does not jump at
//! the keys, as slerping key to key does. The construction is the one the
//! CS175 course builds from the notes' power operator: between two keys a
//! cubic Bezier curve, its inner control points from the neighbouring
//! keys, evaluated by de Casteljau's algorithm with slerp in place of lerp.
//!
//! Also where `t` falls among the keys ([`place`], [`neighbours`]), which
//! `RigTForm::catmull_rom` shares.

use super::Quat;

/// One sixth: the exponent of the power operator in the control points
/// (a cubic Bezier's end tangent is three times its first leg, and the
/// Catmull-Rom tangent is half the turn from the key before to the key
/// after).
const SIXTH: f32 = 1.0 / 6.0;

/// Where a parameter `t` falls among `n` keys, key `i` at `t = i`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Place {
    /// There are no keys.
    Empty,
    /// `t` is NaN.
    Nan,
    /// At key `i`: a whole `t`, or `t` outside `[0, n - 1]` (clamped).
    Key(usize),
    /// Strictly between keys `i` and `i + 1`, at `u` in (0, 1].
    Between(usize, f32),
}

/// Where `t` falls among `n` keys. Never panics: every comparison is false
/// for NaN (caught first), and float-to-integer casts saturate.
pub(crate) fn place(n: usize, t: f32) -> Place {
    let Some(last) = n.checked_sub(1) else {
        return Place::Empty;
    };
    if t.is_nan() {
        return Place::Nan;
    }
    if t <= 0.0 {
        return Place::Key(0);
    }
    if t >= last as f32 {
        return Place::Key(last);
    }
    // 0 < t < last, so last >= 1. The minimum only matters where `last`
    // rounds up as an f32 (more than 2^24 keys).
    let i = (t as usize).min(last - 1);
    let u = t - i as f32;
    // Written to be true for u <= 0, which rounding of a huge i can give.
    if u > 0.0 {
        Place::Between(i, u.min(1.0))
    } else {
        Place::Key(i)
    }
}

/// The keys `i - 1`, `i`, `i + 1` and `i + 2` of a segment that starts at
/// key `i`, a missing neighbour (before the first or after the last key)
/// being the key itself. `i + 1` must be a key; for any other `i` the
/// result is `[fallback; 4]`-like, never a panic.
pub(crate) fn neighbours<T: Copy>(keys: &[T], i: usize, fallback: T) -> [T; 4] {
    let last = keys.len().saturating_sub(1);
    let at = |j: usize| keys.get(j.min(last)).copied().unwrap_or(fallback);
    [
        at(i.saturating_sub(1)),
        at(i),
        at(i.saturating_add(1)),
        at(i.saturating_add(2)),
    ]
}

impl Quat {
    /// The Catmull-Rom spline through the rotations `keys`, key `i` at
    /// `t = i`: a curve that passes through every key and whose angular
    /// velocity is continuous across them (slerping key to key, by
    /// contrast, turns at a constant rate between two keys and changes
    /// rate and axis abruptly at each).
    ///
    /// Between keys `c_i` and `c_{i+1}` it is a cubic Bezier curve of
    /// rotations with the inner control points
    ///
    /// - `d_i+ = cn(c_{i+1} c_{i-1}^-1)^(1/6) c_i`,
    /// - `d_{i+1}- = cn(c_{i+2} c_i^-1)^(-1/6) c_{i+1}`,
    ///
    /// (the notes' power operator after conditional negation, so that every
    /// step takes the short way; a missing neighbour at the first or last
    /// key is the key itself), evaluated by de Casteljau's algorithm with
    /// [`slerp`](Self::slerp) in place of lerp: three slerps, then two, then
    /// one. The result is normalized.
    ///
    /// - At a whole `t` the result is that key, exactly (as stored).
    /// - `t` below 0 gives the first key, above `keys.len() - 1` the last.
    /// - One key gives that key for every `t` but NaN.
    /// - Keys stored as `q` or `-q` give the same rotations (each step
    ///   takes the short way); the sign of the result may differ.
    /// - Left invariant: `catmull_rom(w * keys, t) == w * catmull_rom(keys, t)`
    ///   for any rotation `w`, up to rounding and sign.
    /// - Two keys give the path of `keys[0].slerp(keys[1], s)`, though not
    ///   at constant angular velocity: it eases in and out.
    ///
    /// # Preconditions
    ///
    /// Unit keys (within rounding). An empty slice gives
    /// [`Quat::IDENTITY`] (no rotation to speak of); a NaN `t` gives
    /// [`Quat::NAN`], and so does a NaN or infinite key used between two
    /// keys. No allocation, no panic, for any input bits.
    ///
    /// # Accuracy
    ///
    /// Rotation error at most
    /// [`accuracy::CATMULL_ROM_MAX_ANGLE_ERROR`](crate::accuracy::CATMULL_ROM_MAX_ANGLE_ERROR)
    /// radians against the same construction in f64, for keys up to pi
    /// apart; norm within
    /// [`accuracy::NORMALIZE_MAX_NORM_ERROR`](crate::accuracy::NORMALIZE_MAX_NORM_ERROR)
    /// of 1 (`tests/differential.rs`).
    ///
    /// # Examples
    ///
    /// ```
    /// use rigtform::Quat;
    /// let keys = [
    ///     Quat::IDENTITY,
    ///     Quat::from_rotation_z(0.5),
    ///     Quat::from_rotation_x(0.5) * Quat::from_rotation_z(0.5),
    /// ];
    /// assert_eq!(Quat::catmull_rom(&keys, 1.0), keys[1]);
    /// assert_eq!(Quat::catmull_rom(&keys, 7.0), keys[2]); // clamped
    /// let between = Quat::catmull_rom(&keys, 1.5);
    /// assert!(between.angle_to(keys[1]) < 0.5 && between.angle_to(keys[2]) < 0.5);
    /// // -q is q: the same motion.
    /// let flipped = [keys[0], -keys[1], keys[2]];
    /// assert!(Quat::catmull_rom(&flipped, 1.5).angle_to(between) < 1e-6);
    /// assert_eq!(Quat::catmull_rom(&[], 0.5), Quat::IDENTITY);
    /// ```
    #[doc(alias = "spline")]
    #[must_use]
    pub fn catmull_rom(keys: &[Quat], t: f32) -> Self {
        match place(keys.len(), t) {
            Place::Empty => Self::IDENTITY,
            Place::Nan => Self::NAN,
            Place::Key(i) => keys.get(i).copied().unwrap_or(Self::NAN),
            Place::Between(i, u) => {
                let [before, from, to, after] = neighbours(keys, i, Self::NAN);
                Self::catmull_rom_segment(before, from, to, after, u)
            }
        }
    }

    /// The Catmull-Rom segment from `from` to `to`, with their neighbours
    /// `before` and `after`, at `u` in [0, 1]: the Bezier curve of the
    /// control points of [`catmull_rom`](Self::catmull_rom) by de
    /// Casteljau's algorithm with slerps, normalized.
    pub(crate) fn catmull_rom_segment(
        before: Self,
        from: Self,
        to: Self,
        after: Self,
        u: f32,
    ) -> Self {
        let out_of_from = (to * before.inv()).cn().pow(SIXTH) * from;
        let into_to = (after * from.inv()).cn().pow(-SIXTH) * to;
        let a = from.slerp(out_of_from, u);
        let b = out_of_from.slerp(into_to, u);
        let c = into_to.slerp(to, u);
        let ab = a.slerp(b, u);
        let bc = b.slerp(c, u);
        ab.slerp(bc, u).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn place_finds_keys_segments_and_clamps() {
        assert_eq!(place(0, 0.5), Place::Empty);
        assert_eq!(place(3, f32::NAN), Place::Nan);
        assert_eq!(place(1, 0.5), Place::Key(0));
        assert_eq!(place(3, -1.0), Place::Key(0));
        assert_eq!(place(3, f32::NEG_INFINITY), Place::Key(0));
        assert_eq!(place(3, 2.0), Place::Key(2));
        assert_eq!(place(3, f32::INFINITY), Place::Key(2));
        assert_eq!(place(3, 1.0), Place::Key(1));
        assert_eq!(place(3, 1.25), Place::Between(1, 0.25));
        assert_eq!(place(3, 0.5), Place::Between(0, 0.5));
        assert_eq!(place(usize::MAX, 1e30), Place::Key(usize::MAX - 1));
    }

    #[test]
    fn neighbours_repeat_the_end_keys() {
        let keys = [10, 11, 12];
        assert_eq!(neighbours(&keys, 0, 0), [10, 10, 11, 12]);
        assert_eq!(neighbours(&keys, 1, 0), [10, 11, 12, 12]);
        assert_eq!(neighbours(&[], 0, 7), [7, 7, 7, 7]);
    }
}
