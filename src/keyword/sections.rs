//! `*SECTION_SHELL` and `*SECTION_SOLID` → the property of the same id
//! (keyword manual volume I, "*SECTION_SHELL", "*SECTION_SOLID").
//!
//! Element formulations map to ours where they are the same element:
//! - shells: ELFORM 2 (Belytschko-Tsay: one point, viscous hourglass
//!   control) → Ishell 1 (the reference guide's Q4 with Belytschko
//!   hourglass); ELFORM 16 (fully integrated) → Ishell 12 (QBAT); every
//!   other ELFORM is refused by name;
//! - solids: ELFORM 1 (constant stress, one point, hourglass control) →
//!   Isolid 2: LS-DYNA's default hourglass form IHQ = 1 (*CONTROL_HOURGLASS)
//!   is the standard viscous form on Hallquist's base vectors, the
//!   reference guide's Isolid 2 ("viscous hourglass formulation without
//!   orthogonality"; Isolid 1 is Flanagan-Belytschko's, IHQ 2/3); ELFORM 2
//!   (fully integrated, selectively reduced) → Isolid 14 (HA8); others
//!   refused.
//!
//! LS-DYNA's defaults are kept where ours differ: NIP 2 through the
//! thickness (0 → 2), the shear factor SHRF 1 (0 → 1), the solid bulk
//! viscosity Q1 = 1.5, Q2 = 0.06 (*CONTROL_BULK_VISCOSITY's defaults) and
//! the hourglass coefficient QM = 0.1 (*CONTROL_HOURGLASS's).

use super::card::Cards;
use super::source::Block;
use super::{base_name, Ctx};
use crate::model::{InputResult, PropertyKind, PropertySpec, ShellProperty, SolidProperty};

/// The title line of a `_TITLE` keyword.
pub fn title(b: &Block, cards: &mut Cards) -> InputResult<String> {
    if base_name(&b.name).1 {
        let std = cards.standard();
        Ok(cards.next(std, "the title line")?.title())
    } else {
        Ok(String::new())
    }
}

/// Card 1: SECID ELFORM SHRF NIP PROPT QR/IRID ICOMP SETYP;
/// card 2: T1 T2 T3 T4 NLOC MAREA IDOF EDGSET.
pub fn shell(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(
            std.clone(),
            "the card SECID ELFORM SHRF NIP PROPT QR ICOMP SETYP",
        )?;
        let id = c.id(0, "SECID")?;
        let elform = c.int(1, "ELFORM", 2)?;
        let ishell = match elform {
            0 | 2 => 1,
            16 => 12,
            _ => {
                ctx.refuse(
                    &c.loc(),
                    &kw,
                    format!("ELFORM {elform} (section {id}; ELFORM 2 and 16 are)"),
                );
                1
            }
        };
        let shrf = c.real(2, "SHRF", 1.0)?;
        let nip = c.int(3, "NIP", 2)?;
        if !(1..=10).contains(&nip) && nip != 0 {
            return Err(c.err(
                "NIP",
                format!("{nip}: expected 1 to 10 points through the thickness"),
            ));
        }
        if c.int(6, "ICOMP", 0)? != 0 {
            ctx.refuse(
                &c.loc(),
                &kw,
                format!("ICOMP (section {id}: layered composite)"),
            );
        }
        let d = cards.next(std, "the card T1 T2 T3 T4 NLOC MAREA IDOF EDGSET")?;
        let t1 = d.real(0, "T1", 0.0)?;
        if t1 <= 0.0 {
            return Err(d.err("T1", format!("{t1}: expected the shell thickness > 0")));
        }
        for (i, name) in [(1, "T2"), (2, "T3"), (3, "T4")] {
            let t = d.real(i, name, t1)?;
            if t != t1 && t != 0.0 {
                ctx.refuse(
                    &d.loc(),
                    &kw,
                    format!("field {name} (section {id}): a thickness varying over the element"),
                );
            }
        }
        let whose = format!(" (section {id})");
        ctx.refuse_given(&d, &kw, &[(4, "NLOC"), (5, "MAREA")], &whose, false)?;
        ctx.deck.properties.push(PropertySpec {
            id,
            unit_id: 0,
            title,
            kind: PropertyKind::Shell(ShellProperty {
                ishell,
                ismstr: 0,
                ish3n: 0,
                idrill: 0,
                p_thick_fail: 0.0,
                hm: 0.0,
                hf: 0.0,
                hr: 0.0,
                dm: 0.0,
                dn: 0.0,
                n: if nip == 0 { 2 } else { nip },
                istrain: 1,
                thick: t1,
                ashear: if shrf == 0.0 { 1.0 } else { shrf },
                ithick: 0,
                iplas: 0,
            }),
            loc: c.loc(),
        });
    }
    Ok(())
}

/// Card 1: SECID ELFORM AET.
pub fn solid(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std, "the card SECID ELFORM AET")?;
        let id = c.id(0, "SECID")?;
        let elform = c.int(1, "ELFORM", 1)?;
        let isolid = match elform {
            // IHQ 1, the default: Hallquist's viscous form (module comment).
            0 | 1 => 2,
            2 => 14,
            _ => {
                ctx.refuse(
                    &c.loc(),
                    &kw,
                    format!("ELFORM {elform} (section {id}; ELFORM 1 and 2 are)"),
                );
                1
            }
        };
        if c.int(2, "AET", 0)? != 0 {
            ctx.refuse(&c.loc(), &kw, format!("field AET (section {id})"));
        }
        ctx.deck.properties.push(PropertySpec {
            id,
            unit_id: 0,
            title,
            kind: PropertyKind::Solid(SolidProperty {
                isolid,
                ismstr: 0,
                icpre: 0,
                itetra10: 0,
                inpts: 0,
                itetra4: 0,
                iframe: 0,
                dn: 0.0,
                qa: 1.5,
                qb: 0.06,
                q_blank: false,
                h: 0.1,
                lambda_v: 0.0,
                mu_v: 0.0,
                dtmin: 0.0,
                istrain: 0,
                ortho: None,
            }),
            loc: c.loc(),
        });
    }
    Ok(())
}
