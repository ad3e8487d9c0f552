//! /MOVE_FUNCT/fct_ID: scales and shifts the points of a /FUNCT in place
//! (reference guide /MOVE_FUNCT, Starter; research note
//! `docs/notes/impdisp_fgeo_research.md` §3): x′ = Ascale_x·x + Ashift_x,
//! y′ = Fscale_y·y + Fshift_y, scaled first, then shifted; a negative
//! Ascale_x reverses the points so that x′ still increases. Blank scales
//! are 1. Every user of the function sees the transformed curve.
//!
//! Card after the title: Ascale_x (1-20), Fscale_y (21-40), Ashift_x
//! (41-60), Fshift_y (61-80).

use super::fields::Cards;
use super::source::Block;
use super::{header_id, Deck};
use crate::model::{Id, InputError, InputResult, Loc};

/// A /MOVE_FUNCT card.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct MoveFunct {
    pub fct: Id,
    pub ascale_x: f64,
    pub fscale_y: f64,
    pub ashift_x: f64,
    pub fshift_y: f64,
    pub loc: Loc,
}

pub(super) fn parse_move_funct(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let fct = header_id(block, 1, "fct_ID")?;
    let mut cards = Cards::new(block);
    let _title = cards.title();
    let c = cards.next("the card with Ascale_x, Fscale_y, Ashift_x, Fshift_y")?;
    let one = |v: f64| if v == 0.0 { 1.0 } else { v };
    deck.move_functs.push(MoveFunct {
        fct,
        ascale_x: one(c.real(1, "Ascale_x", 0.0)?),
        fscale_y: one(c.real(21, "Fscale_y", 0.0)?),
        ashift_x: c.real(41, "Ashift_x", 0.0)?,
        fshift_y: c.real(61, "Fshift_y", 0.0)?,
        loc: block.loc.clone(),
    });
    super::warn_surplus(&cards, "the card of /MOVE_FUNCT", &mut deck.warnings);
    Ok(true)
}

/// Applies every /MOVE_FUNCT to its function (in deck order), once the
/// whole deck is read; a function the deck does not define is an error at
/// the card.
pub(super) fn apply(deck: &mut Deck) -> InputResult<()> {
    for m in &deck.move_functs {
        let Some(f) = deck.functions.iter_mut().find(|f| f.id == m.fct) else {
            return Err(InputError::new(
                m.loc.clone(),
                &format!("/MOVE_FUNCT/{}", m.fct),
                "fct_ID",
                format!(
                    "function {} is not defined in the deck; expected a /FUNCT id",
                    m.fct
                ),
            ));
        };
        for x in f.x.iter_mut() {
            *x = m.ascale_x * *x + m.ashift_x;
        }
        for y in f.y.iter_mut() {
            *y = m.fscale_y * *y + m.fshift_y;
        }
        if m.ascale_x < 0.0 {
            f.x.reverse();
            f.y.reverse();
        }
    }
    Ok(())
}
