//! /BEGIN, the starter control cards (/ANALY, /SPMD, /IOFLAG,
//! /SHFRA), time-history requests (/TH/*) and starter /ANIM requests.

use super::fields::{Card, Cards};
use super::list_end;
use super::source::Block;
use super::{header_id, Deck};
use crate::model::{AnimationSpec, Begin, InputResult, TimeHistorySpec, Units};
use serde::{Deserialize, Serialize};

pub(super) fn parse_begin(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let mut cards = Cards::new(block);
    let c0 = cards.next("the run-name card")?;
    let run_name = c0.line.text.trim().to_string();
    let c1 = cards.next("the card with Invers, Irun")?;
    let invers = c1.int(1, "Invers", 0)?;
    let irun = c1.int(11, "Irun", 0)?;
    let input = cards.next_opt();
    let work = cards.next_opt();
    let work_units = match work {
        Some(c) => read_units(&c, None)?,
        None => Units::default(),
    };
    let input_units = match input {
        Some(c) => read_units(&c, Some(&work_units))?,
        None => work_units.clone(),
    };
    deck.begin = Some(Begin {
        run_name,
        invers,
        irun,
        input_units,
        work_units,
        loc: block.loc.clone(),
    });
    Ok(())
}

/// Mass (1-20), length (21-40), time (41-60): a unit code (SI prefix + g, m, s)
/// or a factor to kg, m, s. Blank takes `default` (work units), else SI.
fn read_units(c: &Card, default: Option<&Units>) -> InputResult<Units> {
    let si = Units::default();
    let d = default.unwrap_or(&si);
    // The field at `col`, its name, its SI base unit and its blank default (name, factor).
    let field =
        |col: usize, name: &str, base: &str, blank: (&str, f64)| -> InputResult<(String, f64)> {
            let (dname, dfac) = blank;
            let t = c.text(col, 20);
            if t.is_empty() {
                return Ok((dname.to_string(), dfac));
            }
            if let Ok(v) = super::fields::parse_real(t) {
                if v > 0.0 {
                    return Ok((t.to_string(), v));
                }
                return Err(c.err(name, format!("{v}: a unit factor must be > 0")));
            }
            unit_factor(t, base)
                .map(|f| (t.to_string(), f))
                .ok_or_else(|| {
                    c.err(
                        name,
                        format!(
                            "'{t}': expected a unit like {} or a positive factor",
                            match base {
                                "g" => "kg, g, Mg, mg",
                                "m" => "m, mm, cm, km",
                                _ => "s, ms, mus",
                            }
                        ),
                    )
                })
        };
    let (mass, mass_si) = field(1, "mass unit", "g", (&d.mass, d.mass_si))?;
    let (length, length_si) = field(21, "length unit", "m", (&d.length, d.length_si))?;
    let (time, time_si) = field(41, "time unit", "s", (&d.time, d.time_si))?;
    Ok(Units {
        mass,
        length,
        time,
        mass_si,
        length_si,
        time_si,
    })
}

/// SI factor of a prefixed unit code (`mm` → 1e-3 m, `Mg` → 1e3 kg, `mus` → 1e-6 s).
/// Prefixes are case-sensitive (`m` milli, `M` mega).
pub fn unit_factor(code: &str, base: &str) -> Option<f64> {
    let prefix = code.strip_suffix(base)?;
    let p = match prefix {
        "" => 1.0,
        "y" => 1e-24,
        "z" => 1e-21,
        "a" => 1e-18,
        "f" => 1e-15,
        "p" => 1e-12,
        "n" => 1e-9,
        "mu" | "u" | "µ" | "μ" => 1e-6,
        "m" => 1e-3,
        "c" => 1e-2,
        "d" => 1e-1,
        "da" => 1e1,
        "h" => 1e2,
        "k" => 1e3,
        "M" => 1e6,
        "G" => 1e9,
        "T" => 1e12,
        "P" => 1e15,
        "E" => 1e18,
        _ => return None,
    };
    // Mass is based on the gram: kg = 1.
    Some(if base == "g" { p * 1e-3 } else { p })
}

/// The starter control cards. Values kept as written; they switch Radioss
/// output and decomposition features that crashsim sets otherwise (MPI ranks
/// from mpirun, output to HDF5).
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct Controls {
    /// /ANALY: N2D3D (1-10), IPARITH (21-30), ISUB (31-40).
    pub analy: Option<[i64; 3]>,
    /// /SPMD: DOMDEC (1-10), Nproc (11-20), Dkword (31-40), Nthread (51-60).
    pub spmd: Option<[i64; 4]>,
    /// /IOFLAG: IPRI (1-10), IGTYP (21-30), IOUTP (31-40), IOUTYY (41-50), IROOTYY (51-60), IDROT (61-70).
    pub ioflag: Option<[i64; 6]>,
    /// /SHFRA/V4 or /SHFRA/V5.
    pub shfra: Option<String>,
}

pub(super) fn parse_control(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let mut cards = Cards::new(block);
    let ctl = &mut deck.controls;
    match block.parts[0].as_str() {
        "ANALY" => {
            let c = cards.next("the card with N2D3D, IPARITH, ISUB")?;
            let n2d3d = c.flag(1, "N2D3D", 0, &[0, 1, 2])?;
            if n2d3d != 0 {
                return Err(c.err(
                    "N2D3D",
                    format!("{n2d3d}: 2-D analysis is not supported; expected 0 (3-D)"),
                ));
            }
            ctl.analy = Some([n2d3d, c.int(21, "IPARITH", 0)?, c.int(31, "ISUB", 0)?]);
        }
        "SPMD" => {
            let c = cards.next("the card with DOMDEC, Nproc, Dkword, Nthread")?;
            ctl.spmd = Some([
                c.int(1, "DOMDEC", 0)?,
                c.int(11, "Nproc", 0)?,
                c.int(31, "Dkword", 0)?,
                c.int(51, "Nthread", 0)?,
            ]);
        }
        "IOFLAG" => {
            let c = cards.next("the card with IPRI, IGTYP, IOUTP, IOUTYY, IROOTYY, IDROT")?;
            ctl.ioflag = Some([
                c.int(1, "IPRI", 0)?,
                c.int(21, "IGTYP", 0)?,
                c.int(31, "IOUTP", 0)?,
                c.int(41, "IOUTYY", 0)?,
                c.int(51, "IROOTYY", 0)?,
                c.int(61, "IDROT", 0)?,
            ]);
        }
        "SHFRA" => {
            let v = block.parts.get(1).cloned().unwrap_or_default();
            if v != "V4" && v != "V5" {
                return Ok(false);
            }
            ctl.shfra = Some(v);
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// Object types whose object lines hold one id and a name (id 1-10, skew 11-20, name 21-100).
const TH_ONE_PER_LINE: &[&str] = &[
    "NODE", "SHELL", "SHEL", "SH3N", "BRIC", "BRICK", "SPRING", "TRUSS", "BEAM",
];

pub(super) fn parse_th(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let Some(kind) = block.parts.get(1).cloned() else {
        return Ok(false);
    };
    let id = header_id(block, 2, "thgroup_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let mut variables = Vec::new();
    let mut objects = Vec::new();
    let one_per_line = TH_ONE_PER_LINE.contains(&kind.as_str());
    while let Some(c) = cards.next_nonblank() {
        let first = c.text(1, 10);
        // Variable lines hold names (a letter, then letters, digits or '_');
        // object lines hold ids.
        if objects.is_empty()
            && first
                .chars()
                .next()
                .is_some_and(|ch| ch.is_ascii_alphabetic())
            && first
                .chars()
                .all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
        {
            for k in 0..10 {
                let v = c.text(1 + 10 * k, 10);
                if !v.is_empty() {
                    variables.push(v.to_ascii_uppercase());
                }
            }
            continue;
        }
        if list_end::holds_text(&c) {
            list_end::ended_by_text(&c, &cards, "/TH object id", &mut deck.warnings);
            break;
        }
        if one_per_line {
            // 0 names no object, as a 0 among ten ids per line does.
            let v = c.id_opt(1, "obj_ID")?;
            if v != 0 {
                objects.push(v);
            }
            // Iskew (11-20): the histories are written in the global frame.
            if let Some(sk) = c.text(11, 10).parse::<u64>().ok().filter(|&k| k != 0) {
                deck.warnings.push(crate::model::Warning {
                    loc: c.loc(),
                    keyword: block.header.clone(),
                    message: format!(
                        "object {v}: Iskew {sk}: its time history is written in the global frame (histories in a skew or frame are not written yet); the solution does not depend on it"
                    ),
                });
            }
        } else {
            for k in 0..10 {
                let v = c.id_opt(1 + 10 * k, "obj_ID")?;
                if v != 0 {
                    objects.push(v);
                }
            }
        }
    }
    deck.time_histories.push(TimeHistorySpec {
        id,
        kind,
        title,
        variables,
        objects,
        loc: block.loc.clone(),
    });
    Ok(true)
}

pub(super) fn parse_anim(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    deck.animations.push(AnimationSpec {
        what: block.parts[1..].to_vec(),
        loc: block.loc.clone(),
    });
    Ok(true)
}
