//! Partition quality: what each rank holds and what crosses rank boundaries.

use crate::balance::imbalance;
use crate::{Adjacency, DualGraph, Mesh, Partition, PartitionError};
use serde::{Deserialize, Serialize};

/// What one rank holds.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct RankReport {
    /// Elements on this rank.
    pub elements: usize,
    /// Distinct nodes touched by this rank's elements.
    pub nodes: usize,
    /// Of those, nodes also touched by at least one other rank (a node shared
    /// by ranks a and b counts on both).
    pub shared_nodes: usize,
    /// Sum of this rank's element weights.
    pub weight: i64,
}

/// Partition quality.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Report {
    pub per_rank: Vec<RankReport>,
    /// Dual-graph edges whose two elements are on different ranks.
    pub edge_cut: usize,
    /// max rank weight / mean rank weight − 1.
    pub imbalance: f64,
}

/// Quality of `partition`, with the edge cut measured on the shared-node dual
/// graph (the one that governs halo exchange). See [`report_with`].
pub fn report(
    mesh: &Mesh,
    weights: &[i32],
    partition: &Partition,
) -> Result<Report, PartitionError> {
    report_with(mesh, weights, partition, Adjacency::SharedNode)
}

/// Quality of `partition`, with the edge cut measured on the dual graph of
/// `adjacency`.
pub fn report_with(
    mesh: &Mesh,
    weights: &[i32],
    partition: &Partition,
    adjacency: Adjacency,
) -> Result<Report, PartitionError> {
    let graph = DualGraph::build(mesh, adjacency)?;
    let n_elems = mesh.n_elems();
    let nparts = partition.nparts;
    let part = &partition.part;
    if weights.len() != n_elems {
        return Err(PartitionError::WeightCount {
            expected: n_elems,
            got: weights.len(),
        });
    }
    if nparts == 0 {
        return Err(PartitionError::ZeroParts);
    }
    if part.len() != n_elems {
        return Err(PartitionError::PartitionMismatch(format!(
            "{} ranks given for {n_elems} elements",
            part.len()
        )));
    }
    if let Some((e, &p)) = part.iter().enumerate().find(|(_, &p)| p as usize >= nparts) {
        return Err(PartitionError::PartitionMismatch(format!(
            "element {e} is on rank {p}, expected a rank below {nparts}"
        )));
    }

    let mut per_rank = vec![
        RankReport {
            elements: 0,
            nodes: 0,
            shared_nodes: 0,
            weight: 0,
        };
        nparts
    ];
    // Elements grouped by rank (counting sort, element order kept).
    let mut start = vec![0usize; nparts + 1];
    for (e, &p) in part.iter().enumerate() {
        let r = &mut per_rank[p as usize];
        r.elements += 1;
        r.weight += i64::from(weights[e]);
        start[p as usize + 1] += 1;
    }
    for r in 0..nparts {
        start[r + 1] += start[r];
    }
    let mut by_rank = vec![0usize; n_elems];
    let mut fill = start.clone();
    for (e, &p) in part.iter().enumerate() {
        by_rank[fill[p as usize]] = e;
        fill[p as usize] += 1;
    }

    // Pass 1: distinct nodes per rank, and how many ranks touch each node.
    const NONE: usize = usize::MAX;
    let mut stamp = vec![NONE; mesh.n_nodes];
    let mut ranks_on_node = vec![0u32; mesh.n_nodes];
    for (r, rep) in per_rank.iter_mut().enumerate() {
        for &e in &by_rank[start[r]..start[r + 1]] {
            for &n in mesh.nodes(e) {
                let n = n as usize;
                if stamp[n] != r {
                    stamp[n] = r;
                    rep.nodes += 1;
                    ranks_on_node[n] += 1;
                }
            }
        }
    }
    // Pass 2: the shared ones.
    stamp.fill(NONE);
    for (r, rep) in per_rank.iter_mut().enumerate() {
        for &e in &by_rank[start[r]..start[r + 1]] {
            for &n in mesh.nodes(e) {
                let n = n as usize;
                if stamp[n] != r {
                    stamp[n] = r;
                    if ranks_on_node[n] > 1 {
                        rep.shared_nodes += 1;
                    }
                }
            }
        }
    }

    let edge_cut = (0..n_elems)
        .map(|e| {
            graph
                .neighbours(e)
                .iter()
                .filter(|&&f| (f as usize) > e && part[f as usize] != part[e])
                .count()
        })
        .sum();
    let rank_weights: Vec<i64> = per_rank.iter().map(|r| r.weight).collect();
    Ok(Report {
        per_rank,
        edge_cut,
        imbalance: imbalance(&rank_weights),
    })
}
