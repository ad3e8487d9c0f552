//! /PROP/TYPE2 (/PROP/TRUSS) and /PROP/TYPE3 (/PROP/BEAM) (reference guide
//! /PROP/TYPE2, /PROP/TYPE3; research note `docs/notes/beam_truss_research.md`
//! §1).
//!
//! TRUSS, after the title: Area (1-20), Gap (21-40).
//! BEAM, after the title:
//! 1. Ismstr (11-20)
//! 2. dm (1-20), df (21-40; 0 → 0.01)
//! 3. Area (1-20), Iyy (21-40), Izz (41-60), Ixx (61-80)
//! 4. the released rotations ωx ωy ωz of node 1 (columns 4-6) and node 2
//!    (columns 8-10), 1 = released; Ishear (11-20)

use super::fields::Cards;
use crate::model::{BeamProperty, InputResult, TrussProperty};

pub(super) fn read_truss(cards: &mut Cards) -> InputResult<TrussProperty> {
    let c = cards.next("the card with Area, Gap")?;
    let area = c.positive_real(1, "Area", "cross-section area")?;
    let gap = c.real(21, "Gap", 0.0)?;
    if gap < 0.0 {
        return Err(c.err("Gap", format!("{gap}: the initial gap must be >= 0")));
    }
    Ok(TrussProperty { area, gap })
}

pub(super) fn read_beam(cards: &mut Cards) -> InputResult<BeamProperty> {
    let c1 = cards.next("the card with Ismstr")?;
    let c2 = cards.next("the card with dm, df")?;
    let c3 = cards.next("the card with Area, Iyy, Izz, Ixx")?;
    let c4 = cards.next_opt();
    let area = c3.positive_real(1, "Area", "cross-section area")?;
    let iyy = c3.positive_real(21, "Iyy", "bending moment of area about y")?;
    let izz = c3.positive_real(41, "Izz", "bending moment of area about z")?;
    let ixx = c3.positive_real(61, "Ixx", "torsion constant")?;
    let (dm, df) = (c2.real(1, "dm", 0.0)?, c2.real(21, "df", 0.0)?);
    if dm < 0.0 || df < 0.0 {
        return Err(c2.err("dm", format!("dm = {dm}, df = {df}: damping must be >= 0")));
    }
    let mut released = [false; 6];
    let mut ishear = 0;
    if let Some(c4) = c4 {
        let code = c4.raw(1, 10);
        for (i, col) in [3, 4, 5, 7, 8, 9].iter().enumerate() {
            match code.as_bytes().get(*col).copied() {
                None | Some(b' ') | Some(b'0') => {}
                Some(b'1') => released[i] = true,
                Some(other) => {
                    return Err(c4.err(
                        "OmegaDof",
                        format!(
                            "'{}' in column {}: expected 0 or 1 (rotation kept or released)",
                            other as char,
                            col + 1
                        ),
                    ))
                }
            }
        }
        ishear = c4.int(11, "Ishear", 0)?;
        if !(0..=1).contains(&ishear) {
            return Err(c4.err("Ishear", format!("{ishear}: expected 0 (Timoshenko) or 1")));
        }
    }
    Ok(BeamProperty {
        ismstr: c1.int(11, "Ismstr", 0)?,
        dm,
        df: if df == 0.0 { 0.01 } else { df },
        area,
        iyy,
        izz,
        ixx,
        released,
        ishear,
    })
}
