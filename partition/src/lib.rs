//! Element partitioning for crashsim.
//!
//! Rank 0 turns the model into a plain element → node connectivity ([`Mesh`]),
//! a cost per element ([`element_weights`]) and asks [`partition`] for an
//! element → rank map. The map is computed by METIS k-way on the element
//! *dual graph* (one vertex per element, an edge between elements that touch,
//! see [`Adjacency`]), followed by a small deterministic balancing pass.
//! [`report`] measures the result (elements, nodes, shared nodes and weight
//! per rank, edge cut, imbalance) for the listing and the `partition` command.
//!
//! The crate is pure: no MPI, no deck, no global state. For a given mesh,
//! weights and [`Options`] (the seed is fixed), the result is the same on
//! every run.

mod balance;
mod dual_graph;
mod error;
mod metis_kway;
mod report;
mod weights;

pub use dual_graph::DualGraph;
pub use error::PartitionError;
pub use report::{report, report_with, RankReport, Report};
pub use weights::{
    add_contact_weight, element_cost, element_weights, ElementKind, DEFAULT_CONTACT_EXTRA,
};

use serde::{Deserialize, Serialize};

/// Element → node connectivity in compressed rows (CSR).
///
/// Element `e` has the nodes `elem_nodes[elem_ptr[e]..elem_ptr[e + 1]]`, dense
/// node indices in `0..n_nodes`. `elem_ptr` has one entry more than there are
/// elements and starts at 0. A node may repeat inside one element (a Radioss
/// triangle written as a quadrangle with `n3 == n4`); it counts once.
#[derive(Debug, Clone, Copy)]
pub struct Mesh<'a> {
    pub n_nodes: usize,
    pub elem_ptr: &'a [usize],
    pub elem_nodes: &'a [u32],
}

impl Mesh<'_> {
    /// Number of elements (`elem_ptr.len() - 1`, or 0 for an empty `elem_ptr`).
    pub fn n_elems(&self) -> usize {
        self.elem_ptr.len().saturating_sub(1)
    }

    /// Checks the CSR structure: `elem_ptr` starts at 0, never decreases and
    /// ends at `elem_nodes.len()`; every element has a node; every node index
    /// is below `n_nodes`. An empty mesh is an error.
    pub fn validate(&self) -> Result<(), PartitionError> {
        let n_elems = self.n_elems();
        if n_elems == 0 {
            return Err(PartitionError::EmptyMesh);
        }
        if self.elem_ptr[0] != 0 {
            return Err(PartitionError::InvalidMesh(format!(
                "elem_ptr[0] is {}, expected 0",
                self.elem_ptr[0]
            )));
        }
        if self.elem_ptr[n_elems] != self.elem_nodes.len() {
            return Err(PartitionError::InvalidMesh(format!(
                "elem_ptr ends at {} but elem_nodes has {} entries",
                self.elem_ptr[n_elems],
                self.elem_nodes.len()
            )));
        }
        for e in 0..n_elems {
            let (a, b) = (self.elem_ptr[e], self.elem_ptr[e + 1]);
            if b < a {
                return Err(PartitionError::InvalidMesh(format!(
                    "elem_ptr decreases at element {e} ({a} then {b})"
                )));
            }
            if b == a {
                return Err(PartitionError::ElementWithoutNodes { element: e });
            }
        }
        for e in 0..n_elems {
            for &n in self.nodes(e) {
                if n as usize >= self.n_nodes {
                    return Err(PartitionError::NodeOutOfRange {
                        element: e,
                        node: n,
                        n_nodes: self.n_nodes,
                    });
                }
            }
        }
        Ok(())
    }

    /// Nodes of element `e` (as stored, repeats included). Only call on a
    /// validated mesh with `e < n_elems()`.
    pub(crate) fn nodes(&self, e: usize) -> &[u32] {
        &self.elem_nodes[self.elem_ptr[e]..self.elem_ptr[e + 1]]
    }
}

/// Which elements are neighbours in the dual graph that METIS cuts.
///
/// The default is [`Adjacency::SharedNode`]: the explicit solver exchanges the
/// partial forces of every node that lies on more than one rank, so a cut
/// through elements that share only a corner costs communication just like a
/// cut through an edge. Cutting the shared-node graph is what minimises halo
/// traffic, and it is what a shell mesh (the bulk of a crash model) needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Adjacency {
    /// Two elements are neighbours when they share at least one node.
    #[default]
    SharedNode,
    /// Two elements are neighbours when they share a "face": at least
    /// `min(k(a), k(b))` distinct nodes, where `k` depends on the element's
    /// number of distinct nodes: 1 for 1-D elements (≤ 2 nodes: springs,
    /// trusses, beams — they connect through a node), 2 for 3 or 4 nodes
    /// (shells: an edge), 3 for 5 nodes or more (solids: a face). A tetra4
    /// has 4 nodes like a shell4, so tetra4 pairs sharing an edge are
    /// neighbours too (a superset of true face adjacency); use
    /// [`Adjacency::CommonNodes`]`(3)` for a pure tetra mesh.
    SharedFace,
    /// Two elements are neighbours when they share at least this many
    /// distinct nodes (METIS's `ncommon`); an element with fewer distinct
    /// nodes than that needs all of its nodes shared. 0 is treated as 1.
    CommonNodes(u32),
}

/// Partitioning options.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Options {
    /// Number of ranks (parts), at least 1 and at most the number of elements.
    pub nparts: usize,
    /// Dual graph definition; default [`Adjacency::SharedNode`].
    pub adjacency: Adjacency,
    /// METIS random seed. Fixed so that a mesh and `nparts` always give the
    /// same partition. Default 42.
    pub seed: i32,
    /// METIS load imbalance tolerance in thousandths (30 = 3 %, METIS's own
    /// k-way default). At least 1.
    pub ufactor: i32,
    /// Largest accepted imbalance (max rank weight / mean rank weight − 1)
    /// after METIS; above it the balancing pass moves boundary elements from
    /// the heaviest rank to lighter neighbour ranks. Default 0.05.
    pub max_imbalance: f64,
}

impl Options {
    /// Default options for `nparts` ranks.
    pub fn new(nparts: usize) -> Self {
        Options {
            nparts,
            adjacency: Adjacency::default(),
            seed: 42,
            ufactor: 30,
            max_imbalance: 0.05,
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Options::new(1)
    }
}

/// Element → rank map.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Partition {
    pub nparts: usize,
    /// `part[e]` is the rank of element `e`, in `0..nparts`.
    pub part: Vec<u32>,
}

/// Partitions the elements of `mesh` into `opts.nparts` ranks.
///
/// `weights[e]` is the cost of element `e` (≥ 0, not all zero; see
/// [`element_weights`]). With one part everything goes to rank 0 and METIS is
/// not called. Otherwise METIS k-way partitions the dual graph
/// ([`Options::adjacency`]) with the fixed seed, every rank is given at least
/// one element, and if the weight imbalance exceeds
/// [`Options::max_imbalance`], boundary elements are moved from the heaviest
/// rank to lighter neighbour ranks (deterministic, by element index) until it
/// does not or no move helps.
pub fn partition(
    mesh: &Mesh,
    weights: &[i32],
    opts: &Options,
) -> Result<Partition, PartitionError> {
    mesh.validate()?;
    let n_elems = mesh.n_elems();
    check_weights(weights, n_elems)?;
    check_options(opts, n_elems)?;

    if opts.nparts == 1 {
        return Ok(Partition {
            nparts: 1,
            part: vec![0; n_elems],
        });
    }

    let graph = DualGraph::build(mesh, opts.adjacency)?;
    let mut part = metis_kway::part_kway(&graph, weights, opts)?;
    balance::fill_empty_ranks(&graph, weights, opts.nparts, &mut part);
    balance::refine(&graph, weights, opts.nparts, opts.max_imbalance, &mut part);
    Ok(Partition {
        nparts: opts.nparts,
        part,
    })
}

fn check_weights(weights: &[i32], n_elems: usize) -> Result<(), PartitionError> {
    if weights.len() != n_elems {
        return Err(PartitionError::WeightCount {
            expected: n_elems,
            got: weights.len(),
        });
    }
    let mut total: i64 = 0;
    for (e, &w) in weights.iter().enumerate() {
        if w < 0 {
            return Err(PartitionError::NegativeWeight {
                element: e,
                weight: w,
            });
        }
        total += i64::from(w);
    }
    if total == 0 {
        return Err(PartitionError::ZeroTotalWeight);
    }
    // METIS sums vertex weights in its index type (32-bit in the vendored build).
    if total > i64::from(i32::MAX) {
        return Err(PartitionError::TooLarge(format!(
            "total element weight {total} exceeds {}",
            i32::MAX
        )));
    }
    Ok(())
}

fn check_options(opts: &Options, n_elems: usize) -> Result<(), PartitionError> {
    if opts.nparts == 0 {
        return Err(PartitionError::ZeroParts);
    }
    if opts.nparts > n_elems {
        return Err(PartitionError::TooManyParts {
            nparts: opts.nparts,
            n_elems,
        });
    }
    if u32::try_from(opts.nparts).is_err() {
        return Err(PartitionError::TooLarge(format!(
            "{} parts do not fit a 32-bit rank number",
            opts.nparts
        )));
    }
    if opts.ufactor < 1 {
        return Err(PartitionError::InvalidOption(format!(
            "ufactor must be at least 1, got {}",
            opts.ufactor
        )));
    }
    if !(opts.max_imbalance.is_finite() && opts.max_imbalance >= 0.0) {
        return Err(PartitionError::InvalidOption(format!(
            "max_imbalance must be a finite number ≥ 0, got {}",
            opts.max_imbalance
        )));
    }
    Ok(())
}

#[cfg(test)]
pub(crate) mod test_mesh {
    /// Structured `nx` × `ny` grid of quadrangles, element `i + nx * j`, node
    /// `i + (nx + 1) * j`. Returns (n_nodes, elem_ptr, elem_nodes).
    pub fn quad_grid(nx: usize, ny: usize) -> (usize, Vec<usize>, Vec<u32>) {
        let mut ptr = vec![0];
        let mut nodes = Vec::new();
        let node = |i: usize, j: usize| (i + (nx + 1) * j) as u32;
        for j in 0..ny {
            for i in 0..nx {
                nodes.extend([
                    node(i, j),
                    node(i + 1, j),
                    node(i + 1, j + 1),
                    node(i, j + 1),
                ]);
                ptr.push(nodes.len());
            }
        }
        ((nx + 1) * (ny + 1), ptr, nodes)
    }
}

#[cfg(test)]
mod tests;
