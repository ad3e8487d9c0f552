//! /INTER/TYPE24 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE24: penalty node-to-surface contact (formats 2021-2023). The
/// gap is the shells' half thickness (Igap 1 forced); a solid face has none.
///
/// Card 1: surf_ID1 (1-10), surf_ID2 (11-20), Istf (21-30), Irem_i2 (51-60),
/// Idel (71-80), IPSTIF (91-100, 2023).
/// Card 2: grnd_IDs (1-10), Iedge (31-40), Edge_angle (41-60),
/// Gap_max_s (61-80), Gap_max_m (81-100).
/// Card 3: Stmin (1-20), Stmax (21-40), Igap0 (41-50), Ipen0 (51-60),
/// Ipen_max (61-80), Stfac_mdt (81-100, 2023).
/// Card 4: Stfac (1-20), Fric (21-40), Tstart (61-80), Tstop (81-100).
/// Card 5: IBC (8, 9, 10), Inacti (31-40), VISs (41-60), Tpressfit (81-100).
/// Card 6: Ifric (1-10), Ifiltr (11-20), Xfreq (21-40), sens_ID (51-60),
/// DTstif (61-80, 2023), fric_ID (91-100).
/// Then C1-C5 (Ifric > 0), C6 (Ifric > 1).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type24 {
    /// surf_ID1 alone: self-contact; with surf_ID2: the two surfaces (each
    /// side's nodes on the other's segments); 0 with grnd_IDs and surf_ID2:
    /// the group's nodes on surf_ID2.
    pub surf_id1: Id,
    pub surf_id2: Id,
    /// Istf: 0 → 1000 main segment stiffness; 2 mean, 3 max, 4 min, 5 series
    /// of the main and secondary stiffness; 6 (implicit), 7 (the mass and
    /// time-step stiffness only), 12-14 (Nitsche).
    pub istf: i64,
    /// Irem_i2: 0 → 1 (secondary nodes of TYPE2 removed); 3 no change.
    pub irem_i2: i64,
    /// Idel: 0 → 1000 none; ±1, ±2 as TYPE7's.
    pub idel: i64,
    /// IPSTIF (2023): 0 standard stiffness; 1 the larger of it and the mass
    /// and time-step stiffness Stfac_mdt·m*/DTstif².
    pub ipstif: i64,
    pub grnd_ids: Id,
    /// Iedge: 0 → 1000 no edge contact; > 0 edges as fictitious nodes.
    pub iedge: i64,
    /// Edge_angle (degrees, Iedge ≠ 0): 0 → 135.
    pub edge_angle: f64,
    /// Gap_max_s, Gap_max_m: 0 → 1e30.
    pub gap_max_s: f64,
    pub gap_max_m: f64,
    /// Stmin, Stmax (Istf 2-5): 0 → 0, 1e30.
    pub stmin: f64,
    pub stmax: f64,
    /// Igap0: 0 → 1000 no change; 1 zero gap for secondary shell nodes on free edges.
    pub igap0: i64,
    /// Ipen0: 0 → 1000 initial penetrations within a part are not
    /// detected; 1 they are.
    pub ipen0: i64,
    /// Ipen_max: initial penetrations deeper than this are not taken into
    /// account (0: no limit).
    pub ipen_max: f64,
    /// Stfac_mdt: 0 → 0.1 (with IPSTIF = 1).
    pub stfac_mdt: f64,
    /// Stfac: 0 → 1.
    pub stfac: f64,
    pub fric: f64,
    pub tstart: f64,
    /// Tstop: 0 → 1e30.
    pub tstop: f64,
    pub ibc: [bool; 3],
    /// Inacti: 0 → 1000; −1, 1, 3, 5 (6 read as 5).
    pub inacti: i64,
    /// VISs: 0 → 0.05.
    pub viss: f64,
    /// Tpressfit (Inacti = −1).
    pub tpressfit: f64,
    pub ifric: i64,
    pub ifiltr: i64,
    pub xfreq: f64,
    pub sens_id: Id,
    /// DTstif: the time step of the mass stiffness; 0 = the run's current step.
    pub dtstif: f64,
    pub fric_id: Id,
    pub fric_coefs: Option<[f64; 6]>,
}
