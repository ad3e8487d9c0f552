//! Contact interfaces, laid out as Tribol does: `search` finds candidate
//! pairs, `geometry` measures them, `stiffness`/`gap`/`friction` turn a
//! measured gap into a force, `interfaces` composes them per interface type
//! (one file per type behind the `interfaces::InterfaceType` trait and its
//! registry), and `exchange` carries ghosts and forces between ranks, summed
//! in the order of `key::SumKey`.
//!
//! [`ContactSystem`] is one rank's runtime: it keeps the positions and
//! velocities of the contact nodes it holds or receives as ghosts, rebuilds
//! candidate lists when the largest motion since the last sort exceeds half
//! the sorting margin (decided globally), computes the pairs of the secondary
//! nodes it owns (`pairs`, through each interface's type), and returns each
//! node's contact force summed in a fixed global order. It never names an
//! interface type.

mod close_neighbours;
pub mod edge_geometry;
mod edge_setup;
mod element_data;
pub mod exchange;
pub mod friction;
pub mod gap;
pub mod geometry;
pub mod inacti3;
mod inner_faces;
pub mod interfaces;
pub mod key;
mod pairs;
pub mod restart;
pub mod search;
pub mod setup;
pub mod stiffness;
pub mod tied;

use crate::domain::Subdomain;
use crate::kinematics::rigid_body::{NodeLoad, RigidBodyState};
use crate::parallel::World;
use exchange::GhostPlan;
use geometry::{self as geo, V3};
use interfaces::{CandidateSearch, NodeState, PairState};
use rayon::prelude::*;
use search::{Aabb, Candidates};
use setup::{ContactSetup, NONE};

/// Idel on one pass, replicated on every rank (every rank learns the same
/// deleted elements at the same cycle, so every rank removes the same
/// segments and nodes at the same cycle).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
struct Removal {
    /// Associated elements still alive, per main segment / secondary node.
    seg_alive: Vec<u32>,
    sec_alive: Vec<u32>,
    /// Removed from the interface.
    seg_off: Vec<bool>,
    sec_off: Vec<bool>,
}

/// What an element's deletion does to one entity of a pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum OnDeletion {
    /// Idel: one of a main segment's elements is gone.
    Segment,
    /// Idel = 1, 2: one of a secondary node's (edge's) elements is gone.
    Node,
    /// A dormant face between two solids loses its neighbour: it wakes.
    Wake,
}

/// Element (kind index, element index) → (interface, pass, segment or
/// secondary index, what its deletion does there).
type IdelIndex = std::collections::HashMap<(u8, u32), Vec<(u32, u32, u32, OnDeletion)>>;

/// Segments and nodes an interface removed at one cycle (Idel), for the listing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Removed {
    pub inter_id: u64,
    pub type_number: u32,
    pub idel: i64,
    /// Main segments (edges) and secondary nodes (edges) removed.
    pub segments: u64,
    pub nodes: u64,
    /// The interface pairs edges: `segments` and `nodes` count edges.
    pub edges: bool,
    /// Totals since the start.
    pub segments_total: u64,
    pub nodes_total: u64,
}

/// One pass on this rank: the owned secondary nodes, their candidates and pair memory.
#[derive(Clone, Debug, Default)]
struct PassRun {
    /// Indices into `Pass::sec` of the secondary nodes this rank owns.
    mine: Vec<u32>,
    nodes: Vec<NodeState>,
    /// Sorting types: the candidate segments of each node and their pair memory.
    cand: Candidates,
    state: Vec<PairState>,
    /// Node passes of sorting types: each candidate's distance to its
    /// segment at the last sort, less a round-off allowance (`pairs::
    /// sort_distance`), beside `cand.segs`; empty when not measured (after
    /// a restart, until the next sort).
    dist_sort: Vec<f64>,
    /// Walk types: one pair per node (its current segment and memory).
    walk_pair: Vec<(u32, PairState)>,
    /// Idel: removed segments and nodes (empty vectors when Idel is off).
    removal: Removal,
}

/// A pass's removal state at the start: Idel's counts of living elements,
/// and every dormant face (`Pass::seg_wakers`) off until woken.
fn removal_of(p: &setup::Pass, rule: Option<setup::IdelRule>) -> Removal {
    if rule.is_none() && p.seg_wakers.is_empty() {
        return Removal::default();
    }
    let mut seg_off = vec![false; p.segs.len()];
    for &(m, _) in &p.seg_wakers {
        seg_off[m as usize] = true;
    }
    let nodes = rule.is_some_and(|r| r.nodes);
    Removal {
        seg_alive: match rule {
            Some(_) => (0..p.segs.len())
                .map(|m| p.elements_of_segment(m).len() as u32)
                .collect(),
            None => Vec::new(),
        },
        sec_alive: if nodes {
            (0..p.n_sec())
                .map(|k| p.elements_of_secondary(k).len() as u32)
                .collect()
        } else {
            Vec::new()
        },
        seg_off,
        sec_off: if nodes {
            vec![false; p.n_sec()]
        } else {
            Vec::new()
        },
    }
}

impl PassRun {
    fn seg_off(&self, m: u32) -> bool {
        self.removal
            .seg_off
            .get(m as usize)
            .copied()
            .unwrap_or(false)
    }
    fn sec_off(&self, k: u32) -> bool {
        self.removal
            .sec_off
            .get(k as usize)
            .copied()
            .unwrap_or(false)
    }
}

/// Per-interface sums over this rank's pairs (diagnostics, summed over ranks by the caller).
#[derive(Clone, Copy, Debug, Default)]
pub struct InterfaceSums {
    /// Normal and tangential force resultants on the secondary side.
    pub f_normal: V3,
    pub f_tangent: V3,
    /// Number of pairs in contact.
    pub pairs: u64,
    /// Work taken by this interface's pairs since the start, −Σ F·(v_s − v_c)·Δt
    /// with the velocities at the force evaluation (the run's contact energy
    /// uses the step's mean velocities; this split per interface is approximate).
    pub energy: f64,
}

/// This rank's contact limits on the time step (unscaled).
///
/// - Nodal (EQ. 8.8.5.2, Δt = √(2M/K) with K = K_inter + K_el): the largest
///   q = K_inter/(2M) over the nodes, combined by the caller with the element
///   step as Δt = 1/√(1/Δt_el² + q), the stable step of a node held by its
///   elements and its contact springs together.
/// - Kinematic (EQ. 8.8.5.1): the smallest 0.5·(Gap − p)/(dp/dt).
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct ContactStep {
    pub nodal_q: f64,
    pub node_id: u64,
    pub kin_dt: f64,
    pub inter_id: u64,
}

/// Counters for the benchmark.
#[derive(Clone, Copy, Debug, Default)]
pub struct ContactTimers {
    pub sorts: u64,
    pub search_s: f64,
    pub force_s: f64,
    pub exchange_s: f64,
}

pub struct ContactSystem {
    pub setup: ContactSetup,
    /// Local index of each cnode (NONE: not on this rank).
    local: Vec<u32>,
    owned: Vec<bool>,
    /// Local cnodes (held), and the owned ones per interface's main side.
    held: Vec<u32>,
    main_owned: Vec<Vec<u32>>,
    cx: Vec<V3>,
    cv: Vec<V3>,
    avail: Vec<bool>,
    x_sort: Vec<V3>,
    /// The largest motion of any contact node since the last sort, less a
    /// common translation (`relative_motion`; all ranks; 0 in a sorting
    /// cycle).
    motion: f64,
    plan: GhostPlan,
    runs: Vec<Vec<PassRun>>,
    sorted_once: bool,
    /// Sort every cycle (benchmark reference).
    pub always_sort: bool,
    pub sums: Vec<InterfaceSums>,
    /// Each interface's memory from cycle to cycle, the same on every rank:
    /// total-force types' (TYPE6 Iform 1/2: the last largest penetration
    /// and force, following the reduced p_max) and the others'
    /// (`InterfaceType::advance_memory`: LS-DYNA's segment-based contact
    /// keeps its contact time step there).
    pub(super) total_memory: Vec<[f64; 2]>,
    pub timers: ContactTimers,
    node_ids: Vec<u64>,
    /// Idel: element (kind index, element index) → the (interface, pass,
    /// index, is a secondary node) it is associated with; empty when no
    /// interface deletes.
    idel_index: IdelIndex,
    /// Elements already known deleted (all ranks).
    dead: std::collections::HashSet<(u8, u32)>,
    /// The reactions of analytic main surfaces on their rigid bodies from
    /// this rank's pairs at the last `compute`: (body index, load at the
    /// contact point, keyed by the secondary node).
    pub body_loads: Vec<(usize, NodeLoad)>,
    /// What the interfaces removed at the last `compute`, and totals.
    removed_now: Vec<Removed>,
    removed_total: Vec<(u64, u64)>,
}

impl ContactSystem {
    /// The friction dampers' stability cap for a run at `scale` times the
    /// critical time step (the /DT scale factor).
    pub fn set_time_step_scale(&mut self, scale: f64) {
        for it in self.setup.interfaces.iter_mut() {
            it.friction = it.friction.clone().with_time_step_scale(scale);
        }
    }

    pub fn new(setup: ContactSetup, sd: &Subdomain, node_ids: &[u64]) -> ContactSystem {
        let nc = setup.nodes.len();
        let mut local = vec![NONE; nc];
        let mut owned = vec![false; nc];
        let mut held = Vec::new();
        let mut i = 0usize;
        for (c, &g) in setup.nodes.iter().enumerate() {
            while i < sd.node_global.len() && sd.node_global[i] < g {
                i += 1;
            }
            if i < sd.node_global.len() && sd.node_global[i] == g {
                local[c] = i as u32;
                owned[c] = sd.owns(i as u32);
                held.push(c as u32);
            }
        }
        let main_owned = setup
            .interfaces
            .iter()
            .map(|it| {
                let mut v: Vec<u32> = it
                    .passes
                    .iter()
                    .flat_map(|p| p.segs.iter().flatten().copied())
                    .filter(|&c| owned[c as usize])
                    .collect();
                v.sort_unstable();
                v.dedup();
                v
            })
            .collect();
        let runs = setup
            .interfaces
            .iter()
            .map(|it| {
                it.passes
                    .iter()
                    .map(|p| {
                        // A node's pairs are computed by its owner; an
                        // edge's or segment's by the lowest rank holding
                        // all its nodes.
                        let mine: Vec<u32> = (0..p.n_sec() as u32)
                            .filter(|&k| {
                                if p.is_entity_pass() {
                                    setup.owner_of(&p.sec_side(k as usize)) == Some(sd.rank)
                                } else {
                                    owned[p.sec[k as usize] as usize]
                                }
                            })
                            .collect();
                        let nodes = mine
                            .iter()
                            .map(|&k| NodeState {
                                last_seg: p.sec_start_seg.get(k as usize).copied().unwrap_or(NONE),
                                ..Default::default()
                            })
                            .collect();
                        let n = mine.len();
                        let removal = removal_of(p, setup::IdelRule::of(it.idel));
                        PassRun {
                            mine,
                            nodes,
                            cand: Candidates {
                                ptr: vec![0; n + 1],
                                segs: Vec::new(),
                            },
                            state: Vec::new(),
                            dist_sort: Vec::new(),
                            walk_pair: vec![(NONE, PairState::default()); n],
                            removal,
                        }
                    })
                    .collect()
            })
            .collect();
        let sums = vec![InterfaceSums::default(); setup.interfaces.len()];
        let mut idel_index = IdelIndex::new();
        for (ii, it) in setup.interfaces.iter().enumerate() {
            for (pi, p) in it.passes.iter().enumerate() {
                let mut add = |e: (u8, u32), idx: usize, what: OnDeletion| {
                    idel_index
                        .entry(e)
                        .or_default()
                        .push((ii as u32, pi as u32, idx as u32, what));
                };
                for &(m, e) in &p.seg_wakers {
                    add(e, m as usize, OnDeletion::Wake);
                }
                if setup::IdelRule::of(it.idel).is_none() {
                    continue;
                }
                for m in 0..p.segs.len() {
                    for &e in p.elements_of_segment(m) {
                        add(e, m, OnDeletion::Segment);
                    }
                }
                for k in 0..p.n_sec() {
                    for &e in p.elements_of_secondary(k) {
                        add(e, k, OnDeletion::Node);
                    }
                }
            }
        }
        let removed_total = vec![(0, 0); setup.interfaces.len()];
        ContactSystem {
            idel_index,
            dead: std::collections::HashSet::new(),
            removed_now: Vec::new(),
            body_loads: Vec::new(),
            removed_total,
            local,
            owned,
            held,
            main_owned,
            cx: setup.x0.clone(),
            cv: vec![[0.0; 3]; nc],
            avail: vec![false; nc],
            x_sort: setup.x0.clone(),
            motion: 0.0,
            plan: GhostPlan::default(),
            runs,
            sorted_once: false,
            always_sort: false,
            total_memory: vec![[0.0; 2]; sums.len()],
            sums,
            timers: ContactTimers::default(),
            node_ids: setup.nodes.iter().map(|&g| node_ids[g as usize]).collect(),
            setup,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.setup.is_empty()
    }

    /// Some interface removes segments or nodes of deleted elements (Idel):
    /// `compute` then wants this rank's newly deleted elements every cycle.
    pub fn tracks_deletion(&self) -> bool {
        !self.idel_index.is_empty()
    }

    /// What the interfaces removed at the last `compute` (Idel), identical on every rank.
    pub fn removed(&self) -> &[Removed] {
        &self.removed_now
    }

    /// Ghost nodes this rank currently receives.
    pub fn ghost_count(&self) -> usize {
        self.plan.ghost_count()
    }

    /// A secondary entity for messages: "node ID" or "edge ID1-ID2".
    fn secondary_name(node_ids: &[u64], p: &setup::Pass, k: usize) -> String {
        let side = p.sec_side(k);
        let ids: Vec<String> = side
            .nodes()
            .iter()
            .map(|&c| node_ids[c as usize].to_string())
            .collect();
        if p.is_edge_pass() {
            format!("edge {}", ids.join("-"))
        } else if p.is_segment_pass() {
            format!("segment {}", ids.join("-"))
        } else {
            format!("node {}", ids[0])
        }
    }

    /// Candidate pairs this rank holds from its last sort (sorting types).
    pub fn candidate_count(&self) -> usize {
        self.runs.iter().flatten().map(|r| r.cand.segs.len()).sum()
    }

    /// Secondary nodes this rank owns (all passes, all interfaces).
    pub fn owned_secondary(&self) -> usize {
        self.runs.iter().flatten().map(|r| r.mine.len()).sum()
    }

    /// Contact forces at the current state, added to `fc` (local nodes, in the
    /// fixed order of their keys); contact stiffness per node added to `kc`.
    /// Returns the smallest unscaled contact time step on this rank and the
    /// local nodes whose boundary conditions an impact releases (IBC).
    #[allow(clippy::too_many_arguments)]
    pub fn compute(
        &mut self,
        world: &World,
        x: &[V3],
        v: &[V3],
        mass: &[f64],
        t: f64,
        dt: f64,
        fc: &mut [V3],
        kc: &mut [f64],
        release: &mut Vec<(u32, u8)>,
        deleted: &[(u8, u32)],
        bodies: &[RigidBodyState],
    ) -> Option<ContactStep> {
        if self.is_empty() {
            return None;
        }
        self.removed_now.clear();
        let t0 = std::time::Instant::now();
        for &c in &self.held {
            let l = self.local[c as usize] as usize;
            self.cx[c as usize] = x[l];
            self.cv[c as usize] = v[l];
        }
        // Sort decision: largest motion since the last sort against half the smallest margin.
        // The same reduction tells whether any rank deleted an element this
        // cycle (Idel): only then are the deleted ids gathered; and it
        // bounds the displacements since the sort (`relative_motion`).
        let mut motion = [f64::NEG_INFINITY; 8];
        motion[0] = 0.0;
        motion[1] = deleted.len() as f64;
        for &c in &self.held {
            if self.owned[c as usize] {
                let d = geo::sub(self.cx[c as usize], self.x_sort[c as usize]);
                motion[0] = motion[0].max(geo::norm(d));
                for k in 0..3 {
                    motion[2 + k] = motion[2 + k].max(d[k]);
                    motion[5 + k] = motion[5 + k].max(-d[k]);
                }
            }
        }
        world.max_f64(&mut motion);
        // A face woken by a deletion needs a sort to become a candidate.
        let mut woke = false;
        if self.tracks_deletion() && motion[1] > 0.0 {
            let mine: Vec<u64> = deleted
                .iter()
                .map(|&(k, e)| (k as u64) << 32 | e as u64)
                .collect();
            let mut all: Vec<(u8, u32)> = world
                .allgather_u64(&mine)
                .into_iter()
                .map(|c| ((c >> 32) as u8, c as u32))
                .collect();
            all.sort_unstable();
            all.dedup();
            woke = self.apply_deletions(&all);
        }
        let margin = self
            .setup
            .interfaces
            .iter()
            .map(|i| i.margin)
            .fold(f64::INFINITY, f64::min);
        let sort = !self.sorted_once || self.always_sort || woke || 2.0 * motion[0] >= margin;
        if sort {
            self.rebuild_plan(world);
        }
        self.motion = if sort { 0.0 } else { relative_motion(&motion) };
        self.plan.exchange(world, &mut self.cx, &mut self.cv);
        self.timers.exchange_s += t0.elapsed().as_secs_f64();
        if sort {
            let ts = std::time::Instant::now();
            self.search();
            let first = !self.sorted_once;
            self.sorted_once = true;
            self.timers.sorts += 1;
            if first {
                self.initial_penetrations();
            }
            self.timers.search_s += ts.elapsed().as_secs_f64();
        }
        let tf = std::time::Instant::now();
        let (contribs, step) = self.pairs(world, mass, t, dt, bodies);
        self.timers.force_s += tf.elapsed().as_secs_f64();
        let te = std::time::Instant::now();
        let got = exchange::route(world, &self.setup, &self.plan.route, contribs);
        self.timers.exchange_s += te.elapsed().as_secs_f64();
        // Sum in key order (route sorted them).
        let mut nodal_k: Vec<(u32, f64)> = Vec::new();
        for c in &got {
            let l = self.local[c.c as usize];
            if l == NONE {
                continue;
            }
            let l = l as usize;
            for k in 0..3 {
                fc[l][k] += c.f[k];
            }
            kc[l] += c.k;
            if c.ibc != 0 {
                release.push((l as u32, c.ibc));
            }
            if nodal_k.last().map(|e| e.0) != Some(c.c) {
                nodal_k.push((c.c, 0.0));
            }
            nodal_k.last_mut().unwrap().1 += c.k;
        }
        // Nodal step (EQ. 8.8.5.2) on owned nodes: the largest K/(2M).
        let mut best = ContactStep {
            nodal_q: 0.0,
            node_id: 0,
            kin_dt: f64::INFINITY,
            inter_id: 0,
        };
        if let Some((d, id)) = step {
            best.kin_dt = d;
            best.inter_id = id;
        }
        for (c, k) in nodal_k {
            if !self.owned[c as usize] || k <= 0.0 {
                continue;
            }
            let l = self.local[c as usize] as usize;
            if mass[l] <= 0.0 {
                continue;
            }
            let q = k / (2.0 * mass[l]);
            let id = self.node_ids[c as usize];
            if q > best.nodal_q || (q == best.nodal_q && id < best.node_id) {
                best.nodal_q = q;
                best.node_id = id;
            }
        }
        Some(best)
    }

    /// Idel: elements deleted this cycle (every rank's, sorted) remove the
    /// main segments of their interfaces (Idel ±2: any associated element
    /// deleted; ±1: all of them) and, with Idel = 1, 2, the secondary nodes
    /// none of whose elements is alive. The pairs of removed segments and
    /// nodes leave the candidate lists now, with their memory (friction,
    /// tie); the next sorts never find them again.
    fn apply_deletions(&mut self, dead: &[(u8, u32)]) -> bool {
        let mut woke = false;
        let mut touched: Vec<(usize, usize)> = Vec::new();
        let mut counts = vec![(0u64, 0u64); self.setup.interfaces.len()];
        for e in dead {
            if !self.dead.insert(*e) {
                continue;
            }
            let Some(list) = self.idel_index.get(e) else {
                continue;
            };
            for &(ii, pi, idx, what) in list {
                let (ii, pi, idx) = (ii as usize, pi as usize, idx as usize);
                let rule = setup::IdelRule::of(self.setup.interfaces[ii].idel);
                let r = &mut self.runs[ii][pi].removal;
                // A secondary node leaves when none of its elements lives;
                // a secondary edge as a main entity does (Idel 1: all, 2: any).
                let edge = self.setup.interfaces[ii].passes[pi].is_edge_pass();
                match (what, rule) {
                    (OnDeletion::Wake, _) => {
                        // Its owner still lives (or Idel keeps faces of the dead).
                        let owner_lives = r.seg_alive.get(idx).is_none_or(|&a| a > 0);
                        if r.seg_off[idx] && owner_lives {
                            r.seg_off[idx] = false;
                            woke = true;
                        }
                    }
                    (OnDeletion::Node, Some(rule)) => {
                        r.sec_alive[idx] -= 1;
                        let gone = r.sec_alive[idx] == 0 || (edge && !rule.all);
                        if gone && !r.sec_off[idx] {
                            r.sec_off[idx] = true;
                            counts[ii].1 += 1;
                            touched.push((ii, pi));
                        }
                    }
                    (OnDeletion::Segment, Some(rule)) => {
                        r.seg_alive[idx] -= 1;
                        if (!rule.all || r.seg_alive[idx] == 0) && !r.seg_off[idx] {
                            r.seg_off[idx] = true;
                            counts[ii].0 += 1;
                            touched.push((ii, pi));
                        }
                    }
                    (_, None) => unreachable!("indexed only with Idel"),
                }
            }
        }
        touched.sort_unstable();
        touched.dedup();
        for (ii, pi) in touched {
            let run = &mut self.runs[ii][pi];
            // Sorted candidates: drop the removed pairs and their memory.
            if run.cand.ptr.len() == run.mine.len() + 1 {
                let mut cand = Candidates {
                    ptr: vec![0],
                    segs: Vec::with_capacity(run.cand.segs.len()),
                };
                let mut state = Vec::with_capacity(run.state.len());
                let mut dist = Vec::with_capacity(run.dist_sort.len());
                for j in 0..run.mine.len() {
                    let node_off = run.sec_off(run.mine[j]);
                    for q in run.cand.ptr[j]..run.cand.ptr[j + 1] {
                        let m = run.cand.segs[q];
                        if node_off || run.seg_off(m) {
                            continue;
                        }
                        cand.segs.push(m);
                        if let Some(st) = run.state.get(q) {
                            state.push(*st);
                        }
                        if let Some(&d) = run.dist_sort.get(q) {
                            dist.push(d);
                        }
                    }
                    cand.ptr.push(cand.segs.len());
                }
                run.cand = cand;
                if !run.state.is_empty() {
                    run.state = state;
                }
                run.dist_sort = dist;
            }
            // Walk types: a node whose segment left starts a fresh pair.
            for wp in run.walk_pair.iter_mut() {
                if wp.0 != NONE && run.removal.seg_off[wp.0 as usize] {
                    *wp = (NONE, PairState::default());
                }
            }
        }
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            let (s, n) = counts[ii];
            if s == 0 && n == 0 {
                continue;
            }
            let tot = &mut self.removed_total[ii];
            tot.0 += s;
            tot.1 += n;
            self.removed_now.push(Removed {
                inter_id: it.id,
                type_number: it.type_number,
                idel: it.idel,
                segments: s,
                nodes: n,
                edges: it.passes.iter().any(|p| p.is_edge_pass()),
                segments_total: tot.0,
                nodes_total: tot.1,
            });
        }
        woke
    }

    /// New ghost plan from the current positions (collective).
    fn rebuild_plan(&mut self, world: &World) {
        let boxes: Vec<Aabb> = self
            .setup
            .interfaces
            .iter()
            .zip(&self.runs)
            .map(|(it, runs)| {
                let mut b = Aabb::EMPTY;
                let mut diag = 0.0f64;
                for (p, r) in it.passes.iter().zip(runs) {
                    diag = diag.max(p.max_diag);
                    for &k in &r.mine {
                        for &c in p.sec_side(k as usize).nodes() {
                            b.include(self.cx[c as usize]);
                        }
                    }
                }
                if b.is_empty() {
                    return b;
                }
                let walk = it.ty().walk_reach(diag);
                b.grown(it.max_gap + 2.0 * it.margin + diag + walk)
            })
            .collect();
        self.plan = GhostPlan::build(world, &boxes, &self.main_owned, &self.cx);
        self.avail.iter_mut().for_each(|a| *a = false);
        for &c in &self.held {
            self.avail[c as usize] = true;
        }
        for ids in &self.plan.recv {
            for &c in ids {
                self.avail[c as usize] = true;
            }
        }
        self.plan.set_route(world, &self.setup, &self.avail);
        self.x_sort.clone_from(&self.cx);
    }

    fn seg_x(&self, seg: &[u32; 4]) -> Option<[V3; 4]> {
        seg_values(seg, &self.avail, &self.cx)
    }

    /// Broad phase for every pass of a sorting type: candidates within gap +
    /// margin, segments connected to the node excluded (and, with Irem_gap =
    /// 2, segments with a node initially closer than 2·Gap); pair memory kept
    /// for pairs that remain.
    fn search(&mut self) {
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            if it.ty().search() != CandidateSearch::Sort {
                continue;
            }
            for (pi, p) in it.passes.iter().enumerate() {
                let run = &self.runs[ii][pi];
                // Segments removed by Idel get an empty box: never candidates.
                let boxes: Vec<Aabb> = p
                    .segs
                    .iter()
                    .enumerate()
                    .map(|(m, s)| match self.seg_x(s) {
                        Some(x) if !run.seg_off(m as u32) => Aabb::of_points(&x),
                        _ => Aabb::EMPTY,
                    })
                    .collect();
                let cand = if p.is_edge_pass() {
                    self.edge_candidates(it, p, run, &boxes)
                } else if p.is_segment_pass() {
                    self.segment_candidates(it, p, run, &boxes)
                } else {
                    self.node_candidates(it, p, run, &boxes)
                };
                // Keep the memory of pairs that survive.
                let old = &run.cand;
                let mut state = Vec::with_capacity(cand.segs.len());
                for j in 0..run.mine.len() {
                    let olds = if old.ptr.len() > j + 1 {
                        &old.segs[old.ptr[j]..old.ptr[j + 1]]
                    } else {
                        &[][..]
                    };
                    for &m in &cand.segs[cand.ptr[j]..cand.ptr[j + 1]] {
                        let st = match olds.binary_search(&m) {
                            Ok(q) => run.state[old.ptr[j] + q],
                            Err(_) => PairState::default(),
                        };
                        state.push(st);
                    }
                }
                let dist_sort = if p.is_edge_pass() || p.is_segment_pass() {
                    Vec::new()
                } else {
                    self.sort_distances(p, run, &cand)
                };
                let run = &mut self.runs[ii][pi];
                run.cand = cand;
                run.state = state;
                run.dist_sort = dist_sort;
            }
        }
    }

    /// Each candidate's distance to its segment now (`pairs::sort_distance`;
    /// −∞ where a segment node is not on this rank or the pass has no
    /// segments), for the pairs' motion bound.
    fn sort_distances(&self, p: &setup::Pass, run: &PassRun, cand: &Candidates) -> Vec<f64> {
        if p.segs.is_empty() {
            return Vec::new();
        }
        (0..run.mine.len())
            .into_par_iter()
            .flat_map_iter(|j| {
                let xs = self.cx[p.sec[run.mine[j] as usize] as usize];
                cand.segs[cand.ptr[j]..cand.ptr[j + 1]]
                    .iter()
                    .map(move |&m| {
                        self.seg_x(&p.segs[m as usize])
                            .map_or(f64::NEG_INFINITY, |xm| {
                                pairs::sort_distance(xs, &xm, p.is_tri(m as usize))
                            })
                    })
            })
            .collect()
    }

    /// The candidates of a node pass: the main segments within gap +
    /// margin of each owned secondary node, less those it is on (and, with
    /// Irem_gap = 2, those with a node initially closer than 2·Gap).
    fn node_candidates(
        &self,
        it: &setup::Interface,
        p: &setup::Pass,
        run: &PassRun,
        boxes: &[Aabb],
    ) -> Candidates {
        let pts: Vec<V3> = run
            .mine
            .iter()
            .map(|&k| self.cx[p.sec[k as usize] as usize])
            .collect();
        let method = search::choose(boxes);
        let raw = search::candidates(&pts, it.max_gap + it.margin, boxes, method);
        // Exclusions.
        let mut cand = Candidates {
            ptr: vec![0],
            segs: Vec::with_capacity(raw.segs.len()),
        };
        for (j, &k) in run.mine.iter().enumerate() {
            let s = p.sec[k as usize];
            if run.sec_off(k) {
                // Removed by Idel: no candidates.
                cand.ptr.push(cand.segs.len());
                continue;
            }
            for &m in &raw.segs[raw.ptr[j]..raw.ptr[j + 1]] {
                if !excluded(p, m, s) {
                    cand.segs.push(m);
                }
            }
            cand.ptr.push(cand.segs.len());
        }
        cand
    }

    /// The candidates of an edge pass: the main edges within gap + margin of
    /// each owned secondary edge (the distance between the edges' closest
    /// points, §8.4.5.2), less those that share a node with it; in
    /// self-contact one orientation of each pair (the one whose main edge's
    /// first node has the larger id, as the reference engine keeps).
    fn edge_candidates(
        &self,
        it: &setup::Interface,
        p: &setup::Pass,
        run: &PassRun,
        boxes: &[Aabb],
    ) -> Candidates {
        let reach = it.max_gap + it.margin;
        let ends = |k: u32| p.sec_edges[k as usize].map(|c| self.cx[c as usize]);
        // Midpoints within reach + half the longest edge hold every pair
        // within reach; the exact distance then decides, so the lists do
        // not depend on which rank holds the edge.
        let (mids, half_len) = self.entity_centres(p, run);
        let raw = search::candidates(&mids, reach + half_len, boxes, search::choose(boxes));
        filter_candidates(run, &raw, |k, m| {
            let se = p.sec_edges[k as usize];
            let me = &p.segs[m as usize];
            if me[..2].iter().any(|c| se.contains(c))
                || (p.self_contact && self.node_ids[me[0] as usize] < self.node_ids[se[0] as usize])
            {
                return false;
            }
            let [s1, s2] = ends(k);
            let (m1, m2) = (self.cx[me[0] as usize], self.cx[me[1] as usize]);
            edge_geometry::closest_points_of_edges(s1, s2, m1, m2).dist <= reach
        })
    }

    /// The box centre of each owned secondary entity (an edge's midpoint)
    /// of an entity pass, and the largest half box diagonal (half the
    /// longest edge): the search's query points and their extra reach.
    fn entity_centres(&self, p: &setup::Pass, run: &PassRun) -> (Vec<V3>, f64) {
        let mut half = 0.0f64;
        let centres = run
            .mine
            .iter()
            .map(|&k| {
                let mut b = Aabb::EMPTY;
                for &c in p.sec_side(k as usize).nodes() {
                    b.include(self.cx[c as usize]);
                }
                half = half.max(0.5 * b.diagonal());
                b.centre()
            })
            .collect();
        (centres, half)
    }

    /// The candidates of a segment pass: the main segments whose box comes
    /// within gap + margin of each owned secondary segment's box, less
    /// those that share a node with it; in self-contact (both sides the same
    /// segments) one orientation of each pair, main index above secondary.
    fn segment_candidates(
        &self,
        it: &setup::Interface,
        p: &setup::Pass,
        run: &PassRun,
        boxes: &[Aabb],
    ) -> Candidates {
        let reach = it.max_gap + it.margin;
        let sec_box =
            |k: u32| Aabb::of_points(&p.sec_segs[k as usize].map(|c| self.cx[c as usize]));
        let (centres, half_diag) = self.entity_centres(p, run);
        // Centres within reach + half the largest diagonal hold every pair
        // whose boxes come within reach; the boxes then decide, so the
        // lists do not depend on which rank holds the segment.
        let raw = search::candidates(&centres, reach + half_diag, boxes, search::choose(boxes));
        filter_candidates(run, &raw, |k, m| {
            let ss = &p.sec_segs[k as usize];
            let ms = &p.segs[m as usize];
            !ms.iter().any(|c| ss.contains(c))
                && !(p.self_contact && m <= k)
                && sec_box(k).grown(reach).overlaps(&boxes[m as usize])
        })
    }

    /// Inacti / Fpenmax at the first sort: decide for every pair found inside its gap.
    fn initial_penetrations(&mut self) {
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (pi, p) in it.passes.iter().enumerate() {
                if p.is_edge_pass() {
                    edge_initial_penetrations(it, p, &mut self.runs[ii][pi], &self.cx);
                    continue;
                }
                if p.is_segment_pass() {
                    // Segment pairs keep their initial penetration as a
                    // baseline in the pair memory: nothing to decide here.
                    continue;
                }
                let run = &mut self.runs[ii][pi];
                for j in 0..run.mine.len() {
                    let k = run.mine[j] as usize;
                    let s = p.sec[k];
                    let xs = self.cx[s as usize];
                    let segs: Vec<u32> = match it.ty().search() {
                        CandidateSearch::Sort => {
                            run.cand.segs[run.cand.ptr[j]..run.cand.ptr[j + 1]].to_vec()
                        }
                        CandidateSearch::Analytic => vec![],
                        CandidateSearch::Walk => {
                            let m = run.nodes[j].last_seg;
                            if m == NONE {
                                vec![]
                            } else {
                                vec![m]
                            }
                        }
                    };
                    for m in segs {
                        let seg = &p.segs[m as usize];
                        let Some(xm) = seg_values(seg, &self.avail, &self.cx) else {
                            continue;
                        };
                        let tri = p.is_tri(m as usize);
                        let g = it.pair_gap(p, k, m as usize);
                        let (decision, p0) = it.ty().initial_penetration(it, xs, &xm, tri, g);
                        match decision {
                            gap::InitialPenetration::DeactivateNode => run.nodes[j].off = true,
                            gap::InitialPenetration::DeactivateSegment => {
                                run.nodes[j].off_segs.push(m)
                            }
                            gap::InitialPenetration::ReduceGap => {
                                let g0 = gap::initial_gap(it.inacti, g, p0);
                                run.nodes[j].gap0.push((m, g0, (g - p0) - g0))
                            }
                            _ => {}
                        }
                    }
                    run.nodes[j].off_segs.sort_unstable();
                    run.nodes[j].gap0.sort_by_key(|e| e.0);
                }
            }
        }
    }
}

/// The raw candidates of each owned secondary entity (`raw`, in the order
/// of `run.mine`) that `keep(entity, main entity)` accepts; none for an
/// entity removed by Idel.
fn filter_candidates(
    run: &PassRun,
    raw: &Candidates,
    keep: impl Fn(u32, u32) -> bool,
) -> Candidates {
    let mut cand = Candidates {
        ptr: vec![0],
        segs: Vec::with_capacity(raw.segs.len()),
    };
    for (j, &k) in run.mine.iter().enumerate() {
        if !run.sec_off(k) {
            let mine = &raw.segs[raw.ptr[j]..raw.ptr[j + 1]];
            cand.segs
                .extend(mine.iter().copied().filter(|&m| keep(k, m)));
        }
        cand.ptr.push(cand.segs.len());
    }
    cand
}

/// The sort's exclusions of secondary cnode `s` against segment `m` of
/// pass `p`: the node is one of the segment's, or (Irem_gap = 2) on the
/// segment's list of close neighbours (`close_neighbours`).
pub(crate) fn excluded(p: &setup::Pass, m: u32, s: u32) -> bool {
    p.segs[m as usize].contains(&s) || p.removes(m as usize, s)
}

/// Inacti on an edge pass at the first sort (/INTER/TYPE11 Inacti): a pair
/// of edges found inside its gap deactivates its secondary edge (1) or,
/// for that edge, the main edge (2). Its type refuses the other values.
fn edge_initial_penetrations(it: &setup::Interface, p: &setup::Pass, run: &mut PassRun, cx: &[V3]) {
    for j in 0..run.mine.len() {
        let k = run.mine[j] as usize;
        let [s1, s2] = p.sec_edges[k].map(|c| cx[c as usize]);
        for q in run.cand.ptr[j]..run.cand.ptr[j + 1] {
            let m = run.cand.segs[q];
            let seg = &p.segs[m as usize];
            let (m1, m2) = (cx[seg[0] as usize], cx[seg[1] as usize]);
            let g = it.pair_gap(p, k, m as usize);
            let p0 = g - edge_geometry::closest_points_of_edges(s1, s2, m1, m2).dist;
            match gap::initial_penetration(it.inacti, 0.0, p0, g) {
                gap::InitialPenetration::DeactivateNode => run.nodes[j].off = true,
                gap::InitialPenetration::DeactivateSegment => run.nodes[j].off_segs.push(m),
                _ => {}
            }
        }
        run.nodes[j].off_segs.sort_unstable();
    }
}

/// How far any contact node has moved since the last sort, apart from a
/// common translation T (a distance between nodes and segments does not
/// see T): the smaller of the largest displacement (`m[0]`, T = 0) and
/// half the diagonal of the displacements' box (T its centre; `m[2..5]`
/// the largest components, `m[5..8]` the largest negated ones).
fn relative_motion(m: &[f64; 8]) -> f64 {
    let diag2: f64 = (0..3).map(|k| (m[2 + k] + m[5 + k]).powi(2)).sum();
    let half = 0.5 * diag2.sqrt();
    if half.is_finite() {
        m[0].min(half)
    } else {
        m[0]
    }
}

/// A segment's nodal values (positions or velocities), or `None` when one of
/// its nodes is neither held nor received as a ghost on this rank.
fn seg_values(seg: &[u32; 4], avail: &[bool], a: &[V3]) -> Option<[V3; 4]> {
    if seg.iter().all(|&c| avail[c as usize]) {
        Some(seg.map(|c| a[c as usize]))
    } else {
        None
    }
}
