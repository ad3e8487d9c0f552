//! /MAT/LAW1 (/MAT/ELAST) and /MAT/LAW2 (/MAT/PLAS_JOHNS); /MAT/LAW36 in
//! `material_law36.rs`, /MAT/LAW44 in `material_law44.rs`, /MAT/LAW21 in
//! `material_law21.rs`, /MAT/LAW27 in `material_law27.rs`, /MAT/LAW62 in
//! `material_law62.rs`, /MAT/LAW70 in `material_law70.rs`.
//! Other laws are reported as unsupported (the caller warns, or fails with --strict).

use super::source::Block;
use super::Deck;
use crate::model::{InputResult, JohnsonCook, MaterialLaw, MaterialSpec, NO_LIMIT};

/// Returns false for a law this reader does not support.
pub(super) fn parse_material(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let law = block.parts.get(1).map(String::as_str).unwrap_or("");
    let is_elastic = matches!(law, "LAW1" | "ELAST");
    let is_jc = matches!(law, "LAW2" | "PLAS_JOHNS");
    if matches!(law, "LAW36" | "PLAS_TAB") {
        super::material_law36::parse_law36(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW21" | "DPRAG") {
        super::material_law21::parse_law21(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW27" | "PLAS_BRIT") {
        super::material_law27::parse_law27(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW62" | "VISC_HYP") {
        super::material_law62::parse_law62(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW12" | "3D_COMP") {
        super::material_law12::parse_law12(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW70" | "FOAM_TAB") {
        super::material_law70::parse_law70(block, deck)?;
        return Ok(true);
    }
    if matches!(law, "LAW44" | "COWPER") {
        super::material_law44::parse_law44(block, deck)?;
        return Ok(true);
    }
    if !is_elastic && !is_jc {
        return Ok(false);
    }
    // Card 1: RHO_I (1-20), RHO_0 (21-40); card 2: E (1-20), Nu (21-40), [LAW2: Iflag (41-50)]
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
    } = super::material_opening::read_opening(block, "the card with E (Young's modulus) and Nu")?;
    if !(-1.0 < nu && nu <= 0.5) {
        return Err(c2.err("Nu", format!("{nu}: Poisson's ratio must lie in (-1, 0.5]")));
    }
    // As the Radioss starter does: ν = 0.5 is taken as 0.499 (incompressible limit).
    let nu = if nu == 0.5 { 0.499 } else { nu };
    let law = if is_elastic {
        MaterialLaw::Elastic
    } else {
        let iflag = c2.flag(41, "Iflag", 0, &[0, 1])?;
        // Card 3: a|σ_y (1-20), b|UTS (21-40), n|ε_UTS (41-60), EPS_p_max (61-80), SIG_max0 (81-100)
        let c3 = cards.next("the card with a, b, n, EPS_p_max, SIG_max0")?;
        let v1 = c3.real(1, if iflag == 0 { "a" } else { "SIG_Y" }, 0.0)?;
        let v2 = c3.real(21, if iflag == 0 { "b" } else { "UTS" }, 0.0)?;
        let v3 = c3.real(41, if iflag == 0 { "n" } else { "EPS_UTS" }, 0.0)?;
        let eps_p_max = no_limit_if_zero(c3.real(61, "EPS_p_max", 0.0)?);
        let sig_max0 = no_limit_if_zero(c3.real(81, "SIG_max0", 0.0)?);
        if v1 < 0.0 {
            return Err(c3.err(
                if iflag == 0 { "a" } else { "SIG_Y" },
                format!("{v1}: yield stress must be >= 0"),
            ));
        }
        if eps_p_max < 0.0 {
            return Err(c3.err(
                "EPS_p_max",
                format!("{eps_p_max}: failure strain must be >= 0"),
            ));
        }
        let (a, b, n) = if iflag == 0 {
            // n = 0 → 1 (linear hardening), as the reference guide's default.
            let n = if v3 == 0.0 { 1.0 } else { v3 };
            (v1, v2, n)
        } else {
            // Iflag = 1: (σ_y, UTS, ε_UTS) are engineering values at the ultimate
            // point; with Rm = UTS·(1+ε_UTS) and Ag = ln(1+ε_UTS) the curve
            // σ = a + b·ε_p^n passes through (Ag, Rm) with zero slope of the
            // engineering curve there: n = Rm·Ag/(Rm − a), b = Rm/(n·Ag^(n−1)).
            let (sig_y, uts) = (v1, v2);
            let eps_uts = if v3 == 0.0 { 1.0 } else { v3 };
            if !(uts > sig_y && eps_uts > 0.0) {
                return Err(c3.err("UTS", format!(
                    "UTS = {uts}, EPS_UTS = {eps_uts}: with Iflag = 1 expected UTS > SIG_Y and EPS_UTS > 0"
                )));
            }
            let rm = uts * (1.0 + eps_uts);
            let ag = (1.0 + eps_uts).ln();
            let n = rm * ag / (rm - sig_y);
            if n > 1.0 {
                // Reference guide: n is limited to 1, b from the secant through the UTS point.
                let b = (rm - sig_y) / (ag - rm / e - sig_y / e);
                (sig_y, b, 1.0)
            } else {
                (sig_y, rm / (n * ag.powf(n - 1.0)), n)
            }
        };
        if n > 1.0 {
            return Err(c3.err("n", format!("{n}: the hardening exponent must be <= 1")));
        }
        // Card 4: c (1-20), EPS_DOT_0 (21-40), ICC (41-50), Fsmooth (51-60), F_cut (61-80), Chard (81-100)
        let c4 = cards.next("the card with c, EPS_DOT_0, ICC, Fsmooth, F_cut, Chard")?;
        let c = c4.real(1, "c", 0.0)?;
        let eps_dot_0 = c4.real(21, "EPS_DOT_0", 0.0)?;
        if c < 0.0 {
            return Err(c4.err(
                "c",
                format!("{c}: the strain-rate coefficient must be >= 0"),
            ));
        }
        if c != 0.0 && eps_dot_0 <= 0.0 {
            return Err(c4.err("EPS_DOT_0", format!(
                "{eps_dot_0}: the reference strain rate must be > 0 when the strain-rate coefficient c = {c} is given"
            )));
        }
        let icc = c4.int(41, "ICC", 0)?;
        let icc = match icc {
            0 | 1 => 1,
            2 => 2,
            v => return Err(c4.err("ICC", format!("{v}: expected 0, 1 or 2"))),
        };
        // With no rate term the reference strain rate is irrelevant: 1, as Radioss prints.
        let eps_dot_0 = if c == 0.0 { 1.0 } else { eps_dot_0 };
        let fsmooth = c4.flag(51, "Fsmooth", 0, &[0, 1])?;
        let f_cut = no_limit_if_zero(c4.real(61, "F_cut", 0.0)?);
        let chard = c4.real(81, "Chard", 0.0)?;
        if !(0.0..=1.0).contains(&chard) {
            return Err(c4.err("Chard", format!("{chard}: expected a value in [0, 1]")));
        }
        // Card 5: m (1-20), T_melt (21-40), rhoC_p (41-60), T_r (61-80) — optional in old decks
        let (m, t_melt, rho_cp, t_r) = match cards.next_opt() {
            Some(c5) => (
                super::fields::one_if_zero(c5.real(1, "m", 0.0)?),
                no_limit_if_zero(c5.real(21, "T_melt", 0.0)?),
                no_limit_if_zero(c5.real(41, "rhoC_p", 0.0)?),
                c5.real(61, "T_r", 0.0)?,
            ),
            None => (1.0, NO_LIMIT, NO_LIMIT, 0.0),
        };
        let t_r = if t_r <= 0.0 { 298.0 } else { t_r };
        MaterialLaw::JohnsonCook(JohnsonCook {
            iflag,
            a,
            b,
            n,
            eps_p_max,
            sig_max0,
            c,
            eps_dot_0,
            icc,
            fsmooth,
            f_cut,
            chard,
            m,
            t_melt,
            rho_cp,
            t_r,
        })
    };
    super::warn_surplus(&cards, "the last card of this law", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        e,
        nu,
        law,
        failures: vec![],
        loc: block.loc.clone(),
    });
    Ok(true)
}

fn no_limit_if_zero(v: f64) -> f64 {
    super::fields::zero_default(v, NO_LIMIT)
}
