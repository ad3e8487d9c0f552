//! /MAT/LAW44 (/MAT/COWPER): Cowper-Symonds elasto-plastic law (reference
//! guide /MAT/LAW44; research notes `docs/notes/fail_johnson_law44_research.md`
//! §B.1–B.2, `docs/notes/law44_isolid12_research.md` §1).
//!
//! Cards after the title:
//! 1. RHO_I (1-20), RHO_0 (21-40)
//! 2. E (1-20), Nu (21-40)
//! 3. a (1-20), b (21-40), n (41-60), Chard (61-80), SIG_max0 (81-100)
//! 4. c (1-20), p (21-40), ICC (41-50), Fsmooth (51-60), F_cut (61-80),
//!    VP (91-100)
//! 5. EPS_p_max (1-20), εt1 (21-40), εt2 (41-60)
//! 6. (optional) fct_IDy (1-10), Fscale_y (21-40)

use super::source::Block;
use super::Deck;
use crate::model::{CowperSymonds, InputResult, MaterialLaw, MaterialSpec, NO_LIMIT};

fn no_limit_if_zero(v: f64) -> f64 {
    if v == 0.0 {
        NO_LIMIT
    } else {
        v
    }
}

/// Reads /MAT/LAW44 or /MAT/COWPER into the deck's materials.
pub(super) fn parse_law44(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let super::material_opening::Opening {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        mut cards,
        c2,
    } = super::material_opening::read_opening(block, "the card with E and Nu")?;
    if !(0.0..0.5).contains(&nu) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in [0, 0.5)")));
    }
    let c3 = cards.next("the card with a, b, n, Chard, SIG_max0")?;
    let c4 = cards.next("the card with c, p, ICC, Fsmooth, F_cut, VP")?;
    let c5 = cards.next_opt();
    let c6 = cards.next_opt();
    let a = c3.real(1, "a", 0.0)?;
    if a < 0.0 {
        return Err(c3.err("a", format!("{a}: the yield stress must be >= 0")));
    }
    let n = c3.real(41, "n", 0.0)?;
    if !(0.0..=1.0).contains(&n) {
        return Err(c3.err("n", format!("{n}: expected a hardening exponent in [0, 1]")));
    }
    let chard = c3.real(61, "Chard", 0.0)?;
    if !(0.0..=1.0).contains(&chard) {
        return Err(c3.err(
            "Chard",
            format!("{chard}: expected 0 (isotropic) to 1 (kinematic)"),
        ));
    }
    let (c, p) = (c4.real(1, "c", 0.0)?, c4.real(21, "p", 0.0)?);
    if c < 0.0 || p < 0.0 {
        return Err(c4.err("c", format!("c = {c}, p = {p}: expected values >= 0")));
    }
    let icc = match c4.int(41, "ICC", 0)? {
        0 => 1,
        v @ (1 | 2) => v,
        v => return Err(c4.err("ICC", format!("{v}: expected 1 or 2"))),
    };
    let vp = match c4.int(91, "VP", 0)? {
        0 => 2,
        v @ 1..=3 => v,
        v => return Err(c4.err("VP", format!("{v}: expected 1, 2 or 3"))),
    };
    let limit = |i: usize, name: &str| -> InputResult<f64> {
        Ok(match c5 {
            Some(c) => no_limit_if_zero(c.real(i, name, 0.0)?),
            None => NO_LIMIT,
        })
    };
    let law = CowperSymonds {
        a,
        b: c3.real(21, "b", 0.0)?,
        n,
        chard,
        sig_max0: no_limit_if_zero(c3.real(81, "SIG_max0", 0.0)?),
        c,
        p: if p == 0.0 { 1.0 } else { p },
        icc,
        fsmooth: c4.int(51, "Fsmooth", 0)?,
        f_cut: c4.real(61, "F_cut", 0.0)?,
        vp,
        eps_p_max: limit(1, "EPS_p_max")?,
        eps_t1: limit(21, "eps_t1")?,
        eps_t2: limit(41, "eps_t2")?,
        fct_idy: match c6 {
            Some(c) => c.id_opt(1, "fct_IDy")?,
            None => 0,
        },
        fscale_y: match c6 {
            Some(c) => c.real(21, "Fscale_y", 0.0)?,
            None => 0.0,
        },
    };
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law: MaterialLaw::CowperSymonds(law),
        failures: Vec::new(),
        loc: block.loc.clone(),
    });
    Ok(())
}
