//! `*RIGIDWALL_PLANAR` and `*ELEMENT_MASS` (keyword manual volume I,
//! "*RIGIDWALL_PLANAR", "*ELEMENT_MASS") → /RWALL/PLANE and /ADMAS.

use super::card::Cards;
use super::source::Block;
use super::Ctx;
use crate::deck::{AddedMassCard, NodeGroupKind};
use crate::model::{InputResult, RigidWallSpec};

/// Card 1: NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF; card 2: XT YT ZT
/// XH YH ZH FRIC WVEL. A fixed infinite plane through the tail point with
/// the normal tail → head, pushing the nodes of NSID (0: every node) less
/// those of NSIDEX; FRIC 0 frictionless, below 1 Coulomb (1, no sliding,
/// is refused by name).
pub fn planar(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    if b.name != "RIGIDWALL_PLANAR" && b.name != "RIGIDWALL_PLANAR_ID" {
        // _ORTHO, _MOVING, _FINITE, _FORCES: not read.
        ctx.refuse(&b.loc, &kw, "this variant of *RIGIDWALL_PLANAR");
        return Ok(());
    }
    let std = cards.standard();
    let mut id = ctx.deck.rigid_walls.len() as u64 + 1;
    let mut title = String::new();
    if b.name.ends_with("_ID") {
        let c = cards.next(vec![10, 70], "the card RWID HEADING")?;
        id = c.id(0, "RWID")?;
        title = c.raw(1).to_string();
    }
    let c1 = cards.next(
        std.clone(),
        "card 1: NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF",
    )?;
    let nsid = c1.id_opt(0, "NSID")?;
    let nsidex = c1.id_opt(1, "NSIDEX")?;
    ctx.refuse_given(
        &c1,
        &kw,
        &[(2, "BOXID"), (3, "OFFSET"), (4, "BIRTH")],
        "",
        false,
    )?;
    let death = c1.real(5, "DEATH", 0.0)?;
    if death != 0.0 && death < 1e20 {
        ctx.refuse(&c1.loc(), &kw, "field DEATH");
    }
    let rwksf = c1.real(6, "RWKSF", 0.0)?;
    if rwksf != 0.0 && rwksf != 1.0 {
        ctx.refuse(&c1.loc(), &kw, "field RWKSF");
    }
    let c2 = cards.next(std, "card 2: XT YT ZT XH YH ZH FRIC WVEL")?;
    let tail = c2.vec3(0, ["XT", "YT", "ZT"])?;
    let head = c2.vec3(3, ["XH", "YH", "ZH"])?;
    if tail == head {
        return Err(c2.err(
            "XH",
            "the head is the tail: expected a point off the wall giving its normal",
        ));
    }
    let fric = c2.real(6, "FRIC", 0.0)?;
    if !(0.0..=1.0).contains(&fric) {
        return Err(c2.err(
            "FRIC",
            format!("{fric}: expected 0 (frictionless) to 1 (no sliding)"),
        ));
    }
    if c2.real(7, "WVEL", 0.0)? != 0.0 {
        ctx.refuse(&c2.loc(), &kw, "field WVEL");
    }
    let grnod1 = if nsid == 0 {
        let g = ctx.own_group(
            NodeGroupKind::Part,
            Vec::new(),
            format!("{kw} every node"),
            &c1.loc(),
        );
        ctx.all_parts_groups.push(ctx.deck.node_groups.len() - 1);
        g
    } else {
        nsid
    };
    if fric == 1.0 {
        ctx.refuse(&c2.loc(), &kw, "FRIC 1 (no sliding after contact)");
    }
    let (slide, f) = if fric == 0.0 { (0, 0.0) } else { (2, fric) };
    ctx.deck.rigid_walls.push(RigidWallSpec {
        id,
        title,
        node_id: 0,
        slide,
        grnod1,
        grnod2: nsidex,
        d_search: 0.0,
        fric: f,
        diameter: 0.0,
        ffac: 0.0,
        ifq: 0,
        m: tail,
        mass: 0.0,
        v0: [0.0; 3],
        m1: head,
        loc: c1.loc(),
    });
    Ok(())
}

/// `*ELEMENT_MASS`: EID NID MASS PID (8, 8, 16, 8 columns), a lumped mass
/// on a node (/ADMAS on that node).
pub fn mass(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let widths = if cards.long() {
        vec![20; 4]
    } else {
        vec![8, 8, 16, 8]
    };
    while let Some(c) = cards.next_opt(widths.clone()) {
        if c.is_blank() {
            continue;
        }
        let id = c.id(0, "EID")?;
        let nid = c.id(1, "NID")?;
        let m = c.real(2, "MASS", 0.0)?;
        if m <= 0.0 {
            return Err(c.err("MASS", format!("{m}: expected a mass > 0")));
        }
        let g = ctx.own_group(
            NodeGroupKind::Node,
            vec![nid as i64],
            format!("{kw} {id} node {nid}"),
            &c.loc(),
        );
        ctx.deck.added_masses.push(AddedMassCard {
            id,
            kind: 0,
            title: format!("{kw} {id}"),
            mass: m,
            target: g,
            loc: c.loc(),
        });
    }
    Ok(())
}
