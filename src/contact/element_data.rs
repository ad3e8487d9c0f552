//! What contact set-up reads from the elements under its nodes, segments
//! and edges: bulk moduli, element volumes, the elements around a node.

use super::geometry::{self as geo, V3};
use super::stiffness::ElementSize;
use crate::model::{geometry as mgeo, ElementKind, MaterialSpec, Model};
use std::collections::HashMap;

pub(super) fn bulk(m: &MaterialSpec) -> f64 {
    m.e / (3.0 * (1.0 - 2.0 * m.nu))
}

/// Every element (any kind) attached to each of `nodes` (global node indices).
pub(super) fn node_elements(m: &Model, nodes: &[u32]) -> HashMap<u32, Vec<(u8, u32)>> {
    let mut out: HashMap<u32, Vec<(u8, u32)>> = nodes.iter().map(|&n| (n, Vec::new())).collect();
    for (ki, set) in m.elements.iter().enumerate() {
        for e in 0..set.len() {
            let ns = set.nodes_of(e);
            for (i, q) in ns.iter().enumerate() {
                if ns[..i].contains(q) {
                    continue;
                }
                if let Some(v) = out.get_mut(q) {
                    v.push((ki as u8, e as u32));
                }
            }
        }
    }
    out
}

pub(super) fn element_volume(m: &Model, ki: usize, e: usize) -> f64 {
    let set = &m.elements[ki];
    let n = set.nodes_of(e);
    let x = |i: usize| m.nodes.x[n[i] as usize];
    match set.kind {
        ElementKind::Brick8 => mgeo::hexa_volume([x(0), x(1), x(2), x(3), x(4), x(5), x(6), x(7)]),
        ElementKind::Tetra4 => mgeo::tetra_volume([x(0), x(1), x(2), x(3)]).abs(),
        _ => 0.0,
    }
}

/// The nodes on a free edge of the model's shells: an edge of a 4- or
/// 3-node shell that no other shell shares.
pub(super) fn free_shell_edge_nodes(m: &Model) -> std::collections::HashSet<u32> {
    let mut count: HashMap<[u32; 2], u32> = HashMap::new();
    for set in &m.elements {
        if !matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3) {
            continue;
        }
        for e in 0..set.len() {
            let n = set.nodes_of(e);
            for k in 0..n.len() {
                let (a, b) = (n[k], n[(k + 1) % n.len()]);
                if a != b {
                    *count.entry([a.min(b), a.max(b)]).or_default() += 1;
                }
            }
        }
    }
    count
        .into_iter()
        .filter(|&(_, c)| c == 1)
        .flat_map(|(e, _)| e)
        .collect()
}

/// The positions of a face's 3 or 4 nodes (a triangle repeats its third).
pub(super) fn face_points(m: &Model, n: &[u32]) -> [V3; 4] {
    let x = |i: usize| m.nodes.x[n[i.min(n.len() - 1)] as usize];
    [x(0), x(1), x(2), x(3)]
}

/// A shell face of material `mat` for a type's own stiffness rule: its
/// area and longest diagonal (a triangle: its longest edge).
pub(super) fn shell_size(mat: &MaterialSpec, x: &[V3; 4], tri: bool, thick: f64) -> ElementSize {
    let d = |a: usize, b: usize| geo::norm(geo::sub(x[a], x[b]));
    let dmax = if tri {
        d(0, 1).max(d(1, 2)).max(d(2, 0))
    } else {
        d(0, 2).max(d(1, 3))
    };
    let area = geo::segment_area(x, tri);
    ElementSize {
        bulk: bulk(mat),
        shell: true,
        area,
        dmax,
        volume: 0.0,
        mass: mat.rho * area * thick,
    }
}

/// A solid of material `mat` and volume `volume` under a face of `area`.
pub(super) fn solid_size(mat: &MaterialSpec, area: f64, volume: f64) -> ElementSize {
    ElementSize {
        bulk: bulk(mat),
        shell: false,
        area,
        dmax: 0.0,
        volume,
        mass: mat.rho * volume,
    }
}

/// The reference starter's nodal contact stiffness (ASSTIFI, with SBULK3 and
/// CINMAS; `docs/notes/type24_type25_research.md` §8.1), the secondary node
/// stiffness of TYPE24/25 with Istf > 1, before Stfac, summed over a node's
/// elements: K_s = B̄·(2·V_n)^(1/3) + Σ(E·t)/n_shells, where V_n is the
/// node's share of its solids' volumes (V/8 of a brick, V/4 of a
/// tetrahedron) and B̄ the bulk modulus weighted by those shares; a node on
/// both solids and shells gets the sum, a node on neither 0.
#[derive(Clone, Copy, Default)]
pub(super) struct AssembledStiffness {
    volume: f64,
    bulk_volume: f64,
    et: f64,
    shells: f64,
}

impl AssembledStiffness {
    /// One solid's share: its volume over its corners, with its bulk modulus.
    pub(super) fn add_solid(&mut self, bulk: f64, share: f64) {
        self.volume += share;
        self.bulk_volume += bulk * share;
    }

    /// One shell's E·t.
    pub(super) fn add_shell(&mut self, et: f64) {
        self.et += et;
        self.shells += 1.0;
    }

    pub(super) fn stiffness(&self) -> f64 {
        let solid = if self.volume > 0.0 {
            self.bulk_volume / self.volume * (2.0 * self.volume).cbrt()
        } else {
            0.0
        };
        let shell = if self.shells > 0.0 {
            self.et / self.shells
        } else {
            0.0
        };
        solid + shell
    }
}
