//! The element dual graph: one vertex per element, an edge between two
//! elements that are neighbours under an [`Adjacency`] rule.
//!
//! Built through node → element lists: for every element, walk the elements
//! on its nodes and count how many distinct nodes each of them shares. The
//! cost is the connectivity times the mean node valence, with no hashing.
//! Neighbour lists are sorted and free of duplicates and self loops, so the
//! graph (and therefore METIS's answer) depends only on the mesh.

use crate::{Adjacency, Mesh, PartitionError};

/// Symmetric element adjacency in CSR form.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DualGraph {
    xadj: Vec<usize>,
    adjncy: Vec<u32>,
}

impl DualGraph {
    /// Builds the dual graph of `mesh` under `adjacency` (validates the mesh).
    pub fn build(mesh: &Mesh, adjacency: Adjacency) -> Result<DualGraph, PartitionError> {
        mesh.validate()?;
        if u32::try_from(mesh.n_elems()).is_err() {
            return Err(PartitionError::TooLarge(format!(
                "{} elements do not fit a 32-bit index",
                mesh.n_elems()
            )));
        }
        Ok(Self::from_valid(mesh, adjacency))
    }

    /// Number of vertices (elements).
    pub fn n_vertices(&self) -> usize {
        self.xadj.len() - 1
    }

    /// Number of undirected edges.
    pub fn n_edges(&self) -> usize {
        self.adjncy.len() / 2
    }

    /// Sorted neighbours of element `e`.
    pub fn neighbours(&self, e: usize) -> &[u32] {
        &self.adjncy[self.xadj[e]..self.xadj[e + 1]]
    }

    /// CSR row pointer (`n_vertices() + 1` entries).
    pub fn xadj(&self) -> &[usize] {
        &self.xadj
    }

    /// CSR column indices.
    pub fn adjncy(&self) -> &[u32] {
        &self.adjncy
    }

    /// Builds the graph of a mesh that passed [`Mesh::validate`] and has
    /// fewer than 2^32 elements.
    pub(crate) fn from_valid(mesh: &Mesh, adjacency: Adjacency) -> DualGraph {
        let n_elems = mesh.n_elems();
        let n_nodes = mesh.n_nodes;
        const NONE: usize = usize::MAX;

        // Distinct nodes per element and node → element lists (each element
        // once per node, in increasing element order).
        let mut stamp = vec![NONE; n_nodes];
        let mut distinct = vec![0u32; n_elems];
        let mut n2e_ptr = vec![0usize; n_nodes + 1];
        for (e, k) in distinct.iter_mut().enumerate() {
            for &n in mesh.nodes(e) {
                let n = n as usize;
                if stamp[n] != e {
                    stamp[n] = e;
                    *k += 1;
                    n2e_ptr[n + 1] += 1;
                }
            }
        }
        for n in 0..n_nodes {
            n2e_ptr[n + 1] += n2e_ptr[n];
        }
        let mut fill = n2e_ptr.clone();
        let mut n2e = vec![0u32; n2e_ptr[n_nodes]];
        stamp.fill(NONE);
        for e in 0..n_elems {
            for &n in mesh.nodes(e) {
                let n = n as usize;
                if stamp[n] != e {
                    stamp[n] = e;
                    n2e[fill[n]] = e as u32;
                    fill[n] += 1;
                }
            }
        }

        // Per element: count shared distinct nodes with every element met.
        let mut mark = vec![NONE; n_elems];
        let mut shared = vec![0u32; n_elems];
        let mut touched: Vec<u32> = Vec::new();
        let mut xadj = Vec::with_capacity(n_elems + 1);
        xadj.push(0);
        let mut adjncy = Vec::new();
        stamp.fill(NONE);
        for e in 0..n_elems {
            touched.clear();
            for &n in mesh.nodes(e) {
                let n = n as usize;
                if stamp[n] == e {
                    continue;
                }
                stamp[n] = e;
                for &f in &n2e[n2e_ptr[n]..n2e_ptr[n + 1]] {
                    let fu = f as usize;
                    if fu == e {
                        continue;
                    }
                    if mark[fu] != e {
                        mark[fu] = e;
                        shared[fu] = 0;
                        touched.push(f);
                    }
                    shared[fu] += 1;
                }
            }
            touched.sort_unstable();
            for &f in &touched {
                let fu = f as usize;
                if shared[fu] >= threshold(adjacency, distinct[e], distinct[fu]) {
                    adjncy.push(f);
                }
            }
            xadj.push(adjncy.len());
        }
        DualGraph { xadj, adjncy }
    }
}

/// Minimum number of shared distinct nodes for two elements with `ka` and
/// `kb` distinct nodes to be neighbours (symmetric in `ka`, `kb`).
fn threshold(adjacency: Adjacency, ka: u32, kb: u32) -> u32 {
    match adjacency {
        Adjacency::SharedNode => 1,
        Adjacency::SharedFace => face_nodes(ka).min(face_nodes(kb)),
        Adjacency::CommonNodes(c) => c.max(1).min(ka).min(kb),
    }
}

/// Nodes of a "face" of an element with `k` distinct nodes: a node for 1-D
/// elements, an edge for shells (3–4 nodes), a face for solids (5+).
fn face_nodes(k: u32) -> u32 {
    match k {
        0..=2 => 1,
        3 | 4 => 2,
        _ => 3,
    }
}
