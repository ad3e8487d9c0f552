//! The engine file `NAME_0001.rad`: run end time, time-step control, output
//! frequencies. Its data lines are read list-directed (values separated by
//! blanks), as Radioss reads them; its parameters are mostly in the header.

use super::controls::AnimCard;
use super::error::{DeckError, DeckResult, Loc};
use super::fields::{parse_int, Cards};
use super::source::Block;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Engine {
    /// /RUN/name/number: run name, run number, end time.
    pub run: Option<RunCard>,
    /// /DT: time-step scale factor (0 → 0.9) and minimum time step.
    pub dt_scale: f64,
    pub dt_min: f64,
    /// /DT/<type>/<action> cards: (type, action, scale, min).
    pub dt_controls: Vec<DtControl>,
    /// /PRINT/n/nline: listing every |n| cycles; header every nline lines.
    pub print_every: i64,
    pub print_lines: i64,
    /// /ANIM/DT: first animation time and period.
    pub anim_start: f64,
    pub anim_period: Option<f64>,
    pub anim: Vec<AnimCard>,
    /// /TFILE/format: time-history period.
    pub tfile_format: i64,
    pub th_period: Option<f64>,
    /// /RFILE/n: restart file every `rfile_cycles` cycles (None = not asked).
    pub rfile_cycles: Option<i64>,
    pub rfile_sets: i64,
    /// /PARITH/ON|OFF (crashsim is always reproducible; kept for the listing).
    pub parith: Option<bool>,
    pub mon: Option<bool>,
    pub version: Option<i64>,
    /// /PROC/... values (legacy, ignored).
    pub proc_: Vec<i64>,
    /// /STOP: Emax, Mmax, Nmax, NTH, NANIM, NERR_POSIT.
    pub stop: Option<StopCard>,
    pub title: Option<String>,
    pub loc: Loc,
}

impl Default for Engine {
    fn default() -> Self {
        Engine {
            run: None,
            dt_scale: 0.9,
            dt_min: 0.0,
            dt_controls: Vec::new(),
            print_every: 0,
            print_lines: 55,
            anim_start: 0.0,
            anim_period: None,
            anim: Vec::new(),
            tfile_format: 4,
            th_period: None,
            rfile_cycles: None,
            rfile_sets: 0,
            parith: None,
            mon: None,
            version: None,
            proc_: Vec::new(),
            stop: None,
            title: None,
            loc: Loc::default(),
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct RunCard {
    pub name: String,
    pub number: i64,
    pub restart_letter: Option<String>,
    pub tstop: f64,
    pub loc: Loc,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct DtControl {
    pub target: String,
    pub action: String,
    pub scale: f64,
    pub min: f64,
    pub loc: Loc,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct StopCard {
    pub emax: f64,
    pub mmax: f64,
    pub nmax: f64,
    pub nth: i64,
    pub nanim: i64,
    pub nerr_posit: i64,
}

fn header_int(block: &Block, idx: usize, name: &str) -> DeckResult<Option<i64>> {
    match block.parts.get(idx).map(|s| s.trim()) {
        None | Some("") => Ok(None),
        Some(t) => parse_int(t).map(Some).map_err(|m| {
            DeckError::new(
                block.loc.clone(),
                &block.header,
                name,
                format!("'{t}' in the keyword line: {m}"),
            )
        }),
    }
}

/// Returns false for a keyword the engine reader does not know.
pub(super) fn parse_engine_block(block: &Block, eng: &mut Engine) -> DeckResult<bool> {
    let mut cards = Cards::new(block);
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    match block.parts[0].as_str() {
        "RUN" => {
            if p1.is_empty() {
                return Err(DeckError::new(
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
            eng.run = Some(RunCard {
                name,
                number,
                restart_letter: block.parts.get(3).cloned(),
                tstop,
                loc: c.loc(),
            });
        }
        "DT" => {
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
            if p1.is_empty() {
                eng.dt_scale = if scale == 0.0 { 0.9 } else { scale };
                eng.dt_min = min;
            } else {
                eng.dt_controls.push(DtControl {
                    target: p1.to_string(),
                    action: block.parts.get(2).cloned().unwrap_or_default(),
                    scale: if scale == 0.0 { 0.9 } else { scale },
                    min,
                    loc: block.loc.clone(),
                });
            }
        }
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
                eng.anim.push(AnimCard {
                    what: block.parts[1..].to_vec(),
                    loc: block.loc.clone(),
                });
            }
        }
        "TFILE" => {
            eng.tfile_format = header_int(block, 1, "Type")?.unwrap_or(4);
            let c = cards.next("the card with dT_his")?;
            let p = c.tok_real(0, "dT_his")?.unwrap_or(0.0);
            if p <= 0.0 {
                return Err(c.err(
                    "dT_his",
                    format!("{p}: the time-history period must be > 0"),
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
                    return Err(DeckError::new(
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
            eng.stop = Some(StopCard {
                emax: or_big(c.tok_real(0, "Emax")?),
                mmax: or_big(c.tok_real(1, "Mmax")?),
                nmax: or_big(c.tok_real(2, "Nmax")?),
                nth: c.tok_int(3, "NTH")?.unwrap_or(0),
                nanim: c.tok_int(4, "NANIM")?.unwrap_or(0),
                nerr_posit: c.tok_int(5, "NERR_POSIT")?.unwrap_or(0),
            });
        }
        "TITLE" => eng.title = Some(cards.title()),
        _ => return Ok(false),
    }
    Ok(true)
}
