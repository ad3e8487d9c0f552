//! `*MAT_ELASTIC` (MAT_001), `*MAT_PLASTIC_KINEMATIC` (MAT_003),
//! `*MAT_JOHNSON_COOK` (MAT_015) and `*MAT_PIECEWISE_LINEAR_PLASTICITY`
//! (MAT_024) → the material of the same id (keyword manual volume II).
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
use crate::model::{
    CowperSymonds, InputResult, JohnsonCook, MaterialLaw, MaterialSpec, RateCurve,
    TabulatedPlasticity, NO_LIMIT,
};

/// MID RO E PR DA DB K.
pub fn elastic(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std, "the card MID RO E PR DA DB K")?;
        let (id, rho, e, nu) = common(&c)?;
        let whose = format!(" (material {id})");
        ctx.refuse_given(&c, &kw, &[(4, "DA"), (5, "DB"), (6, "K")], &whose, false)?;
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
            chard: 1.0 - beta,
            c: src,
            p: if src == 0.0 { 1.0 } else { srp },
            // VP 0: the rate of the total strain scales the yield stress;
            // VP 1: viscoplastic, the plastic strain rate.
            vp: if vp == 1.0 { 1 } else { 2 },
            eps_p_max: if fs > 0.0 { fs } else { NO_LIMIT },
            ..bilinear(sigy, e * etan / (e - etan))
        });
        ctx.deck
            .materials
            .push(material(id, title, rho, e, nu, law, c.loc()));
    }
    Ok(())
}

/// MID RO E PR, checked.
pub(super) fn common(c: &super::card::Card) -> InputResult<(u64, f64, f64, f64)> {
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

pub(super) fn material(
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
        let whose = format!(" (material {id})");
        ctx.refuse_given(
            &c,
            &kw,
            &[(5, "DTF"), (6, "VP"), (7, "RATEOP")],
            &whose,
            false,
        )?;
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
        let damage = [
            (1, "PC"),
            (2, "SPALL"),
            (3, "IT"),
            (4, "D1"),
            (5, "D2"),
            (6, "D3"),
            (7, "D4"),
        ];
        ctx.refuse_given(&c3, &kw, &damage, &whose, false)?;
        if let Some(c4) = cards.next_opt(std) {
            let more = [
                (0, "D5"),
                (1, "C2/P/XNP"),
                (2, "EROD"),
                (3, "EFMIN"),
                (4, "NUMINT"),
            ];
            ctx.refuse_given(&c4, &kw, &more, &whose, false)?;
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

/// `*MAT_PIECEWISE_LINEAR_PLASTICITY` (MAT_024): card 1 MID RO E PR SIGY
/// ETAN FAIL TDEL, card 2 C P LCSS LCSR VP, cards 3–4 EPS1–8 and ES1–8.
/// The yield stress against the effective plastic strain is the curve
/// LCSS, else the points (EPSi, ESi), which become /MAT/LAW36 with that one
/// curve (reference guide /MAT/LAW36: σ_y = f(ε_p), extended with its last
/// slope); without either it is bilinear, SIGY + E·ETAN/(E − ETAN)·ε_p,
/// with Cowper-Symonds rate scaling (C, P): /MAT/LAW44 with n = 1, as
/// MAT_003. FAIL (> 0) is the plastic strain at failure. A rate curve
/// (LCSR), Cowper-Symonds on a curve, a table LCSS, FAIL < 0 and TDEL are
/// refused by name.
pub fn piecewise_linear(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std.clone(), "card 1: MID RO E PR SIGY ETAN FAIL TDEL")?;
        let (id, rho, e, nu) = common(&c)?;
        let (sigy, etan) = (c.real(4, "SIGY", 0.0)?, c.real(5, "ETAN", 0.0)?);
        let fail = c.real(6, "FAIL", 0.0)?;
        if fail < 0.0 {
            ctx.refuse(
                &c.loc(),
                &kw,
                format!("FAIL < 0 (a user failure subroutine, material {id})"),
            );
        }
        if c.real(7, "TDEL", 0.0)? != 0.0 {
            ctx.refuse(&c.loc(), &kw, format!("field TDEL (material {id})"));
        }
        let eps_p_max = if fail > 0.0 { fail } else { NO_LIMIT };
        let c2 = cards.next(std.clone(), "card 2: C P LCSS LCSR VP")?;
        let (rc, rp) = (c2.real(0, "C", 0.0)?, c2.real(1, "P", 0.0)?);
        let lcss = c2.id_opt(2, "LCSS")?;
        if c2.id_opt(3, "LCSR")? != 0 {
            ctx.refuse(&c2.loc(), &kw, format!("field LCSR (material {id})"));
        }
        let vp = c2.real(4, "VP", 0.0)?;
        let (c3, c4) = (cards.next_opt(std.clone()), cards.next_opt(std));
        let mut points = Vec::new();
        if let (Some(c3), Some(c4)) = (&c3, &c4) {
            for i in 0..8 {
                let (x, y) = (c3.real(i, "EPS", 0.0)?, c4.real(i, "ES", 0.0)?);
                if (x != 0.0 || y != 0.0) && points.last().is_some_and(|&(p, _)| x <= p) {
                    return Err(c3.err(
                        &format!("EPS{}", i + 1),
                        format!("{x}: expected increasing plastic strains"),
                    ));
                }
                if y > 0.0 {
                    points.push((x, y));
                }
            }
        }
        let law = if lcss == 0 && points.is_empty() {
            if sigy <= 0.0 || !(0.0..e).contains(&etan) {
                return Err(c.err("SIGY, ETAN", format!("SIGY {sigy}, ETAN {etan}: without LCSS or EPS/ES, expected SIGY > 0 and 0 <= ETAN < E")));
            }
            MaterialLaw::CowperSymonds(CowperSymonds {
                c: rc,
                p: if rc == 0.0 { 1.0 } else { rp },
                vp: if vp == 1.0 { 1 } else { 2 },
                eps_p_max,
                ..bilinear(sigy, e * etan / (e - etan))
            })
        } else {
            if rc != 0.0 || rp != 0.0 {
                ctx.refuse(
                    &c2.loc(),
                    &kw,
                    format!("C and P with a yield curve (material {id})"),
                );
            }
            let fct = if lcss != 0 {
                lcss
            } else {
                let f = ctx.own_id();
                let (x, y) = points.into_iter().unzip();
                ctx.deck.functions.push(crate::model::Function {
                    id: f,
                    title: format!("{kw} {id}: EPS/ES"),
                    x,
                    y,
                    loc: c2.loc(),
                });
                f
            };
            MaterialLaw::Tabulated(TabulatedPlasticity {
                eps_p_max,
                eps_t: NO_LIMIT,
                eps_m: NO_LIMIT,
                eps_f: NO_LIMIT,
                fsmooth: 0,
                chard: 0.0,
                f_cut: 0.0,
                vp: if vp == 1.0 { 1 } else { 2 },
                fct_p: 0,
                fscale_p: 1.0,
                fct_e: 0,
                e_inf: 0.0,
                ce: 0.0,
                curves: vec![RateCurve {
                    fct,
                    fscale: 1.0,
                    eps_dot: 0.0,
                    x: Vec::new(),
                    y: Vec::new(),
                }],
            })
        };
        ctx.deck
            .materials
            .push(material(id, title, rho, e, nu, law, c.loc()));
    }
    Ok(())
}

/// σ_y = a + b·ε_p, isotropic, no rate, no failure (LAW44's fields).
fn bilinear(a: f64, b: f64) -> CowperSymonds {
    CowperSymonds {
        a,
        b,
        n: 1.0,
        chard: 0.0,
        sig_max0: NO_LIMIT,
        c: 0.0,
        p: 1.0,
        icc: 1,
        fsmooth: 0,
        f_cut: NO_LIMIT,
        vp: 2,
        eps_p_max: NO_LIMIT,
        eps_t1: NO_LIMIT,
        eps_t2: NO_LIMIT,
        fct_idy: 0,
        fscale_y: 1.0,
    }
}
