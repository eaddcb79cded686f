//! The Catmull-Rom construction of `Quat::catmull_rom` and
//! `RigTForm::catmull_rom` in f64: the reference their accuracy and their
//! translation are measured against.

use nalgebra as na;
use rigtform_proofs::reference::Quat64;

fn from_na(q: na::Quaternion<f64>) -> Quat64 {
    let q = q.normalize();
    Quat64 {
        w: q.w,
        x: q.i,
        y: q.j,
        z: q.k,
    }
}

fn cn(q: Quat64) -> Quat64 {
    if q.w < 0.0 {
        Quat64 {
            w: -q.w,
            x: -q.x,
            y: -q.y,
            z: -q.z,
        }
    } else {
        q
    }
}

/// Where `t` falls among `n >= 2` keys: the segment `i` (keys `i` and
/// `i + 1`) and the parameter `u` in [0, 1] along it, `t` clamped to
/// `[0, n - 1]`.
fn segment(n: usize, t: f64) -> (usize, f64) {
    let t = t.clamp(0.0, (n - 1) as f64);
    let i = (t.floor() as usize).min(n - 2);
    (i, t - i as f64)
}

/// Keys `i - 1`, `i`, `i + 1`, `i + 2`, the missing ones at the ends
/// repeating the end keys.
fn neighbours<T: Copy>(keys: &[T], i: usize) -> [T; 4] {
    let last = keys.len() - 1;
    [i.saturating_sub(1), i, i + 1, i + 2].map(|j| keys[j.min(last)])
}

/// The Catmull-Rom spline of rotations through `keys` (normalized first)
/// at `t`, in f64: control points `cn(c_{i+1} c_{i-1}^-1)^(1/6) c_i` and
/// `cn(c_{i+2} c_i^-1)^(-1/6) c_{i+1}`, de Casteljau's algorithm with the
/// notes' slerp. Needs at least one key.
///
/// ```
/// use nalgebra as na;
/// use rigtform_testkit::catmull_rom::catmull_rom64;
/// let keys = [na::Quaternion::new(1.0, 0.0, 0.0, 0.0); 3];
/// assert_eq!(catmull_rom64(&keys, 1.5), keys[0]);
/// ```
pub fn catmull_rom64(keys: &[na::Quaternion<f64>], t: f64) -> na::Quaternion<f64> {
    let keys: Vec<Quat64> = keys.iter().map(|&q| from_na(q)).collect();
    let q = if keys.len() == 1 {
        keys[0]
    } else {
        let (i, u) = segment(keys.len(), t);
        let [before, from, to, after] = neighbours(&keys, i);
        let out_of_from = cn(to * before.conj()).pow(1.0 / 6.0) * from;
        let into_to = cn(after * from.conj()).pow(-1.0 / 6.0) * to;
        let a = Quat64::slerp(from, out_of_from, u);
        let b = Quat64::slerp(out_of_from, into_to, u);
        let c = Quat64::slerp(into_to, to, u);
        let ab = Quat64::slerp(a, b, u);
        let bc = Quat64::slerp(b, c, u);
        Quat64::slerp(ab, bc, u)
    };
    na::Quaternion::new(q.w, q.x, q.y, q.z)
}

/// The Catmull-Rom curve of translations through `keys` at `t`, in f64,
/// in the Bernstein form of its cubic Bezier segments (control points
/// `c_i + (c_{i+1} - c_{i-1}) / 6` and `c_{i+1} - (c_{i+2} - c_i) / 6`):
/// the same cubic as the library's de Casteljau evaluation, computed
/// another way.
/// Needs at least one key.
///
/// ```
/// use nalgebra as na;
/// use rigtform_testkit::catmull_rom::catmull_rom_translation64;
/// let keys = [na::Vector3::zeros(), na::Vector3::x(), na::Vector3::new(1.0, 1.0, 0.0)];
/// let mid = catmull_rom_translation64(&keys, 0.5);
/// assert!((mid - na::Vector3::new(0.5, -1.0 / 16.0, 0.0)).norm() < 1e-15);
/// ```
pub fn catmull_rom_translation64(keys: &[na::Vector3<f64>], t: f64) -> na::Vector3<f64> {
    if keys.len() == 1 {
        return keys[0];
    }
    let (i, u) = segment(keys.len(), t);
    let [before, from, to, after] = neighbours(keys, i);
    let p1 = from + (to - before) / 6.0;
    let p2 = to - (after - from) / 6.0;
    let v = 1.0 - u;
    from * (v * v * v) + p1 * (3.0 * v * v * u) + p2 * (3.0 * v * u * u) + to * (u * u * u)
}

/// Step of [`one_sided_angular_velocity`]: 1/256, exact in f32 beside
/// whole numbers, small enough for its second-order difference (error about
/// `h^2` times the path's third derivative), large enough that f32
/// rounding of the rotations (a few 1e-7 rad) divided by it stays near
/// 1e-4 rad per unit of `t`.
pub const VELOCITY_STEP: f32 = 1.0 / 256.0;

/// The angular velocity, in radians per unit of `t` in the world frame, of
/// the rotation path `path` as it leaves `path(s)` in the direction `dir`
/// (+1 after `s`, -1 before it), by a one-sided second-order difference:
/// with `L(x) = log(path(s + dir x) path(s)^-1)` (the short way, in f64),
/// `dir (4 L(h) - L(2 h)) / (2 h)`. Where a path's angular velocity jumps,
/// the two sides differ by the jump.
///
/// ```
/// use rigtform::Quat;
/// use rigtform_testkit::catmull_rom::one_sided_angular_velocity;
/// let path = |s: f32| Quat::from_rotation_z(if s < 1.0 { s } else { 3.0 * s - 2.0 });
/// let before = one_sided_angular_velocity(path, 1.0, -1.0);
/// let after = one_sided_angular_velocity(path, 1.0, 1.0);
/// assert!((before.z - 1.0).abs() < 1e-3 && (after.z - 3.0).abs() < 1e-3);
/// ```
pub fn one_sided_angular_velocity(
    path: impl Fn(f32) -> rigtform::Quat,
    s: f32,
    dir: f32,
) -> na::Vector3<f64> {
    let at = crate::reference::to_f64(path(s)).normalize();
    let log = |x: f32| {
        let d = crate::reference::to_f64(path(s + dir * x)).normalize() * at.conjugate();
        let d = if d.w < 0.0 { -d } else { d };
        let v = d.imag();
        let n = v.norm();
        if n == 0.0 {
            v
        } else {
            v * (2.0 * n.atan2(d.w) / n)
        }
    };
    let h = VELOCITY_STEP;
    (log(h) * 4.0 - log(2.0 * h)) * (f64::from(dir) / (2.0 * f64::from(h)))
}
