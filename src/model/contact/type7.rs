//! /INTER/TYPE7 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE7: general node to surface penalty contact (format 2020-2026).
///
/// Card 1: grnd_IDs (1-10), surf_IDm (11-20), Istf (21-30), Ithe (31-40),
/// Igap (41-50), [Multimp 51-60, ignored], Ibag (61-70), Idel (71-80),
/// Icurv (81-90), Iadm (91-100).
/// Card 2: Fscalegap (1-20), Gapmax (21-40), Fpenmax (41-60), Itied (81-90), Ists (91-100).
/// Card 3: Stmin (1-20), Stmax (21-40), %mesh_size (41-60), dtmin (61-80),
/// Irem_gap (81-90), Irem_i2 (91-100).
/// If Icurv ∈ {1, 2}: node_ID1 (1-10), node_ID2 (11-20).
/// Card 4: Stfac (1-20), Fric (21-40), Gapmin (41-60), Tstart (61-80), Tstop (81-100).
/// Card 5: IBCX IBCY IBCZ (8, 9, 10), Inacti (31-40), VISs (41-60), VISF (61-80), Bumult (81-100).
/// Card 6: Ifric (1-10), Ifiltr (11-20), Xfreq (21-40), Iform (41-50),
/// sens_ID (51-60), fct_IDF (61-70), AscaleF (71-90), fric_ID (91-100).
/// Then: C1..C5 if Ifric > 0; C6 if Ifric > 1; the Iadm card if Iadm = 2;
/// two thermal cards if Ithe = 1 (the Starter's order).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type7 {
    /// grnd_IDs (1-10): secondary node group. 0 = self-contact: the secondary
    /// nodes are the nodes of surf_IDm. With Ists ≠ 0 it is a surface id.
    pub grnod_ids: Id,
    /// surf_IDm (11-20): main surface, required.
    pub surf_idm: Id,
    /// Istf (21-30): stiffness definition. 0 → 1000 = K from the main side only
    /// (Stfac·Km); 1 = Stfac is the stiffness; 2/3/4/5 = mean/max/min/series of
    /// Km and Ks, clamped to [Stmin, Stmax].
    pub istf: i64,
    /// Ithe (31-40): 0 no heat; 1 heat transfer / frictional heating (adds the thermal cards).
    pub ithe: i64,
    /// Igap (41-50): 0 → 1000 = constant gap Gapmin; 1 variable; 2 variable with
    /// Fscalegap and Gapmax; 3 = 2 plus %mesh_size.
    pub igap: i64,
    /// Ibag (61-70): airbag vent closure. 0 → 1000 = no closure (the Starter's
    /// built-in default; the reference card names 2 "no closure, default":
    /// 2 and 1000 mean the same); 1 = closure.
    pub ibag: i64,
    /// Idel (71-80): 0 → 1000 = no deletion; 1 / 2 = remove main segments when
    /// all / one of their elements are deleted (and non-connected secondary
    /// nodes); -1 / -2 the same keeping the secondary nodes.
    pub idel: i64,
    /// Icurv (81-90): gap curvature: 0 none, 1 spherical, 2 cylindrical, 3 bicubic.
    pub icurv: i64,
    /// Iadm (91-100): adaptive meshing refinement: 0 off, 1 mesh size, 2 + penetration and angle.
    pub iadm: i64,
    /// Fscalegap (card 2, 1-20): gap scale factor (Igap 2, 3), 0 → 1.0.
    pub fscalegap: f64,
    /// Gapmax (21-40): maximum gap (Igap 2, 3), 0 → 1e30 (no maximum).
    pub gapmax: f64,
    /// Fpenmax (41-60): maximum initial penetration fraction; 0 = not used.
    pub fpenmax: f64,
    /// Itied (81-90): 0 not tied; 1 tied with rebound; 2 tied without rebound
    /// (when the contact time step falls below dtmin).
    pub itied: i64,
    /// Ists (91-100, format 2026): 0 node to surface; 1 linear STS, 2 STS with
    /// smoothing (grnd_IDs is then a surface). 0 in older formats.
    pub ists: i64,
    /// Stmin (card 3, 1-20): minimum stiffness (Istf 2..5 only), default 0.
    pub stmin: f64,
    /// Stmax (21-40): maximum stiffness (Istf 2..5 only), 0 → 1e30.
    pub stmax: f64,
    /// %mesh_size (41-60): fraction of the mesh size (Igap = 3 only), 0 → 0.4.
    /// The listing prints 0 when Igap ≠ 3, where it is unused.
    pub mesh_size_pct: f64,
    /// dtmin (61-80): minimum interface time step; 0 = none (/DT/INTER/DEL applies).
    pub dtmin: f64,
    /// Irem_gap (81-90): 0 → 1 = keep secondary nodes when the element size is
    /// below the gap in self-contact; 2 = deactivate them.
    pub irem_gap: i64,
    /// Irem_i2 (91-100): 0 → 3 = no change (the Starter uses 1 in implicit
    /// runs); 1 = remove secondary nodes also tied by a TYPE2.
    pub irem_i2: i64,
    /// node_ID1, node_ID2 (Icurv 1 or 2 only): sphere centre / cylinder axis
    /// nodes. Icurv 1 needs node_ID1 (node_ID2 may be 0); Icurv 2 needs both.
    pub curv_nodes: Option<[Id; 2]>,
    /// Stfac (card 4, 1-20): 0 → 1.0. A scale factor on Km, or the stiffness
    /// itself when Istf = 1.
    pub stfac: f64,
    /// Fric (21-40): Coulomb friction, default 0; with fct_IDF ≠ 0 it is a
    /// scale factor and 0 → 1.0.
    pub fric: f64,
    /// Gapmin (41-60): minimum gap; 0 = computed by the Starter (from the main
    /// side's thickness and smallest edge).
    pub gapmin: f64,
    /// Tstart (61-80), default 0.
    pub tstart: f64,
    /// Tstop (81-100): 0 → 1e30.
    pub tstop: f64,
    /// IBCX, IBCY, IBCZ (card 5, columns 8, 9, 10): deactivate the secondary
    /// nodes' boundary conditions in X, Y, Z at impact.
    pub ibc: [bool; 3],
    /// Inacti (31-40): initial penetrations. 0 → 1000 = no action; 1 deactivate
    /// node stiffness; 2 element stiffness; 3 move nodes; 5, 6 variable gap.
    pub inacti: i64,
    /// VISs (41-60): critical damping on the stiffness, 0 → 0.05.
    pub viss: f64,
    /// VISF (61-80): critical damping on friction, 0 → 1.0 (the card default).
    /// The Starter substitutes 1.0 only when there is friction (Fric ≠ 0 or
    /// Ifric ≠ 0) and uses 0 with Iform = 2, so its listing prints 0 without
    /// friction; VISF has no effect in those cases, so the value is the same in use.
    pub visf: f64,
    /// Bumult (81-100): sorting (bucket) factor, 0 → 0.2 (the Starter raises it
    /// ×1.5 above 1.5M nodes and ×2 above 2.5M).
    pub bumult: f64,
    /// Ifric (card 6, 1-10): 0 Coulomb; 1 generalized viscous; 2 Darmstad;
    /// 3 Renard; 4 exponential decay (in the Starter's reader, not on the
    /// reference card). Ignored when fric_ID ≠ 0.
    pub ifric: i64,
    /// Ifiltr (11-20): friction filter: 0 none; 1 simple (α = Xfreq); 2 −3 dB
    /// with period; 3 −3 dB with cut-off frequency. Forced to 0 when Xfreq = 0,
    /// as the Starter does.
    pub ifiltr: i64,
    /// Xfreq (21-40): filtering coefficient, default 0.
    pub xfreq: f64,
    /// Iform (41-50): friction penalty formulation: 0 → 1 viscous (total); 2 stiffness (incremental).
    pub iform: i64,
    /// sens_ID (51-60): activation sensor (0 = none; overrides Tstart/Tstop).
    pub sens_id: Id,
    /// fct_IDF (61-70): friction vs temperature function (0 = none).
    pub fct_idf: Id,
    /// AscaleF (71-90): abscissa scale on fct_IDF, 0 → 1.0.
    pub ascalef: f64,
    /// fric_ID (91-100): /FRICTION to use (0 = this card's friction).
    pub fric_id: Id,
    /// C1..C6 (friction law coefficients): `Some` when Ifric > 0; C6 is read
    /// only when Ifric > 1 (else 0).
    pub fric_coefs: Option<[f64; 6]>,
    /// The Iadm = 2 card.
    pub adm: Option<Type7Adm>,
    /// The two thermal cards (Ithe = 1).
    pub thermal: Option<Type7Thermal>,
    /// An LS-DYNA keyword contact run on this kernel (`*CONTACT_AUTOMATIC_…`,
    /// SOFT = 0): its penalty stiffness replaces Istf's; `None` for /INTER/TYPE7.
    #[serde(default)]
    pub dyna: Option<DynaPenalty>,
}

/// LS-DYNA's SOFT = 0 penalty stiffness (keyword manual volume I, *CONTACT
/// card 3 and *CONTROL_CONTACT SLSFAC; theory manual, "Contact-Impact
/// Algorithm", penalty method): a segment on a shell takes k = f·K·A/d_max
/// (A its area, d_max its longest diagonal), on a solid k = f·K·A²/V, with
/// K the bulk modulus and f = SLSFAC·SFM for main segments, SLSFAC·SFS for
/// secondary nodes (from the elements around them); a pair takes the
/// smaller of its two (the default penalty option: the minimum of the main
/// segment's and the secondary node's).
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
pub struct DynaPenalty {
    /// SLSFAC (*CONTROL_CONTACT, default 0.1).
    pub slsfac: f64,
    /// SFS, SFM (*CONTACT card 3, default 1).
    pub sfs: f64,
    pub sfm: f64,
    /// SOFT (0, 1 or 2: segment-based, `contact::interfaces::dyna_segment`) and SOFSCL (optional card A, default 0.1): SOFT = 1
    /// takes the larger of the SOFT = 0 stiffness and the soft constraint
    /// SOFSCL·0.5·m*/Δt² (m* the smaller of the secondary node's and the
    /// main nodes' masses, Δt the solution step).
    #[serde(default)]
    pub soft: i64,
    #[serde(default)]
    pub sofscl: f64,
    /// DEPTH (optional card A): 5 adds edge-to-edge crossings to SOFT = 2.
    #[serde(default)]
    pub depth: i64,
}

/// TYPE7 adaptive-meshing card (Iadm = 2).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type7Adm {
    /// NRadm (1-10): elements through a 90° radius, 0 → 3.
    pub nradm: i64,
    /// Padm (11-30): penetration percentage criterion, 0 → 1.0.
    pub padm: f64,
    /// Angladm (31-50): angle criterion in degrees, default 0.
    pub angladm: f64,
}

/// TYPE7 thermal cards (Ithe = 1).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type7Thermal {
    /// Kthe (1-20): heat exchange coefficient (or a scale factor when
    /// fct_IDK ≠ 0, then 0 → 1.0); default 0.
    pub kthe: f64,
    /// fct_IDK (21-30): heat exchange vs contact pressure function (0 = none).
    pub fct_idk: Id,
    /// Tint (41-60): interface temperature (Ithe_form = 0), default 0.
    pub tint: f64,
    /// Ithe_form (61-70): 0 exchange with a constant-temperature interface only; 1 between all parts.
    pub ithe_form: i64,
    /// AscaleK (71-90): abscissa scale on fct_IDK, 0 → 1.0.
    pub ascalek: f64,
    /// Frad (card 2, 1-20): radiation factor, default 0 (no radiation).
    pub frad: f64,
    /// Drad (21-40): maximum radiation distance; 0 = computed by the Starter.
    pub drad: f64,
    /// Fheats (41-60): fraction of frictional heat to the secondary side, default 0.
    pub fheats: f64,
    /// Fheatm (61-80): fraction of frictional heat to the main side, default 0.
    pub fheatm: f64,
}
