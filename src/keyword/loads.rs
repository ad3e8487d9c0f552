//! Prescribed motions and loads (keyword manual volume I:
//! "*BOUNDARY_PRESCRIBED_MOTION", "*LOAD_NODE", "*LOAD_BODY") → /IMPVEL
//! and /IMPDISP, /CLOAD, /GRAV.

use super::card::{Card, Cards};
use super::source::Block;
use super::{base_name, Ctx};
use crate::model::{ConcentratedLoadSpec, Dof, GravitySpec, Id, ImposedMotionSpec, InputResult};

/// DOF 1, 2, 3 (x, y, z) and 5, 6, 7 (about x, y, z), or `None`.
fn dof(code: i64) -> Option<Dof> {
    Some(match code {
        1 => Dof::X,
        2 => Dof::Y,
        3 => Dof::Z,
        5 => Dof::Xx,
        6 => Dof::Yy,
        7 => Dof::Zz,
        _ => return None,
    })
}

/// The card's DOF (field 2), or `None` after refusing a code not computed.
fn dof_field(ctx: &mut Ctx, c: &Card, kw: &str) -> InputResult<Option<Dof>> {
    let code = c.int(1, "DOF", 0)?;
    let d = dof(code);
    if d.is_none() {
        ctx.refuse(
            &c.loc(),
            kw,
            format!("DOF {code} (1-3 and 5-7 are computed)"),
        );
    }
    Ok(d)
}

/// `*BOUNDARY_PRESCRIBED_MOTION_NODE` / `_SET`: NID|NSID DOF VAD LCID SF VID
/// DEATH BIRTH. VAD 0 velocity (/IMPVEL), 2 displacement (/IMPDISP), the
/// value SF·f(t) from BIRTH to DEATH (0: never); VAD 1 (acceleration), 3
/// (velocity against displacement), DOF 4, 8 and the other signs refused.
pub fn prescribed_motion(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let (base, _, with_id) = base_name(&b.name);
    let set = base.ends_with("_SET");
    if with_id {
        let std = cards.standard();
        cards.next(std, "the card ID HEADING")?;
    }
    while let Some(c) = cards.next_opt(cards.standard()) {
        if c.is_blank() {
            continue;
        }
        let vad = c.int(2, "VAD", 0)?;
        let Some(dir) = dof_field(ctx, &c, &kw)? else {
            continue;
        };
        if vad != 0 && vad != 2 {
            ctx.refuse(
                &c.loc(),
                &kw,
                format!("VAD {vad} (0 velocity and 2 displacement are computed)"),
            );
            continue;
        }
        let grnod = ctx.card_nodes(&c, set, &kw)?;
        let fct = c.id(3, "LCID")?;
        let sf = one(c.real(4, "SF", 1.0)?);
        if c.id_opt(5, "VID")? != 0 {
            ctx.refuse(&c.loc(), &kw, "field VID");
        }
        let death = c.real(6, "DEATH", 0.0)?;
        let birth = c.real(7, "BIRTH", 0.0)?;
        let spec = ImposedMotionSpec {
            id: ctx.deck.imposed_velocities.len() as Id
                + ctx.deck.imposed_displacements.len() as Id
                + 1,
            unit_id: 0,
            title: kw.clone(),
            fct,
            dir,
            skew_id: 0,
            sens_id: 0,
            grnod,
            frame_id: 0,
            icoor: 0,
            ascale_x: 1.0,
            fscale_y: sf,
            tstart: birth,
            tstop: if death == 0.0 || death >= 1e28 {
                1e30
            } else {
                death
            },
            loc: c.loc(),
        };
        if vad == 0 {
            ctx.deck.imposed_velocities.push(spec);
        } else {
            ctx.deck.imposed_displacements.push(spec);
        }
    }
    Ok(())
}

fn one(v: f64) -> f64 {
    if v == 0.0 {
        1.0
    } else {
        v
    }
}

/// `*LOAD_NODE_POINT` / `_SET`: NID|NSID DOF LCID SF CID M1 M2 M3: a force
/// (DOF 1-3) or moment (5-7) SF·f(t) on each node; follower loads (4, 8)
/// and local systems refused.
pub fn node_load(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let set = base_name(&b.name).0.ends_with("_SET");
    while let Some(c) = cards.next_opt(cards.standard()) {
        if c.is_blank() {
            continue;
        }
        let Some(dir) = dof_field(ctx, &c, &kw)? else {
            continue;
        };
        if c.id_opt(4, "CID")? != 0 {
            ctx.refuse(&c.loc(), &kw, "field CID");
        }
        let grnod = ctx.card_nodes(&c, set, &kw)?;
        ctx.deck.concentrated_loads.push(ConcentratedLoadSpec {
            id: ctx.deck.concentrated_loads.len() as Id + 1,
            unit_id: 0,
            title: kw.clone(),
            fct: c.id(2, "LCID")?,
            dir,
            skew_id: 0,
            sens_id: 0,
            grnod,
            ascale_x: 1.0,
            fscale_y: one(c.real(3, "SF", 1.0)?),
            loc: c.loc(),
        });
    }
    Ok(())
}

/// `*LOAD_BODY_X` / `_Y` / `_Z`: LCID SF LCIDDR XC YC ZC CID, a base
/// acceleration of every node. LS-DYNA's sign: a positive value loads the
/// body along the negative axis (gravity is given positive), so the /GRAV
/// acceleration is −SF·f(t).
pub fn body_load(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let dir = match b.name.as_str() {
        "LOAD_BODY_X" => Dof::X,
        "LOAD_BODY_Y" => Dof::Y,
        _ => Dof::Z,
    };
    let std = cards.standard();
    let c = cards.next(std, "the card LCID SF LCIDDR XC YC ZC CID")?;
    let fct = c.id(0, "LCID")?;
    let sf = one(c.real(1, "SF", 1.0)?);
    for (i, name) in [(2, "LCIDDR"), (6, "CID")] {
        if c.id_opt(i, name)? != 0 {
            ctx.refuse(&c.loc(), &kw, format!("field {name}"));
        }
    }
    ctx.deck.gravity.push(GravitySpec {
        id: ctx.deck.gravity.len() as Id + 1,
        unit_id: 0,
        title: kw,
        fct,
        dir,
        skew_id: 0,
        sens_id: 0,
        grnod: 0,
        ascale_x: 1.0,
        fscale_y: -sf,
        loc: c.loc(),
    });
    Ok(())
}
