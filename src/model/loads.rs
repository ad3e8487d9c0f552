//! Boundary and initial conditions and loads: fixed degrees of freedom,
//! imposed velocities and displacements, initial velocities, concentrated
//! loads and gravity. Each names a node group by id; the model resolves it.

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// A degree of freedom named by a `Dir` field.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq)]
pub enum Dof {
    X,
    Y,
    Z,
    Xx,
    Yy,
    Zz,
}

impl Dof {
    /// 0..2 translations, 3..5 rotations.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// /BCS: Trarot (1-10, "111 111"), skew_ID (11-20), grnod_ID (21-30).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BoundarySpec {
    pub id: Id,
    pub title: String,
    /// Fixed translations X, Y, Z then rotations X, Y, Z.
    pub fixed: [bool; 6],
    pub skew_id: Id,
    pub grnod: Id,
    pub loc: Loc,
}

/// /IMPVEL and /IMPDISP: value(t) = Fscale_Y · f(t / Ascale_x) on Dir, between Tstart and Tstop.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ImposedMotionSpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub fct: Id,
    pub dir: Dof,
    pub skew_id: Id,
    pub sens_id: Id,
    pub grnod: Id,
    /// /IMPVEL only (0 = none).
    pub frame_id: Id,
    /// 0 Cartesian, 1 cylindrical.
    pub icoor: i64,
    /// Abscissa (time) scale (0 → 1).
    pub ascale_x: f64,
    /// Ordinate scale (0 → 1).
    pub fscale_y: f64,
    pub tstart: f64,
    /// 0 → 1e30.
    pub tstop: f64,
    pub loc: Loc,
}

/// /INIVEL/TRA (translational) or /INIVEL/ROT (rotational): V (1-60), grnod_ID (61-70), skew_ID (71-80).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct InitialVelocitySpec {
    pub id: Id,
    pub title: String,
    pub rotational: bool,
    pub v: [f64; 3],
    pub grnod: Id,
    pub skew_id: Id,
    pub loc: Loc,
}

/// /CLOAD: force (or moment) on each node of the group, Fscale_y · f(t / Ascale_x).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ConcentratedLoadSpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub fct: Id,
    pub dir: Dof,
    pub skew_id: Id,
    pub sens_id: Id,
    pub grnod: Id,
    pub ascale_x: f64,
    pub fscale_y: f64,
    pub loc: Loc,
}

/// /DAMP: Rayleigh damping of a node group, mass-proportional α and
/// stiffness-proportional β per degree of freedom (X, Y, Z, XX, YY, ZZ),
/// active from Tstart to Tstop (reference guide /DAMP; research note
/// `docs/notes/springs_research.md` §5).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DampingSpec {
    pub id: Id,
    pub title: String,
    pub alpha: [f64; 6],
    pub beta: [f64; 6],
    /// 0 = every node.
    pub grnod: Id,
    pub skew_id: Id,
    pub tstart: f64,
    pub tstop: f64,
    pub loc: Loc,
}

/// An engine-file /DAMP: new coefficients for the starter's /DAMP of the
/// same id from this run on.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct DampingOverride {
    pub id: Id,
    pub alpha: [f64; 6],
    pub beta: [f64; 6],
    pub loc: Loc,
}

/// /GRAV: acceleration Fscale_y · f(t / Ascale_x) (constant Fscale_y if fct_ID = 0).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct GravitySpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub fct: Id,
    pub dir: Dof,
    pub skew_id: Id,
    pub sens_id: Id,
    /// 0 = every node.
    pub grnod: Id,
    pub ascale_x: f64,
    pub fscale_y: f64,
    pub loc: Loc,
}

/// /IMPDISP/FGEO: nodes moved along straight lines from their initial to
/// their final positions, u(t) = f(Ascale·t)·(X_f − X₀) between Tstart and
/// Tstop (research note `docs/notes/impdisp_fgeo_research.md` §2).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FinalGeometry {
    pub id: Id,
    pub fct: Id,
    pub ascale: f64,
    pub tstart: f64,
    pub tstop: f64,
    /// The nodes (dense indices) and their final positions.
    pub nodes: Vec<u32>,
    pub target: Vec<[f64; 3]>,
    pub loc: Loc,
}

/// /PLOAD: a pressure p(t) = Fscale_y · f(t / Ascale_x) on each segment of
/// a surface, pushing along the segment's right-hand normal N1N3 × N2N4
/// (reference guide /PLOAD, comment 1).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PressureLoadSpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub surf: Id,
    pub fct: Id,
    pub ascale_x: f64,
    pub fscale_y: f64,
    /// Idel 2: the load stays on a segment whose element was deleted
    /// (1, the default: it goes with its element).
    pub keep_after_deletion: bool,
    pub loc: Loc,
}
