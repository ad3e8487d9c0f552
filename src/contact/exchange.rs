//! Contact across ranks (ARCHITECTURE "Parallel design"): ghost nodes and
//! force routing.
//!
//! - **Ghosts.** When the candidate lists are rebuilt, every rank publishes,
//!   per interface, the box of the secondary nodes it owns, grown by the gap,
//!   twice the sorting margin and the largest segment size. Each rank then
//!   sends the owners' main-surface nodes that fall in another rank's box; from
//!   then on, until the next sort, only their positions and velocities travel
//!   (every cycle). Any segment within reach of a secondary node has all its
//!   nodes inside that node's box, so each node–segment pair is found on the
//!   one rank that owns the secondary node.
//! - **Forces.** A pair's forces go to every rank that holds the node (its
//!   holders), keyed by (interface, pass, secondary entity, main entity,
//!   corner) ([`SumKey`]);
//!   each rank sums a node's contributions in key order, so the sum is the
//!   same bits on every rank and for any number of ranks. They travel
//!   neighbour to neighbour, not through a collective over every rank: at
//!   each sort a rank lists the holders of every node it can see (held or
//!   ghost: a pair's nodes are among them until the next sort), and one
//!   exchange of those lists makes the set symmetric (`GhostPlan::route`),
//!   so a cycle costs messages to a few neighbours, whatever the rank count.

use super::geometry::V3;
use super::key::SumKey;
use super::search::Aabb;
use super::setup::ContactSetup;
use crate::parallel::World;

/// Who sends which contact nodes to whom every cycle.
#[derive(Clone, Debug, Default)]
pub struct GhostPlan {
    pub ranks: Vec<u32>,
    pub send: Vec<Vec<u32>>,
    pub recv: Vec<Vec<u32>>,
    /// The ranks contributions travel between, ascending (symmetric: each
    /// lists the other), set at the sort by [`GhostPlan::set_route`].
    pub route: Vec<u32>,
}

fn box_to(b: &Aabb) -> [f64; 6] {
    [b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2]]
}
fn box_from(a: &[f64; 6]) -> Aabb {
    Aabb {
        min: [a[0], a[1], a[2]],
        max: [a[3], a[4], a[5]],
    }
}

impl GhostPlan {
    /// Builds the plan (collective). `my_boxes[i]`: this rank's grown box of
    /// interface i; `main_owned[i]`: the main-surface cnodes of interface i that
    /// this rank owns.
    pub fn build(
        world: &World,
        my_boxes: &[Aabb],
        main_owned: &[Vec<u32>],
        cx: &[V3],
    ) -> GhostPlan {
        let me = world.rank() as usize;
        let n = world.size() as usize;
        if n == 1 {
            return GhostPlan::default();
        }
        let mine: Vec<[f64; 6]> = my_boxes.iter().map(box_to).collect();
        let all = world.allgather(&mine);
        let mut send: Vec<Vec<u64>> = vec![Vec::new(); n];
        for (q, boxes) in all.iter().enumerate() {
            if q == me {
                continue;
            }
            let mut ids: Vec<u32> = Vec::new();
            for (i, b) in boxes.iter().enumerate() {
                let b = box_from(b);
                if b.is_empty() {
                    continue;
                }
                ids.extend(
                    main_owned[i]
                        .iter()
                        .copied()
                        .filter(|&c| b.contains(cx[c as usize])),
                );
            }
            ids.sort_unstable();
            ids.dedup();
            send[q] = ids.into_iter().map(u64::from).collect();
        }
        let got = world.alltoallv_u64(&send);
        let mut plan = GhostPlan::default();
        for q in 0..n {
            if q == me || (send[q].is_empty() && got[q].is_empty()) {
                continue;
            }
            plan.ranks.push(q as u32);
            plan.send.push(send[q].iter().map(|&c| c as u32).collect());
            plan.recv.push(got[q].iter().map(|&c| c as u32).collect());
        }
        plan
    }

    /// Ghost positions and velocities: owners send, the others receive (collective
    /// among the plan's ranks).
    pub fn exchange(&self, world: &World, cx: &mut [V3], cv: &mut [V3]) {
        if self.ranks.is_empty() {
            return;
        }
        let send: Vec<Vec<f64>> = self
            .send
            .iter()
            .map(|ids| {
                let mut b = Vec::with_capacity(ids.len() * 6);
                for &c in ids {
                    b.extend_from_slice(&cx[c as usize]);
                    b.extend_from_slice(&cv[c as usize]);
                }
                b
            })
            .collect();
        let mut recv: Vec<Vec<f64>> = self
            .recv
            .iter()
            .map(|ids| vec![0.0; ids.len() * 6])
            .collect();
        world.exchange_f64(&self.ranks, &send, &mut recv);
        for (ids, buf) in self.recv.iter().zip(&recv) {
            for (j, &c) in ids.iter().enumerate() {
                let b = &buf[6 * j..6 * j + 6];
                cx[c as usize] = [b[0], b[1], b[2]];
                cv[c as usize] = [b[3], b[4], b[5]];
            }
        }
    }

    /// The contribution neighbours (collective, at a sort): the holders of
    /// every cnode this rank can see (`avail`), and the ranks that list this
    /// one among theirs.
    pub fn set_route(&mut self, world: &World, setup: &ContactSetup, avail: &[bool]) {
        let (me, n) = (world.rank() as usize, world.size() as usize);
        if n == 1 {
            return;
        }
        let mut dest = vec![false; n];
        for (c, _) in avail.iter().enumerate().filter(|(_, &a)| a) {
            for &r in setup.holders_of(c as u32) {
                dest[r as usize] = true;
            }
        }
        dest[me] = false;
        let send: Vec<Vec<u64>> = dest
            .iter()
            .map(|&d| if d { vec![1] } else { vec![] })
            .collect();
        let got = world.alltoallv_u64(&send);
        self.route = (0..n)
            .filter(|&q| q != me && (dest[q] || !got[q].is_empty()))
            .map(|q| q as u32)
            .collect();
    }

    pub fn ghost_count(&self) -> usize {
        self.recv.iter().map(|r| r.len()).sum()
    }
}

/// One contribution of a pair to one node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contribution {
    /// The node (cnode).
    pub c: u32,
    /// Sort key: (interface, pass, secondary entity, main entity, corner).
    pub key: SumKey,
    pub f: V3,
    /// Stiffness added to the node (nodal time step).
    pub k: f64,
    /// IBC bits (x = 1, y = 2, z = 4) to release on the secondary node at impact.
    pub ibc: u8,
}

impl Contribution {
    fn encode(&self, out: &mut Vec<u64>) {
        let [hi, lo] = self.key.to_words();
        out.extend_from_slice(&[
            self.c as u64,
            hi,
            lo,
            self.f[0].to_bits(),
            self.f[1].to_bits(),
            self.f[2].to_bits(),
            self.k.to_bits(),
            self.ibc as u64,
        ]);
    }
    fn decode(b: &[u64]) -> Contribution {
        Contribution {
            c: b[0] as u32,
            key: SumKey::from_words([b[1], b[2]]),
            f: [
                f64::from_bits(b[3]),
                f64::from_bits(b[4]),
                f64::from_bits(b[5]),
            ],
            k: f64::from_bits(b[6]),
            ibc: b[7] as u8,
        }
    }
}

/// Sends each contribution to every holder of its node, through the
/// neighbours `route` (`GhostPlan::route`: every holder of a node this rank
/// computed a pair on is among them); returns the ones for this rank's
/// nodes, sorted by (node, key): the fixed summation order.
pub fn route(
    world: &World,
    setup: &ContactSetup,
    route: &[u32],
    out: Vec<Contribution>,
) -> Vec<Contribution> {
    let n = world.size() as usize;
    let mut got: Vec<Contribution> = if n == 1 {
        out
    } else {
        let me = world.rank();
        let mut mine = Vec::new();
        let mut send: Vec<Vec<u64>> = vec![Vec::new(); route.len()];
        for c in &out {
            for &r in setup.holders_of(c.c) {
                if r == me {
                    mine.push(*c);
                    continue;
                }
                let i = route
                    .binary_search(&r)
                    .expect("a holder of a node with a pair here is a route neighbour (set_route)");
                c.encode(&mut send[i]);
            }
        }
        let recv = world.exchange_with_neighbours(route, &send);
        mine.extend(
            recv.iter()
                .flat_map(|b| b.chunks_exact(8).map(Contribution::decode)),
        );
        mine
    };
    got.sort_unstable_by_key(|a| (a.c, a.key));
    got
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parallel::{run_ranks, Serial};

    /// Six contact nodes; with two ranks, 0–2 on rank 0 and 2–5 on rank 1 (node 2 shared).
    fn setup(nranks: usize) -> ContactSetup {
        let holders: Vec<Vec<u32>> = (0..6)
            .map(|c| match (nranks, c) {
                (1, _) => vec![0],
                (_, 0 | 1) => vec![0],
                (_, 2) => vec![0, 1],
                _ => vec![1],
            })
            .collect();
        let mut ptr = vec![0u32];
        for h in &holders {
            ptr.push(ptr.last().unwrap() + h.len() as u32);
        }
        ContactSetup {
            nodes: (0..6).collect(),
            x0: vec![[0.0; 3]; 6],
            holders_ptr: ptr,
            holders: holders.concat(),
            ..Default::default()
        }
    }

    /// Pair contributions as the pairs of several ranks would give them (made-up values).
    fn contributions() -> Vec<Contribution> {
        (0..40u32)
            .map(|i| Contribution {
                c: (i * 7) % 6,
                key: SumKey::pair(0, (i % 2) as usize, 100 + (i * 13) % 17, i).at((i % 5) as u8),
                f: [
                    0.1 * i as f64 + 1e-9,
                    -1.0 / (1.0 + i as f64),
                    3.3e3 * (i % 3) as f64,
                ],
                k: i as f64,
                ibc: 0,
            })
            .collect()
    }

    /// Each node's force summed in the order `route` returns.
    fn sums(got: &[Contribution]) -> Vec<(u32, [u64; 3])> {
        let mut out: Vec<(u32, V3)> = Vec::new();
        for c in got {
            match out.last_mut() {
                Some((n, f)) if *n == c.c => (0..3).for_each(|k| f[k] += c.f[k]),
                _ => out.push((c.c, c.f)),
            }
        }
        out.into_iter()
            .map(|(n, f)| (n, f.map(f64::to_bits)))
            .collect()
    }

    #[test]
    fn routed_contact_forces_sum_to_the_same_bits_on_one_and_two_ranks() {
        let one = sums(&route(&Serial, &setup(1), &[], contributions()));
        assert_eq!(one.len(), 6);
        let two = run_ranks(2, |w| {
            // Each rank computed every other pair, in reverse order.
            let mine: Vec<Contribution> = contributions()
                .into_iter()
                .enumerate()
                .filter(|(i, _)| i % 2 == w.rank() as usize)
                .map(|(_, c)| c)
                .rev()
                .collect();
            sums(&route(w, &setup(2), &[1 - w.rank()], mine))
        });
        let held = |r: u32| -> Vec<(u32, [u64; 3])> {
            let s = setup(2);
            one.iter()
                .filter(|(n, _)| s.holders_of(*n).contains(&r))
                .copied()
                .collect()
        };
        assert_eq!(two[0], held(0));
        assert_eq!(two[1], held(1));
    }

    #[test]
    fn ghosts_are_the_owned_main_nodes_in_another_ranks_box() {
        // Main nodes on a line x = 0, 1, 2, 3: rank 0 owns 0 and 1, rank 1 owns 2 and 3.
        let plans = run_ranks(2, |w| {
            let mut cx: Vec<V3> = (0..4).map(|i| [i as f64, 0.0, 0.0]).collect();
            let mut cv = vec![[0.0; 3]; 4];
            let me = w.rank();
            let owned: Vec<u32> = if me == 0 { vec![0, 1] } else { vec![2, 3] };
            // Rank 0's secondary nodes reach to x = 2.5; rank 1's stay beyond x = 2.5.
            let b = if me == 0 {
                Aabb {
                    min: [-0.5, -1.0, -1.0],
                    max: [2.5, 1.0, 1.0],
                }
            } else {
                Aabb {
                    min: [2.5, -1.0, -1.0],
                    max: [3.5, 1.0, 1.0],
                }
            };
            let plan = GhostPlan::build(w, &[b], &[owned], &cx);
            // The owner moves its node; the ghost follows at the exchange.
            if me == 1 {
                cx[2] = [2.25, 0.5, 0.0];
                cv[2] = [1.0, 2.0, 3.0];
            }
            plan.exchange(w, &mut cx, &mut cv);
            (
                plan.ranks.clone(),
                plan.send.clone(),
                plan.recv.clone(),
                cx[2],
                cv[2],
            )
        });
        assert_eq!(
            plans[0],
            (
                vec![1],
                vec![vec![]],
                vec![vec![2]],
                [2.25, 0.5, 0.0],
                [1.0, 2.0, 3.0]
            )
        );
        assert_eq!(
            plans[1],
            (
                vec![0],
                vec![vec![2]],
                vec![vec![]],
                [2.25, 0.5, 0.0],
                [1.0, 2.0, 3.0]
            )
        );
        assert_eq!(
            GhostPlan::build(&Serial, &[Aabb::EMPTY], &[vec![0]], &[[0.0; 3]]).ghost_count(),
            0
        );
    }
}
