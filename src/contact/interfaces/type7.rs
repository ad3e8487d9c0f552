//! TYPE7 node-to-segment penalty contact (theory manual §8.8): both sides,
//! edges and corners; F = Ks·P + C·dP/dt with Ks = K0·Gap/(Gap − P) and
//! C = VISs·√(2·Ks·M) (EQ. 8.8.9.1, 8.8.3.3); friction by Ifric/Iform/Ifiltr
//! (EQ. 8.8.3.4–5).
//!
//! Details as the reference engine applies them (its listing prints them as
//! "QUADRATIC DAMPING FLAG 0" and "FRICTION CRITICAL DAMPING FACTOR"):
//! - while the node closes in, the damper works on the tangent stiffness
//!   Kt = Ks·Gap/(Gap − P) (EQ. 8.8.9.2) rather than Ks, and a quadratic term
//!   0.4²·2·M·(dP/dt)/(Gap − P) is added to C, so that a fast impact is
//!   braked before the node reaches the mid-plane;
//! - the reaction is not cut at zero: on the way out the damper may pull
//!   (EQ. 8.8.9.1 as written), which takes out the energy the damper of the
//!   way in did not;
//! - the friction damper VISF·√(2·K·M) enters the stiffness the nodal time
//!   step sees as VISF·√(2·K·M)/Δt (with Δt the last step): a node sliding
//!   under friction is integrated with a step at which that damper is stable.

use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes, NODE_SHAPE,
};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::{self, GapRule, InitialPenetration};
use crate::contact::geometry::{self as geo, V3};
use super::layout::{Interface, Pass};
use crate::contact::stiffness;
use crate::model::InterfaceKind;
use serde::{Deserialize, Serialize};

/// TYPE7's own options (the /INTER/TYPE7 card's fields the engine reads
/// beyond the common ones).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type7 {
    /// Istf, Stmin, Stmax: how the pair stiffness combines the sides' (card eq. (1)–(5)).
    pub istf: i64,
    pub stmin: f64,
    pub stmax: f64,
    /// VISs: critical damping factor of the normal damper.
    pub viss: f64,
    /// Bumult: sorting margin factor.
    pub bumult: f64,
    /// Fpenmax: initial penetration (fraction of the gap) beyond which the node is deactivated.
    pub fpenmax: f64,
    /// dtmin and ITIED: a pair whose time step falls below dtmin removes the
    /// node (ITIED = 0) or ties it (1, 2).
    pub dtmin: f64,
    pub itied: i64,
    /// Irem_gap = 2.
    pub irem_gap: bool,
    /// The gap card: Igap (0 read as 1000), Gapmin (0: the default), Fscale_gap, Gapmax, %mesh_size.
    pub igap: i64,
    pub gapmin: f64,
    pub fscalegap: f64,
    pub gapmax: f64,
    pub mesh_size_pct: f64,
    /// A keyword deck's SOFT = 0 contact: LS-DYNA's penalty stiffness
    /// instead of Istf's.
    #[serde(default)]
    pub dyna: Option<crate::model::contact::DynaPenalty>,
}

impl Type7 {
    /// A keyword deck's SOFT = 1 contact: the larger of `k0` (SOFT = 0's)
    /// and the soft constraint 0.5·SOFSCL·m*/Δt², m* the smaller of the
    /// secondary node's mass and the main nodes' (their initial masses, the
    /// same on every rank), Δt this cycle's step.
    fn soft_constraint(&self, c: &PairContext, k0: f64) -> f64 {
        match self.dyna {
            Some(d) if d.soft == 1 => {
                let m = c
                    .main
                    .nodes()
                    .iter()
                    .map(|&n| c.cnode_mass[n as usize])
                    .fold(c.ms, f64::min);
                k0.max(stiffness::soft_constraint(d.sofscl, m, c.dt))
            }
            _ => k0,
        }
    }
}

impl InterfaceType for Type7 {
    fn type_number(&self) -> u32 {
        7
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type7(t) = kind else {
            return None;
        };
        let refused = [
            (t.sens_id != 0, "an activation sensor (sens_ID)"),
            (t.ithe != 0, "heat transfer (Ithe = 1)"),
            (t.icurv != 0, "a curved gap envelope (Icurv)"),
            (t.iadm != 0, "adaptive meshing (Iadm)"),
            (t.ists != 0, "surface-to-surface contact (Ists)"),
            (
                t.fct_idf != 0 || t.fric_id != 0,
                "friction from a function or /FRICTION (fct_IDF, fric_ID)",
            ),
            (t.ibag == 1, "airbag vent closure (Ibag = 1)"),
            (t.ifric == 4, "Ifric = 4 (exponential decay law)"),
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
        let InterfaceKind::Type7(t) = kind else {
            return None;
        };
        if t.dyna.is_some_and(|d| d.soft == 2) {
            // LS-DYNA's segment-based contact (`dyna_segment`).
            return None;
        }
        let common = CardCommon {
            stfac: t.stfac,
            friction: FrictionLaw {
                ifric: t.ifric,
                fric: t.fric,
                c: t.fric_coefs.unwrap_or([0.0; 6]),
                ifiltr: t.ifiltr,
                xfreq: t.xfreq,
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
        let own = Type7 {
            istf: t.istf,
            stmin: t.stmin,
            stmax: t.stmax,
            viss: t.viss,
            bumult: t.bumult,
            fpenmax: t.fpenmax,
            dtmin: t.dtmin,
            itied: t.itied,
            irem_gap: t.irem_gap == 2,
            igap: t.igap,
            gapmin: t.gapmin,
            fscalegap: t.fscalegap,
            gapmax: t.gapmax,
            mesh_size_pct: t.mesh_size_pct,
            dyna: t.dyna,
        };
        Some((own, common))
    }

    /// Igap 1000 (or 0): constant Gapmin; 1, 2, 3: variable (card eq. (8)–(10)).
    /// Gapmin 0: the default of card comment 10, from the mean main shell
    /// thickness (Igap 0, 1000) or the smallest one.
    fn gap_rule(&self, _common: &CardCommon, sizes: &SurfaceSizes) -> GapRule {
        let igap = self.igap;
        let shell_t = if sizes.n_shell == 0 {
            None
        } else if igap == 1000 || igap == 0 {
            Some(sizes.thick_sum / sizes.n_shell as f64)
        } else {
            Some(sizes.thick_min)
        };
        let gapmin = if self.gapmin > 0.0 {
            self.gapmin
        } else {
            gap::type7_default_gapmin(shell_t, sizes.l_min)
        };
        GapRule {
            igap: if igap == 0 { 1000 } else { igap },
            gapmin,
            fscalegap: self.fscalegap,
            gapmax: self.gapmax,
            mesh_size_pct: self.mesh_size_pct,
        }
    }

    fn sorting_margin(&self) -> f64 {
        self.bumult
    }

    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        stiffness::brick_type7(bulk, area, volume)
    }

    /// LS-DYNA's SOFT = 0 rule for a keyword deck's contact.
    fn element_stiffness(&self, el: &stiffness::ElementSize, main: bool) -> Option<f64> {
        let d = self.dyna?;
        let f = d.slsfac * if main { d.sfm } else { d.sfs };
        Some(stiffness::dyna_soft0(f, el))
    }

    /// By Istf (card eq. (1)–(3)); a keyword deck's contact: the smaller of
    /// the main segment's and the secondary node's (LS-DYNA's default
    /// penalty option).
    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        if self.dyna.is_some() {
            return p.seg_k[m].min(p.sec_k[k]);
        }
        stiffness::type7_pair(
            self.istf,
            it.stfac,
            it.stfac * p.seg_k[m],
            p.sec_k[k],
            self.stmin,
            self.stmax,
        )
    }

    fn removes_initially_close(&self) -> bool {
        self.irem_gap
    }

    /// The pair's gap (Inacti 5, 6: the corrected one, which follows the node
    /// back out), the penalty or tied force, and dtmin / ITIED.
    #[inline]
    fn pair(&self, c: &PairContext, ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let (it, p, k, m) = (c.it, c.p, c.k, c.m as usize);
        let tri = p.is_tri(m);
        let nominal = it.pair_gap(p, k, m);
        let gi = ns.gap0.binary_search_by_key(&c.m, |e| e.0);
        let g = match gi {
            Ok(i) => ns.gap0[i].1,
            Err(_) => nominal,
        };
        let k0 = self.soft_constraint(c, self.pair_stiffness(it, p, k, m));
        let inp = Pair {
            xs: c.xs,
            vs: c.vs,
            ms: c.ms,
            xm: c.xm,
            vm: c.vm,
            tri,
            k0,
            gap: g,
            viss: self.viss,
            friction: &it.friction,
            area: p.seg_area[m],
            dt: c.dt,
            linear: self.dyna.is_some(),
        };
        let f = if st.tie.is_some() {
            tied(&inp, st, self.itied)
        } else {
            pair(&inp, st)
        };
        // Inacti 5/6: the corrected gap follows the node back out.
        if let Ok(i) = gi {
            let d = geo::project(c.xs, c.xm, tri).dist;
            let (_, g0, clear) = ns.gap0[i];
            ns.gap0[i].1 = gap::relax_gap(g0, nominal, d, clear);
        }
        let Some(f) = f else {
            return PairOutcome::Free;
        };
        // dtmin / ITIED.
        if self.dtmin > 0.0 && st.tie.is_none() {
            let dtp = f.dt_kin.min((2.0 * c.ms / f.kt).sqrt());
            if dtp < self.dtmin {
                if self.itied == 0 {
                    ns.off = true;
                    return PairOutcome::NodeOff;
                }
                st.tie = Some((f.shape, geo::sub(c.xs, f.point)));
            }
        }
        PairOutcome::Force(f)
    }

    /// EQ. 8.8.5.1: 0.5·(Gap − P)/(dP/dt).
    fn kinematic_step(&self, f: &PairForce) -> Option<f64> {
        Some(f.dt_kin)
    }

    /// The pair's gap, where [`pair`]'s own reach test decides alone: not
    /// tied, no Inacti 5/6 gap to relax.
    fn free_beyond(
        &self,
        it: &Interface,
        p: &Pass,
        k: usize,
        m: usize,
        ns: &NodeState,
        st: &PairState,
    ) -> Option<f64> {
        let relaxing = ns.gap0.binary_search_by_key(&(m as u32), |e| e.0).is_ok();
        (st.tie.is_none() && !relaxing).then(|| it.pair_gap(p, k, m))
    }

    /// [`pair`] beyond reach: the friction memory cleared.
    fn when_free(&self, st: &mut PairState) {
        // Written only when not already clear: most pairs beyond reach stay
        // so cycle after cycle, and an unwritten memory is never written back.
        if st.ft.iter().chain(&st.ff).any(|x| x.to_bits() != 0) {
            st.ft = [0.0; 3];
            st.ff = [0.0; 3];
        }
    }

    /// Penetration g − d on both sides; Inacti and Fpenmax decide.
    fn initial_penetration(
        &self,
        it: &Interface,
        xs: V3,
        xm: &[V3; 4],
        tri: bool,
        g: f64,
    ) -> (InitialPenetration, f64) {
        let p0 = g - geo::project(xs, xm, tri).dist;
        (gap::initial_penetration(it.inacti, self.fpenmax, p0, g), p0)
    }
}

/// A TYPE7 pair's inputs.
pub struct Pair<'a> {
    pub xs: V3,
    pub vs: V3,
    pub ms: f64,
    pub xm: &'a [V3; 4],
    pub vm: &'a [V3; 4],
    pub tri: bool,
    /// Initial stiffness K0 of the pair (Istf).
    pub k0: f64,
    /// The pair's gap (constant, variable, or reduced for an initial penetration).
    pub gap: f64,
    pub viss: f64,
    pub friction: &'a FrictionLaw,
    /// Area of the main segment, for the contact pressure of the friction laws.
    pub area: f64,
    pub dt: f64,
    /// LS-DYNA's penalty law (a keyword deck's contact): F = K0·P, linear to
    /// and through the contact surface, and a damper VISs·2·√(K0·M) (VDC as
    /// a fraction of critical), instead of EQ. 8.8.9.1's K0·Gap/(Gap − P)
    /// and its quadratic damper.
    pub linear: bool,
}

/// The pair's force, or `None` when the node is outside the gap (or at the
/// segment's mid-plane, where it is deactivated, §8.8.11.1).
pub fn pair(p: &Pair, st: &mut PairState) -> Option<PairForce> {
    // Most candidates of the sort are out of the gap at a given cycle: a node
    // farther than the gap from the ball holding the segment's nodes is
    // farther than the gap from the segment (exact, so the result is the same
    // as the full projection's).
    if geo::beyond_reach(p.xs, p.xm, p.tri, p.gap) {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let pr = geo::project(p.xs, p.xm, p.tri);
    if pr.dist >= p.gap || pr.dist < 1e-10 * p.gap {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let s = geo::dot(geo::sub(p.xs, pr.point), pr.normal);
    st.side = if s >= 0.0 { 1 } else { -1 };
    let pen = p.gap - pr.dist;
    let (f_el, kt) = if p.linear {
        (p.k0 * pen, p.k0)
    } else {
        stiffness::type7_reaction(p.k0, p.gap, pen)
    };
    let vc = geo::interpolate(&pr.shape, p.vm);
    let vrel = geo::sub(p.vs, vc);
    // Penetration rate: the node closing on the contact point.
    let dpdt = -geo::dot(vrel, pr.dir);
    let c = if p.linear {
        p.viss * 2.0 * (p.k0 * p.ms).sqrt()
    } else {
        damping(p.viss, p.k0, p.gap, pen, p.ms, dpdt)
    };
    // Signed: the damper may pull while the node leaves (EQ. 8.8.9.1).
    let f_n = f_el + c * dpdt;
    // The stiffness the dampers see: Kt closing in, Ks going out.
    let kd = if dpdt > 0.0 || p.linear {
        kt
    } else {
        p.k0 * p.gap / (p.gap - pen)
    };
    let mut f_t = [0.0; 3];
    if p.friction.active() && f_n != 0.0 {
        let vt = friction::tangential(vrel, pr.dir);
        let f_abs = f_n.abs();
        let pressure = if p.area > 0.0 { f_abs / p.area } else { 0.0 };
        let mu = p.friction.mu(pressure, geo::norm(vt));
        let k = if p.friction.iform == 1 { kd } else { p.k0 };
        let raw = friction::tangential_force(
            p.friction, mu, f_abs, vt, pr.dir, k, p.ms, p.dt, &mut st.ft,
        );
        let a = p.friction.filter_alpha(p.dt);
        st.ff = geo::add(geo::scale(raw, a), geo::scale(st.ff, 1.0 - a));
        f_t = st.ff;
    }
    let fs = geo::add(geo::scale(pr.dir, f_n), f_t);
    let dt_kin = if dpdt > 0.0 {
        0.5 * pr.dist / dpdt
    } else {
        f64::INFINITY
    };
    let k_step = p.friction.step_stiffness(kt, c, kd, p.ms, p.dt);
    Some(PairForce {
        fs,
        sec_shape: NODE_SHAPE,
        shape: pr.shape,
        kt: k_step,
        dt_kin,
        f_n,
        f_t,
        pen,
        dir: pr.dir,
        point: pr.point,
    })
}

/// Coefficient of the normal damper at penetration `pen` (≥ 0) and
/// penetration rate `dpdt` (> 0 closing): C = VISs·√(2·K·M) with K = Kt while
/// closing and Ks while opening (EQ. 8.8.9.1–2), plus, while closing, the
/// quadratic term 0.4²·2·M·(dP/dt)/(Gap − P).
pub fn damping(viss: f64, k0: f64, gap: f64, pen: f64, m: f64, dpdt: f64) -> f64 {
    let ks = k0 * gap / (gap - pen);
    if dpdt > 0.0 {
        let kt = ks * gap / (gap - pen);
        viss * (2.0 * kt * m).sqrt() + QUAD_DAMPING * QUAD_DAMPING * 2.0 * m * dpdt / (gap - pen)
    } else {
        viss * (2.0 * ks * m).sqrt()
    }
}

/// Coefficient of the quadratic damper (the reference engine's default,
/// "QUADRATIC DAMPING FLAG 0").
const QUAD_DAMPING: f64 = 0.4;

/// A tied pair (ITIED 1, 2): a spring K0 with critical damping VISs holds the
/// node at the point of the segment where it was tied. With ITIED = 1 the tie
/// lets go when the spring pulls the node towards the segment (rebound).
pub fn tied(p: &Pair, st: &mut PairState, itied: i64) -> Option<PairForce> {
    let (shape, offset) = st.tie?;
    let anchor = geo::add(geo::interpolate(&shape, p.xm), offset);
    let vc = geo::interpolate(&shape, p.vm);
    let err = geo::sub(p.xs, anchor);
    let vrel = geo::sub(p.vs, vc);
    let c = p.viss.max(0.05) * (2.0 * p.k0 * p.ms).sqrt();
    let fs = geo::sub(geo::scale(err, -p.k0), geo::scale(vrel, c));
    let ol = geo::norm(offset);
    let dir = if ol > 0.0 {
        geo::scale(offset, 1.0 / ol)
    } else {
        [0.0; 3]
    };
    let f_n = geo::dot(fs, dir);
    if itied == 1 && f_n < 0.0 {
        st.tie = None;
        return None;
    }
    Some(PairForce {
        fs,
        sec_shape: NODE_SHAPE,
        shape,
        kt: p.k0,
        dt_kin: f64::INFINITY,
        f_n: f_n.max(0.0),
        f_t: geo::sub(fs, geo::scale(dir, f_n)),
        pen: 0.0,
        dir,
        point: anchor,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plate() -> [V3; 4] {
        [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ]
    }

    fn input<'a>(
        xs: V3,
        vs: V3,
        xm: &'a [V3; 4],
        vm: &'a [V3; 4],
        law: &'a FrictionLaw,
    ) -> Pair<'a> {
        Pair {
            xs,
            vs,
            ms: 1.0,
            xm,
            vm,
            tri: false,
            k0: 1000.0,
            gap: 0.1,
            viss: 0.0,
            friction: law,
            area: 1.0,
            dt: 1e-3,
            linear: false,
        }
    }

    /// A keyword deck's contact: F = K0·P (no stiffening toward the gap),
    /// the nodal step sees K0, the damper VISs·2·√(K0·M); a node past the
    /// surface keeps being pushed by K0·P (LS-DYNA's penalty law).
    #[test]
    fn the_linear_penalty_law_of_a_keyword_contact() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        for z in [0.09, 0.05, 0.001] {
            let mut inp = input([0.3, 0.3, z], [0.0; 3], &xm, &vm, &law);
            inp.linear = true;
            let f = pair(&inp, &mut st).unwrap();
            let pen = 0.1 - z;
            assert!((f.fs[2] - 1000.0 * pen).abs() < 1e-9, "{z}: {:?}", f.fs);
            assert!((f.kt - 1000.0).abs() < 1e-9);
        }
        let mut inp = input([0.3, 0.3, 0.05], [0.0, 0.0, -2.0], &xm, &vm, &law);
        inp.linear = true;
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        let c = 0.05 * 2.0 * (1000.0f64 * 1.0).sqrt();
        assert!((f.fs[2] - (1000.0 * 0.05 + c * 2.0)).abs() < 1e-9, "{:?}", f.fs);
    }

    #[test]
    fn both_sides_and_balanced_moments() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let up = pair(&input([0.25, 0.5, 0.05], [0.0; 3], &xm, &vm, &law), &mut st).unwrap();
        assert!(up.fs[2] > 0.0);
        // F = K0·P·Gap/(Gap − P) with P = 0.05: 1000·0.05·2 = 100.
        assert!((up.fs[2] - 100.0).abs() < 1e-9);
        let down = pair(
            &input([0.25, 0.5, -0.05], [0.0; 3], &xm, &vm, &law),
            &mut st,
        )
        .unwrap();
        assert!((down.fs[2] + 100.0).abs() < 1e-9);
        // Segment forces −N_i·F have the same moment about the node as −F at the contact point.
        let mut m = [0.0; 3];
        for i in 0..4 {
            let f = geo::scale(up.fs, -up.shape[i]);
            m = geo::add(m, geo::cross(xm[i], f));
        }
        let m_ref = geo::cross(up.point, geo::scale(up.fs, -1.0));
        for k in 0..3 {
            assert!((m[k] - m_ref[k]).abs() < 1e-12);
        }
        // Outside the gap: nothing.
        assert!(pair(&input([0.25, 0.5, 0.2], [0.0; 3], &xm, &vm, &law), &mut st).is_none());
    }

    #[test]
    fn closing_speed_gives_damping_and_a_kinematic_step() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let mut inp = input([0.5, 0.5, 0.05], [0.0, 0.0, -2.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        let kt = 1000.0 * 4.0;
        // Closing at 2: C = VISs·√(2·Kt·M) + 0.4²·2·M·2/(Gap − P).
        let c = 0.05 * (2.0f64 * kt).sqrt() + 0.16 * 2.0 * 2.0 / 0.05;
        // The nodal step's stiffness: Kt and the damper over the step (note
        // contact_time_step_research.md §2).
        assert!((f.kt - (kt + c / 1e-3)).abs() < 1e-9 * kt);
        let expect = 100.0 + c * 2.0;
        assert!((f.fs[2] - expect).abs() < 1e-9);
        // EQ. 8.8.5.1: 0.5·(Gap − P)/(dP/dt) = 0.5·0.05/2.
        assert!((f.dt_kin - 0.0125).abs() < 1e-15);
    }

    #[test]
    fn opening_damper_works_on_the_secant_stiffness_and_may_pull() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        // Leaving at 2: C = VISs·√(2·Ks·M), Ks = K0·Gap/(Gap − P) = 2000.
        let mut inp = input([0.5, 0.5, 0.05], [0.0, 0.0, 2.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        let expect = 100.0 - 0.05 * (2.0f64 * 2000.0).sqrt() * 2.0;
        assert!((f.fs[2] - expect).abs() < 1e-9);
        // A node leaving fast from a shallow penetration is pulled back.
        let mut inp = input([0.5, 0.5, 0.0999], [0.0, 0.0, 50.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        assert!(f.fs[2] < 0.0 && f.f_n < 0.0, "{:?}", f.fs);
    }

    #[test]
    fn friction_damper_stiffens_the_nodal_step() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw {
            fric: 0.3,
            iform: 1,
            visf: 1.0,
            ..FrictionLaw::none()
        };
        let mut st = PairState::default();
        let mut inp = input([0.5, 0.5, 0.05], [1.0, 0.0, 0.0], &xm, &vm, &law);
        inp.dt = 1e-4;
        let f = pair(&inp, &mut st).unwrap();
        // Not moving along the normal: Ks = 2000; √(2·2000·1)/1e-4 > Kt = 4000.
        let k = (2.0f64 * 2000.0).sqrt() / 1e-4;
        assert!((f.kt - k).abs() < 1e-6 * k);
        // Without friction the step sees Kt only.
        let none = FrictionLaw::none();
        let mut inp = input([0.5, 0.5, 0.05], [1.0, 0.0, 0.0], &xm, &vm, &none);
        inp.dt = 1e-4;
        assert!((pair(&inp, &mut st).unwrap().kt - 4000.0).abs() < 1e-9);
    }

    /// One secondary node over one flat main segment, through the registry
    /// and the trait's kernel.
    #[test]
    fn the_registered_kernel_gives_the_penalty_force_over_a_flat_segment() {
        use crate::contact::interfaces::TypeOptions;
        let Some(TypeOptions::Type7(own)) = TypeOptions::by_number(7) else {
            panic!("TYPE7 is registered");
        };
        // Istf = 1000: K0 = Stfac·Km (card eq. (1)); Km = 1000, Stfac = 1.
        let own = Type7 {
            istf: 1000,
            stmax: 1e30,
            ..own
        };
        let p = Pass {
            segs: vec![[0, 1, 2, 3]],
            seg_k: vec![1000.0],
            seg_gap: vec![0.0],
            seg_lmin: vec![1.0],
            seg_area: vec![1.0],
            sec: vec![4],
            sec_k: vec![0.0],
            sec_gap: vec![0.0],
            sec_lmin: vec![0.0],
            ..Pass::default()
        };
        // Constant gap 0.1 (Igap 1000).
        let it = Interface {
            id: 1,
            type_number: 7,
            title: String::new(),
            options: TypeOptions::Type7(own),
            passes: Vec::new(),
            gap: GapRule {
                igap: 1000,
                gapmin: 0.1,
                fscalegap: 1.0,
                gapmax: 1e30,
                mesh_size_pct: 0.4,
            },
            max_gap: 0.1,
            margin: 0.01,
            stfac: 1.0,
            friction: FrictionLaw::none(),
            tstart: 0.0,
            tstop: 1e30,
            ibc: [false; 3],
            inacti: 0,
            idel: 0,
        };
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let c = PairContext {
            it: &it,
            p: &p,
            k: 0,
            m: 0,
            xs: [0.25, 0.5, 0.03],
            vs: [0.0; 3],
            ms: 1.0,
            xs_side: &[[0.25, 0.5, 0.03]; 4],
            vs_side: &[[0.0; 3]; 4],
            sec: super::super::Side::node(4),
            main: super::super::Side::segment(&[0, 1, 2, 3]),
            cnode_mass: &[1.0; 5],
            xm: &xm,
            vm: &vm,
            dt: 1e-3,
            bodies: &[],
            scale: None,
            memory: [0.0; 2],
        };
        let mut ns = NodeState::default();
        let mut st = PairState::default();
        let PairOutcome::Force(f) = it.ty().pair(&c, &mut ns, &mut st) else {
            panic!("the node is inside the gap");
        };
        // By hand: P = Gap − d = 0.1 − 0.03 = 0.07; Ks = K0·Gap/(Gap − P)
        // (EQ. 8.8.9.1, 8.8.11.1); F = Ks·P along the normal +z; no damper
        // (VISs = 0), no friction.
        let (k0, gap, pen) = (1000.0, 0.1, 0.07);
        let ks = k0 * gap / (gap - pen);
        let expect = ks * pen;
        assert!((f.pen - pen).abs() < 1e-15);
        assert_eq!(f.dir, [0.0, 0.0, 1.0]);
        assert!((f.fs[2] - expect).abs() < 1e-12 * expect, "{:?}", f.fs);
        assert_eq!((f.fs[0], f.fs[1]), (0.0, 0.0));
        assert!((f.f_n - expect).abs() < 1e-12 * expect);
        // Kt = K0·Gap²/(Gap − P)² (EQ. 8.8.9.2).
        let kt = k0 * (gap / (gap - pen)).powi(2);
        assert!((f.kt - kt).abs() < 1e-12 * kt);
        // The node takes all of F; the segment's shape functions sum to one.
        assert_eq!(f.sec_shape, NODE_SHAPE);
        assert!((f.shape.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        // Not closing: no kinematic limit (EQ. 8.8.5.1 needs dP/dt > 0).
        assert_eq!(it.ty().kinematic_step(&f), Some(f64::INFINITY));
        assert!(!ns.off);
    }

    #[test]
    fn coulomb_friction_opposes_sliding() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw {
            fric: 0.3,
            ..FrictionLaw::none()
        };
        let mut st = PairState::default();
        let inp = input([0.5, 0.5, 0.05], [5.0, 0.0, 0.0], &xm, &vm, &law);
        let mut f = pair(&inp, &mut st).unwrap();
        for _ in 0..1000 {
            f = pair(&inp, &mut st).unwrap();
        }
        assert!((f.fs[0] + 0.3 * 100.0).abs() < 1e-9, "{:?}", f.fs);
    }
}
