//! Clipping in homogeneous clip space, before the perspective divide:
//! against the near plane (`z >= -w`, which also keeps `w > 0`), and against
//! a guard band `|x|, |y| <= GUARD_BAND * w` that bounds screen coordinates so
//! the fixed-point edge functions cannot overflow. Triangles beyond the far
//! plane are left to the depth test, which rejects `z > 1`.

use rigtform::Cvec4;

use crate::vertex::ClipVertex;

/// How far outside the viewport, in viewport half-widths, screen
/// coordinates may reach before a triangle is cut (a guard band: only
/// triangles that reach this far pay for clipping).
pub const GUARD_BAND: f32 = 4.0;

/// The five clip planes `p` with `dot(p, clip) >= 0` inside:
/// near, then the guard band left, right, bottom, top.
const PLANES: [[f32; 4]; 5] = [
    [0.0, 0.0, 1.0, 1.0],
    [1.0, 0.0, 0.0, GUARD_BAND],
    [-1.0, 0.0, 0.0, GUARD_BAND],
    [0.0, 1.0, 0.0, GUARD_BAND],
    [0.0, -1.0, 0.0, GUARD_BAND],
];

fn distance(plane: [f32; 4], v: &ClipVertex) -> f32 {
    Cvec4::from_array(plane).dot(v.clip)
}

/// Clips the triangle `tri` and appends the triangles of the remaining
/// convex polygon to `out` as a fan, in order: nothing when it is entirely
/// outside, the triangle itself when entirely inside.
///
/// A vertex made where an edge crosses a plane is computed from the edge's
/// inside end towards its outside end, whichever triangle the edge belongs
/// to, so two triangles sharing an edge share the new vertex bit for bit
/// (no cracks). A triangle with a non-finite coordinate is dropped.
///
/// ```
/// use rigtform::Cvec4;
/// use rigtform_render::{clip_triangle, ClipVertex};
/// let v = |x, z, w| ClipVertex { clip: Cvec4::new(x, 0.0, z, w), attrs: [0.0; 9] };
/// let mut out = Vec::new();
/// // One vertex behind the near plane: a quadrilateral, two triangles.
/// clip_triangle([v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(0.0, -3.0, 1.0)], &mut out);
/// assert_eq!(out.len(), 2);
/// assert!(out.iter().flatten().all(|c| c.clip.z >= -c.clip.w));
/// ```
pub fn clip_triangle(tri: [ClipVertex; 3], out: &mut Vec<[ClipVertex; 3]>) {
    if !tri.iter().all(|v| v.clip.is_finite()) {
        return;
    }
    // Outcodes: bit k set when a vertex is outside plane k.
    let outcode = |v: &ClipVertex| {
        PLANES.iter().enumerate().fold(0u8, |code, (k, &p)| {
            code | (u8::from(distance(p, v) < 0.0) << k)
        })
    };
    let codes = tri.each_ref().map(outcode);
    // The usual case: nothing to cut.
    if codes == [0; 3] {
        out.push(tri);
        return;
    }
    // Trivial rejection: all three outside one plane.
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    let mut polygon: Vec<ClipVertex> = tri.to_vec();
    let mut next = Vec::with_capacity(polygon.len() + 2);
    for plane in PLANES {
        next.clear();
        for (i, &a) in polygon.iter().enumerate() {
            let b = polygon[(i + 1) % polygon.len()];
            let (da, db) = (distance(plane, &a), distance(plane, &b));
            let (a_in, b_in) = (da >= 0.0, db >= 0.0);
            if a_in {
                next.push(a);
            }
            if a_in != b_in {
                // From the inside end, whichever way round the edge runs.
                let (inside, outside, d_in, d_out) =
                    if a_in { (a, b, da, db) } else { (b, a, db, da) };
                next.push(inside.lerp(outside, d_in / (d_in - d_out)));
            }
        }
        std::mem::swap(&mut polygon, &mut next);
        if polygon.len() < 3 {
            return;
        }
    }
    for i in 1..polygon.len() - 1 {
        out.push([polygon[0], polygon[i], polygon[i + 1]]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
        ClipVertex {
            clip: Cvec4::new(x, y, z, w),
            attrs: [x, y, z, w, 0.0, 0.0, 0.0, 0.0, 0.0],
        }
    }

    fn clipped(tri: [ClipVertex; 3]) -> Vec<[ClipVertex; 3]> {
        let mut out = Vec::new();
        clip_triangle(tri, &mut out);
        out
    }

    fn inside_all_planes(c: &ClipVertex) -> bool {
        PLANES.iter().all(|&p| distance(p, c) >= -1e-5)
    }

    #[test]
    fn triangle_inside_is_kept_unchanged() {
        let tri = [
            v(0.0, 0.0, 0.0, 1.0),
            v(1.0, 0.0, 0.0, 1.0),
            v(0.0, 1.0, 0.0, 1.0),
        ];
        assert_eq!(clipped(tri), vec![tri]);
    }

    #[test]
    fn triangle_behind_near_plane_is_dropped() {
        let tri = [
            v(0.0, 0.0, -2.0, 1.0),
            v(1.0, 0.0, -2.0, 1.0),
            v(0.0, 1.0, -3.0, 1.0),
        ];
        assert!(clipped(tri).is_empty());
    }

    #[test]
    fn triangle_crossing_near_plane_is_kept_in_front_of_it() {
        // Two vertices in front, one behind: a quadrilateral.
        let tri = [
            v(0.1, 0.2, 0.5, 1.0),
            v(1.0, 0.3, 0.2, 1.2),
            v(0.0, 1.0, -3.0, 1.0),
        ];
        let out = clipped(tri);
        assert_eq!(out.len(), 2);
        assert!(out.iter().flatten().all(inside_all_planes));
        // The original vertices in front survive, and the cut is on the plane.
        let all: Vec<_> = out.iter().flatten().collect();
        assert!(all.contains(&&tri[0]) && all.contains(&&tri[1]));
        let on_plane = all
            .iter()
            .filter(|c| (c.clip.z + c.clip.w).abs() < 1e-6)
            .count();
        assert!(on_plane >= 2);
        // Attributes are carried along with the position.
        for c in &all {
            let a = c.attrs;
            let same = (a[0] - c.clip.x).abs()
                + (a[1] - c.clip.y).abs()
                + (a[2] - c.clip.z).abs()
                + (a[3] - c.clip.w).abs();
            assert!(same < 1e-6, "{c:?}");
        }
    }

    #[test]
    fn triangle_with_one_vertex_in_front_stays_a_triangle() {
        let tri = [
            v(0.0, 0.0, 0.0, 1.0),
            v(1.0, 0.0, -3.0, 1.0),
            v(0.0, 1.0, -3.0, 1.0),
        ];
        let out = clipped(tri);
        assert_eq!(out.len(), 1);
        assert!(out.iter().flatten().all(inside_all_planes));
    }

    #[test]
    fn shared_edge_gets_the_same_cut_from_both_sides() {
        let (a, b) = (v(0.3, 0.1, 0.2, 1.0), v(-0.7, 0.4, -2.9, 1.1));
        let left = clipped([a, b, v(-1.0, -1.0, 0.5, 1.0)]);
        let right = clipped([b, a, v(1.0, 1.0, 0.5, 1.0)]);
        let on_near_plane = |tris: &[[ClipVertex; 3]]| -> Vec<ClipVertex> {
            tris.iter()
                .flatten()
                .filter(|c| (c.clip.z + c.clip.w).abs() < 1e-5)
                .copied()
                .collect()
        };
        let (l, r) = (on_near_plane(&left), on_near_plane(&right));
        assert!(!l.is_empty() && !r.is_empty());
        assert!(l.iter().any(|x| r.contains(x)), "{l:?} / {r:?}");
    }

    #[test]
    fn guard_band_bounds_screen_coordinates() {
        let tri = [
            v(0.0, 0.0, 0.0, 1.0),
            v(1e6, 0.0, 0.0, 1.0),
            v(0.0, 1e6, 0.0, 1.0),
        ];
        let out = clipped(tri);
        assert!(!out.is_empty());
        for c in out.iter().flatten() {
            assert!(c.clip.x / c.clip.w <= GUARD_BAND * 1.0001);
            assert!(c.clip.y / c.clip.w <= GUARD_BAND * 1.0001);
        }
    }

    #[test]
    fn triangle_with_nan_vertex_is_dropped() {
        let tri = [
            v(f32::NAN, 0.0, 0.0, 1.0),
            v(1.0, 0.0, 0.0, 1.0),
            v(0.0, 1.0, 0.0, 1.0),
        ];
        assert!(clipped(tri).is_empty());
    }
}
