//! The static layout of the interfaces as the runtime holds them, built once
//! by `contact::setup` and replicated on every rank: each interface's shared
//! options and its type's own (`TypeOptions`), its passes (secondary nodes
//! against main segments, with their gaps, stiffnesses and neighbour tables),
//! Idel rules, and the contact-node table.

use super::{InterfaceType, Side, TypeOptions};
use crate::contact::friction::FrictionLaw;
use crate::contact::gap::GapRule;
use crate::contact::geometry::{self as geo, V3};
use serde::{Deserialize, Serialize};

pub const NONE: u32 = u32::MAX;

/// One pass: secondary nodes against main segments, or (edge-to-edge)
/// secondary edges against main edges.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Pass {
    /// Main entities as cnodes: segments (a triangle repeats its third node)
    /// or, in an edge-to-edge pass, edges (the second node repeated, see
    /// `Side::segment`).
    pub segs: Vec<[u32; 4]>,
    /// Main segment stiffness (scale factor included, see `Interface::istf`).
    pub seg_k: Vec<f64>,
    /// Main element gap g_m (half the shell thickness, 0 on solids).
    pub seg_gap: Vec<f64>,
    /// Smallest edge of each main segment (initial).
    pub seg_lmin: Vec<f64>,
    /// Contact pressure area of each main segment (initial).
    pub seg_area: Vec<f64>,
    /// The element under each main segment: (kind index, element index).
    pub seg_elem: Vec<(u8, u32)>,
    /// Secondary nodes (cnodes, ascending); empty in an edge-to-edge pass.
    pub sec: Vec<u32>,
    /// Edge-to-edge passes: the secondary edges as cnodes (then `sec_k`,
    /// `sec_gap` and `sec_lmin` are indexed by edge).
    #[serde(default)]
    pub sec_edges: Vec<[u32; 2]>,
    /// Segment-to-segment passes: the secondary segments as cnodes (a
    /// triangle repeats its third node; `sec_k`, `sec_gap` and `sec_lmin`
    /// are indexed by segment).
    #[serde(default)]
    pub sec_segs: Vec<[u32; 4]>,
    /// Both sides hold the same edges (self-contact): of the two
    /// orientations of a pair only the one whose main edge's first node has
    /// the larger node id is a candidate.
    #[serde(default)]
    pub self_contact: bool,
    /// Secondary node stiffness Ks (card eq. (6)/(7)), TYPE3 own-surface stiffness.
    pub sec_k: Vec<f64>,
    /// Secondary gap g_s (half the largest connected shell thickness) and smallest connected edge.
    pub sec_gap: Vec<f64>,
    pub sec_lmin: Vec<f64>,
    /// TYPE5: closest main segment found by the Starter's full search (NONE if none).
    pub sec_start_seg: Vec<u32>,
    /// Segments around each main node (CSR over cnodes of the segments): TYPE5 walk.
    pub node_segs_ptr: Vec<u32>,
    pub node_segs_key: Vec<u32>,
    pub node_segs: Vec<u32>,
    /// Largest segment diagonal (for the ghost boxes).
    pub max_diag: f64,
    /// Idel (empty when the interface does not delete): the elements
    /// associated with each main segment, CSR over `segs` — every 4- or
    /// 3-node shell whose nodes are the segment's and every solid that has
    /// the segment as a face — as (kind index, element index).
    pub seg_elems_ptr: Vec<u32>,
    pub seg_elems: Vec<(u8, u32)>,
    /// Idel = 1, 2 (empty otherwise): the elements attached to each secondary
    /// node (every kind), CSR over `sec`; a node none of whose elements is
    /// alive is "non-connected" and leaves the secondary side. A node with no
    /// element at all is never removed (no deletion concerns it), and a node
    /// on a spring stays connected while the spring lives (springs are never
    /// deleted).
    pub sec_elems_ptr: Vec<u32>,
    pub sec_elems: Vec<(u8, u32)>,
    /// Dormant main segments (faces between two solids, TYPE25): each with
    /// the solid whose deletion wakes it, (segment, (kind index, element
    /// index)), by segment. A dormant segment is no candidate until then.
    #[serde(default)]
    pub seg_wakers: Vec<(u32, (u8, u32))>,
    /// Irem_gap = 2 (`close_neighbours`): the secondary nodes (cnodes,
    /// ascending) each main segment never pairs with, CSR over `segs`;
    /// empty when the type removes none.
    #[serde(default)]
    pub removed_ptr: Vec<u32>,
    #[serde(default)]
    pub removed: Vec<u32>,
}

impl Pass {
    /// Number of secondary entities (nodes, edges or segments).
    pub fn n_sec(&self) -> usize {
        if self.is_edge_pass() {
            self.sec_edges.len()
        } else if self.is_segment_pass() {
            self.sec_segs.len()
        } else {
            self.sec.len()
        }
    }
    /// The pass pairs edges with edges.
    pub fn is_edge_pass(&self) -> bool {
        !self.sec_edges.is_empty()
    }
    /// The pass pairs segments with segments.
    pub fn is_segment_pass(&self) -> bool {
        !self.sec_segs.is_empty()
    }
    /// The secondary entities are edges or segments, not nodes: each is
    /// computed by the lowest rank holding all its nodes.
    pub fn is_entity_pass(&self) -> bool {
        self.is_edge_pass() || self.is_segment_pass()
    }
    /// Secondary entity k's nodes.
    pub fn sec_side(&self, k: usize) -> Side {
        if self.is_edge_pass() {
            Side::edge(self.sec_edges[k])
        } else if self.is_segment_pass() {
            Side::segment(&self.sec_segs[k])
        } else {
            Side::node(self.sec[k])
        }
    }
    /// Secondary entity k as its pairs' sum key and restart record name it:
    /// a node's global node index, an edge's or segment's index in the pass
    /// (both the same on every rank).
    pub fn sec_key(&self, k: usize, nodes_g: &[u32]) -> u32 {
        if self.is_entity_pass() {
            k as u32
        } else {
            nodes_g[self.sec[k] as usize]
        }
    }
    /// Segments around main cnode `c` (empty when `c` is on no segment).
    pub fn segments_around(&self, c: u32) -> &[u32] {
        match self.node_segs_key.binary_search(&c) {
            Ok(i) => {
                &self.node_segs[self.node_segs_ptr[i] as usize..self.node_segs_ptr[i + 1] as usize]
            }
            Err(_) => &[],
        }
    }
    /// Irem_gap = 2: segment `m` never pairs with secondary cnode `c`.
    pub fn removes(&self, m: usize, c: u32) -> bool {
        match self.removed_ptr.get(m..m + 2) {
            Some(&[a, b]) => self.removed[a as usize..b as usize]
                .binary_search(&c)
                .is_ok(),
            _ => false,
        }
    }
    pub fn is_tri(&self, s: usize) -> bool {
        self.segs[s][3] == self.segs[s][2]
    }
    /// Idel: the elements associated with main segment `s`.
    pub fn elements_of_segment(&self, s: usize) -> &[(u8, u32)] {
        csr(&self.seg_elems_ptr, &self.seg_elems, s)
    }
    /// Idel = 1, 2: the elements attached to secondary node `k` (index into `sec`).
    pub fn elements_of_secondary(&self, k: usize) -> &[(u8, u32)] {
        csr(&self.sec_elems_ptr, &self.sec_elems, k)
    }
}

fn csr<'a, T>(ptr: &[u32], v: &'a [T], i: usize) -> &'a [T] {
    if i + 1 >= ptr.len() {
        return &[];
    }
    &v[ptr[i] as usize..ptr[i + 1] as usize]
}

/// What an interface's Idel asks for (card /INTER/TYPE7, Idel; TYPE3 and TYPE5
/// read the same flag, with 0 meaning no deletion).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IdelRule {
    /// Idel = ±1: a main segment is removed when *all* its associated elements
    /// are deleted; Idel = ±2: as soon as *one* of them is.
    pub all: bool,
    /// Idel = 1, 2: non-connected nodes also leave the secondary side (not with -1, -2).
    pub nodes: bool,
}

impl IdelRule {
    /// `None` for 0 and 1000 (no deletion).
    pub fn of(idel: i64) -> Option<IdelRule> {
        match idel {
            1 => Some(IdelRule {
                all: true,
                nodes: true,
            }),
            2 => Some(IdelRule {
                all: false,
                nodes: true,
            }),
            -1 => Some(IdelRule {
                all: true,
                nodes: false,
            }),
            -2 => Some(IdelRule {
                all: false,
                nodes: false,
            }),
            _ => None,
        }
    }
}

/// One interface, resolved: the options every type shares, its passes, and
/// its type with the type's own options (`interfaces::TypeOptions`).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Interface {
    pub id: u64,
    pub type_number: u32,
    pub title: String,
    /// The interface type (registry entry) and its own options.
    pub options: TypeOptions,
    pub passes: Vec<Pass>,
    pub gap: GapRule,
    /// Largest gap of any pair (search reach without the margin).
    pub max_gap: f64,
    /// Sorting margin: candidates are kept while motion stays below it (Bumult).
    pub margin: f64,
    pub stfac: f64,
    pub friction: FrictionLaw,
    pub tstart: f64,
    pub tstop: f64,
    pub ibc: [bool; 3],
    pub inacti: i64,
    /// Idel: 0/1000 none; ±1 all elements of a segment deleted; ±2 any (see [`IdelRule`]).
    pub idel: i64,
}

impl Interface {
    /// The interface's type.
    pub fn ty(&self) -> &dyn InterfaceType {
        self.options.implementation()
    }

    /// The gap of pair (secondary k, segment m) of pass `p` (card eq. (8)–(10)).
    #[inline]
    pub fn pair_gap(&self, p: &Pass, k: usize, m: usize) -> f64 {
        self.gap
            .pair_gap(p.sec_gap[k], p.seg_gap[m], p.sec_lmin[k], p.seg_lmin[m])
    }
}

/// All interfaces plus the contact-node table.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct ContactSetup {
    pub interfaces: Vec<Interface>,
    /// Global node index of each cnode, ascending.
    pub nodes: Vec<u32>,
    /// Initial position of each cnode.
    pub x0: Vec<V3>,
    /// Ranks holding each cnode (CSR), ascending.
    pub holders_ptr: Vec<u32>,
    pub holders: Vec<u32>,
    /// Initial nodal mass of each cnode (elements and /ADMAS), for the
    /// dampers of edge pairs, whose main nodes may be ghosts.
    #[serde(default)]
    pub mass: Vec<f64>,
}

impl ContactSetup {
    pub fn is_empty(&self) -> bool {
        self.interfaces.is_empty()
    }
    pub fn holders_of(&self, c: u32) -> &[u32] {
        &self.holders
            [self.holders_ptr[c as usize] as usize..self.holders_ptr[c as usize + 1] as usize]
    }
    /// The rank that computes the pairs of a secondary side: the lowest rank
    /// holding all its nodes (for a node, its owner). A side on one element
    /// always has one: the element's rank holds all its nodes.
    pub fn owner_of(&self, side: &Side) -> Option<u32> {
        let (first, rest) = side.nodes().split_first()?;
        self.holders_of(*first)
            .iter()
            .copied()
            .find(|r| rest.iter().all(|&c| self.holders_of(c).contains(r)))
    }
    pub fn cnode_of(&self, global: u32) -> Option<u32> {
        self.nodes.binary_search(&global).ok().map(|i| i as u32)
    }
}

/// Among `segs`, the one whose closest point is nearest to p (ties: lowest index);
/// `None` when the positions of none of them are known.
pub fn closest_segment(segs: &[u32], p: V3, x_of: impl Fn(u32) -> Option<[V3; 4]>) -> Option<u32> {
    let mut best: Option<(f64, u32)> = None;
    for &s in segs {
        let Some(x) = x_of(s) else { continue };
        let tri = x[3] == x[2];
        let pr = geo::project(p, &x, tri);
        if best.is_none_or(|b| pr.dist < b.0 || (pr.dist == b.0 && s < b.1)) {
            best = Some((pr.dist, s));
        }
    }
    best.map(|b| b.1)
}
