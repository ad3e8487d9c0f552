//! Node ↔ segment geometry (Radioss theory manual §8.4.5.1, §8.6.6.3), as
//! pure functions: closest point of a 3- or 4-node segment to a node, the
//! shape functions of that point, the distance and its direction, and the
//! tetrahedron-volume side test of TYPE5.
//!
//! A 4-node segment is split into four triangles around its centre (the
//! "four-triangle split" of §8.4.5.1): the closest point is then found
//! analytically on each triangle, edges and corners included, and carries
//! shape functions `N_i = λ_c/4 + λ_i` that sum to one and reproduce the
//! point (`Σ N_i x_i = x_c`), so forces spread by them (EQ. 8.6.6.6) balance
//! forces and moments about the contact point. A 3-node segment repeats its
//! third node (`n[3] == n[2]`) and is one triangle.

pub use crate::vec3::{add, cross, dot, norm, scale, sub, V3};

/// Closest point of triangle (a, b, c) to p, as barycentric weights of a, b, c
/// (Voronoi-region walk: vertices, edges, then the face).
pub fn closest_on_triangle(p: V3, a: V3, b: V3, c: V3) -> [f64; 3] {
    let ab = sub(b, a);
    let ac = sub(c, a);
    let ap = sub(p, a);
    let d1 = dot(ab, ap);
    let d2 = dot(ac, ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return [1.0, 0.0, 0.0];
    }
    let bp = sub(p, b);
    let d3 = dot(ab, bp);
    let d4 = dot(ac, bp);
    if d3 >= 0.0 && d4 <= d3 {
        return [0.0, 1.0, 0.0];
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return [1.0 - v, v, 0.0];
    }
    let cp = sub(p, c);
    let d5 = dot(ab, cp);
    let d6 = dot(ac, cp);
    if d6 >= 0.0 && d5 <= d6 {
        return [0.0, 0.0, 1.0];
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return [1.0 - w, 0.0, w];
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return [0.0, 1.0 - w, w];
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        // Degenerate triangle: fall back on its first vertex.
        return [1.0, 0.0, 0.0];
    }
    let v = vb / denom;
    let w = vc / denom;
    [1.0 - v - w, v, w]
}

/// Where a node meets a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// Closest point of the segment (on its face, an edge or a corner).
    pub point: V3,
    /// Shape functions of that point on the segment's four nodes (EQ. 8.6.6.6).
    pub shape: [f64; 4],
    /// Distance node ↔ closest point.
    pub dist: f64,
    /// Unit vector from the closest point towards the node (the direction the
    /// contact force pushes the node, §8.8.10: radial from an edge or corner,
    /// normal on the face); the segment normal when the node is on the segment.
    pub dir: V3,
    /// Unit normal of the segment (n1→n3 × n2→n4 for a quadrangle).
    pub normal: V3,
}

/// Unit normal of a segment: (x3 − x1) × (x4 − x2) for a quadrangle, the
/// plane normal for a triangle (n[3] == n[2]).
pub fn segment_normal(x: &[V3; 4], tri: bool) -> V3 {
    let n = if tri {
        cross(sub(x[1], x[0]), sub(x[2], x[0]))
    } else {
        cross(sub(x[2], x[0]), sub(x[3], x[1]))
    };
    let l = norm(n);
    if l > 0.0 {
        scale(n, 1.0 / l)
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// Segment area (half the diagonal cross product for a quadrangle).
pub fn segment_area(x: &[V3; 4], tri: bool) -> f64 {
    if tri {
        0.5 * norm(cross(sub(x[1], x[0]), sub(x[2], x[0])))
    } else {
        0.5 * norm(cross(sub(x[2], x[0]), sub(x[3], x[1])))
    }
}

/// Closest point of a segment to node `p` (§8.4.5.1): four-triangle split of a
/// quadrangle around its centre, one triangle for a 3-node segment.
/// True when `p` is at least `reach` away from every point of the segment:
/// the segment lies in the ball around its nodes' mean c whose radius r is the
/// farthest node, so |p − c| ≥ r + reach is enough. A cheap, exact reject
/// before `project`.
pub fn beyond_reach(p: V3, x: &[V3; 4], tri: bool, reach: f64) -> bool {
    let n = if tri { 3 } else { 4 };
    let mut c = [0.0; 3];
    for xi in &x[..n] {
        c = add(c, *xi);
    }
    let c = scale(c, 1.0 / n as f64);
    let mut r2 = 0.0f64;
    for xi in &x[..n] {
        let d = sub(*xi, c);
        r2 = r2.max(dot(d, d));
    }
    let d = sub(p, c);
    let lim = r2.sqrt() + reach;
    dot(d, d) >= lim * lim
}

pub fn project(p: V3, x: &[V3; 4], tri: bool) -> Projection {
    let normal = segment_normal(x, tri);
    let (point, shape) = if tri {
        let l = closest_on_triangle(p, x[0], x[1], x[2]);
        let q = add(add(scale(x[0], l[0]), scale(x[1], l[1])), scale(x[2], l[2]));
        (q, [l[0], l[1], l[2], 0.0])
    } else {
        let c = scale(add(add(x[0], x[1]), add(x[2], x[3])), 0.25);
        let mut best: Option<(f64, V3, [f64; 4])> = None;
        for i in 0..4 {
            let j = (i + 1) % 4;
            let l = closest_on_triangle(p, c, x[i], x[j]);
            let q = add(add(scale(c, l[0]), scale(x[i], l[1])), scale(x[j], l[2]));
            let d = sub(p, q);
            let d2 = dot(d, d);
            if best.as_ref().is_none_or(|b| d2 < b.0) {
                let mut sh = [0.25 * l[0]; 4];
                sh[i] += l[1];
                sh[j] += l[2];
                best = Some((d2, q, sh));
            }
        }
        let (_, q, sh) = best.expect("four triangles");
        (q, sh)
    };
    let d = sub(p, point);
    let dist = norm(d);
    let dir = if dist > 0.0 {
        scale(d, 1.0 / dist)
    } else {
        normal
    };
    Projection {
        point,
        shape,
        dist,
        dir,
        normal,
    }
}

/// Six times the signed volume of tetrahedron (a, b, c, p): positive when p is
/// on the side the normal (b − a) × (c − a) points to (§8.6.6.3).
pub fn tetra_volume6(a: V3, b: V3, c: V3, p: V3) -> f64 {
    dot(cross(sub(b, a), sub(c, a)), sub(p, a))
}

/// Bilinear shape functions H1..H4 at isoparametric (s, t) (§8.4.5.1).
pub fn quad_shape(s: f64, t: f64) -> [f64; 4] {
    [
        0.25 * (1.0 - s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 + t),
        0.25 * (1.0 - s) * (1.0 + t),
    ]
}

/// Interpolates nodal vectors with shape functions.
#[inline]
pub fn interpolate(shape: &[f64; 4], v: &[V3; 4]) -> V3 {
    let mut out = [0.0; 3];
    for i in 0..4 {
        for k in 0..3 {
            out[k] += shape[i] * v[i][k];
        }
    }
    out
}

/// Smallest edge length of a segment.
pub fn min_edge(x: &[V3; 4], tri: bool) -> f64 {
    let n = if tri { 3 } else { 4 };
    (0..n)
        .map(|i| norm(sub(x[(i + 1) % n], x[i])))
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ball reject never drops a point the projection finds within reach
    /// (warped quads and triangles, points all around).
    #[test]
    fn beyond_reach_only_rejects_points_out_of_reach() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64) / ((1u64 << 53) as f64) * 2.0 - 1.0
        };
        let mut rejected = 0;
        for case in 0..4000 {
            let mut x = square();
            for xi in x.iter_mut() {
                for v in xi.iter_mut() {
                    *v += 0.3 * rnd();
                }
            }
            let tri = case % 3 == 0;
            let p = [2.0 * rnd() + 0.5, 2.0 * rnd() + 0.5, rnd()];
            let reach = 0.05 + 0.5 * (rnd() + 1.0);
            if beyond_reach(p, &x, tri, reach) {
                rejected += 1;
                assert!(project(p, &x, tri).dist >= reach, "case {case}");
            }
        }
        assert!(
            rejected > 500,
            "the test must reject some points: {rejected}"
        );
    }

    fn square() -> [V3; 4] {
        [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ]
    }

    #[test]
    fn face_projection_reproduces_the_point_and_sums_to_one() {
        let x = square();
        let p = project([0.3, 0.6, 0.25], &x, false);
        assert!((p.dist - 0.25).abs() < 1e-15);
        assert!((p.point[0] - 0.3).abs() < 1e-15 && (p.point[1] - 0.6).abs() < 1e-15);
        let s: f64 = p.shape.iter().sum();
        assert!((s - 1.0).abs() < 1e-15);
        let q = interpolate(&p.shape, &x);
        for k in 0..3 {
            assert!((q[k] - p.point[k]).abs() < 1e-15);
        }
        assert!((p.dir[2] - 1.0).abs() < 1e-14 && p.dir[0].abs() < 1e-14);
        // Below the segment: same distance, direction reversed.
        let p2 = project([0.3, 0.6, -0.25], &x, false);
        assert!((p2.dist - 0.25).abs() < 1e-15);
        assert!((p2.dir[2] + 1.0).abs() < 1e-14);
    }

    #[test]
    fn edge_and_corner_projections_point_radially() {
        let x = square();
        // Beyond the edge x = 1: closest point on the edge, direction radial.
        let p = project([1.3, 0.5, 0.4], &x, false);
        assert!((p.dist - 0.5).abs() < 1e-14);
        assert!((p.dir[0] - 0.6).abs() < 1e-14 && (p.dir[2] - 0.8).abs() < 1e-14);
        assert!(p.shape[0].abs() < 1e-15 && p.shape[3].abs() < 1e-15);
        // Beyond a corner: all weight on that node.
        let c = project([-0.3, -0.4, 0.0], &x, false);
        assert!((c.dist - 0.5).abs() < 1e-14);
        assert!((c.shape[0] - 1.0).abs() < 1e-15);
    }

    #[test]
    fn triangle_segment_and_tetra_sign() {
        let x = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let p = project([0.2, 0.2, -0.1], &x, true);
        assert!((p.dist - 0.1).abs() < 1e-15);
        assert_eq!(p.shape[3], 0.0);
        assert!(tetra_volume6(x[0], x[1], x[2], [0.2, 0.2, -0.1]) < 0.0);
        assert!(tetra_volume6(x[0], x[1], x[2], [0.2, 0.2, 0.1]) > 0.0);
        assert_eq!(segment_normal(&x, true), [0.0, 0.0, 1.0]);
    }

    #[test]
    fn warped_quadrangle_shape_functions_still_reproduce_the_point() {
        let x = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.1],
            [1.2, 1.0, -0.1],
            [0.0, 0.9, 0.05],
        ];
        for p in [[0.5, 0.5, 0.3], [0.9, 0.1, -0.2], [2.0, 2.0, 0.0]] {
            let pr = project(p, &x, false);
            let q = interpolate(&pr.shape, &x);
            for k in 0..3 {
                assert!((q[k] - pr.point[k]).abs() < 1e-14);
            }
            assert!(pr.shape.iter().all(|&s| s >= -1e-15));
        }
    }
}
