//! /RANDOM and /RANDOM/GRNOD/grnd_ID: a random noise added once to the
//! initial node coordinates, as the reference starter adds it (reference
//! guide /RANDOM; research note `docs/notes/submodel_pload_random_research.md`
//! §3).
//!
//! Card: Xalea (1-20) and, from input version 110 on, Seed (21-40), both
//! reals; version-41 decks have Xalea in 1-16 only.
//!
//! Each perturbed node, x then y then z, gets Xalea·r with r from one
//! 16-bit linear congruential generator shared by every /RANDOM card:
//! I ← (25173·I + 13849) mod 65536, r = (I − 32768)/32768 ∈ [−1, 1), its
//! state starting at 0, or at int(Seed·32768 + 32768) for a non-zero Seed of
//! the first card that draws. Without a group every node is perturbed in
//! the deck's reading order (the reference's internal order); with a group,
//! its nodes in the group's order. The noise is exact to the digits the
//! reference starter prints for the QA deck SUBMODEL_update_v_100_PLOAD.

use super::fields::Cards;
use super::source::Block;
use super::{header_id, Deck};
use crate::model::{Id, InputError, InputResult, Loc};

/// One /RANDOM card.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RandomCard {
    pub xalea: f64,
    pub seed: f64,
    /// 0: every node.
    pub grnod: Id,
    pub loc: Loc,
}

/// /RANDOM or /RANDOM/GRNOD/grnd_ID.
pub(super) fn parse_random(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let grnod = match block.parts.get(1).map(String::as_str) {
        None | Some("") => 0,
        Some("GRNOD") => header_id(block, 2, "grnd_ID")?,
        // /RANDOM/0: no unit system of its own.
        Some(t) if t.trim().chars().all(|c| c == '0') => 0,
        // /RANDOM/unit_ID: the noise is a length in that unit system.
        Some(t) if t.chars().all(|c| c.is_ascii_digit()) => {
            return Err(InputError::new(
                block.loc.clone(),
                &block.header,
                "unit_ID",
                format!(
                    "'{t}': a noise in a unit system of its own is not supported; expected /RANDOM"
                ),
            ))
        }
        Some(_) => return Ok(false),
    };
    let invers = deck.begin.as_ref().map_or(0, |b| b.invers);
    let mut cards = Cards::new(block);
    let c = cards.next("the card with Xalea, Seed")?;
    let (xalea, seed) = if invers > 0 && invers < 51 {
        (c.real_opt(1, 16, "Xalea")?.unwrap_or(0.0), 0.0)
    } else if invers > 0 && invers < 110 {
        (c.real(1, "Xalea", 0.0)?, 0.0)
    } else {
        (c.real(1, "Xalea", 0.0)?, c.real(21, "Seed", 0.0)?)
    };
    if xalea < 0.0 || !xalea.is_finite() {
        return Err(c.err("Xalea", format!("{xalea}: expected a noise amplitude >= 0")));
    }
    if seed < 0.0 || !seed.is_finite() {
        return Err(c.err("Seed", format!("{seed}: expected a seed >= 0 (0: none)")));
    }
    super::warn_surplus(&cards, "the card with Xalea, Seed", &mut deck.warnings);
    deck.random_noises.push(RandomCard {
        xalea,
        seed,
        grnod,
        loc: c.loc(),
    });
    Ok(true)
}

/// The reference starter's generator (16-bit LCG, full period 65536).
struct Aleat {
    i: i64,
    started: bool,
}

impl Aleat {
    fn draw(&mut self, seed: f64) -> f64 {
        if !self.started {
            self.started = true;
            if seed != 0.0 {
                self.i = (seed * 32768.0 + 32768.0) as i64 % 65536;
            }
        }
        self.i = (25173 * self.i + 13849) % 65536;
        (self.i - 32768) as f64 / 32768.0
    }
}

/// Adds every card's noise to `x` (model node order). `reading_order`: the
/// model index of each node in the deck's reading order; `group`: a node
/// group's model indices, named by the card at its line.
pub(super) fn perturb(
    cards: &[RandomCard],
    reading_order: &[u32],
    group: impl Fn(Id, &Loc) -> Result<Vec<u32>, InputError>,
    x: &mut [[f64; 3]],
) -> Result<(), InputError> {
    let mut rng = Aleat {
        i: 0,
        started: false,
    };
    for c in cards {
        if c.xalea == 0.0 {
            continue;
        }
        let nodes = if c.grnod == 0 {
            reading_order.to_vec()
        } else {
            group(c.grnod, &c.loc)?
        };
        for n in nodes {
            for k in 0..3 {
                x[n as usize][k] += c.xalea * rng.draw(c.seed);
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn card(xalea: f64, seed: f64) -> RandomCard {
        RandomCard {
            xalea,
            seed,
            grnod: 0,
            loc: Loc::default(),
        }
    }

    /// The reference starter's "NEW NODE COORDINATES" of the QA deck's
    /// first node (25.4, 0, 0) with Xalea = .00100000005 and no seed.
    #[test]
    fn the_first_node_moves_as_the_reference_starter_lists() {
        let mut x = [[25.4, 0.0, 0.0]];
        perturb(
            &[card(0.00100000005, 0.0)],
            &[0],
            |_, _| unreachable!(),
            &mut x,
        )
        .unwrap();
        let want = [25.39942263791, 4.874878173431e-4, -4.714966056061e-5];
        for k in 0..3 {
            assert!(
                (x[0][k] - want[k]).abs() <= 1e-12 * want[k].abs(),
                "{:?}",
                x[0]
            );
        }
    }

    /// Full period: 65536 draws visit every value of [−1, 1) on the 2⁻¹⁵
    /// grid once, so the noise is uniform in ±Xalea with mean −1/65536·Xalea.
    #[test]
    fn the_generator_has_full_period_and_a_seed_shifts_it() {
        let mut rng = Aleat {
            i: 0,
            started: false,
        };
        let mut seen = vec![false; 65536];
        for _ in 0..65536 {
            let r = rng.draw(0.0);
            assert!((-1.0..1.0).contains(&r));
            let k = ((r + 1.0) * 32768.0) as usize;
            assert!(!seen[k]);
            seen[k] = true;
        }
        let mut seeded = Aleat {
            i: 0,
            started: false,
        };
        // Seed 0.5 starts the state at 49152.
        let want = ((25173 * 49152 + 13849) % 65536 - 32768) as f64 / 32768.0;
        assert_eq!(seeded.draw(0.5), want);
    }

    #[test]
    fn a_group_takes_the_noise_in_its_order_and_other_nodes_keep_theirs() {
        let mut x = [[0.0; 3]; 3];
        let mut c = card(1.0, 0.0);
        c.grnod = 4;
        perturb(&[c], &[0, 1, 2], |_, _| Ok(vec![2]), &mut x).unwrap();
        assert_eq!(x[0], [0.0; 3]);
        assert_eq!(x[1], [0.0; 3]);
        assert_eq!(x[2][0], (13849.0 - 32768.0) / 32768.0);
    }
}
