//! /PROP/TYPE45 (/PROP/KJOINT2): a penalty joint between two rigid bodies
//! (reference guide /PROP/TYPE45; research note
//! `docs/notes/kjoint2_research.md` §2). After the first card, three cards
//! per free degree of freedom of the joint type, in the order Tx, Ty, Tz,
//! Rx, Ry, Rz. Blank lines inside the block are cards of zeros.

use super::fields::Cards;
use crate::model::{InputResult, JointDof, JointProperty};

const DOF_NAMES: [&str; 6] = [
    "translation X",
    "translation Y",
    "translation Z",
    "rotation X",
    "rotation Y",
    "rotation Z",
];

/// A stiffness, damping or friction value: blank with a function is 1 (the
/// value is then the function's scale), as the reference starter reads it.
fn scale_or_one(v: f64, fct: crate::model::Id) -> f64 {
    if v == 0.0 && fct != 0 {
        1.0
    } else {
        v
    }
}

/// The three cards of free degree of freedom `dof`.
fn read_dof(cards: &mut Cards, dof: usize) -> InputResult<JointDof> {
    let what = DOF_NAMES[dof];
    // K (1-20) fct_K (21-30) S- (31-50) S+ (51-70) Icomb (71-80)
    let c1 = cards.next(&format!("the card with K, fct_K, S-, S+ of the {what}"))?;
    // C (1-20) fct_C (21-30)
    let c2 = cards.next_opt();
    // Kf (1-20) FF/FM (21-40) fct_F (41-50)
    let c3 = cards.next_opt();
    let fct_k = c1.id_opt(21, "fct_K")?;
    let mut d = JointDof {
        k: scale_or_one(c1.real(1, "K", 0.0)?, fct_k),
        fct_k,
        stop_minus: c1.real(31, "S-", 0.0)?,
        stop_plus: c1.real(51, "S+", 0.0)?,
        icomb: c1.int(71, "Icomb", 0)?,
        ..Default::default()
    };
    if d.k < 0.0 {
        return Err(c1.err("K", format!("{}: expected a stiffness >= 0 ({what})", d.k)));
    }
    if d.stop_minus > 0.0 || d.stop_plus < 0.0 {
        return Err(c1.err(
            "S-",
            format!(
                "S- = {}, S+ = {}: expected S- <= 0 <= S+ ({what})",
                d.stop_minus, d.stop_plus
            ),
        ));
    }
    if let Some(c2) = c2 {
        d.fct_c = c2.id_opt(21, "fct_C")?;
        d.c = scale_or_one(c2.real(1, "C", 0.0)?, d.fct_c);
    }
    if let Some(c3) = c3 {
        d.kf = c3.real(1, "Kf", 0.0)?;
        d.fct_f = c3.id_opt(41, "fct_F")?;
        d.friction = scale_or_one(c3.real(21, "FF", 0.0)?, d.fct_f);
    }
    Ok(d)
}

/// /PROP/TYPE45: Type, Kn, ScF, Cr, sens_ID, Skew_ID1, Skew_ID2, then the
/// free degrees of freedom of the type.
pub(super) fn read_joint(cards: &mut Cards) -> InputResult<JointProperty> {
    // Type (1-10) Kn (11-30) ScF (31-50) Cr (51-70) sens_ID (71-80)
    // Skew_ID1 (81-90) Skew_ID2 (91-100)
    let c1 = cards.next("the card with Type, Kn, ScF, Cr, sens_ID, Skew_ID1, Skew_ID2")?;
    let joint_type = c1.int(1, "Type", 0)?;
    let Some(free) = JointProperty::free_dofs(joint_type) else {
        return Err(c1.err(
            "Type",
            format!("{joint_type}: expected a joint type from 1 to 9"),
        ));
    };
    let kn = c1.real(11, "Kn", 0.0)?;
    if kn < 0.0 {
        return Err(c1.err(
            "Kn",
            format!("{kn}: expected a stiffness >= 0 (0: automatic)"),
        ));
    }
    let scf = c1.real(31, "ScF", 0.0)?;
    if scf < 0.0 {
        return Err(c1.err("ScF", format!("{scf}: expected a scale factor >= 0")));
    }
    let cr = c1.real(51, "Cr", 0.0)?;
    if !(0.0..=1.0).contains(&cr) {
        return Err(c1.err(
            "Cr",
            format!("{cr}: expected a critical damping factor in [0, 1]"),
        ));
    }
    let automatic = JointProperty::automatic(kn);
    let mut dofs = Vec::with_capacity(free.len());
    for &dof in free {
        dofs.push((dof, read_dof(cards, dof)?));
    }
    Ok(JointProperty {
        joint_type,
        kn,
        // Reference starter: ScF 0 is 1 with the automatic stiffness, 10
        // (on the rotations only) with Kn given; Cr 0 is 0.05.
        scf: match (scf, automatic) {
            (0.0, true) => 1.0,
            (0.0, false) => 10.0,
            (s, _) => s,
        },
        cr: if cr == 0.0 { 0.05 } else { cr },
        sens_id: c1.id_opt(71, "sens_ID")?,
        skew_ids: [c1.id_opt(81, "Skew_ID1")?, c1.id_opt(91, "Skew_ID2")?],
        free: dofs,
    })
}
