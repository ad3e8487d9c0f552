//! /MAT/LAW27 (/MAT/PLAS_BRIT): Johnson-Cook plasticity with brittle
//! tension damage, for shells (research note `docs/notes/law27_research.md`
//! §1: the reference's configuration file and starter reader; the guide
//! page was not retrievable).
//!
//! Cards after the title (input versions 51 on; 20-column fields):
//! 1. RHO_I (1-20), RHO_0 (21-40)
//! 2. E (1-20), Nu (21-40)
//! 3. a (1-20), b (21-40), n (41-60), [61-80 unused], SIG_max0 (81-100)
//! 4. c (1-20), EPS_DOT_0 (21-40), ICC (41-50)
//! 5. EPS_t1, EPS_m1, d_max1, EPS_f1
//! 6. EPS_t2, EPS_m2, d_max2, EPS_f2
//!
//! Version-41 decks (16-column fields) are refused by name.

use super::fields::zero_default as or;
use super::source::Block;
use super::Deck;
use crate::model::{BrittlePlastic, InputResult, MaterialLaw, MaterialSpec};

/// Reads /MAT/LAW27 or /MAT/PLAS_BRIT into the deck's materials.
pub(super) fn parse_law27(block: &Block, deck: &mut Deck) -> InputResult<()> {
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
    if deck
        .begin
        .as_ref()
        .is_some_and(|b| b.invers > 0 && b.invers < 51)
    {
        return Err(c2.err(
            "E",
            "/MAT/LAW27 in the version-41 format (16-column fields) is not read; expected an input version of 51 or later",
        ));
    }
    if !(-1.0 < nu && nu <= 0.5) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in (-1, 0.5]")));
    }
    // The reference starter takes ν ≥ 0.5 as 0.499.
    let nu = nu.min(0.499);
    let c3 = cards.next("the card with a, b, n, SIG_max0")?;
    let c4 = cards.next("the card with c, EPS_DOT_0, ICC")?;
    let a = or(c3.real(1, "a", 0.0)?, 1e20);
    let b = c3.real(21, "b", 0.0)?;
    let n = or(c3.real(41, "n", 0.0)?, 1.0);
    if a < 0.0 || b < 0.0 {
        return Err(c3.err("a", format!("a = {a}, b = {b}: expected values >= 0")));
    }
    if !(0.0..=1.0).contains(&n) {
        return Err(c3.err(
            "n",
            format!("{n}: the hardening exponent must lie in (0, 1]"),
        ));
    }
    let c = c4.real(1, "c", 0.0)?;
    let eps_dot0 = c4.real(21, "EPS_DOT_0", 0.0)?;
    let eps_dot0 = if c == 0.0 { 1.0 } else { eps_dot0 };
    if eps_dot0 <= 0.0 {
        return Err(c4.err(
            "EPS_DOT_0",
            format!("{eps_dot0}: the reference strain rate must be > 0 when c is given"),
        ));
    }
    let icc = match c4.int(41, "ICC", 0)? {
        0 | 1 => 1,
        2 => 2,
        v => return Err(c4.err("ICC", format!("{v}: expected 1 or 2 (blank: 1)"))),
    };
    let mut crack = [[0.0; 4]; 2];
    for (d, dir) in crack.iter_mut().enumerate() {
        let what = format!(
            "the card with EPS_t{0}, EPS_m{0}, d_max{0}, EPS_f{0}",
            d + 1
        );
        let cd = cards.next(&what)?;
        let name = |f: &str| format!("{f}{}", d + 1);
        let et = or(cd.real(1, &name("EPS_t"), 0.0)?, 1e20);
        let em = or(cd.real(21, &name("EPS_m"), 0.0)?, 1.1e20);
        let dmax = or(cd.real(41, &name("d_max"), 0.0)?, 0.999);
        let ef = or(cd.real(61, &name("EPS_f"), 0.0)?, 1.2e20);
        if em <= et {
            return Err(cd.err(
                &name("EPS_m"),
                format!("{em}: the strain of full damage must exceed EPS_t ({et})"),
            ));
        }
        if !(0.0..1.0).contains(&dmax) {
            return Err(cd.err(&name("d_max"), format!("{dmax}: expected 0 <= d_max < 1")));
        }
        *dir = [et, em, dmax, ef];
    }
    super::warn_surplus(&cards, "the last card of /MAT/LAW27", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law: MaterialLaw::BrittlePlastic(BrittlePlastic {
            a,
            b,
            n,
            sig_max0: or(c3.real(81, "SIG_max0", 0.0)?, 1e20),
            c,
            eps_dot0,
            icc,
            crack,
        }),
        failures: Vec::new(),
        loc: block.loc.clone(),
    });
    Ok(())
}
