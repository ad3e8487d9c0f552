//! //SUBMODEL and //ENDSUB (reference guide, "//SUBMODEL" starter keyword):
//! the blocks between them are a submodel, read as the rest of the deck.
//!
//! Cards of //SUBMODEL/submodel_ID/unit_ID/Vers_number:
//! 1. submodel_title (100 characters)
//! 2. off_def, off_nod, off_ele, off_part, off_mat, off_type, off_sub
//!    (10 columns each): id offsets, each defaulting to off_def (0).
//!
//! A submodel without offsets and without a /TRANSFORM naming it leaves
//! every id and every coordinate as written (research note
//! `docs/notes/submodel_pload_random_research.md` §1), so it changes nothing
//! in the solution and is read as such. What would change the model is
//! refused by name: non-zero offsets, a unit system or input version of
//! its own (unit_ID, Vers_number), a /BEGIN inside the block. //ENDSUB is
//! mandatory: an unclosed //SUBMODEL, or an //ENDSUB without one, is an
//! error at its line.

use super::fields::Cards;
use super::source::Block;
use super::{header_id, Deck};
use crate::model::{InputError, InputResult};

const OFFSETS: [&str; 7] = [
    "off_def", "off_nod", "off_ele", "off_part", "off_mat", "off_type", "off_sub",
];

/// //SUBMODEL (opens a submodel) and //ENDSUB (closes the innermost one).
pub(super) fn parse_submodel(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    // The source splits `//SUBMODEL/1` into ["/SUBMODEL", "1"].
    match block.parts[0].as_str() {
        "/SUBMODEL" => open(block, deck).map(|_| true),
        "/ENDSUB" => close(block, deck).map(|_| true),
        _ => Ok(false),
    }
}

fn open(block: &Block, deck: &mut Deck) -> InputResult<()> {
    header_id(block, 1, "submodel_ID")?;
    for (idx, name, what) in [
        (2, "unit_ID", "a unit system of its own"),
        (3, "Vers_number", "an input version of its own"),
    ] {
        let t = block.parts.get(idx).map(|s| s.trim()).unwrap_or("");
        if !t.is_empty() && t != "0" {
            return Err(InputError::new(
                block.loc.clone(),
                &block.header,
                name,
                format!(
                    "'{t}': a submodel with {what} is not supported; \
                     expected the submodel in the deck's own units and version (blank)"
                ),
            ));
        }
    }
    let mut cards = Cards::new(block);
    cards.title();
    if let Some(c) = cards.next_opt() {
        for (k, name) in OFFSETS.iter().enumerate() {
            let off = c.int(1 + 10 * k, name, 0)?;
            if off != 0 {
                return Err(c.err(
                    name,
                    format!(
                        "{off}: id offsets of a submodel are not supported; \
                         expected 0 or blank (ids as written)"
                    ),
                ));
            }
        }
    }
    super::warn_surplus(&cards, "the offsets card", &mut deck.warnings);
    deck.open_submodels.push(block.loc.clone());
    Ok(())
}

fn close(block: &Block, deck: &mut Deck) -> InputResult<()> {
    if deck.open_submodels.pop().is_none() {
        return Err(InputError::new(
            block.loc.clone(),
            &block.header,
            "",
            "//ENDSUB without an open //SUBMODEL; expected //SUBMODEL/id before it",
        ));
    }
    super::warn_surplus(&Cards::new(block), "//ENDSUB", &mut deck.warnings);
    Ok(())
}

/// The deck is read: every //SUBMODEL must have met its //ENDSUB.
pub(super) fn check_closed(deck: &Deck) -> InputResult<()> {
    match deck.open_submodels.last() {
        Some(loc) => Err(InputError::new(
            loc.clone(),
            "//SUBMODEL",
            "",
            "this submodel has no //ENDSUB; expected //ENDSUB after its last block",
        )),
        None => Ok(()),
    }
}

/// A /BEGIN inside a submodel would give it its own units and version.
pub(super) fn refuse_begin_inside(block: &Block, deck: &Deck) -> InputResult<()> {
    if deck.open_submodels.is_empty() {
        return Ok(());
    }
    Err(InputError::new(
        block.loc.clone(),
        &block.header,
        "",
        "a /BEGIN inside a //SUBMODEL (units and version of its own) is not supported; \
         expected the submodel's blocks in the deck's units",
    ))
}
