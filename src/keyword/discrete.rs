//! Discrete springs and dampers: `*ELEMENT_DISCRETE`, `*SECTION_DISCRETE`,
//! `*MAT_SPRING_ELASTIC` (`*MAT_S01`) and `*MAT_DAMPER_VISCOUS`
//! (`*MAT_S02`) → /SPRING elements with a /PROP/TYPE4 (keyword manual
//! volume I "*ELEMENT_DISCRETE", "*SECTION_DISCRETE"; volume II
//! "*MAT_SPRING_ELASTIC", "*MAT_DAMPER_VISCOUS"; reference guide
//! /PROP/TYPE4).
//!
//! A translational discrete element (DRO 0) acts along the line of its two
//! nodes: F = K·Δl for the elastic spring, F = DC·dΔl/dt for the viscous
//! damper — TYPE4's F = K·δ + C·δ̇ along the spring's axis with (K, 0) or
//! (0, DC), massless (its time step from its nodes' masses, as LS-DYNA's
//! discrete elements carry no mass). Since a part names a section and a
//! material, each part of a discrete section gets, once the deck is read,
//! a TYPE4 property of its own (the section and the material together; an
//! id of the reader's own) and no material, as a Radioss /PART of springs.
//!
//! Refused by name: DRO 1 (torsional), KD, V0, CL, FD, CDL, TDL; VID
//! (an orientation), S other than 1, OFFSET.

use super::card::Cards;
use super::source::Block;
use super::Ctx;
use crate::deck::ElementCard;
use crate::model::{
    InputError, InputResult, PropertyKind, PropertySpec, SpringDof, SpringProperty,
};

/// Card 1: SECID DRO KD V0 CL FD; card 2: CDL TDL.
pub fn section(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        super::sections::title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std.clone(), "the card SECID DRO KD V0 CL FD")?;
        let id = c.id(0, "SECID")?;
        let whose = format!(" (section {id})");
        let fields = [(1, "DRO"), (2, "KD"), (3, "V0"), (4, "CL"), (5, "FD")];
        ctx.refuse_given(&c, &kw, &fields, &whose, false)?;
        let c2 = cards.next(std, "card 2: CDL TDL")?;
        ctx.refuse_given(&c2, &kw, &[(0, "CDL"), (1, "TDL")], &whose, false)?;
        ctx.discrete_sections.push(id);
    }
    Ok(())
}

/// `*MAT_SPRING_ELASTIC`: MID K.
pub fn spring(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    law(b, cards, ctx, "K", false)
}

/// `*MAT_DAMPER_VISCOUS`: MID DC.
pub fn damper(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    law(b, cards, ctx, "DC", true)
}

fn law(b: &Block, cards: &mut Cards, ctx: &mut Ctx, name: &str, damper: bool) -> InputResult<()> {
    while cards.remaining() > 0 {
        super::sections::title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std, &format!("the card MID {name}"))?;
        let id = c.id(0, "MID")?;
        let v = c.real(1, name, 0.0)?;
        if v <= 0.0 {
            return Err(c.err(name, format!("{v}: expected a value > 0")));
        }
        let dof = if damper {
            SpringDof::linear(0.0, v)
        } else {
            SpringDof::linear(v, 0.0)
        };
        ctx.discrete_materials.push((id, dof));
    }
    Ok(())
}

/// EID PID N1 N2 VID S PF OFFSET (8, 8, 8, 8, 8, 16, 8, 16 columns).
pub fn element(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let widths = if cards.long() {
        vec![20; 8]
    } else {
        vec![8, 8, 8, 8, 8, 16, 8, 16]
    };
    while let Some(c) = cards.next_opt(widths.clone()) {
        if c.is_blank() {
            continue;
        }
        let id = c.id(0, "EID")?;
        let whose = format!(" (element {id})");
        ctx.refuse_given(&c, &kw, &[(4, "VID"), (7, "OFFSET")], &whose, false)?;
        let s = c.real(5, "S", 1.0)?;
        if s != 1.0 && s != 0.0 {
            ctx.refuse(
                &c.loc(),
                &kw,
                format!("field S{whose}: a force scale other than 1"),
            );
        }
        ctx.deck.elements.spring.push(ElementCard {
            id,
            part: c.id(1, "PID")?,
            nodes: vec![c.id(2, "N1")?, c.id(3, "N2")?],
            phi: 0.0,
            thick: 0.0,
            loc: c.loc(),
        });
    }
    Ok(())
}

/// Once the deck is read: each part of a discrete section takes a TYPE4
/// property of its section and its spring or damper material, and no
/// material. A discrete section with another material is an error naming
/// the part.
pub fn finish(ctx: &mut Ctx) -> InputResult<()> {
    for pi in 0..ctx.deck.parts.len() {
        let part = &ctx.deck.parts[pi];
        if !ctx.discrete_sections.contains(&part.prop) {
            continue;
        }
        let Some(dof) = ctx.discrete_materials.iter().find(|m| m.0 == part.mat) else {
            return Err(InputError::new(
                part.loc.clone(),
                "*PART",
                "MID",
                format!(
                    "part {} has the discrete section {}: expected a *MAT_SPRING_ELASTIC or *MAT_DAMPER_VISCOUS, not material {}",
                    part.id, part.prop, part.mat
                ),
            ));
        };
        let spec = PropertySpec {
            id: 0,
            unit_id: 0,
            title: format!("part {} discrete", part.id),
            kind: PropertyKind::Spring(SpringProperty {
                mass: 0.0,
                sens_id: 0,
                isflag: 0,
                ileng: 0,
                dof: dof.1.clone(),
            }),
            loc: part.loc.clone(),
        };
        let id = ctx.own_id();
        ctx.deck.properties.push(PropertySpec { id, ..spec });
        let part = &mut ctx.deck.parts[pi];
        part.prop = id;
        part.mat = 0;
    }
    Ok(())
}
