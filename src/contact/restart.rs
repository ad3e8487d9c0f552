//! What the contact and tied interfaces carry from one cycle to the next,
//! in a form that does not depend on the rank layout, for the restart file
//! (`output::restart` writes and reads it; this module only packs and
//! unpacks).
//!
//! Contact ([`ContactSystem`]):
//!
//! - replicated [`ContactScalars`]: the interfaces' shape (to refuse a file
//!   of another deck), whether the first sort happened, the sort count, the
//!   Idel removal tables and the deleted elements already seen, the removal
//!   totals, and the per-interface energy (summed over ranks);
//! - one record per owned secondary node of each pass, keyed by
//!   `interface << 40 | pass << 32 | global node`: its memory (`NodeState`:
//!   Inacti off / deactivated segments / corrected gaps, the walk's last
//!   segment), its candidate segments (global segment indices of the pass,
//!   ascending) with their pair memory (friction, ITIED ties, side), and the
//!   walk pair;
//! - the positions at the last sort of every contact node (rows by contact
//!   node index: the ascending global node list of the interfaces).
//!
//! The candidate lists are restored as they were, not searched again: the
//! run that never stopped sorts only when the motion since the last sort
//! passes the margin, and a search at another cycle could find other pairs.
//! The ghost plan is rebuilt for the new layout from the positions at the
//! last sort, which is the plan that layout would have built at that sort.
//!
//! Tied (TYPE2, [`TiedSystem`]): the offsets d⃗ of the ties (they turn with
//! the segment every cycle), keyed by `interface << 32 | secondary global
//! node`, and the positions a rank receiving a main node as a ghost holds
//! for it (rows by tied node index).

use super::exchange::GhostPlan;
use super::interfaces::PairState;
use super::key::SumKey;
use super::search::Candidates;
use super::tied::TiedSystem;
use super::{ContactSystem, NodeState, Removal, NONE};
use crate::parallel::World;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Layout of the contact sections; a file with another is refused.
pub const LAYOUT: u32 = 3;

/// Interfaces as the restart file describes them: (id, type, per pass
/// (secondary nodes, main segments)).
pub type Shape = Vec<(u64, u32, Vec<(u64, u64)>)>;

/// Contact state every rank holds alike.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ContactScalars {
    pub layout: u32,
    pub shape: Shape,
    /// Contact nodes (all interfaces).
    pub nodes: u64,
    pub sorted_once: bool,
    pub sorts: u64,
    removal: Vec<Vec<Removal>>,
    /// Deleted elements already applied (kind index, element index), ascending.
    dead: Vec<(u8, u32)>,
    removed_total: Vec<(u64, u64)>,
    /// Per-interface energy, summed over ranks.
    energy: Vec<f64>,
    /// The run's contact energy (solver::run), summed over ranks.
    pub e_contact: f64,
    /// Each interface's memory (total-force types', the segment-based
    /// contact's time step; layout 3), alike on every rank.
    total_memory: Vec<[f64; 2]>,
}

/// One owned secondary node's memory in one pass.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct SecRecord {
    node: NodeState,
    cand: Vec<u32>,
    state: Vec<PairState>,
    /// Walk types: the node's current pair (segment, memory).
    walk_pair: (u32, PairState),
}

/// This rank's share of the contact state.
pub struct ContactExport {
    pub scalars: ContactScalars,
    /// Keyed records of the owned secondary nodes.
    pub records: Vec<(u64, Vec<u8>)>,
    /// Owned contact nodes (contact node indices, ascending) and their
    /// positions at the last sort.
    pub sort_rows: Vec<u64>,
    pub x_sort: Vec<f64>,
}

/// A secondary entity's record key: the first word of its pairs' sum key,
/// `interface << 40 | pass << 32 | global node` (an edge: its index in the pass).
fn key(ii: usize, pi: usize, global: u32) -> u64 {
    SumKey::pair(ii, pi, global, 0).to_words()[0]
}

/// A tie's record key (restart file layout): `interface << 32 | global node`.
fn tie_key(ii: usize, global: u32) -> u64 {
    (ii as u64) << 32 | global as u64
}

impl ContactSystem {
    /// The interfaces' shape.
    pub fn shape(&self) -> Shape {
        self.setup
            .interfaces
            .iter()
            .map(|it| {
                (
                    it.id,
                    it.type_number,
                    it.passes
                        .iter()
                        .map(|p| (p.n_sec() as u64, p.segs.len() as u64))
                        .collect(),
                )
            })
            .collect()
    }

    /// Contact node indices this rank holds (ascending).
    pub fn held_rows(&self) -> Vec<u64> {
        self.held.iter().map(|&c| c as u64).collect()
    }

    /// Contact nodes in all interfaces.
    pub fn node_count(&self) -> usize {
        self.setup.nodes.len()
    }

    /// This rank's state (collective: the energies are summed).
    pub fn export(&self, world: &World, e_contact: f64) -> Result<ContactExport, String> {
        let mut sums: Vec<f64> = self.sums.iter().map(|s| s.energy).collect();
        sums.push(e_contact);
        world.sum_f64(&mut sums);
        let e_contact = sums.pop().unwrap_or(0.0);
        let mut dead: Vec<(u8, u32)> = self.dead.iter().copied().collect();
        dead.sort_unstable();
        let scalars = ContactScalars {
            layout: LAYOUT,
            shape: self.shape(),
            nodes: self.setup.nodes.len() as u64,
            sorted_once: self.sorted_once,
            sorts: self.timers.sorts,
            removal: self
                .runs
                .iter()
                .map(|r| r.iter().map(|p| p.removal.clone()).collect())
                .collect(),
            dead,
            removed_total: self.removed_total.clone(),
            energy: sums,
            e_contact,
            total_memory: self.total_memory.clone(),
        };
        let mut records = Vec::new();
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (pi, p) in it.passes.iter().enumerate() {
                let run = &self.runs[ii][pi];
                let has_cand = run.cand.ptr.len() == run.mine.len() + 1;
                let has_state = !run.state.is_empty();
                for (j, &k) in run.mine.iter().enumerate() {
                    let (cand, state) = if has_cand {
                        let r = run.cand.ptr[j]..run.cand.ptr[j + 1];
                        let st = if has_state {
                            run.state[r.clone()].to_vec()
                        } else {
                            Vec::new()
                        };
                        (run.cand.segs[r].to_vec(), st)
                    } else {
                        (Vec::new(), Vec::new())
                    };
                    let rec = SecRecord {
                        node: run.nodes[j].clone(),
                        cand,
                        state,
                        walk_pair: run.walk_pair[j],
                    };
                    let g = p.sec_key(k as usize, &self.setup.nodes);
                    records.push((
                        key(ii, pi, g),
                        bincode::serialize(&rec).map_err(|e| e.to_string())?,
                    ));
                }
            }
        }
        let owned: Vec<u32> = self
            .held
            .iter()
            .copied()
            .filter(|&c| self.owned[c as usize])
            .collect();
        Ok(ContactExport {
            scalars,
            records,
            sort_rows: owned.iter().map(|&c| c as u64).collect(),
            x_sort: owned
                .iter()
                .flat_map(|&c| self.x_sort[c as usize])
                .collect(),
        })
    }

    /// Takes the state back (collective: the ghost plan is rebuilt).
    /// `records`: every rank's records; `x_sort`: the rows of `held_rows`.
    pub fn import(
        &mut self,
        world: &World,
        sc: &ContactScalars,
        records: &[(u64, Vec<u8>)],
        x_sort: &[f64],
    ) -> Result<(), String> {
        if sc.layout != LAYOUT {
            return Err(format!(
                "contact state layout {}, expected {LAYOUT} (a restart file of another crashsim version)",
                sc.layout
            ));
        }
        let shape = self.shape();
        let fmt = |s: &Shape| {
            s.iter()
                .map(|(id, ty, p)| format!("/INTER/TYPE{ty}/{id} {p:?}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        if sc.shape != shape || sc.nodes != self.setup.nodes.len() as u64 {
            return Err(format!(
                "written for the interfaces [{}] ({} contact nodes), this deck has [{}] ({} contact nodes): expected a restart file of this deck",
                fmt(&sc.shape),
                sc.nodes,
                fmt(&shape),
                self.setup.nodes.len()
            ));
        }
        let bad = |what: &str| format!("contact state: {what} (a damaged restart file?)");
        if sc.removal.len() != self.runs.len()
            || sc
                .removal
                .iter()
                .zip(&self.runs)
                .any(|(a, b)| a.len() != b.len())
            || sc.removed_total.len() != self.runs.len()
            || sc.energy.len() != self.runs.len()
            || sc.total_memory.len() != self.runs.len()
        {
            return Err(bad("interface tables of the wrong size"));
        }
        let by_key: HashMap<u64, &[u8]> = records.iter().map(|(k, b)| (*k, &b[..])).collect();
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (pi, p) in it.passes.iter().enumerate() {
                let run = &mut self.runs[ii][pi];
                let rm = &sc.removal[ii][pi];
                if rm.seg_alive.len() != run.removal.seg_alive.len()
                    || rm.sec_alive.len() != run.removal.sec_alive.len()
                    || rm.seg_off.len() != run.removal.seg_off.len()
                    || rm.sec_off.len() != run.removal.sec_off.len()
                {
                    return Err(bad(&format!(
                        "/INTER/TYPE{}/{}: Idel tables of the wrong size",
                        it.type_number, it.id
                    )));
                }
                run.removal = rm.clone();
                let nseg = p.segs.len() as u32;
                let mut cand = Candidates {
                    ptr: vec![0],
                    segs: Vec::new(),
                };
                let mut state = Vec::new();
                let mut nodes = Vec::with_capacity(run.mine.len());
                let mut walk_pair = Vec::with_capacity(run.mine.len());
                for &k in &run.mine {
                    let g = p.sec_key(k as usize, &self.setup.nodes);
                    let id = ContactSystem::secondary_name(&self.node_ids, p, k as usize);
                    let rec = by_key.get(&key(ii, pi, g)).ok_or_else(|| {
                        format!(
                            "no contact state for secondary {id} of /INTER/TYPE{}/{}: expected a restart file of this deck",
                            it.type_number, it.id
                        )
                    })?;
                    let rec: SecRecord = bincode::deserialize(rec).map_err(|e| {
                        bad(&format!(
                            "secondary {id} of /INTER/TYPE{}/{}: {e}",
                            it.type_number, it.id
                        ))
                    })?;
                    let seg_ok = |m: u32| m < nseg;
                    if !rec.cand.iter().all(|&m| seg_ok(m))
                        || !(rec.state.is_empty() || rec.state.len() == rec.cand.len())
                        || !(rec.node.last_seg == NONE || seg_ok(rec.node.last_seg))
                        || !(rec.walk_pair.0 == NONE || seg_ok(rec.walk_pair.0))
                        || !rec.node.off_segs.iter().all(|&m| seg_ok(m))
                        || !rec.node.gap0.iter().all(|e| seg_ok(e.0))
                    {
                        return Err(bad(&format!(
                            "secondary {id} of /INTER/TYPE{}/{}: segments out of range",
                            it.type_number, it.id
                        )));
                    }
                    cand.segs.extend_from_slice(&rec.cand);
                    cand.ptr.push(cand.segs.len());
                    state.extend_from_slice(&rec.state);
                    nodes.push(rec.node);
                    walk_pair.push(rec.walk_pair);
                }
                if !state.is_empty() && state.len() != cand.segs.len() {
                    return Err(bad("pair memory and candidates differ in length"));
                }
                run.cand = cand;
                run.state = state;
                // Measured again at the next sort.
                run.dist_sort = Vec::new();
                run.nodes = nodes;
                run.walk_pair = walk_pair;
            }
        }
        if x_sort.len() != 3 * self.held.len() {
            return Err(bad("sort positions of the wrong size"));
        }
        // The ghost plan of this layout, from the positions at the last sort.
        for (i, &c) in self.held.iter().enumerate() {
            self.cx[c as usize] = [x_sort[3 * i], x_sort[3 * i + 1], x_sort[3 * i + 2]];
        }
        self.plan = GhostPlan::default();
        self.rebuild_plan(world);
        self.sorted_once = sc.sorted_once;
        self.timers.sorts = sc.sorts;
        self.dead = sc.dead.iter().copied().collect();
        self.removed_total.clone_from(&sc.removed_total);
        self.total_memory.clone_from(&sc.total_memory);
        self.removed_now.clear();
        let root = world.rank() == 0;
        for (s, &e) in self.sums.iter_mut().zip(&sc.energy) {
            *s = super::InterfaceSums {
                energy: if root { e } else { 0.0 },
                ..Default::default()
            };
        }
        Ok(())
    }
}

/// This rank's share of the tied state.
pub struct TiedExport {
    /// (id, ties) per interface.
    pub shape: Vec<(u64, u64)>,
    /// Offsets of the ties whose secondary node this rank owns.
    pub offsets: Vec<(u64, Vec<u8>)>,
    /// Owned tied nodes (tied node indices, ascending) and the position a
    /// rank receiving them as ghosts holds.
    pub ghost_rows: Vec<u64>,
    pub x_ghost: Vec<f64>,
}

impl TiedSystem {
    pub fn shape(&self) -> Vec<(u64, u64)> {
        self.setup
            .interfaces
            .iter()
            .map(|it| (it.id, it.ties.len() as u64))
            .collect()
    }

    /// Tied nodes this rank receives as ghosts (tied node indices, ascending).
    pub fn ghost_rows(&self) -> Vec<u64> {
        let mut r: Vec<u64> = self.recv.iter().flatten().map(|&q| q as u64).collect();
        r.sort_unstable();
        r.dedup();
        r
    }

    pub fn node_count(&self) -> usize {
        self.setup.nodes.len()
    }

    pub fn export(&self) -> TiedExport {
        let mut offsets = Vec::new();
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (j, tie) in it.ties.iter().enumerate() {
                if self.local[tie.sec as usize] == NONE || !self.owned[tie.sec as usize] {
                    continue;
                }
                let k = tie_key(ii, self.setup.nodes[tie.sec as usize]);
                let d = self.d[ii][j];
                offsets.push((k, d.iter().flat_map(|c| c.to_le_bytes()).collect()));
            }
        }
        let owned: Vec<usize> = (0..self.setup.nodes.len())
            .filter(|&t| self.local[t] != NONE && self.owned[t])
            .collect();
        TiedExport {
            shape: self.shape(),
            offsets,
            ghost_rows: owned.iter().map(|&t| t as u64).collect(),
            x_ghost: owned.iter().flat_map(|&t| self.x_ghost[t]).collect(),
        }
    }

    /// Takes the offsets (every rank's records) and the ghost positions (the
    /// rows of `ghost_rows`) back.
    pub fn import(
        &mut self,
        shape: &[(u64, u64)],
        offsets: &[(u64, Vec<u8>)],
        x_ghost: &[f64],
    ) -> Result<(), String> {
        let mine = self.shape();
        if shape != mine {
            return Err(format!(
                "written for the tied interfaces (id, ties) {shape:?}, this deck has {mine:?}: expected a restart file of this deck"
            ));
        }
        let by_key: HashMap<u64, &[u8]> = offsets.iter().map(|(k, b)| (*k, &b[..])).collect();
        for (ii, it) in self.setup.interfaces.iter().enumerate() {
            for (j, tie) in it.ties.iter().enumerate() {
                if self.local[tie.sec as usize] == NONE {
                    continue;
                }
                let g = self.setup.nodes[tie.sec as usize];
                let k = tie_key(ii, g);
                let b = by_key
                    .get(&k)
                    .filter(|b| b.len() == 24)
                    .ok_or_else(|| {
                        format!(
                            "no tie offset for a secondary node of /INTER/TYPE2/{}: expected a restart file of this deck",
                            it.id
                        )
                    })?;
                let mut d = [0.0; 3];
                for (c, ch) in d.iter_mut().zip(b.chunks_exact(8)) {
                    *c = f64::from_le_bytes(ch.try_into().expect("8 bytes"));
                }
                self.d[ii][j] = d;
                self.d_next[ii][j] = d;
            }
        }
        let rows = self.ghost_rows();
        if x_ghost.len() != 3 * rows.len() {
            return Err(
                "tied state: ghost positions of the wrong size (a damaged restart file?)".into(),
            );
        }
        for (i, &q) in rows.iter().enumerate() {
            self.tx[q as usize] = [x_ghost[3 * i], x_ghost[3 * i + 1], x_ghost[3 * i + 2]];
        }
        self.started = true;
        Ok(())
    }
}
