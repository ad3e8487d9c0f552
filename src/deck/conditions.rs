//! Boundary and initial conditions, loads, rigid walls, rigid bodies and
//! sections: /BCS, /IMPVEL, /IMPDISP, /INIVEL/TRA (and /ROT), /CLOAD, /GRAV,
//! /RWALL/PLANE, /RBODY, /SECT.

use super::fields::{Card, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck, Id};
use crate::model::{
    BoundarySpec, ConcentratedLoadSpec, CrossSectionSpec, DampingSpec, Dof, GravitySpec,
    ImposedMotionSpec, InitialVelocitySpec, InputResult, RigidBodySpec, RigidWallSpec,
};

fn read_dir(c: &Card, col: usize, default: Option<Dof>) -> InputResult<Dof> {
    match c.text(col, 10).to_ascii_uppercase().as_str() {
        "X" => Ok(Dof::X),
        "Y" => Ok(Dof::Y),
        "Z" => Ok(Dof::Z),
        "XX" => Ok(Dof::Xx),
        "YY" => Ok(Dof::Yy),
        "ZZ" => Ok(Dof::Zz),
        "" if default.is_some() => Ok(default.unwrap()),
        t => Err(c.err("Dir", format!("'{t}': expected X, Y, Z, XX, YY or ZZ"))),
    }
}

/// Returns false for a variant this reader does not support.
pub(super) fn parse_condition(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    match block.parts[0].as_str() {
        "BCS" => boundary_conditions(block, deck),
        "IMPVEL" | "IMPDISP" => imposed_motion(block, deck),
        "INIVEL" => initial_velocity(block, deck),
        "CLOAD" | "GRAV" => load(block, deck),
        // /DAMP/damp_ID[/unit_ID] (a header without the id too: its
        // reader names the missing field); /DAMP/VREL and others are not read.
        "DAMP"
            if block.parts.len() <= 3
                && block
                    .parts
                    .get(1)
                    .is_none_or(|p| p.trim().parse::<u64>().is_ok()) =>
        {
            damping(block, deck)
        }
        "RWALL" => rigid_wall(block, deck),
        "RBODY" => rigid_body(block, deck),
        "SECT" => section(block, deck),
        _ => Ok(false),
    }
}

/// /BCS: fixed degrees of freedom on a node group.
fn boundary_conditions(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 1, "bcs_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with Trarot, skew_ID, grnod_ID")?;
    let fixed = read_trarot(&c)?;
    deck.bcs.push(BoundarySpec {
        id,
        title,
        fixed,
        skew_id: c.id_opt(11, "skew_ID")?,
        grnod: c.id(21, "grnod_ID")?,
        loc: c.loc(),
    });
    Ok(true)
}

/// /IMPVEL and /IMPDISP: a velocity or displacement imposed through a function.
fn imposed_motion(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let vel = block.parts[0] == "IMPVEL";
    let id = header_id(block, 1, "impvel_ID")?;
    let unit_id = header_id_opt(block, 2, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // fct_IDT (1-10) Dir (11-20) skew_ID (21-30) sens_ID (31-40) grnod_ID (41-50) frame_ID (51-60, IMPVEL) Icoor (61-70)
    let c = cards.next("the card with fct_IDT, Dir, skew_ID, sens_ID, grnod_ID")?;
    // Ascale_x (1-20) Fscale_Y (21-40) Tstart (41-60) Tstop (61-80): may be absent
    let c2 = cards.next_opt();
    let (ascale_x, fscale_y, tstart, tstop) = match c2 {
        Some(c2) => (
            super::fields::one_if_zero(c2.real(1, "Ascale_x", 0.0)?),
            super::fields::one_if_zero(c2.real(21, "Fscale_Y", 0.0)?),
            c2.real(41, "Tstart", 0.0)?,
            c2.real(61, "Tstop", 0.0)?,
        ),
        None => (1.0, 1.0, 0.0, 0.0),
    };
    let tstop = if tstop == 0.0 { 1e30 } else { tstop };
    if ascale_x <= 0.0 {
        return Err(c2.unwrap().err(
            "Ascale_x",
            format!("{ascale_x}: the time scale must be > 0"),
        ));
    }
    let card = ImposedMotionSpec {
        id,
        unit_id,
        title,
        fct: c.id(1, "fct_IDT")?,
        dir: read_dir(&c, 11, None)?,
        skew_id: c.id_opt(21, "skew_ID")?,
        sens_id: c.id_opt(31, "sens_ID")?,
        grnod: c.id(41, "grnod_ID")?,
        frame_id: if vel { c.id_opt(51, "frame_ID")? } else { 0 },
        icoor: c.flag(61, "Icoor", 0, &[0, 1])?,
        ascale_x,
        fscale_y,
        tstart,
        tstop,
        loc: c.loc(),
    };
    if vel {
        deck.imposed_velocities.push(card);
    } else {
        deck.imposed_displacements.push(card);
    }
    Ok(true)
}

/// /INIVEL: initial translational or rotational velocities.
fn initial_velocity(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    let rotational = match p1 {
        "TRA" => false,
        "ROT" => true,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "inivel_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // Vx (1-20) Vy (21-40) Vz (41-60) grnod_ID (61-70) skew_ID (71-80)
    let c = cards.next("the card with Vx, Vy, Vz, grnod_ID, skew_ID")?;
    deck.initial_velocities.push(InitialVelocitySpec {
        id,
        title,
        rotational,
        v: [
            c.real(1, "Vx", 0.0)?,
            c.real(21, "Vy", 0.0)?,
            c.real(41, "Vz", 0.0)?,
        ],
        grnod: c.id(61, "grnod_ID")?,
        skew_id: c.id_opt(71, "skew_ID")?,
        loc: c.loc(),
    });
    Ok(true)
}

/// /CLOAD and /GRAV: concentrated loads and gravity through a function.
fn load(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let grav = block.parts[0] == "GRAV";
    let id = header_id(block, 1, if grav { "grav_ID" } else { "cload_ID" })?;
    let unit_id = header_id_opt(block, 2, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // fct_IDT (1-10) Dir (11-20) skew_ID (21-30) sens_ID (31-40) grnod_ID (41-50) Ascale_x (61-80) Fscale_y (81-100)
    let c =
        cards.next("the card with fct_IDT, Dir, skew_ID, sens_ID, grnod_ID, Ascale_x, Fscale_y")?;
    let ascale_x = super::fields::one_if_zero(c.real(61, "Ascale_x", 0.0)?);
    if ascale_x <= 0.0 {
        return Err(c.err(
            "Ascale_x",
            format!("{ascale_x}: the time scale must be > 0"),
        ));
    }
    let fscale_y = super::fields::one_if_zero(c.real(81, "Fscale_y", 0.0)?);
    if grav {
        deck.gravity.push(GravitySpec {
            id,
            unit_id,
            title,
            fct: c.id_opt(1, "fct_IDT")?,
            dir: read_dir(&c, 11, Some(Dof::Z))?,
            skew_id: c.id_opt(21, "skew_ID")?,
            sens_id: c.id_opt(31, "sens_ID")?,
            grnod: c.id_opt(41, "grnod_ID")?,
            ascale_x,
            fscale_y,
            loc: c.loc(),
        });
    } else {
        deck.concentrated_loads.push(ConcentratedLoadSpec {
            id,
            unit_id,
            title,
            fct: c.id(1, "fct_IDT")?,
            dir: read_dir(&c, 11, None)?,
            skew_id: c.id_opt(21, "skew_ID")?,
            sens_id: c.id_opt(31, "sens_ID")?,
            grnod: c.id(41, "grnod_ID")?,
            ascale_x,
            fscale_y,
            loc: c.loc(),
        });
    }
    Ok(true)
}

/// /RWALL/PLANE: a fixed or moving planar rigid wall.
fn rigid_wall(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    if p1 != "PLANE" {
        return Ok(false);
    }
    let id = header_id(block, 2, "rwall_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // node_ID (1-10) Slide (11-20) grnod_ID1 (21-30) grnod_ID2 (31-40)
    let c1 = cards.next("the card with node_ID, Slide, grnod_ID1, grnod_ID2")?;
    // D_search (1-20) fric (21-40) Diameter (41-60) ffac (61-80) ifq (81-90)
    let c2 = cards.next("the card with D_search, fric, Diameter, ffac, ifq")?;
    let node_id = c1.id_opt(1, "node_ID")?;
    // node_ID = 0: XM YM ZM; else Mass VX0 VY0 VZ0
    let c3 = cards.next(if node_id == 0 {
        "the card with XM, YM, ZM"
    } else {
        "the card with Mass, VX0, VY0, VZ0"
    })?;
    // X_M1 (1-20) Y_M1 (21-40) Z_M1 (41-60)
    let c4 = cards.next("the card with X_M1, Y_M1, Z_M1")?;
    let (m, mass, v0) = if node_id == 0 {
        (
            [
                c3.real(1, "XM", 0.0)?,
                c3.real(21, "YM", 0.0)?,
                c3.real(41, "ZM", 0.0)?,
            ],
            0.0,
            [0.0; 3],
        )
    } else {
        let mass = c3.real(1, "Mass", 0.0)?;
        if mass < 0.0 {
            return Err(c3.err("Mass", format!("{mass}: wall mass must be >= 0")));
        }
        (
            [0.0; 3],
            mass,
            [
                c3.real(21, "VX0", 0.0)?,
                c3.real(41, "VY0", 0.0)?,
                c3.real(61, "VZ0", 0.0)?,
            ],
        )
    };
    let slide = c1.flag(11, "Slide", 0, &[0, 1, 2])?;
    let fric = c2.real(21, "fric", 0.0)?;
    if fric < 0.0 {
        return Err(c2.err("fric", format!("{fric}: friction coefficient must be >= 0")));
    }
    let d_search = c2.real(1, "D_search", 0.0)?;
    if d_search < 0.0 {
        return Err(c2.err(
            "D_search",
            format!("{d_search}: search distance must be >= 0"),
        ));
    }
    deck.rigid_walls.push(RigidWallSpec {
        id,
        title,
        node_id,
        slide,
        grnod1: c1.id_opt(21, "grnod_ID1")?,
        grnod2: c1.id_opt(31, "grnod_ID2")?,
        d_search,
        fric,
        diameter: c2.real(41, "Diameter", 0.0)?,
        ffac: c2.real(61, "ffac", 0.0)?,
        ifq: c2.flag(81, "ifq", 0, &[0, 1, 2, 3])?,
        m,
        mass,
        v0,
        m1: [
            c4.real(1, "X_M1", 0.0)?,
            c4.real(21, "Y_M1", 0.0)?,
            c4.real(41, "Z_M1", 0.0)?,
        ],
        loc: c1.loc(),
    });
    Ok(true)
}

/// /RBODY: a rigid body on a node group.
fn rigid_body(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 1, "rbody_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // RBID (1-10) ISENS (11-20) NSKEW (21-30) ISPHER (31-40) MASS (41-60) Gnod_id (61-70) IKREM (71-80) ICOG (81-90) Surf_id (91-100)
    let c1 = cards
        .next("the card with RBID, ISENS, NSKEW, ISPHER, MASS, Gnod_id, IKREM, ICOG, Surf_id")?;
    // Jxx Jyy Jzz, then Jxy Jyz Jxz, then Ioptoff Iexpams: optional
    let c2 = cards.next_opt();
    let c3 = cards.next_opt();
    let c4 = cards.next_opt();
    let mut inertia = [0.0; 6];
    if let Some(c) = c2 {
        inertia[0] = c.real(1, "Jxx", 0.0)?;
        inertia[1] = c.real(21, "Jyy", 0.0)?;
        inertia[2] = c.real(41, "Jzz", 0.0)?;
    }
    if let Some(c) = c3 {
        inertia[3] = c.real(1, "Jxy", 0.0)?;
        inertia[4] = c.real(21, "Jyz", 0.0)?;
        inertia[5] = c.real(41, "Jxz", 0.0)?;
    }
    let mass = c1.real(41, "MASS", 0.0)?;
    if mass < 0.0 {
        return Err(c1.err("MASS", format!("{mass}: added mass must be >= 0")));
    }
    deck.rigid_bodies.push(RigidBodySpec {
        id,
        title,
        main_node: c1.id(1, "RBID")?,
        sens_id: c1.id_opt(11, "ISENS")?,
        skew_id: c1.id_opt(21, "NSKEW")?,
        ispher: c1.int(31, "ISPHER", 0)?,
        mass,
        grnod: c1.id(61, "Gnod_id")?,
        ikrem: c1.int(71, "IKREM", 0)?,
        icog: c1.int(81, "ICOG", 0)?,
        surf_id: c1.id_opt(91, "Surf_id")?,
        inertia,
        ioptoff: match c4 {
            Some(c) => c.int(1, "Ioptoff", 0)?,
            None => 0,
        },
        iexpams: match c4 {
            Some(c) => c.int(11, "Iexpams", 0)?,
            None => 0,
        },
        loc: c1.loc(),
    });
    Ok(true)
}

/// /SECT: a cross-section for force outputs.
fn section(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 1, "sect_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    // node_ID1..3 (1-30) grnod_ID (31-40) I_SAVE (41-50) Frame_ID (51-60) Dt (61-80) alpha (81-100)
    let c1 = cards.next(
        "the card with node_ID1, node_ID2, node_ID3, grnod_ID, I_SAVE, Frame_ID, Dt, alpha",
    )?;
    // File name (1-100), may be blank
    let c2 = cards.next("the file-name card (may be blank)")?;
    // grbricID (1-10) grshel_ID (21-30) grtrus (31-40) grbeam (41-50) grsprin (51-60) grtria (61-70) Ninter (71-80) Iframe (91-100)
    let c3 = cards.next("the card with grbric_ID, grshel_ID, grtrus_ID, grbeam_ID, grsprg_ID, grtria_ID, Ninter, Iframe")?;
    let ninter = c3.int(71, "Ninter", 0)?;
    if ninter < 0 {
        return Err(c3.err(
            "Ninter",
            format!("{ninter}: expected a number of interfaces >= 0"),
        ));
    }
    let mut interfaces = Vec::new();
    while (interfaces.len() as i64) < ninter {
        let c = cards.next("the list of interface ids (Ninter of them)")?;
        for k in 0..10 {
            if (interfaces.len() as i64) < ninter {
                if let Some(v) = c.int_opt(1 + 10 * k, 10, "int_ID")? {
                    if v <= 0 {
                        return Err(
                            c.err("int_ID", format!("{v}: expected a positive interface id"))
                        );
                    }
                    interfaces.push(v as Id);
                }
            }
        }
    }
    deck.sections.push(CrossSectionSpec {
        id,
        title,
        nodes: [
            c1.id_opt(1, "node_ID1")?,
            c1.id_opt(11, "node_ID2")?,
            c1.id_opt(21, "node_ID3")?,
        ],
        grnod: c1.id_opt(31, "grnod_ID")?,
        isave: c1.int(41, "I_SAVE", 0)?,
        frame_id: c1.id_opt(51, "Frame_ID")?,
        dt: c1.real(61, "Dt", 0.0)?,
        alpha: c1.real(81, "alpha", 0.0)?,
        file_name: c2.text(1, 100).to_string(),
        grbric: c3.id_opt(1, "grbricID")?,
        grshel: c3.id_opt(21, "grshel_ID")?,
        grtrus: c3.id_opt(31, "grtrus_ID")?,
        grbeam: c3.id_opt(41, "grbeam_ID")?,
        grsprg: c3.id_opt(51, "grsprg_ID")?,
        grtria: c3.id_opt(61, "grtria_ID")?,
        iframe: c3.int(91, "Iframe", 0)?,
        interfaces,
        loc: c1.loc(),
    });
    Ok(true)
}

/// The Trarot field: six 0/1 codes in columns 4-6 (translations) and 8-10
/// (rotations) of the first field, e.g. `   111 111`. Six codes written
/// anywhere in the field (`111111`) are accepted too; fewer are read by column.
fn read_trarot(c: &Card) -> InputResult<[bool; 6]> {
    let raw = c.raw(1, 10);
    let shown = raw.trim();
    let digits: String = raw.chars().filter(|ch| !ch.is_whitespace()).collect();
    if !digits.chars().all(|ch| ch == '0' || ch == '1') || digits.is_empty() {
        return Err(c.err("Trarot", format!("'{shown}': expected six 0/1 codes like '111 111' (translations X Y Z, rotations X Y Z)")));
    }
    let mut out = [false; 6];
    if digits.len() == 6 {
        for (i, ch) in digits.chars().enumerate() {
            out[i] = ch == '1';
        }
        return Ok(out);
    }
    // Fewer codes: read by position as the reference guide lays the field
    // out (/BCS, "Trarot input format"): columns 4-6 TX TY TZ, 8-10 ωX ωY ωZ,
    // a blank column reading 0 (e.g. '     1' fixes TZ only).
    let col = |k: usize| raw.as_bytes().get(k - 1).copied().unwrap_or(b' ');
    for (i, k) in [4, 5, 6, 8, 9, 10].into_iter().enumerate() {
        out[i] = col(k) == b'1';
    }
    let placed: usize = [4, 5, 6, 8, 9, 10]
        .iter()
        .filter(|&&k| col(k) != b' ')
        .count();
    if placed != digits.len() {
        return Err(c.err("Trarot", format!("'{shown}': a code outside columns 4-6 (translations X Y Z) and 8-10 (rotations X Y Z)")));
    }
    Ok(out)
}

#[cfg(test)]
mod trarot_tests {
    use super::*;
    use crate::deck::source::Line;
    use crate::model::Loc;

    fn trarot(text: &str) -> InputResult<[bool; 6]> {
        let line = Line {
            text: text.to_string(),
            loc: Loc::default(),
        };
        read_trarot(&Card {
            line: &line,
            kw: "/BCS/1",
        })
    }

    #[test]
    fn trarot_is_read_as_the_reference_guide_lays_it_out() {
        let (t, f) = (true, false);
        assert_eq!(trarot("   111 111").unwrap(), [t, t, t, t, t, t]);
        assert_eq!(trarot("   101 000").unwrap(), [t, f, t, f, f, f]);
        assert_eq!(trarot("111111").unwrap(), [t, t, t, t, t, t]);
        // Fewer codes by column: column 6 is TZ, column 10 ωZ (OpenRadioss QA LOI44 writes '     1').
        assert_eq!(trarot("     1             0").unwrap(), [f, f, t, f, f, f]);
        assert_eq!(trarot("         1").unwrap(), [f, f, f, f, f, t]);
        assert_eq!(trarot("   11").unwrap(), [t, t, f, f, f, f]);
        assert!(trarot(" 1").is_err(), "column 2 holds no code");
        assert!(trarot("   121 000").is_err());
        assert!(trarot("").is_err());
    }
}

/// /DAMP/damp_ID (reference guide /DAMP, Starter): short format
/// α (1-20) β (21-40) grnd_ID (41-50) skew_ID (51-60) Tstart (61-80)
/// Tstop (81-100), or the full format: that line with αx βx, then one line
/// αy βy ... αzz βzz per degree of freedom.
fn damping(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 1, "damp_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with alpha, beta, grnod_ID, skew_ID, Tstart, Tstop")?;
    let mut pairs = vec![(c.real(1, "alpha", 0.0)?, c.real(21, "beta", 0.0)?)];
    while let Some(l) = cards.next_nonblank() {
        pairs.push((l.real(1, "alpha", 0.0)?, l.real(21, "beta", 0.0)?));
    }
    if pairs.iter().any(|&(a, b)| a < 0.0 || b < 0.0) {
        return Err(c.err("alpha", "the damping coefficients must be >= 0"));
    }
    let (alpha, beta) = match pairs.len() {
        1 => ([pairs[0].0; 6], [pairs[0].1; 6]),
        6 => (
            std::array::from_fn(|i| pairs[i].0),
            std::array::from_fn(|i| pairs[i].1),
        ),
        n => {
            return Err(c.err(
                "alpha",
                format!("{n} lines of coefficients: expected 1 (short format) or 6 (full format)"),
            ))
        }
    };
    let tstop = c.real(81, "Tstop", 0.0)?;
    deck.dampings.push(DampingSpec {
        id,
        title,
        alpha,
        beta,
        grnod: c.id_opt(41, "grnod_ID")?,
        skew_id: c.id_opt(51, "skew_ID")?,
        tstart: c.real(61, "Tstart", 0.0)?,
        tstop: if tstop == 0.0 { 1e30 } else { tstop },
        loc: c.loc(),
    });
    Ok(true)
}
