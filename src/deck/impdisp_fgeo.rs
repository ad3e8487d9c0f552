//! /IMPDISP/FGEO: nodes moved to a prescribed final geometry (reference
//! guide /IMPDISP/FGEO, Starter; research note
//! `docs/notes/impdisp_fgeo_research.md` §1). Each listed node travels the
//! straight line from its initial position X₀ to its final position X_f,
//! the fraction of the path given by the time function: u(t) = f(Ascale·t)·(X_f − X₀).
//!
//! Cards after the title:
//! 1. fct_ID (1-10), part_ID (11-20), sens_ID (31-40)
//! 2. Ascale (1-20), Tstart (41-60), Tstop (61-80)
//! 3. … node_ID (1-10), X (11-30), Y (31-50), Z (51-70): one line per node,
//!    up to the next keyword.
//!
//! The card has a format from input version 140 on only; older decks get
//! the reference starter's warning and the card is read all the same, as it
//! does. part_ID (spring targets) and sens_ID are refused by name.

use super::fields::Cards;
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{Id, InputResult, Loc, Warning};

/// A final-geometry card before its nodes are resolved.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct FgeoCard {
    pub id: Id,
    pub title: String,
    pub fct: Id,
    pub ascale: f64,
    pub tstart: f64,
    pub tstop: f64,
    /// (node id, final position, where).
    pub nodes: Vec<(Id, [f64; 3], Loc)>,
    pub loc: Loc,
}

/// Reads /IMPDISP/FGEO/impdisp_ID.
pub(super) fn parse_fgeo(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 2, "impdisp_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c1 = cards.next("the card with fct_ID, part_ID, sens_ID")?;
    let fct = c1.id(1, "fct_ID")?;
    if c1.id_opt(11, "part_ID")? != 0 {
        return Err(c1.err("part_ID", "final positions from a spring part are not supported yet; list the nodes and their final positions"));
    }
    if c1.id_opt(31, "sens_ID")? != 0 {
        return Err(c1.err(
            "sens_ID",
            "a sensor-started /IMPDISP/FGEO is not supported yet (sensors are not computed)",
        ));
    }
    let c2 = cards.next("the card with Ascale, Tstart, Tstop")?;
    let ascale = c2.real(1, "Ascale", 0.0)?;
    if ascale < 0.0 {
        return Err(c2.err(
            "Ascale",
            format!("{ascale}: the time scale must be > 0 (blank: 1)"),
        ));
    }
    let tstart = c2.real(41, "Tstart", 0.0)?;
    let tstop = c2.real(61, "Tstop", 0.0)?;
    let mut nodes = Vec::new();
    while let Some(c) = cards.next_nonblank() {
        let n = c.id(1, "node_ID")?;
        let p = [
            c.real(11, "X", 0.0)?,
            c.real(31, "Y", 0.0)?,
            c.real(51, "Z", 0.0)?,
        ];
        nodes.push((n, p, c.loc()));
    }
    if nodes.is_empty() {
        return Err(c2.err(
            "node_ID",
            "no node line: expected node_ID, X, Y, Z lines after the Ascale card",
        ));
    }
    if deck.begin.as_ref().is_some_and(|b| b.invers < 140) {
        deck.warnings.push(Warning {
            loc: block.loc.clone(),
            keyword: block.header.clone(),
            message: "/IMPDISP/FGEO has a format from input version 140 on; read all the same, as the reference starter does".into(),
        });
    }
    deck.final_geometries.push(FgeoCard {
        id,
        title,
        fct,
        ascale: if ascale == 0.0 { 1.0 } else { ascale },
        tstart,
        tstop: if tstop == 0.0 { 1e30 } else { tstop },
        nodes,
        loc: block.loc.clone(),
    });
    Ok(true)
}

/// The deck's final-geometry motions with their nodes resolved (each node
/// in one card at most) and their function checked by `check_fct`.
pub(super) fn resolve(
    deck: &Deck,
    nodes: &super::id_index::IdIndex,
    check_fct: impl Fn(Id, &Loc, &str, &str) -> Result<(), crate::model::InputError>,
) -> Result<Vec<crate::model::FinalGeometry>, crate::model::InputError> {
    let mut seen = std::collections::HashMap::new();
    let mut out = Vec::with_capacity(deck.final_geometries.len());
    for c in &deck.final_geometries {
        let kw = format!("/IMPDISP/FGEO/{}", c.id);
        check_fct(c.fct, &c.loc, &kw, "fct_ID")?;
        let mut idx = Vec::with_capacity(c.nodes.len());
        for (id, _, loc) in &c.nodes {
            let n = nodes.resolve(*id, loc, &kw, "node_ID")?;
            if let Some(first) = seen.insert(n, loc.clone()) {
                return Err(crate::model::InputError::new(
                    loc.clone(),
                    &kw,
                    "node_ID",
                    format!("node {id} already has a final position (at {first}); expected each node once"),
                ));
            }
            idx.push(n);
        }
        out.push(crate::model::FinalGeometry {
            id: c.id,
            fct: c.fct,
            ascale: c.ascale,
            tstart: c.tstart,
            tstop: c.tstop,
            nodes: idx,
            target: c.nodes.iter().map(|n| n.1).collect(),
            loc: c.loc.clone(),
        });
    }
    Ok(out)
}
