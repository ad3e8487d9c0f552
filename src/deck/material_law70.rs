//! /MAT/LAW70 (/MAT/FOAM_TAB): tabulated visco-elastic foam (reference guide
//! /MAT/LAW70; research note `docs/notes/law70_research.md` §1.1). Cards
//! after the title:
//! 1. RHO_I (1-20), RHO_0 (21-40)
//! 2. E0 (1-20), ν (21-40), E_max (41-60), eps_max (61-80), Itens (81-90)
//! 3. Fcut (1-20), Fsmooth/ISRATE (21-30), NL (31-40), NuL (41-50), Iflag
//!    (51-60), Shape (61-80), Hys (81-100)
//! 4. NL loading lines: fct_ID (1-10), strain rate (11-30), Fscale (31-50)
//! 5. NuL unloading lines, the same
//! 6. with Itens > 0: fct_IDT (1-10), FscaleT (11-30)
//!
//! Defaults as the reference starter (note §1.1): eps_max, Shape, Hys and a
//! scale 0 → 1; the first loading rate is 0 (a warning when the card gives
//! another); the rates increase; E_max 0 → the largest slope of the scaled
//! loading curves (resolved with the curves, `resolve_foam_curves`).

use super::fields::{one_if_zero, Cards};
use super::source::Block;
use super::Deck;
use crate::model::{FoamTab, Function, InputError, InputResult, Loc, MaterialLaw, MaterialSpec};
use crate::model::{RateCurve, Warning};

/// Reads /MAT/LAW70 or /MAT/FOAM_TAB into the deck's materials.
pub(super) fn parse_law70(block: &Block, deck: &mut Deck) -> InputResult<()> {
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
        "the card with E0, Nu, E_max, eps_max, Itens",
    )?;
    if !(0.0..0.5).contains(&nu) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in [0, 0.5)")));
    }
    let e_max = c2.real(41, "E_max", 0.0)?;
    if e_max != 0.0 && e_max < e {
        return Err(c2.err(
            "E_max",
            format!("{e_max}: expected E_max >= E0 = {e} (0: the curves' largest slope)"),
        ));
    }
    let eps_max = one_if_zero(c2.real(61, "eps_max", 0.0)?);
    if eps_max < 0.0 {
        return Err(c2.err("eps_max", format!("{eps_max}: expected a strain > 0")));
    }
    let itens = c2.int(81, "Itens", 0)?;
    let c3 = cards.next("the card with Fcut, Fsmooth, NL, NuL, Iflag, Shape, Hys")?;
    let f_cut = c3.real(1, "Fcut", 0.0)?;
    let israte = c3.int(21, "Fsmooth", 0)?;
    let nl = c3.int(31, "NL", 0)?;
    if !(1..=100).contains(&nl) {
        return Err(c3.err("NL", format!("{nl}: expected 1 to 100 loading curves")));
    }
    let nul = c3.int(41, "NuL", 0)?;
    if !(0..=100).contains(&nul) {
        return Err(c3.err("NuL", format!("{nul}: expected 0 to 100 unloading curves")));
    }
    let iflag = c3.flag(51, "Iflag", 0, &[0, 1, 2, 3, 4])?;
    let shape = one_if_zero(c3.real(61, "Shape", 0.0)?);
    let hys = one_if_zero(c3.real(81, "Hys", 0.0)?);
    let mut loading = read_rate_curves(&mut cards, nl as usize, "loading")?;
    if loading[0].eps_dot != 0.0 {
        deck.warnings.push(Warning {
            loc: block.loc.clone(),
            keyword: block.header.clone(),
            message: format!(
                "the first loading curve's strain rate {} is taken as 0, as the reference starter does",
                loading[0].eps_dot
            ),
        });
        loading[0].eps_dot = 0.0;
    }
    let unloading = read_rate_curves(&mut cards, nul as usize, "unloading")?;
    if itens > 0 {
        cards.next("the card with fct_IDT, FscaleT (Itens > 0)")?;
    }
    super::warn_surplus(&cards, "the last card of /MAT/LAW70", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law: MaterialLaw::FoamTab(FoamTab {
            e_max,
            eps_max,
            f_cut,
            israte,
            iflag,
            shape,
            hys,
            itens,
            loading,
            unloading,
        }),
        failures: vec![],
        loc: block.loc.clone(),
    });
    Ok(())
}

/// `n` lines of fct_ID (1-10), strain rate (11-30), Fscale (31-50; 0 → 1),
/// the rates increasing (a repeated function is fine).
fn read_rate_curves(cards: &mut Cards, n: usize, what: &str) -> InputResult<Vec<RateCurve>> {
    let mut out: Vec<RateCurve> = Vec::with_capacity(n);
    for k in 0..n {
        let c = cards.next(&format!(
            "{what} curve {} of {n}: fct_ID, strain rate, Fscale",
            k + 1
        ))?;
        let fct = c.id(1, "fct_ID")?;
        let eps_dot = c.real(11, "strain rate", 0.0)?;
        if out.last().is_some_and(|p| eps_dot <= p.eps_dot) {
            return Err(c.err(
                "strain rate",
                format!("{eps_dot}: the {what} curves' strain rates must increase"),
            ));
        }
        let fscale = one_if_zero(c.real(31, "Fscale", 0.0)?);
        out.push(RateCurve {
            fct,
            fscale,
            eps_dot,
            x: Vec::new(),
            y: Vec::new(),
        });
    }
    Ok(out)
}

/// Copies the points of a LAW70 material's curves from their /FUNCT and
/// resolves E_max 0 (the largest slope of the scaled loading curves, not
/// below E0); an unknown function is an error at the material card.
pub(super) fn resolve_foam_curves(
    f: &mut FoamTab,
    e0: f64,
    functions: &[Function],
    loc: &Loc,
    kw: &str,
) -> InputResult<()> {
    for c in f.loading.iter_mut().chain(f.unloading.iter_mut()) {
        let Some(func) = functions.iter().find(|g| g.id == c.fct) else {
            return Err(InputError::new(
                loc.clone(),
                kw,
                "fct_ID",
                format!(
                    "function {} is not defined in the deck; expected a /FUNCT id",
                    c.fct
                ),
            ));
        };
        (c.x, c.y) = (func.x.clone(), func.y.clone());
    }
    if f.e_max == 0.0 {
        let mut s = e0;
        for c in &f.loading {
            for i in 1..c.x.len() {
                let dx = c.x[i] - c.x[i - 1];
                if dx > 0.0 {
                    s = s.max(c.fscale * (c.y[i] - c.y[i - 1]) / dx);
                }
            }
        }
        f.e_max = s;
    }
    Ok(())
}
