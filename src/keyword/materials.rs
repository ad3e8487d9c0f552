//! `*MAT_ELASTIC` (MAT_001) and `*MAT_PLASTIC_KINEMATIC` (MAT_003) → the
//! material of the same id (keyword manual volume II).
//!
//! MAT_003 is bilinear plasticity with Cowper-Symonds rate scaling:
//! σ_y = (SIGY + E_p·ε_p)·(1 + (ε̇/C)^(1/P)), E_p = E·ETAN/(E − ETAN), with
//! mixed hardening BETA (1 isotropic, 0 kinematic) and erosion at the
//! effective plastic strain FS. That is /MAT/LAW44 (/MAT/COWPER) with
//! a = SIGY, b = E_p, n = 1, Chard = 1 − BETA, c = C, p = P and
//! EPS_p_max = FS (reference guide /MAT/LAW44).

use super::card::Cards;
use super::sections::title;
use super::source::Block;
use super::Ctx;
use crate::model::{CowperSymonds, InputResult, MaterialLaw, MaterialSpec, NO_LIMIT};

/// MID RO E PR DA DB K.
pub fn elastic(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std, "the card MID RO E PR DA DB K")?;
        let (id, rho, e, nu) = common(&c)?;
        for (i, name) in [(4, "DA"), (5, "DB"), (6, "K")] {
            if c.real(i, name, 0.0)? != 0.0 {
                ctx.refuse(&c.loc(), &kw, format!("field {name} (material {id})"));
            }
        }
        ctx.deck.materials.push(material(
            id,
            title,
            rho,
            e,
            nu,
            MaterialLaw::Elastic,
            c.loc(),
        ));
    }
    Ok(())
}

/// Card 1: MID RO E PR SIGY ETAN BETA; card 2: SRC SRP FS VP.
pub fn plastic_kinematic(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std.clone(), "the card MID RO E PR SIGY ETAN BETA")?;
        let (id, rho, e, nu) = common(&c)?;
        let sigy = c.real(4, "SIGY", 0.0)?;
        if sigy <= 0.0 {
            return Err(c.err("SIGY", format!("{sigy}: expected the yield stress > 0")));
        }
        let etan = c.real(5, "ETAN", 0.0)?;
        if !(0.0..e).contains(&etan) {
            return Err(c.err(
                "ETAN",
                format!("{etan}: expected a tangent modulus from 0 to below E = {e}"),
            ));
        }
        let beta = c.real(6, "BETA", 0.0)?;
        if !(0.0..=1.0).contains(&beta) {
            return Err(c.err(
                "BETA",
                format!("{beta}: expected 0 (kinematic) to 1 (isotropic)"),
            ));
        }
        // Card 2 may be left out (all defaults).
        let (src, srp, fs, vp) = match cards.next_opt(std) {
            Some(d) => (
                d.real(0, "SRC", 0.0)?,
                d.real(1, "SRP", 0.0)?,
                d.real(2, "FS", 0.0)?,
                d.real(3, "VP", 0.0)?,
            ),
            None => (0.0, 0.0, 0.0, 0.0),
        };
        if src != 0.0 && srp <= 0.0 {
            return Err(c.err(
                "SRP",
                "with SRC, expected the Cowper-Symonds exponent P > 0",
            ));
        }
        let law = MaterialLaw::CowperSymonds(CowperSymonds {
            a: sigy,
            b: e * etan / (e - etan),
            n: 1.0,
            chard: 1.0 - beta,
            sig_max0: NO_LIMIT,
            c: src,
            p: if src == 0.0 { 1.0 } else { srp },
            icc: 1,
            fsmooth: 0,
            f_cut: NO_LIMIT,
            // VP 0: the rate of the total strain scales the yield stress;
            // VP 1: viscoplastic, the plastic strain rate.
            vp: if vp == 1.0 { 1 } else { 2 },
            eps_p_max: if fs > 0.0 { fs } else { NO_LIMIT },
            eps_t1: NO_LIMIT,
            eps_t2: NO_LIMIT,
            fct_idy: 0,
            fscale_y: 1.0,
        });
        ctx.deck
            .materials
            .push(material(id, title, rho, e, nu, law, c.loc()));
    }
    Ok(())
}

/// MID RO E PR, checked.
fn common(c: &super::card::Card) -> InputResult<(u64, f64, f64, f64)> {
    let id = c.id(0, "MID")?;
    let rho = c.real(1, "RO", 0.0)?;
    if rho <= 0.0 {
        return Err(c.err("RO", format!("{rho}: expected the density > 0")));
    }
    let e = c.real(2, "E", 0.0)?;
    if e <= 0.0 {
        return Err(c.err("E", format!("{e}: expected Young's modulus > 0")));
    }
    let nu = c.real(3, "PR", 0.0)?;
    if !(-1.0..0.5).contains(&nu) {
        return Err(c.err("PR", format!("{nu}: expected Poisson's ratio in (-1, 0.5)")));
    }
    Ok((id, rho, e, nu))
}

fn material(
    id: u64,
    title: String,
    rho: f64,
    e: f64,
    nu: f64,
    law: MaterialLaw,
    loc: crate::model::Loc,
) -> MaterialSpec {
    MaterialSpec {
        id,
        unit_id: 0,
        title,
        rho,
        rho_ref: 0.0,
        e,
        nu,
        law,
        failures: Vec::new(),
        loc,
    }
}
