//! TYPE5 node-to-surface contact (theory manual §8.6), also each pass of
//! TYPE3 (§8.5.2): the node is penetrated when it is on the negative side of
//! its closest main segment (tetrahedron volume sign, §8.6.6.3) or within the
//! gap on the positive side; the reaction is a linear spring F = K·p along
//! the segment normal (EQ. 8.6.6.3) spread by the shape functions of the
//! contact point (EQ. 8.6.6.6); friction is incremental Coulomb with
//! Kt = K/10 (EQ. 8.5.4.1–4) and the Ifric laws and filter of §8.6.4.

use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes, NODE_SHAPE,
};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::{self, GapRule, InitialPenetration};
use crate::contact::geometry::{self as geo, V3};
use super::layout::{self, Interface, Pass};
use crate::contact::stiffness;
use crate::model::InterfaceKind;
use serde::{Deserialize, Serialize};

/// TYPE5 has no options of its own beyond the common ones
/// (`interfaces::CardCommon`: Stfac, Fric and its law, Gap, Tstart/Tstop,
/// IBC, Inacti, Idel).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type5 {}

impl InterfaceType for Type5 {
    fn type_number(&self) -> u32 {
        5
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type5(t) = kind else {
            return None;
        };
        if t.sens_id != 0 {
            Some("an activation sensor (sens_ID)")
        } else if t.inacti != 0 {
            Some("Inacti (moving nodes out of initial penetrations)")
        } else if t.ptlim < 1e29 {
            Some("a tangential pressure limit (Ptlim)")
        } else {
            None
        }
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Walk
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type5(t) = kind else {
            return None;
        };
        let common = CardCommon {
            stfac: t.stfac,
            friction: FrictionLaw {
                ifric: t.ifric,
                fric: t.fric,
                c: t.fric_coefs.unwrap_or([0.0; 6]),
                ifiltr: t.ifiltr,
                xfreq: t.xfreq,
                ..FrictionLaw::none()
            },
            gap_card: t.gap,
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: t.ibc,
            inacti: t.inacti,
            idel: t.idel,
        };
        Some((Type5 {}, common))
    }

    fn gap_rule(&self, common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        constant_gap(common.gap_card)
    }

    fn sorting_margin(&self) -> f64 {
        DEFAULT_BUMULT
    }

    /// EQ. 8.5.3.3.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        stiffness::brick_type3(bulk, area, volume)
    }

    /// s·Km (§8.6.3).
    fn pair_stiffness(&self, it: &Interface, p: &Pass, _k: usize, m: usize) -> f64 {
        it.stfac * p.seg_k[m]
    }

    fn walk(
        &self,
        it: &Interface,
        p: &Pass,
        s0: u32,
        xs: V3,
        x_of: &dyn Fn(u32) -> Option<V3>,
        seg_on: &dyn Fn(u32) -> bool,
    ) -> Option<u32> {
        walk(p, s0, xs, walk_reach(it, p), x_of, seg_on)
    }

    fn walk_reach(&self, max_diag: f64) -> f64 {
        2.0 * max_diag
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let k = self.pair_stiffness(c.it, c.p, c.k, c.m as usize);
        kernel(c, k, st)
    }

    fn initial_penetration(
        &self,
        it: &Interface,
        xs: V3,
        xm: &[V3; 4],
        tri: bool,
        g: f64,
    ) -> (InitialPenetration, f64) {
        initial_penetration(it, xs, xm, tri, g)
    }
}

/// Bumult of the types whose card has none.
pub const DEFAULT_BUMULT: f64 = 0.2;

/// The constant gap of TYPE3 and TYPE5.
pub fn constant_gap(gap: f64) -> GapRule {
    GapRule {
        igap: 1000,
        gapmin: gap,
        fscalegap: 1.0,
        gapmax: 1e30,
        mesh_size_pct: 0.4,
    }
}

/// How far the walk may look: a node within gap + 2·margin + the largest
/// segment of its last segment's nodes walks.
pub fn walk_reach(it: &Interface, p: &Pass) -> f64 {
    it.max_gap + 2.0 * it.margin + p.max_diag
}

/// The TYPE3/TYPE5 pair at spring stiffness `k` and the constant gap.
pub fn kernel(c: &PairContext, k: f64, st: &mut PairState) -> PairOutcome {
    let m = c.m as usize;
    let inp = Pair {
        xs: c.xs,
        vs: c.vs,
        xm: c.xm,
        vm: c.vm,
        tri: c.p.is_tri(m),
        k,
        gap: c.it.gap.gapmin,
        friction: &c.it.friction,
        area: c.p.seg_area[m],
        dt: c.dt,
    };
    match pair(&inp, st) {
        Some(f) => PairOutcome::Force(f),
        None => PairOutcome::Free,
    }
}

/// One-sided penetration (no Fpenmax on TYPE3, 5); Inacti decides.
pub fn initial_penetration(
    it: &Interface,
    xs: V3,
    xm: &[V3; 4],
    tri: bool,
    g: f64,
) -> (InitialPenetration, f64) {
    let p0 = penetration(xs, xm, tri, g).map(|r| r.0).unwrap_or(0.0);
    (gap::initial_penetration(it.inacti, 0.0, p0, g), p0)
}

/// TYPE5's engine search (§8.6.6.1): from the previous closest segment S0,
/// the node M1 of S0 closest to N; the segments around M1; the closest main
/// node M2 among their nodes; the closest of the segments around M2. The walk
/// is only taken while N is within `reach` of S0's nodes (farther nodes keep
/// their segment), so it only ever reads nodes every rank can see.
/// Segments removed by Idel (`seg_on` false) are never chosen, nor walked through.
pub fn walk(
    p: &Pass,
    s0: u32,
    xs: V3,
    reach: f64,
    x_of: &dyn Fn(u32) -> Option<V3>,
    seg_on: &dyn Fn(u32) -> bool,
) -> Option<u32> {
    let seg0 = p.segs[s0 as usize];
    let mut m1: Option<(f64, u32)> = None;
    for &c in &seg0 {
        let xc = x_of(c)?;
        let d = geo::norm(geo::sub(xc, xs));
        if d > reach {
            return None;
        }
        if m1.is_none_or(|b| d < b.0 || (d == b.0 && c < b.1)) {
            m1 = Some((d, c));
        }
    }
    let (_, m1) = m1?;
    let mut m2: Option<(f64, u32)> = None;
    for &sg in p.segments_around(m1) {
        if !seg_on(sg) {
            continue;
        }
        for &c in &p.segs[sg as usize] {
            let xc = x_of(c)?;
            let d = geo::norm(geo::sub(xc, xs));
            if m2.is_none_or(|b| d < b.0 || (d == b.0 && c < b.1)) {
                m2 = Some((d, c));
            }
        }
    }
    let (_, m2) = m2?;
    layout::closest_segment(p.segments_around(m2), xs, |sg| {
        if !seg_on(sg) {
            return None;
        }
        let seg = p.segs[sg as usize];
        let mut x = [[0.0; 3]; 4];
        for i in 0..4 {
            x[i] = x_of(seg[i])?;
        }
        Some(x)
    })
}

pub struct Pair<'a> {
    pub xs: V3,
    pub vs: V3,
    pub xm: &'a [V3; 4],
    pub vm: &'a [V3; 4],
    pub tri: bool,
    /// Interface spring stiffness K (EQ. 8.5.3.1 / 8.6.3.1).
    pub k: f64,
    pub gap: f64,
    pub friction: &'a FrictionLaw,
    pub area: f64,
    pub dt: f64,
}

/// Depth of the node below the segment's gap surface, if it projects inside
/// the segment: `gap − (x − c)·n` (positive when penetrated).
pub fn penetration(xs: V3, xm: &[V3; 4], tri: bool, gap: f64) -> Option<(f64, geo::Projection)> {
    let pr = geo::project(xs, xm, tri);
    let d = geo::sub(xs, pr.point);
    let ds = geo::dot(d, pr.normal);
    // Beyond an edge the closest point leaves the face: not this segment's contact.
    let off = geo::norm(friction::tangential(d, pr.normal));
    let size = geo::segment_area(xm, tri).sqrt();
    if off > 1e-6 * size {
        return None;
    }
    // `ds` has the sign of the tetrahedron (node, segment) volume (§8.6.6.3):
    // negative once the node is through the segment.
    Some((gap - ds, pr))
}

pub fn pair(p: &Pair, st: &mut PairState) -> Option<PairForce> {
    let (pen, pr) = penetration(p.xs, p.xm, p.tri, p.gap)?;
    if pen <= 0.0 {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let n = pr.normal;
    let f_n = p.k * pen;
    let vc = geo::interpolate(&pr.shape, p.vm);
    let vrel = geo::sub(p.vs, vc);
    let mut f_t = [0.0; 3];
    if p.friction.active() {
        let vt = friction::tangential(vrel, n);
        let pressure = if p.area > 0.0 { f_n / p.area } else { 0.0 };
        let mu = p.friction.mu(pressure, geo::norm(vt));
        let raw = friction::tangential_force(
            p.friction,
            mu,
            f_n,
            vt,
            n,
            0.1 * p.k,
            0.0,
            p.dt,
            &mut st.ft,
        );
        let a = p.friction.filter_alpha(p.dt);
        st.ff = geo::add(geo::scale(raw, a), geo::scale(st.ff, 1.0 - a));
        f_t = st.ff;
    }
    let fs = geo::add(geo::scale(n, f_n), f_t);
    Some(PairForce {
        fs,
        sec_shape: NODE_SHAPE,
        shape: pr.shape,
        kt: p.k,
        dt_kin: f64::INFINITY,
        f_n,
        f_t,
        pen,
        dir: n,
        point: pr.point,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sided_linear_spring() {
        let xm = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let mk = |z: f64| Pair {
            xs: [0.3, 0.3, z],
            vs: [0.0; 3],
            xm: &xm,
            vm: &vm,
            tri: false,
            k: 200.0,
            gap: 0.0,
            friction: &law,
            area: 1.0,
            dt: 1e-3,
        };
        assert!(pair(&mk(0.01), &mut st).is_none());
        let f = pair(&mk(-0.01), &mut st).unwrap();
        assert!((f.fs[2] - 2.0).abs() < 1e-12);
        // Beyond the edge: not this segment.
        let mut q = mk(-0.01);
        q.xs = [1.5, 0.3, -0.01];
        assert!(pair(&q, &mut st).is_none());
    }
}
