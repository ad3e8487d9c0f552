//! The engine file `NAME_0001.rad`: run end time, time-step control, output
//! frequencies. Its data lines are read list-directed (values separated by
//! blanks), as Radioss reads them; its parameters are mostly in the header.

use super::fields::{parse_int, Cards};
use super::source::Block;
use crate::model::{
    AnimationSpec, DampingOverride, Engine, InputError, InputResult, RunSpec, StopSpec,
};

fn header_int(block: &Block, idx: usize, name: &str) -> InputResult<Option<i64>> {
    match block.parts.get(idx).map(|s| s.trim()) {
        None | Some("") => Ok(None),
        Some(t) => parse_int(t).map(Some).map_err(|m| {
            InputError::new(
                block.loc.clone(),
                &block.header,
                name,
                format!("'{t}' in the keyword line: {m}"),
            )
        }),
    }
}

/// /DT, /DT/NODA (/CST), /DT/BRICK/CST; false for another /DT/<type>/<action>.
fn parse_dt(block: &Block, eng: &mut Engine, cards: &mut Cards) -> InputResult<bool> {
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    match () {
        // /DT/NODA/CST/0: the nodal step with added mass (every node).
        _ if p1 == "NODA"
            && block.parts.get(2).is_some_and(|p| p == "CST")
            && block.parts.get(3).is_none_or(|p| p.trim() == "0") =>
        {
            let c = cards.next("the card with Tsca, Tmin")?;
            let scale = c.tok_real(0, "Tsca")?.unwrap_or(0.0);
            let min = c.tok_real(1, "Tmin")?.unwrap_or(0.0);
            if scale < 0.0 || min <= 0.0 {
                return Err(c.err(
                "Tmin",
                format!("scale {scale}, minimum {min}: expected a scale >= 0 (blank 0.9) and a minimum step > 0"),
            ));
            }
            eng.nodal_cst = Some((if scale == 0.0 { 0.9 } else { scale }, min));
        }
        // /DT/NODA/0: the nodal step alone (no action keyword).
        _ if p1 == "NODA"
            && block
                .parts
                .get(2)
                .is_none_or(|p| p.trim().chars().all(|c| c.is_ascii_digit())) =>
        {
            let c = cards.next("the card with Tsca, Tmin")?;
            let scale = c.tok_real(0, "Tsca")?.unwrap_or(0.0);
            let min = c.tok_real(1, "Tmin")?.unwrap_or(0.0);
            if scale < 0.0 || min < 0.0 {
                return Err(c.err(
                    "Tsca",
                    format!("scale {scale}, minimum {min}: expected values >= 0"),
                ));
            }
            eng.nodal = Some(if scale == 0.0 { 0.9 } else { scale });
        }
        // /DT/BRICK/CST/0: checked against the model's solids before the run.
        _ if p1 == "BRICK"
            && block.parts.get(2).is_some_and(|p| p == "CST")
            && block.parts.get(3).is_none_or(|p| p.trim() == "0") =>
        {
            let c = cards.next("the card with Tsca, Tmin")?;
            c.tok_real(0, "Tsca")?;
            c.tok_real(1, "Tmin")?;
            eng.brick_cst = Some(block.loc.clone());
        }
        // Any other /DT/<type>/<action> (per-type steps, AMS, other nodal
        // options) is not computed: left to the keyword policy, which names it.
        _ if !p1.is_empty() => return Ok(false),
        _ => {
            let c = cards.next_nonblank();
            let (scale, min) = match c {
                Some(c) => (
                    c.tok_real(0, "Tsca")?.unwrap_or(0.0),
                    c.tok_real(1, "Tmin")?.unwrap_or(0.0),
                ),
                None => (0.0, 0.0),
            };
            if scale < 0.0 || min < 0.0 {
                let c = c.unwrap();
                return Err(c.err(
                    "Tsca",
                    format!("scale {scale}, minimum {min}: expected values >= 0"),
                ));
            }
            eng.dt_scale = if scale == 0.0 { 0.9 } else { scale };
            eng.dt_min = min;
        }
    }
    Ok(true)
}

/// Returns false for a keyword the engine reader does not know.
pub(crate) fn parse_engine_block(block: &Block, eng: &mut Engine) -> InputResult<bool> {
    let mut cards = Cards::new(block);
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    match block.parts[0].as_str() {
        "RUN" => {
            if p1.is_empty() {
                return Err(InputError::new(
                    block.loc.clone(),
                    &block.header,
                    "RunName",
                    "expected /RUN/RunName/RunNumber",
                ));
            }
            let name = block
                .header
                .trim_start_matches('/')
                .split('/')
                .nth(1)
                .unwrap_or("")
                .trim()
                .to_string();
            let number = header_int(block, 2, "RunNumber")?.unwrap_or(1);
            let c = cards.next("the card with Tstop (end time)")?;
            let tstop = c.tok_real(0, "Tstop")?.unwrap_or(0.0);
            if tstop <= 0.0 {
                return Err(c.err("Tstop", format!("{tstop}: the end time must be > 0")));
            }
            eng.run = Some(RunSpec {
                name,
                number,
                restart_letter: block.parts.get(3).cloned(),
                tstop,
                loc: c.loc(),
            });
        }
        "DT" => return parse_dt(block, eng, &mut cards),
        "PRINT" => {
            eng.print_every = header_int(block, 1, "Nprint")?.unwrap_or(0);
            eng.print_lines = header_int(block, 2, "Nline")?.unwrap_or(55);
        }
        "ANIM" => {
            if p1 == "DT" {
                let c = cards.next("the card with Tstart, Tfreq")?;
                eng.anim_start = c.tok_real(0, "Tstart")?.unwrap_or(0.0);
                let f = c.tok_real(1, "Tfreq")?.unwrap_or(0.0);
                if f <= 0.0 {
                    return Err(c.err("Tfreq", format!("{f}: the animation period must be > 0")));
                }
                eng.anim_period = Some(f);
            } else {
                eng.anim.push(AnimationSpec {
                    what: block.parts[1..].to_vec(),
                    loc: block.loc.clone(),
                });
            }
        }
        "TFILE" => {
            eng.tfile_format = header_int(block, 1, "Type")?.unwrap_or(4);
            let c = cards.next("the card with dT_his")?;
            // 0 samples every cycle: OpenRadioss QA's OPTIONS_damp deck has
            // dT_his = 0, its engine listing prints "TIME INTERVAL FOR TIME
            // HISTORY PLOTS 0.000000" and its T01 file holds a row per cycle.
            let p = c.tok_real(0, "dT_his")?.unwrap_or(0.0);
            if p < 0.0 {
                return Err(c.err(
                    "dT_his",
                    format!("{p}: the time-history period must be >= 0 (0: every cycle)"),
                ));
            }
            eng.th_period = Some(p);
        }
        "RFILE" => {
            if p1 == "OFF" {
                eng.rfile_cycles = None;
            } else {
                eng.rfile_sets = header_int(block, 1, "n")?.unwrap_or(0);
                let n = match cards.next_nonblank() {
                    Some(c) => c.tok_int(0, "Ncycle")?.unwrap_or(0),
                    None => 0,
                };
                if n < 0 {
                    return Err(InputError::new(
                        block.loc.clone(),
                        &block.header,
                        "Ncycle",
                        format!("{n}: expected a cycle count >= 0"),
                    ));
                }
                eng.rfile_cycles = Some(if n == 0 { 10_000_000 } else { n });
            }
        }
        "PARITH" | "MON" => {
            let on = match p1 {
                "ON" | "" => true,
                "OFF" => false,
                _ => return Ok(false),
            };
            if block.parts[0] == "PARITH" {
                eng.parith = Some(on);
            } else {
                eng.mon = Some(on);
            }
        }
        "VERS" => eng.version = header_int(block, 1, "version")?,
        "PROC" => {
            for i in 1..block.parts.len() {
                eng.proc_.push(header_int(block, i, "Nproc")?.unwrap_or(0));
            }
        }
        "STOP" => {
            let c = cards.next("the card with Emax, Mmax, Nmax, NTH, NANIM, NERR_POSIT")?;
            let or_big = |v: Option<f64>| match v {
                None | Some(0.0) => 1e30,
                Some(v) => v,
            };
            eng.stop = Some(StopSpec {
                emax: or_big(c.tok_real(0, "Emax")?),
                mmax: or_big(c.tok_real(1, "Mmax")?),
                nmax: or_big(c.tok_real(2, "Nmax")?),
                nth: c.tok_int(3, "NTH")?.unwrap_or(0),
                nanim: c.tok_int(4, "NANIM")?.unwrap_or(0),
                nerr_posit: c.tok_int(5, "NERR_POSIT")?.unwrap_or(0),
                loc: block.loc.clone(),
            });
        }
        "TITLE" => eng.title = Some(cards.title()),
        "DTIX" => {
            // ΔT_ini ΔT_max (reference guide /DTIX, Engine).
            let c = cards.next("the card with DT_ini, DT_max")?;
            let ini = c.tok_real(0, "DT_ini")?.unwrap_or(0.0);
            let max = c.tok_real(1, "DT_max")?.unwrap_or(0.0);
            if ini < 0.0 || max < 0.0 {
                return Err(c.err("DT_ini", format!("{ini} {max}: expected time steps >= 0")));
            }
            eng.dtix = (ini, max);
        }
        "RBODY" if p1 == "ON" => {
            // The rigid bodies to switch on (rbody_IDs, list-directed; 0: none).
            while let Some(c) = cards.next_nonblank() {
                for i in 0..c.tokens().len() {
                    let id = c.tok_int(i, "rbody_ID")?.unwrap_or(0);
                    if id != 0 {
                        eng.rbody_on.push((id, c.loc()));
                    }
                }
            }
        }
        "DAMP" if block.parts.len() == 2 => eng.dampings.push(damping(block, &mut cards)?),
        _ => return Ok(false),
    }
    Ok(true)
}

/// Engine /DAMP/damp_ID: `α β` (list-directed) for every degree of freedom,
/// or six lines, one `α β` pair per degree of freedom X, Y, Z, XX, YY, ZZ
/// (reference guide /DAMP, Engine).
fn damping(block: &Block, cards: &mut Cards) -> InputResult<DampingOverride> {
    let id = header_int(block, 1, "damp_ID")?.unwrap_or(0);
    if id <= 0 {
        return Err(InputError::new(
            block.loc.clone(),
            &block.header,
            "damp_ID",
            "expected /DAMP/damp_ID with the id of a starter /DAMP",
        ));
    }
    let mut pairs = Vec::new();
    while let Some(c) = cards.next_nonblank() {
        let a = c.tok_real(0, "alpha")?.unwrap_or(0.0);
        let b = c.tok_real(1, "beta")?.unwrap_or(0.0);
        if a < 0.0 || b < 0.0 {
            return Err(c.err(
                "alpha",
                format!("{a} {b}: the damping coefficients must be >= 0"),
            ));
        }
        pairs.push((a, b));
    }
    let (alpha, beta) = match pairs.len() {
        1 => ([pairs[0].0; 6], [pairs[0].1; 6]),
        6 => (
            std::array::from_fn(|i| pairs[i].0),
            std::array::from_fn(|i| pairs[i].1),
        ),
        n => {
            return Err(InputError::new(
                block.loc.clone(),
                &block.header,
                "alpha",
                format!(
                    "{n} lines: expected one line `alpha beta` or six, one per degree of freedom"
                ),
            ))
        }
    };
    Ok(DampingOverride {
        id: id as u64,
        alpha,
        beta,
        loc: block.loc.clone(),
    })
}
