//! `*HOURGLASS`, `*CONTROL_HOURGLASS` and `*PART`'s HGID → the hourglass
//! fields of the part's property (keyword manual volume I "*HOURGLASS",
//! "*CONTROL_HOURGLASS"; the reference guide's /PROP/SOLID Isolid and h).
//!
//! A part takes its HGID's hourglass, else `*CONTROL_HOURGLASS`'s IHQ and
//! QH, else LS-DYNA's default (IHQ 1, QM 0.1), which is what its section's
//! translation already says. Where that differs, the part gets a copy of
//! its section's property (an id of the reader's own) with:
//! - one-point solids (ELFORM 1): IHQ 0/1 → Isolid 2 (the standard viscous
//!   form on Hallquist's base vectors), IHQ 2/3 → Isolid 1
//!   (Flanagan-Belytschko's viscous form), h = QM (our linear term
//!   ¼·h·ρ·V^(2/3)·c is LS-DYNA's a_h with QM), the bulk viscosity Q1, Q2;
//!   the stiffness forms IHQ 4-10 are refused by name;
//! - fully integrated solids (ELFORM 2) and shells ELFORM 16: no hourglass
//!   modes, nothing to change (IHQ 8, warping for ELFORM 16, refused);
//! - Belytschko-Tsay shells (ELFORM 2): the viscous forms IHQ 0-3 with
//!   QM = QB = QW = 0.1 run as the section's default; any other IHQ or
//!   coefficient is refused by name (no exact map to Ishell 1's hm, hf, hr).

use super::card::Cards;
use super::source::Block;
use super::Ctx;
use crate::model::{Id, InputError, InputResult, Loc, PropertyKind};

/// One hourglass definition (`*HOURGLASS`, or `*CONTROL_HOURGLASS`'s).
#[derive(Clone)]
pub struct Hourglass {
    pub ihq: i64,
    pub qm: f64,
    pub q1: f64,
    pub q2: f64,
    pub qb: f64,
    pub qw: f64,
    pub kw: String,
    pub loc: Loc,
}

/// HGID IHQ QM IBQ Q1 Q2 QB/VDC QW (IHQ 0: *CONTROL_HOURGLASS's; QM 0 →
/// 0.1; Q1 0 → 1.5, Q2 0 → 0.06; QB, QW 0 → QM).
pub fn hourglass(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        // The title line (`_TITLE`) names nothing the model keeps.
        super::sections::title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std, "the card HGID IHQ QM IBQ Q1 Q2 QB QW")?;
        let id = c.id(0, "HGID")?;
        let or = |v: f64, d: f64| if v == 0.0 { d } else { v };
        let qm = or(c.real(2, "QM", 0.0)?, 0.1);
        let hg = Hourglass {
            ihq: c.int(1, "IHQ", 0)?,
            qm,
            q1: or(c.real(4, "Q1", 0.0)?, 1.5),
            q2: or(c.real(5, "Q2", 0.0)?, 0.06),
            qb: or(c.real(6, "QB", 0.0)?, qm),
            qw: or(c.real(7, "QW", 0.0)?, qm),
            kw: kw.clone(),
            loc: c.loc(),
        };
        if !(0..=10).contains(&hg.ihq) || qm < 0.0 {
            return Err(c.err("IHQ", format!("{}: expected 0 to 10 (and QM >= 0)", hg.ihq)));
        }
        ctx.hourglasses.push((id, hg));
    }
    Ok(())
}

/// IHQ QH: the default hourglass of every part without HGID.
pub fn control(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let std = cards.standard();
    let c = cards.next(std, "the card IHQ QH")?;
    let qm = c.real(1, "QH", 0.0)?;
    let qm = if qm == 0.0 { 0.1 } else { qm };
    ctx.control_hourglass = Some(Hourglass {
        ihq: c.int(0, "IHQ", 0)?,
        qm,
        q1: 1.5,
        q2: 0.06,
        qb: qm,
        qw: qm,
        kw: format!("*{}", b.name),
        loc: c.loc(),
    });
    Ok(())
}

/// Once the deck is read: each part's hourglass into a copy of its
/// property where it changes it; an undefined HGID is an error naming the
/// part's card.
pub fn finish(ctx: &mut Ctx) -> InputResult<()> {
    for (pi, hgid, loc) in std::mem::take(&mut ctx.part_hgid) {
        let hg = ctx
            .hourglasses
            .iter()
            .find(|h| h.0 == hgid)
            .map(|h| h.1.clone());
        let Some(mut hg) = hg else {
            return Err(InputError::new(
                loc,
                "*PART",
                "HGID",
                format!("hourglass {hgid} is not defined (expected a *HOURGLASS)"),
            ));
        };
        if hg.ihq == 0 {
            hg.ihq = ctx.control_hourglass.as_ref().map_or(1, |c| c.ihq);
        }
        apply(ctx, pi, &hg);
    }
    if let Some(hg) = ctx.control_hourglass.clone() {
        for pi in std::mem::take(&mut ctx.parts_without_hgid) {
            apply(ctx, pi, &hg);
        }
    }
    Ok(())
}

/// Part `pi`'s property with hourglass `hg`: unchanged, a copy, or refused.
fn apply(ctx: &mut Ctx, pi: usize, hg: &Hourglass) {
    let part = &ctx.deck.parts[pi];
    let found = ctx.deck.properties.iter().find(|p| p.id == part.prop);
    let Some(mut copy) = found.cloned() else {
        return; // references::check names the missing section
    };
    let prop = copy.kind.clone();
    let whose = format!("IHQ {} (part {})", hg.ihq, part.id);
    match &mut copy.kind {
        PropertyKind::Solid(s) if s.isolid != 14 => {
            s.isolid = match hg.ihq {
                0 | 1 => 2,
                2 | 3 => 1,
                _ => {
                    return ctx.refuse(
                        &hg.loc,
                        &hg.kw,
                        format!("{whose}: a stiffness or assumed-strain form"),
                    )
                }
            };
            (s.h, s.qa, s.qb) = (hg.qm, hg.q1, hg.q2);
        }
        PropertyKind::Shell(s) if s.ishell == 1 => {
            let default = |q: f64| (q - 0.1).abs() < 1e-12;
            if hg.ihq > 3 || !default(hg.qm) || !default(hg.qb) || !default(hg.qw) {
                let what = format!("{whose}, QM {} on Belytschko-Tsay shells (the viscous forms with QM 0.1 are computed)", hg.qm);
                return ctx.refuse(&hg.loc, &hg.kw, what);
            }
            return;
        }
        _ if hg.ihq == 8 => {
            return ctx.refuse(
                &hg.loc,
                &hg.kw,
                format!("{whose}: warping for fully integrated shells"),
            )
        }
        // Fully integrated elements: no hourglass modes.
        _ => return,
    }
    if copy.kind == prop {
        return;
    }
    let id: Id = ctx.own_id();
    copy.id = id;
    ctx.deck.properties.push(copy);
    ctx.deck.parts[pi].prop = id;
}
