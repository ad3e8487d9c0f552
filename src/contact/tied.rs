//! /INTER/TYPE2 tied interfaces: the set-up built once on rank 0 (which main
//! segment holds each secondary node, where, and with which offset) and the
//! per-rank runtime that applies the kinematic condition of
//! `interfaces::type2` every cycle across ranks.
//!
//! Parallel design (ARCHITECTURE "Contact across ranks", "Determinism"):
//! - the owner of a secondary node spreads its force and moment over the main
//!   nodes; each share goes to every rank holding that main node, keyed by
//!   (interface, secondary node global id, corner) (`key::SumKey`, pass and
//!   main entity 0), and each rank sums a main
//!   node's shares in key order, so the sum has the same bits on every rank
//!   and for any number of ranks;
//! - after the velocity update, the owners of main nodes send their velocities
//!   (and rotational velocities) to the ranks that hold a secondary node tied
//!   to them but not the main node (a static plan: ties never change), and
//!   every holder of a secondary node recovers its velocity in corner order;
//!   the same message carries the main nodes' positions after the step
//!   (x + Δt v, the bits the owner computes), which the next cycle's force
//!   transfer and the placing of the secondary nodes use;
//! - the offsets d⃗ (turned with their segment every cycle) are state that
//!   every holder of the secondary node updates from the same data.

use super::geometry::{self as geo, V3};
use super::interfaces::type2;
use super::key::SumKey;
use super::setup::NONE;
use crate::domain::Subdomain;
use crate::model::tie_projection::{nearest_segment, search_distance};
use crate::model::InterfaceKind;
use crate::model::Model;
use crate::parallel::World;
use serde::{Deserialize, Serialize};

/// One secondary node on its main segment.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tie {
    /// Secondary node (tnode).
    pub sec: u32,
    /// Main segment (tnodes; a triangle repeats its third node, shape[3] = 0).
    pub seg: [u32; 4],
    /// Shape functions Φ_i of the projection p (§8.4.5.1 four-triangle split).
    pub shape: [f64; 4],
    /// d⃗ = x_s − Σ Φ_i x_i at t = 0 (global frame; turned with the segment at run time).
    pub offset: V3,
    /// Rotations transmitted through the main nodes' rotational DOFs (shells);
    /// false: main nodes without rotations (bricks), the segment's rigid spin
    /// is used (`type2::Turn::Spin`).
    pub rot: bool,
    /// Rotations transmitted (Spotflag 5); false: translations only
    /// (Spotflag 4, `type2::Turn::Fixed`).
    pub turns: bool,
    /// Secondary node's own mass and rotational inertia (transferred once).
    pub ms: f64,
    pub is: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct TiedInterface {
    pub id: u64,
    pub title: String,
    pub ties: Vec<Tie>,
    /// Secondary nodes without a segment within dsearch, kept free (Ignore = 1000) or removed.
    pub untied: Vec<u64>,
    pub removed: bool,
    pub dsearch: f64,
}

/// All TYPE2 interfaces and the table of the nodes they touch ("tnodes").
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct TiedSetup {
    pub interfaces: Vec<TiedInterface>,
    /// Global node index of each tnode, ascending.
    pub nodes: Vec<u32>,
    /// Ranks holding each tnode (CSR), ascending: the first one owns it.
    pub holders_ptr: Vec<u32>,
    pub holders: Vec<u32>,
}

impl TiedSetup {
    pub fn is_empty(&self) -> bool {
        self.interfaces.is_empty()
    }
    pub fn holders_of(&self, t: u32) -> &[u32] {
        &self.holders
            [self.holders_ptr[t as usize] as usize..self.holders_ptr[t as usize + 1] as usize]
    }
    /// Listing lines for the set-up (one per interface, plus the untied nodes).
    pub fn notes(&self) -> Vec<String> {
        let mut out = Vec::new();
        for it in &self.interfaces {
            let rot = it.ties.iter().filter(|t| t.rot).count();
            out.push(format!(
                "/INTER/TYPE2/{}: {} secondary nodes tied (Spotflag 5, standard kinematic formulation), {} with rotations, {} on segments without rotational DOFs (moments as force couples, rotation = the segment's spin); dsearch {:e}",
                it.id,
                it.ties.len(),
                rot,
                it.ties.len() - rot,
                it.dsearch
            ));
            if !it.untied.is_empty() {
                let list: Vec<String> = it.untied.iter().take(20).map(|i| i.to_string()).collect();
                out.push(format!(
                    "WARNING /INTER/TYPE2/{}: {} secondary nodes have no main segment within dsearch and are {}: {}{}",
                    it.id,
                    it.untied.len(),
                    if it.removed { "removed from the interface (Ignore)" } else { "left free (Ignore = 1000)" },
                    list.join(" "),
                    if it.untied.len() > 20 { " ..." } else { "" }
                ));
            }
        }
        out
    }
}

/// The first card that holds each node, by card name.
type Holder = std::collections::HashMap<u32, String>;

fn mark<'a>(map: &mut Holder, nodes: impl IntoIterator<Item = &'a u32>, card: String) {
    for &n in nodes {
        map.entry(n).or_insert_with(|| card.clone());
    }
}

/// Every node constrained by some other condition, for the conflict checks:
/// (boundary conditions and imposed motions, rigid bodies and walls).
fn constrained_nodes(m: &Model) -> (Holder, Holder) {
    let mut bc_of: Holder = Default::default();
    for c in &m.bcs {
        if c.card.fixed.iter().any(|&f| f) {
            mark(
                &mut bc_of,
                &c.nodes,
                format!("{}: /BCS/{}", c.card.loc, c.card.id),
            );
        }
    }
    for c in &m.imposed_velocities {
        mark(
            &mut bc_of,
            &c.nodes,
            format!("{}: /IMPVEL/{}", c.card.loc, c.card.id),
        );
    }
    for c in &m.imposed_displacements {
        mark(
            &mut bc_of,
            &c.nodes,
            format!("{}: /IMPDISP/{}", c.card.loc, c.card.id),
        );
    }
    let mut rb_of: Holder = Default::default();
    for r in &m.rigid_bodies {
        let nodes = r
            .secondary_nodes
            .iter()
            .chain(std::iter::once(&r.main_node));
        mark(
            &mut rb_of,
            nodes,
            format!("{}: /RBODY/{}", r.card.loc, r.card.id),
        );
    }
    for w in &m.rigid_walls {
        mark(
            &mut rb_of,
            &w.secondary_nodes,
            format!("{}: /RWALL/{}", w.card.loc, w.card.id),
        );
    }
    (bc_of, rb_of)
}

/// One TYPE2 interface before the tnode numbering: (id, title, ties as
/// (secondary node, segment, shape, offset, (rotations, turns)), untied node ids,
/// untied nodes removed, dsearch).
type RawTied = (
    u64,
    String,
    Vec<(u32, [u32; 4], [f64; 4], V3, (bool, bool))>,
    Vec<u64>,
    bool,
    f64,
);

/// Main nodes that are themselves tied (chains) or on a rigid body: refused.
fn check_main_nodes(
    raw: &[RawTied],
    kws: &[String],
    tied_by: &std::collections::HashMap<u32, u64>,
    rb_of: &Holder,
    nid: &dyn Fn(u32) -> u64,
) -> Result<(), String> {
    for ((_, _, ties, _, _, _), kw) in raw.iter().zip(kws) {
        for (_, seg, _, _, _) in ties {
            for &q in seg {
                if let Some(other) = tied_by.get(&q) {
                    return Err(format!(
                        "{kw}, field surf_IDm: main node {} is itself a secondary node of /INTER/TYPE2/{other}: tied-interface hierarchies (Level) are not supported by the engine yet",
                        nid(q)
                    ));
                }
                if let Some(what) = rb_of.get(&q) {
                    return Err(format!(
                        "{kw}, field surf_IDm: main node {} is also constrained by {what}: a tie onto a rigid body or wall is not supported by the engine yet",
                        nid(q)
                    ));
                }
            }
        }
    }
    Ok(())
}

/// Builds the TYPE2 set-up on rank 0; `holders[g]` lists the ranks holding global node g.
pub fn build(m: &Model, holders: &[Vec<u32>]) -> Result<TiedSetup, String> {
    let mut raw: Vec<RawTied> = Vec::new();
    let (bc_of, rb_of) = constrained_nodes(m);
    // Secondary nodes over all TYPE2 (tied twice) and main nodes (chains).
    let mut tied_by: std::collections::HashMap<u32, u64> = Default::default();
    let mut kws: Vec<String> = Vec::new();
    let nid = |n: u32| m.nodes.ids[n as usize];
    for i in &m.interfaces {
        let InterfaceKind::Type2(t) = &i.card.kind else {
            continue;
        };
        let c = &i.card;
        let kw = format!("{}: /INTER/TYPE2/{}", c.loc, c.id);
        if i.main_segments.is_empty() {
            return Err(format!(
                "{kw}, field surf_IDm: the main surface has no segment"
            ));
        }
        let dsearch = search_distance(t, &i.main_segments, &m.nodes.x);
        let mut main_nodes: Vec<u32> = i.main_segments.iter().flatten().copied().collect();
        main_nodes.sort_unstable();
        main_nodes.dedup();
        let mut ties = Vec::new();
        let mut untied = Vec::new();
        for &s in &i.secondary_nodes {
            if main_nodes.binary_search(&s).is_ok() {
                return Err(format!(
                    "{kw}, field grnd_IDs: node {} is both a secondary node and a node of the main surface surf_IDm {}: a node cannot be tied to itself",
                    nid(s), t.surf_idm
                ));
            }
            if let Some(other) = tied_by.insert(s, c.id) {
                return Err(format!(
                    "{kw}, field grnd_IDs: node {} is already a secondary node of /INTER/TYPE2/{other}: a node can be tied once",
                    nid(s)
                ));
            }
            if let Some(what) = bc_of.get(&s) {
                return Err(format!(
                    "{kw}, field grnd_IDs: secondary node {} also has a kinematic condition ({what}): incompatible with the tie (its motion is the main segment's)",
                    nid(s)
                ));
            }
            if let Some(what) = rb_of.get(&s) {
                return Err(format!(
                    "{kw}, field grnd_IDs: secondary node {} is also constrained by {what}: incompatible kinematic conditions",
                    nid(s)
                ));
            }
            let xs = m.nodes.x[s as usize];
            let (dist, k, pr) = nearest_segment(xs, &i.main_segments, &m.nodes.x);
            if dist > dsearch {
                untied.push(nid(s));
                continue;
            }
            let seg = i.main_segments[k];
            let rot = seg.iter().all(|&q| m.nodal_inertia[q as usize] > 0.0);
            let p = geo::interpolate(&pr.shape, &seg.map(|q| m.nodes.x[q as usize]));
            ties.push((s, seg, pr.shape, geo::sub(xs, p), (rot, t.spotflag != 4)));
        }
        let removed = matches!(t.ignore, 1..=3);
        raw.push((c.id, c.title.clone(), ties, untied, removed, dsearch));
        kws.push(kw);
    }
    check_main_nodes(&raw, &kws, &tied_by, &rb_of, &nid)?;
    let mut all: Vec<u32> = raw
        .iter()
        .flat_map(|r| r.2.iter().flat_map(|t| std::iter::once(t.0).chain(t.1)))
        .collect();
    all.sort_unstable();
    all.dedup();
    let tn = |g: u32| all.binary_search(&g).expect("tnode") as u32;
    let interfaces = raw
        .into_iter()
        .map(
            |(id, title, ties, untied, removed, dsearch)| TiedInterface {
                id,
                title,
                ties: ties
                    .into_iter()
                    .map(|(s, seg, shape, offset, (rot, turns))| Tie {
                        sec: tn(s),
                        seg: seg.map(tn),
                        shape,
                        offset,
                        rot,
                        turns,
                        ms: m.nodal_mass[s as usize],
                        is: m.nodal_inertia[s as usize],
                    })
                    .collect(),
                untied,
                removed,
                dsearch,
            },
        )
        .collect();
    let mut holders_ptr = vec![0u32];
    let mut hs = Vec::new();
    for &g in &all {
        hs.extend_from_slice(&holders[g as usize]);
        holders_ptr.push(hs.len() as u32);
    }
    Ok(TiedSetup {
        interfaces,
        nodes: all,
        holders_ptr,
        holders: hs,
    })
}

/// Per-interface sums for the listing (this rank's owned secondary nodes).
#[derive(Clone, Copy, Debug, Default)]
pub struct TiedSums {
    pub tied: u64,
    /// Resultant force and moment the secondary nodes passed to the main nodes.
    pub force: V3,
    pub moment: V3,
}

/// One rank's runtime of the TYPE2 interfaces.
#[derive(Clone)]
pub struct TiedSystem {
    pub setup: TiedSetup,
    /// Local index of each tnode (NONE: not on this rank).
    pub(super) local: Vec<u32>,
    pub(super) owned: Vec<bool>,
    /// Velocity plan: ranks, tnodes sent to each (owned here), tnodes received.
    ranks: Vec<u32>,
    send: Vec<Vec<u32>>,
    pub(super) recv: Vec<Vec<u32>>,
    /// Main-node velocity and rotational velocity per tnode (held or received).
    tv: Vec<V3>,
    tw: Vec<V3>,
    /// Positions of the received (ghost) tnodes at the current cycle's start
    /// (local tnodes are read from x).
    pub(super) tx: Vec<V3>,
    /// Per owned tnode, the position the ranks receiving it as a ghost
    /// hold for it (x + Δt v at the last `recover`): the restart file's.
    pub(super) x_ghost: Vec<V3>,
    /// Offsets d⃗ of the ties (per interface, per tie) at the cycle's start,
    /// and after the step's rotation (`recover` → `place`).
    pub(super) d: Vec<Vec<V3>>,
    pub(super) d_next: Vec<Vec<V3>>,
    /// The ghost positions have been received once.
    pub(super) started: bool,
    pub sums: Vec<TiedSums>,
}

impl TiedSystem {
    pub fn new(setup: TiedSetup, sd: &Subdomain) -> TiedSystem {
        let nt = setup.nodes.len();
        let mut local = vec![NONE; nt];
        let mut owned = vec![false; nt];
        for (t, &g) in setup.nodes.iter().enumerate() {
            if let Ok(l) = sd.node_global.binary_search(&g) {
                local[t] = l as u32;
                owned[t] = sd.owns(l as u32);
            }
        }
        // Static plan, the same on every rank from the global tables: the owner
        // of main node q sends it to each holder of a secondary node tied to q
        // that does not hold q.
        let me = sd.rank;
        let mut send: std::collections::BTreeMap<u32, Vec<u32>> = Default::default();
        let mut recv: std::collections::BTreeMap<u32, Vec<u32>> = Default::default();
        for it in &setup.interfaces {
            for tie in &it.ties {
                for &r in setup.holders_of(tie.sec) {
                    for &q in &tie.seg {
                        let hq = setup.holders_of(q);
                        if hq.contains(&r) {
                            continue;
                        }
                        let owner = hq[0];
                        if owner == me {
                            send.entry(r).or_default().push(q);
                        }
                        if r == me {
                            recv.entry(owner).or_default().push(q);
                        }
                    }
                }
            }
        }
        let mut ranks: Vec<u32> = send.keys().chain(recv.keys()).copied().collect();
        ranks.sort_unstable();
        ranks.dedup();
        let norm = |m: &mut std::collections::BTreeMap<u32, Vec<u32>>, r: u32| {
            let mut v = m.remove(&r).unwrap_or_default();
            v.sort_unstable();
            v.dedup();
            v
        };
        let sendv = ranks.iter().map(|&r| norm(&mut send, r)).collect();
        let recvv = ranks.iter().map(|&r| norm(&mut recv, r)).collect();
        let sums = vec![TiedSums::default(); setup.interfaces.len()];
        let d: Vec<Vec<V3>> = setup
            .interfaces
            .iter()
            .map(|it| it.ties.iter().map(|t| t.offset).collect())
            .collect();
        TiedSystem {
            local,
            owned,
            ranks,
            send: sendv,
            recv: recvv,
            tv: vec![[0.0; 3]; nt],
            tw: vec![[0.0; 3]; nt],
            tx: vec![[0.0; 3]; nt],
            x_ghost: vec![[0.0; 3]; nt],
            d_next: d.clone(),
            d,
            started: false,
            sums,
            setup,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.setup.is_empty()
    }

    /// Local secondary nodes: (translation tied, rotation tied) per local node.
    /// A secondary node's rotation follows its segment (the main nodes'
    /// rotations, or the segment's spin where they have none) unless the tie
    /// passes translations only (Spotflag 4).
    pub fn masks(&self, n: usize) -> (Vec<bool>, Vec<bool>) {
        let mut tr = vec![false; n];
        let mut ro = vec![false; n];
        for it in &self.setup.interfaces {
            for tie in &it.ties {
                let l = self.local[tie.sec as usize];
                if l != NONE {
                    tr[l as usize] = true;
                    ro[l as usize] = tie.turns;
                }
            }
        }
        (tr, ro)
    }

    /// Adds the secondary nodes' masses and inertias to the local main nodes
    /// (manual eqs. (1)–(2)), in (interface, secondary node, corner) order.
    pub fn add_masses(&self, mass: &mut [f64], inertia: &mut [f64]) {
        for it in &self.setup.interfaces {
            for tie in &it.ties {
                let sh =
                    type2::mass_share(&tie.shape, tie.ms, tie.is, tie.offset, tie.rot && tie.turns);
                for (i, &q) in tie.seg.iter().enumerate() {
                    let l = self.local[q as usize];
                    if l == NONE || tie.shape[i] == 0.0 {
                        continue;
                    }
                    mass[l as usize] += sh[i].0;
                    inertia[l as usize] += sh[i].1;
                }
            }
        }
    }

    /// Position of tnode t: local from x, else the received one.
    fn pos(&self, t: u32, x: &[V3]) -> V3 {
        let l = self.local[t as usize];
        if l != NONE {
            x[l as usize]
        } else {
            self.tx[t as usize]
        }
    }

    /// How the tie's segment turns, from its corners' positions.
    fn turn(tie: &Tie, xm: &[V3; 4]) -> type2::Turn {
        if !tie.turns {
            type2::Turn::Fixed
        } else if tie.rot {
            type2::Turn::Nodal
        } else {
            type2::Turn::Spin(type2::SpinMap::new(xm, tie.seg[3] == tie.seg[2]))
        }
    }

    /// The secondary nodes' forces and moments `f` (6 components: the total
    /// force the node would integrate, external − internal + contact) spread
    /// over their main nodes: returns the shares per local node in `ftie`,
    /// summed in key order (collective). `x`: positions at the cycle's start.
    pub fn transfer(
        &mut self,
        world: &World,
        x: &[V3],
        f: &dyn Fn(usize) -> [f64; 6],
        ftie: &mut [[f64; 6]],
    ) {
        for v in ftie.iter_mut() {
            *v = [0.0; 6];
        }
        for s in self.sums.iter_mut() {
            *s = TiedSums::default();
        }
        // (tnode, key, share)
        let mut out: Vec<(u32, SumKey, [f64; 6])> = Vec::new();
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (j, tie) in it.ties.iter().enumerate() {
                let l = self.local[tie.sec as usize];
                if l == NONE || !self.owned[tie.sec as usize] {
                    continue;
                }
                let fs = f(l as usize);
                let force = [fs[0], fs[1], fs[2]];
                let moment = [fs[3], fs[4], fs[5]];
                let xm = tie.seg.map(|q| self.pos(q, x));
                let turn = Self::turn(tie, &xm);
                let sh = type2::spread(&tie.shape, force, moment, self.d[ii][j], &turn);
                let su = &mut self.sums[ii];
                su.tied += 1;
                for k in 0..3 {
                    su.force[k] += force[k];
                    su.moment[k] += moment[k];
                }
                let key = SumKey::pair(ii, 0, self.setup.nodes[tie.sec as usize], 0);
                for (i, &q) in tie.seg.iter().enumerate() {
                    if tie.shape[i] == 0.0 && sh[i] == [0.0; 6] {
                        continue;
                    }
                    out.push((q, key.at(i as u8), sh[i]));
                }
            }
        }
        let n = world.size() as usize;
        let mut got = if n == 1 {
            out
        } else {
            let mut send: Vec<Vec<u64>> = vec![Vec::new(); n];
            for c in &out {
                for &r in self.setup.holders_of(c.0) {
                    let b = &mut send[r as usize];
                    b.push(c.0 as u64);
                    b.extend_from_slice(&c.1.to_words());
                    b.extend(c.2.iter().map(|x| x.to_bits()));
                }
            }
            let recv = world.alltoallv_u64(&send);
            recv.iter()
                .flat_map(|b| {
                    b.chunks_exact(9).map(|c| {
                        let mut s = [0.0; 6];
                        for k in 0..6 {
                            s[k] = f64::from_bits(c[3 + k]);
                        }
                        (c[0] as u32, SumKey::from_words([c[1], c[2]]), s)
                    })
                })
                .collect()
        };
        got.sort_unstable_by_key(|a| (a.0, a.1));
        for (q, _, s) in got {
            let l = self.local[q as usize];
            if l == NONE {
                continue;
            }
            for k in 0..6 {
                ftie[l as usize][k] += s[k];
            }
        }
    }

    /// Secondary nodes' velocities and rotational velocities from their main
    /// nodes' (collective: ghost main-node velocities), and the offsets turned
    /// over the step `dt` the positions will then make (0 before the first
    /// cycle). `x`: positions at the cycle's start, not yet updated.
    pub fn recover(&mut self, world: &World, x: &[V3], v: &mut [V3], vr: &mut [V3], dt: f64) {
        for (t, &l) in self.local.iter().enumerate() {
            if l != NONE {
                self.tv[t] = v[l as usize];
                self.tw[t] = vr[l as usize];
                if self.owned[t] {
                    // What a ghost of this node receives below.
                    let mut xn = x[l as usize];
                    for k in 0..3 {
                        xn[k] += dt * v[l as usize][k];
                    }
                    self.x_ghost[t] = xn;
                }
            }
        }
        // Ghost positions after the step, x + Δt v (as the owner updates them).
        let mut next: Vec<(u32, V3)> = Vec::new();
        if !self.ranks.is_empty() {
            let send: Vec<Vec<f64>> = self
                .send
                .iter()
                .map(|ids| {
                    let mut b = Vec::with_capacity(9 * ids.len());
                    for &q in ids {
                        let l = self.local[q as usize] as usize;
                        b.extend_from_slice(&self.tv[q as usize]);
                        b.extend_from_slice(&self.tw[q as usize]);
                        let mut xn = x[l];
                        for k in 0..3 {
                            xn[k] += dt * v[l][k];
                        }
                        b.extend_from_slice(&xn);
                    }
                    b
                })
                .collect();
            let mut recv: Vec<Vec<f64>> = self
                .recv
                .iter()
                .map(|ids| vec![0.0; 9 * ids.len()])
                .collect();
            world.exchange_f64(&self.ranks, &send, &mut recv);
            for (ids, b) in self.recv.iter().zip(&recv) {
                for (j, &q) in ids.iter().enumerate() {
                    let c = &b[9 * j..9 * j + 9];
                    self.tv[q as usize] = [c[0], c[1], c[2]];
                    self.tw[q as usize] = [c[3], c[4], c[5]];
                    next.push((q, [c[6], c[7], c[8]]));
                }
            }
        }
        if !self.started {
            // Before the first cycle (dt = 0): the positions now.
            for &(q, xn) in &next {
                self.tx[q as usize] = xn;
            }
            self.started = true;
        }
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (j, tie) in it.ties.iter().enumerate() {
                let l = self.local[tie.sec as usize];
                if l == NONE {
                    continue;
                }
                let vm = tie.seg.map(|q| self.tv[q as usize]);
                let wm = tie.seg.map(|q| self.tw[q as usize]);
                let xm = tie.seg.map(|q| self.pos(q, x));
                let turn = Self::turn(tie, &xm);
                let d = self.d[ii][j];
                let (vs, ws) = type2::recover(&tie.shape, &vm, &wm, d, &turn);
                v[l as usize] = vs;
                if tie.turns && (tie.rot || tie.is > 0.0) {
                    vr[l as usize] = ws;
                }
                self.d_next[ii][j] = crate::vec3::rotate(d, ws, dt);
            }
        }
        for (q, xn) in next {
            self.tx[q as usize] = xn;
        }
    }

    /// After the position update: each secondary node placed at
    /// Σ Φ_i x_iⁿ⁺¹ + d⃗ⁿ⁺¹ (module doc of `interfaces::type2`).
    pub fn place(&mut self, x: &mut [V3]) {
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (j, tie) in it.ties.iter().enumerate() {
                self.d[ii][j] = self.d_next[ii][j];
                let l = self.local[tie.sec as usize];
                if l == NONE {
                    continue;
                }
                let xm = tie.seg.map(|q| self.pos(q, x));
                let p = geo::interpolate(&tie.shape, &xm);
                x[l as usize] = geo::add(p, self.d[ii][j]);
            }
        }
    }
}
