//! The one ordering key of contact's deterministic sums (ARCHITECTURE
//! "Determinism"): every contribution of a pair to a node, penalty contact
//! or tied, carries a [`SumKey`], and each rank adds a node's contributions in
//! key order, so the sum has the same bits on every rank and for any number
//! of ranks.
//!
//! The derived order is field by field: interface, pass, secondary entity,
//! main entity, corner. It is the order of the packed words the key travels
//! as ([`SumKey::to_words`]): (interface << 40 | pass << 32 | secondary,
//! main << 8 | corner).

/// Which node of a pair takes a contribution: main-side node i is corner i,
/// secondary-side node j is corner `SECONDARY_CORNER + j` (so a node-to-segment
/// pair's secondary node, corner 4, comes after the segment's corners 0..3).
pub const SECONDARY_CORNER: u8 = 4;

/// Identifies one contribution of one pair to one node.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SumKey {
    /// Interface index (contact or tied table), below 2^24.
    pub iface: u32,
    /// Pass of the interface, below 256 (0 for tied interfaces).
    pub pass: u32,
    /// The secondary entity: a secondary node's global node index.
    pub sec: u32,
    /// The main entity: the main segment's index in its pass (0 for tied
    /// interfaces, whose secondary node has one segment).
    pub main: u32,
    /// The node of the pair (see [`SECONDARY_CORNER`]).
    pub corner: u8,
}

impl SumKey {
    /// The key of a pair (corner 0): set the corner with [`SumKey::at`].
    pub fn pair(iface: usize, pass: usize, sec: u32, main: u32) -> SumKey {
        SumKey {
            iface: iface as u32,
            pass: pass as u32,
            sec,
            main,
            corner: 0,
        }
    }

    /// The same pair's key at another corner.
    pub fn at(self, corner: u8) -> SumKey {
        SumKey { corner, ..self }
    }

    /// The two words the key travels as between ranks; their (first, second)
    /// order is the key's order.
    pub fn to_words(&self) -> [u64; 2] {
        [
            ((self.iface as u64) << 40) | ((self.pass as u64) << 32) | self.sec as u64,
            ((self.main as u64) << 8) | self.corner as u64,
        ]
    }

    pub fn from_words(w: [u64; 2]) -> SumKey {
        SumKey {
            iface: (w[0] >> 40) as u32,
            pass: ((w[0] >> 32) & 0xff) as u32,
            sec: w[0] as u32,
            main: (w[1] >> 8) as u32,
            corner: w[1] as u8,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_key_orders_as_its_packed_words_and_travels_unchanged() {
        let keys = [
            SumKey::pair(0, 0, 7, 3).at(4),
            SumKey::pair(0, 0, 7, 3).at(0),
            SumKey::pair(0, 1, 2, 0).at(1),
            SumKey::pair(1, 0, 0, 0),
            SumKey::pair(0, 0, 8, 0).at(2),
            SumKey::pair(0, 0, 7, 2).at(4),
            SumKey::pair(3, 255, u32::MAX, 1 << 20).at(7),
        ];
        for a in &keys {
            assert_eq!(SumKey::from_words(a.to_words()), *a);
            for b in &keys {
                assert_eq!(a.cmp(b), a.to_words().cmp(&b.to_words()), "{a:?} {b:?}");
            }
        }
    }
}
