//! /INTER/TYPE5 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE5: node to surface "sliding and voids" (non-symmetric).
///
/// Card 1: grnd_IDs (1-10), surf_IDm (11-20), Ibag (61-70), Idel (71-80).
/// Card 2: Stfac (1-20), Fric (21-40), Gap (41-60), Tstart (61-80), Tstop (81-100).
/// Card 3: IBCX IBCY IBCZ (8, 9, 10), IRM (21-30), Inacti (31-40).
/// Card 4: Ifric (1-10), Ifiltr (11-20), Xfreq (21-40), sens_ID (51-60), Ptlim (61-80).
/// Then C1..C5 if Ifric > 0 and C6 if Ifric > 1.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type5 {
    /// grnd_IDs (1-10): secondary node group, required.
    pub grnod_ids: Id,
    /// surf_IDm (11-20): main surface, required.
    pub surf_idm: Id,
    /// Ibag (61-70): 0 = no airbag vent closure, 1 = closure (no 1000 convention here).
    pub ibag: i64,
    /// Idel (71-80): 0 no deletion; 1, 2, -1, -2 as in TYPE3.
    pub idel: i64,
    /// Stfac (card 2, 1-20): stiffness factor, 0 → 0.2 (listing prints 0.2).
    pub stfac: f64,
    /// Fric (21-40): Coulomb friction, default 0.
    pub fric: f64,
    /// Gap (41-60): default 0 (not computed).
    pub gap: f64,
    /// Tstart (61-80), default 0.
    pub tstart: f64,
    /// Tstop (81-100): 0 → 1e30.
    pub tstop: f64,
    /// IBCX, IBCY, IBCZ (card 3, columns 8, 9, 10).
    pub ibc: [bool; 3],
    /// IRM (21-30): main segment renumbering, 0 / 1 / 2 as in TYPE3.
    pub irm: i64,
    /// Inacti (31-40): 0 no action; 3 move secondary nodes; 4 move main nodes.
    pub inacti: i64,
    /// Ifric (card 4, 1-10): 0 Coulomb, 1 generalized viscous, 2 Darmstad, 3 Renard.
    pub ifric: i64,
    /// Ifiltr (11-20): friction filter 0..3; forced to 0 when Xfreq = 0 (as the Starter does).
    pub ifiltr: i64,
    /// Xfreq (21-40): filtering coefficient, default 0.
    pub xfreq: f64,
    /// sens_ID (51-60): activation sensor (0 = none; overrides Tstart/Tstop).
    pub sens_id: Id,
    /// Ptlim (61-80): maximum tangential pressure, 0 → 1e30.
    pub ptlim: f64,
    /// C1..C6: friction law coefficients; `Some` when Ifric > 0 (C6 read only
    /// when Ifric > 1, else 0).
    pub fric_coefs: Option<[f64; 6]>,
}
