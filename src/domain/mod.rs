//! One rank's share of the model. `split` is pure (no MPI): rank 0 calls it
//! and `parallel::scatter` sends each rank its Subdomain.
//!
//! A node lives on every rank that has an element touching it. Local node
//! numbering follows global order, so per-rank loops keep the global order.

use crate::model::ElementKind;
use crate::model::{Model, NO_NODE};
use crashsim_partition as part;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Elements of one kind held by a rank.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct LocalElements {
    pub kind: ElementKind,
    /// Index of each element in the model's set of this kind (global order).
    pub global: Vec<u32>,
    pub part: Vec<u32>,
    /// Local node indices, `kind.nodes()` per element (`NO_NODE` = absent).
    pub nodes: Vec<u32>,
    pub thick: Vec<f64>,
}

/// Nodes this rank shares with one neighbour rank (local indices, global order).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SharedNodes {
    pub rank: u32,
    pub nodes: Vec<u32>,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Subdomain {
    pub rank: u32,
    pub nranks: u32,
    /// Global (dense model) index of each local node, ascending.
    pub node_global: Vec<u32>,
    pub x: Vec<[f64; 3]>,
    pub mass: Vec<f64>,
    /// Rotational inertia of shell nodes (0 for others).
    pub inertia: Vec<f64>,
    pub elements: Vec<LocalElements>,
    /// Neighbour ranks in ascending order with the nodes shared with each.
    pub shared: Vec<SharedNodes>,
}

impl Subdomain {
    /// Whether this rank owns local node `l` (the lowest rank holding it does):
    /// sums over nodes count each node once, on its owner.
    pub fn owns(&self, l: u32) -> bool {
        !self
            .shared
            .iter()
            .any(|s| s.rank < self.rank && s.nodes.binary_search(&l).is_ok())
    }

    pub fn n_elements(&self) -> usize {
        self.elements.iter().map(|e| e.global.len()).sum()
    }
    /// Local nodes that at least one other rank also holds.
    pub fn n_shared_nodes(&self) -> usize {
        let mut all: Vec<u32> = self
            .shared
            .iter()
            .flat_map(|s| s.nodes.iter().copied())
            .collect();
        all.sort_unstable();
        all.dedup();
        all.len()
    }
}

/// Element → node connectivity of the whole model, kinds in `ElementKind::ALL`
/// order, for the partitioner (absent optional nodes left out).
pub fn mesh_csr(model: &Model) -> (Vec<usize>, Vec<u32>) {
    let mut ptr = vec![0usize];
    let mut nodes = Vec::new();
    for set in &model.elements {
        for e in 0..set.len() {
            nodes.extend(set.nodes_of(e).iter().copied().filter(|&n| n != NO_NODE));
            ptr.push(nodes.len());
        }
    }
    (ptr, nodes)
}

/// Element costs for the partitioner, with extra weight on elements that carry
/// contact segments (their faces are an interface's main or secondary
/// segments) or contact edges (an edge-to-edge interface's edges: the shell
/// that holds the edge, whose rank computes the edge's pairs).
pub fn element_weights(model: &Model) -> Result<Vec<i32>, part::PartitionError> {
    let mut elems = Vec::with_capacity(model.n_elements());
    let mut face_owner: HashMap<[u32; 4], usize> = HashMap::new();
    let mut edge_owner: HashMap<[u32; 2], usize> = HashMap::new();
    let mut offset = 0;
    for set in &model.elements {
        let k = match set.kind {
            ElementKind::Shell4 => part::ElementKind::Shell4,
            ElementKind::Shell3 => part::ElementKind::Shell3,
            ElementKind::Brick8 => part::ElementKind::Brick8,
            ElementKind::Tetra4 => part::ElementKind::Tetra4,
            ElementKind::Spring => part::ElementKind::Spring,
            ElementKind::Truss => part::ElementKind::Truss,
            ElementKind::Beam => part::ElementKind::Beam,
        };
        for e in 0..set.len() {
            let p = &model.parts[set.part[e] as usize];
            let npt = p
                .prop
                .and_then(|i| {
                    model.properties[i as usize]
                        .shell
                        .as_ref()
                        .map(|s| s.n.max(1) as u32)
                })
                .unwrap_or(1);
            elems.push((k, npt));
            if matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3) {
                let n = set.nodes_of(e);
                let mut key = [n[0], n[1], n[2], *n.get(3).unwrap_or(&n[2])];
                key.sort_unstable();
                face_owner.entry(key).or_insert(offset + e);
                for k in 0..n.len() {
                    let (a, b) = (n[k], n[(k + 1) % n.len()]);
                    edge_owner.entry([a.min(b), a.max(b)]).or_insert(offset + e);
                }
            }
        }
        offset += set.len();
    }
    let mut with_segments = Vec::new();
    for i in &model.interfaces {
        for s in i.main_segments.iter().chain(&i.secondary_segments) {
            let mut key = *s;
            key.sort_unstable();
            if let Some(&e) = face_owner.get(&key) {
                with_segments.push(e);
            }
        }
        for ed in i.main_edges.iter().chain(&i.secondary_edges) {
            if let Some(&e) = edge_owner.get(&[ed[0].min(ed[1]), ed[0].max(ed[1])]) {
                with_segments.push(e);
            }
        }
    }
    with_segments.sort_unstable();
    with_segments.dedup();
    part::element_weights(&elems, &with_segments, part::DEFAULT_CONTACT_EXTRA)
}

/// Partitions the model's elements over `nranks` (METIS k-way on the
/// shared-node dual graph, fixed seed: the same deck and `nranks` give the
/// same map). Returns the element → rank map (kinds in `ElementKind::ALL`
/// order) and its quality report.
pub fn partition(
    model: &Model,
    nranks: usize,
) -> Result<(part::Partition, part::Report), part::PartitionError> {
    let (ptr, nodes) = mesh_csr(model);
    let mesh = part::Mesh {
        n_nodes: model.nodes.len(),
        elem_ptr: &ptr,
        elem_nodes: &nodes,
    };
    if mesh.n_elems() < nranks {
        return Ok(fewer_elements_than_ranks(&mesh, model, nranks)?);
    }
    let weights = element_weights(model)?;
    let p = part::partition(&mesh, &weights, &part::Options::new(nranks))?;
    let r = part::report(&mesh, &weights, &p)?;
    Ok((p, r))
}

/// A model with fewer elements than ranks (one spring on 2 ranks, rigid
/// bodies and no element at all): element e on rank e, the other ranks
/// empty, as the reference engine runs such decks on any number of
/// domains. Nodes no element touches live on rank 0 (`split`).
fn fewer_elements_than_ranks(
    mesh: &part::Mesh,
    model: &Model,
    nranks: usize,
) -> Result<(part::Partition, part::Report), part::PartitionError> {
    let n = mesh.n_elems();
    let p = part::Partition {
        nparts: nranks,
        part: (0..n as u32).collect(),
    };
    if n > 0 {
        let r = part::report(mesh, &element_weights(model)?, &p)?;
        return Ok((p, r));
    }
    let empty = part::RankReport {
        elements: 0,
        nodes: 0,
        shared_nodes: 0,
        weight: 0,
    };
    let r = part::Report {
        per_rank: vec![empty; nranks],
        edge_cut: 0,
        imbalance: 0.0,
    };
    Ok((p, r))
}

/// Splits the model into one Subdomain per rank following `owner` (element → rank).
pub fn split(model: &Model, owner: &[u32], nranks: usize) -> Vec<Subdomain> {
    // Which ranks touch each node.
    let mut node_ranks: Vec<Vec<u32>> = vec![Vec::new(); model.nodes.len()];
    let mut offset = 0;
    for set in &model.elements {
        for e in 0..set.len() {
            let r = owner[offset + e];
            for &n in set.nodes_of(e) {
                if n != NO_NODE && !node_ranks[n as usize].contains(&r) {
                    node_ranks[n as usize].push(r);
                }
            }
        }
        offset += set.len();
    }
    // Nodes no element touches (a rigid body's main node, a free mass) live on rank 0.
    for r in &mut node_ranks {
        if r.is_empty() {
            r.push(0);
        }
        r.sort_unstable();
    }
    (0..nranks as u32)
        .map(|rank| {
            let node_global: Vec<u32> = (0..model.nodes.len() as u32)
                .filter(|&n| node_ranks[n as usize].contains(&rank))
                .collect();
            let mut local = HashMap::with_capacity(node_global.len());
            for (l, &g) in node_global.iter().enumerate() {
                local.insert(g, l as u32);
            }
            let mut elements = Vec::new();
            let mut offset = 0;
            for (k, set) in model.elements.iter().enumerate() {
                let mut le = LocalElements {
                    kind: ElementKind::ALL[k],
                    global: Vec::new(),
                    part: Vec::new(),
                    nodes: Vec::new(),
                    thick: Vec::new(),
                };
                for e in 0..set.len() {
                    if owner[offset + e] != rank {
                        continue;
                    }
                    le.global.push(e as u32);
                    le.part.push(set.part[e]);
                    le.thick.push(set.thick[e]);
                    le.nodes.extend(set.nodes_of(e).iter().map(|&n| {
                        if n == NO_NODE {
                            NO_NODE
                        } else {
                            local[&n]
                        }
                    }));
                }
                offset += set.len();
                elements.push(le);
            }
            let mut neighbours: Vec<u32> = node_global
                .iter()
                .flat_map(|&g| node_ranks[g as usize].iter().copied())
                .filter(|&r| r != rank)
                .collect();
            neighbours.sort_unstable();
            neighbours.dedup();
            let shared = neighbours
                .into_iter()
                .map(|nb| SharedNodes {
                    rank: nb,
                    nodes: node_global
                        .iter()
                        .enumerate()
                        .filter(|(_, &g)| node_ranks[g as usize].contains(&nb))
                        .map(|(l, _)| l as u32)
                        .collect(),
                })
                .collect();
            Subdomain {
                rank,
                nranks: nranks as u32,
                x: node_global
                    .iter()
                    .map(|&g| model.nodes.x[g as usize])
                    .collect(),
                mass: node_global
                    .iter()
                    .map(|&g| model.nodal_mass[g as usize])
                    .collect(),
                inertia: node_global
                    .iter()
                    .map(|&g| model.nodal_inertia[g as usize])
                    .collect(),
                node_global,
                elements,
                shared,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elements_under_contact_edges_weigh_more_for_the_partitioner() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("decks/edge_cross/edge_cross_0000.rad");
        let mut m = crate::input::load(&path, &Default::default()).expect("deck");
        let with = element_weights(&m).unwrap();
        for i in m.interfaces.iter_mut() {
            i.secondary_edges.clear();
            i.main_edges.clear();
        }
        let without = element_weights(&m).unwrap();
        // Every shell of both plates holds an edge of the TYPE11 (A's free
        // edges, B's edges).
        assert_eq!(with.len(), 6);
        for (w, wo) in with.iter().zip(&without) {
            assert_eq!(w - wo, part::DEFAULT_CONTACT_EXTRA);
        }
    }
}
