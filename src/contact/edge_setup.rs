//! Set-up of an edge-to-edge pass (/INTER/TYPE11): each edge's stiffness,
//! gap and size from the element it lies on, and the default minimum gap.
//!
//! Sources: /INTER/TYPE11 reference card (Istf, Igap, Gapmin, %mesh_size)
//! and the Theory Manual §8.4.5.2 (the gap of each edge defines a cylinder
//! around it). What the card leaves to the Starter (the edge stiffness and
//! the default Gapmin) follows the reference Starter, as gathered in
//! docs/notes/type11_type19_research.md §5–6:
//! - an edge on shells takes the thickest of them (on equal thickness the
//!   stiffer): k = E·t, gap t/2; an edge on solids only: k = B·V/L², gap 0
//!   (the shell wins when both hold it). Stfac multiplies k in the kernel.
//!   A type with its own rule (`InterfaceType::element_stiffness`: a
//!   keyword deck's LS-DYNA penalty) takes it from the element instead;
//! - Idel (card /INTER/TYPE11): an edge leaves when all (Idel 1) or any
//!   (Idel 2) of the elements holding it are deleted; -1, -2 remove main
//!   edges only;
//! - the default Gapmin is the mean over the two sides of
//!   min(l_min/2, DX), DX being the mean (Igap 0) or smallest (Igap ≠ 0)
//!   shell thickness of the side's edges, or l_min/10 when no edge lies on
//!   a shell.

use super::element_data::{
    bulk, element_volume, face_points, node_elements, shell_size, solid_size,
};
use super::geometry::{self as geo};
use super::interfaces::layout::{IdelRule, Pass};
use super::interfaces::{InterfaceType, PassSides};
use super::stiffness::ElementSize;
use crate::model::{distinct_nodes, ElementKind, Model};
use std::collections::HashMap;

/// What one edge takes from the element under it.
struct EdgeData {
    /// Stiffness without Stfac.
    k: f64,
    /// Half the shell thickness (0 on solids).
    gap: f64,
    /// The shell thickness, when the edge lies on a shell.
    thick: Option<f64>,
    len: f64,
    elem: (u8, u32),
}

/// The shell or solid an edge lies on (both its nodes are the element's):
/// the thickest shell (ties: the stiffer, then the first), else the first
/// solid.
fn edge_data(
    m: &Model,
    ne: &HashMap<u32, Vec<(u8, u32)>>,
    e: [u32; 2],
    own: &dyn Fn(&ElementSize) -> Option<f64>,
) -> Result<EdgeData, String> {
    let xa = m.nodes.x[e[0] as usize];
    let xb = m.nodes.x[e[1] as usize];
    let len = geo::norm(geo::sub(xb, xa));
    let mut best: Option<EdgeData> = None;
    for &(ki, el) in elements_holding(ne, e) {
        let set = &m.elements[ki as usize];
        let shell = matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3);
        let solid = matches!(set.kind, ElementKind::Brick8 | ElementKind::Tetra4);
        if !shell && !solid {
            continue;
        }
        let part = &m.parts[set.part[el as usize] as usize];
        let Some(mat) = part.mat.map(|i| &m.materials[i as usize]) else {
            continue;
        };
        let d = if shell {
            let t = set.thick[el as usize];
            let n = set.nodes_of(el as usize);
            let size = shell_size(mat, &face_points(m, n), n.len() == 3, t);
            EdgeData {
                k: own(&size).unwrap_or(mat.e * t),
                gap: 0.5 * t,
                thick: Some(t),
                len,
                elem: (ki, el),
            }
        } else {
            let v = element_volume(m, ki as usize, el as usize);
            let size = solid_size(mat, v.max(0.0).powf(2.0 / 3.0), v);
            let k = own(&size).unwrap_or(if len > 0.0 {
                bulk(mat) * v / (len * len)
            } else {
                0.0
            });
            EdgeData {
                k,
                gap: 0.0,
                thick: None,
                len,
                elem: (ki, el),
            }
        };
        let better = match &best {
            None => true,
            Some(b) => match (d.thick, b.thick) {
                (Some(t), Some(tb)) => t > tb || (t == tb && d.k > b.k),
                (Some(_), None) => true,
                _ => false,
            },
        };
        if better {
            best = Some(d);
        }
    }
    best.ok_or_else(|| {
        format!(
            "edge {} {} lies on no shell or solid element: its stiffness is undefined (each edge of a /LINE must be an edge of a shell or solid)",
            m.nodes.ids[e[0] as usize], m.nodes.ids[e[1] as usize]
        )
    })
}

/// The elements (of any kind) holding both nodes of edge `e`, from the
/// elements around each node.
fn elements_holding(
    ne: &HashMap<u32, Vec<(u8, u32)>>,
    e: [u32; 2],
) -> impl Iterator<Item = &(u8, u32)> {
    ne[&e[0]].iter().filter(move |el| ne[&e[1]].contains(el))
}

/// Idel: the elements of each edge (every element, of any kind, holding
/// both its nodes), CSR: (ptr, elements).
fn edge_elements(
    ne: &HashMap<u32, Vec<(u8, u32)>>,
    edges: &[[u32; 2]],
) -> (Vec<u32>, Vec<(u8, u32)>) {
    let mut ptr = vec![0u32];
    let mut out = Vec::new();
    for e in edges {
        out.extend(elements_holding(ne, *e));
        ptr.push(out.len() as u32);
    }
    (ptr, out)
}

/// The default Gapmin of one side (see the module's comment).
fn side_gap1(data: &[EdgeData], igap: i64) -> f64 {
    let l_min = data
        .iter()
        .map(|d| d.len)
        .filter(|&l| l > 0.0)
        .fold(f64::INFINITY, f64::min);
    let l_min = if l_min.is_finite() { l_min } else { 0.0 };
    let t: Vec<f64> = data.iter().filter_map(|d| d.thick).collect();
    if t.is_empty() {
        return 0.1 * l_min;
    }
    let dx = if igap == 0 || igap == 1000 {
        t.iter().sum::<f64>() / t.len() as f64
    } else {
        t.iter().copied().fold(f64::INFINITY, f64::min)
    };
    dx.min(0.5 * l_min)
}

/// The sizes an edge pass adds to its interface's (sorting margin, search
/// reach, default gap).
#[derive(Default)]
pub(super) struct EdgeSizes {
    /// Main edges: summed length, count, shortest (non-zero) length.
    pub l_sum: f64,
    pub n_edges: usize,
    pub l_min: f64,
    /// Largest half thickness of the secondary and of the main edges.
    pub gs_max: f64,
    pub gm_max: f64,
    /// The default Gapmin (see the module's comment).
    pub gapmin: f64,
}

/// One edge-to-edge pass: main edges in `segs` (second node repeated),
/// secondary edges in `sec_edges`, each with its stiffness (`seg_k`,
/// `sec_k`, Stfac not applied), half thickness (`seg_gap`, `sec_gap`) and
/// length (`seg_lmin`, `sec_lmin`: the size Igap = 3 scales).
pub(super) fn build_edge_pass(
    m: &Model,
    cnode: &dyn Fn(u32) -> u32,
    ty: &dyn InterfaceType,
    idel: i64,
    sides: &PassSides,
    kw: &str,
) -> Result<(Pass, EdgeSizes), String> {
    let igap = ty.igap();
    let nodes = distinct_nodes(
        sides
            .sec_edges
            .iter()
            .chain(sides.main_edges)
            .flatten()
            .copied(),
    );
    let ne = node_elements(m, &nodes);
    let data = |edges: &[[u32; 2]], main: bool| -> Result<Vec<EdgeData>, String> {
        let own = |size: &ElementSize| ty.element_stiffness(size, main);
        edges
            .iter()
            .map(|&e| edge_data(m, &ne, e, &own).map_err(|s| format!("{kw}: {s}")))
            .collect()
    };
    let main = data(sides.main_edges, true)?;
    let sec = data(sides.sec_edges, false)?;
    let mut sizes = EdgeSizes {
        l_min: f64::INFINITY,
        ..Default::default()
    };
    let mut pass = Pass {
        self_contact: sides.self_contact,
        ..Default::default()
    };
    for (e, d) in sides.main_edges.iter().zip(&main) {
        let c = [cnode(e[0]), cnode(e[1])];
        pass.segs.push([c[0], c[1], c[1], c[1]]);
        pass.seg_k.push(d.k);
        pass.seg_gap.push(d.gap);
        pass.seg_lmin.push(d.len);
        pass.seg_area.push(0.0);
        pass.seg_elem.push(d.elem);
        pass.max_diag = pass.max_diag.max(d.len);
        sizes.l_sum += d.len;
        sizes.n_edges += 1;
        if d.len > 0.0 {
            sizes.l_min = sizes.l_min.min(d.len);
        }
        sizes.gm_max = sizes.gm_max.max(d.gap);
    }
    for (e, d) in sides.sec_edges.iter().zip(&sec) {
        pass.sec_edges.push([cnode(e[0]), cnode(e[1])]);
        pass.sec_k.push(d.k);
        pass.sec_gap.push(d.gap);
        pass.sec_lmin.push(d.len);
        sizes.gs_max = sizes.gs_max.max(d.gap);
    }
    sizes.gapmin = 0.5 * (side_gap1(&main, igap) + side_gap1(&sec, igap));
    if let Some(rule) = IdelRule::of(idel) {
        (pass.seg_elems_ptr, pass.seg_elems) = edge_elements(&ne, sides.main_edges);
        if rule.nodes {
            (pass.sec_elems_ptr, pass.sec_elems) = edge_elements(&ne, sides.sec_edges);
        }
    }
    Ok((pass, sizes))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shell_edge(t: f64, len: f64) -> EdgeData {
        EdgeData {
            k: 1.0,
            gap: 0.5 * t,
            thick: Some(t),
            len,
            elem: (0, 0),
        }
    }

    #[test]
    fn default_gapmin_of_a_side_is_the_thickness_or_half_the_shortest_edge() {
        let side = [shell_edge(0.002, 0.01), shell_edge(0.004, 0.02)];
        // Igap 0: mean thickness 3 mm, below half the shortest edge (5 mm).
        assert!((side_gap1(&side, 0) - 0.003).abs() < 1e-15);
        // Igap 1: the smallest thickness.
        assert!((side_gap1(&side, 1) - 0.002).abs() < 1e-15);
        // A thick shell on short edges: half the shortest edge.
        assert!((side_gap1(&[shell_edge(0.01, 0.004)], 0) - 0.002).abs() < 1e-15);
        // Solids only: a tenth of the shortest edge.
        let solid = EdgeData {
            k: 1.0,
            gap: 0.0,
            thick: None,
            len: 0.05,
            elem: (2, 0),
        };
        assert!((side_gap1(&[solid], 0) - 0.005).abs() < 1e-15);
    }
}
