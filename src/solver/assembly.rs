//! Deterministic assembly of element corner contributions into nodal forces.
//!
//! Every element corner writes its force and moment into its own slot of a
//! contribution buffer (no element writes into a node). A node's force is then
//! the sum of all the slots of all the elements that touch it — on this rank
//! and on the neighbour ranks that hold the node too — added in one fixed
//! order: by (element kind, global element index, corner). The set of
//! contributions and the order do not depend on the partition, so the nodal
//! forces are bitwise the same for any number of ranks and threads
//! (ARCHITECTURE.md, "Determinism").
//!
//! Shared nodes: at set-up each rank tells each neighbour, for every node they
//! share, the keys of its contributions; per cycle only the values travel.

use crate::domain::Subdomain;
use crate::parallel::World;
use rayon::prelude::*;

pub use crate::element::SLOT;

/// Which element corner a contribution comes from: the one key of the
/// assembly's fixed summation order (derived order: kind, element, corner).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SlotKey {
    /// Index of the element kind in `ElementKind::ALL`.
    pub kind: u8,
    /// Global element index within its kind.
    pub element: u32,
    /// Corner of the element (below 16).
    pub corner: u8,
}

impl SlotKey {
    pub fn new(kind: usize, element: u32, corner: usize) -> SlotKey {
        debug_assert!(kind < 256 && corner < 16);
        SlotKey {
            kind: kind as u8,
            element,
            corner: corner as u8,
        }
    }
    /// The word the key travels as between ranks; words order as keys do.
    pub fn to_word(self) -> u64 {
        ((self.kind as u64) << 56) | ((self.element as u64) << 4) | self.corner as u64
    }
    pub fn from_word(w: u64) -> SlotKey {
        SlotKey {
            kind: (w >> 56) as u8,
            element: ((w >> 4) & 0xffff_ffff) as u32,
            corner: (w & 0xf) as u8,
        }
    }
}

#[derive(Clone, Copy, Debug)]
enum Source {
    Local(u32),
    Remote(u32),
}

/// How to add up every node's contributions.
pub struct AssemblyPlan {
    /// Per local node, its sources in key order (CSR).
    ptr: Vec<u32>,
    src: Vec<Source>,
    /// Per neighbour: the local slots to send, in the order the neighbour expects.
    send_slots: Vec<Vec<u32>>,
    neighbours: Vec<u32>,
    /// Offset of each neighbour's values in the combined receive buffer (in slots).
    recv_off: Vec<usize>,
    recv_len: Vec<usize>,
    send_buf: Vec<Vec<f64>>,
    recv_buf: Vec<Vec<f64>>,
}

impl AssemblyPlan {
    /// `slots`: for every local contribution slot, (local node, key).
    pub fn build(world: &World, sd: &Subdomain, slots: &[(u32, SlotKey)]) -> AssemblyPlan {
        let n = sd.node_global.len();
        // Local sources per node.
        let mut per_node: Vec<Vec<(SlotKey, Source)>> = vec![Vec::new(); n];
        for (s, &(node, k)) in slots.iter().enumerate() {
            per_node[node as usize].push((k, Source::Local(s as u32)));
        }
        for v in &mut per_node {
            v.sort_by_key(|(k, _)| *k);
        }
        // What each neighbour gets: for each shared node (in the shared list's
        // order), the local slots touching it in key order, and their keys.
        let neighbours: Vec<u32> = sd.shared.iter().map(|s| s.rank).collect();
        let mut send_slots = Vec::new();
        let mut send_keys: Vec<Vec<u64>> = Vec::new();
        for sh in &sd.shared {
            let mut slots_out = Vec::new();
            // Layout: per shared node, a count, then the keys.
            let mut keys_out = Vec::new();
            for &l in &sh.nodes {
                let list: Vec<&(SlotKey, Source)> = per_node[l as usize]
                    .iter()
                    .filter(|(_, s)| matches!(s, Source::Local(_)))
                    .collect();
                keys_out.push(list.len() as u64);
                for (k, s) in list {
                    keys_out.push(k.to_word());
                    if let Source::Local(i) = s {
                        slots_out.push(*i);
                    }
                }
            }
            send_slots.push(slots_out);
            send_keys.push(keys_out);
        }
        let got_keys = world.exchange_with_neighbours(&neighbours, &send_keys);
        let mut recv_off = Vec::new();
        let mut recv_len = Vec::new();
        let mut total = 0usize;
        for (i, sh) in sd.shared.iter().enumerate() {
            recv_off.push(total);
            let keys = &got_keys[i];
            let mut pos = 0usize;
            let mut count = 0usize;
            for &l in &sh.nodes {
                let c = keys[pos] as usize;
                pos += 1;
                for _ in 0..c {
                    let k = SlotKey::from_word(keys[pos]);
                    per_node[l as usize].push((k, Source::Remote((total + count) as u32)));
                    pos += 1;
                    count += 1;
                }
            }
            recv_len.push(count);
            total += count;
        }
        let mut ptr = vec![0u32];
        let mut src = Vec::new();
        for v in &mut per_node {
            v.sort_by_key(|(k, _)| *k);
            src.extend(v.iter().map(|(_, s)| *s));
            ptr.push(src.len() as u32);
        }
        let send_buf = send_slots
            .iter()
            .map(|s| vec![0.0; s.len() * SLOT])
            .collect();
        let recv_buf = recv_len.iter().map(|&l| vec![0.0; l * SLOT]).collect();
        AssemblyPlan {
            ptr,
            src,
            send_slots,
            neighbours,
            recv_off,
            recv_len,
            send_buf,
            recv_buf,
        }
    }

    /// Sums the contributions into `out` (one [f64; 6] per local node: force, moment).
    pub fn assemble(&mut self, world: &World, contrib: &[[f64; SLOT]], out: &mut [[f64; SLOT]]) {
        for (buf, slots) in self.send_buf.iter_mut().zip(&self.send_slots) {
            for (i, &s) in slots.iter().enumerate() {
                buf[i * SLOT..(i + 1) * SLOT].copy_from_slice(&contrib[s as usize]);
            }
        }
        if !self.neighbours.is_empty() {
            world.exchange_f64(&self.neighbours, &self.send_buf, &mut self.recv_buf);
        }
        // Flatten the receive buffers' view: Remote(i) is slot i of the concatenation.
        let recv = &self.recv_buf;
        let offs = &self.recv_off;
        let lens = &self.recv_len;
        let remote = |i: usize| -> &[f64] {
            let mut b = 0;
            while i >= offs[b] + lens[b] {
                b += 1;
            }
            let j = i - offs[b];
            &recv[b][j * SLOT..(j + 1) * SLOT]
        };
        let ptr = &self.ptr;
        let src = &self.src;
        out.par_iter_mut().enumerate().for_each(|(n, o)| {
            let mut acc = [0.0; SLOT];
            for s in &src[ptr[n] as usize..ptr[n + 1] as usize] {
                let v: &[f64] = match *s {
                    Source::Local(i) => &contrib[i as usize],
                    Source::Remote(i) => remote(i as usize),
                };
                for k in 0..SLOT {
                    acc[k] += v[k];
                }
            }
            *o = acc;
        });
    }

    /// One value per slot (the nodal time step's element stiffness,
    /// `solver::run::interface_nodal_step`), first half: sends each
    /// neighbour `value(slot)` of the slots it shares, returns what came.
    pub fn exchange_scalar(&self, world: &World, value: impl Fn(usize) -> f64) -> ScalarRemote {
        let send: Vec<Vec<f64>> = self
            .send_slots
            .iter()
            .map(|slots| slots.iter().map(|&s| value(s as usize)).collect())
            .collect();
        let mut recv: Vec<Vec<f64>> = self.recv_len.iter().map(|&n| vec![0.0; n]).collect();
        if !self.neighbours.is_empty() {
            world.exchange_f64(&self.neighbours, &send, &mut recv);
        }
        ScalarRemote(recv.concat())
    }

    /// Second half: node `n`'s sum of `value(slot)` over its local slots
    /// and what `remote` brought, in the forces' key order (the same bits
    /// on any partition).
    pub fn node_sum(&self, n: usize, value: impl Fn(usize) -> f64, remote: &ScalarRemote) -> f64 {
        let mut acc = 0.0;
        for s in &self.src[self.ptr[n] as usize..self.ptr[n + 1] as usize] {
            acc += match *s {
                Source::Local(i) => value(i as usize),
                Source::Remote(i) => remote.0[i as usize],
            };
        }
        acc
    }
}

/// The values a scalar exchange brought, in the order of the plan's remote sources.
pub struct ScalarRemote(Vec<f64>);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slot_keys_order_as_their_words_and_round_trip() {
        let keys = [
            SlotKey::new(0, 7, 3),
            SlotKey::new(0, 8, 0),
            SlotKey::new(1, 0, 0),
            SlotKey::new(0, 7, 2),
            SlotKey::new(4, u32::MAX, 15),
        ];
        for a in keys {
            assert_eq!(SlotKey::from_word(a.to_word()), a);
            for b in keys {
                assert_eq!(a.cmp(&b), a.to_word().cmp(&b.to_word()));
            }
        }
    }
}
