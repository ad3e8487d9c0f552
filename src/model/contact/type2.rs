//! /INTER/TYPE2 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE2: tied interface (kinematic, or penalty for Spotflag 25-28).
///
/// Card 1: grnd_IDs (1-10), surf_IDm (11-20), Ignore (21-30), Spotflag (31-40),
/// Level (41-50), Isearch (51-60), Idel2 (61-70), surf_IDs (71-80), dsearch (81-100).
/// Then, in this order: two rupture cards if Spotflag ∈ {20, 21, 22}; the
/// penalty card if Spotflag ∈ {25..28}; the optional thermal card (read when
/// present: no flag announces it).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type2 {
    /// grnd_IDs (1-10): secondary node group, required.
    pub grnod_ids: Id,
    /// surf_IDm (11-20): main surface, required.
    pub surf_idm: Id,
    /// Ignore (21-30): 0 → 1000 = keep secondary nodes with no main segment;
    /// 1, 2, 3 = remove them (2 and 3 also recompute dsearch when it is 0).
    pub ignore: i64,
    /// Spotflag (31-40): formulation. 0 → 5 (standard kinematic). Allowed: 1-5,
    /// 10-12, 20-22 (rupture), 25-28 (penalty / kinematic with penalty switch), 30.
    pub spotflag: i64,
    /// Level (41-50): hierarchy level, >= 0 (0 default). Forced to 0 for Spotflag 25-28.
    pub level: i64,
    /// Isearch (51-60): 0 → 2; 1 = old search.
    pub isearch: i64,
    /// Idel2 (61-70): 0 → 1000 = no deletion; 1 = release when all elements of
    /// the main segment are deleted; 2 = when one is. Forced to 1000 (none)
    /// unless Spotflag ∈ {1, 5, 25..28}, as the Starter does.
    pub idel2: i64,
    /// surf_IDs (71-80, format 2025+): optional secondary surface (0 = none).
    /// Informational: the Starter does not use it yet.
    pub surf_ids: Id,
    /// dsearch (81-100): search distance; 0 = computed by the Starter.
    pub dsearch: f64,
    /// Rupture cards (Spotflag 20, 21, 22).
    pub rupture: Option<Type2Rupture>,
    /// Penalty card (Spotflag 25..28).
    pub penalty: Option<Type2Penalty>,
    /// Thermal card; `None` when absent or blank.
    pub thermal: Option<Type2Thermal>,
    /// Not a Radioss field: the secondary nodes are moved onto their main
    /// segment at set-up (LS-DYNA's `*CONTACT_TIED_..._TO_SURFACE` without
    /// an `_OFFSET` option: "slave nodes are projected to the master surface
    /// during initialization"), before masses and element geometry.
    #[serde(default)]
    pub project: bool,
}

/// TYPE2 rupture cards (Spotflag 20-22).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type2Rupture {
    /// Rupt (1-10): 0 → 2 (failure when Max_N_Dist or Max_T_Dist is reached);
    /// 1 = failure on the combined criterion.
    pub rupt: i64,
    /// Ifiltr (11-20): 0 none, 1 alpha filter.
    pub ifiltr: i64,
    /// fct_IDsr (21-30): stress factor vs stress rate (0 = none).
    pub fct_idsr: Id,
    /// fct_IDsn (31-40): max normal stress vs normal distance, required.
    pub fct_idsn: Id,
    /// fct_IDst (41-50): max tangential stress vs tangential distance, required.
    pub fct_idst: Id,
    /// Isym (51-60): 0 symmetric rupture, 1 traction only.
    pub isym: i64,
    /// Max_N_Dist (61-80): 0 → 1e20.
    pub max_n_dist: f64,
    /// Max_T_Dist (81-100): 0 → 1e20.
    pub max_t_dist: f64,
    /// Fscalestress (card 2, 1-20): 0 → 1.0.
    pub fscale_stress: f64,
    /// Fscalestr_rate (21-40): 0 → 1.0.
    pub fscale_str_rate: f64,
    /// Fscaledist (41-60): 0 → 1.0.
    pub fscale_dist: f64,
    /// Alpha (61-80): filter coefficient; with Ifiltr = 1, 0 → 1.0 and clamped to [0, 1].
    pub alpha: f64,
    /// Area (81-100): area used when the secondary node has none (0 = none).
    pub area: f64,
}

/// TYPE2 penalty card (Spotflag 25-28).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type2Penalty {
    /// Stfac (1-20): stiffness factor, 0 → 1.0.
    pub stfac: f64,
    /// Visc (21-40): critical damping, 0 → 0.05.
    pub visc: f64,
    /// Istf (61-70): 0 → 2; 1..5 as in TYPE7.
    pub istf: i64,
}

/// TYPE2 optional thermal card.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type2Thermal {
    /// Ithe (1-10): 0 none, 1 heat transfer.
    pub ithe: i64,
    /// Kthe (11-30): heat exchange coefficient.
    pub kthe: f64,
    /// Iproj (91-100): 0 → 1 = move the secondary projection to the main edge;
    /// 2 = unchanged. Not on the card for Spotflag ∈ {1, 28, 30} (then 1).
    pub iproj: i64,
}
