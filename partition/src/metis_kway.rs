//! The call to METIS k-way (`METIS_PartGraphKway`) on the dual graph.

use crate::{DualGraph, Options, PartitionError};
use metis::option::{Seed, UFactor};
use metis::Idx;
use std::sync::Mutex;

/// METIS (through GKlib) keeps its random generator in process-global state
/// that is re-seeded at the start of each call. Two concurrent calls would
/// race on it (a data race in C, and non-deterministic partitions), so all
/// calls from this crate are serialised.
static METIS_LOCK: Mutex<()> = Mutex::new(());

fn idx(value: usize, what: &str) -> Result<Idx, PartitionError> {
    Idx::try_from(value)
        .map_err(|_| PartitionError::TooLarge(format!("{what} ({value}) exceeds METIS's index")))
}

/// Partitions `graph` into `opts.nparts` (≥ 2) parts with vertex weights
/// `weights` (validated: one per vertex, ≥ 0, sum fits `Idx`). Returns the
/// rank of every element.
pub(crate) fn part_kway(
    graph: &DualGraph,
    weights: &[i32],
    opts: &Options,
) -> Result<Vec<u32>, PartitionError> {
    let n = graph.n_vertices();
    idx(n, "number of elements")?;
    idx(graph.adjncy().len(), "dual graph size")?;
    let nparts = idx(opts.nparts, "number of parts")?;
    let xadj: Vec<Idx> = graph.xadj().iter().map(|&x| x as Idx).collect();
    let adjncy: Vec<Idx> = graph.adjncy().iter().map(|&a| a as Idx).collect();
    let vwgt: Vec<Idx> = weights.iter().map(|&w| Idx::from(w)).collect();
    let mut part: Vec<Idx> = vec![0; n];

    let metis_graph = metis::Graph::new(1, nparts, &xadj, &adjncy)
        .map_err(|e| PartitionError::Metis(e.to_string()))?
        .set_vwgt(&vwgt)
        .set_option(Seed(Idx::from(opts.seed)))
        .set_option(UFactor(Idx::from(opts.ufactor)));
    let result = {
        let _guard = METIS_LOCK
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        metis_graph.part_kway(&mut part)
    };
    result.map_err(|e| PartitionError::Metis(e.to_string()))?;

    part.iter()
        .map(|&p| match u32::try_from(p) {
            Ok(r) if (r as usize) < opts.nparts => Ok(r),
            _ => Err(PartitionError::Metis(format!(
                "returned rank {p} outside 0..{}",
                opts.nparts
            ))),
        })
        .collect()
}
