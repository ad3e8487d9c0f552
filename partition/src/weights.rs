//! Element weights: the relative cost of one explicit cycle for an element.
//!
//! The numbers are *estimates* from operation counts of an explicit element
//! update (strain rate, constitutive update at each integration point,
//! internal forces, hourglass control, time step) relative to each other.
//! They are to be calibrated against element-loop benchmarks of the solver;
//! only their ratios matter to the partitioner.

use crate::PartitionError;
use serde::{Deserialize, Serialize};

/// Element families the partitioner distinguishes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ElementKind {
    Shell4,
    Shell3,
    Brick8,
    Tetra4,
    Spring,
    Truss,
    Beam,
}

/// Default extra weight of an element carrying one contact segment: the
/// segment's share of bucket sort, candidate projection and penalty forces,
/// about a third of a 5-point shell4 update. An estimate, to be calibrated.
pub const DEFAULT_CONTACT_EXTRA: i32 = 6;

/// Largest integration-point count taken into account (keeps weights far
/// from integer overflow on absurd input).
const MAX_POINTS: u32 = 1000;

/// Estimated relative cost of one cycle of an element of `kind` with
/// `integration_points` points (0 is read as 1):
///
/// | kind   | cost                  | with the usual points          |
/// |--------|-----------------------|--------------------------------|
/// | Shell4 | 10 + 2 N (N through the thickness) | N = 5: 20         |
/// | Shell3 | round(0.7 × shell4)   | N = 5: 14                      |
/// | Brick8 | 12 + 4 N              | N = 1 (reduced): 16; N = 8: 44 |
/// | Tetra4 | 6 + 2 N               | N = 1: 8                       |
/// | Spring | 2                     |                                |
/// | Truss  | 3                     |                                |
/// | Beam   | 3 + N                 | N = 1: 4                       |
///
/// The costs are estimates to be calibrated by benchmarks.
pub fn element_cost(kind: ElementKind, integration_points: u32) -> i32 {
    // MAX_POINTS bounds every expression far below i32::MAX.
    let n = integration_points.clamp(1, MAX_POINTS) as i32;
    let shell4 = 10 + 2 * n;
    match kind {
        ElementKind::Shell4 => shell4,
        ElementKind::Shell3 => (7 * shell4 + 5) / 10,
        ElementKind::Brick8 => 12 + 4 * n,
        ElementKind::Tetra4 => 6 + 2 * n,
        ElementKind::Spring => 2,
        ElementKind::Truss => 3,
        ElementKind::Beam => 3 + n,
    }
}

/// Adds `extra` to the weight of every element listed in
/// `elems_with_segments`. An element listed k times (it carries k contact
/// segments, e.g. several faces of a brick) gets k × `extra`. Errors (and
/// changes nothing) if an index is out of range, `extra` is negative or a
/// weight would overflow.
pub fn add_contact_weight(
    weights: &mut [i32],
    elems_with_segments: &[usize],
    extra: i32,
) -> Result<(), PartitionError> {
    if extra < 0 {
        return Err(PartitionError::InvalidOption(format!(
            "contact extra weight must be ≥ 0, got {extra}"
        )));
    }
    if let Some(&e) = elems_with_segments.iter().find(|&&e| e >= weights.len()) {
        return Err(PartitionError::ElementOutOfRange {
            element: e,
            n_elems: weights.len(),
        });
    }
    let mut added = weights.to_vec();
    for &e in elems_with_segments {
        added[e] = added[e]
            .checked_add(extra)
            .ok_or_else(|| PartitionError::TooLarge(format!("weight of element {e} overflows")))?;
    }
    weights.copy_from_slice(&added);
    Ok(())
}

/// Weights for a whole mesh: [`element_cost`] of each `(kind, integration
/// points)` in element order, plus [`add_contact_weight`] with
/// `contact_extra` (e.g. [`DEFAULT_CONTACT_EXTRA`]) for the elements that
/// carry contact segments.
pub fn element_weights(
    elements: &[(ElementKind, u32)],
    elems_with_segments: &[usize],
    contact_extra: i32,
) -> Result<Vec<i32>, PartitionError> {
    let mut w: Vec<i32> = elements
        .iter()
        .map(|&(kind, npts)| element_cost(kind, npts))
        .collect();
    add_contact_weight(&mut w, elems_with_segments, contact_extra)?;
    Ok(w)
}
