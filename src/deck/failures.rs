//! /FAIL/JOHNSON (Johnson-Cook failure), /FAIL/TAB (tabulated failure,
//! `failure_tab.rs`) and /FAIL/HASHIN, attached to the material of the same id. Other failure
//! models stay unsupported (the keyword policy refuses them by name).
//!
//! Card (reference guide /FAIL/JOHNSON, no title line):
//! 1. D1 (1-20), D2 (21-40), D3 (41-60), D4 (61-80), D5 (81-100)
//! 2. ε̇₀ (1-20), Ifail_sh (21-30), Ifail_so (31-40), EPSF_MIN (41-60, 2024
//!    format; blank before), Dadv (61-80), Ixfem (91-100)
//! 3. optional: FAILIP (2025) or fail_ID, neither changes a solid's
//!    failure (FAILIP counts in-plane points of multi-point shells).

use super::fields::Cards;
use super::id_index::IdIndex;
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{
    FailureModel, FailureSpec, Function, Id, InputError, InputResult, JohnsonFailure, Loc,
    MaterialSpec, TabFailure,
};

/// /FAIL/HASHIN (research note `docs/notes/law12_research.md` §3.1): the
/// first card Iform (1-10), Ifail_sh (11-20), Ifail_so (21-30); the
/// strengths that follow set the criteria, which change the solution only
/// with Ifail_so > 0 (refused by the engine, with shells).
fn read_fail_hashin(block: &Block) -> InputResult<(Id, FailureModel)> {
    let mat_id = header_id(block, 2, "mat_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let c1 = cards.next("the card with Iform, Ifail_sh, Ifail_so")?;
    let iform = c1.flag(1, "Iform", 1, &[0, 1, 2])?;
    let ifail_sh = c1.flag(11, "Ifail_sh", 0, &[0, 1, 2])?;
    let ifail_so = c1.flag(21, "Ifail_so", 0, &[0, 1, 2])?;
    // The strengths (three more cards) are the criteria's only.
    while cards.next_opt().is_some() {}
    Ok((
        mat_id,
        FailureModel::Hashin(crate::model::HashinFailure {
            iform: if iform == 0 { 1 } else { iform },
            ifail_sh,
            ifail_so,
        }),
    ))
}

/// A failure card read, before it is attached to its material.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct FailureCard {
    pub mat_id: crate::model::Id,
    pub spec: FailureSpec,
}

/// Reads /FAIL/JOHNSON, /FAIL/TAB and /FAIL/HASHIN (/mat_ID); false for
/// another failure model.
pub(super) fn parse_failure(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let (mat_id, model) = match block.parts.get(1).map(String::as_str) {
        Some("JOHNSON") => read_fail_johnson(block, deck)?,
        Some("TAB") => super::failure_tab::read_fail_tab(block, deck)?,
        Some("HASHIN") => read_fail_hashin(block)?,
        _ => return Ok(false),
    };
    deck.failures.push(FailureCard {
        mat_id,
        spec: FailureSpec {
            model,
            loc: block.loc.clone(),
        },
    });
    Ok(true)
}

/// /FAIL/JOHNSON (the card of the module doc).
fn read_fail_johnson(block: &Block, deck: &mut Deck) -> InputResult<(Id, FailureModel)> {
    let mat_id = header_id(block, 2, "mat_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let c1 = cards.next("the card with D1, D2, D3, D4, D5")?;
    let mut d = [0.0; 5];
    for (k, v) in d.iter_mut().enumerate() {
        *v = c1.real(1 + 20 * k, &format!("D{}", k + 1), 0.0)?;
    }
    let (mut eps_dot_0, mut ifail_sh, mut ifail_so, mut epsf_min, mut ixfem) = (0.0, 0, 0, 0.0, 0);
    if let Some(c2) = cards.next_opt() {
        eps_dot_0 = c2.real(1, "EPS_0", 0.0)?;
        ifail_sh = c2.flag(21, "Ifail_sh", 0, &[0, 1, 2])?;
        ifail_so = c2.flag(31, "Ifail_so", 0, &[0, 1, 2, 3, 4])?;
        epsf_min = c2.real(41, "EPSF_MIN", 0.0)?;
        ixfem = c2.int(91, "Ixfem", 0)?;
        if eps_dot_0 < 0.0 {
            return Err(c2.err(
                "EPS_0",
                format!("{eps_dot_0}: the reference strain rate must be >= 0"),
            ));
        }
    }
    // Line 3 (FAILIP or fail_ID) and a last fail_ID line: read, not used.
    for _ in 0..2 {
        if let Some(c) = cards.next_opt() {
            c.int(1, "FAILIP / fail_ID", 0)?;
        }
    }
    super::warn_surplus(&cards, "the last card of /FAIL/JOHNSON", &mut deck.warnings);
    let model = FailureModel::Johnson(JohnsonFailure {
        d,
        // Starter defaults: ε̇₀ 0 → 1e-20; Ifail_sh, Ifail_so 0 → 1; Ixfem not 1, 2 → 0.
        eps_dot_0: if eps_dot_0 == 0.0 { 1e-20 } else { eps_dot_0 },
        ifail_sh: if ifail_sh == 0 { 1 } else { ifail_sh },
        ifail_so: if ifail_so == 0 { 1 } else { ifail_so },
        epsf_min,
        ixfem: if matches!(ixfem, 1 | 2) { ixfem } else { 0 },
    });
    Ok((mat_id, model))
}

/// The deck's materials with their failure cards attached (the curves of a
/// /FAIL/TAB filled from their /FUNCT); a card whose material or function
/// is not defined is an error at the card.
pub(super) fn materials_with_failures(deck: &Deck) -> Result<Vec<MaterialSpec>, InputError> {
    let mut mats = deck.materials.clone();
    let index = IdIndex::build(
        "material",
        deck.materials.iter().map(|m| (m.id, m.loc.clone())),
        "/MAT",
    )?;
    for f in &deck.failures {
        let kw = match f.spec.model {
            FailureModel::Johnson(_) => "/FAIL/JOHNSON",
            FailureModel::Tab(_) => "/FAIL/TAB",
            FailureModel::Hashin(_) => "/FAIL/HASHIN",
        };
        let m = index.resolve(f.mat_id, &f.spec.loc, kw, "mat_ID")?;
        let mut spec = f.spec.clone();
        if let FailureModel::Tab(t) = &mut spec.model {
            let kw = format!("/FAIL/TAB/{}", f.mat_id);
            fill_tab_curves(t, &deck.functions, &spec.loc, &kw)?;
        }
        mats[m as usize].failures.push(spec);
    }
    Ok(mats)
}

/// Copies the points of a /FAIL/TAB's functions into its curves.
fn fill_tab_curves(
    t: &mut TabFailure,
    functions: &[Function],
    loc: &Loc,
    kw: &str,
) -> InputResult<()> {
    let points = |fct: Id, field: &str| -> InputResult<(Vec<f64>, Vec<f64>)> {
        match functions.iter().find(|f| f.id == fct) {
            Some(f) => Ok((f.x.clone(), f.y.clone())),
            None => Err(InputError::new(
                loc.clone(),
                kw,
                field,
                format!("function {fct} is not defined in the deck; expected a /FUNCT id"),
            )),
        }
    };
    for r in t.rates.iter_mut() {
        (r.x, r.y) = points(r.fct, "fct_ID")?;
    }
    for (c, field) in [(&mut t.size, "fct_IDel"), (&mut t.temperature, "fct_IDt")] {
        if c.fct > 0 {
            (c.x, c.y) = points(c.fct, field)?;
        }
    }
    Ok(())
}
