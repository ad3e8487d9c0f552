//! `*MAT_ELASTIC` (MAT_001), `*MAT_PLASTIC_KINEMATIC` (MAT_003) and
//! `*MAT_JOHNSON_COOK` (MAT_015) → the material of the same id (keyword
//! manual volume II).
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
use crate::model::{CowperSymonds, InputResult, JohnsonCook, MaterialLaw, MaterialSpec, NO_LIMIT};

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

/// `*MAT_JOHNSON_COOK` (MAT_015) on shells: card 1 MID RO G E PR DTF VP
/// RATEOP, card 2 A B N C M TM TR EPSO, card 3 CP PC SPALL IT D1 D2 D3 D4,
/// card 4 D5 C2/P/XNP EROD EFMIN NUMINT. σ_y = (A + B·ε_p^N)·(1 +
/// C·ln(ε̇/EPSO))·(1 − T*^M) is /MAT/LAW2 (reference guide /MAT/LAW2) with
/// ρ·C_p = RO·CP for the adiabatic heating; no thermal term without M and
/// TM. The damage constants D1–D5 (failure), the viscoplastic and other
/// rate options, erosion and the solid's pressure cut-off are refused by
/// name.
pub fn johnson_cook(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std.clone(), "card 1: MID RO G E PR DTF VP RATEOP")?;
        let id = c.id(0, "MID")?;
        let rho = c.real(1, "RO", 0.0)?;
        let g = c.real(2, "G", 0.0)?;
        let nu = c.real(4, "PR", 0.0)?;
        let e = match c.real(3, "E", 0.0)? {
            e if e > 0.0 => e,
            _ => 2.0 * g * (1.0 + nu),
        };
        if rho <= 0.0 || e <= 0.0 || !(-1.0..0.5).contains(&nu) {
            return Err(c.err(
                "RO, G, E, PR",
                format!(
                    "RO {rho}, E {e}, PR {nu}: expected RO > 0, E (or G) > 0 and -1 < PR < 0.5"
                ),
            ));
        }
        for (i, name) in [(5, "DTF"), (6, "VP"), (7, "RATEOP")] {
            if c.real(i, name, 0.0)? != 0.0 {
                ctx.refuse(&c.loc(), &kw, format!("field {name} (material {id})"));
            }
        }
        let c2 = cards.next(std.clone(), "card 2: A B N C M TM TR EPSO")?;
        let (a, bb, n) = (
            c2.real(0, "A", 0.0)?,
            c2.real(1, "B", 0.0)?,
            c2.real(2, "N", 0.0)?,
        );
        if a <= 0.0 {
            return Err(c2.err("A", format!("{a}: expected the yield stress > 0")));
        }
        let rate_c = c2.real(3, "C", 0.0)?;
        let (m, tm, tr) = (
            c2.real(4, "M", 0.0)?,
            c2.real(5, "TM", 0.0)?,
            c2.real(6, "TR", 0.0)?,
        );
        let epso = c2.real(7, "EPSO", 0.0)?;
        if rate_c != 0.0 && epso <= 0.0 {
            return Err(c2.err(
                "EPSO",
                format!("{epso}: with C, expected the reference strain rate > 0"),
            ));
        }
        let c3 = cards.next(std.clone(), "card 3: CP PC SPALL IT D1 D2 D3 D4")?;
        let cp = c3.real(0, "CP", 0.0)?;
        for (i, name) in [
            (1, "PC"),
            (2, "SPALL"),
            (3, "IT"),
            (4, "D1"),
            (5, "D2"),
            (6, "D3"),
            (7, "D4"),
        ] {
            if c3.real(i, name, 0.0)? != 0.0 {
                ctx.refuse(&c3.loc(), &kw, format!("field {name} (material {id})"));
            }
        }
        if let Some(c4) = cards.next_opt(std) {
            for (i, name) in [
                (0, "D5"),
                (1, "C2/P/XNP"),
                (2, "EROD"),
                (3, "EFMIN"),
                (4, "NUMINT"),
            ] {
                if c4.real(i, name, 0.0)? != 0.0 {
                    ctx.refuse(&c4.loc(), &kw, format!("field {name} (material {id})"));
                }
            }
        }
        let thermal = m != 0.0 && tm > 0.0;
        let law = MaterialLaw::JohnsonCook(JohnsonCook {
            c: rate_c,
            eps_dot_0: if rate_c == 0.0 { 1.0 } else { epso },
            m: if thermal { m } else { 1.0 },
            t_melt: if thermal { tm } else { NO_LIMIT },
            rho_cp: if cp > 0.0 { rho * cp } else { NO_LIMIT },
            // Without a thermal term T* is 0 whatever T_r: the blank card's 298.
            t_r: if thermal { tr } else { 298.0 },
            ..JohnsonCook::hardening(a, bb, n)
        });
        ctx.deck
            .materials
            .push(material(id, title, rho, e, nu, law, c.loc()));
    }
    Ok(())
}
