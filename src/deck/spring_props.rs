//! Spring properties: /PROP/TYPE4 (/PROP/SPRING), /PROP/TYPE8
//! (/PROP/SPR_GENE) and /PROP/TYPE13 (/PROP/SPR_BEAM). Every degree of
//! freedom is the same three cards (reference guide /PROP/TYPE4, TYPE8,
//! TYPE13; research note `docs/notes/springs_research.md` §1.1, 2.1, 3.1).
//! Blank lines inside the block are cards of zeros (the Starter reads them
//! so; the six-block layouts depend on it).

use super::fields::{one_if_zero, Card, Cards};
use crate::model::{
    GeneralSpringProperty, InputResult, SpringBeamProperty, SpringDof, SpringProperty, Warning,
};

/// A δ bound of 0 means none (reference guide: δmin, δmax default ∓10³⁰).
const NONE: f64 = 1e30;

/// Reads the three cards of one degree of freedom.
fn read_dof(cards: &mut Cards, what: &str, warnings: &mut Vec<Warning>) -> InputResult<SpringDof> {
    // K (1-20) C (21-40) A (41-60) B (61-80) D (81-100)
    let c1 = cards.next(&format!("the card with K, C, A, B, D of {what}"))?;
    // fct_ID1 (1-10) H (11-20) fct_ID2 (21-30) fct_ID3 (31-40) fct_ID4 (41-50) δmin (61-80) δmax (81-100)
    let c2 = cards.next_opt();
    // F (1-20) E (21-40) Ascale (41-60) Hscale (61-80)
    let c3 = cards.next_opt();
    let k = c1.real(1, "K", 0.0)?;
    if k < 0.0 {
        return Err(c1.err("K", format!("{k}: spring stiffness must be >= 0")));
    }
    let c = c1.real(21, "C", 0.0)?;
    if c < 0.0 {
        return Err(c1.err("C", format!("{c}: spring damping must be >= 0")));
    }
    let mut d = SpringDof::linear(k, c);
    if let Some(c2) = c2 {
        read_functions(&c2, &mut d, what, warnings)?;
    }
    if let Some(c3) = c3 {
        d.fscale = one_if_zero(c3.real(1, "F", 0.0)?);
        d.e = one_if_zero(c3.real(21, "E", 0.0)?);
        d.ascale = one_if_zero(c3.real(41, "Ascale", 0.0)?);
        d.hscale = one_if_zero(c3.real(61, "Hscale", 0.0)?);
    } else {
        d.e = 1.0;
    }
    if d.fct_id1 != 0 {
        d.a = one_if_zero(c1.real(41, "A", 0.0)?);
        d.b = c1.real(61, "B", 0.0)?;
        d.d = one_if_zero(c1.real(81, "D", 0.0)?);
    } else {
        // Without fct_ID1 the spring is linear: A = 1, B = 0, E = 0.
        d.e = 0.0;
    }
    if d.d <= 0.0 && d.b != 0.0 {
        return Err(c1.err(
            "D",
            format!("{}: the rate scale must be > 0 when B ≠ 0", d.d),
        ));
    }
    Ok(d)
}

/// The function card of one degree of freedom.
fn read_functions(
    c: &Card,
    d: &mut SpringDof,
    what: &str,
    warnings: &mut Vec<Warning>,
) -> InputResult<()> {
    d.fct_id1 = c.id_opt(1, "fct_ID1")?;
    d.h = c.int(11, "H", 0)?;
    d.fct_id2 = c.id_opt(21, "fct_ID2")?;
    d.fct_id3 = c.id_opt(31, "fct_ID3")?;
    d.fct_id4 = c.id_opt(41, "fct_ID4")?;
    let lo = c.real(61, "delta_min", 0.0)?;
    let hi = c.real(81, "delta_max", 0.0)?;
    d.delta_min = if lo == 0.0 { -NONE } else { lo };
    d.delta_max = if hi == 0.0 { NONE } else { hi };
    if !matches!(d.h, 0..=2 | 4..=8) {
        return Err(c.err(
            "H",
            format!("{}: expected 0, 1, 2, 4, 5, 6, 7 or 8 ({what})", d.h),
        ));
    }
    let needs = |ok: bool, msg: &str| {
        if ok {
            Ok(())
        } else {
            Err(c.err("H", format!("H = {}: {msg} ({what})", d.h)))
        }
    };
    match d.h {
        4 | 5 | 6 => needs(
            d.fct_id1 != 0 && d.fct_id3 != 0,
            "needs the loading curve fct_ID1 and the curve fct_ID3",
        )?,
        7 | 8 => needs(d.fct_id1 != 0, "needs the loading curve fct_ID1")?,
        _ => {}
    }
    if d.h == 7 && d.fct_id3 == 0 {
        // Reference Starter: WARNING, the hysteresis without its unloading
        // curve is the uncoupled elasto-plastic spring (H = 2).
        warnings.push(Warning {
            loc: c.loc(),
            keyword: c.kw.to_string(),
            message: format!(
                "H = 7 without the unloading curve fct_ID3 ({what}): computed as H = 2, as the reference Starter does"
            ),
        });
        d.h = 2;
    }
    Ok(())
}

/// /PROP/TYPE4: Mass, sens_ID, Isflag, Ileng, then one degree of freedom.
pub(super) fn read_spring(
    cards: &mut Cards,
    warnings: &mut Vec<Warning>,
) -> InputResult<SpringProperty> {
    // Mass (1-20) sens_ID (51-60) Isflag (61-70) Ileng (71-80)
    let c1 = cards.next("the card with Mass, sens_ID, Isflag, Ileng")?;
    let mass = c1.real(1, "Mass", 0.0)?;
    if mass < 0.0 {
        return Err(c1.err("Mass", format!("{mass}: spring mass must be >= 0")));
    }
    let ileng = c1.int(71, "Ileng", 0)?;
    if !(0..=1).contains(&ileng) {
        return Err(c1.err("Ileng", format!("{ileng}: expected 0 or 1")));
    }
    Ok(SpringProperty {
        mass,
        sens_id: c1.id_opt(51, "sens_ID")?,
        isflag: c1.int(61, "Isflag", 0)?,
        ileng,
        dof: read_dof(cards, "the axial direction", warnings)?,
    })
}

const DIRECTIONS8: [&str; 6] = [
    "direction X",
    "direction Y",
    "direction Z",
    "rotation XX",
    "rotation YY",
    "rotation ZZ",
];
const DIRECTIONS13: [&str; 6] = [
    "tension",
    "shear XY",
    "shear XZ",
    "torsion",
    "bending Y",
    "bending Z",
];

/// Mass and Inertia of a six-degree-of-freedom spring, checked.
fn mass_inertia(c1: &Card) -> InputResult<(f64, f64)> {
    let mass = c1.real(1, "Mass", 0.0)?;
    if mass < 0.0 {
        return Err(c1.err("Mass", format!("{mass}: spring mass must be >= 0")));
    }
    let inertia = c1.real(21, "Inertia", 0.0)?;
    if inertia < 0.0 {
        return Err(c1.err("Inertia", format!("{inertia}: spring inertia must be >= 0")));
    }
    Ok((mass, inertia))
}

fn read_dofs(
    cards: &mut Cards,
    names: &[&str; 6],
    warnings: &mut Vec<Warning>,
) -> InputResult<[SpringDof; 6]> {
    let mut out = Vec::with_capacity(6);
    for name in names {
        out.push(read_dof(cards, name, warnings)?);
    }
    Ok(out.try_into().expect("six directions"))
}

/// /PROP/TYPE8: Mass, Inertia, skew, sensor, failure flags, six degrees of
/// freedom, then Fsmooth and Fcut.
pub(super) fn read_general_spring(
    cards: &mut Cards,
    warnings: &mut Vec<Warning>,
) -> InputResult<GeneralSpringProperty> {
    // Mass (1-20) Inertia (21-40) skew_ID (41-50) sens_ID (51-60) Isflag (61-70)
    // Ifail (71-80) Ifail2 (81-90) Iequil (91-100)
    let c1 = cards
        .next("the card with Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ifail2, Iequil")?;
    let (mass, inertia) = mass_inertia(&c1)?;
    let dofs = read_dofs(cards, &DIRECTIONS8, warnings)?;
    // Fsmooth (1-10) Fcut (11-30)
    let (fsmooth, fcut) = match cards.next_opt() {
        Some(c) => (c.int(1, "Fsmooth", 0)?, c.real(11, "Fcut", 0.0)?),
        None => (0, 0.0),
    };
    let ifail = c1.int(71, "Ifail", 0)?;
    if !(0..=1).contains(&ifail) {
        return Err(c1.err("Ifail", format!("{ifail}: expected 0 or 1")));
    }
    let ifail2 = c1.int(81, "Ifail2", 0)?;
    Ok(GeneralSpringProperty {
        mass,
        inertia,
        skew_id: c1.id_opt(41, "skew_ID")?,
        sens_id: c1.id_opt(51, "sens_ID")?,
        isflag: c1.int(61, "Isflag", 0)?,
        ifail,
        // Reference Starter: an Ifail2 other than 1 or 2 is 0.
        ifail2: if matches!(ifail2, 1 | 2) { ifail2 } else { 0 },
        iequil: c1.int(91, "Iequil", 0)?,
        dofs,
        fsmooth,
        fcut,
    })
}

/// /PROP/TYPE13: Mass, Inertia, skew, sensor, failure flags, Ileng, six
/// degrees of freedom, v0 and ω0, then c, n, α, β per direction.
pub(super) fn read_spring_beam(
    cards: &mut Cards,
    warnings: &mut Vec<Warning>,
) -> InputResult<SpringBeamProperty> {
    // Mass (1-20) Inertia (21-40) skew_ID (41-50) sens_ID (51-60) Isflag (61-70)
    // Ifail (71-80) Ileng (81-90) Ifail2 (91-100)
    let c1 = cards
        .next("the card with Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ileng, Ifail2")?;
    let (mass, inertia) = mass_inertia(&c1)?;
    let dofs = read_dofs(cards, &DIRECTIONS13, warnings)?;
    // v0 (1-20) ω0 (21-40)
    let (v0, omega0) = match cards.next_opt() {
        Some(c) => (c.real(1, "v0", 0.0)?, c.real(21, "omega0", 0.0)?),
        None => (0.0, 0.0),
    };
    // Per direction: c (1-20) n (21-40) α (41-60) β (61-80); n 0 → 1, α 0 → 1, β 0 → 2.
    let mut fail = [[0.0, 1.0, 1.0, 2.0]; 6];
    for f in fail.iter_mut() {
        let Some(c) = cards.next_opt() else { break };
        *f = [
            c.real(1, "c", 0.0)?,
            one_if_zero(c.real(21, "n", 0.0)?),
            one_if_zero(c.real(41, "alpha", 0.0)?),
            match c.real(61, "beta", 0.0)? {
                0.0 => 2.0,
                b => b,
            },
        ];
    }
    let ileng = c1.int(81, "Ileng", 0)?;
    if !(0..=1).contains(&ileng) {
        return Err(c1.err("Ileng", format!("{ileng}: expected 0 or 1")));
    }
    Ok(SpringBeamProperty {
        mass,
        inertia,
        skew_id: c1.id_opt(41, "skew_ID")?,
        sens_id: c1.id_opt(51, "sens_ID")?,
        isflag: c1.int(61, "Isflag", 0)?,
        ifail: c1.int(71, "Ifail", 0)?,
        ileng,
        ifail2: c1.int(91, "Ifail2", 0)?,
        dofs,
        v0,
        omega0,
        fail,
    })
}
