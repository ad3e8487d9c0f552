//! LS-DYNA's segment-based contact, SOFT = 2 on optional card A of a
//! keyword deck's *CONTACT_AUTOMATIC_SINGLE_SURFACE or _SURFACE_TO_SURFACE
//! (source document 003, "segment based contact"; no Radioss card has it,
//! so the keyword reader gives it as a TYPE7 card whose `DynaPenalty` says
//! SOFT 2, and this type takes such cards before TYPE7 does).
//!
//! Pairs are segments against segments (a secondary segment of the pass
//! against a main one; single-surface contact pairs each two segments of
//! the surface once and never two that share a node). For one pair:
//!
//! - Penetration: each node of one segment that lies over the other (the
//!   foot of its normal inside the other segment: the four edge planes)
//!   and closer to its mid-surface than the contact thickness
//!   g = (t1 + t2)/2 (shells' true thickness, a solid face 0) penetrates by
//!   g − its distance, measured on its side of the other segment (the side
//!   taken when the pair first touches and kept while it stays in contact,
//!   so a shell pushed through keeps being pushed back). The pair's depth
//!   is the deepest node's; the segment penetrated more is the slave, the
//!   other the master (source 003: "the least penetrated element to be the
//!   master"), judged at the first touch and kept.
//! - Baseline: the depth found when the pair first touches — at the start,
//!   the initial penetration — is stored and only further penetration
//!   pushes, f = k·(d − d_i); when the pair moves apart to less than d_i,
//!   that becomes the new baseline; the memory goes when it separates
//!   (source 003: "the initially penetrated location becomes the baseline").
//! - Stiffness: k = 0.5·SLSFAC·SF·m1·m2/(m1 + m2)/Δt_c² with m1, m2 the two
//!   segments' masses (a shell's element mass, half a solid's), SF = SFS
//!   when the secondary segment is the slave and SFM when the main one is,
//!   and Δt_c = 1.05 times the first solution step, reset to 1.05 times the
//!   step whenever the step rises above it (source 003, the interface's
//!   memory: [`InterfaceType::advance_memory`]).
//! - Force along the master's normal at the slave's penetrating nodes, each
//!   taking its share of the depth, and the opposite on the master's nodes
//!   at the feet of those normals (their shape functions), so force and
//!   moment balance; damping VDC % of critical on m1·m2/(m1 + m2); Coulomb
//!   friction FS in the incremental form with k as tangential penalty.
//! - DEPTH = 5 (edge to edge): a pair that first touches with no node over
//!   the other segment but two of their edges crossing closer than g (the
//!   closest points inside both edges) is an edge pair: the depth is g
//!   minus the edges' distance along their common normal (side kept from
//!   the first touch), the force acts along that normal on the two edges'
//!   nodes by the closest points' weights, with the same baseline and
//!   stiffness (source 003, "edge to edge" of version 970).
//! - Time step: the penalty k + c/Δt enters the nodal step (EQ. 8.8.5.2);
//!   no kinematic step (source 003: the contact step is not meaningful).

use super::layout::{Interface, Pass};
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes,
};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::GapRule;
use crate::contact::geometry::{self as geo, V3};
use crate::contact::{edge_geometry, stiffness};
use crate::model::contact::EP30;
use crate::model::{self, InterfaceKind};
use crate::vec3::{add, cross, dot, norm, scale, sub};
use serde::{Deserialize, Serialize};

/// The segment-based contact's options (from the keyword deck's card).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DynaSegment {
    /// SLSFAC·SFS and SLSFAC·SFM.
    pub f_sec: f64,
    pub f_main: f64,
    /// Damping, a fraction of critical (VDC/100).
    pub vdc: f64,
    /// DEPTH = 5: edge-to-edge crossings too.
    pub edges: bool,
}

/// How a pair touches, fixed at its first touch (`PairState::pen_memory[2]`).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    /// The secondary segment penetrates the main one.
    SecSlave,
    /// The main segment penetrates the secondary one.
    MainSlave,
    /// Edge `i` of the secondary segment crosses edge `j` of the main one.
    Edges(usize, usize),
}

impl Mode {
    fn code(self) -> f64 {
        match self {
            Mode::SecSlave => 1.0,
            Mode::MainSlave => 2.0,
            Mode::Edges(i, j) => (10 + 4 * i + j) as f64,
        }
    }
    fn of(code: f64) -> Mode {
        match code as usize {
            1 => Mode::SecSlave,
            2 => Mode::MainSlave,
            c => Mode::Edges((c - 10) / 4, (c - 10) % 4),
        }
    }
}

/// One segment as a kernel sees it: its nodes' positions, velocities, how
/// many there are (3 or 4).
#[derive(Clone, Copy)]
struct Seg<'a> {
    x: &'a [V3; 4],
    v: &'a [V3; 4],
    n: usize,
}

impl Seg<'_> {
    fn tri(&self) -> bool {
        self.n == 3
    }
    fn normal(&self) -> V3 {
        geo::segment_normal(self.x, self.tri())
    }
    fn centre(&self) -> V3 {
        let s = self.x[..self.n].iter().fold([0.0; 3], |a, &b| add(a, b));
        scale(s, 1.0 / self.n as f64)
    }
    fn edge(&self, i: usize) -> (V3, V3) {
        (self.x[i], self.x[(i + 1) % self.n])
    }
}

/// One side's penetration of the other: the depth, the slave's node
/// weights, the master's shape functions and the master's normal (towards
/// the slave).
struct Depth {
    d: f64,
    w_slave: [f64; 4],
    n_master: [f64; 4],
    dir: V3,
}

/// How far the nodes of `slave` on side `side` (±1) of `master` penetrate
/// it with contact thickness `g`: `None` when no node over `master` is
/// within g of it.
fn surface_depth(slave: Seg, master: Seg, g: f64, side: f64) -> Option<Depth> {
    let normal = master.normal();
    let mut w = [0.0; 4];
    let mut shape = [0.0; 4];
    let mut d_max = 0.0f64;
    for i in 0..slave.n {
        let pr = geo::project(slave.x[i], master.x, master.tri());
        let over = pr.dist == 0.0 || dot(pr.dir, normal).abs() >= 1.0 - 1e-9;
        let depth = g - side * dot(sub(slave.x[i], pr.point), normal);
        if over && depth > 0.0 {
            w[i] = depth;
            for j in 0..4 {
                shape[j] += depth * pr.shape[j];
            }
            d_max = d_max.max(depth);
        }
    }
    let sum: f64 = w.iter().sum();
    (sum > 0.0).then(|| Depth {
        d: d_max,
        w_slave: w.map(|x| x / sum),
        n_master: shape.map(|x| x / sum),
        dir: scale(normal, side),
    })
}

/// Edge `i` of `a` against edge `j` of `b`: the common normal (a's side
/// `side`), the depth g − distance along it and the weights of the closest
/// points; `None` for parallel edges or closest points at an end.
fn edge_depth(a: Seg, b: Seg, (i, j): (usize, usize), g: f64, side: f64) -> Option<Depth> {
    let (a1, a2) = a.edge(i);
    let (b1, b2) = b.edge(j);
    let c = cross(sub(a2, a1), sub(b2, b1));
    let l = norm(c);
    if l <= 1e-9 * norm(sub(a2, a1)) * norm(sub(b2, b1)) {
        return None;
    }
    let e = edge_geometry::closest_points_of_edges(a1, a2, b1, b2);
    let inside = |h: f64| h > 0.0 && h < 1.0;
    if !inside(e.h_s) || !inside(e.h_m) {
        return None;
    }
    let dir = scale(c, side / l);
    let (ws, wm) = e.weights();
    let mut w_slave = [0.0; 4];
    let mut n_master = [0.0; 4];
    w_slave[i] = ws[0];
    w_slave[(i + 1) % a.n] += ws[1];
    n_master[j] = wm[0];
    n_master[(j + 1) % b.n] += wm[1];
    Some(Depth {
        d: g - dot(e.n, dir),
        w_slave,
        n_master,
        dir,
    })
}

/// The side (±1) point `p` is on of a plane through `o` with normal `n`.
fn side_of(p: V3, o: V3, n: V3) -> f64 {
    if dot(sub(p, o), n) >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// A new touch: how the pair touches and its sides, or `None`.
fn first_touch(a: Seg, b: Seg, g: f64, edges: bool) -> Option<(Mode, f64, f64)> {
    let s_ab = side_of(a.centre(), b.centre(), b.normal());
    let s_ba = side_of(b.centre(), a.centre(), a.normal());
    let ab = surface_depth(a, b, g, s_ab).map_or(0.0, |d| d.d);
    let ba = surface_depth(b, a, g, s_ba).map_or(0.0, |d| d.d);
    if ab > 0.0 || ba > 0.0 {
        let mode = if ab >= ba {
            Mode::SecSlave
        } else {
            Mode::MainSlave
        };
        return Some((mode, s_ab, s_ba));
    }
    if !edges {
        return None;
    }
    let mut best: Option<(f64, Mode, f64)> = None;
    for i in 0..a.n {
        for j in 0..b.n {
            let (a1, a2) = a.edge(i);
            let (b1, b2) = b.edge(j);
            let e = edge_geometry::closest_points_of_edges(a1, a2, b1, b2);
            let c = cross(sub(a2, a1), sub(b2, b1));
            let side = if dot(e.n, c) >= 0.0 { 1.0 } else { -1.0 };
            if let Some(d) = edge_depth(a, b, (i, j), g, side) {
                if d.d > 0.0 && best.is_none_or(|b| d.d > b.0) {
                    best = Some((d.d, Mode::Edges(i, j), side));
                }
            }
        }
    }
    best.map(|b| (b.1, b.2, 0.0))
}

/// The pair's penetration now in its mode, as force on the secondary
/// segment: direction, the secondary nodes' weights, the main nodes'.
fn current_depth(a: Seg, b: Seg, g: f64, mode: Mode, s_ab: f64, s_ba: f64) -> Option<Depth> {
    match mode {
        Mode::SecSlave => surface_depth(a, b, g, s_ab),
        Mode::MainSlave => surface_depth(b, a, g, s_ba).map(|d| Depth {
            d: d.d,
            w_slave: d.n_master,
            n_master: d.w_slave,
            dir: scale(d.dir, -1.0),
        }),
        Mode::Edges(i, j) => edge_depth(a, b, (i, j), g, s_ab),
    }
}

impl InterfaceType for DynaSegment {
    /// No Radioss number: the keyword reader's SOFT = 2 (listed under its
    /// TYPE7 card).
    fn type_number(&self) -> u32 {
        DYNA_SEGMENT
    }

    fn unsupported(_kind: &InterfaceKind) -> Option<&'static str> {
        None
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::SegmentToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Sort
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type7(t) = kind else {
            return None;
        };
        let d = t.dyna.filter(|d| d.soft == 2)?;
        let own = DynaSegment {
            f_sec: d.slsfac * d.sfs,
            f_main: d.slsfac * d.sfm,
            vdc: t.viss,
            edges: d.depth == 5,
        };
        let common = CardCommon {
            stfac: 1.0,
            friction: FrictionLaw {
                fric: t.fric,
                iform: 2,
                ..FrictionLaw::none()
            },
            gap_card: 0.0,
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: [false; 3],
            inacti: 1000,
            idel: 0,
        };
        Some((own, common))
    }

    /// One pass: the surface's segments against themselves (single surface)
    /// or the secondary surface's against the main one's.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<super::PassSides<'a>> {
        let (sec_segs, self_contact) = if i.secondary_segments.is_empty() {
            (&i.main_segments[..], true)
        } else {
            (&i.secondary_segments[..], false)
        };
        vec![super::PassSides {
            sec: Vec::new(),
            own: None,
            main: &i.main_segments,
            sec_edges: &[],
            main_edges: &[],
            sec_segs: std::borrow::Cow::Borrowed(sec_segs),
            self_contact,
        }]
    }

    /// For the search reach: the two half thicknesses.
    fn gap_rule(&self, _common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        GapRule {
            igap: 2,
            gapmin: 0.0,
            fscalegap: 1.0,
            gapmax: EP30,
            mesh_size_pct: 0.4,
        }
    }

    fn sorting_margin(&self) -> f64 {
        0.2
    }

    fn solid_segment_stiffness(&self, _bulk: f64, _area: f64, _volume: f64) -> f64 {
        0.0
    }

    /// The segment's mass, which this type's passes keep where others keep
    /// a stiffness (`seg_k`, `sec_k`): a shell's element mass, half a
    /// solid's (source 003; the keyword manual's TETFAC: "half the mass of
    /// a solid element is considered for the contact segment").
    fn element_stiffness(&self, el: &stiffness::ElementSize, _main: bool) -> Option<f64> {
        Some(if el.shell { el.mass } else { 0.5 * el.mass })
    }

    /// SLSFAC·SFS·m1·m2/(m1 + m2), to be halved and divided by Δt_c².
    fn pair_stiffness(&self, _it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        stiffness::mass_time_step(self.f_sec, p.sec_k[k], p.seg_k[m], 1.0)
    }

    /// Δt_c = 1.05·Δt at the first step, and again whenever Δt passes it.
    fn advance_memory(&self, memory: &mut [f64; 2], dt: f64) {
        if dt > 0.0 && (memory[0] == 0.0 || dt > memory[0]) {
            memory[0] = 1.05 * dt;
        }
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let (p, k, m) = (c.p, c.k, c.m as usize);
        let a = Seg {
            x: c.xs_side,
            v: c.vs_side,
            n: c.sec.count as usize,
        };
        let b = Seg {
            x: c.xm,
            v: c.vm,
            n: c.main.count as usize,
        };
        let g = p.sec_gap[k] + p.seg_gap[m];
        if st.side == 0 {
            let Some((mode, s_ab, s_ba)) = first_touch(a, b, g, self.edges) else {
                return PairOutcome::Free;
            };
            st.side = s_ab as i8;
            st.pen_memory = [f64::INFINITY, s_ba, mode.code()];
        }
        let mode = Mode::of(st.pen_memory[2]);
        let depth = current_depth(a, b, g, mode, f64::from(st.side), st.pen_memory[1]);
        let Some(depth) = depth.filter(|d| d.d > 0.0) else {
            *st = PairState::default();
            return PairOutcome::Free;
        };
        st.pen_memory[0] = st.pen_memory[0].min(depth.d);
        let pen = depth.d - st.pen_memory[0];
        let (ms, mm) = (p.sec_k[k], p.seg_k[m]);
        let f = if mode == Mode::MainSlave {
            self.f_main
        } else {
            self.f_sec
        };
        let dtc = c.memory[0];
        let kp = 0.5 * stiffness::mass_time_step(f, ms, mm, dtc);
        if pen <= 0.0 || kp == 0.0 {
            return PairOutcome::Free;
        }
        let mass = ms * mm / (ms + mm).max(1e-300);
        PairOutcome::Force(self.force(c, &depth, pen, kp, mass, st, a, b))
    }
}

/// The registry number of LS-DYNA's segment-based contact: none of the
/// Radioss types' (/INTER/TYPE1..25).
pub const DYNA_SEGMENT: u32 = 1002;

impl DynaSegment {
    /// The pair's force from its penetration `pen` beyond the baseline.
    #[allow(clippy::too_many_arguments)]
    fn force(
        &self,
        c: &PairContext,
        depth: &Depth,
        pen: f64,
        kp: f64,
        mass: f64,
        st: &mut PairState,
        a: Seg,
        b: Seg,
    ) -> PairForce {
        let va = geo::interpolate(&depth.w_slave, a.v);
        let vb = geo::interpolate(&depth.n_master, b.v);
        let vrel = sub(va, vb);
        let dpdt = -dot(vrel, depth.dir);
        let damper = self.vdc * 2.0 * (kp * mass).sqrt();
        let f_n = (kp * pen + damper * dpdt).max(0.0);
        let law = &c.it.friction;
        let mut f_t = [0.0; 3];
        if law.active() && f_n > 0.0 {
            let vt = friction::tangential(vrel, depth.dir);
            f_t = friction::tangential_force(
                law, law.fric, f_n, vt, depth.dir, kp, mass, c.dt, &mut st.ft,
            );
        }
        let kt = if c.dt > 0.0 { kp + damper / c.dt } else { kp };
        PairForce {
            fs: add(scale(depth.dir, f_n), f_t),
            sec_shape: depth.w_slave,
            shape: depth.n_master,
            kt,
            dt_kin: f64::INFINITY,
            f_n,
            f_t,
            pen,
            dir: depth.dir,
            point: geo::interpolate(&depth.n_master, b.x),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ZERO: [V3; 4] = [[0.0; 3]; 4];

    fn square(z: f64, dx: f64) -> [V3; 4] {
        [
            [dx, 0.0, z],
            [dx + 1.0, 0.0, z],
            [dx + 1.0, 1.0, z],
            [dx, 1.0, z],
        ]
    }

    #[test]
    fn a_shell_pair_closer_than_the_mean_thickness_penetrates_by_the_difference() {
        let (xa, xb) = (square(0.7, 0.0), square(0.0, 0.0));
        let (a, b) = (Seg { x: &xa, v: &ZERO, n: 4 }, Seg { x: &xb, v: &ZERO, n: 4 });
        let (mode, s_ab, s_ba) = first_touch(a, b, 1.0, false).unwrap();
        assert_eq!((mode, s_ab, s_ba), (Mode::SecSlave, 1.0, -1.0));
        let d = current_depth(a, b, 1.0, mode, s_ab, s_ba).unwrap();
        assert!((d.d - 0.3).abs() < 1e-12 && d.dir == [0.0, 0.0, 1.0]);
        assert!(d.w_slave.iter().all(|&w| (w - 0.25).abs() < 1e-12));
        assert!((d.n_master.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        // Pushed through the mid-plane, the side stays: the depth grows.
        let xa2 = square(-0.2, 0.0);
        let a2 = Seg { x: &xa2, ..a };
        let d2 = current_depth(a2, b, 1.0, mode, s_ab, s_ba).unwrap();
        assert!((d2.d - 1.2).abs() < 1e-12 && d2.dir[2] == 1.0);
        // Beside it (no node over the other), no touch.
        let xa3 = square(0.7, 1.5);
        assert!(first_touch(Seg { x: &xa3, ..a }, b, 1.0, false).is_none());
    }

    #[test]
    fn the_more_penetrated_segment_is_the_slave() {
        // A small segment over the middle of a large one: only its nodes
        // are over the other.
        let big = [[-2.0, -2.0, 0.0], [3.0, -2.0, 0.0], [3.0, 3.0, 0.0], [-2.0, 3.0, 0.0]];
        let small = square(0.5, 0.0);
        let b = Seg { x: &small, v: &ZERO, n: 4 };
        let a = Seg { x: &big, v: &ZERO, n: 4 };
        let (mode, s_ab, s_ba) = first_touch(a, b, 1.0, false).unwrap();
        assert_eq!(mode, Mode::MainSlave);
        let d = current_depth(a, b, 1.0, mode, s_ab, s_ba).unwrap();
        // The force on the big (secondary) segment points down, away from
        // the small one above it; the small one's nodes take the weights.
        assert!((d.d - 0.5).abs() < 1e-12 && d.dir == [0.0, 0.0, -1.0]);
        assert!(d.n_master.iter().all(|&w| (w - 0.25).abs() < 1e-12));
    }

    #[test]
    fn crossing_edges_are_found_only_with_depth_5() {
        // Segment a in the plane y = 0 above segment b in the plane x = 0.5:
        // a's bottom edge along x crosses b's top edge along y, 0.2 apart.
        let xa = [[0.0, 0.0, 0.2], [1.0, 0.0, 0.2], [1.0, 0.0, 1.2], [0.0, 0.0, 1.2]];
        let xb = [[0.5, -0.5, -1.0], [0.5, 0.5, -1.0], [0.5, 0.5, 0.0], [0.5, -0.5, 0.0]];
        let a = Seg { x: &xa, v: &ZERO, n: 4 };
        let b = Seg { x: &xb, v: &ZERO, n: 4 };
        assert!(first_touch(a, b, 0.5, false).is_none());
        let (mode, side, _) = first_touch(a, b, 0.5, true).unwrap();
        assert_eq!(mode, Mode::Edges(0, 2));
        let d = current_depth(a, b, 0.5, mode, side, 0.0).unwrap();
        assert!((d.d - 0.3).abs() < 1e-12, "{}", d.d);
        // Pushes a up, b down; the closest points halve both edges.
        assert!((d.dir[2] - 1.0).abs() < 1e-12);
        assert!((d.w_slave[0] - 0.5).abs() < 1e-12 && (d.w_slave[1] - 0.5).abs() < 1e-12);
        assert!((d.n_master[2] - 0.5).abs() < 1e-12 && (d.n_master[3] - 0.5).abs() < 1e-12);
        // Once through, the kept side measures the crossing as deeper.
        let xa2 = xa.map(|p| [p[0], p[1], p[2] - 0.4]);
        let d2 = current_depth(Seg { x: &xa2, ..a }, b, 0.5, mode, side, 0.0).unwrap();
        assert!((d2.d - 0.7).abs() < 1e-12, "{}", d2.d);
    }

    #[test]
    fn the_contact_step_is_105_percent_of_the_first_step_and_follows_it_up() {
        let t = DynaSegment::default();
        let mut mem = [0.0; 2];
        t.advance_memory(&mut mem, 0.0);
        assert_eq!(mem[0], 0.0);
        t.advance_memory(&mut mem, 1.0e-3);
        assert!((mem[0] - 1.05e-3).abs() < 1e-18);
        t.advance_memory(&mut mem, 1.04e-3);
        assert!((mem[0] - 1.05e-3).abs() < 1e-18);
        t.advance_memory(&mut mem, 0.5e-3);
        assert!((mem[0] - 1.05e-3).abs() < 1e-18);
        t.advance_memory(&mut mem, 1.06e-3);
        assert!((mem[0] - 1.113e-3).abs() < 1e-15);
    }
}
