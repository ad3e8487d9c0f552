//! One edge pair as the edge-to-edge laws see it (TYPE11's, LS-DYNA's
//! linear penalty on a keyword deck's edges, and the edge part of TYPE25):
//! its inputs, what it gives, how its closest points move, and the force
//! spread on its four nodes so that forces and moments balance (§8.4.5.2).

use super::PairForce;
use crate::contact::edge_geometry::EdgePoints;
use crate::contact::friction::FrictionLaw;
use crate::contact::geometry::{self as geo, V3};

/// One edge pair's inputs: the secondary edge S1–S2 and main edge M1–M2.
pub struct EdgePair<'a> {
    pub xs: [V3; 2],
    pub vs: [V3; 2],
    pub ms: [f64; 2],
    pub xm: [V3; 2],
    pub vm: [V3; 2],
    pub mm: [f64; 2],
    /// Pair stiffness K (Istf).
    pub k: f64,
    pub gap: f64,
    pub viss: f64,
    pub friction: &'a FrictionLaw,
    pub dt: f64,
    /// LS-DYNA's linear penalty (a keyword deck's edges), with SOFSCL when
    /// SOFT = 1 (0 for SOFT = 0); `None`: the Radioss law.
    pub soft: Option<f64>,
}

pub enum EdgeOutcome {
    Free,
    Force(PairForce),
    /// The pair reached the law's gap: its secondary edge leaves the interface.
    Deactivate,
}

/// How the closest points of edge pair `e` move: the unit common normal
/// (from the main edge to the secondary one), the points' weights on each
/// edge, the relative velocity (secondary minus main) and the penetration
/// rate (the two points closing on each other).
pub fn closing(e: &EdgePair, ep: &EdgePoints) -> (V3, [f64; 2], [f64; 2], V3, f64) {
    let n = geo::scale(ep.n, 1.0 / ep.dist);
    let (ws, wm) = ep.weights();
    let lerp = |w: [f64; 2], a: [V3; 2]| geo::add(geo::scale(a[0], w[0]), geo::scale(a[1], w[1]));
    let vrel = geo::sub(lerp(ws, e.vs), lerp(wm, e.vm));
    (n, ws, wm, vrel, -geo::dot(vrel, n))
}

/// The pair force of normal `f_n` (along the unit common normal) and
/// tangential `f_t` on the closest points `ep` of the edges of `e`.
pub fn edge_force(
    e: &EdgePair,
    ep: &EdgePoints,
    (f_n, f_t): (f64, V3),
    k_step: f64,
    dt_kin: f64,
    pen: f64,
) -> EdgeOutcome {
    let n = geo::scale(ep.n, 1.0 / ep.dist);
    let (ws, wm) = ep.weights();
    EdgeOutcome::Force(PairForce {
        fs: geo::add(geo::scale(n, f_n), f_t),
        sec_shape: [ws[0], ws[1], 0.0, 0.0],
        shape: [wm[0], wm[1], 0.0, 0.0],
        kt: k_step,
        dt_kin,
        f_n,
        f_t,
        pen,
        dir: n,
        point: geo::add(geo::scale(e.xs[0], ws[0]), geo::scale(e.xs[1], ws[1])),
    })
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// A secondary edge along x at height z over a main edge along y
    /// (gap 0.1, K = 1000, unit masses, no friction; also TYPE25's edge tests).
    pub(in crate::contact::interfaces) fn crossing(z: f64, vz: f64) -> EdgePair<'static> {
        static NONE: std::sync::OnceLock<FrictionLaw> = std::sync::OnceLock::new();
        EdgePair {
            // Secondary along x at height z over the main edge along y.
            xs: [[-1.0, 0.25, z], [1.0, 0.25, z]],
            vs: [[0.0, 0.0, vz]; 2],
            ms: [1.0, 1.0],
            xm: [[0.5, -1.0, 0.0], [0.5, 1.0, 0.0]],
            vm: [[0.0; 3]; 2],
            mm: [1.0, 1.0],
            k: 1000.0,
            gap: 0.1,
            viss: 0.0,
            friction: NONE.get_or_init(FrictionLaw::none),
            dt: 1e-3,
            soft: None,
        }
    }
}
