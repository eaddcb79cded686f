//! Triangle setup and rasterization: back-face culling, edge functions in
//! exact fixed-point arithmetic with a top-left fill rule, the samples each
//! triangle covers, and what is interpolated across it: the depth at each
//! sample, and perspective-correct attributes at the one shading point of
//! each pixel. The [`fragment`](crate::fragment) stage puts these together
//! for every covered pixel.
//!
//! Vertex positions are snapped to 1/256 of a pixel. Edge functions are then
//! evaluated exactly in 64-bit integers, so whether a sample lies inside,
//! outside or exactly on an edge is never a matter of rounding, and a
//! sample on an edge shared by two triangles goes to exactly one of them.

use core::cmp::Ordering;

use crate::samples::Msaa;
use crate::vertex::ATTRIBUTES;
use crate::viewport::ScreenVertex;

/// Fixed-point fraction bits of screen positions: 1/256 of a pixel, the
/// unit of the sample positions ([`Msaa::offsets`]) too.
pub const SUBPIXEL_BITS: u32 = 8;
const ONE: i64 = 1 << SUBPIXEL_BITS;

/// The largest screen coordinate, in pixels, that triangle setup accepts:
/// 2^20, so that snapped coordinates stay below 2^28 and products of their
/// differences in the edge functions below 2^58, far from `i64` overflow.
pub const MAX_COORDINATE: f32 = 1_048_576.0;

/// Whether triangles facing away from the camera are drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Skip triangles that are clockwise on screen (OpenGL's back faces).
    #[default]
    Back,
    /// Draw both sides.
    None,
}

/// One edge function `E(p) = a (p.x - x0) + b (p.y - y0)`, positive inside.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Edge {
    a: i64,
    b: i64,
    x0: i64,
    y0: i64,
    /// 0 for a top or left edge, whose own samples are inside; 1 otherwise.
    bias: i64,
}

impl Edge {
    /// The edge from `p` to `q`, positive on the left of it in screen
    /// coordinates with y down, i.e. inside a counter-clockwise (in NDC)
    /// triangle.
    fn new((px, py): (i64, i64), (qx, qy): (i64, i64)) -> Self {
        let (a, b) = (qy - py, px - qx);
        // The gradient (a, b) points inside. A left edge has the inside to
        // its right (a > 0); a top edge is horizontal with the inside below
        // (a == 0, b > 0, y pointing down). Exactly one of two triangles
        // sharing an edge sees it as top-left, since their gradients are
        // opposite.
        let top_left = a > 0 || (a == 0 && b > 0);
        Self {
            a,
            b,
            x0: px,
            y0: py,
            bias: i64::from(!top_left),
        }
    }

    fn at(&self, x: i64, y: i64) -> i64 {
        self.a * (x - self.x0) + self.b * (y - self.y0)
    }
}

/// A triangle after setup: fixed-point edge functions, its pixel bounding
/// box, and what is interpolated across it.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    edges: [Edge; 3],
    /// Twice the area in subpixel units squared (positive).
    area: i64,
    /// `1 / area`, which turns edge values into barycentric weights.
    inv_area: f32,
    /// Inclusive pixel bounds, clamped to the viewport.
    x_min: u32,
    x_max: u32,
    y_min: u32,
    y_max: u32,
    z: [f32; 3],
    inv_w: [f32; 3],
    attrs_w: [[f32; ATTRIBUTES]; 3],
}

fn snap(v: f32) -> i64 {
    (v * ONE as f32).round() as i64
}

impl Triangle {
    /// Sets up the screen triangle `v` for a `width x height` viewport.
    ///
    /// `None` when it is culled (back-facing with [`Cull::Back`]), has no
    /// area after snapping, lies outside the viewport, or has a coordinate
    /// that is not finite or beyond [`MAX_COORDINATE`] pixels (clipping
    /// against the guard band of [`clip`](crate::clip) keeps them far
    /// inside), where the edge functions could overflow.
    ///
    /// ```
    /// use rigtform_render::{Cull, Msaa, ScreenVertex, Triangle};
    /// let v = |x, y| ScreenVertex { x, y, z: 0.0, inv_w: 1.0, attrs_w: [0.0; 9] };
    /// // Clockwise on screen (y down) is counter-clockwise in NDC: a front face.
    /// let t = Triangle::setup([v(0.0, 0.0), v(0.0, 4.0), v(4.0, 0.0)], Cull::Back, 8, 8).unwrap();
    /// assert_eq!(t.doubled_area(), 16.0);
    /// assert!(Triangle::setup([v(0.0, 0.0), v(4.0, 0.0), v(0.0, 4.0)], Cull::Back, 8, 8).is_none());
    /// ```
    #[must_use]
    pub fn setup(v: [ScreenVertex; 3], cull: Cull, width: u32, height: u32) -> Option<Self> {
        let in_range = |c: f32| c.abs() <= MAX_COORDINATE;
        if !v.iter().all(|s| in_range(s.x) && in_range(s.y)) {
            return None;
        }
        let p = v.map(|s| (snap(s.x), snap(s.y)));
        let area = Edge::new(p[1], p[2]).at(p[0].0, p[0].1);
        // Front faces keep their order; back faces, when drawn, are turned
        // round so that the edge functions are positive inside.
        let order = match (area.cmp(&0), cull) {
            (Ordering::Greater, _) => [0, 1, 2],
            (Ordering::Less, Cull::None) => [0, 2, 1],
            _ => return None,
        };
        let p = order.map(|i| p[i]);
        let v = order.map(|i| v[i]);
        let edges = [
            Edge::new(p[1], p[2]),
            Edge::new(p[2], p[0]),
            Edge::new(p[0], p[1]),
        ];
        let lo = |c: [i64; 3]| c.into_iter().min().unwrap_or(0).div_euclid(ONE);
        let hi = |c: [i64; 3]| c.into_iter().max().unwrap_or(0).div_euclid(ONE);
        let (xs, ys) = (p.map(|q| q.0), p.map(|q| q.1));
        let (x_min, x_max) = (lo(xs).max(0), hi(xs).min(i64::from(width) - 1));
        let (y_min, y_max) = (lo(ys).max(0), hi(ys).min(i64::from(height) - 1));
        if x_min > x_max || y_min > y_max {
            return None;
        }
        let area = area.abs();
        Some(Self {
            edges,
            area,
            inv_area: (1.0 / area as f64) as f32,
            x_min: x_min as u32,
            x_max: x_max as u32,
            y_min: y_min as u32,
            y_max: y_max as u32,
            z: v.map(|s| s.z),
            inv_w: v.map(|s| s.inv_w),
            attrs_w: v.map(|s| s.attrs_w),
        })
    }

    /// The inclusive range of pixel rows the triangle may touch.
    #[must_use]
    pub fn rows(&self) -> (u32, u32) {
        (self.y_min, self.y_max)
    }

    /// Twice the triangle's area in square pixels, after snapping.
    #[must_use]
    pub fn doubled_area(&self) -> f64 {
        self.area as f64 / (ONE * ONE) as f64
    }

    /// Calls `f(x, y, mask, e)` for every pixel in rows `y_from ..= y_to`
    /// with at least one covered sample, left to right, top to bottom:
    /// `mask` has bit `s` set for each covered sample `s`, and `e[s]` holds
    /// the three edge functions at sample `s`: barycentric weights times
    /// twice the area, less the fill rule's bias of one unit (1/65536 of a
    /// square pixel) on edges that are not top-left, so that a covered
    /// sample has no negative weight.
    ///
    /// ```
    /// use rigtform_render::{Cull, Msaa, ScreenVertex, Triangle};
    /// let v = |x, y| ScreenVertex { x, y, z: 0.0, inv_w: 1.0, attrs_w: [0.0; 9] };
    /// // The square [0, 4]^2 as two triangles sharing a diagonal: 16 pixels,
    /// // each covered exactly once.
    /// let mut count = 0;
    /// for tri in [[v(0.0, 0.0), v(0.0, 4.0), v(4.0, 4.0)], [v(0.0, 0.0), v(4.0, 4.0), v(4.0, 0.0)]] {
    ///     let t = Triangle::setup(tri, Cull::Back, 8, 8).unwrap();
    ///     t.for_each_covered(Msaa::Off, 0, 7, |_, _, mask, _| count += mask.count_ones());
    /// }
    /// assert_eq!(count, 16);
    /// ```
    #[inline]
    pub fn for_each_covered(
        &self,
        msaa: Msaa,
        y_from: u32,
        y_to: u32,
        mut f: impl FnMut(u32, u32, u32, &[[i64; 3]; 4]),
    ) {
        let offsets = msaa.offsets();
        // Each edge's value at each sample, relative to the pixel corner.
        let mut step = [[0i64; 3]; 4];
        for (s, &(ox, oy)) in offsets.iter().enumerate() {
            for (k, e) in self.edges.iter().enumerate() {
                step[s][k] = e.a * ox + e.b * oy - e.bias;
            }
        }
        let mut e = [[0i64; 3]; 4];
        for y in y_from.max(self.y_min)..=y_to.min(self.y_max) {
            let corner_y = i64::from(y) * ONE;
            let mut corner = self
                .edges
                .map(|edge| edge.at(i64::from(self.x_min) * ONE, corner_y));
            for x in self.x_min..=self.x_max {
                let mut mask = 0;
                for s in 0..offsets.len() {
                    let v = [
                        corner[0] + step[s][0],
                        corner[1] + step[s][1],
                        corner[2] + step[s][2],
                    ];
                    if (v[0] | v[1] | v[2]) >= 0 {
                        mask |= 1 << s;
                    }
                    e[s] = v;
                }
                if mask != 0 {
                    f(x, y, mask, &e);
                }
                for (c, edge) in corner.iter_mut().zip(&self.edges) {
                    *c += edge.a * ONE;
                }
            }
        }
    }

    /// The depth plane of the triangle, to evaluate at every covered
    /// sample with [`DepthPlane::at`]: what the depth reads of the
    /// triangle, taken once into a small value of its own rather than read
    /// through the triangle at every sample (the fragment stage measured
    /// faster so, see `fill_triangle`).
    ///
    /// ```
    /// use rigtform_render::{Cull, Msaa, ScreenVertex, Triangle};
    /// let v = |x, y, z| ScreenVertex { x, y, z, inv_w: 1.0, attrs_w: [0.0; 9] };
    /// let t = Triangle::setup([v(0.0, 0.0, 0.5), v(0.0, 4.0, 0.5), v(4.0, 0.0, 0.5)], Cull::Back, 8, 8)
    ///     .unwrap();
    /// let depth = t.depth_plane();
    /// t.for_each_covered(Msaa::Off, 0, 7, |_, _, _, e| assert_eq!(depth.at(&e[0]), 0.5));
    /// ```
    #[must_use]
    #[inline]
    pub fn depth_plane(&self) -> DepthPlane {
        let [z0, z1, z2] = self.z;
        DepthPlane {
            z0,
            dz1: z1 - z0,
            dz2: z2 - z0,
            inv_area: self.inv_area,
        }
    }

    /// Barycentric weights (times twice the area) of the shading point of
    /// pixel `(x, y)`, from its coverage `mask` and edge values `e` (as
    /// [`for_each_covered`](Self::for_each_covered) hands them over): its
    /// centre when inside the triangle, otherwise the first covered sample
    /// (so attributes are never extrapolated).
    #[must_use]
    #[inline]
    pub fn shading_weights(&self, x: u32, y: u32, mask: u32, e: &[[i64; 3]; 4]) -> [i64; 3] {
        let (cx, cy) = (i64::from(x) * ONE + ONE / 2, i64::from(y) * ONE + ONE / 2);
        let at_centre = self.edges.map(|edge| edge.at(cx, cy));
        if at_centre.iter().all(|&v| v >= 0) {
            at_centre
        } else {
            e[mask.trailing_zeros() as usize]
        }
    }

    /// Perspective-correct attributes from barycentric weights (of any
    /// common scale): `a / w` and `1 / w` interpolate linearly on screen,
    /// and their ratio gives `a`, in which the scale cancels.
    ///
    /// ```
    /// use rigtform_render::{Cull, ScreenVertex, Triangle};
    /// // a = 2 at every vertex, at depths w = 1, 1 and 4.
    /// let v = |x, y, w: f32| ScreenVertex { x, y, z: 0.0, inv_w: 1.0 / w, attrs_w: [2.0 / w; 9] };
    /// let t = Triangle::setup([v(0.0, 0.0, 1.0), v(0.0, 4.0, 1.0), v(4.0, 0.0, 4.0)], Cull::Back, 8, 8)
    ///     .unwrap();
    /// let a = t.interpolate([1, 1, 2]);
    /// assert!((a[0] - 2.0).abs() < 1e-6);
    /// ```
    #[must_use]
    #[inline]
    pub fn interpolate(&self, weights: [i64; 3]) -> [f32; ATTRIBUTES] {
        let l = weights.map(|w| w as f32);
        let inv_w = l[0] * self.inv_w[0] + l[1] * self.inv_w[1] + l[2] * self.inv_w[2];
        let w = 1.0 / inv_w;
        let mut out = [0.0; ATTRIBUTES];
        for (k, o) in out.iter_mut().enumerate() {
            *o =
                (l[0] * self.attrs_w[0][k] + l[1] * self.attrs_w[1][k] + l[2] * self.attrs_w[2][k])
                    * w;
        }
        out
    }
}

/// The depth of a triangle as a function of the edge values of a sample
/// (see [`Triangle::depth_plane`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthPlane {
    z0: f32,
    dz1: f32,
    dz2: f32,
    inv_area: f32,
}

impl DepthPlane {
    /// The NDC depth at a sample from its edge values `e` (as
    /// [`Triangle::for_each_covered`] hands them over): depth interpolates
    /// linearly on screen.
    #[must_use]
    #[inline]
    pub fn at(&self, e: &[i64; 3]) -> f32 {
        let (l1, l2) = (e[1] as f32 * self.inv_area, e[2] as f32 * self.inv_area);
        self.z0 + self.dz1 * l1 + self.dz2 * l2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sv(x: f32, y: f32) -> ScreenVertex {
        ScreenVertex {
            x,
            y,
            z: 0.0,
            inv_w: 1.0,
            attrs_w: [0.0; ATTRIBUTES],
        }
    }

    /// Counts how often each sample of a `w x h` viewport is covered by the
    /// given triangles.
    fn coverage(tris: &[[ScreenVertex; 3]], msaa: Msaa, w: u32, h: u32) -> Vec<u32> {
        let n = msaa.samples();
        let mut count = vec![0; (w * h) as usize * n];
        for &t in tris {
            if let Some(t) = Triangle::setup(t, Cull::None, w, h) {
                t.for_each_covered(msaa, 0, h - 1, |x, y, mask, _| {
                    for s in 0..n {
                        if mask & (1 << s) != 0 {
                            count[(y * w + x) as usize * n + s] += 1;
                        }
                    }
                });
            }
        }
        count
    }

    /// A small deterministic generator (SplitMix64) for test triangles.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f32 {
            self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            ((z ^ (z >> 31)) >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    #[test]
    fn coverage_of_a_triangle_matches_its_area() {
        // Each sample position repeats on the unit pixel lattice, and a
        // convex region of area A and perimeter P holds N lattice points with
        // A - P/2 < N < A + P/2 + 1 (Nosarzewska, 1948), so the coverage of
        // a triangle, in pixels, is within P/2 + 1 of its area for either
        // sample pattern. On average over many triangles the fill rule must
        // not be biased: the mean error stays well under one pixel.
        let mut rng = Rng(7);
        for msaa in [Msaa::Off, Msaa::X4] {
            let (mut signed_error, mut n) = (0.0, 0.0);
            for _ in 0..400 {
                let tri = [0; 3].map(|_| sv(2.0 + 60.0 * rng.next(), 2.0 + 60.0 * rng.next()));
                let Some(t) = Triangle::setup(tri, Cull::None, 64, 64) else {
                    continue;
                };
                let area = t.doubled_area() / 2.0;
                let perimeter: f64 = (0..3)
                    .map(|i| {
                        let (a, b) = (tri[i], tri[(i + 1) % 3]);
                        f64::from((b.x - a.x).hypot(b.y - a.y))
                    })
                    .sum();
                let covered: u32 = coverage(&[tri], msaa, 64, 64).iter().sum();
                let covered = f64::from(covered) / msaa.samples() as f64;
                let error = covered - area;
                assert!(
                    error.abs() < perimeter / 2.0 + 1.0,
                    "{msaa:?}: covered {covered}, area {area}, perimeter {perimeter}"
                );
                signed_error += error;
                n += 1.0;
            }
            let bias = signed_error / n;
            println!("{msaa:?}: mean coverage error over {n} triangles: {bias:+.4} pixels");
            assert!(bias.abs() < 0.25, "{msaa:?}: mean error {bias} pixels");
        }
    }

    #[test]
    fn coverage_of_a_pixel_aligned_rectangle_is_exact() {
        let (a, b, c, d) = (sv(3.0, 2.0), sv(13.0, 2.0), sv(13.0, 9.0), sv(3.0, 9.0));
        for msaa in [Msaa::Off, Msaa::X4] {
            let count = coverage(&[[a, d, c], [a, c, b]], msaa, 16, 16);
            let covered: u32 = count.iter().sum();
            assert_eq!(covered as usize, 10 * 7 * msaa.samples());
        }
    }

    #[test]
    fn triangles_sharing_edges_paint_each_sample_once() {
        // A fan of triangles around an interior vertex, with edges at all
        // slopes, including ones exactly through sample positions, tiling
        // the square [4, 28]^2: every sample inside is painted exactly once.
        let mut rng = Rng(11);
        for round in 0..50 {
            let centre = if round == 0 {
                sv(16.5, 16.5)
            } else {
                sv(8.0 + 16.0 * rng.next(), 8.0 + 16.0 * rng.next())
            };
            let ring = [
                sv(4.0, 4.0),
                sv(4.0 + 24.0 * rng.next(), 4.0),
                sv(28.0, 4.0),
                sv(28.0, 4.0 + 24.0 * rng.next()),
                sv(28.0, 28.0),
                sv(4.0 + 24.0 * rng.next(), 28.0),
                sv(4.0, 28.0),
                sv(4.0, 4.0 + 24.0 * rng.next()),
            ];
            let tris: Vec<_> = (0..ring.len())
                .map(|i| [centre, ring[i], ring[(i + 1) % ring.len()]])
                .collect();
            for msaa in [Msaa::Off, Msaa::X4] {
                let count = coverage(&tris, msaa, 32, 32);
                assert!(count.iter().all(|&c| c <= 1), "double paint, round {round}");
                assert_eq!(count.iter().sum::<u32>() as usize, 24 * 24 * msaa.samples());
            }
        }
    }

    #[test]
    fn back_faces_are_culled_and_drawn_without_culling() {
        // Clockwise on screen with y down is counter-clockwise in NDC: front.
        let front = [sv(1.0, 1.0), sv(1.0, 9.0), sv(9.0, 1.0)];
        let back = [front[0], front[2], front[1]];
        assert!(Triangle::setup(front, Cull::Back, 10, 10).is_some());
        assert!(Triangle::setup(back, Cull::Back, 10, 10).is_none());
        let (f, b) = (
            Triangle::setup(front, Cull::None, 10, 10).unwrap(),
            Triangle::setup(back, Cull::None, 10, 10).unwrap(),
        );
        assert_eq!(f.area, b.area);
    }

    #[test]
    fn degenerate_and_offscreen_triangles_are_dropped() {
        let line = [sv(1.0, 1.0), sv(5.0, 5.0), sv(9.0, 9.0)];
        assert!(Triangle::setup(line, Cull::None, 10, 10).is_none());
        let off = [sv(-9.0, 1.0), sv(-9.0, 9.0), sv(-1.0, 1.0)];
        assert!(Triangle::setup(off, Cull::None, 10, 10).is_none());
        for bad in [f32::NAN, f32::INFINITY, 2.0 * MAX_COORDINATE] {
            let tri = [sv(1.0, 1.0), sv(1.0, 9.0), sv(bad, 1.0)];
            assert!(Triangle::setup(tri, Cull::None, 10, 10).is_none(), "{bad}");
        }
        let edge = [sv(1.0, 1.0), sv(1.0, 9.0), sv(MAX_COORDINATE, 1.0)];
        assert!(Triangle::setup(edge, Cull::None, 10, 10).is_some());
    }

    #[test]
    fn attributes_are_perspective_correct() {
        // An edge from w = 1 to w = 4 on screen: the screen midpoint is not
        // the attribute midpoint; with a = w the attribute there is the
        // harmonic mean 2 / (1 + 1/4) = 1.6.
        let mk = |x: f32, y: f32, w: f32| ScreenVertex {
            x,
            y,
            z: 0.0,
            inv_w: 1.0 / w,
            attrs_w: [1.0; ATTRIBUTES], // a / w with a = w
        };
        let tri = [mk(0.0, 0.0, 1.0), mk(0.0, 64.0, 1.0), mk(64.0, 0.0, 4.0)];
        let t = Triangle::setup(tri, Cull::Back, 64, 64).unwrap();
        let attrs = t.interpolate([t.area / 2, 0, t.area / 2]);
        assert!((attrs[0] - 1.6).abs() < 1e-5, "{}", attrs[0]);
        let at_vertex = t.interpolate([0, 0, t.area]);
        assert!((at_vertex[0] - 4.0).abs() < 1e-5);
    }

    #[test]
    fn shading_point_is_inside_the_triangle() {
        // A thin sliver that covers samples but not pixel centres.
        let tri = [sv(0.0, 0.05), sv(0.0, 0.3), sv(16.0, 0.05)];
        let t = Triangle::setup(tri, Cull::None, 16, 4).unwrap();
        let mut shaded = 0;
        t.for_each_covered(Msaa::X4, 0, 3, |x, y, mask, e| {
            let w = t.shading_weights(x, y, mask, e);
            assert!(w.iter().all(|&v| v >= 0));
            shaded += 1;
        });
        assert!(shaded > 0);
    }
}
