//! /MAT/LAW21 (/MAT/DPRAG): Drucker-Prager for rock, concrete and soil
//! (reference guide /MAT/LAW21; research note `docs/notes/law21_research.md`
//! §1).
//!
//! Cards after the title:
//! 1. RHO_I (1-20), RHO_0 (21-40: the reference density of μ = ρ/ρ₀ − 1)
//! 2. E (1-20), Nu (21-40)
//! 3. A0 (1-20), A1 (21-40), A2 (41-60), Amax (61-80)
//! 4. func_IDf (1-10), Kt (21-40), FscaleP (41-60)
//! 5. P_min (1-20), P_ext (21-40)
//! 6. B (1-20), Mu_max (21-40)

use super::fields::zero_default as or;
use super::source::Block;
use super::Deck;
use crate::model::{DruckerPrager, InputResult, MaterialLaw, MaterialSpec};

/// The starter's "no limit" (it prints 1e20 for blank Amax, Mu_max, −P_min).
const NONE: f64 = 1e20;

/// Reads /MAT/LAW21 or /MAT/DPRAG into the deck's materials.
pub(super) fn parse_law21(block: &Block, deck: &mut Deck) -> InputResult<()> {
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
    if !(-1.0 < nu && nu < 0.5) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in (-1, 0.5)")));
    }
    let c3 = cards.next("the card with A0, A1, A2, Amax")?;
    let c4 = cards.next("the card with func_IDf, Kt, FscaleP")?;
    let c5 = cards.next("the card with P_min, P_ext")?;
    let c6 = cards.next_opt();
    let fct = c4.id_opt(1, "func_IDf")?;
    if fct == 0 {
        return Err(c4.err(
            "func_IDf",
            "blank: expected the /FUNCT of the pressure P(μ) in compression",
        ));
    }
    let kt = c4.real(21, "Kt", 0.0)?;
    if kt <= 0.0 {
        return Err(c4.err("Kt", format!("{kt}: the tension bulk modulus must be > 0")));
    }
    let (b, mu_max) = match c6 {
        Some(c) => (c.real(1, "B", 0.0)?, c.real(21, "Mu_max", 0.0)?),
        None => (0.0, 0.0),
    };
    if b < 0.0 {
        return Err(c4.err("B", format!("{b}: the unloading bulk modulus must be >= 0")));
    }
    let law = DruckerPrager {
        a0: c3.real(1, "A0", 0.0)?,
        a1: c3.real(21, "A1", 0.0)?,
        a2: c3.real(41, "A2", 0.0)?,
        amax: or(c3.real(61, "Amax", 0.0)?, NONE),
        fct,
        fscale_p: or(c4.real(41, "FscaleP", 0.0)?, 1.0),
        kt,
        p_min: or(c5.real(1, "P_min", 0.0)?, -NONE),
        p_ext: c5.real(21, "P_ext", 0.0)?,
        b: or(b, kt),
        mu_max: or(mu_max, NONE),
        x: vec![],
        y: vec![],
    };
    super::warn_surplus(&cards, "the last card of /MAT/LAW21", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law: MaterialLaw::DruckerPrager(law),
        failures: Vec::new(),
        loc: block.loc.clone(),
    });
    Ok(())
}
