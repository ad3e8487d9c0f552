//! The opening every /MAT card shares (read once here for every law's
//! reader: `materials.rs`, `material_law21.rs`, `material_law36.rs`,
//! `material_law44.rs`).

use super::fields::{Card, Cards};
use super::source::Block;
use super::{header_id, header_id_opt};
use crate::model::{Id, InputResult};

/// The opening every /MAT card shares: the header's mat_ID and unit_ID,
/// the title, card 1 (RHO_I 1-20, RHO_0 21-40) and card 2's E (1-20) and
/// Nu (21-40); `card2` names card 2 in messages. Each law checks Nu's range
/// (they differ) and reads the rest of card 2 from `c2` and its own cards
/// from `cards`.
pub(super) struct Opening<'a> {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub rho: f64,
    pub rho_ref: f64,
    pub e: f64,
    pub nu: f64,
    pub cards: Cards<'a>,
    pub c2: Card<'a>,
}

pub(super) fn read_opening<'a>(block: &'a Block, card2: &str) -> InputResult<Opening<'a>> {
    let id = header_id(block, 2, "mat_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c1 = cards.next("the card with RHO_I (initial density)")?;
    let rho = c1.positive_real(1, "RHO_I", "density")?;
    let rho_ref = c1.real(21, "RHO_0", 0.0)?;
    let c2 = cards.next(card2)?;
    Ok(Opening {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e: c2.positive_real(1, "E", "Young's modulus")?,
        nu: c2.real(21, "Nu", 0.0)?,
        cards,
        c2,
    })
}
