//! Closest points of two edges (edge-to-edge contact, /INTER/TYPE11 and the
//! edge part of TYPE19; Radioss Theory Manual §8.4.5.2): the gap around
//! each edge is a capsule, and contact is detected when the distance between
//! the edges' closest points is below the sum of their gaps. The force of a
//! pair is applied at these points and shared by the four nodes with the
//! weights computed here, which keeps forces and (for the normal force,
//! along the line joining the points) moments in equilibrium.
//!
//! The minimum of |P_s − P_m|² over both edge parameters, clamped to the
//! edges in the order main, secondary, main (the order Radioss uses, so that
//! parallel and end-to-end configurations need no branch of their own: the
//! first clamp picks an end and the two others project it).

use super::geometry::V3;
use crate::vec3::{dot, norm, sub};

/// The closest points of a secondary edge S1–S2 and a main edge M1–M2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgePoints {
    /// Weight of S1 in the secondary point P_s = h_s·S1 + (1 − h_s)·S2.
    pub h_s: f64,
    /// Weight of M1 in the main point P_m = h_m·M1 + (1 − h_m)·M2.
    pub h_m: f64,
    /// P_s − P_m: from the main point to the secondary point.
    pub n: V3,
    /// |P_s − P_m|.
    pub dist: f64,
}

impl EdgePoints {
    /// The secondary side's node weights [S1, S2] and the main side's [M1, M2].
    pub fn weights(&self) -> ([f64; 2], [f64; 2]) {
        ([self.h_s, 1.0 - self.h_s], [self.h_m, 1.0 - self.h_m])
    }
}

/// The closest points of edges S1–S2 and M1–M2 (§8.4.5.2, ∂D/∂s = 0 on
/// both parameters, each clamped to its edge). A zero-length edge is a point.
pub fn closest_points_of_edges(s1: V3, s2: V3, m1: V3, m2: V3) -> EdgePoints {
    const TINY: f64 = 1e-20;
    let ds = sub(s2, s1);
    let dm = sub(m2, m1);
    let w = sub(m2, s2);
    let a = dot(ds, ds);
    let c = dot(dm, dm);
    let b = dot(ds, dm);
    let xa = dot(ds, w);
    let xb = -dot(dm, w);
    let det = (a * c - b * b).max(TINY);
    let (a, c) = (a.max(TINY), c.max(TINY));
    // With P_s = S2 − h_s·dS and P_m = M2 − h_m·dM, the stationary point of
    // |P_s − P_m|² solves a·h_s − b·h_m = −XA, −b·h_s + c·h_m = −XB.
    let h_m = ((-b * xa - a * xb) / det).clamp(0.0, 1.0);
    let h_s = ((b * h_m - xa) / a).clamp(0.0, 1.0);
    let h_m = ((b * h_s - xb) / c).clamp(0.0, 1.0);
    let at = |h: f64, p: V3, q: V3| [0, 1, 2].map(|k| h * p[k] + (1.0 - h) * q[k]);
    let n = sub(at(h_s, s1, s2), at(h_m, m1, m2));
    EdgePoints {
        h_s,
        h_m,
        n,
        dist: norm(n),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-14
    }

    /// Brute force: the smallest distance over a fine grid of both parameters.
    fn brute(s1: V3, s2: V3, m1: V3, m2: V3) -> f64 {
        let n = 400;
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let p = [0, 1, 2]
                    .map(|k| u * s1[k] + (1.0 - u) * s2[k] - v * m1[k] - (1.0 - v) * m2[k]);
                best = best.min(norm(p));
            }
        }
        best
    }

    #[test]
    fn crossing_edges_meet_at_their_crossing_point_along_the_common_normal() {
        // Secondary along x at z = 0.3, main along y at z = 0: they cross
        // above (0.25, 0.5) of the main edge's plane.
        let e = closest_points_of_edges(
            [0.0, 0.0, 0.3],
            [1.0, 0.0, 0.3],
            [0.25, -0.5, 0.0],
            [0.25, 1.5, 0.0],
        );
        assert!(close(e.dist, 0.3), "{e:?}");
        assert!(close(e.h_s, 0.75) && close(e.h_m, 0.75), "{e:?}");
        assert!(close(e.n[0], 0.0) && close(e.n[1], 0.0) && close(e.n[2], 0.3));
        let (ws, wm) = e.weights();
        assert!(close(ws[0] + ws[1], 1.0) && close(wm[0] + wm[1], 1.0));
    }

    #[test]
    fn parallel_and_end_cases_give_the_true_distance() {
        let cases: [[V3; 4]; 5] = [
            // Parallel, overlapping, 0.2 apart.
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.5, 0.2, 0.0],
                [1.5, 0.2, 0.0],
            ],
            // Collinear, end to end with a gap of 0.5.
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.5, 0.0, 0.0],
                [2.5, 0.0, 0.0],
            ],
            // T: the main edge's end points at the middle of the secondary edge.
            [
                [0.0, 0.0, 0.0],
                [2.0, 0.0, 0.0],
                [1.0, 0.4, 0.0],
                [1.0, 3.0, 0.0],
            ],
            // Skew edges whose closest points are both ends.
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1.0, 1.0],
                [2.0, 3.0, 1.0],
            ],
            // A zero-length main edge: a point against the secondary edge.
            [
                [0.0, 0.0, 0.0],
                [1.0, 1.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
            ],
        ];
        for [s1, s2, m1, m2] in cases {
            let e = closest_points_of_edges(s1, s2, m1, m2);
            let want = brute(s1, s2, m1, m2);
            assert!((e.dist - want).abs() < 5e-6, "{e:?} against {want}");
            assert!((0.0..=1.0).contains(&e.h_s) && (0.0..=1.0).contains(&e.h_m));
        }
        let e =
            closest_points_of_edges([0.0; 3], [1.0, 0.0, 0.0], [1.5, 0.0, 0.0], [2.5, 0.0, 0.0]);
        assert!(
            close(e.dist, 0.5) && close(e.h_s, 0.0) && close(e.h_m, 1.0),
            "{e:?}"
        );
    }

    #[test]
    fn the_four_node_forces_balance_forces_and_moments() {
        // A force along n at the contact points, shared with the weights:
        // +w on the secondary nodes, −w on the main ones.
        let (s1, s2, m1, m2) = (
            [0.1, -0.3, 0.5],
            [0.9, 0.4, 0.35],
            [0.2, 0.6, 0.0],
            [0.7, -0.5, 0.1],
        );
        let e = closest_points_of_edges(s1, s2, m1, m2);
        let (ws, wm) = e.weights();
        let f = crate::vec3::scale(e.n, 2.5 / e.dist);
        let pts = [s1, s2, m1, m2];
        let w = [ws[0], ws[1], -wm[0], -wm[1]];
        let mut sum = [0.0; 3];
        let mut moment = [0.0; 3];
        for (p, wi) in pts.iter().zip(w) {
            let fi = crate::vec3::scale(f, wi);
            sum = crate::vec3::add(sum, fi);
            moment = crate::vec3::add(moment, crate::vec3::cross(*p, fi));
        }
        assert!(norm(sum) < 1e-14, "{sum:?}");
        assert!(norm(moment) < 1e-14, "{moment:?}");
    }
}
