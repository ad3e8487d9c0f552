//! /INTER/TYPE25 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE25: penalty contact without an activation gap (format 2021-2022).
/// The only gap is the shells' half thickness; a solid face has none.
///
/// Card 1: surf_ID1 (1-10), surf_ID2 (11-20), Istf (21-30), Ithe (31-40),
/// Igap (41-50), Irem_i2 (51-60), Idel (71-80), Iedge (81-90), IPSTIF (91-100, 2023).
/// Card 2: grnd_IDs (1-10), Gap_scale (21-40), %mesh_size (41-60),
/// Gap_max_s (61-80), Gap_max_m (81-100).
/// Card 3: Stmin (1-20), Stmax (21-40), Igap0 (41-50), Ishape (51-60), Edge_angle (61-80),
/// Stfac_mdt (81-100, 2023).
/// Card 4: Stfac (1-20), Fric (21-40), Tpressfit (41-60), Tstart (61-80), Tstop (81-100).
/// Card 5: IBC (8, 9, 10), IVIS2 (21-30), Inacti (31-40), VISs (41-60), Ithick (61-70), Pmax (81-100).
/// Card 6: Ifric (1-10), Ifiltr (11-20), Xfreq (21-40), sens_ID (51-60),
/// DTstif (61-80, 2023), fric_ID (91-100).
/// Then C1-C5 (Ifric > 0), C6 (Ifric > 1).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type25 {
    /// surf_ID1 alone: self-contact; with surf_ID2: the two surfaces (each
    /// side's nodes on the other's segments); 0 with grnd_IDs and surf_ID2:
    /// the group's nodes on surf_ID2.
    pub surf_id1: Id,
    pub surf_id2: Id,
    /// Istf: 0 → 1000 main segment stiffness; 2 mean, 3 max, 4 min, 5 series
    /// of the main and secondary stiffness.
    pub istf: i64,
    pub ithe: i64,
    /// Igap: 0 → 1 variable gap (half thicknesses); 2, 3 as TYPE7's.
    pub igap: i64,
    /// Irem_i2: 0 → 1 (secondary nodes of TYPE2 removed); 3 no change.
    pub irem_i2: i64,
    /// Idel: 0 → 1000 none; ±1, ±2 as TYPE7's.
    pub idel: i64,
    /// Iedge: 0 → 1000 no edge contact; 1, 11, 13, 22 edge selections.
    pub iedge: i64,
    pub grnd_ids: Id,
    /// Gap_scale: 0 → 1.
    pub gap_scale: f64,
    /// %mesh_size (Igap 3): 0 → 0.4.
    pub mesh_size_pct: f64,
    /// Gap_max_s, Gap_max_m: 0 → 1e30.
    pub gap_max_s: f64,
    pub gap_max_m: f64,
    /// Stmin, Stmax (Istf 2-5): 0 → 0, 1e30.
    pub stmin: f64,
    pub stmax: f64,
    /// Igap0: 0 → 1000 no change; 1 zero gap for secondary shell nodes on free edges.
    pub igap0: i64,
    /// Ishape: 0 → 1 square gap shape along free edges; 2 rounded.
    pub ishape: i64,
    /// Edge_angle (degrees, Iedge ≠ 0): 0 → 135.
    pub edge_angle: f64,
    /// Stfac: 0 → 1.
    pub stfac: f64,
    pub fric: f64,
    /// Tpressfit (Inacti = −1).
    pub tpressfit: f64,
    pub tstart: f64,
    /// Tstop: 0 → 1e30.
    pub tstop: f64,
    pub ibc: [bool; 3],
    /// IVIS2: 0 → 1 damping with the harmonic mean of the two sides' masses;
    /// 6 the secondary node's mass; 4 none; 2, 3, 5, −1 other forms.
    pub ivis2: i64,
    /// Inacti: 0 → 1000; −1, 1, 3, 5 (6 read as 5).
    pub inacti: i64,
    /// VISs: 0 → 0.05 (1.0 with IVIS2 = 5).
    pub viss: f64,
    /// Ithick: 1 = the main gap follows the current shell thickness.
    pub ithick: i64,
    /// Pmax: 0 → 1e30.
    pub pmax: f64,
    pub ifric: i64,
    pub ifiltr: i64,
    pub xfreq: f64,
    pub sens_id: Id,
    pub fric_id: Id,
    pub fric_coefs: Option<[f64; 6]>,
    /// IPSTIF (2023): 0 standard stiffness; 1 the larger of it and the mass
    /// and time-step stiffness Stfac_mdt·m*/DTstif².
    pub ipstif: i64,
    /// Stfac_mdt: 0 → 0.1 (with IPSTIF = 1).
    pub stfac_mdt: f64,
    /// DTstif: the time step of that stiffness; 0 = the run's current step.
    pub dtstif: f64,
}

/// TYPE25's penalty as its card sets it: the pair stiffness (Istf, Stmin,
/// Stmax), the damper (VISs, IVIS2) and the gap's scale and caps; shared
/// by its node part, its edge part (Iedge) and TYPE24's kernel
/// (`contact::interfaces::type25`).
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct Penalty25 {
    pub istf: i64,
    pub stmin: f64,
    pub stmax: f64,
    pub viss: f64,
    pub ivis2: i64,
    pub gap_scale: f64,
    pub gap_max_s: f64,
    pub gap_max_m: f64,
}

impl Type25 {
    /// The penalty's options from the card.
    pub fn penalty(&self) -> Penalty25 {
        Penalty25 {
            istf: self.istf,
            stmin: self.stmin,
            stmax: self.stmax,
            viss: self.viss,
            ivis2: self.ivis2,
            gap_scale: self.gap_scale,
            gap_max_s: self.gap_max_s,
            gap_max_m: self.gap_max_m,
        }
    }

    /// The edge-to-edge part of the card (Iedge 1: the surfaces' free
    /// edges, the borders of their shells): a TYPE11 card of the same
    /// stiffness, friction, times and Idel, carrying TYPE25's penalty; its
    /// lines are set by the caller.
    pub fn edge_part(&self) -> super::Type11 {
        super::Type11 {
            line_ids: 0,
            line_idm: 0,
            istf: self.istf,
            ithe: 0,
            igap: 2,
            irem_gap: 1,
            idel: self.idel,
            stmin: self.stmin,
            stmax: self.stmax,
            mesh_size_pct: self.mesh_size_pct,
            dtmin: 0.0,
            iform: 2,
            sens_id: self.sens_id,
            stfac: self.stfac,
            fric: self.fric,
            gapmin: 0.0,
            tstart: self.tstart,
            tstop: self.tstop,
            ibc: [false; 3],
            inacti: 1000,
            viss: self.viss,
            visf: 0.0,
            bumult: 0.2,
            fric_id: self.fric_id,
            thermal: None,
            dyna: None,
            penalty25: Some(self.penalty()),
        }
    }
}
