//! /INTER/TYPE6 options: rigid body contact whose total force is a user
//! function of the largest penetration (theory manual §8.7).

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE6 (reference guide "/INTER/TYPE6", format 2017 and later):
///
/// Card 1: surf_ID1 (1-10), surf_ID2 (11-20).
/// Card 2: Sfric (1-20), Fric (21-40), Gap (41-60), Tstart (61-80), Tstop (81-100).
/// Card 3: IRS (11-20), IRm (21-30), Inacti (31-40), fct_IDff (41-50),
///         fct_IDfv (51-60), Ascalef (61-80), Ascalev (81-100).
/// Card 4: fct_IDld (1-10), Iform (11-20), Ascalex (21-40), FscaleId (41-60), Icor (61-70).
/// Card 5: fct_IDul (1-10), Stiff (21-40), Fscaleul (41-60).
/// Card 6: Visc (1-20), fct_IDdv (21-30), fct_IDdf (31-40), Fscalev (41-60).
///
/// Cards 5 and 6 may be absent (their fields take their defaults).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type6 {
    /// surf_ID1, surf_ID2: the two rigid surfaces (each on one rigid body),
    /// facing each other. Surface 1 is stored as the secondary side.
    pub surf_id1: Id,
    pub surf_id2: Id,
    /// Sfric: static friction force, default 0.
    pub sfric: f64,
    /// Fric: Coulomb friction coefficient, default 0.
    pub fric: f64,
    /// Gap: impact activation gap, default 0.
    pub gap: f64,
    pub tstart: f64,
    /// Tstop: 0 → 1e30.
    pub tstop: f64,
    /// IRS, IRm: segment normal renumbering of surfaces 1 and 2 (0, 1, 2 as TYPE3).
    pub irs: i64,
    pub irm: i64,
    /// Inacti: 0 or 5.
    pub inacti: i64,
    /// fct_IDff, fct_IDfv: friction factor vs normal force and vs sliding velocity (0: none).
    pub fct_id_ff: Id,
    pub fct_id_fv: Id,
    /// Ascalef, Ascalev: their abscissa scales, 0 → 1.
    pub ascalef: f64,
    pub ascalev: f64,
    /// fct_IDld: loading force vs penetration (required).
    pub fct_id_ld: Id,
    /// Iform: 0 nonlinear elastic; 1 elasto-plastic with the unloading curve;
    /// 2 elasto-plastic unloading on Stiff. The reader applies the Starter's
    /// rules: Iform > 0 with no fct_IDul becomes 2, with Stiff = 0 becomes 0.
    pub iform: i64,
    /// Ascalex: penetration scale of fct_IDld and fct_IDul, 0 → 1 (f is
    /// evaluated at p / Ascalex).
    pub ascalex: f64,
    /// FscaleId: ordinate scale of fct_IDld, 0 → 1.
    pub fscale_ld: f64,
    /// Icor: force correction for an initial intersection (forced to 0 with Iform = 0).
    pub icor: i64,
    /// fct_IDul: unloading force vs penetration (0: none).
    pub fct_id_ul: Id,
    /// Stiff: loading / unloading transition stiffness, 0 → 1e30.
    pub stiff: f64,
    /// Fscaleul: ordinate scale of fct_IDul, 0 → 1.
    pub fscale_ul: f64,
    /// Visc: damping force per unit normal velocity, default 0.
    pub visc: f64,
    /// fct_IDdv: damping force vs normal velocity; fct_IDdf: damping factor vs normal force (0: none).
    pub fct_id_dv: Id,
    pub fct_id_df: Id,
    /// Fscalev: ordinate scale of fct_IDdv, 0 → 1.
    pub fscalev: f64,
}
