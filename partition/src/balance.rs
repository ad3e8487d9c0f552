//! Deterministic post-processing of METIS's answer: no empty rank, and a
//! weight imbalance within the requested tolerance where boundary moves can
//! achieve it. METIS meets its `ufactor` on large meshes; on small meshes
//! (a few hundred elements, coarse element weights) it can miss by several
//! percent, which this pass repairs.

use crate::DualGraph;

/// Safety bound on balancing sweeps; every move strictly lowers the sum of
/// squared rank weights, so the loop ends anyway.
const MAX_SWEEPS: usize = 10_000;

/// max rank weight / mean rank weight − 1 (0 for zero total weight).
pub(crate) fn imbalance(rank_weights: &[i64]) -> f64 {
    let total: i64 = rank_weights.iter().sum();
    let max = rank_weights.iter().copied().max().unwrap_or(0);
    if total <= 0 {
        return 0.0;
    }
    max as f64 / (total as f64 / rank_weights.len() as f64) - 1.0
}

fn rank_weights(weights: &[i32], nparts: usize, part: &[u32]) -> Vec<i64> {
    let mut w = vec![0i64; nparts];
    for (&p, &we) in part.iter().zip(weights) {
        w[p as usize] += i64::from(we);
    }
    w
}

fn rank_counts(nparts: usize, part: &[u32]) -> Vec<usize> {
    let mut c = vec![0usize; nparts];
    for &p in part {
        c[p as usize] += 1;
    }
    c
}

/// Gives every empty rank one element (possible since nparts ≤ elements):
/// taken from the heaviest rank that has at least two elements, preferring
/// its lowest-index element on a rank boundary, else its lowest-index one.
pub(crate) fn fill_empty_ranks(
    graph: &DualGraph,
    weights: &[i32],
    nparts: usize,
    part: &mut [u32],
) {
    let mut counts = rank_counts(nparts, part);
    let mut w = rank_weights(weights, nparts, part);
    for r in 0..nparts {
        if counts[r] != 0 {
            continue;
        }
        // Heaviest donor with ≥ 2 elements (lowest rank on ties).
        let Some(donor) = (0..nparts)
            .filter(|&d| counts[d] >= 2)
            .max_by(|&a, &b| w[a].cmp(&w[b]).then(b.cmp(&a)))
        else {
            return;
        };
        let in_donor = |e: &usize| part[*e] as usize == donor;
        let on_boundary = (0..part.len()).filter(in_donor).find(|&e| {
            graph
                .neighbours(e)
                .iter()
                .any(|&f| part[f as usize] as usize != donor)
        });
        let Some(e) = on_boundary.or_else(|| (0..part.len()).find(in_donor)) else {
            return;
        };
        part[e] = r as u32;
        counts[donor] -= 1;
        counts[r] += 1;
        w[donor] -= i64::from(weights[e]);
        w[r] += i64::from(weights[e]);
    }
}

/// Distinct ranks among the neighbours of `e` with how many neighbours each.
fn neighbour_ranks(graph: &DualGraph, part: &[u32], e: usize, out: &mut Vec<(u32, u32)>) {
    out.clear();
    for &f in graph.neighbours(e) {
        let r = part[f as usize];
        match out.iter_mut().find(|(q, _)| *q == r) {
            Some((_, c)) => *c += 1,
            None => out.push((r, 1)),
        }
    }
}

/// Best helpful move of element `e` out of rank `h`: a neighbour rank `r`
/// with `w[r] + weight < w[h]` (so the pair gets more even), preferring the
/// largest cut gain (neighbours in `r` minus neighbours in `h`), then the
/// lighter rank, then the lower rank. Returns (rank, gain).
fn best_move(conn: &[(u32, u32)], h: u32, weight: i64, w: &[i64]) -> Option<(u32, i64)> {
    let internal = conn
        .iter()
        .find(|(q, _)| *q == h)
        .map_or(0, |(_, c)| i64::from(*c));
    conn.iter()
        .filter(|(r, _)| *r != h && w[*r as usize] + weight < w[h as usize])
        .map(|&(r, c)| (r, i64::from(c) - internal))
        .min_by(|a, b| {
            b.1.cmp(&a.1)
                .then(w[a.0 as usize].cmp(&w[b.0 as usize]))
                .then(a.0.cmp(&b.0))
        })
}

/// Moves boundary elements from overweight ranks to lighter neighbour ranks
/// until the imbalance is at most `tolerance` or no move helps.
///
/// A move of element `e` from rank `s` to a neighbour rank `r` is allowed
/// when `w[r] + w[e] < w[s]`; each move strictly lowers the sum of squared
/// rank weights, so the process ends. One sweep tries the ranks from the
/// heaviest down (lower rank on ties) and stops at the first that can move
/// something: first, in increasing element order, every
/// element whose best move does not increase the edge cut is moved while the
/// rank is overweight (its own imbalance above `tolerance`); if that moved
/// nothing, the single move with the best cut gain (ties: lighter target,
/// lower element index) is made. Trying the next rank when the heaviest is
/// stuck resolves chains (the heaviest rank next to an almost as heavy one
/// that must pass weight on first). At the end, the moves made after the
/// maximum rank weight last went down are undone, so churn that did not
/// help is not kept. A rank never gives away its last element.
/// Deterministic.
pub(crate) fn refine(
    graph: &DualGraph,
    weights: &[i32],
    nparts: usize,
    tolerance: f64,
    part: &mut [u32],
) {
    let mut state = State {
        w: rank_weights(weights, nparts, part),
        counts: rank_counts(nparts, part),
        conn: Vec::new(),
        log: Vec::new(),
    };
    let total: i64 = state.w.iter().sum();
    if total <= 0 {
        return;
    }
    let mean = total as f64 / nparts as f64;
    // Same arithmetic as `imbalance`, so the stop test and the report agree.
    let over = |w: &[i64], s: usize| w[s] as f64 / mean - 1.0 > tolerance;
    let max_weight = |w: &[i64]| w.iter().copied().max().unwrap_or(0);
    // The first state with the lowest maximum rank weight is the answer;
    // moves made after it (that did not lower the maximum) are undone.
    let mut best_max = max_weight(&state.w);
    let mut best_len = 0;

    for _ in 0..MAX_SWEEPS {
        if imbalance(&state.w) <= tolerance {
            break;
        }
        let mut sources: Vec<usize> = (0..nparts).collect();
        sources.sort_by(|&a, &b| state.w[b].cmp(&state.w[a]).then(a.cmp(&b)));
        let moved = sources.into_iter().any(|s| {
            state.greedy_pass(graph, weights, part, s, &over)
                || state.best_single_move(graph, weights, part, s)
        });
        if !moved {
            break;
        }
        if max_weight(&state.w) < best_max {
            best_max = max_weight(&state.w);
            best_len = state.log.len();
        }
    }
    while state.log.len() > best_len {
        if let Some((e, from)) = state.log.pop() {
            part[e] = from;
        }
    }
}

struct State {
    w: Vec<i64>,
    counts: Vec<usize>,
    conn: Vec<(u32, u32)>,
    /// Moves made, as (element, rank it came from).
    log: Vec<(usize, u32)>,
}

impl State {
    fn apply(&mut self, weights: &[i32], part: &mut [u32], e: usize, r: u32) {
        let we = i64::from(weights[e]);
        let s = part[e] as usize;
        self.log.push((e, part[e]));
        part[e] = r;
        self.w[s] -= we;
        self.w[r as usize] += we;
        self.counts[s] -= 1;
        self.counts[r as usize] += 1;
    }

    /// Moves, in element order, every element of `s` whose best helpful move
    /// does not increase the cut, while `s` is overweight. True if it moved.
    fn greedy_pass(
        &mut self,
        graph: &DualGraph,
        weights: &[i32],
        part: &mut [u32],
        s: usize,
        over: &dyn Fn(&[i64], usize) -> bool,
    ) -> bool {
        let mut moved = false;
        for e in 0..part.len() {
            if part[e] as usize != s || weights[e] == 0 {
                continue;
            }
            if self.counts[s] <= 1 || !over(&self.w, s) {
                break;
            }
            neighbour_ranks(graph, part, e, &mut self.conn);
            if let Some((r, gain)) = best_move(&self.conn, s as u32, i64::from(weights[e]), &self.w)
            {
                if gain >= 0 {
                    self.apply(weights, part, e, r);
                    moved = true;
                }
            }
        }
        moved
    }

    /// Makes the single helpful move out of `s` with the best cut gain.
    fn best_single_move(
        &mut self,
        graph: &DualGraph,
        weights: &[i32],
        part: &mut [u32],
        s: usize,
    ) -> bool {
        if self.counts[s] <= 1 {
            return false;
        }
        let mut best: Option<(usize, u32, i64)> = None;
        for e in 0..part.len() {
            if part[e] as usize != s || weights[e] == 0 {
                continue;
            }
            neighbour_ranks(graph, part, e, &mut self.conn);
            let Some((r, gain)) = best_move(&self.conn, s as u32, i64::from(weights[e]), &self.w)
            else {
                continue;
            };
            let better = match best {
                None => true,
                Some((_, br, bg)) => {
                    gain > bg || (gain == bg && self.w[r as usize] < self.w[br as usize])
                }
            };
            if better {
                best = Some((e, r, gain));
            }
        }
        match best {
            Some((e, r, _)) => {
                self.apply(weights, part, e, r);
                true
            }
            None => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_mesh::quad_grid;
    use crate::{Adjacency, Mesh};

    #[test]
    fn refine_repairs_a_lopsided_split() {
        // 10 x 14 grid: rows 0..9 (90 elements) on rank 0, rows 9..14 (50) on
        // rank 1; the balanced split moves about two rows.
        let (n_nodes, ptr, nodes) = quad_grid(10, 14);
        let mesh = Mesh {
            n_nodes,
            elem_ptr: &ptr,
            elem_nodes: &nodes,
        };
        let g = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
        let weights = vec![1; 140];
        let mut part: Vec<u32> = (0..140).map(|e| u32::from(e >= 90)).collect();
        assert!(imbalance(&rank_weights(&weights, 2, &part)) > 0.12);
        refine(&g, &weights, 2, 0.05, &mut part);
        let w = rank_weights(&weights, 2, &part);
        assert!(imbalance(&w) <= 0.05, "rank weights {w:?}");
        // Only the two rows next to the boundary moved (elements 70..90),
        // starting with the first of them.
        for (e, &p) in part.iter().enumerate() {
            if p == 1 {
                assert!(e >= 70, "element {e} moved from the interior");
            }
        }
        assert!(part[80..90].iter().all(|&p| p == 1));
        assert_eq!(w, vec![73, 67]);
        // Deterministic.
        let mut again: Vec<u32> = (0..140).map(|e| u32::from(e >= 90)).collect();
        refine(&g, &weights, 2, 0.05, &mut again);
        assert_eq!(part, again);
    }

    #[test]
    fn refine_four_ranks_with_uneven_weights() {
        // 4 column bands of a 12 x 10 grid, then make band 0 twice as heavy.
        let (n_nodes, ptr, nodes) = quad_grid(12, 10);
        let mesh = Mesh {
            n_nodes,
            elem_ptr: &ptr,
            elem_nodes: &nodes,
        };
        let g = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
        let part0: Vec<u32> = (0..120).map(|e| ((e % 12) / 3) as u32).collect();
        let weights: Vec<i32> = part0
            .iter()
            .map(|&p| if p == 0 { 40 } else { 20 })
            .collect();
        let mut part = part0.clone();
        refine(&g, &weights, 4, 0.05, &mut part);
        let w = rank_weights(&weights, 4, &part);
        assert!(imbalance(&w) <= 0.05, "rank weights {w:?}");
        assert!(rank_counts(4, &part).iter().all(|&c| c > 0));
    }

    #[test]
    fn refine_stops_when_no_move_helps() {
        // Two elements, one of weight 10 and one of weight 1: nothing to do.
        let ptr = [0, 2, 4];
        let nodes = [0, 1, 1, 2];
        let mesh = Mesh {
            n_nodes: 3,
            elem_ptr: &ptr,
            elem_nodes: &nodes,
        };
        let g = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
        let mut part = vec![0, 1];
        refine(&g, &[10, 1], 2, 0.05, &mut part);
        assert_eq!(part, vec![0, 1]);
    }

    #[test]
    fn refine_undoes_moves_that_do_not_lower_the_maximum() {
        // Strip of 6: a huge element alone on rank 0 (stuck), ranks 1 and 2
        // uneven. Evening out ranks 1 and 2 does not lower the maximum.
        let (n_nodes, ptr, nodes) = quad_grid(6, 1);
        let mesh = Mesh {
            n_nodes,
            elem_ptr: &ptr,
            elem_nodes: &nodes,
        };
        let g = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
        let weights = [100, 1, 1, 1, 1, 5];
        let mut part = vec![0, 1, 1, 1, 2, 2];
        refine(&g, &weights, 3, 0.05, &mut part);
        assert_eq!(part, vec![0, 1, 1, 1, 2, 2]);
    }

    #[test]
    fn fill_empty_ranks_takes_boundary_elements() {
        let (n_nodes, ptr, nodes) = quad_grid(4, 1);
        let mesh = Mesh {
            n_nodes,
            elem_ptr: &ptr,
            elem_nodes: &nodes,
        };
        let g = DualGraph::build(&mesh, Adjacency::SharedNode).unwrap();
        let mut part = vec![0, 0, 0, 1];
        fill_empty_ranks(&g, &[1; 4], 4, &mut part);
        // Rank 0 (heaviest) gives its boundary element 2 to rank 2, then its
        // lowest-index boundary element 1 (next to rank 2) to rank 3.
        assert_eq!(part, vec![0, 3, 2, 1]);
    }
}
