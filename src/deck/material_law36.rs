//! /MAT/LAW36 (/MAT/PLAS_TAB): tabulated elasto-plastic law (reference guide
//! /MAT/LAW36, 2017 format; research note `docs/notes/law36_research.md` §1).
//!
//! Cards after the title:
//! 1. RHO_I (1-20), RHO_0 (21-40)
//! 2. E (1-20), Nu (21-40), Eps_p_max (41-60), Eps_t (61-80), Eps_m (81-100)
//! 3. N_funct (1-10), F_smooth (11-20), C_hard (21-40), F_cut (41-60),
//!    Eps_f (61-80), VP (91-100)
//! 4. fct_IDp (1-10), Fscale (11-30), Fct_IDE (31-40), EInf (41-60), CE (61-80)
//! 5. ⌈N/5⌉ lines of func_IDs (five 10-column fields), then ⌈N/5⌉ lines of
//!    Fscale_i, then ⌈N/5⌉ lines of Eps_dot_i (five 20-column fields each).

use super::fields::{Card, Cards};
use super::source::Block;
use super::Deck;
use crate::model::{
    Function, InputError, InputResult, MaterialLaw, MaterialSpec, RateCurve, TabulatedPlasticity,
    NO_LIMIT,
};

/// Reads /MAT/LAW36 or /MAT/PLAS_TAB into the deck's materials.
pub(super) fn parse_law36(block: &Block, deck: &mut Deck) -> InputResult<()> {
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
    } = super::material_opening::read_opening(
        block,
        "the card with E, Nu, Eps_p_max, Eps_t, Eps_m",
    )?;
    if !(0.0..=0.5).contains(&nu) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in [0, 0.5]")));
    }
    let nu = if nu == 0.5 { 0.499 } else { nu };
    let limit = |c: &Card, col: usize, name: &str| -> InputResult<f64> {
        let v = c.real(col, name, 0.0)?;
        if v < 0.0 {
            return Err(c.err(name, format!("{v}: expected a strain >= 0 (0: no limit)")));
        }
        Ok(if v == 0.0 { NO_LIMIT } else { v })
    };
    let (eps_p_max, eps_t, eps_m) = (
        limit(&c2, 41, "Eps_p_max")?,
        limit(&c2, 61, "Eps_t")?,
        limit(&c2, 81, "Eps_m")?,
    );
    if eps_t < NO_LIMIT && eps_m < NO_LIMIT && eps_t >= eps_m {
        return Err(c2.err(
            "Eps_m",
            format!("{eps_m}: expected Eps_m > Eps_t = {eps_t}"),
        ));
    }
    let c3 = cards.next("the card with N_funct, F_smooth, C_hard, F_cut, Eps_f, VP")?;
    let n = c3.int(1, "N_funct", 0)?;
    if !(1..=100).contains(&n) {
        return Err(c3.err("N_funct", format!("{n}: expected 1 to 100 yield curves")));
    }
    let fsmooth = c3.flag(11, "F_smooth", 0, &[0, 1, 2])?;
    let chard = c3.real(21, "C_hard", 0.0)?;
    if !(0.0..=1.0).contains(&chard) {
        return Err(c3.err("C_hard", format!("{chard}: expected a value in [0, 1]")));
    }
    let f_cut = c3.real(41, "F_cut", 0.0)?;
    let eps_f = limit(&c3, 61, "Eps_f")?;
    let vp = c3.int(91, "VP", 0)?;
    let c4 = cards.next("the card with fct_IDp, Fscale, Fct_IDE, EInf, CE")?;
    let fct_p = c4.int(1, "fct_IDp", 0)?.max(0) as u64;
    let fscale_p = super::fields::one_if_zero(c4.real(11, "Fscale", 0.0)?);
    let fct_e = c4.int(31, "Fct_IDE", 0)?.max(0) as u64;
    let (e_inf, ce) = (c4.real(41, "EInf", 0.0)?, c4.real(61, "CE", 0.0)?);
    let curves = read_curves(&mut cards, n as usize)?;
    super::warn_surplus(&cards, "the last card of this law", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law: MaterialLaw::Tabulated(TabulatedPlasticity {
            eps_p_max,
            eps_t,
            eps_m,
            eps_f,
            fsmooth,
            chard,
            f_cut,
            vp,
            fct_p,
            fscale_p,
            fct_e,
            e_inf,
            ce,
            curves,
        }),
        failures: vec![],
        loc: block.loc.clone(),
    });
    Ok(())
}

/// The N curves: func_IDs, then Fscale_i, then Eps_dot_i, five per line.
fn read_curves(cards: &mut Cards, n: usize) -> InputResult<Vec<RateCurve>> {
    let lines = n.div_ceil(5);
    let mut fct = Vec::with_capacity(n);
    for _ in 0..lines {
        let c = cards.next("a line of func_ID (five 10-column fields)")?;
        for k in 0..5.min(n - fct.len()) {
            let name = format!("func_ID{}", fct.len() + 1);
            let f = c.int(1 + 10 * k, &name, 0)?;
            if f <= 0 {
                return Err(c.err(&name, format!("{f}: expected the id of a /FUNCT")));
            }
            fct.push(f as u64);
        }
    }
    // Fscale_i (0 → 1), then Eps_dot_i (strictly increasing).
    let mut reals = |what: &str, rates: bool| -> InputResult<Vec<f64>> {
        let mut v: Vec<f64> = Vec::with_capacity(n);
        for _ in 0..lines {
            let c = cards.next(&format!("a line of {what} (five 20-column fields)"))?;
            for k in 0..5.min(n - v.len()) {
                let name = format!("{what}{}", v.len() + 1);
                let x = c.real(1 + 20 * k, &name, 0.0)?;
                if rates && v.last().is_some_and(|&p| x <= p) {
                    return Err(c.err(
                        &name,
                        format!("{x}: the strain rates must increase strictly"),
                    ));
                }
                v.push(if !rates && x == 0.0 { 1.0 } else { x });
            }
        }
        Ok(v)
    };
    let fscale = reals("Fscale_", false)?;
    let rates = reals("Eps_dot_", true)?;
    Ok((0..n)
        .map(|i| RateCurve {
            fct: fct[i],
            fscale: fscale[i],
            eps_dot: rates[i],
            x: Vec::new(),
            y: Vec::new(),
        })
        .collect())
}

/// Copies each LAW36 curve's points from its /FUNCT and resolves F_cut's
/// default (10 kHz in the deck's time unit with several curves, as the
/// starter; LAW44's with Fsmooth too); an unknown function is an error at
/// the material card.
pub(super) fn resolve_curves(
    mats: &mut [MaterialSpec],
    functions: &[Function],
    time_si: f64,
) -> Result<(), InputError> {
    for m in mats.iter_mut() {
        if let MaterialLaw::FoamTab(f) = &mut m.law {
            let kw = format!("/MAT/LAW70/{}", m.id);
            super::material_law70::resolve_foam_curves(f, m.e, functions, &m.loc, &kw)?;
            continue;
        }
        if let MaterialLaw::DruckerPrager(d) = &mut m.law {
            let Some(f) = functions.iter().find(|f| f.id == d.fct) else {
                return Err(InputError::new(
                    m.loc.clone(),
                    &format!("/MAT/LAW21/{}", m.id),
                    "func_IDf",
                    format!(
                        "function {} is not defined in the deck; expected a /FUNCT id",
                        d.fct
                    ),
                ));
            };
            (d.x, d.y) = (f.x.clone(), f.y.clone());
            continue;
        }
        if let MaterialLaw::CowperSymonds(c) = &mut m.law {
            // LAW44: Fsmooth without F_cut filters at 10 kHz.
            if c.fsmooth != 0 && c.f_cut == 0.0 {
                c.f_cut = 1e4 * time_si;
            }
            continue;
        }
        let MaterialLaw::Tabulated(t) = &mut m.law else {
            continue;
        };
        for c in t.curves.iter_mut() {
            let Some(f) = functions.iter().find(|f| f.id == c.fct) else {
                return Err(InputError::new(
                    m.loc.clone(),
                    &format!("/MAT/LAW36/{}", m.id),
                    "func_ID",
                    format!(
                        "function {} is not defined in the deck; expected a /FUNCT id",
                        c.fct
                    ),
                ));
            };
            c.x = f.x.clone();
            c.y = f.y.clone();
        }
        if t.curves.len() > 1 && (t.f_cut == 0.0 || t.vp == 1) {
            t.f_cut = 1e4 * time_si;
        }
    }
    Ok(())
}
