//! Errors of the partitioner. Bad input is answered, never panicked on.

use std::fmt;

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PartitionError {
    /// The mesh has no elements.
    EmptyMesh,
    /// The CSR arrays are inconsistent (what is wrong is in the message).
    InvalidMesh(String),
    /// An element has an empty node list.
    ElementWithoutNodes { element: usize },
    /// An element refers to a node index outside `0..n_nodes`.
    NodeOutOfRange {
        element: usize,
        node: u32,
        n_nodes: usize,
    },
    /// `nparts` is 0.
    ZeroParts,
    /// More parts than elements: some rank would be empty.
    TooManyParts { nparts: usize, n_elems: usize },
    /// The weight array does not have one entry per element.
    WeightCount { expected: usize, got: usize },
    /// A weight is negative.
    NegativeWeight { element: usize, weight: i32 },
    /// All weights are zero: there is nothing to balance.
    ZeroTotalWeight,
    /// An element index (e.g. in the contact list) is outside `0..n_elems`.
    ElementOutOfRange { element: usize, n_elems: usize },
    /// An option is out of its range.
    InvalidOption(String),
    /// A size does not fit METIS's index type.
    TooLarge(String),
    /// A partition does not match the mesh (length, rank numbers).
    PartitionMismatch(String),
    /// METIS itself reported an error.
    Metis(String),
}

impl fmt::Display for PartitionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use PartitionError::*;
        match self {
            EmptyMesh => write!(f, "cannot partition an empty mesh (no elements)"),
            InvalidMesh(why) => write!(f, "invalid element connectivity: {why}"),
            ElementWithoutNodes { element } => {
                write!(f, "element {element} has no nodes")
            }
            NodeOutOfRange {
                element,
                node,
                n_nodes,
            } => write!(
                f,
                "element {element} refers to node {node}, expected a node index below {n_nodes}"
            ),
            ZeroParts => write!(f, "number of parts must be at least 1"),
            TooManyParts { nparts, n_elems } => write!(
                f,
                "cannot split {n_elems} elements into {nparts} parts: \
                 expected at most one part per element"
            ),
            WeightCount { expected, got } => {
                write!(f, "expected one weight per element ({expected}), got {got}")
            }
            NegativeWeight { element, weight } => write!(
                f,
                "element {element} has weight {weight}, expected a weight ≥ 0"
            ),
            ZeroTotalWeight => write!(f, "all element weights are zero"),
            ElementOutOfRange { element, n_elems } => write!(
                f,
                "element index {element} out of range, expected an index below {n_elems}"
            ),
            InvalidOption(why) => write!(f, "invalid partition option: {why}"),
            TooLarge(why) => write!(f, "mesh too large for METIS: {why}"),
            PartitionMismatch(why) => write!(f, "partition does not match the mesh: {why}"),
            Metis(why) => write!(f, "METIS failed: {why}"),
        }
    }
}

impl std::error::Error for PartitionError {}
