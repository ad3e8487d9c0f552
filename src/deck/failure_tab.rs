//! /FAIL/TAB/mat_ID: tabulated failure (reference guide /FAIL/TAB; research
//! note `docs/notes/fail_tab_research.md` §2). No title line.
//!
//! Card layout by input version (the reference's formats 110, 120 and 130):
//! 1. Ifail_sh (1-10), Ifail_so (11-20), N_rate (21-30), then P_thickfail in
//!    41-60 and Ixfem in 91-100 from version 120 on; P_thickfail in 61-80 in
//!    the 110 format (no Ixfem). There is no format below 110: an older deck
//!    is read with the 110 layout and warned about, as the reference starter
//!    does (so a P_thickfail in 41-60 of a version-100 deck is not read; the
//!    warning says so).
//! 2. Dcrit (1-20), D (21-40), n (41-60)
//! 3. N_rate lines: fct_ID_i (1-10), Fscale_i (11-30), ε̇_i (31-50)
//! 4. fct_IDel (1-10), Fscale_el (11-30), EI_ref (31-50)
//! 5. fct_IDt (1-10), FscaleT (11-30)
//! 6. optional fail_ID (1-10), not used.

use super::fields::Cards;
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{FailureModel, Id, InputResult, RateCurve, ScaleCurve, TabFailure, Warning};

/// Reads a /FAIL/TAB card into its model (defaults resolved, curves still
/// without their points).
pub(super) fn read_fail_tab(block: &Block, deck: &mut Deck) -> InputResult<(Id, FailureModel)> {
    let mat_id = header_id(block, 2, "mat_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let invers = deck.begin.as_ref().map_or(0, |b| b.invers);
    let mut cards = Cards::new(block);
    let c1 = cards.next("the card with Ifail_sh, Ifail_so, N_rate, P_thickfail")?;
    let ifail_sh = c1.flag(1, "Ifail_sh", 0, &[0, 1, 2, 3])?;
    let ifail_so = c1.flag(11, "Ifail_so", 0, &[0, 1, 2])?;
    let n_rate = c1.int(21, "N_rate", 0)?;
    let (p_thickfail, ixfem) = if invers >= 120 {
        (c1.real(41, "P_thickfail", 0.0)?, c1.int(91, "Ixfem", 0)?)
    } else {
        let warn = |message: String| Warning {
            loc: c1.loc(),
            keyword: block.header.clone(),
            message,
        };
        if invers < 110 {
            deck.warnings.push(warn(format!(
                "input version {invers}: /FAIL/TAB has no format before 110; read with the 110 layout, as the reference starter does"
            )));
        }
        if !c1.text(31, 30).is_empty() {
            deck.warnings.push(warn(format!(
                "'{}' in columns 31-60 is not a field of the 110 layout (P_thickfail is in 61-80 before version 120): not read",
                c1.text(31, 30)
            )));
        }
        (c1.real(61, "P_thickfail", 0.0)?, 0)
    };
    if ixfem != 0 {
        return Err(c1.err(
            "Ixfem",
            format!("{ixfem}: XFEM crack propagation is not computed; expected 0"),
        ));
    }
    if n_rate < 1 {
        return Err(c1.err(
            "N_rate",
            format!("{n_rate}: expected at least one failure-strain function (N_rate >= 1)"),
        ));
    }
    if !(-1.0..=1.0).contains(&p_thickfail) {
        return Err(c1.err(
            "P_thickfail",
            format!("{p_thickfail}: expected a thickness fraction in [-1, 1]"),
        ));
    }
    let c2 = cards.next("the card with Dcrit, D, n")?;
    let dcrit = c2.real(1, "Dcrit", 0.0)?;
    let d = c2.real(21, "D", 0.0)?;
    let n = c2.real(41, "n", 0.0)?;
    if dcrit < 0.0 || n < 0.0 {
        return Err(c2.err("Dcrit / n", "expected Dcrit >= 0 and n >= 0"));
    }
    let mut rates: Vec<RateCurve> = Vec::new();
    for i in 0..n_rate {
        let c = cards.next(&format!("failure-strain line {} of {n_rate}", i + 1))?;
        let fct = c.int(1, "fct_ID", 0)?;
        let eps_dot = c.real_opt(31, 20, "Epsdot")?.unwrap_or(0.0);
        if fct <= 0 {
            return Err(c.err(
                "fct_ID",
                format!("{fct}: expected the id of a /FUNCT ε_f(η)"),
            ));
        }
        if rates.last().is_some_and(|r| eps_dot <= r.eps_dot) {
            return Err(c.err(
                "Epsdot",
                format!("{eps_dot}: the strain rates must increase from line to line"),
            ));
        }
        rates.push(RateCurve {
            fct: fct as Id,
            fscale: c.real_opt(11, 20, "Fscale")?.unwrap_or(0.0),
            eps_dot,
            x: vec![],
            y: vec![],
        });
    }
    let scale_line = |cards: &mut Cards, what: &str, fs: &str| -> InputResult<(ScaleCurve, f64)> {
        let Some(c) = cards.next_opt() else {
            return Ok((
                ScaleCurve {
                    fct: 0,
                    fscale: 1.0,
                    x: vec![],
                    y: vec![],
                },
                0.0,
            ));
        };
        let fct = c.int(1, what, 0)?;
        if fct < 0 {
            return Err(c.err(what, format!("{fct}: expected a /FUNCT id or 0")));
        }
        let fscale = c.real_opt(11, 20, fs)?.unwrap_or(0.0);
        let fscale = if fscale == 0.0 { 1.0 } else { fscale };
        let third = c.real_opt(31, 20, "EI_ref")?.unwrap_or(0.0);
        let fct = fct as Id;
        Ok((
            ScaleCurve {
                fct,
                fscale,
                x: vec![],
                y: vec![],
            },
            third,
        ))
    };
    let (size, el_ref) = scale_line(&mut cards, "fct_IDel", "Fscale_el")?;
    let (temperature, _) = scale_line(&mut cards, "fct_IDt", "FscaleT")?;
    if let Some(c) = cards.next_opt() {
        c.int(1, "fail_ID", 0)?;
    }
    super::warn_surplus(&cards, "the last card of /FAIL/TAB", &mut deck.warnings);
    let model = FailureModel::Tab(TabFailure {
        ifail_sh: if ifail_sh == 0 { 1 } else { ifail_sh },
        ifail_so: if ifail_so == 0 { 1 } else { ifail_so },
        p_thickfail,
        dcrit: if dcrit == 0.0 { 1.0 } else { dcrit },
        d: if d == 1.0 { 0.999 } else { d },
        n: if n == 0.0 { 1.0 } else { n },
        rates,
        size,
        el_ref: if el_ref == 0.0 { 1.0 } else { el_ref },
        temperature,
    });
    Ok((mat_id, model))
}
