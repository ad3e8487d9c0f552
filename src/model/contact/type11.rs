//! /INTER/TYPE11 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE11: edge to edge contact between two /LINE sets (format 2018-2024).
///
/// Card 1: line_IDs (1-10), line_IDm (11-20), Istf (21-30), Ithe (31-40),
/// Igap (41-50), [Multimp 51-60, ignored], Irem_gap (61-70), Idel (71-80).
/// Card 2: Stmin (1-20), Stmax (21-40), %mesh_size (41-60), dtmin (61-80), Iform (81-90), sens_ID (91-100).
/// Card 3: Stfac (1-20), Fric (21-40), Gapmin (41-60), Tstart (61-80), Tstop (81-100).
/// Card 4: IBCX IBCY IBCZ (8, 9, 10), Inacti (31-40), VISs (41-60), VISF (61-80), Bumult (81-100).
/// Card 5: fric_ID (91-100).
/// If Ithe > 0: Kthe (1-20), fct_IDK (21-30), AscaleK (31-50), Tint (51-70),
/// Ithe_form (71-80); then Frad (1-20), Drad (21-40).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type11 {
    /// line_IDs (1-10): secondary /LINE, required.
    pub line_ids: Id,
    /// line_IDm (11-20): main /LINE; 0 = the secondary line (self-contact).
    pub line_idm: Id,
    /// Istf (21-30): 0 → 5 (Km and Ks in series); 1 = Stfac is the stiffness;
    /// 2/3/4 = mean/max/min. A negative Stfac in the deck means Istf = 1 with
    /// stiffness |Stfac| (as the Starter reads it).
    pub istf: i64,
    /// Ithe (31-40): 0 none; 1 heat transfer with constant main temperature Tint; 2 variable.
    pub ithe: i64,
    /// Igap (41-50): 0 → 1000 = constant gap Gapmin; 1 variable; 3 variable +
    /// mesh size (2 is not allowed for TYPE11).
    pub igap: i64,
    /// Irem_gap (61-70, format 2020+): 0 → 1 = no deactivation; 2 = deactivate
    /// secondary nodes when the element size is below the gap. Forced to 1
    /// with Igap = 3, as the Starter does.
    pub irem_gap: i64,
    /// Idel (71-80): 0 → 1000 = no deletion; 1, 2, -1, -2 as in TYPE7.
    pub idel: i64,
    /// Stmin (card 2, 1-20): minimum stiffness (not with Istf = 1), default 0.
    pub stmin: f64,
    /// Stmax (21-40): maximum stiffness, 0 → 1e30.
    pub stmax: f64,
    /// %mesh_size (41-60): Igap = 3 only, 0 → 0.4.
    pub mesh_size_pct: f64,
    /// dtmin (61-80): minimum interface time step, default 0 (none).
    pub dtmin: f64,
    /// Iform (81-90): friction penalty formulation: 0 → 1 viscous; 2 incremental.
    pub iform: i64,
    /// sens_ID (91-100): activation sensor (0 = none).
    pub sens_id: Id,
    /// Stfac (card 3, 1-20): 0 → 1.0; the stiffness itself when Istf = 1 (stored positive).
    pub stfac: f64,
    /// Fric (21-40): Coulomb friction, default 0.
    pub fric: f64,
    /// Gapmin (41-60): minimum gap; 0 = computed by the Starter.
    pub gapmin: f64,
    /// Tstart (61-80), default 0.
    pub tstart: f64,
    /// Tstop (81-100): 0 → 1e30.
    pub tstop: f64,
    /// IBCX, IBCY, IBCZ (card 4, columns 8, 9, 10).
    pub ibc: [bool; 3],
    /// Inacti (31-40): 0 → 1000 = no action; 1, 2, 3, 5, 6 as in TYPE7.
    pub inacti: i64,
    /// VISs (41-60): 0 → 0.05.
    pub viss: f64,
    /// VISF (61-80): 0 → 1.0 (card default; the Starter keeps 0 when Fric = 0
    /// or Iform = 2, where VISF has no effect).
    pub visf: f64,
    /// Bumult (81-100): 0 → 0.2.
    pub bumult: f64,
    /// fric_ID (card 5, 91-100): /FRICTION to use (0 = Fric). Card 5 may be
    /// absent in pre-2018 decks when Ithe = 0.
    pub fric_id: Id,
    /// The thermal cards (Ithe > 0).
    pub thermal: Option<Type11Thermal>,
    /// Not a Radioss field: the edge part of a keyword deck's
    /// `*CONTACT_AUTOMATIC_GENERAL` runs LS-DYNA's SOFT 0/1 penalty
    /// (`contact::interfaces::type11`, linear law).
    #[serde(default)]
    pub dyna: Option<super::DynaPenalty>,
    /// Not a Radioss field: the edge-to-edge part of a /INTER/TYPE25 with
    /// Iedge runs TYPE25's penalty (`super::Type25::edge_part`).
    #[serde(default)]
    pub penalty25: Option<super::Penalty25>,
}

/// TYPE11 thermal cards (Ithe > 0). The layout differs from TYPE7's.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type11Thermal {
    /// Kthe (1-20): heat exchange coefficient (scale factor when fct_IDK ≠ 0, then 0 → 1.0).
    pub kthe: f64,
    /// fct_IDK (21-30): heat exchange vs pressure function (0 = none).
    pub fct_idk: Id,
    /// AscaleK (31-50): abscissa scale on fct_IDK, 0 → 1.0.
    pub ascalek: f64,
    /// Tint (51-70): interface temperature, default 0.
    pub tint: f64,
    /// Ithe_form (71-80): 0 constant-temperature interface; 1 between all parts.
    pub ithe_form: i64,
    /// Frad (card 2, 1-20): radiation factor, default 0.
    pub frad: f64,
    /// Drad (21-40): maximum radiation distance, default 0.
    pub drad: f64,
}
