//! TYPE25 penalty contact without an activation gap, node to surface
//! (reference card /INTER/TYPE25; the reference engine's law as gathered in
//! docs/notes/type24_type25_research.md §2–3). Its edge-to-edge part
//! with Iedge = 1 (the free shell edges) is an added interface of edge
//! pairs (`deck::to_model`, a TYPE11 card carrying `Penalty25`) that
//! runs TYPE25's edge penalty (`edge_pair`, below); Iedge 11, 13, 22 (solid
//! and sharp edges) are refused by name.
//!
//! - Gap: only the shells' half thicknesses, g = g_s + g_m (each times
//!   Gap_scale, each at most Gap_max_s, Gap_max_m); a solid face has none;
//!   with Igap0 = 1 a secondary node on a free shell edge has none either.
//!   A solid face is one-sided: a node behind it (over its inside, the
//!   projection within the face) penetrates by its depth; a shell is
//!   two-sided, its side taken at the impact.
//! - One segment per node: of the candidates in contact, the nearest;
//!   the node's memory (baseline, secant, friction, the side of a shell)
//!   goes with it when it slides onto another segment, as the reference
//!   keeps one candidate and one memory per node.
//! - Penetration as a baseline: the penetration found when a node first
//!   touches a segment (at the start: the initial penetration) is stored,
//!   and only further penetration p = p_raw − p_impact pushes; the baseline
//!   is dropped when the node leaves.
//! - No force jump: when the penetration grows more in a cycle than the
//!   normal approach dp = max(0, dP/dt·Δt) explains (a node sliding onto a
//!   segment), the stiffness becomes (K_old·p_old + K·dp)/p; otherwise it
//!   keeps the last cycle's, so unloading follows the secant.
//! - Force ½·K·p (EQ. 8.5.3.2/8.5.3.3: K = Stfac·E·t on shells, Stfac·B·A²/V
//!   on solids; Istf combines it with the secondary node's stiffness);
//!   damper VISs·√(2·½K·m*)·dP/dt with m* the harmonic mean of the node's
//!   mass and the segment point's (IVIS2 1; 6: the node's; 4: none);
//!   incremental Coulomb friction with the full K as tangential penalty.
//! - IPSTIF = 1 (format 2023): K is at least the mass and time-step
//!   stiffness Stfac_mdt·m*/Δt² (`stiffness::mass_time_step`, m* the
//!   harmonic mean of the node's mass and the segment point's, Δt = DTstif
//!   or the run's step): the piece LS-DYNA's SOFT = 1/2 stiffness is made of.
//! - Idel as TYPE7's: a main segment leaves when all (±1) or any (±2) of
//!   its elements are deleted, and (1, 2) a secondary node none of whose
//!   elements lives.
//! - A face between two solids (/SURF/PART/ALL) is dormant while both live
//!   and becomes the survivor's contact face when the other is deleted
//!   (`contact::inner_faces`).
//! - Time step: no kinematic step (the penalty is constant); K + C/Δt per
//!   pair enters the nodal step (EQ. 8.8.5.2).

use std::borrow::Cow;
use super::layout::{Interface, Pass};
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes, NODE_SHAPE,
};
use super::edge_pair::{closing, edge_force, EdgeOutcome, EdgePair};
use crate::contact::edge_geometry::closest_points_of_edges;
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::GapRule;
use crate::contact::geometry::{self as geo, V3};
use crate::contact::stiffness;
use crate::model::contact::EP30;
use crate::model::contact::Penalty25;
use crate::model::{self, InterfaceKind};
use serde::{Deserialize, Serialize};

/// TYPE25's own options.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type25 {
    /// Istf, Stmin, Stmax, VISs, IVIS2, Gap_scale, Gap_max_s, Gap_max_m.
    pub law: Penalty25,
    /// IPSTIF = 1: Stfac_mdt and DTstif (0: the run's step); None when off.
    pub mass_stiffness: Option<(f64, f64)>,
    /// Igap0 = 1: secondary nodes on a free shell edge have no gap.
    #[serde(default)]
    pub igap0: bool,
    /// How a new impact starts: TYPE25's rule, or TYPE24's.
    #[serde(default)]
    pub impact: Impact,
    /// Igap = 2: the gap of Igap 1 (the reference: Gapmin 0, Gapmax
    /// infinite) and each segment leaves out the secondary nodes within
    /// √2·gap of it along the surface, as TYPE7's Irem_gap = 2
    /// (`contact::close_neighbours`).
    #[serde(default)]
    pub remove_close: bool,
    /// Igap = 3: %mesh_size; each side's gap is then at most that fraction
    /// of its shortest edge (the node's: of the edges around it; the
    /// segment's: of its own), as the reference starter's i25sti3.F limits
    /// g_s and g_m (docs/notes/type24_type25_research.md §2.4).
    #[serde(default)]
    pub mesh_gap: Option<f64>,
}

/// How a node's new impact on a segment starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum Impact {
    /// TYPE25 (and TYPE24 with Inacti 5): the penetration at the impact is
    /// the baseline only further penetration pushes against, and the
    /// stiffness starts at K·dp/p (i25for3.F, i24dst3.F "PENE_Offset").
    #[default]
    Baseline,
    /// TYPE24 (i24dst3.F, i24for3.F): no baseline; the impact takes the full
    /// stiffness at once (the secant rule applies from the next cycle); a
    /// node found penetrated before the first step (deeper than 1e-8, the
    /// reference's Ipen_min) feels nothing until it leaves that contact.
    Full,
}

impl InterfaceType for Type25 {
    fn type_number(&self) -> u32 {
        25
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type25(t) = kind else {
            return None;
        };
        let refused = [
            (t.sens_id != 0, "an activation sensor (sens_ID)"),
            (t.ithe != 0, "heat transfer (Ithe)"),
            (t.fric_id != 0, "friction from /FRICTION (fric_ID)"),
            (t.ifric != 0 || t.ifiltr != 0, "a friction law or filter (Ifric, Ifiltr)"),
            (
                !matches!(t.iedge, 0 | 1 | 1000),
                "edge-to-edge contact of solid and sharp edges (Iedge 11, 13, 22)",
            ),
            (!matches!(t.igap, 0 | 1 | 2 | 3), "a gap option other than the half thicknesses (Igap 5)"),
            (
                t.igap == 3 && t.iedge == 1,
                "the mesh-size gap (Igap 3) on the edge-to-edge part (Iedge 1)",
            ),
            (t.ishape == 2, "the rounded gap shape along free edges (Ishape = 2)"),
            (
                !matches!(t.inacti, 0 | 5 | 1000),
                "an initial-penetration treatment other than the baseline (Inacti -1, 1, 3)",
            ),
            (!matches!(t.ivis2, 1 | 4 | 6), "a damping form other than IVIS2 1, 4, 6"),
            (t.ithick == 1, "a gap following the shell thickness (Ithick = 1)"),
        ];
        refused.into_iter().find(|r| r.0).map(|r| r.1)
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Sort
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type25(t) = kind else {
            return None;
        };
        let common = penalty_common(t.stfac, t.fric, (t.tstart, t.tstop), t.ibc, t.inacti, t.idel);
        let own = Type25 {
            law: t.penalty(),
            mass_stiffness: (t.ipstif == 1).then_some((t.stfac_mdt, t.dtstif)),
            igap0: t.igap0 == 1,
            impact: Impact::Baseline,
            remove_close: t.igap == 2,
            mesh_gap: (t.igap == 3).then_some(t.mesh_size_pct),
        };
        Some((own, common))
    }

    /// Self-contact or nodes to surface: one pass. Two surfaces: each
    /// surface's nodes on the other's segments.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<super::PassSides<'a>> {
        let pass = |sec: Vec<u32>, main: &'a [[u32; 4]]| super::PassSides {
            sec,
            own: None,
            main,
            sec_edges: &[],
            main_edges: &[],
            sec_segs: Cow::Borrowed(&[]),
            self_contact: false,
        };
        if i.secondary_segments.is_empty() {
            return vec![pass(i.secondary_nodes.clone(), &i.main_segments)];
        }
        let nodes = super::type3::nodes_of;
        vec![
            pass(nodes(&i.secondary_segments), &i.main_segments),
            pass(nodes(&i.main_segments), &i.secondary_segments),
        ]
    }

    /// For the search reach only (the kernel sums the capped half thicknesses).
    fn gap_rule(&self, _common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        gap_rule(&self.law)
    }

    fn sorting_margin(&self) -> f64 {
        0.2
    }

    /// One segment per node, the nearest in contact: the reference keeps
    /// the candidate of the node's impact (i25slid.F I25KEEPF, the closest
    /// sub-triangle, i25dst3_1.F) and the node's friction, baseline and
    /// secant memory go with the node (i25irtlm.F). The nearest, not the
    /// deepest: a node behind a solid's far face is not in that face.
    fn one_segment_per_node(&self) -> bool {
        true
    }

    /// With Istf > 1 the reference starter gives each secondary node its
    /// assembled stiffness (I25STSECND: Stfac·STIFINT, ASSTIFI; research
    /// note type24_type25_research.md §8.1); Istf 0, 1, 1000 never read it.
    fn assembled_node_stiffness(&self) -> bool {
        true
    }

    fn nearness(&self, c: &PairContext, side: i8) -> Option<(f64, i8)> {
        let (p, m) = (c.p, c.m as usize);
        let g = self.gap(p, c.k, m);
        let shell = p.seg_elem[m].0 < 2;
        penetration(c.xs, c.xm, p.is_tri(m), g, shell, side).map(|r| (-r.2.dist, r.1))
    }

    fn zero_gap_on_free_shell_edges(&self) -> bool {
        self.igap0
    }

    fn removes_initially_close(&self) -> bool {
        self.remove_close
    }

    /// The reference engine keeps a face between two solids out of contact
    /// until one of them is deleted (`contact::inner_faces`).
    fn inner_solid_faces_as_segments(&self) -> bool {
        false
    }

    /// Half the solid stiffness B·A²/V (EQ. 8.5.3.3), as the shell's 0.5·E·t:
    /// segment stiffness is stored as the force stiffness ½·K.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        stiffness::brick_type3(bulk, area, volume)
    }

    /// The pair stiffness K (the force takes ½·K): the main segment's
    /// Stfac·E·t or Stfac·B·A²/V, or (Istf 2-5) its mean, max, min or series
    /// with the secondary node's (TYPE7's node stiffness), held in [Stmin, Stmax].
    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        let km = 2.0 * it.stfac * p.seg_k[m];
        let ks = it.stfac * p.sec_k[k];
        pair_stiffness_of(&self.law, ks, km)
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let (it, p, k, m) = (c.it, c.p, c.k, c.m as usize);
        let shell = p.seg_elem[m].0 < 2;
        let g = self.gap(p, k, m);
        let Some((p_raw, side, pr)) = penetration(c.xs, c.xm, p.is_tri(m), g, shell, st.side)
        else {
            *st = PairState::default();
            return PairOutcome::Free;
        };
        let mm: f64 = (0..4).map(|j| pr.shape[j] * c.cnode_mass[c.main.nodes[j] as usize]).sum();
        let mut k_new = self.pair_stiffness(it, p, k, m);
        let mut step_known = true;
        if let Some((s, dt_s)) = self.mass_stiffness {
            let dt_s = if dt_s > 0.0 { dt_s } else { c.dt };
            // Before the first step (Δt = 0) it is not known yet.
            step_known = dt_s > 0.0;
            k_new = k_new.max(stiffness::mass_time_step(s, c.ms, mm, dt_s));
        }
        if st.side == 0 {
            // A new impact: its baseline, and its stiffness the secant's
            // start (taken at the first step when not known yet).
            let baseline = match self.impact {
                Impact::Baseline => p_raw,
                Impact::Full if c.dt == 0.0 && p_raw > 1e-8 => f64::INFINITY,
                Impact::Full => 0.0,
            };
            *st = PairState {
                side,
                pen_memory: [baseline, 0.0, if step_known { k_new } else { 0.0 }],
                ..PairState::default()
            };
        }
        if st.pen_memory[2] == 0.0 && step_known {
            st.pen_memory[2] = k_new;
        }
        let pen = (p_raw - st.pen_memory[0]).max(0.0);
        if pen == 0.0 {
            st.pen_memory[1] = 0.0;
            return PairOutcome::Free;
        }
        let mass = match self.law.ivis2 {
            6 => c.ms,
            _ => c.ms * mm / (c.ms + mm).max(1e-30),
        };
        let law = Law {
            k_new,
            ramp_new: self.impact == Impact::Baseline,
            viss: if self.law.ivis2 == 4 { 0.0 } else { self.law.viss },
            mass,
            friction: &it.friction,
            dt: c.dt,
        };
        PairOutcome::Force(law.force(c, &pr, pen, st))
    }

    /// None: the penalty stiffness is constant (the nodal step sees it).
    fn kinematic_step(&self, _f: &PairForce) -> Option<f64> {
        None
    }
}

/// The common options of a TYPE24 or TYPE25 card: Stfac, Coulomb friction
/// in the incremental form (the reference forces it: MODFR 2), no card gap,
/// (Tstart, Tstop), IBC, Inacti, Idel.
pub fn penalty_common(
    stfac: f64,
    fric: f64,
    (tstart, tstop): (f64, f64),
    ibc: [bool; 3],
    inacti: i64,
    idel: i64,
) -> CardCommon {
    CardCommon {
        stfac,
        friction: FrictionLaw {
            ifric: 0,
            fric,
            iform: 2,
            visf: 0.0,
            ..FrictionLaw::none()
        },
        gap_card: 0.0,
        tstart,
        tstop,
        ibc,
        inacti,
        idel,
    }
}

/// A pair's stiffness by Istf from the secondary and main stiffnesses
/// (Stfac included): 2 mean, 3 max, 4 min, 5 in series, each held in
/// [Stmin, Stmax]; 1000 (and 0) the main side's; TYPE24's 7 none (only
/// the mass and time-step stiffness).
pub fn pair_stiffness_of(q: &Penalty25, ks: f64, km: f64) -> f64 {
    let kn = match q.istf {
        2 => 0.5 * (km + ks),
        3 => km.max(ks),
        4 => km.min(ks),
        5 => stiffness::series(km, ks),
        7 => return 0.0,
        _ => return km,
    };
    q.stmin.max(q.stmax.min(kn))
}

/// The gap rule, for the search reach (the kernels sum the capped half
/// thicknesses, `edge_gap`).
pub fn gap_rule(q: &Penalty25) -> GapRule {
    GapRule {
        igap: 2,
        gapmin: 0.0,
        fscalegap: q.gap_scale,
        gapmax: (q.gap_max_s + q.gap_max_m).min(EP30),
        mesh_size_pct: 0.4,
    }
}

/// A pair's gap from the two sides' half shell thicknesses: each times
/// Gap_scale and at most Gap_max_s, Gap_max_m, and at most its cap (Igap
/// 3's share of the mesh size; infinite otherwise).
pub fn pair_gap(q: &Penalty25, gs: f64, gm: f64, caps: [f64; 2]) -> f64 {
    (q.gap_scale * gs).min(q.gap_max_s).min(caps[0])
        + (q.gap_scale * gm).min(q.gap_max_m).min(caps[1])
}

/// TYPE25's penalty on an edge pair (Iedge; the reference engine's
/// i25for3e as gathered in docs/notes/type24_type25_research.md §3):
/// p = g − d between the edges' closest points (g the two half
/// thicknesses); the baseline P0 is the penetration at the impact and then
/// relaxes toward a smaller one, P0 ← min(P0, 0.95·P0 + 0.05·p), so only
/// further penetration p − P0 pushes: F_n = ½·K·(p − P0) + C·dp/dt, C =
/// VISs·√(2·½K·m*) with m* the harmonic mean of the two sides' masses at
/// the closest points (IVIS2 1; 6: the secondary side's; 4: none);
/// incremental Coulomb friction with the full K as tangential penalty; no
/// kinematic step, K + C/Δt to the nodal step. Edges that cross (d → 0)
/// release the pair.
pub fn edge_pair(e: &EdgePair, q: &Penalty25, st: &mut PairState) -> EdgeOutcome {
    let ep = closest_points_of_edges(e.xs[0], e.xs[1], e.xm[0], e.xm[1]);
    let p_raw = e.gap - ep.dist;
    if p_raw <= 0.0 || ep.dist < 1e-10 * e.gap || e.k <= 0.0 {
        *st = PairState::default();
        return EdgeOutcome::Free;
    }
    if st.side == 0 {
        st.side = 1;
        st.pen_memory[0] = p_raw;
    }
    let p0 = st.pen_memory[0].min(0.95 * st.pen_memory[0] + 0.05 * p_raw);
    st.pen_memory[0] = p0;
    let pen = p_raw - p0;
    if pen <= 0.0 {
        return EdgeOutcome::Free;
    }
    let (n, ws, wm, vrel, dpdt) = closing(e, &ep);
    let (m_s, m_m) = (
        ws[0] * e.ms[0] + ws[1] * e.ms[1],
        wm[0] * e.mm[0] + wm[1] * e.mm[1],
    );
    let mass = match q.ivis2 {
        6 => m_s,
        _ => m_s * m_m / (m_s + m_m).max(1e-30),
    };
    let kf = 0.5 * e.k;
    let c = if q.ivis2 == 4 {
        0.0
    } else {
        q.viss * (2.0 * kf * mass).sqrt()
    };
    let f_n = kf * pen + c * dpdt;
    let mut f_t = [0.0; 3];
    if e.friction.active() && f_n != 0.0 {
        let vt = friction::tangential(vrel, n);
        f_t = friction::tangential_force(
            e.friction,
            e.friction.fric,
            f_n.abs(),
            vt,
            n,
            e.k,
            mass,
            e.dt,
            &mut st.ft,
        );
    }
    let kt = if e.dt > 0.0 { e.k + c / e.dt } else { e.k };
    edge_force(e, &ep, (f_n, f_t), kt, f64::INFINITY, pen)
}

impl Type25 {
    /// The pair's gap: the half thicknesses, each scaled and capped (Igap 3:
    /// also at most %mesh_size times its side's shortest edge).
    fn gap(&self, p: &Pass, k: usize, m: usize) -> f64 {
        let caps = self.mesh_gap.map_or([f64::INFINITY; 2], |pct| {
            [pct * p.sec_lmin[k], pct * p.seg_lmin[m]]
        });
        pair_gap(&self.law, p.sec_gap[k], p.seg_gap[m], caps)
    }
}

/// The raw penetration of node `xs` into the segment with gap `g`, the side
/// it is on, and its projection; `None` when it is out of contact.
/// `side0`: the side taken at the impact (0 = none yet); a solid face's is +1.
fn penetration(
    xs: V3,
    xm: &[V3; 4],
    tri: bool,
    g: f64,
    shell: bool,
    side0: i8,
) -> Option<(f64, i8, geo::Projection)> {
    let mut pr = geo::project(xs, xm, tri);
    let b = geo::dot(geo::sub(xs, pr.point), pr.normal);
    let side = match (shell, side0) {
        (false, _) => 1,
        (true, 0) => {
            if b >= 0.0 {
                1
            } else {
                -1
            }
        }
        (true, s) => s,
    };
    let bs = f64::from(side) * b;
    let p_raw = if bs >= 0.0 {
        g - pr.dist
    } else {
        // Behind the face (or past a shell's mid-plane): only over the face
        // itself, where the closest point is the foot of the normal.
        let over_face = geo::dot(pr.dir, pr.normal).abs() >= 1.0 - 1e-9;
        if !over_face {
            return None;
        }
        pr.dir = geo::scale(pr.normal, f64::from(side));
        g + pr.dist
    };
    (p_raw > 0.0).then_some((p_raw, side, pr))
}

/// One pair's penalty law (see the module's comment).
struct Law<'a> {
    k_new: f64,
    /// A new impact's stiffness starts at K·dp/p (TYPE25), or at K (TYPE24).
    ramp_new: bool,
    viss: f64,
    /// The damper's mass.
    mass: f64,
    friction: &'a FrictionLaw,
    dt: f64,
}

impl Law<'_> {
    fn force(&self, c: &PairContext, pr: &geo::Projection, pen: f64, st: &mut PairState) -> PairForce {
        let vc = geo::interpolate(&pr.shape, c.vm);
        let vrel = geo::sub(c.vs, vc);
        let dpdt = -geo::dot(vrel, pr.dir);
        let dp = (dpdt * self.dt).max(0.0);
        let [_, p_old, k_old] = st.pen_memory;
        let k = if !self.ramp_new && (p_old == 0.0 || self.dt == 0.0) {
            self.k_new
        } else if pen > p_old && dp < pen - p_old {
            (k_old * p_old + self.k_new * dp) / pen
        } else {
            k_old
        };
        st.pen_memory[1] = pen;
        st.pen_memory[2] = k;
        let kf = 0.5 * k;
        let damper = self.viss * (2.0 * kf * self.mass).sqrt();
        let f_n = kf * pen + damper * dpdt;
        let mut f_t = [0.0; 3];
        if self.friction.active() && f_n != 0.0 {
            let vt = friction::tangential(vrel, pr.dir);
            f_t = friction::tangential_force(
                self.friction,
                self.friction.fric,
                f_n.abs(),
                vt,
                pr.dir,
                self.k_new,
                self.mass,
                self.dt,
                &mut st.ft,
            );
        }
        let kt = if self.dt > 0.0 {
            self.k_new + damper / self.dt
        } else {
            self.k_new
        };
        PairForce {
            fs: geo::add(geo::scale(pr.dir, f_n), f_t),
            sec_shape: NODE_SHAPE,
            shape: pr.shape,
            kt,
            dt_kin: f64::INFINITY,
            f_n,
            f_t,
            pen,
            dir: pr.dir,
            point: pr.point,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn face() -> [V3; 4] {
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
    }

    #[test]
    fn a_solid_face_is_one_sided_and_a_shell_keeps_its_impact_side() {
        let x = face();
        // Solid face (no gap): in front, free; behind, the depth.
        assert!(penetration([0.3, 0.4, 0.01], &x, false, 0.0, false, 0).is_none());
        let (p, s, pr) = penetration([0.3, 0.4, -0.02], &x, false, 0.0, false, 0).unwrap();
        assert!((p - 0.02).abs() < 1e-15 && s == 1 && pr.dir == [0.0, 0.0, 1.0]);
        // Behind but beyond the face's edge: not over the face, free.
        assert!(penetration([1.2, 0.4, -0.02], &x, false, 0.0, false, 0).is_none());
        // Shell with gap 0.1 hit from below: side −1, pushed down.
        let (p, s, pr) = penetration([0.3, 0.4, -0.07], &x, false, 0.1, true, 0).unwrap();
        assert!((p - 0.03).abs() < 1e-15 && s == -1 && pr.dir[2] < 0.0);
        // Past the mid-plane from below: still pushed down, by g + depth.
        let (p, _, pr) = penetration([0.3, 0.4, 0.02], &x, false, 0.1, true, -1).unwrap();
        assert!((p - 0.12).abs() < 1e-15 && pr.dir == [0.0, 0.0, -1.0]);
    }

    /// TYPE25's edge penalty: the impact's penetration is the baseline,
    /// further penetration pushes with ½K·(p − P0), and when the edges back
    /// off the baseline follows at 5 % a cycle (P0 ← min(P0, 0.95·P0 +
    /// 0.05·p)), so pushing back in is felt again from the lower baseline.
    #[test]
    fn an_edge_pair_pushes_only_against_penetration_beyond_its_baseline() {
        let q = Penalty25 {
            istf: 1000,
            stmin: 0.0,
            stmax: EP30,
            viss: 0.0,
            ivis2: 1,
            gap_scale: 1.0,
            gap_max_s: EP30,
            gap_max_m: EP30,
        };
        let pair = |z: f64| super::super::edge_pair::tests::crossing(z, 0.0);
        let force = |z: f64, st: &mut PairState| match edge_pair(&pair(z), &q, st) {
            EdgeOutcome::Force(f) => f.f_n,
            _ => 0.0,
        };
        let mut st = PairState::default();
        // Impact at p = 0.02: the baseline, no force.
        assert_eq!(force(0.08, &mut st), 0.0);
        assert!((st.pen_memory[0] - 0.02).abs() < 1e-15);
        // 0.03 further: ½·1000·0.03.
        assert!((force(0.05, &mut st) - 15.0).abs() < 1e-9);
        // Back to p = 0.01: the baseline moves 5 % of the way, 0.0195.
        assert_eq!(force(0.09, &mut st), 0.0);
        assert!((st.pen_memory[0] - 0.0195).abs() < 1e-15);
        // Out of the gap: the memory goes.
        assert_eq!(force(0.2, &mut st), 0.0);
        assert_eq!(st, PairState::default());
    }
}
