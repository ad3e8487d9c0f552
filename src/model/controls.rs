//! Run controls: the input's header (run name, units) and the engine
//! controls (end time, time-step control, output periods, stop criteria).

use super::{AnimationSpec, Loc};
use serde::{Deserialize, Serialize};

/// /BEGIN: run name; Invers (1-10), Irun (11-20); input units; work units.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Begin {
    pub run_name: String,
    pub invers: i64,
    pub irun: i64,
    pub input_units: Units,
    pub work_units: Units,
    pub loc: Loc,
}

/// A unit system: each unit as written (e.g. "kg", "mm", "ms") and its factor to SI.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Units {
    pub mass: String,
    pub length: String,
    pub time: String,
    pub mass_si: f64,
    pub length_si: f64,
    pub time_si: f64,
}

impl Default for Units {
    fn default() -> Self {
        Units {
            mass: "kg".into(),
            length: "m".into(),
            time: "s".into(),
            mass_si: 1.0,
            length_si: 1.0,
            time_si: 1.0,
        }
    }
}

/// The engine (run) controls: end time, time-step control, output periods, stop criteria
/// (Radioss: the engine file `NAME_0001.rad`).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Engine {
    /// /RUN/name/number: run name, run number, end time.
    pub run: Option<RunSpec>,
    /// /DT: time-step scale factor (0 → 0.9) and minimum time step.
    pub dt_scale: f64,
    pub dt_min: f64,
    /// /DTIX: the first time step at most `dtix.0`, every step at most
    /// `dtix.1` (0: no bound).
    #[serde(default)]
    pub dtix: (f64, f64),
    /// /DT/NODA/CST/0: the nodal time step with added mass (scale ΔTsca,
    /// minimum ΔTmin): the step comes from the nodes, each node below
    /// ΔTmin gets the mass (and inertia) that brings it there.
    #[serde(default)]
    pub nodal_cst: Option<(f64, f64)>,
    /// /DT/NODA/0: the time step from the nodes without added mass (its
    /// scale; its Tmin is read and, as in the reference engine, acts on
    /// nothing without an action keyword).
    #[serde(default)]
    pub nodal: Option<f64>,
    /// /DT/BRICK/CST/0: bricks' mass scaling, accepted in a model without
    /// solids, where it changes nothing (refused by name with solids).
    #[serde(default)]
    pub brick_cst: Option<Loc>,
    /// /RBODY/ON: the rigid bodies it names (they are active from the start:
    /// checked to exist, nothing to switch).
    #[serde(default)]
    pub rbody_on: Vec<(i64, Loc)>,
    /// /PRINT/n/nline: listing every |n| cycles; header every nline lines.
    pub print_every: i64,
    pub print_lines: i64,
    /// /ANIM/DT: first animation time and period.
    pub anim_start: f64,
    pub anim_period: Option<f64>,
    pub anim: Vec<AnimationSpec>,
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
    pub stop: Option<StopSpec>,
    pub title: Option<String>,
    /// /DAMP: new coefficients for starter /DAMP cards.
    pub dampings: Vec<super::DampingOverride>,
    pub loc: Loc,
}

impl Default for Engine {
    fn default() -> Self {
        Engine {
            run: None,
            dt_scale: 0.9,
            dt_min: 0.0,
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
            dampings: Vec::new(),
            dtix: (0.0, 0.0),
            nodal_cst: None,
            nodal: None,
            brick_cst: None,
            rbody_on: Vec::new(),
            loc: Loc::default(),
        }
    }
}

/// The run to compute: name, number and end time (Radioss: /RUN).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct RunSpec {
    pub name: String,
    pub number: i64,
    pub restart_letter: Option<String>,
    pub tstop: f64,
    pub loc: Loc,
}

/// Stop criteria (Radioss: /STOP).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct StopSpec {
    pub emax: f64,
    pub mmax: f64,
    pub nmax: f64,
    pub nth: i64,
    pub nanim: i64,
    pub nerr_posit: i64,
    pub loc: Loc,
}
