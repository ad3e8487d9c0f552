//! /INTER/TYPE7 Inacti = 3: "change node coordinates to avoid initial
//! penetrations" (card Inacti; §"Initial penetrations": the Starter corrects
//! the coordinates of the penetrated nodes; card comment 13: this may create
//! initial energy if the node belongs to a spring element).
//!
//! A starter step, done once on rank 0 on the model before it is partitioned:
//! every secondary node of a TYPE7 interface with Inacti = 3 that lies inside
//! the gap of a main segment not connected to it (the pairs the engine would
//! find at its first sort: same exclusions, same pair gap) is translated along
//! the contact direction — the segment normal over its face, radially from an
//! edge or a corner (`geometry::project`) — by its penetration P = Gap − d,
//! which puts it exactly at the gap of that segment (no extra clearance: the
//! pair starts with no force, P = 0 to round-off).
//!
//! A node in several segments' gaps is moved out of the deepest one; every
//! node is then measured again (a move may bring it into another segment's
//! gap, and in self-contact a moved node carries its segments along), for at
//! most [`PASSES`] passes. All nodes of one pass are measured on the same
//! coordinates (Jacobi), so the result does not depend on the order nodes are
//! visited. Nodes still inside a gap after the last pass are reported by id;
//! the engine then treats them as Inacti = 0 would (the full reaction).
//!
//! Fpenmax (card comment 13, "whatever the value of Inacti"): a node with an
//! initial penetration P ≥ Fpenmax·Gap is not moved; the engine deactivates
//! its stiffness at the first sort.
//!
//! The caller rebuilds the model from the moved coordinates, so that element
//! reference geometry, masses, gaps and the output mesh all start from them.

use super::geometry::{self as geo, V3};
use super::interfaces::TypeOptions;
use super::search::{self, Aabb};
use super::setup;
use crate::model::InterfaceKind;
use crate::model::Model;

/// Passes over the secondary nodes before giving up on the ones still penetrated.
pub const PASSES: usize = 10;

/// A node counts as penetrated when P > this fraction of its gap: what is
/// left after a move is round-off.
const REL_TOL: f64 = 1e-9;

/// How many node ids a listing note names.
const LIST: usize = 10;

/// What one interface's Inacti = 3 did.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    pub interface_id: u64,
    /// Moved nodes: (node id, total displacement), ascending id.
    pub moved: Vec<(u64, V3)>,
    /// Node ids still inside a gap after the last pass.
    pub unfreed: Vec<u64>,
    /// Node ids left in place because P ≥ Fpenmax·Gap (deactivated by the engine).
    pub fpenmax: Vec<u64>,
}

impl Report {
    /// The largest move: (node id, length).
    pub fn largest(&self) -> Option<(u64, f64)> {
        let mut best: Option<(u64, f64)> = None;
        for &(id, d) in &self.moved {
            let l = geo::norm(d);
            if best.is_none_or(|b| l > b.1) {
                best = Some((id, l));
            }
        }
        best
    }

    /// The listing note.
    pub fn note(&self, loc: &str) -> String {
        let ids = |v: &[u64]| -> String {
            let mut s: Vec<String> = v.iter().take(LIST).map(|i| i.to_string()).collect();
            if v.len() > LIST {
                s.push(format!("… ({} more)", v.len() - LIST));
            }
            s.join(", ")
        };
        let mut s = format!("{loc}: /INTER/TYPE7/{}: Inacti = 3: ", self.interface_id);
        match self.largest() {
            Some((id, l)) => {
                let moved: Vec<u64> = self.moved.iter().map(|m| m.0).collect();
                s.push_str(&format!(
                    "{} secondary nodes moved out of initial penetrations (to the gap, along the contact direction), largest move {l:.6e} (node {id}); moved: {}",
                    moved.len(),
                    ids(&moved)
                ));
            }
            None => s.push_str("no secondary node initially penetrated, no coordinates changed"),
        }
        if !self.unfreed.is_empty() {
            s.push_str(&format!(
                "; {} nodes still penetrated after {PASSES} passes (left to the contact force): {}",
                self.unfreed.len(),
                ids(&self.unfreed)
            ));
        }
        if !self.fpenmax.is_empty() {
            s.push_str(&format!(
                "; {} nodes with P >= Fpenmax*Gap not moved (their stiffness is deactivated): {}",
                self.fpenmax.len(),
                ids(&self.fpenmax)
            ));
        }
        s
    }
}

/// Whether any interface asks for Inacti = 3.
pub fn wanted(m: &Model) -> bool {
    m.interfaces
        .iter()
        .any(|i| matches!(&i.card.kind, InterfaceKind::Type7(t) if t.inacti == 3))
}

/// The deepest penetrated segment of secondary `k` of pass `p` at coordinates
/// `x` (cnode order), among `cands`: (P, gap, direction), P > tolerance.
fn deepest(
    it: &setup::Interface,
    p: &setup::Pass,
    k: usize,
    cands: &[u32],
    x: &[V3],
) -> Option<(f64, f64, V3)> {
    let s = p.sec[k];
    let xs = x[s as usize];
    let mut best: Option<(f64, f64, V3)> = None;
    for &m in cands {
        let seg = &p.segs[m as usize];
        // The engine's exclusions (the sort's).
        if super::excluded(p, m, s) {
            continue;
        }
        let xm = [
            x[seg[0] as usize],
            x[seg[1] as usize],
            x[seg[2] as usize],
            x[seg[3] as usize],
        ];
        let m = m as usize;
        let g = it
            .gap
            .pair_gap(p.sec_gap[k], p.seg_gap[m], p.sec_lmin[k], p.seg_lmin[m]);
        let pr = geo::project(xs, &xm, p.is_tri(m));
        let pen = g - pr.dist;
        if pen > REL_TOL * g && best.is_none_or(|b| pen > b.0) {
            best = Some((pen, g, pr.dir));
        }
    }
    best
}

/// New coordinates of every model node (when any moved) and the reports.
pub type Depenetrated = (Option<Vec<[f64; 3]>>, Vec<Report>);

/// Moves the secondary nodes of every TYPE7 interface with Inacti = 3 out of
/// their initial penetrations. Returns the new coordinates of every model
/// node (model order) when any node moved, and one report per such interface
/// (deck order).
pub fn depenetrate(m: &Model) -> Result<Depenetrated, String> {
    if !wanted(m) {
        return Ok((None, Vec::new()));
    }
    // Rank-independent: the setup's static data, as if one rank held everything.
    let holders = vec![vec![0u32]; m.nodes.len()];
    let cs = setup::build(m, &holders)?;
    let x0: Vec<V3> = cs.x0.clone();
    let mut x: Vec<V3> = cs.x0.clone();
    let mut reports = Vec::new();
    for it in &cs.interfaces {
        let TypeOptions::Type7(t7) = &it.options else {
            continue;
        };
        if it.inacti != 3 {
            continue;
        }
        let mut moved_by: std::collections::BTreeMap<u32, V3> = Default::default();
        let mut fpen: std::collections::BTreeSet<u32> = Default::default();
        let mut unfreed: std::collections::BTreeSet<u32> = Default::default();
        for p in &it.passes {
            // Candidate segments of each of the pass's secondary nodes on coordinates `x`.
            let candidates_on = |x: &[V3]| {
                let boxes: Vec<Aabb> = p
                    .segs
                    .iter()
                    .map(|s| Aabb::of_points(&s.map(|c| x[c as usize])))
                    .collect();
                let pts: Vec<V3> = p.sec.iter().map(|&s| x[s as usize]).collect();
                search::candidates(&pts, it.max_gap, &boxes, search::choose(&boxes))
            };
            // Fpenmax, on the coordinates as they are before this interface moves anything.
            let mut skip = vec![false; p.sec.len()];
            if t7.fpenmax > 0.0 {
                let cand = candidates_on(&x);
                for (k, sk) in skip.iter_mut().enumerate() {
                    let c = &cand.segs[cand.ptr[k]..cand.ptr[k + 1]];
                    for &mi in c {
                        if let Some((pen, g, _)) = deepest(it, p, k, std::slice::from_ref(&mi), &x)
                        {
                            if pen >= t7.fpenmax * g {
                                *sk = true;
                                fpen.insert(p.sec[k]);
                                break;
                            }
                        }
                    }
                }
            }
            let mut still: Vec<usize> = Vec::new();
            for pass in 0..=PASSES {
                let cand = candidates_on(&x);
                let moves: Vec<(u32, V3)> = (0..p.sec.len())
                    .filter(|&k| !skip[k])
                    .filter_map(|k| {
                        let c = &cand.segs[cand.ptr[k]..cand.ptr[k + 1]];
                        deepest(it, p, k, c, &x)
                            .map(|(pen, _, dir)| (k as u32, geo::scale(dir, pen)))
                    })
                    .collect();
                if moves.is_empty() {
                    still.clear();
                    break;
                }
                if pass == PASSES {
                    still = moves.iter().map(|m| m.0 as usize).collect();
                    break;
                }
                for (k, d) in moves {
                    let s = p.sec[k as usize];
                    x[s as usize] = geo::add(x[s as usize], d);
                    moved_by.entry(s).or_insert([0.0; 3]);
                }
            }
            unfreed.extend(still.iter().map(|&k| p.sec[k]));
        }
        let id_of = |c: u32| m.nodes.ids[cs.nodes[c as usize] as usize];
        reports.push(Report {
            interface_id: it.id,
            moved: moved_by
                .keys()
                .map(|&c| (id_of(c), geo::sub(x[c as usize], x0[c as usize])))
                .collect(),
            unfreed: unfreed.iter().map(|&c| id_of(c)).collect(),
            fpenmax: fpen.iter().map(|&c| id_of(c)).collect(),
        });
    }
    if reports.iter().all(|r| r.moved.is_empty()) {
        return Ok((None, reports));
    }
    let mut out = m.nodes.x.clone();
    for (c, &g) in cs.nodes.iter().enumerate() {
        out[g as usize] = x[c];
    }
    Ok((Some(out), reports))
}
