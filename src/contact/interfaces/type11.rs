//! TYPE11 edge-to-edge penalty contact (Theory Manual §8.4.5.2; reference
//! card /INTER/TYPE11): the gap of each edge is a cylinder around it, a pair
//! of edges is in contact when the distance between their closest points is
//! below the pair's gap, and the penalty force "is calculated as in
//! node-to-segment contact" (TYPE7, §8.8) and applied to the four nodes so
//! that forces and moments balance (`contact::edge_geometry`).
//!
//! The law, with K the pair stiffness (Istf, below), g the pair gap and
//! p = g − d the penetration, follows the reference engine (gathered in
//! docs/notes/type11_type19_research.md §7; its form is EQ. 8.8.9.1–2 and
//! 8.8.3.3–4 with K0 = K/2 and Gap = 0.9·g):
//! - g' = 0.9·g; Ks = ½·K·g'/(g' − p); elastic force Ks·p (EQ. 8.8.9.1);
//! - a pair that reaches p ≥ g' deactivates its secondary edge (as a TYPE7
//!   node at the mid-plane, §8.8.11.1);
//! - damper C = VISs·√(2·K·M) with K = Kt = Ks·g'/(g' − p) while closing
//!   and Ks while opening, plus 0.4²·2·M·(dp/dt)/(g' − p) while closing;
//!   M is the smaller of the two sides' interpolated nodal masses. The
//!   damper never makes the normal force pull: |F_n| ≥ 0;
//! - Coulomb friction with Iform 1 (viscous, VISF·√(2·K·M)) or 2
//!   (incremental), μ = Fric (EQ. 8.8.3.4–5);
//! - kinematic time step 0.5·(g' − p)/(dp/dt) (EQ. 8.8.5.1); the tangent
//!   stiffness ½·K·g'²/(g' − p)² (EQ. 8.8.9.2) enters the nodal step.
//!
//! Pair stiffness (card Istf; Stfac multiplies each edge's k = E·t on
//! shells, B·V/L² on solids, `contact::edge_setup`): 5 (default) the two
//! edges in series (EQ. 8.5.3.1), 2 mean, 3 max, 4 min, each held in
//! [Stmin, Stmax]; 1: every edge has stiffness Stfac, so the pair Stfac/2
//! (series, not held).
//!
//! Gap (card Igap): 1000 constant Gapmin; 1 variable max(Gapmin, g_s + g_m)
//! with the edges' half shell thicknesses; 3 also at most %mesh_size times
//! the sum of the edges' lengths.
//!
//! The edge part of a keyword deck's `*CONTACT_AUTOMATIC_GENERAL`
//! (`Type11::dyna`) runs LS-DYNA's penalty instead, as its node part does
//! (`type7`'s `DynaPenalty`): each edge's stiffness is the SOFT = 0 rule of
//! the shell under it (SLSFAC·SFS·K·A/d_max; LS-DYNA documents edge contact
//! as the shell's contact surface wrapped around its free edge, with the
//! shell's penalty: its edge stiffness formula is not published, so the
//! segment's is taken), the pair takes the smaller of its two edges'
//! (SOFT = 1: at least 0.5·SOFSCL·m*/Δt², m* the smaller edge mass); the
//! force is linear, F = K·p, through the whole gap (no 0.9 fraction, no
//! deactivation: edges that cross release the pair), damped by VDC % of
//! critical, 2·√(K·M).
//!
//! The edge part of a /INTER/TYPE25 with Iedge (`Type11::penalty25`) runs
//! TYPE25's edge penalty (`type25::edge_pair`): its gap the two half
//! thicknesses scaled and capped as TYPE25's, its stiffness by TYPE25's
//! Istf.

use std::borrow::Cow;
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes,
};
use super::edge_pair::{closing, edge_force, EdgeOutcome, EdgePair};
use super::layout::{Interface, Pass};
use crate::contact::edge_geometry::closest_points_of_edges;
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::GapRule;
use crate::contact::stiffness;
use crate::model::InterfaceKind;
use serde::{Deserialize, Serialize};

/// The fraction of the gap the elastic law works in (reference engine).
pub const GAP_FRACTION: f64 = 0.9;

/// TYPE11's own options.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type11 {
    pub istf: i64,
    pub stmin: f64,
    pub stmax: f64,
    pub viss: f64,
    pub bumult: f64,
    /// Igap (1000 constant, 1, 3), Gapmin (0: the default), %mesh_size.
    pub igap: i64,
    pub gapmin: f64,
    pub mesh_size_pct: f64,
    /// A keyword deck's penalty (module comment).
    pub dyna: Option<crate::model::contact::DynaPenalty>,
    /// The edge part of a TYPE25 with Iedge: TYPE25's penalty (module comment).
    #[serde(default)]
    pub penalty25: Option<crate::model::contact::Penalty25>,
}

impl InterfaceType for Type11 {
    fn type_number(&self) -> u32 {
        11
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type11(t) = kind else {
            return None;
        };
        let refused = [
            (t.sens_id != 0, "an activation sensor (sens_ID)"),
            (t.ithe != 0, "heat transfer (Ithe)"),
            (t.fric_id != 0, "friction from /FRICTION (fric_ID)"),
            (t.irem_gap == 2, "removal of close neighbour lines (Irem_gap = 2)"),
            (
                !matches!(t.inacti, 0 | 1 | 2 | 1000),
                "an initial-penetration treatment other than Inacti 0, 1, 2",
            ),
            (t.dtmin > 0.0, "a minimum interface time step (dtmin)"),
            (t.ibc.iter().any(|&b| b), "boundary-condition release at impact (IBC)"),
        ];
        refused.into_iter().find(|r| r.0).map(|r| r.1)
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::EdgeToEdge
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Sort
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type11(t) = kind else {
            return None;
        };
        let common = CardCommon {
            stfac: t.stfac,
            friction: FrictionLaw {
                ifric: 0,
                fric: t.fric,
                iform: if t.iform == 2 { 2 } else { 1 },
                visf: t.visf,
                ..FrictionLaw::none()
            },
            gap_card: t.gapmin,
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: t.ibc,
            inacti: t.inacti,
            idel: t.idel,
        };
        let own = Type11 {
            istf: t.istf,
            stmin: t.stmin,
            stmax: t.stmax,
            viss: t.viss,
            bumult: t.bumult,
            igap: t.igap,
            gapmin: t.gapmin,
            mesh_size_pct: t.mesh_size_pct,
            dyna: t.dyna,
            penalty25: t.penalty25,
        };
        Some((own, common))
    }

    /// Both sides are edges: one pass, the secondary line's edges against
    /// the main line's (the same edges in self-contact).
    fn passes<'a>(&self, i: &'a crate::model::Interface) -> Vec<super::PassSides<'a>> {
        let self_contact = match &i.card.kind {
            InterfaceKind::Type11(t) => t.line_idm == 0 || t.line_idm == t.line_ids,
            _ => false,
        };
        vec![super::PassSides {
            sec: Vec::new(),
            own: None,
            main: &[],
            sec_edges: &i.secondary_edges,
            main_edges: &i.main_edges,
            sec_segs: Cow::Borrowed(&[]),
            self_contact,
        }]
    }

    fn igap(&self) -> i64 {
        self.igap
    }

    fn gap_rule(&self, _common: &CardCommon, sizes: &SurfaceSizes) -> GapRule {
        if let Some(p) = &self.penalty25 {
            return super::type25::gap_rule(p);
        }
        GapRule {
            igap: if self.igap == 0 { 1000 } else { self.igap },
            gapmin: if self.gapmin > 0.0 {
                self.gapmin
            } else {
                sizes.edge_gapmin
            },
            fscalegap: 1.0,
            gapmax: crate::model::contact::EP30,
            mesh_size_pct: self.mesh_size_pct,
        }
    }

    fn sorting_margin(&self) -> f64 {
        self.bumult
    }

    /// Not used: an edge's solid stiffness is B·V/L² (`contact::edge_setup`).
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        stiffness::brick_type7(bulk, area, volume)
    }

    /// A keyword deck's edge: the SOFT = 0 rule of its shell (SLSFAC·SFS on
    /// the secondary edges, SLSFAC·SFM on the main ones).
    fn element_stiffness(&self, el: &stiffness::ElementSize, main: bool) -> Option<f64> {
        let d = self.dyna?;
        let f = d.slsfac * if main { d.sfm } else { d.sfs };
        Some(stiffness::dyna_soft0(f, el))
    }

    /// By Istf; a keyword deck's: the smaller of the two edges'; a TYPE25's
    /// by its Istf (1000: the main edge's).
    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        if self.dyna.is_some() {
            return p.sec_k[k].min(p.seg_k[m]);
        }
        if let Some(q) = &self.penalty25 {
            let (ks, km) = (it.stfac * p.sec_k[k], it.stfac * p.seg_k[m]);
            return super::type25::pair_stiffness_of(q, ks, km);
        }
        edge_pair_stiffness(self.istf, it.stfac, p.sec_k[k], p.seg_k[m], self.stmin, self.stmax)
    }

    #[inline]
    fn pair(&self, c: &PairContext, ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let (it, p, k, m) = (c.it, c.p, c.k, c.m as usize);
        let mass = |side: &super::Side, j: usize| c.cnode_mass[side.nodes[j] as usize];
        let inp = EdgePair {
            xs: [c.xs_side[0], c.xs_side[1]],
            vs: [c.vs_side[0], c.vs_side[1]],
            ms: [mass(&c.sec, 0), mass(&c.sec, 1)],
            xm: [c.xm[0], c.xm[1]],
            vm: [c.vm[0], c.vm[1]],
            mm: [mass(&c.main, 0), mass(&c.main, 1)],
            k: self.pair_stiffness(it, p, k, m),
            gap: match &self.penalty25 {
                Some(q) => super::type25::pair_gap(q, p.sec_gap[k], p.seg_gap[m], [f64::INFINITY; 2]),
                None => it.pair_gap(p, k, m),
            },
            viss: self.viss,
            friction: &it.friction,
            dt: c.dt,
            soft: self.dyna.map(|d| if d.soft == 1 { d.sofscl } else { 0.0 }),
        };
        let out = match &self.penalty25 {
            Some(q) => super::type25::edge_pair(&inp, q, st),
            None => edge_pair(&inp, st),
        };
        match out {
            EdgeOutcome::Free => PairOutcome::Free,
            EdgeOutcome::Force(f) => PairOutcome::Force(f),
            EdgeOutcome::Deactivate => {
                ns.off = true;
                PairOutcome::NodeOff
            }
        }
    }

    /// EQ. 8.8.5.1 with the law's gap: 0.5·(g' − p)/(dp/dt).
    fn kinematic_step(&self, f: &PairForce) -> Option<f64> {
        Some(f.dt_kin)
    }
}

/// The pair stiffness from the edges' stiffnesses `ks`, `km` (without Stfac).
pub fn edge_pair_stiffness(istf: i64, stfac: f64, ks: f64, km: f64, stmin: f64, stmax: f64) -> f64 {
    let (ks, km) = (stfac * ks, stfac * km);
    let k = match istf {
        1 => return stiffness::series(stfac, stfac),
        2 => 0.5 * (ks + km),
        3 => ks.max(km),
        4 => ks.min(km),
        _ => stiffness::series(ks, km),
    };
    stmin.max(stmax.min(k))
}

/// The elastic force and tangent stiffness at penetration `p` of the law's
/// gap `gl` = 0.9·g with pair stiffness `k`: ½·K·gl·p/(gl − p) and
/// ½·K·gl²/(gl − p)².
pub fn edge_reaction(k: f64, gl: f64, p: f64) -> (f64, f64) {
    stiffness::type7_reaction(0.5 * k, gl, p)
}

/// The force of one edge pair (see the module's comment).
pub fn edge_pair(e: &EdgePair, st: &mut PairState) -> EdgeOutcome {
    if let Some(sofscl) = e.soft {
        return linear_edge_pair(e, sofscl, st);
    }
    let ep = closest_points_of_edges(e.xs[0], e.xs[1], e.xm[0], e.xm[1]);
    if ep.dist >= e.gap || e.k <= 0.0 {
        st.ft = [0.0; 3];
        return EdgeOutcome::Free;
    }
    let gl = GAP_FRACTION * e.gap;
    let pen = e.gap - ep.dist;
    if (gl - pen) <= 1e-10 * gl {
        return EdgeOutcome::Deactivate;
    }
    let (n, ws, wm, vrel, dpdt) = closing(e, &ep);
    let (f_el, kt) = edge_reaction(e.k, gl, pen);
    let ks = f_el / pen;
    let mass = (ws[0] * e.ms[0] + ws[1] * e.ms[1]).min(wm[0] * e.mm[0] + wm[1] * e.mm[1]);
    let kd = if dpdt > 0.0 { kt } else { ks };
    let mut c = e.viss * (2.0 * kd * mass).sqrt();
    if dpdt > 0.0 {
        c += 0.4 * 0.4 * 2.0 * mass * dpdt / (gl - pen);
    }
    // The damper brakes closing and opening alike but never pulls.
    let f_n = (f_el + c * dpdt).max(0.0);
    let mut f_t = [0.0; 3];
    if e.friction.active() && f_n > 0.0 {
        let vt = friction::tangential(vrel, n);
        let k = if e.friction.iform == 1 { kd } else { 0.5 * e.k };
        f_t = friction::tangential_force(
            e.friction, e.friction.fric, f_n, vt, n, k, mass, e.dt, &mut st.ft,
        );
    }
    let dt_kin = if dpdt > 0.0 {
        0.5 * (gl - pen) / dpdt
    } else {
        f64::INFINITY
    };
    let k_step = if e.friction.active() && e.dt > 0.0 {
        kt.max(e.friction.visf * (2.0 * kd * mass).sqrt() / e.dt)
    } else {
        kt
    };
    edge_force(e, &ep, (f_n, f_t), k_step, dt_kin, pen)
}

/// LS-DYNA's penalty on an edge pair (a keyword deck's, module comment):
/// F = K·p over the whole gap, K at least the soft constraint when
/// `sofscl` > 0, damper VDC % of critical; crossed edges release the pair.
fn linear_edge_pair(e: &EdgePair, sofscl: f64, st: &mut PairState) -> EdgeOutcome {
    let ep = closest_points_of_edges(e.xs[0], e.xs[1], e.xm[0], e.xm[1]);
    if ep.dist >= e.gap || ep.dist < 1e-10 * e.gap || e.k <= 0.0 {
        st.ft = [0.0; 3];
        return EdgeOutcome::Free;
    }
    let pen = e.gap - ep.dist;
    let (n, ws, wm, vrel, dpdt) = closing(e, &ep);
    let mass = (ws[0] * e.ms[0] + ws[1] * e.ms[1]).min(wm[0] * e.mm[0] + wm[1] * e.mm[1]);
    let k = if sofscl > 0.0 {
        e.k.max(stiffness::soft_constraint(sofscl, mass, e.dt))
    } else {
        e.k
    };
    let c = e.viss * 2.0 * (k * mass).sqrt();
    // Signed, as the node-to-surface penalty's (type7::pair, linear).
    let f_n = k * pen + c * dpdt;
    let mut f_t = [0.0; 3];
    if e.friction.active() && f_n != 0.0 {
        let vt = friction::tangential(vrel, n);
        f_t = friction::tangential_force(
            e.friction, e.friction.fric, f_n.abs(), vt, n, k, mass, e.dt, &mut st.ft,
        );
    }
    let dt_kin = if dpdt > 0.0 {
        0.5 * ep.dist / dpdt
    } else {
        f64::INFINITY
    };
    let k_step = e.friction.step_stiffness(k, c, k, mass, e.dt);
    edge_force(e, &ep, (f_n, f_t), k_step, dt_kin, pen)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::interfaces::edge_pair::tests::crossing;

    /// A keyword deck's edges: F = K·p through the whole gap (no 0.9
    /// fraction, no deactivation), SOFT 1 at least 0.5·SOFSCL·m*/Δt², the
    /// damper 2·VDC·√(K·M); crossed edges are free.
    #[test]
    fn the_linear_penalty_of_a_keyword_deck_s_edges() {
        let mut st = PairState::default();
        let mut e = crossing(0.01, 0.0);
        e.soft = Some(0.0);
        let EdgeOutcome::Force(f) = edge_pair(&e, &mut st) else {
            panic!("linear: no deactivation at 0.9 g");
        };
        assert!((f.f_n - 1000.0 * 0.09).abs() < 1e-12, "{}", f.f_n);
        // SOFT 1: m* = 1 (weights of unit masses), Δt 1e-3, SOFSCL 0.1.
        e.soft = Some(0.1);
        let EdgeOutcome::Force(f1) = edge_pair(&e, &mut st) else { panic!() };
        let k1 = 0.5 * 0.1 * 1.0 / 1e-6;
        assert!((f1.f_n - k1 * 0.09).abs() < 1e-9 * k1, "{}", f1.f_n);
        // Closing at 2: damper 2·VDC·√(K·M)·2.
        let mut d = crossing(0.04, -2.0);
        d.soft = Some(0.0);
        d.viss = 0.05;
        let EdgeOutcome::Force(fd) = edge_pair(&d, &mut st) else { panic!() };
        let expect = 1000.0 * 0.06 + 0.05 * 2.0 * (1000.0f64 * 1.0).sqrt() * 2.0;
        assert!((fd.f_n - expect).abs() < 1e-9 * expect, "{} {expect}", fd.f_n);
        // Crossed (distance 0): free.
        let mut x = crossing(0.0, 0.0);
        x.soft = Some(0.0);
        assert!(matches!(edge_pair(&x, &mut st), EdgeOutcome::Free));
    }

    #[test]
    fn crossing_edges_push_apart_along_their_common_normal_with_the_law_s_force() {
        let mut st = PairState::default();
        let EdgeOutcome::Force(f) = edge_pair(&crossing(0.04, 0.0), &mut st) else {
            panic!("the edges are within the gap");
        };
        // p = 0.1 − 0.04; law gap 0.09; F = ½·K·0.09·p/(0.09 − p).
        let (p, gl) = (0.06, 0.09);
        let expect = 0.5 * 1000.0 * gl * p / (gl - p);
        assert!((f.f_n - expect).abs() < 1e-9 * expect, "{} {expect}", f.f_n);
        assert!((f.pen - p).abs() < 1e-15);
        assert_eq!(f.dir, [0.0, 0.0, 1.0]);
        // The crossing point: x = 0.5 on the secondary edge (weights ¾, ¼ of
        // S1, S2), y = 0.25 on the main edge (weights ⅜, ⅝ of M1, M2).
        assert!((f.sec_shape[0] - 0.25).abs() < 1e-15 && (f.sec_shape[1] - 0.75).abs() < 1e-15);
        assert!((f.shape[0] - 0.375).abs() < 1e-15 && (f.shape[1] - 0.625).abs() < 1e-15);
        // Beyond the gap: free.
        assert!(matches!(edge_pair(&crossing(0.1, 0.0), &mut st), EdgeOutcome::Free));
        // At the law's gap the secondary edge leaves.
        assert!(matches!(edge_pair(&crossing(0.01, 0.0), &mut st), EdgeOutcome::Deactivate));
    }

    #[test]
    fn closing_edges_are_damped_and_the_damper_never_pulls() {
        let mut st = PairState::default();
        let mut e = crossing(0.04, -2.0);
        e.viss = 0.05;
        let EdgeOutcome::Force(closing) = edge_pair(&e, &mut st) else { panic!() };
        let EdgeOutcome::Force(still) = edge_pair(&crossing(0.04, 0.0), &mut st) else { panic!() };
        assert!(closing.f_n > still.f_n);
        assert!((closing.dt_kin - 0.5 * (0.09 - 0.06) / 2.0).abs() < 1e-15);
        let mut e = crossing(0.04, 1e6);
        e.viss = 0.05;
        let EdgeOutcome::Force(opening) = edge_pair(&e, &mut st) else { panic!() };
        assert_eq!(opening.f_n, 0.0);
    }

    #[test]
    fn istf_combines_the_edges_stiffness() {
        assert_eq!(edge_pair_stiffness(5, 2.0, 1.0, 3.0, 0.0, 1e30), 1.5);
        assert_eq!(edge_pair_stiffness(1, 8.0, 1.0, 3.0, 0.0, 1e30), 4.0);
        assert_eq!(edge_pair_stiffness(2, 1.0, 1.0, 3.0, 0.0, 1e30), 2.0);
        assert_eq!(edge_pair_stiffness(3, 1.0, 1.0, 3.0, 0.0, 2.5), 2.5);
        assert_eq!(edge_pair_stiffness(4, 1.0, 1.0, 3.0, 1.5, 1e30), 1.5);
    }
}
