//! `*NODE`, `*ELEMENT_SHELL`, `*ELEMENT_SOLID` and `*PART` (keyword manual
//! volume I: "*NODE", "*ELEMENT_SHELL", "*ELEMENT_SOLID", "*PART").

use super::card::Cards;
use super::source::Block;
use super::Ctx;
use crate::deck::{ElementCard, NodeCard, NodeGroupKind, PartCard};
use crate::model::{BoundarySpec, InputResult};

/// `*NODE`: NID (8), X Y Z (16 each), TC RC (8 each); 20 columns each in
/// the long format. TC/RC fix translations/rotations (1 x, 2 y, 3 z, 4 xy,
/// 5 yz, 6 zx, 7 all): the node gets a boundary condition.
pub fn node(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let widths = if cards.long() {
        vec![20; 6]
    } else {
        vec![8, 16, 16, 16, 8, 8]
    };
    while let Some(c) = cards.next_opt(widths.clone()) {
        if c.is_blank() {
            continue;
        }
        let id = c.id(0, "NID")?;
        let x = [
            c.real(1, "X", 0.0)?,
            c.real(2, "Y", 0.0)?,
            c.real(3, "Z", 0.0)?,
        ];
        let tc = c.int(4, "TC", 0)?;
        let rc = c.int(5, "RC", 0)?;
        let (Some(t), Some(r)) = (constraint(tc), constraint(rc)) else {
            return Err(c.err(
                if constraint(tc).is_none() { "TC" } else { "RC" },
                "expected 0 to 7 (0 free, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all)",
            ));
        };
        if tc != 0 || rc != 0 {
            let kw = format!("*{} node {id}", b.name);
            let grnod = ctx.own_group(NodeGroupKind::Node, vec![id as i64], kw.clone(), &c.loc());
            ctx.deck.bcs.push(BoundarySpec {
                id: grnod,
                title: kw,
                fixed: [t[0], t[1], t[2], r[0], r[1], r[2]],
                skew_id: 0,
                grnod,
                loc: c.loc(),
            });
        }
        ctx.deck.nodes.push(NodeCard {
            id,
            x,
            loc: c.loc(),
        });
        super::define_transformation::note(ctx, b, Some(ctx.deck.nodes.len() - 1));
    }
    Ok(())
}

/// TC/RC code → fixed x, y, z.
pub(super) fn constraint(code: i64) -> Option<[bool; 3]> {
    Some(match code {
        0 => [false; 3],
        1 => [true, false, false],
        2 => [false, true, false],
        3 => [false, false, true],
        4 => [true, true, false],
        5 => [false, true, true],
        6 => [true, false, true],
        7 => [true; 3],
        _ => return None,
    })
}

/// An element card of nodes `nodes` (ids) in part `part`.
fn element(id: u64, part: u64, nodes: Vec<u64>, loc: crate::model::Loc) -> ElementCard {
    ElementCard {
        id,
        part,
        nodes,
        phi: 0.0,
        thick: 0.0,
        loc,
    }
}

/// Element fields: 8 columns (20 in the long format).
fn element_widths(long: bool) -> Vec<usize> {
    vec![if long { 20 } else { 8 }; 10]
}

/// `*ELEMENT_SHELL`: EID PID N1 N2 N3 N4 (N5–N8 of higher-order shells
/// refused). N4 = N3 or blank: a triangle.
pub fn shell(_b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    while let Some(c) = cards.next_opt(element_widths(cards.long())) {
        if c.is_blank() {
            continue;
        }
        let id = c.id(0, "EID")?;
        let part = c.id(1, "PID")?;
        let mut n = Vec::with_capacity(4);
        for (i, name) in ["N1", "N2", "N3"].iter().enumerate() {
            n.push(c.id(2 + i, name)?);
        }
        let n4 = c.id_opt(5, "N4")?;
        for (i, name) in ["N5", "N6", "N7", "N8"].iter().enumerate() {
            if c.id_opt(6 + i, name)? != 0 {
                return Err(c.err(
                    name,
                    "a higher-order shell node: expected 0 (4-node and 3-node shells only)",
                ));
            }
        }
        let card = |nodes: Vec<u64>| element(id, part, nodes, c.loc());
        if n4 == 0 || n4 == n[2] {
            ctx.deck.elements.shell3.push(card(n));
        } else {
            n.push(n4);
            ctx.deck.elements.shell4.push(card(n));
        }
    }
    Ok(())
}

/// `*ELEMENT_SOLID`: EID PID N1..N8 on one line (or EID PID, then the
/// eight nodes on the next line). N5 = … = N8 = N4: a tetrahedron.
pub fn solid(_b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let long = cards.long();
    while let Some(c) = cards.next_opt(element_widths(long)) {
        if c.is_blank() {
            continue;
        }
        let id = c.id(0, "EID")?;
        let part = c.id(1, "PID")?;
        let names = ["N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"];
        let mut n = Vec::with_capacity(8);
        if c.raw(2).is_empty() {
            let d = cards.next(element_widths(long), "the line with the eight nodes N1..N8")?;
            for (i, name) in names.iter().enumerate() {
                n.push(d.id(i, name)?);
            }
        } else {
            for (i, name) in names.iter().enumerate() {
                n.push(c.id(2 + i, name)?);
            }
        }
        let card = |nodes: Vec<u64>| element(id, part, nodes, c.loc());
        if n[4..].iter().all(|&v| v == n[3]) {
            n.truncate(4);
            ctx.deck.elements.tetra4.push(card(n));
        } else {
            ctx.deck.elements.brick8.push(card(n));
        }
    }
    Ok(())
}

/// `*PART`: a heading line, then PID SECID MID EOSID HGID GRAV ADPOPT TMID
/// (repeated for each part of the keyword).
pub fn part(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let std = cards.standard();
        let title = cards.next(std.clone(), "the part's heading")?.title();
        let c = cards.next(std, "the card PID SECID MID EOSID HGID GRAV ADPOPT TMID")?;
        let id = c.id(0, "PID")?;
        let prop = c.id(1, "SECID")?;
        let mat = c.id(2, "MID")?;
        let fields = [(3, "EOSID"), (6, "ADPOPT"), (7, "TMID")];
        ctx.refuse_given(&c, &kw, &fields, &format!(" (part {id})"), true)?;
        // HGID: applied once the deck is read (`hourglass::finish`).
        match c.id_opt(4, "HGID")? {
            0 => ctx.parts_without_hgid.push(ctx.deck.parts.len()),
            h => ctx.part_hgid.push((ctx.deck.parts.len(), h, c.loc())),
        }
        ctx.deck.parts.push(PartCard {
            id,
            title,
            prop,
            mat,
            subset: 0,
            thick: 0.0,
            loc: c.loc(),
        });
    }
    Ok(())
}
