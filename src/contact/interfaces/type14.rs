//! TYPE14 hyper-ellipsoid to node contact (theory manual §8.9): a rigid
//! analytic surface, |ξ/a|^n + |η/b|^n + |ζ/c|^n = 1 (/SURF/ELLIPS), carried
//! by the rigid body whose /RBODY names it (surf_ID), against secondary
//! nodes. Every secondary node is checked against the ellipsoid each cycle
//! (`CandidateSearch::Analytic`: no segments, no sort).
//!
//! - Geometry (the pure functions below): F(ξ) = Σ|ξ_k/a_k|^n, s = F^{1/n} (the node lies on the ellipsoid
//!   scaled by s), the distance d = (s − 1)·h with h the distance from the
//!   centre to the tangent plane at ξ/s (exact on a sphere: |ξ| − r), the
//!   normal ∇F/|∇F|, the contact point ξ − d·n.
//! - Penetration p = Gap − d (> 0 in contact).
//! - Force (§8.9, reference guide comment 1): with fct_IDld the user gives
//!   the *total* elastic force against the largest penetration: the
//!   interface's resultant is Stif·f(p_max), shared by the nodes in
//!   proportion to their penetration vectors (the runtime's total-force
//!   phases, as TYPE6); without it each node is a linear spring Stif·p.
//! - Viscosity (§8.9: "a local normal viscosity is computed at each
//!   node"; the reference engine's form, docs/notes/
//!   type6_type14_type15_research.md §2.2): each penetrated node takes a
//!   normal damper c = Visc·2·√(k·m), k its stiffness (Stif, or the total
//!   force's share per unit penetration), m its mass, against the normal
//!   speed relative to the surface at its contact point; the normal force
//!   is not clamped at 0, so the damper may pull while the node leaves.
//!   Its stiffness for the nodal step is k + 2c/Δt, as the reference's.
//!   With functions (reference guide /INTER/TYPE14: fct_IDd1 "damping
//!   coefficient vs normal velocity", fct_IDd2 "vs nodal elastic force")
//!   the coefficient is c = Visc·g1(v_n)·g2(F_e), a missing one counting
//!   1 (the reference engine's product, research note §2.2), v_n the
//!   node's normal speed relative to the surface (positive leaving), F_e
//!   its elastic force.
//! - Friction (Fric): each node already in contact at the last cycle takes
//!   an elastic tangential spring of its normal stiffness on its slip
//!   relative to the surface, capped at μ·max(F_n, 0) (incremental,
//!   `Type14::friction`); μ = Fric·gf(F_e) with fct_IDf (§8.9: "a local
//!   friction coefficient is computed at each impacted node, depending upon
//!   elastic force computed at its location"), else Fric.
//! - The reaction, −F at the contact point, goes to the rigid body (force
//!   and moment about its centre). A fixed ellipsoid (no /RBODY) takes none.
//! - Time step: each node's stiffness enters its nodal step (EQ. 8.8.5.2);
//!   the body's, √(2M/K) with K the larger of the tangent and the secant of
//!   Stif·f at p_max, the global minimum as an interface step; without
//!   fct_IDld, the smaller of √(2M/K) and √(2J/K_r) with K the sum of the
//!   node springs' stiffnesses and K_r = Σ k·r² about the body's centre
//!   (`contact::pairs`, for every analytic surface on a body).

use super::ellipsoid::{self, distance, shape_value, Carried};
use super::layout::{Interface, Pass};
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes, NODE_SHAPE,
};
use crate::contact::gap::GapRule;
use crate::contact::geometry as geo;
use crate::kinematics::function;
use crate::model::{self, Function, InterfaceKind};
use serde::{Deserialize, Serialize};

/// TYPE14's own options; the ellipsoid, its body and the load curve are
/// bound from the model (`bind`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type14 {
    pub surf_idm: model::Id,
    pub fct_id_ld: model::Id,
    pub stif: f64,
    pub gap: f64,
    /// The ellipsoid and the rigid body carrying it (bound from the model).
    pub carried: Option<Carried>,
    /// The load curve f(p) (fct_IDld), `None`: linear node springs.
    pub load: Option<Function>,
    /// Visc: the critical damping fraction of each penetrated node's normal
    /// damper, c = Visc·2·√(k·m) (k the node's stiffness, m its mass).
    #[serde(default)]
    pub visc: f64,
    /// fct_IDf, fct_IDd1, fct_IDd2 and their curves (bound from the model).
    #[serde(default)]
    pub fct_ids: [model::Id; 3],
    #[serde(default)]
    pub friction_factor: Option<Function>,
    #[serde(default)]
    pub damping_of_speed: Option<Function>,
    #[serde(default)]
    pub damping_of_force: Option<Function>,
}

impl Type14 {
    /// The normal damper's coefficient for stiffness `k`, mass `m`, normal
    /// speed `v_n` and elastic force `f_e` (module comment).
    fn damping(&self, k: f64, m: f64, v_n: f64, f_e: f64) -> f64 {
        if self.damping_of_speed.is_none() && self.damping_of_force.is_none() {
            return self.visc * 2.0 * (k * m).sqrt();
        }
        let g = |f: &Option<Function>, x: f64| super::curve_at(f, x, 1.0, 1.0);
        self.visc * g(&self.damping_of_speed, v_n) * g(&self.damping_of_force, f_e)
    }

    /// Stif·f(p) and its slope.
    fn curve(&self, p: f64) -> (f64, f64) {
        match &self.load {
            Some(f) => function::scaled_with_slope(f, p, 1.0, self.stif),
            None => (self.stif * p, self.stif),
        }
    }
}

impl InterfaceType for Type14 {
    fn type_number(&self) -> u32 {
        14
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToEllipsoid
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Analytic
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type14(t) = kind else {
            return None;
        };
        let common = ellipsoid::card_common(t.fric, t.gap);
        let own = Type14 {
            surf_idm: t.surf_idm,
            fct_id_ld: t.fct_id_ld,
            stif: t.stif,
            gap: t.gap,
            visc: t.visc,
            fct_ids: [t.fct_id_f, t.fct_id_d1, t.fct_id_d2],
            ..Default::default()
        };
        Some((own, common))
    }


    /// The ellipsoid (surf_IDm), the rigid body whose /RBODY names it
    /// (none: the ellipsoid stays where it is), and the load curve.
    fn bind(&mut self, m: &model::Model, i: &model::Interface, kw: &str) -> Result<(), String> {
        let carried = ellipsoid::bind(m, self.surf_idm, kw)?;
        if self.stif <= 0.0 {
            return Err(format!(
                "{kw}, field Stif: 0: expected the stiffness (with fct_IDld, the scale of its force) > 0"
            ));
        }
        if let Some(b) = carried.body.map(|b| &m.rigid_bodies[b]) {
            if let Some(n) = i.secondary_nodes.iter().find(|&&n| b.holds(n)) {
                return Err(format!(
                    "{kw}, field grnd_IDs: node {} is on /RBODY/{}, which carries the \
                     ellipsoid: expected nodes off the ellipsoid's body",
                    m.nodes.ids[*n as usize], b.card.id
                ));
            }
        }
        self.carried = Some(carried);
        if self.fct_id_ld != 0 {
            self.load = Some(super::bound_curve(m, self.fct_id_ld, kw, "fct_IDld")?);
        }
        let curve = |id: model::Id, field: &str| super::optional_curve(m, id, kw, field);
        self.friction_factor = curve(self.fct_ids[0], "fct_IDf")?;
        self.damping_of_speed = curve(self.fct_ids[1], "fct_IDd1")?;
        self.damping_of_force = curve(self.fct_ids[2], "fct_IDd2")?;
        Ok(())
    }

    fn gap_rule(&self, common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        super::type5::constant_gap(common.gap_card)
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

    fn is_total_force(&self) -> bool {
        self.load.is_some()
    }

    /// Stif·f(p_max), and the body's step √(2M/K).
    fn total_force(&self, p_max: f64, _memory: &mut [f64; 2]) -> (f64, f64) {
        if p_max <= 0.0 {
            return (0.0, f64::INFINITY);
        }
        let (f, tangent) = self.curve(p_max);
        let k = tangent.max(f / p_max);
        let dt = match &self.carried {
            Some(c) if c.body.is_some() && k > 0.0 => (2.0 * c.body_mass / k).sqrt(),
            _ => f64::INFINITY,
        };
        (f.max(0.0), dt)
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let Some(carried) = self.carried.as_ref() else {
            return PairOutcome::Free;
        };
        let (pose, e) = (carried.pose(c.bodies), &carried.ellipsoid);
        let xi = pose.local(c.xs);
        // Screen: the node within the ellipsoid grown by the gap.
        let a_min = e.axes.iter().copied().fold(f64::INFINITY, f64::min);
        let reach = (1.0 + self.gap / a_min).powi(e.n as i32);
        if shape_value(xi, e.axes, e.n) > reach {
            return PairOutcome::Free;
        }
        let Some((d, n_local)) = distance(xi, e.axes, e.n) else {
            return PairOutcome::Free;
        };
        let pen = self.gap - d;
        if pen <= 0.0 {
            if c.scale.is_some() || self.load.is_none() {
                *st = PairState::default();
            }
            return PairOutcome::Free;
        }
        let n = pose.turn(n_local);
        let point = pose.global(geo::sub(xi, geo::scale(n_local, d)));
        let k = match (&self.load, c.scale) {
            (None, _) => self.stif,
            (Some(_), Some(fac)) => fac,
            // Measuring (total force): the penetration vector.
            (Some(_), None) => {
                return PairOutcome::Force(PairForce {
                    fs: geo::scale(n, pen),
                    sec_shape: NODE_SHAPE,
                    shape: [0.0; 4],
                    dt_kin: f64::INFINITY,
                    f_n: pen,
                    pen,
                    dir: n,
                    point,
                    ..Default::default()
                })
            }
        };
        // The normal damper against the surface's velocity at the node's
        // contact point (the body's motion there; a fixed ellipsoid's is 0).
        let v_surface = carried.surface_velocity(c.bodies, point);
        let v_rel = geo::sub(c.vs, v_surface);
        let v_n = geo::dot(v_rel, n);
        let f_e = k * pen;
        let c_d = self.damping(k, c.ms, v_n, f_e);
        let f_n = f_e - c_d * v_n;
        let kt = if c.dt > 0.0 { k + 2.0 * c_d / c.dt } else { k };
        let law = &c.it.friction;
        let mu = law.fric * super::curve_at(&self.friction_factor, f_e, 1.0, 1.0);
        let f_t = ellipsoid::friction(law, mu, k, f_n, v_rel, n, c.dt, st);
        PairOutcome::Force(PairForce {
            fs: geo::add(geo::scale(n, f_n), f_t),
            sec_shape: NODE_SHAPE,
            shape: [0.0; 4],
            kt,
            dt_kin: f64::INFINITY,
            f_n,
            f_t,
            pen,
            dir: n,
            point,
        })
    }
}
