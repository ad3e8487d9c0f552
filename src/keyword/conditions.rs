//! Sets, constraints, initial velocities and curves (keyword manual volume
//! I: "*SET_NODE", "*SET_PART", "*BOUNDARY_SPC", "*INITIAL_VELOCITY",
//! "*DEFINE_CURVE").

use super::card::{Card, Cards};
use super::include_transform::IdKind;
use super::sections::title;
use super::source::Block;
use super::{base_name, Ctx};
use crate::deck::{NodeGroupCard, NodeGroupKind, SegmentCard, SurfaceCard, SurfaceDef};
use crate::model::{BoundarySpec, Function, Id, InitialVelocitySpec, InputResult};

/// The ids of a list card: up to 8 fields, blanks and zeros ignored.
fn list(c: &Card, name: &str, out: &mut Vec<i64>) -> InputResult<()> {
    for i in 0..8 {
        let v = c.int(i, name, 0)?;
        if v < 0 {
            return Err(c.err(name, format!("{v}: expected an id > 0")));
        }
        if v > 0 {
            out.push(v);
        }
    }
    Ok(())
}

/// A set's first card (SID and options) and its id list (`item`: the list
/// fields' name in messages).
fn set_lines(
    b: &Block,
    cards: &mut Cards,
    item: &str,
) -> InputResult<(Id, String, crate::model::Loc, Vec<i64>)> {
    let title = title(b, cards)?;
    let std = cards.standard();
    let c = cards.next(std.clone(), "the card SID DA1 DA2 DA3 DA4")?;
    let id = c.id(0, "SID")?;
    let mut items = Vec::new();
    while let Some(d) = cards.next_opt(std.clone()) {
        list(&d, item, &mut items)?;
    }
    Ok((id, title, c.loc(), items))
}

/// `*SET_NODE_LIST`: SID DA1..DA4 SOLVER, then node ids, 8 a line.
pub fn node_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let (id, title, loc, items) = set_lines(b, cards, "NID")?;
    ctx.deck.node_groups.push(NodeGroupCard {
        id,
        title,
        kind: NodeGroupKind::Node,
        items,
        item_locs: vec![(0, loc.clone())],
        loc,
    });
    Ok(())
}

/// `*SET_PART_LIST`: SID DA1..DA4 SOLVER, then part ids, 8 a line.
pub fn part_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let (id, _, loc, items) = set_lines(b, cards, "PID")?;
    if ctx.part_sets.iter().any(|(s, _)| *s == id) {
        return Err(crate::model::InputError::new(
            loc,
            &format!("*{}", b.name),
            "SID",
            format!("part set {id} is defined twice"),
        ));
    }
    ctx.part_sets.push((id, items));
    Ok(())
}

/// DOFX DOFY DOFZ DOFRX DOFRY DOFRZ from field `first` on.
fn dofs(c: &Card, first: usize) -> InputResult<[bool; 6]> {
    let names = ["DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"];
    let mut fixed = [false; 6];
    for (k, name) in names.iter().enumerate() {
        fixed[k] = match c.int(first + k, name, 0)? {
            0 => false,
            1 => true,
            v => return Err(c.err(name, format!("{v}: expected 0 (free) or 1 (fixed)"))),
        };
    }
    Ok(fixed)
}

/// The `_ID` option's first card: ID and HEADING.
fn id_card(b: &Block, cards: &mut Cards) -> InputResult<()> {
    if base_name(&b.name).2 {
        let std = cards.standard();
        cards.next(std, "the card ID HEADING")?;
    }
    Ok(())
}

/// `*BOUNDARY_SPC_SET`: NSID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ.
pub fn spc_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    spc(b, cards, ctx, true)
}

/// `*BOUNDARY_SPC_NODE`: NID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ.
pub fn spc_node(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    spc(b, cards, ctx, false)
}

fn spc(b: &Block, cards: &mut Cards, ctx: &mut Ctx, set: bool) -> InputResult<()> {
    id_card(b, cards)?;
    let kw = format!("*{}", b.name);
    while let Some(c) = cards.next_opt(cards.standard()) {
        if c.is_blank() {
            continue;
        }
        if c.id_opt(1, "CID")? != 0 {
            ctx.refuse(&c.loc(), &kw, "field CID (constraints in a local system)");
        }
        let fixed = dofs(&c, 2)?;
        let grnod = ctx.card_nodes(&c, set, &kw)?;
        ctx.deck.bcs.push(BoundarySpec {
            id: ctx.deck.bcs.len() as Id + 1,
            title: kw.clone(),
            fixed,
            skew_id: 0,
            grnod,
            loc: c.loc(),
        });
    }
    Ok(())
}

/// A translational initial velocity `v` on node group `grnod`.
fn velocity(
    ctx: &mut Ctx,
    kw: &str,
    v: [f64; 3],
    rotational: bool,
    grnod: Id,
    loc: &crate::model::Loc,
) {
    ctx.deck.initial_velocities.push(InitialVelocitySpec {
        id: ctx.deck.initial_velocities.len() as Id + 1,
        title: kw.to_string(),
        rotational,
        v,
        grnod,
        skew_id: 0,
        loc: loc.clone(),
    });
}

/// `*INITIAL_VELOCITY_GENERATION`: card 1 ID STYP OMEGA VX VY VZ IVATN
/// ICID, card 2 XC YC ZC NX NY NZ PHASE IRIGID. STYP 1 part set, 2 part,
/// 3 node set; a rotation (OMEGA) is refused by name.
pub fn velocity_generation(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let std = cards.standard();
        let c = cards.next(std.clone(), "the card ID STYP OMEGA VX VY VZ IVATN ICID")?;
        let styp = c.int(1, "STYP", 0)?;
        let kind = match styp {
            2 => IdKind::Part,
            _ => IdKind::Set,
        };
        let id = c.offset_by_type(c.id(0, "ID")?, Some(kind));
        if c.real(2, "OMEGA", 0.0)? != 0.0 {
            ctx.refuse(&c.loc(), &kw, "field OMEGA (a rotating initial velocity)");
        }
        let v = c.vec3(3, ["VX", "VY", "VZ"])?;
        ctx.refuse_given(&c, &kw, &[(6, "IVATN"), (7, "ICID")], "", true)?;
        cards.next(std, "the card XC YC ZC NX NY NZ PHASE IRIGID")?;
        let grnod = match styp {
            3 => id,
            2 => ctx.own_group(
                NodeGroupKind::Part,
                vec![id as i64],
                format!("{kw} part {id}"),
                &c.loc(),
            ),
            1 => ctx.part_set_group(id, format!("{kw} part set {id}"), &c.loc(), &kw, "ID"),
            _ => {
                return Err(c.err(
                    "STYP",
                    format!("{styp}: expected 1 (part set), 2 (part) or 3 (node set)"),
                ))
            }
        };
        velocity(ctx, &kw, v, false, grnod, &c.loc());
    }
    Ok(())
}

/// `*INITIAL_VELOCITY`: card 1 NSID NSIDEX BOXID IRIGID ICID, card 2 VX VY
/// VZ VXR VYR VZR.
pub fn velocity_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let std = cards.standard();
        let c = cards.next(std.clone(), "the card NSID NSIDEX BOXID IRIGID ICID")?;
        let nsid = c.id(0, "NSID")?;
        let ignored = [(1, "NSIDEX"), (2, "BOXID"), (3, "IRIGID"), (4, "ICID")];
        ctx.refuse_given(&c, &kw, &ignored, "", true)?;
        let d = cards.next(std, "the card VX VY VZ VXR VYR VZR")?;
        let v = d.vec3(0, ["VX", "VY", "VZ"])?;
        let w = d.vec3(3, ["VXR", "VYR", "VZR"])?;
        velocity(ctx, &kw, v, false, nsid, &c.loc());
        if w != [0.0; 3] {
            velocity(ctx, &kw, w, true, nsid, &d.loc());
        }
    }
    Ok(())
}

/// `*INITIAL_VELOCITY_NODE`: NID VX VY VZ VXR VYR VZR ICID, a node a line.
pub fn velocity_node(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while let Some(c) = cards.next_opt(cards.standard()) {
        if c.is_blank() {
            continue;
        }
        let g = ctx.card_nodes(&c, false, &kw)?;
        let v = c.vec3(1, ["VX", "VY", "VZ"])?;
        let w = c.vec3(4, ["VXR", "VYR", "VZR"])?;
        if c.int(7, "ICID", 0)? != 0 {
            ctx.refuse(&c.loc(), &kw, "field ICID");
        }
        velocity(ctx, &kw, v, false, g, &c.loc());
        if w != [0.0; 3] {
            velocity(ctx, &kw, w, true, g, &c.loc());
        }
    }
    Ok(())
}

/// `*DEFINE_CURVE`: LCID SIDR SFA SFO OFFA OFFO DATTYP, then abscissa and
/// ordinate pairs (20 columns each): x = SFA·a + OFFA, y = SFO·o + OFFO.
pub fn curve(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let title = title(b, cards)?;
    let std = cards.standard();
    let c = cards.next(std, "the card LCID SIDR SFA SFO OFFA OFFO DATTYP")?;
    let id = c.id(0, "LCID")?;
    if c.int(1, "SIDR", 0)? == 1 {
        ctx.refuse(
            &c.loc(),
            &kw,
            "SIDR 1 (a curve for dynamic relaxation only)",
        );
    }
    let one = |v: f64| if v == 0.0 { 1.0 } else { v };
    let sfa = one(c.real(2, "SFA", 1.0)?);
    let sfo = one(c.real(3, "SFO", 1.0)?);
    let offa = c.real(4, "OFFA", 0.0)?;
    let offo = c.real(5, "OFFO", 0.0)?;
    if c.int(6, "DATTYP", 0)? != 0 {
        ctx.refuse(&c.loc(), &kw, "field DATTYP");
    }
    let (mut x, mut y) = (Vec::new(), Vec::new());
    while let Some(d) = cards.next_opt(vec![20, 20]) {
        if d.is_blank() {
            continue;
        }
        let a = d.real(0, "A", 0.0)? * sfa + offa;
        if x.last().is_some_and(|&p| a <= p) {
            return Err(d.err("A", format!("{a}: expected abscissas in increasing order")));
        }
        x.push(a);
        y.push(d.real(1, "O", 0.0)? * sfo + offo);
    }
    if x.is_empty() {
        return Err(c.err(
            "A",
            "no point: expected abscissa and ordinate pairs after this card",
        ));
    }
    ctx.deck.functions.push(Function {
        id,
        title,
        x,
        y,
        loc: c.loc(),
    });
    Ok(())
}

/// `*SET_SEGMENT`: SID DA1..DA4 SOLVER, then one segment a line, N1 N2 N3
/// N4 (N4 = N3 or blank: a triangle) and its attributes A1..A4: the
/// surface of that id (/SURF/SEG).
pub fn segment_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let title = title(b, cards)?;
    let std = cards.standard();
    let c = cards.next(std.clone(), "the card SID DA1 DA2 DA3 DA4 SOLVER")?;
    let id = c.id(0, "SID")?;
    let mut segs = Vec::new();
    while let Some(d) = cards.next_opt(std.clone()) {
        if d.is_blank() {
            continue;
        }
        let n = [d.id(0, "N1")?, d.id(1, "N2")?, d.id(2, "N3")?];
        let n4 = d.id_opt(3, "N4")?;
        segs.push(SegmentCard {
            id: segs.len() as Id + 1,
            nodes: [n[0], n[1], n[2], if n4 == 0 { n[2] } else { n4 }],
            loc: d.loc(),
        });
    }
    if segs.is_empty() {
        return Err(c.err(
            "N1",
            "no segment: expected lines N1 N2 N3 N4 after this card",
        ));
    }
    ctx.deck.surfaces.push(SurfaceCard {
        id,
        title,
        def: SurfaceDef::Segments(segs),
        item_locs: vec![(0, c.loc())],
        loc: c.loc(),
    });
    Ok(())
}

/// `*SET_SHELL(_LIST)`: SID DA1 DA2 DA3 DA4 SOLVER, then shell ids, 8 a
/// line. A contact's set type 1: its shells' faces, made into a surface
/// once the deck is read (`Ctx::resolve_shell_sets`). (The attributes DA1-DA4
/// only filter `_ADVANCED` sets, which are not read.)
pub fn shell_set(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let (id, _, loc, items) = set_lines(b, cards, "EID")?;
    let err = |msg: String| {
        crate::model::InputError::new(loc.clone(), &format!("*{}", b.name), "SID", msg)
    };
    if ctx.shell_sets.iter().any(|s| s.0 == id) {
        return Err(err(format!("shell set {id} is defined twice")));
    }
    if items.is_empty() {
        return Err(err(
            "no shell: expected lines of shell ids after this card".into()
        ));
    }
    ctx.shell_sets
        .push((id, items.into_iter().map(|e| e as Id).collect(), loc));
    Ok(())
}
