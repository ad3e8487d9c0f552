//! Irem_gap = 2 of /INTER/TYPE7 (reference guide: "deactivating secondary
//! nodes if element size < gap value, in case of self-impact contact"): in
//! a surface whose elements are smaller than the gap, a node would touch
//! the segments around it through the gap alone. Each main segment gets,
//! once and from the initial coordinates, the list of secondary nodes it
//! never pairs with: those within √2·gap of it along the surface
//! (`docs/notes/irem_gap2_research.md`, the reference starter's list):
//!
//! - the distance is a path over the surface's segments, starting at 0 on
//!   the segment's nodes, each step a straight line between two nodes of one
//!   segment (a quadrangle's diagonals included), through secondary nodes;
//! - the search grows one ring of segments at a time (a node's distance is
//!   relaxed by the nodes of the ring before it, the reference's
//!   level-synchronous search, not an exact shortest path) and stops once
//!   the nearest node it reached plus the surface's shortest edge passes
//!   √2·gap (Igap 0: the constant gap; else g_m + the largest g_s);
//! - a node is left out when its distance is at most √2 times its pair's
//!   gap with the segment (≤, not <).
//!
//! The lists are built once; the sort at every cycle and the initial
//! penetration checks skip their pairs, as they skip a node of the segment.

use super::gap::GapRule;
use super::geometry::{self as geo, V3};
use super::interfaces::layout::{Pass, NONE};
use rayon::prelude::*;

/// One segment's search, with its scratch kept between segments (stamped
/// with the segment so nothing needs clearing).
struct Scratch {
    stamp: Vec<u32>,
    dist: Vec<f64>,
    seg_stamp: Vec<u32>,
    seg_level: Vec<u32>,
    expanded: Vec<(u32, u32)>,
}

impl Scratch {
    fn new(n_cnodes: usize, n_segs: usize) -> Self {
        Scratch {
            stamp: vec![u32::MAX; n_cnodes],
            dist: vec![f64::INFINITY; n_cnodes],
            seg_stamp: vec![u32::MAX; n_segs],
            seg_level: vec![0; n_segs],
            expanded: vec![(u32::MAX, 0); n_cnodes],
        }
    }
    fn dist(&self, c: u32, i: u32) -> f64 {
        if self.stamp[c as usize] == i {
            self.dist[c as usize]
        } else {
            f64::INFINITY
        }
    }
    fn set_dist(&mut self, c: u32, i: u32, d: f64) {
        self.stamp[c as usize] = i;
        self.dist[c as usize] = d;
    }
    fn level(&self, g: u32, i: u32) -> Option<u32> {
        (self.seg_stamp[g as usize] == i).then(|| self.seg_level[g as usize])
    }
}

/// What the search reads of the pass.
struct Surface<'a> {
    p: &'a Pass,
    /// Each cnode's index among the secondary nodes (NONE: not secondary).
    sec_of: Vec<u32>,
    /// The segments around each cnode (CSR over cnodes).
    around_ptr: Vec<u32>,
    around: Vec<u32>,
    /// Whether each main segment has a secondary node (the others carry no path).
    carries: Vec<bool>,
    /// The shortest edge of the main surface.
    min_edge: f64,
    /// Each segment's six node-to-node lengths (edges and diagonals, by
    /// `PAIR`), computed once.
    lengths: Vec<[f64; 6]>,
    gap: &'a GapRule,
    gs_max: f64,
}

/// The index in a segment's `lengths` of its nodes a and b.
const PAIR: [[usize; 4]; 4] = [[0, 0, 1, 2], [0, 0, 3, 4], [1, 3, 0, 5], [2, 4, 5, 0]];

/// |x_a − x_b| for the node pairs (0,1), (0,2), (0,3), (1,2), (1,3), (2,3).
fn lengths(x0: &[V3], s: &[u32; 4]) -> [f64; 6] {
    let d = |a: usize, b: usize| geo::norm(geo::sub(x0[s[b] as usize], x0[s[a] as usize]));
    [d(0, 1), d(0, 2), d(0, 3), d(1, 2), d(1, 3), d(2, 3)]
}

fn distinct(s: &[u32; 4]) -> &[u32] {
    if s[3] == s[2] {
        &s[..3]
    } else {
        &s[..]
    }
}

impl Surface<'_> {
    fn sec_index(&self, c: u32) -> Option<usize> {
        let k = self.sec_of[c as usize];
        (k != NONE).then_some(k as usize)
    }

    fn segments_around(&self, c: u32) -> &[u32] {
        &self.around[self.around_ptr[c as usize] as usize..self.around_ptr[c as usize + 1] as usize]
    }

    /// The search limit around segment i.
    fn reach(&self, i: usize) -> f64 {
        // Constant gap unless Igap 1-3, as `GapRule::pair_gap` reads it.
        let g = if matches!(self.gap.igap, 1..=3) {
            self.p.seg_gap[i] + self.gs_max
        } else {
            self.gap.gapmin
        };
        std::f64::consts::SQRT_2 * g
    }

    /// √2 times the gap of pair (secondary cnode c, segment i).
    fn threshold(&self, k: usize, i: usize) -> f64 {
        let p = self.p;
        std::f64::consts::SQRT_2
            * self
                .gap
                .pair_gap(p.sec_gap[k], p.seg_gap[i], p.sec_lmin[k], p.seg_lmin[i])
    }

    /// One ring: every segment around the nodes of the frontier, each node
    /// of it that is secondary relaxed from the frontier node; returns the
    /// next frontier and the smallest distance set.
    fn ring(
        &self,
        sc: &mut Scratch,
        i: u32,
        level: u32,
        frontier: &[u32],
        found: &mut Vec<u32>,
    ) -> (Vec<u32>, f64) {
        let mut next = Vec::new();
        let mut nearest = f64::INFINITY;
        for &f in frontier {
            let fs = distinct(&self.p.segs[f as usize]);
            for &n in fs {
                if sc.expanded[n as usize] == (i, level) {
                    continue;
                }
                sc.expanded[n as usize] = (i, level);
                let dn = sc.dist(n, i);
                for &g in self.segments_around(n) {
                    if !self.carries[g as usize] {
                        continue;
                    }
                    match sc.level(g, i) {
                        None => {
                            sc.seg_stamp[g as usize] = i;
                            sc.seg_level[g as usize] = level;
                            next.push(g);
                        }
                        Some(l) if l != level => continue,
                        Some(_) => {}
                    }
                    let gs = distinct(&self.p.segs[g as usize]);
                    let a = gs.iter().position(|&c| c == n).unwrap_or(0);
                    for (b, &m) in gs.iter().enumerate() {
                        if fs.contains(&m) || self.sec_index(m).is_none() {
                            continue;
                        }
                        let d = dn + self.lengths[g as usize][PAIR[a][b]];
                        if sc.stamp[m as usize] != i {
                            found.push(m);
                        }
                        let new = sc.dist(m, i).min(d);
                        sc.set_dist(m, i, new);
                        nearest = nearest.min(new);
                    }
                }
            }
        }
        (next, nearest)
    }

    /// The secondary nodes segment i never pairs with, ascending.
    fn removed(&self, sc: &mut Scratch, i: usize) -> Vec<u32> {
        let iu = i as u32;
        let own = distinct(&self.p.segs[i]);
        for &n in own {
            sc.set_dist(n, iu, 0.0);
        }
        sc.seg_stamp[i] = iu;
        sc.seg_level[i] = 1;
        let limit = self.reach(i);
        let (mut frontier, mut nearest, mut level) = (vec![iu], 0.0f64, 1u32);
        let mut found = Vec::new();
        while nearest + self.min_edge <= limit && !frontier.is_empty() {
            level += 1;
            (frontier, nearest) = self.ring(sc, iu, level, &frontier, &mut found);
        }
        // The segment's own nodes are stamped from the start: never found.
        let mut out: Vec<u32> = found
            .into_iter()
            .filter(|&m| {
                let k = self.sec_index(m).expect("a secondary node");
                sc.dist(m, iu) <= self.threshold(k, i)
            })
            .collect();
        out.sort_unstable();
        out
    }
}

/// Each main segment's left-out secondary nodes (cnodes), CSR over the
/// pass's segments; empty when no main node is also secondary (no
/// self-contact, nothing to leave out). `x0`: initial cnode positions.
pub fn removal_lists(p: &Pass, x0: &[V3], gap: &GapRule) -> (Vec<u32>, Vec<u32>) {
    let is_sec = |c: &u32| p.sec.binary_search(c).is_ok();
    let carries: Vec<bool> = p
        .segs
        .iter()
        .map(|s| distinct(s).iter().any(is_sec))
        .collect();
    if !carries.iter().any(|&c| c) {
        return (Vec::new(), Vec::new());
    }
    let mut sec_of = vec![NONE; x0.len()];
    for (k, &c) in p.sec.iter().enumerate() {
        sec_of[c as usize] = k as u32;
    }
    let mut count = vec![0u32; x0.len() + 1];
    for s in &p.segs {
        for &c in distinct(s) {
            count[c as usize + 1] += 1;
        }
    }
    for c in 0..x0.len() {
        count[c + 1] += count[c];
    }
    let mut around = vec![0u32; count[x0.len()] as usize];
    let mut fill = count.clone();
    for (g, s) in p.segs.iter().enumerate() {
        for &c in distinct(s) {
            around[fill[c as usize] as usize] = g as u32;
            fill[c as usize] += 1;
        }
    }
    let surface = Surface {
        p,
        sec_of,
        around_ptr: count,
        around,
        carries,
        min_edge: p.seg_lmin.iter().copied().fold(f64::INFINITY, f64::min),
        lengths: p.segs.iter().map(|s| lengths(x0, s)).collect(),
        gap,
        gs_max: p.sec_gap.iter().copied().fold(0.0, f64::max),
    };
    let lists: Vec<Vec<u32>> = (0..p.segs.len())
        .into_par_iter()
        .map_init(
            || Scratch::new(x0.len(), p.segs.len()),
            |sc, i| surface.removed(sc, i),
        )
        .collect();
    let mut ptr = Vec::with_capacity(lists.len() + 1);
    ptr.push(0u32);
    let mut nodes = Vec::new();
    for l in lists {
        nodes.extend(l);
        ptr.push(nodes.len() as u32);
    }
    (ptr, nodes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat strip of unit squares along x (nodes 2j at y = 0, 2j + 1 at
    /// y = 1), every node secondary (self-contact), constant gap g.
    fn strip(n: usize, g: f64) -> (Pass, Vec<V3>, GapRule) {
        let mut x0 = Vec::new();
        for j in 0..=n {
            x0.push([j as f64, 0.0, 0.0]);
            x0.push([j as f64, 1.0, 0.0]);
        }
        let segs: Vec<[u32; 4]> = (0..n as u32)
            .map(|j| [2 * j, 2 * j + 2, 2 * j + 3, 2 * j + 1])
            .collect();
        let ns = segs.len();
        let p = Pass {
            sec: (0..x0.len() as u32).collect(),
            sec_gap: vec![0.0; x0.len()],
            sec_lmin: vec![1.0; x0.len()],
            seg_gap: vec![0.0; ns],
            seg_lmin: vec![1.0; ns],
            segs,
            ..Default::default()
        };
        let gap = GapRule {
            igap: 1000,
            gapmin: g,
            fscalegap: 1.0,
            gapmax: 1e30,
            mesh_size_pct: 0.4,
        };
        (p, x0, gap)
    }

    /// Gap 1.5 (√2·g = 2.12): from segment 0 (x in [0, 1]) the nodes at
    /// x = 2 are one edge away, those at x = 3 two (node 7 by the edge
    /// from node 5, not by the diagonal from node 4), those at x = 4
    /// three; gap 1.2 (1.70) keeps x = 2 only; gap 0.5 (0.71, below the
    /// shortest edge) leaves nothing out.
    #[test]
    fn nodes_within_root_two_gaps_along_the_surface_are_left_out() {
        let (p, x0, gap) = strip(6, 1.5);
        let (ptr, nodes) = removal_lists(&p, &x0, &gap);
        let of = |i: usize| nodes[ptr[i] as usize..ptr[i + 1] as usize].to_vec();
        assert_eq!(of(0), [4, 5, 6, 7]);
        // Segment 3 (x in [3, 4]) reaches both ways.
        assert_eq!(of(3), [2, 3, 4, 5, 10, 11, 12, 13]);
        let (p, x0, gap) = strip(6, 1.2);
        let (ptr, nodes) = removal_lists(&p, &x0, &gap);
        assert_eq!(nodes[ptr[0] as usize..ptr[1] as usize], [4, 5]);
        let (p, x0, gap) = strip(6, 0.5);
        let (_, nodes) = removal_lists(&p, &x0, &gap);
        assert!(nodes.is_empty());
    }
}
