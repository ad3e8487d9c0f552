//! TYPE15 hyper-ellipsoid to segment contact (theory manual §8.10): the
//! rigid analytic surface of /SURF/ELLIPS, carried by the rigid body whose
//! /RBODY names it (surf_ID), against the segments of a surface. It sees an
//! ellipsoid that falls between the nodes of a mesh coarser than itself,
//! which TYPE14 (nodes) misses.
//!
//! - Facets: a 3-node segment is one triangle; a 4-node one is split into
//!   the four triangles (G, N_k, N_k+1) around its centre G (the
//!   reference's split, docs/notes/type6_type14_type15_research.md §2.3).
//!   Each triangle is a secondary entity of its own (the quad's nodes
//!   turned so that N_k, N_k+1 come first, `triangles`), with its own
//!   contact memory; the share of G goes a quarter to each quad node.
//! - Geometry (`facet_contact`, pure, in the ellipsoid's axes): the
//!   ellipsoid's point farthest across the facet's plane (the support point
//!   of the normal pointing from the centre to the plane) is projected onto
//!   the plane and then to the nearest point K of the triangle; the facet
//!   is in contact when K is inside the ellipsoid. The contact point M on
//!   the surface is K moved out by its distance (§8.9's d = (s − 1)·h) and
//!   put on the surface along its ray; n̂ the normal there, the depth
//!   D = M·n̂ (the distance from the centre to the tangent plane at M) and
//!   the penetration p = (M − K)·n̂.
//! - Force (§8.10): "non-linear increasing function of penetration,
//!   computed in order to avoid penetrations up to half the ellipsoid":
//!   K = Stif·[D/(D − p)]², F_n = K·p along n̂, on the facet; no damping
//!   (the starter sets Visc 0). A facet whose penetration reaches the
//!   centre plane (D − p < 1e-10·D) leaves the interface for good, as the
//!   reference's does.
//! - Friction (§8.10: F_t ≤ μ·F_n for each penetrated element; sliding and
//!   rolling): an elastic tangential spring of stiffness K on the facet's
//!   slip against the surface's velocity at M (the body's motion there),
//!   capped at Fric·F_n (`ellipsoid::friction`), from the second cycle of
//!   a contact.
//! - The reaction, −F at M, goes to the rigid body (force and moment about
//!   its centre): a ball rolls.
//! - Time step (§8.10: "a kinematic time step keeps the element from
//!   crossing the line L_t within one step"): for each corner V of a facet
//!   in contact that approaches the plane L_t through the centre normal to
//!   n̂, 0.5·h_V/|v_n| (h_V its distance to L_t, v_n its normal speed
//!   relative to the surface), an interface step in the global minimum;
//!   the tangent stiffness dF/dp = Stif·D²·(D + p)/(D − p)³ enters the
//!   facet nodes' nodal step (EQ. 8.8.5.2), and the body's: the smaller of
//!   √(2M/K) and √(2J/K_r) over its facets in contact (K = Σ k, K_r =
//!   Σ k·r² about its centre, J its smallest principal inertia), as the
//!   reference adds them to the body's main node.

use super::ellipsoid::{self, Carried, Pose};
use super::layout::{Interface, Pass};
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, PassSides, SurfaceSizes,
};
use crate::contact::gap::GapRule;
use crate::contact::geometry::{self as geo, V3};
use crate::model::{self, InterfaceKind};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

/// TYPE15's own options; the ellipsoid and its body are bound from the
/// model (`bind`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type15 {
    pub surf_idm: model::Id,
    /// Stif: the stiffness at zero penetration.
    pub stif: f64,
    /// The ellipsoid and the rigid body carrying it (bound from the model).
    pub carried: Option<Carried>,
}

/// The secondary entities of a surface: each 3-node segment as it is, each
/// 4-node one four times, turned so that triangle k's corners N_k, N_k+1
/// come first (its third corner is the centre of all four nodes).
pub fn triangles(segments: &[[u32; 4]]) -> Vec<[u32; 4]> {
    let mut out = Vec::with_capacity(4 * segments.len());
    for s in segments {
        if s[3] == s[2] {
            out.push(*s);
        } else {
            out.extend((0..4).map(|k| [0, 1, 2, 3].map(|j| s[(k + j) % 4])));
        }
    }
    out
}

/// One facet against the ellipsoid, in its axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FacetContact {
    /// Barycentric weights of K on the triangle's corners (t0, t1, t2).
    pub bary: [f64; 3],
    /// The contact point M on the surface, the outward normal there, the
    /// depth D = M·n̂ and the penetration p = (M − K)·n̂ (> 0).
    pub point: V3,
    pub normal: V3,
    pub depth: f64,
    pub pen: f64,
}

/// Triangle t (local coordinates) against the ellipsoid (axes, n): `None`
/// when it is clear of it (module comment, Geometry).
pub fn facet_contact(t: [V3; 3], axes: V3, n: u32) -> Option<FacetContact> {
    let m = geo::cross(geo::sub(t[1], t[0]), geo::sub(t[2], t[0]));
    let len = geo::norm(m);
    if len == 0.0 {
        return None;
    }
    let m = geo::scale(m, 1.0 / len);
    // w points from the centre to the plane, at distance h_p along it.
    let h_c = geo::dot(m, t[0]);
    let w = if h_c >= 0.0 { m } else { geo::scale(m, -1.0) };
    let h_p = h_c.abs();
    let h = ellipsoid::support(w, axes, n);
    let h_h = geo::dot(w, h);
    if h_h <= h_p {
        return None;
    }
    let k0 = geo::sub(h, geo::scale(w, h_h - h_p));
    let bary = geo::closest_on_triangle(k0, t[0], t[1], t[2]);
    let k = [0, 1, 2].map(|i| (0..3).map(|c| bary[c] * t[c][i]).sum::<f64>());
    if ellipsoid::shape_value(k, axes, n) > 1.0 {
        return None;
    }
    let (d, nk) = ellipsoid::distance(k, axes, n).unwrap_or((-h_h, w));
    let point = ellipsoid::onto_surface(geo::sub(k, geo::scale(nk, d)), axes, n)?;
    let g = ellipsoid::shape_gradient(point, axes, n);
    let normal = geo::scale(g, 1.0 / geo::norm(g));
    let depth = geo::dot(point, normal);
    let pen = geo::dot(geo::sub(point, k), normal);
    (pen > 0.0).then_some(FacetContact {
        bary,
        point,
        normal,
        depth,
        pen,
    })
}

/// F_n = Stif·[D/(D − p)]²·p and its slope dF/dp = Stif·D²·(D + p)/(D − p)³
/// (§8.10).
pub fn normal_force(stif: f64, depth: f64, pen: f64) -> (f64, f64) {
    let r = depth - pen;
    let k = stif * depth * depth / (r * r);
    (k * pen, k * (depth + pen) / r)
}

/// A facet's three corners from its entity's node values `x` (positions
/// or velocities): N_k, N_k+1 and the centre of a quad, or a triangle's.
fn facet(x: &[V3; 4], quad: bool) -> [V3; 3] {
    let third = if quad {
        geo::scale(x.iter().fold([0.0; 3], |a, &y| geo::add(a, y)), 0.25)
    } else {
        x[2]
    };
    [x[0], x[1], third]
}

/// The weights on the entity's nodes of the facet point of barycentric
/// weights `b`: a quad's centre shares its weight among the four nodes.
fn node_weights(b: [f64; 3], quad: bool) -> [f64; 4] {
    if quad {
        let g = 0.25 * b[2];
        [b[0] + g, b[1] + g, g, g]
    } else {
        [b[0], b[1], b[2], 0.0]
    }
}

impl Type15 {
    /// 0.5·h_V/|v_n| over the corners closing on the plane L_t through the
    /// centre normal to n (global): the interface's kinematic step.
    fn kinematic(pose: &Pose, t: &[V3; 3], v: &[V3; 3], v_surface: V3, n: V3) -> f64 {
        let mut dt = f64::INFINITY;
        for (x, vx) in t.iter().zip(v) {
            let v_n = geo::dot(geo::sub(*vx, v_surface), n);
            let h = geo::dot(geo::sub(*x, pose.center), n);
            if v_n < 0.0 && h > 0.0 {
                dt = dt.min(0.5 * h / -v_n);
            }
        }
        dt
    }
}

impl InterfaceType for Type15 {
    fn type_number(&self) -> u32 {
        15
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::SegmentToEllipsoid
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Analytic
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type15(t) = kind else {
            return None;
        };
        let common = ellipsoid::card_common(t.fric, 0.0);
        let own = Type15 {
            surf_idm: t.surf_idm,
            stif: t.stif,
            ..Default::default()
        };
        Some((own, common))
    }

    /// The secondary surface's triangles against the ellipsoid.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<PassSides<'a>> {
        vec![PassSides {
            sec: Vec::new(),
            own: None,
            main: &i.main_segments,
            sec_edges: &[],
            main_edges: &[],
            sec_segs: Cow::Owned(triangles(&i.secondary_segments)),
            self_contact: false,
        }]
    }

    /// The ellipsoid (surf_IDm) and the rigid body whose /RBODY names it
    /// (none: it stays where it is); a secondary segment on that body is an
    /// error.
    fn bind(&mut self, m: &model::Model, i: &model::Interface, kw: &str) -> Result<(), String> {
        let carried = ellipsoid::bind(m, self.surf_idm, kw)?;
        if let Some(b) = carried.body.map(|b| &m.rigid_bodies[b]) {
            if let Some(s) = i.secondary_segments.iter().find(|s| s.iter().all(|&n| b.holds(n))) {
                return Err(format!(
                    "{kw}, field surf_IDs: the segment of nodes {} is on /RBODY/{}, which \
                     carries the ellipsoid: expected segments off the ellipsoid's body",
                    s.iter().map(|&n| m.nodes.ids[n as usize].to_string()).collect::<Vec<_>>().join(" "),
                    b.card.id
                ));
            }
        }
        self.carried = Some(carried);
        Ok(())
    }

    fn gap_rule(&self, _common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        super::type5::constant_gap(0.0)
    }

    fn sorting_margin(&self) -> f64 {
        super::type5::DEFAULT_BUMULT
    }

    /// Not used: the ellipsoid has no segments.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        crate::contact::stiffness::brick_type3(bulk, area, volume)
    }

    fn pair_stiffness(&self, _it: &Interface, _p: &Pass, _k: usize, _m: usize) -> f64 {
        self.stif
    }

    fn reaction_body(&self) -> Option<usize> {
        self.carried.as_ref()?.body
    }

    fn kinematic_step(&self, f: &PairForce) -> Option<f64> {
        Some(f.dt_kin)
    }

    fn pair(&self, c: &PairContext, ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let Some(carried) = self.carried.as_ref() else {
            return PairOutcome::Free;
        };
        let (pose, e) = (carried.pose(c.bodies), &carried.ellipsoid);
        let quad = c.sec.count == 4;
        let t = facet(c.xs_side, quad);
        let Some(fc) = facet_contact(t.map(|x| pose.local(x)), e.axes, e.n) else {
            *st = PairState::default();
            return PairOutcome::Free;
        };
        if fc.depth - fc.pen < 1e-10 * fc.depth {
            ns.off = true;
            return PairOutcome::NodeOff;
        }
        let sec_shape = node_weights(fc.bary, quad);
        let n = pose.turn(fc.normal);
        let point = pose.global(fc.point);
        let (f_n, kt) = normal_force(self.stif, fc.depth, fc.pen);
        let v_surface = carried.surface_velocity(c.bodies, point);
        let v_rel = geo::sub(geo::interpolate(&sec_shape, c.vs_side), v_surface);
        let k = f_n / fc.pen;
        let f_t = ellipsoid::friction(&c.it.friction, c.it.friction.fric, k, f_n, v_rel, n, c.dt, st);
        PairOutcome::Force(PairForce {
            fs: geo::add(geo::scale(n, f_n), f_t),
            sec_shape,
            shape: [0.0; 4],
            kt,
            dt_kin: Self::kinematic(&pose, &t, &facet(c.vs_side, quad), v_surface, n),
            f_n,
            f_t,
            pen: fc.pen,
            dir: n,
            point,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quad_gives_four_turned_triangles_and_a_triangle_one() {
        let t = triangles(&[[1, 2, 3, 4], [5, 6, 7, 7]]);
        assert_eq!(
            t,
            vec![[1, 2, 3, 4], [2, 3, 4, 1], [3, 4, 1, 2], [4, 1, 2, 3], [5, 6, 7, 7]]
        );
    }

    #[test]
    fn a_sphere_on_a_facet_penetrates_by_its_radius_less_the_plane_distance() {
        // Plane z = -9 under a sphere of radius 10: p = 1, D = 10, M = (0, 0, -10).
        let t = [[-20.0, -20.0, -9.0], [40.0, -20.0, -9.0], [-20.0, 40.0, -9.0]];
        let fc = facet_contact(t, [10.0; 3], 2).unwrap();
        assert!((fc.pen - 1.0).abs() < 1e-12, "{fc:?}");
        assert!((fc.depth - 10.0).abs() < 1e-12);
        assert!(geo::norm(geo::sub(fc.point, [0.0, 0.0, -10.0])) < 1e-12);
        assert!(geo::norm(geo::sub(fc.normal, [0.0, 0.0, -1.0])) < 1e-12);
        // The weights give K = (0, 0, -9).
        let k = [0, 1, 2].map(|i| (0..3).map(|c| fc.bary[c] * t[c][i]).sum::<f64>());
        assert!(geo::norm(geo::sub(k, [0.0, 0.0, -9.0])) < 1e-12);
        // The same facet either way round, and from above.
        let r = facet_contact([t[0], t[2], t[1]], [10.0; 3], 2).unwrap();
        assert!((r.pen - 1.0).abs() < 1e-12);
        let up = t.map(|x| [x[0], x[1], 9.0]);
        let u = facet_contact(up, [10.0; 3], 2).unwrap();
        assert!((u.pen - 1.0).abs() < 1e-12 && u.normal[2] > 0.99);
        // Clear of it: the plane beyond the radius, or the nearest point of
        // a small triangle off to the side outside the sphere.
        assert!(facet_contact(t.map(|x| [x[0], x[1], -10.5]), [10.0; 3], 2).is_none());
        let side = [[30.0, 0.0, -9.0], [40.0, 0.0, -9.0], [30.0, 10.0, -9.0]];
        assert!(facet_contact(side, [10.0; 3], 2).is_none());
    }

    #[test]
    fn a_facet_beside_the_lowest_point_meets_the_sphere_at_its_nearest_point() {
        // The triangle stops at x = 3: K = (3, 0, -9), inside (|K|² = 90).
        let t = [[3.0, -20.0, -9.0], [3.0, 20.0, -9.0], [30.0, 0.0, -9.0]];
        let fc = facet_contact(t, [10.0; 3], 2).unwrap();
        let k = [3.0, 0.0, -9.0];
        let r = geo::norm(k);
        assert!((fc.pen - (10.0 - r)).abs() < 1e-12, "{fc:?}");
        assert!(geo::norm(geo::sub(fc.normal, geo::scale(k, 1.0 / r))) < 1e-12);
        assert!((fc.depth - 10.0).abs() < 1e-12);
    }

    #[test]
    fn the_force_stiffens_as_the_facet_nears_the_centre() {
        let (f, k) = normal_force(2.0, 10.0, 0.0);
        assert_eq!((f, k), (0.0, 2.0));
        let (f, k) = normal_force(2.0, 10.0, 5.0);
        assert!((f - 2.0 * 4.0 * 5.0).abs() < 1e-12);
        // Tangent = the derivative, by central difference.
        let h = 1e-5;
        let d = (normal_force(2.0, 10.0, 5.0 + h).0 - normal_force(2.0, 10.0, 5.0 - h).0) / (2.0 * h);
        assert!((k - d).abs() < 1e-6 * k, "{k} {d}");
    }
}
