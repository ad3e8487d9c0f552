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
/// stiffness of TYPE25 with Istf > 1, before Stfac:
/// K_s = B̄·(2·V_n)^(1/3) + Σ(E·t)/n_shells, where V_n is the node's share of
/// its solids' volumes (V/8 of a brick, V/4 of a tetrahedron) and B̄ the
/// bulk modulus weighted by those shares; a node on both solids and shells
/// gets the sum, a node on neither 0.
pub(super) fn assembled_node_stiffness(m: &Model, nodes: &[u32]) -> HashMap<u32, f64> {
    // Per node: (Σ V share, Σ B·V share, Σ E·t, shells).
    let mut acc: HashMap<u32, [f64; 4]> = nodes.iter().map(|&n| (n, [0.0; 4])).collect();
    for (ki, set) in m.elements.iter().enumerate() {
        let shell = matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3);
        let corners = match set.kind {
            ElementKind::Brick8 => 8.0,
            ElementKind::Tetra4 => 4.0,
            _ if shell => 0.0,
            _ => continue,
        };
        for e in 0..set.len() {
            let n = set.nodes_of(e);
            if !n.iter().any(|q| acc.contains_key(q)) {
                continue;
            }
            let part = &m.parts[set.part[e] as usize];
            let Some(mat) = part.mat.map(|i| &m.materials[i as usize]) else {
                continue;
            };
            let add = if shell {
                [0.0, 0.0, mat.e * set.thick[e], 1.0]
            } else {
                let share = element_volume(m, ki, e).max(0.0) / corners;
                [share, bulk(mat) * share, 0.0, 0.0]
            };
            for (i, q) in n.iter().enumerate() {
                // A degenerate element repeats a node: its share counts once per corner.
                if shell && n[..i].contains(q) {
                    continue;
                }
                if let Some(a) = acc.get_mut(q) {
                    for j in 0..4 {
                        a[j] += add[j];
                    }
                }
            }
        }
    }
    acc.into_iter()
        .map(|(n, [v, bv, et, ns])| {
            let solid = if v > 0.0 {
                bv / v * (2.0 * v).cbrt()
            } else {
                0.0
            };
            let shell = if ns > 0.0 { et / ns } else { 0.0 };
            (n, solid + shell)
        })
        .collect()
}
