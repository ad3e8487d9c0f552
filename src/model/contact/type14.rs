//! /INTER/TYPE14 options: a rigid hyper-ellipsoid against nodes (theory
//! manual §8.9).

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE14 (reference guide "/INTER/TYPE14"):
///
/// Card 1: grnd_IDs (1-10), surf_IDm (11-20), fct_IDld (21-30), fct_IDf (31-40),
///         fct_IDd1 (41-50), fct_IDd2 (51-60).
/// Card 2: Stif (1-20), Fric (21-40), Visc (41-60), Gap (61-80).
///
/// Tstart and Tstop are not on the card (0 and 1e30).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type14 {
    /// grnd_IDs: the secondary nodes.
    pub grnd_ids: Id,
    /// surf_IDm: the main surface, a /SURF/ELLIPS.
    pub surf_idm: Id,
    /// fct_IDld: elastic force vs penetration (0: linear node springs of stiffness Stif).
    pub fct_id_ld: Id,
    /// fct_IDf: friction factor vs nodal elastic force (0: none).
    pub fct_id_f: Id,
    /// fct_IDd1, fct_IDd2: damping vs normal velocity, vs nodal elastic force (0: none).
    pub fct_id_d1: Id,
    pub fct_id_d2: Id,
    /// Stif: the stiffness (with fct_IDld, the scale of its force).
    pub stif: f64,
    /// Fric: friction coefficient.
    pub fric: f64,
    /// Visc: normal viscosity coefficient.
    pub visc: f64,
    /// Gap: impact activation gap.
    pub gap: f64,
}
