//! `*RIGIDWALL_PLANAR` (and `_MOVING`) and `*ELEMENT_MASS` (keyword manual
//! volume I, "*RIGIDWALL_PLANAR", "*ELEMENT_MASS") → /RWALL/PLANE and
//! /ADMAS. A moving wall (card 3: MASS V0) is /RWALL/PLANE's moving wall: a
//! new node at the tail point (made once the deck is read) carrying MASS,
//! starting at V0 along the normal; frictionless only (LS-DYNA's moving
//! wall moves along its normal; ours is a free node).

use super::card::Cards;
use super::source::Block;
use super::{base_name, Ctx};
use crate::deck::{AddedMassCard, NodeGroupKind};
use crate::model::{InputResult, RigidWallSpec};

/// Card 1: NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF; card 2: XT YT ZT
/// XH YH ZH FRIC WVEL. A fixed infinite plane through the tail point with
/// the normal tail → head, pushing the nodes of NSID (0: every node) less
/// those of NSIDEX; FRIC 0 frictionless, below 1 Coulomb (1, no sliding,
/// is refused by name).
pub fn planar(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let moving = b.name.starts_with("RIGIDWALL_PLANAR_MOVING");
    if !matches!(
        base_name(&b.name).0,
        "RIGIDWALL_PLANAR" | "RIGIDWALL_PLANAR_MOVING"
    ) {
        // _ORTHO, _FINITE, _FORCES: not read.
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
    let (mass, v0) = if moving {
        if fric != 0.0 {
            // LS-DYNA's wall moves along its normal only; ours is a free
            // node, which friction would push sideways.
            ctx.refuse(
                &c2.loc(),
                &kw,
                "FRIC on a moving wall (frictionless is computed)",
            );
        }
        moving_wall(cards, tail, head)?
    } else {
        (0.0, [0.0; 3])
    };
    if moving {
        ctx.moving_walls.push(ctx.deck.rigid_walls.len());
    }
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
        mass,
        v0,
        m1: head,
        loc: c1.loc(),
    });
    Ok(())
}

/// `_MOVING`'s card 3: MASS (> 0) and V0, the initial speed along the
/// normal tail → head.
fn moving_wall(cards: &mut Cards, tail: [f64; 3], head: [f64; 3]) -> InputResult<(f64, [f64; 3])> {
    let std = cards.standard();
    let c = cards.next(std, "card 3 (_MOVING): MASS V0")?;
    let mass = c.real(0, "MASS", 0.0)?;
    if mass <= 0.0 {
        return Err(c.err("MASS", format!("{mass}: expected the wall's mass > 0")));
    }
    let v0 = c.real(1, "V0", 0.0)?;
    let n = crate::vec3::sub(head, tail);
    let n = crate::vec3::scale(n, v0 / crate::vec3::norm(n));
    Ok((mass, n))
}

/// Once the deck is read: each moving wall's node, at its tail point.
pub fn finish(ctx: &mut Ctx) {
    for i in std::mem::take(&mut ctx.moving_walls) {
        let (m, loc) = (
            ctx.deck.rigid_walls[i].m,
            ctx.deck.rigid_walls[i].loc.clone(),
        );
        ctx.deck.rigid_walls[i].node_id = ctx.add_node(m, &loc);
    }
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
