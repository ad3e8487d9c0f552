//! /PART, /PROP/TYPE1 (SHELL), /PROP/TYPE14 (SOLID), the spring properties
//! (TYPE4, TYPE8, TYPE13: `super::spring_props`), /DEF_SHELL, /DEF_SOLID,
//! /FUNCT, /ADMAS.
//! Values are kept as written (0 = "default"); `to_model` resolves the
//! defaults that depend on other cards (/DEF_SHELL, the material law).

use super::fields::{zero_default, Card, Cards};
use super::source::Block;
use super::spring_props;
use super::{header_id, header_id_opt, Deck, Id};
use crate::model::{
    DefShell, DefSolid, Function, InputError, InputResult, Loc, PropertyKind, PropertySpec,
    ShellProperty, SolidOrtho, SolidProperty,
};
use serde::{Deserialize, Serialize};

/// `/PART/part_ID`: title; prop_ID (1-10), mat_ID (11-20), subset_ID (21-30), Thick (31-50).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PartCard {
    pub id: Id,
    pub title: String,
    pub prop: Id,
    pub mat: Id,
    pub subset: Id,
    /// Part thickness overriding the property's (0 = none).
    pub thick: f64,
    pub loc: Loc,
}

pub(super) fn parse_part(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let id = header_id(block, 1, "part_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with prop_ID, mat_ID, subset_ID")?;
    let prop = c.id_opt(1, "prop_ID")?;
    let mat = c.id_opt(11, "mat_ID")?;
    let subset = c.id_opt(21, "subset_ID")?;
    let thick = c.real(31, "Thick", 0.0)?;
    if thick < 0.0 {
        return Err(c.err(
            "Thick",
            format!("{thick}: part thickness must be >= 0 (0 = property thickness)"),
        ));
    }
    super::warn_surplus(
        &cards,
        "the card with prop_ID, mat_ID, subset_ID",
        &mut deck.warnings,
    );
    deck.parts.push(PartCard {
        id,
        title,
        prop,
        mat,
        subset,
        thick,
        loc: c.loc(),
    });
    Ok(())
}

/// Returns false for a property type this reader does not support.
pub(super) fn parse_property(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let ty = block.parts.get(1).map(String::as_str).unwrap_or("");
    let which = match ty {
        "TYPE1" | "SHELL" => 1,
        "TYPE14" | "SOLID" => 14,
        "TYPE4" | "SPRING" => 4,
        "TYPE8" | "SPR_GENE" => 8,
        "TYPE13" | "SPR_BEAM" => 13,
        "TYPE2" | "TRUSS" => 2,
        "TYPE3" | "BEAM" => 3,
        "TYPE45" | "KJOINT2" => 45,
        "TYPE6" | "SOL_ORTH" => 6,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "prop_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let kind = match which {
        1 => PropertyKind::Shell(read_shell(&mut cards)?),
        14 => {
            let mut p = read_solid(&mut cards)?;
            // Input versions before 2019 read Isolid 12 as 17 (H8C), as the
            // reference reader's older formats do (research note
            // docs/notes/law44_isolid12_research.md §2).
            if p.isolid == 12 && deck.begin.as_ref().is_some_and(|b| b.invers < 2019) {
                p.isolid = 17;
            }
            PropertyKind::Solid(p)
        }
        4 => PropertyKind::Spring(spring_props::read_spring(&mut cards, &mut deck.warnings)?),
        8 => PropertyKind::GeneralSpring(spring_props::read_general_spring(
            &mut cards,
            &mut deck.warnings,
        )?),
        2 => PropertyKind::Truss(super::beam_props::read_truss(&mut cards)?),
        3 => PropertyKind::Beam(super::beam_props::read_beam(&mut cards)?),
        45 => PropertyKind::Joint(super::joint_props::read_joint(&mut cards)?),
        6 => PropertyKind::Solid(read_solid_ortho(&mut cards)?),
        _ => PropertyKind::SpringBeam(spring_props::read_spring_beam(
            &mut cards,
            &mut deck.warnings,
        )?),
    };
    if which == 1 {
        super::warn_surplus(&cards, "the card with N, Thick", &mut deck.warnings);
    }
    deck.properties.push(PropertySpec {
        id,
        unit_id,
        title,
        kind,
        loc: block.loc.clone(),
    });
    Ok(true)
}

fn read_shell(cards: &mut Cards) -> InputResult<ShellProperty> {
    // Ishell (1-10) Ismstr (11-20) Ish3n (21-30) Idrill (31-40) P_thick_fail (61-80)
    let c1 = cards.next("the card with Ishell, Ismstr, Ish3n, Idrill")?;
    // hm (1-20) hf (21-40) hr (41-60) dm (61-80) dn (81-100)
    let c2 = cards.next("the card with hm, hf, hr, dm, dn")?;
    // N (1-10) Istrain (11-20) Thick (21-40) Ashear (41-60) Ithick (71-80) Iplas (81-90)
    let c3 = cards.next("the card with N, Istrain, Thick, Ashear, Ithick, Iplas")?;
    let n = c3.int(1, "N", 0)?;
    if !(0..=10).contains(&n) {
        return Err(c3.err(
            "N",
            format!("{n}: expected 0 to 10 integration points through the thickness"),
        ));
    }
    let thick = c3.positive_real(21, "Thick", "shell thickness")?;
    let p = ShellProperty {
        ishell: c1.int(1, "Ishell", 0)?,
        ismstr: c1.int(11, "Ismstr", 0)?,
        ish3n: c1.int(21, "Ish3n", 0)?,
        idrill: c1.int(31, "Idrill", 0)?,
        p_thick_fail: c1.real(61, "P_thick_fail", 0.0)?,
        hm: c2.real(1, "hm", 0.0)?,
        hf: c2.real(21, "hf", 0.0)?,
        hr: c2.real(41, "hr", 0.0)?,
        dm: c2.real(61, "dm", 0.0)?,
        dn: c2.real(81, "dn", 0.0)?,
        n,
        istrain: c3.int(11, "Istrain", 0)?,
        thick,
        ashear: c3.real(41, "Ashear", 0.0)?,
        ithick: c3.int(71, "Ithick", 0)?,
        iplas: c3.int(81, "Iplas", 0)?,
    };
    for (v, name) in [(p.hm, "hm"), (p.hf, "hf"), (p.hr, "hr")] {
        if v < 0.0 {
            return Err(c2.err(name, format!("{v}: hourglass coefficient must be >= 0")));
        }
    }
    Ok(p)
}

/// The cards /PROP/SOLID and /PROP/SOL_ORTH share: Isolid (1-10) Ismstr
/// (11-20) Icpre (31-40) Itetra10 (41-50) Inpts (51-60) Itetra4 (61-70)
/// Iframe (71-80) dn (81-100); qa (1-20) qb (21-40) h (41-60); and,
/// optional, dtmin (1-20) Istrain (21-30).
fn solid_cards(c1: &Card, c2: &Card, c_dt: Option<Card>) -> InputResult<SolidProperty> {
    let or = zero_default;
    let (qa, qb) = (c2.real(1, "qa", 0.0)?, c2.real(21, "qb", 0.0)?);
    let p = SolidProperty {
        isolid: c1.int(1, "Isolid", 0)?,
        ismstr: c1.int(11, "Ismstr", 0)?,
        icpre: c1.int(31, "Icpre", 0)?,
        itetra10: c1.int(41, "Itetra10", 0)?,
        inpts: c1.int(51, "Inpts", 0)?,
        itetra4: c1.int(61, "Itetra4", 0)?,
        iframe: c1.int(71, "Iframe", 0)?,
        dn: c1.real(81, "dn", 0.0)?,
        qa: or(qa, 1.1),
        qb: or(qb, 0.05),
        q_blank: qa == 0.0 && qb == 0.0,
        h: or(c2.real(41, "h", 0.0)?, 0.1),
        lambda_v: 0.0,
        mu_v: 0.0,
        dtmin: match &c_dt {
            Some(c) => c.real(1, "dtmin", 0.0)?,
            None => 0.0,
        },
        // Istrain selects the strain output only (research note
        // law12_research.md §2.2).
        istrain: match &c_dt {
            Some(c) => c.int(21, "Istrain", 0)?,
            None => 0,
        },
        ortho: None,
    };
    for (v, name) in [(p.qa, "qa"), (p.qb, "qb"), (p.h, "h")] {
        if v < 0.0 {
            return Err(c2.err(name, format!("{v}: expected a value >= 0")));
        }
    }
    Ok(p)
}

fn read_solid(cards: &mut Cards) -> InputResult<SolidProperty> {
    let c1 =
        cards.next("the card with Isolid, Ismstr, Icpre, Itetra10, Inpts, Itetra4, Iframe, dn")?;
    // qa (1-20) qb (21-40) h (41-60) LAMBDA_v (61-80) MU_v (81-100)
    let c2 = cards.next("the card with qa, qb, h, LAMBDA_v, MU_v")?;
    // dtmin (1-20) Istrain (21-30) Ihkt (31-40) — optional
    let c3 = cards.next_opt();
    let mut p = solid_cards(&c1, &c2, c3)?;
    p.lambda_v = c2.real(61, "LAMBDA_v", 0.0)?;
    p.mu_v = c2.real(81, "MU_v", 0.0)?;
    Ok(p)
}

/// /PROP/TYPE6 (/PROP/SOL_ORTH): the /PROP/SOLID cards with the
/// orthotropic directions (research note `docs/notes/law28_sol_orth_research.md`
/// §2.1; the same first card in the 2017 to 2022 layouts, Itetra10 and
/// Itetra4 blank before 2021).
fn read_solid_ortho(cards: &mut Cards) -> InputResult<SolidProperty> {
    let c1 =
        cards.next("the card with Isolid, Ismstr, Icpre, Itetra10, Inpts, Itetra4, Iframe, dn")?;
    let c2 = cards.next("the card with qa, qb, h")?;
    // Vx (1-20) Vy (21-40) Vz (41-60) skew_ID (61-70) Ip (71-80) Iorth (81-90)
    let c3 = cards.next("the card with Vx, Vy, Vz, skew_ID, Ip, Iorth")?;
    // phi (1-20)
    let c4 = cards.next_opt();
    // dt_min (1-20) Istrain (21-30) Ihkt (31-40)
    let mut p = solid_cards(&c1, &c2, cards.next_opt())?;
    let ip = c3.int(71, "Ip", 0)?;
    if !matches!(ip, 0..=5 | 11..=13 | 20..=24) {
        return Err(c3.err("Ip", format!("{ip}: expected 0 to 5, 11 to 13 or 20 to 24")));
    }
    p.ortho = Some(SolidOrtho {
        v: [
            c3.real(1, "Vx", 0.0)?,
            c3.real(21, "Vy", 0.0)?,
            c3.real(41, "Vz", 0.0)?,
        ],
        skew_id: c3.id_opt(61, "skew_ID")?,
        ip,
        iorth: c3.int(81, "Iorth", 0)?,
        phi: match c4 {
            Some(c) => c.real(1, "phi", 0.0)?,
            None => 0.0,
        },
    });
    Ok(p)
}

pub(super) fn parse_defaults(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let mut cards = Cards::new(block);
    if block.parts[0] == "DEF_SHELL" {
        // ISHELL (1-10) ISMSTR (11-20) ITHICK (21-30) IPLAS (31-40) ISTRAIN (41-50) I_SH3N (71-80) IDRIL (81-90)
        let c =
            cards.next("the card with ISHELL, ISMSTR, ITHICK, IPLAS, ISTRAIN, I_SH3N, IDRIL")?;
        deck.def_shell = Some(DefShell {
            ishell: c.int(1, "ISHELL", 0)?,
            ismstr: c.int(11, "ISMSTR", 0)?,
            ithick: c.int(21, "ITHICK", 0)?,
            iplas: c.int(31, "IPLAS", 0)?,
            istrain: c.int(41, "ISTRAIN", 0)?,
            ish3n: c.int(71, "I_SH3N", 0)?,
            idrill: c.int(81, "IDRIL", 0)?,
        });
    } else {
        // I_SOLID (1-10) ISMSTR (11-20) ISTRAIN (31-40) IFRAME (81-90)
        let c = cards.next("the card with I_SOLID, ISMSTR, ISTRAIN, IFRAME")?;
        deck.def_solid = Some(DefSolid {
            isolid: c.int(1, "I_SOLID", 0)?,
            ismstr: c.int(11, "ISMSTR", 0)?,
            istrain: c.int(31, "ISTRAIN", 0)?,
            iframe: c.int(81, "IFRAME", 0)?,
        });
    }
    Ok(())
}

pub(super) fn parse_function(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let id = header_id(block, 1, "fct_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let (mut x, mut y) = (Vec::new(), Vec::new());
    while let Some(c) = cards.next_nonblank() {
        let xi = c.real(1, "X", 0.0)?;
        let yi = c.real(21, "Y", 0.0)?;
        if let Some(&prev) = x.last() {
            if xi <= prev {
                return Err(c.err(
                    "X",
                    format!("{xi} after {prev}: abscissas must increase strictly"),
                ));
            }
        }
        x.push(xi);
        y.push(yi);
    }
    if x.is_empty() {
        return Err(InputError::new(
            block.loc.clone(),
            &block.header,
            "X",
            "function has no points; expected at least one (X, Y) line",
        ));
    }
    deck.functions.push(Function {
        id,
        title,
        x,
        y,
        loc: block.loc.clone(),
    });
    Ok(())
}

/// /ADMAS/type/admas_ID: added mass on nodes or parts.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct AddedMassCard {
    pub id: Id,
    /// 0: MASS on each node of the group; 1: MASS distributed over the group's
    /// nodes by their mass; 2..: per-part variants (see `target`).
    pub kind: i64,
    pub title: String,
    pub mass: f64,
    /// Node group (kind 0, 1) or part id.
    pub target: Id,
    pub loc: Loc,
}

/// Returns false for an /ADMAS type that is not supported.
pub(super) fn parse_admas(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let kind = match block.parts.get(1).map(|s| super::fields::parse_int(s)) {
        Some(Ok(k)) if k == 0 || k == 1 => k,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "admas_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // MASS (1-20), grnd_ID (21-30)
    let c = cards.next("the card with MASS and grnd_ID")?;
    let mass = c.real(1, "MASS", 0.0)?;
    if mass < 0.0 {
        return Err(c.err("MASS", format!("{mass}: added mass must be >= 0")));
    }
    let target = c.id(21, "grnd_ID")?;
    deck.added_masses.push(AddedMassCard {
        id,
        kind,
        title,
        mass,
        target,
        loc: c.loc(),
    });
    Ok(true)
}
