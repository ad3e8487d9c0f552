//! /SKEW/FIX, /SKEW/MOV and /SKEW/MOV2 (reference guide, Starter): read here,
//! resolved into `model::Skew` by the model builder (nodes must exist, be
//! distinct and not aligned; a fixed skew's axes must not be parallel).
//!
//! Cards (title line first):
//! * FIX: Ox Oy Oz, then the Y′ axis X1 Y1 Z1, then the Z′ axis X2 Y2 Z2
//!   (three 20-column reals per line); a deck of input version before 2017
//!   may give the two axes alone (origin 0);
//! * MOV: node_ID1 node_ID2 node_ID3 (10 columns each) and Dir (31-40: X, Y
//!   or Z, blank X);
//! * MOV2: node_ID1 node_ID2 node_ID3.

use super::fields::Cards;
use super::id_index::IdIndex;
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{Id, InputError, InputResult, Loc, Skew, SkewKind};

/// A skew card before its nodes are resolved.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct SkewCard {
    /// The keyword as written (/SKEW/MOV/4), for messages.
    pub keyword: String,
    pub id: Id,
    pub title: String,
    pub kind: SkewCardKind,
    pub loc: Loc,
}

#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub enum SkewCardKind {
    Fixed {
        origin: [f64; 3],
        y: [f64; 3],
        z: [f64; 3],
    },
    Moving {
        nodes: [Id; 3],
        dir: u8,
    },
}

/// Reads /SKEW/FIX, /SKEW/MOV, /SKEW/MOV2; false for another skew type.
pub(super) fn parse_skew(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let variant = block.parts.get(1).map(String::as_str).unwrap_or("");
    if !matches!(variant, "FIX" | "MOV" | "MOV2") {
        return Ok(false);
    }
    let id = header_id(block, 2, "skew_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let kind = if variant == "FIX" {
        // Input versions before 2017 wrote the two axes without the origin
        // line (the QA deck OPTIONS_NEW_BOX_V11, version 110): two cards there
        // are the axes, the origin is 0.
        let invers = deck.begin.as_ref().map_or(0, |b| b.invers);
        let no_origin = invers > 0 && invers < 2017 && cards.remaining().len() == 2;
        let mut v = [[0.0; 3]; 3];
        for (row, what) in v.iter_mut().skip(no_origin as usize).zip(
            [
                "origin Ox, Oy, Oz",
                "Y′ axis X1, Y1, Z1",
                "Z′ axis X2, Y2, Z2",
            ][no_origin as usize..]
                .iter(),
        ) {
            let c = cards.next(&format!("the card with the {what}"))?;
            for (k, x) in row.iter_mut().enumerate() {
                *x = c.real(1 + 20 * k, what, 0.0)?;
            }
        }
        SkewCardKind::Fixed {
            origin: v[0],
            y: v[1],
            z: v[2],
        }
    } else {
        let c = cards.next("the card with node_ID1, node_ID2, node_ID3")?;
        let mut nodes = [0; 3];
        for (k, n) in nodes.iter_mut().enumerate() {
            *n = c.id_opt(1 + 10 * k, &format!("node_ID{}", k + 1))?;
        }
        let dir = match (variant, c.text(31, 10).to_ascii_uppercase().as_str()) {
            ("MOV2", _) | (_, "" | "X") => b'X',
            (_, "Y") => b'Y',
            (_, "Z") => b'Z',
            (_, d) => return Err(c.err("Dir", format!("'{d}': expected X, Y or Z (blank: X)"))),
        };
        SkewCardKind::Moving { nodes, dir }
    };
    super::warn_surplus(&cards, "the last card of the skew", &mut deck.warnings);
    deck.skews.push(SkewCard {
        keyword: block.header.clone(),
        id,
        title,
        kind,
        loc: block.loc.clone(),
    });
    Ok(true)
}

/// The deck's skews with their nodes resolved, checked on the initial
/// geometry `x` (nodes given, distinct and not aligned; fixed axes not
/// parallel); ids unique.
pub(super) fn resolve_skews(
    deck: &Deck,
    nodes: &IdIndex,
    x: &[[f64; 3]],
) -> Result<Vec<Skew>, InputError> {
    IdIndex::build(
        "skew",
        deck.skews.iter().map(|s| (s.id, s.loc.clone())),
        "/SKEW",
    )?;
    let mut out = Vec::with_capacity(deck.skews.len());
    for c in &deck.skews {
        let kw = &c.keyword;
        let kind = match &c.kind {
            SkewCardKind::Fixed { origin, y, z } => SkewKind::Fixed {
                origin: *origin,
                y: *y,
                z: *z,
            },
            SkewCardKind::Moving { nodes: ids, dir } => {
                let mut n = [0u32; 3];
                for k in 0..3 {
                    let field = format!("node_ID{}", k + 1);
                    if ids[k] == 0 {
                        return Err(InputError::new(
                            c.loc.clone(),
                            kw,
                            &field,
                            "blank: a moving skew needs three nodes",
                        ));
                    }
                    n[k] = nodes.resolve(ids[k], &c.loc, kw, &field)?;
                }
                SkewKind::Moving {
                    nodes: n,
                    dir: *dir,
                }
            }
        };
        let skew = Skew {
            id: c.id,
            title: c.title.clone(),
            kind,
            loc: c.loc.clone(),
        };
        if skew.axes(x).is_none() {
            return Err(InputError::new(
                c.loc.clone(),
                kw,
                "axes",
                "the skew's axes are degenerate (coincident or aligned nodes, or zero or parallel vectors); expected three independent directions",
            ));
        }
        out.push(skew);
    }
    Ok(out)
}
