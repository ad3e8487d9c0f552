//! /MAT/LAW62 (/MAT/VISC_HYP): hyper-visco-elastic Ogden-type law (reference
//! guide /MAT/LAW62; research note `docs/notes/law62_research.md` §1: the
//! reference's configuration file and starter reader).
//!
//! Cards after the title (input versions 51 on; 20-column real fields):
//! 1. RHO_I (1-20), Ref_rho (21-40)
//! 2. Nu (1-20), N (21-30), M (31-40), mu_max (41-60), Flag_Visc (61-70)
//! 3. μ_1 … μ_N, five per line; then α_1 … α_N, five per line
//! 4. when M > 0: γ_1 … γ_M, five per line; then τ_1 … τ_M, five per line
//!
//! Version-44 decks (16- and 8-column fields) are refused by name.

use super::fields::{zero_default as or, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{InputResult, MaterialLaw, MaterialSpec, ViscoHyperelastic};

/// The starter's value for a blank maximum viscosity and a τ_i ≤ 0.
const NONE: f64 = 1e20;

/// `n` reals, five 20-column fields per line, named `name_i` in messages.
fn read_list(cards: &mut Cards, n: usize, name: &str, what: &str) -> InputResult<Vec<f64>> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let c = cards.next(what)?;
        for k in 0..(n - out.len()).min(5) {
            let i = out.len() + 1;
            out.push(c.real(1 + 20 * k, &format!("{name}_{i}"), 0.0)?);
        }
    }
    Ok(out)
}

/// Reads /MAT/LAW62 or /MAT/VISC_HYP into the deck's materials.
pub(super) fn parse_law62(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let id = header_id(block, 2, "mat_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c1 = cards.next("the card with RHO_I (initial density)")?;
    let rho = c1.positive_real(1, "RHO_I", "density")?;
    let rho_ref = c1.real(21, "Ref_rho", 0.0)?;
    let c2 = cards.next("the card with Nu, N, M, mu_max, Flag_Visc")?;
    if deck
        .begin
        .as_ref()
        .is_some_and(|b| b.invers > 0 && b.invers < 51)
    {
        return Err(c2.err(
            "Nu",
            "/MAT/LAW62 in the version-44 format (16- and 8-column fields) is not read; expected an input version of 51 or later",
        ));
    }
    let nu = c2.real(1, "Nu", 0.0)?;
    if !(0.0..=0.5).contains(&nu) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in [0, 0.5)")));
    }
    // The reference starter takes ν ≥ 0.5 as 0.499.
    let nu = nu.min(0.499);
    let n = c2.int(21, "N", 0)?;
    if !(1..=50).contains(&n) {
        return Err(c2.err("N", format!("{n}: the Ogden order must lie in 1..50")));
    }
    let m = c2.int(31, "M", 0)?;
    if !(0..=50).contains(&m) {
        return Err(c2.err("M", format!("{m}: the Maxwell order must lie in 0..50")));
    }
    let mu_max = or(c2.real(41, "mu_max", 0.0)?, NONE);
    let flag_visc = c2.int(61, "Flag_Visc", 0)?;
    let mu = read_list(
        &mut cards,
        n as usize,
        "mu",
        "the card of the shear moduli mu_i",
    )?;
    let alpha = read_list(
        &mut cards,
        n as usize,
        "alpha",
        "the card of the exponents alpha_i",
    )?;
    let alpha: Vec<f64> = alpha.into_iter().map(|a| or(a, 1.0)).collect();
    let (gamma, tau) = if m > 0 {
        let g = read_list(
            &mut cards,
            m as usize,
            "gamma",
            "the card of the stiffness ratios gamma_i",
        )?;
        let t = read_list(
            &mut cards,
            m as usize,
            "tau",
            "the card of the relaxation times tau_i",
        )?;
        (
            g,
            t.into_iter()
                .map(|t| if t > 0.0 { t } else { NONE })
                .collect(),
        )
    } else {
        (Vec::new(), Vec::new())
    };
    let g: f64 = mu.iter().sum();
    if !(g > 0.0) {
        return Err(c2.err(
            "mu_i",
            format!("the initial shear modulus, the sum of the mu_i, is {g}: it must be > 0"),
        ));
    }
    if let Some((i, gi)) = gamma
        .iter()
        .enumerate()
        .find(|(_, g)| !(0.0..=1.0).contains(*g))
    {
        return Err(c2.err(
            &format!("gamma_{}", i + 1),
            format!("{gi}: a stiffness ratio must lie in [0, 1]"),
        ));
    }
    let long_term = 1.0 - gamma.iter().sum::<f64>();
    if !(long_term > 0.0) {
        return Err(c2.err(
            "gamma_i",
            format!(
                "the stiffness ratios sum to {}: the long-term ratio 1 - sum must be > 0",
                1.0 - long_term
            ),
        ));
    }
    super::warn_surplus(&cards, "the last card of /MAT/LAW62", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        // The small-strain equivalents: G = Σμ_i, E = 2G(1 + ν).
        e: 2.0 * g * (1.0 + nu),
        nu,
        law: MaterialLaw::ViscoHyperelastic(ViscoHyperelastic {
            mu,
            alpha,
            gamma,
            tau,
            mu_max,
            flag_visc,
        }),
        failures: Vec::new(),
        loc: block.loc.clone(),
    });
    Ok(())
}
