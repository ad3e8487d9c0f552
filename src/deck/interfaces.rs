//! Contact interfaces: /INTER/TYPE2 (tied), /INTER/TYPE3 (surface to surface,
//! symmetric), /INTER/TYPE5 (node to surface), /INTER/TYPE7 (general node to
//! surface penalty contact) and /INTER/TYPE11 (edge to edge).
//!
//! Layouts follow the Starter's reader definitions (`inter_typeN.cfg`, newest
//! format) and the reference guide; columns are 1-based and inclusive. A blank
//! field and an explicit 0 are the same thing, and unlike /PART or /PROP the
//! values here are stored *after* default resolution (`0 → default`), as the
//! Starter listing (`_0000.out`) prints them. `/DEFAULT/INTER/TYPEn` is not
//! supported: a 0 always takes the built-in default.
//!
//! The "1000" convention: several flags (Istf, Igap, Ibag, Idel, Inacti, Ignore,
//! Idel2) use 0 for "take /DEFAULT/INTER or the built-in default", and the
//! built-in default is 1000, meaning the historic/"off" behaviour. Those flags
//! are stored as 1000, as the listing prints them.

use super::error::{DeckResult, Loc, Warning};
use super::fields::{Card, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck, Id};
use serde::{Deserialize, Serialize};

/// "No limit" value the Starter substitutes for Tstop, Stmax, Gapmax, Ptlim.
pub const EP30: f64 = 1.0e30;
/// Starter's "infinite" rupture distance for TYPE2 (Max_N_Dist, Max_T_Dist).
pub const EP20: f64 = 1.0e20;

/// One `/INTER/TYPEn/inter_ID[/unit_ID]` block.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct InterfaceCard {
    pub id: Id,
    /// Header unit_ID (0 = none).
    pub unit_id: Id,
    /// inter_title: the line after the header (up to 100 characters).
    pub title: String,
    pub kind: InterfaceKind,
    /// Where the keyword line is.
    pub loc: Loc,
    /// Where card 1 (the ids of both sides) is.
    #[serde(default)]
    pub ids_loc: Loc,
}

// A deck holds few interfaces: the size of the TYPE7 variant does not matter,
// and boxing it would change the public shape `Type7(Type7)`.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum InterfaceKind {
    Type2(Type2),
    Type3(Type3),
    Type5(Type5),
    Type7(Type7),
    Type11(Type11),
}

/// What one side of an interface references.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
pub enum Side {
    /// A `/GRNOD` node group.
    NodeGroup(Id),
    /// A `/SURF` surface (segments).
    Surface(Id),
    /// A `/LINE` set of 2-node segments.
    Line(Id),
    /// self-contact (TYPE7 grnod=0 / TYPE11 main line 0): same as the other side
    SameAsOther,
    None,
}

impl InterfaceCard {
    /// 2, 3, 5, 7 or 11.
    pub fn type_number(&self) -> u32 {
        match self.kind {
            InterfaceKind::Type2(_) => 2,
            InterfaceKind::Type3(_) => 3,
            InterfaceKind::Type5(_) => 5,
            InterfaceKind::Type7(_) => 7,
            InterfaceKind::Type11(_) => 11,
        }
    }

    /// What the secondary (slave) side references.
    pub fn secondary_side(&self) -> Side {
        match &self.kind {
            InterfaceKind::Type2(t) => Side::NodeGroup(t.grnod_ids),
            InterfaceKind::Type3(t) => Side::Surface(t.surf_id1),
            InterfaceKind::Type5(t) => Side::NodeGroup(t.grnod_ids),
            InterfaceKind::Type7(t) => {
                if t.grnod_ids == 0 {
                    Side::SameAsOther
                } else if t.ists != 0 {
                    Side::Surface(t.grnod_ids)
                } else {
                    Side::NodeGroup(t.grnod_ids)
                }
            }
            InterfaceKind::Type11(t) => Side::Line(t.line_ids),
        }
    }

    /// The field names of (secondary side, main side) on card 1.
    pub fn side_fields(&self) -> (&'static str, &'static str) {
        match &self.kind {
            InterfaceKind::Type3(_) => ("surf_ID1", "surf_ID2"),
            InterfaceKind::Type11(_) => ("line_IDs", "line_IDm"),
            _ => ("grnd_IDs", "surf_IDm"),
        }
    }

    /// What the main (master) side references.
    pub fn main_side(&self) -> Side {
        match &self.kind {
            InterfaceKind::Type2(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type3(t) => Side::Surface(t.surf_id2),
            InterfaceKind::Type5(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type7(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type11(t) => {
                if t.line_idm == 0 {
                    Side::SameAsOther
                } else {
                    Side::Line(t.line_idm)
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------
// TYPE2
// ---------------------------------------------------------------------------

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

const SPOTFLAGS: &[i64] = &[0, 1, 2, 3, 4, 5, 10, 11, 12, 20, 21, 22, 25, 26, 27, 28, 30];

fn read_type2(cards: &mut Cards) -> DeckResult<Type2> {
    let c1 = cards.next(
        "the card with grnd_IDs, surf_IDm, Ignore, Spotflag, Level, Isearch, Idel2, dsearch",
    )?;
    let grnod_ids = c1.id(1, "grnd_IDs")?;
    let surf_idm = c1.id(11, "surf_IDm")?;
    let ignore = flag(&c1, 21, "Ignore", &[0, 1, 2, 3, 1000], 1000)?;
    let spotflag = flag(&c1, 31, "Spotflag", SPOTFLAGS, 5)?;
    let mut level = c1.int(41, "Level", 0)?;
    if level < 0 {
        return Err(c1.err(
            "Level",
            format!("{level} in columns 41-50: expected a hierarchy level >= 0"),
        ));
    }
    let penalty_flag = (25..=28).contains(&spotflag);
    if penalty_flag {
        level = 0;
    }
    let isearch = flag(&c1, 51, "Isearch", &[0, 1, 2], 2)?;
    let mut idel2 = flag(&c1, 61, "Idel2", &[0, 1, 2, 1000], 1000)?;
    if !matches!(spotflag, 1 | 5 | 25..=28) {
        idel2 = 1000;
    }
    let surf_ids = c1.id_opt(71, "surf_IDs")?;
    let dsearch = real_ge0(&c1, 81, "dsearch", 0.0, "the search distance")?;

    let rupture = if matches!(spotflag, 20..=22) {
        let r1 = cards.next(
            "the rupture card with Rupt, Ifiltr, fct_IDsr, fct_IDsn, fct_IDst (Spotflag 20-22)",
        )?;
        let r2 = cards.next("the rupture card with Fscalestress, Fscalestr_rate, Fscaledist, Alpha, Area (Spotflag 20-22)")?;
        let ifiltr = flag(&r1, 11, "Ifiltr", &[0, 1], 0)?;
        let mut alpha = r2.real(61, "Alpha", 0.0)?;
        if ifiltr == 1 {
            if alpha == 0.0 {
                alpha = 1.0;
            }
            alpha = alpha.clamp(0.0, 1.0);
        }
        Some(Type2Rupture {
            rupt: flag(&r1, 1, "Rupt", &[0, 1, 2], 2)?,
            ifiltr,
            fct_idsr: r1.id_opt(21, "fct_IDsr")?,
            fct_idsn: r1.id(31, "fct_IDsn")?,
            fct_idst: r1.id(41, "fct_IDst")?,
            isym: flag(&r1, 51, "Isym", &[0, 1], 0)?,
            max_n_dist: real_ge0(&r1, 61, "Max_N_Dist", EP20, "the maximum normal distance")?,
            max_t_dist: real_ge0(
                &r1,
                81,
                "Max_T_Dist",
                EP20,
                "the maximum tangential distance",
            )?,
            fscale_stress: real_ge0(&r2, 1, "Fscalestress", 1.0, "a scale factor")?,
            fscale_str_rate: real_ge0(&r2, 21, "Fscalestr_rate", 1.0, "a scale factor")?,
            fscale_dist: real_ge0(&r2, 41, "Fscaledist", 1.0, "a scale factor")?,
            alpha,
            area: real_ge0(&r2, 81, "Area", 0.0, "the area")?,
        })
    } else {
        None
    };

    let penalty = if penalty_flag {
        let p = cards.next("the penalty card with Stfac, Visc, Istf (Spotflag 25-28)")?;
        Some(Type2Penalty {
            stfac: real_ge0(&p, 1, "Stfac", 1.0, "the stiffness factor")?,
            visc: real_ge0(&p, 21, "Visc", 0.05, "the critical damping")?,
            istf: flag(&p, 61, "Istf", &[0, 1, 2, 3, 4, 5], 2)?,
        })
    } else {
        None
    };

    let thermal = match cards.next_opt() {
        Some(t) if !t.is_blank() => {
            let has_iproj = !matches!(spotflag, 1 | 28 | 30);
            Some(Type2Thermal {
                ithe: flag(&t, 1, "Ithe", &[0, 1], 0)?,
                kthe: real_ge0(&t, 11, "Kthe", 0.0, "the heat exchange coefficient")?,
                iproj: if has_iproj {
                    flag(&t, 91, "Iproj", &[0, 1, 2], 1)?
                } else {
                    1
                },
            })
        }
        _ => None,
    };

    Ok(Type2 {
        grnod_ids,
        surf_idm,
        ignore,
        spotflag,
        level,
        isearch,
        idel2,
        surf_ids,
        dsearch,
        rupture,
        penalty,
        thermal,
    })
}

// ---------------------------------------------------------------------------
// TYPE3
// ---------------------------------------------------------------------------

/// /INTER/TYPE3: surface to surface "sliding and voids" (symmetric: the nodes of
/// each surface are checked against the segments of the other).
///
/// Card 1: surf_ID1 (1-10), surf_ID2 (11-20), Idel (71-80).
/// Card 2: Stfac (1-20), Fric (21-40), Gap (41-60), Tstart (61-80), Tstop (81-100).
/// Card 3: IBCX IBCY IBCZ (8, 9, 10), IRS (11-20), IRM (21-30).
/// Card 4 (may be absent): Ptlim (61-80).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type3 {
    /// surf_ID1 (1-10): the first surface, stored on the *secondary* side
    /// (the Starter listing prints its segments as SECONDARY SURFACE). Required.
    pub surf_id1: Id,
    /// surf_ID2 (11-20): the second surface, the main side. Required.
    pub surf_id2: Id,
    /// Idel (71-80): 0 no deletion; 1 / 2 remove main segments when all / one of
    /// their elements are deleted; -1 / -2 the same keeping non-connected nodes.
    pub idel: i64,
    /// Stfac (card 2, 1-20): stiffness factor, 0 → 0.2 (the Starter listing
    /// prints 0.2). The theory manual recommends <= 1.0; larger values are
    /// accepted.
    pub stfac: f64,
    /// Fric (21-40): Coulomb friction, default 0.
    pub fric: f64,
    /// Gap (41-60): initial gap, default 0 (not computed: the listing prints 0).
    pub gap: f64,
    /// Tstart (61-80), default 0.
    pub tstart: f64,
    /// Tstop (81-100): 0 → 1e30.
    pub tstop: f64,
    /// IBCX, IBCY, IBCZ (card 3, columns 8, 9, 10): deactivate the secondary
    /// nodes' boundary conditions in X, Y, Z at impact.
    pub ibc: [bool; 3],
    /// IRS (11-20): renumbering of surface 1 segments: 0 = reverse a normal that
    /// points into the solid, 1 = always reverse, 2 = never.
    pub irs: i64,
    /// IRM (21-30): the same for surface 2.
    pub irm: i64,
    /// Ptlim (card 4, 61-80): maximum tangential pressure, 0 → 1e30. Card 4 is
    /// often absent (e.g. INT357); the listing still prints 1e30.
    pub ptlim: f64,
}

fn read_type3(cards: &mut Cards) -> DeckResult<Type3> {
    let c1 = cards.next("the card with surf_ID1, surf_ID2, Idel")?;
    let c2 = cards.next("the card with Stfac, Fric, Gap, Tstart, Tstop")?;
    let c3 = cards.next("the card with IBC, IRS, IRM")?;
    let c4 = cards.next_opt();
    let (tstart, tstop) = times(&c2)?;
    Ok(Type3 {
        surf_id1: c1.id(1, "surf_ID1")?,
        surf_id2: c1.id(11, "surf_ID2")?,
        idel: flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2], 0)?,
        stfac: real_ge0(&c2, 1, "Stfac", 0.2, "the stiffness factor")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        gap: real_ge0(&c2, 41, "Gap", 0.0, "the gap")?,
        tstart,
        tstop,
        ibc: read_ibc(&c3)?,
        irs: flag(&c3, 11, "IRS", &[0, 1, 2], 0)?,
        irm: flag(&c3, 21, "IRM", &[0, 1, 2], 0)?,
        ptlim: match c4 {
            Some(c) => real_ge0(&c, 61, "Ptlim", EP30, "the tangential pressure limit")?,
            None => EP30,
        },
    })
}

// ---------------------------------------------------------------------------
// TYPE5
// ---------------------------------------------------------------------------

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

fn read_type5(cards: &mut Cards) -> DeckResult<Type5> {
    let c1 = cards.next("the card with grnd_IDs, surf_IDm, Ibag, Idel")?;
    let c2 = cards.next("the card with Stfac, Fric, Gap, Tstart, Tstop")?;
    let c3 = cards.next("the card with IBC, IRM, Inacti")?;
    // Card 4 is absent from the oldest formats: then every field takes its default.
    let c4 = cards.next_opt();
    let (tstart, tstop) = times(&c2)?;
    let (ifric, ifiltr, xfreq, sens_id, ptlim) = match &c4 {
        Some(c) => {
            let ifric = flag(c, 1, "Ifric", &[0, 1, 2, 3], 0)?;
            let (ifiltr, xfreq) = filter(c)?;
            (
                ifric,
                ifiltr,
                xfreq,
                c.id_opt(51, "sens_ID")?,
                real_ge0(c, 61, "Ptlim", EP30, "the tangential pressure limit")?,
            )
        }
        None => (0, 0, 0.0, 0, EP30),
    };
    let fric_coefs = friction_coefs(cards, ifric)?;
    Ok(Type5 {
        grnod_ids: c1.id(1, "grnd_IDs")?,
        surf_idm: c1.id(11, "surf_IDm")?,
        ibag: flag(&c1, 61, "Ibag", &[0, 1], 0)?,
        idel: flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2], 0)?,
        stfac: real_ge0(&c2, 1, "Stfac", 0.2, "the stiffness factor")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        gap: real_ge0(&c2, 41, "Gap", 0.0, "the gap")?,
        tstart,
        tstop,
        ibc: read_ibc(&c3)?,
        irm: flag(&c3, 21, "IRM", &[0, 1, 2], 0)?,
        inacti: flag(&c3, 31, "Inacti", &[0, 3, 4], 0)?,
        ifric,
        ifiltr,
        xfreq,
        sens_id,
        ptlim,
        fric_coefs,
    })
}

// ---------------------------------------------------------------------------
// TYPE7
// ---------------------------------------------------------------------------

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

fn read_type7(cards: &mut Cards) -> DeckResult<Type7> {
    let c1 = cards
        .next("the card with grnd_IDs, surf_IDm, Istf, Ithe, Igap, Ibag, Idel, Icurv, Iadm")?;
    let grnod_ids = c1.id_opt(1, "grnd_IDs")?;
    let surf_idm = c1.id(11, "surf_IDm")?;
    let istf = flag(&c1, 21, "Istf", &[0, 1, 2, 3, 4, 5, 1000], 1000)?;
    let ithe = flag(&c1, 31, "Ithe", &[0, 1], 0)?;
    let igap = flag(&c1, 41, "Igap", &[0, 1, 2, 3, 1000], 1000)?;
    let ibag = flag(&c1, 61, "Ibag", &[0, 1, 2, 1000], 1000)?;
    let idel = flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?;
    let icurv = flag(&c1, 81, "Icurv", &[0, 1, 2, 3], 0)?;
    let iadm = flag(&c1, 91, "Iadm", &[0, 1, 2], 0)?;
    if iadm != 0 && icurv != 0 {
        return Err(c1.err(
            "Iadm",
            format!("Iadm = {iadm} with Icurv = {icurv}: adaptive meshing (Iadm) cannot be combined with a curvature gap (Icurv); set one of them to 0"),
        ));
    }

    let c2 = cards.next("the card with Fscalegap, Gapmax, Fpenmax, Itied")?;
    let fscalegap = real_ge0(&c2, 1, "Fscalegap", 1.0, "the gap scale factor")?;
    let gapmax = real_ge0(&c2, 21, "Gapmax", EP30, "the maximum gap")?;
    let fpenmax = real_ge0(&c2, 41, "Fpenmax", 0.0, "the maximum penetration fraction")?;
    let itied = flag(&c2, 81, "Itied", &[0, 1, 2], 0)?;
    let ists = flag(&c2, 91, "Ists", &[0, 1, 2], 0)?;

    let c3 = cards.next("the card with Stmin, Stmax, %mesh_size, dtmin, Irem_gap, Irem_i2")?;
    let stmin = real_ge0(&c3, 1, "Stmin", 0.0, "the minimum stiffness")?;
    let stmax = real_ge0(&c3, 21, "Stmax", EP30, "the maximum stiffness")?;
    if stmax < stmin {
        return Err(c3.err(
            "Stmax",
            format!("{stmax} in columns 21-40 is below Stmin = {stmin}: expected Stmax >= Stmin"),
        ));
    }
    let mesh_size_pct = real_ge0(&c3, 41, "%mesh_size", 0.4, "the mesh size fraction")?;
    let dtmin = real_ge0(&c3, 61, "dtmin", 0.0, "the minimum time step")?;
    let irem_gap = flag(&c3, 81, "Irem_gap", &[0, 1, 2], 1)?;
    let irem_i2 = flag(&c3, 91, "Irem_i2", &[0, 1, 3], 3)?;

    let curv_nodes = if icurv == 1 || icurv == 2 {
        let n = cards.next("the card with node_ID1, node_ID2 (Icurv = 1 or 2)")?;
        let n1 = n.id(1, "node_ID1")?;
        let n2 = if icurv == 2 {
            n.id(11, "node_ID2")?
        } else {
            n.id_opt(11, "node_ID2")?
        };
        Some([n1, n2])
    } else {
        None
    };

    let c4 = cards.next("the card with Stfac, Fric, Gapmin, Tstart, Tstop")?;
    let stfac = real_ge0(&c4, 1, "Stfac", 1.0, "the stiffness factor")?;
    let fric_in = real_ge0(&c4, 21, "Fric", 0.0, "the friction coefficient")?;
    let gapmin = real_ge0(&c4, 41, "Gapmin", 0.0, "the minimum gap")?;
    let (tstart, tstop) = times(&c4)?;

    let c5 = cards.next("the card with IBC, Inacti, VISs, VISF, Bumult")?;
    let ibc = read_ibc(&c5)?;
    let inacti = flag(&c5, 31, "Inacti", &[0, 1, 2, 3, 5, 6, 1000], 1000)?;
    let viss = real_ge0(&c5, 41, "VISs", 0.05, "the critical damping")?;
    let visf = real_ge0(&c5, 61, "VISF", 1.0, "the friction critical damping")?;
    let bumult = real_ge0(&c5, 81, "Bumult", 0.2, "the sorting factor")?;

    let c6 = cards
        .next("the card with Ifric, Ifiltr, Xfreq, Iform, sens_ID, fct_IDF, AscaleF, fric_ID")?;
    let ifric = flag(&c6, 1, "Ifric", &[0, 1, 2, 3, 4], 0)?;
    let (ifiltr, xfreq) = filter(&c6)?;
    let iform = flag(&c6, 41, "Iform", &[0, 1, 2], 1)?;
    let sens_id = c6.id_opt(51, "sens_ID")?;
    let fct_idf = c6.id_opt(61, "fct_IDF")?;
    let ascalef = real_ge0(&c6, 71, "AscaleF", 1.0, "the abscissa scale factor")?;
    let fric_id = c6.id_opt(91, "fric_ID")?;
    let fric = if fric_in == 0.0 && fct_idf != 0 {
        1.0
    } else {
        fric_in
    };

    let fric_coefs = friction_coefs(cards, ifric)?;

    let adm = if iadm == 2 {
        let a = cards.next("the card with NRadm, Padm, Angladm (Iadm = 2)")?;
        let nradm = a.int(1, "NRadm", 0)?;
        if nradm < 0 {
            return Err(a.err(
                "NRadm",
                format!("{nradm} in columns 1-10: expected a number of elements >= 0 (0 = 3)"),
            ));
        }
        Some(Type7Adm {
            nradm: if nradm == 0 { 3 } else { nradm },
            padm: real_ge0(&a, 11, "Padm", 1.0, "the penetration criterion")?,
            angladm: real_ge0(&a, 31, "Angladm", 0.0, "the angle criterion")?,
        })
    } else {
        None
    };

    let thermal = if ithe == 1 {
        let t1 = cards
            .next("the thermal card with Kthe, fct_IDK, Tint, Ithe_form, AscaleK (Ithe = 1)")?;
        let t2 = cards.next("the thermal card with Frad, Drad, Fheats, Fheatm (Ithe = 1)")?;
        let fct_idk = t1.id_opt(21, "fct_IDK")?;
        let kthe = real_ge0(&t1, 1, "Kthe", 0.0, "the heat exchange coefficient")?;
        Some(Type7Thermal {
            kthe: if kthe == 0.0 && fct_idk != 0 {
                1.0
            } else {
                kthe
            },
            fct_idk,
            tint: t1.real(41, "Tint", 0.0)?,
            ithe_form: flag(&t1, 61, "Ithe_form", &[0, 1], 0)?,
            ascalek: real_ge0(&t1, 71, "AscaleK", 1.0, "the abscissa scale factor")?,
            frad: real_ge0(&t2, 1, "Frad", 0.0, "the radiation factor")?,
            drad: real_ge0(&t2, 21, "Drad", 0.0, "the radiation distance")?,
            fheats: real_ge0(&t2, 41, "Fheats", 0.0, "the frictional heating factor")?,
            fheatm: real_ge0(&t2, 61, "Fheatm", 0.0, "the frictional heating factor")?,
        })
    } else {
        None
    };

    Ok(Type7 {
        grnod_ids,
        surf_idm,
        istf,
        ithe,
        igap,
        ibag,
        idel,
        icurv,
        iadm,
        fscalegap,
        gapmax,
        fpenmax,
        itied,
        ists,
        stmin,
        stmax,
        mesh_size_pct,
        dtmin,
        irem_gap,
        irem_i2,
        curv_nodes,
        stfac,
        fric,
        gapmin,
        tstart,
        tstop,
        ibc,
        inacti,
        viss,
        visf,
        bumult,
        ifric,
        ifiltr,
        xfreq,
        iform,
        sens_id,
        fct_idf,
        ascalef,
        fric_id,
        fric_coefs,
        adm,
        thermal,
    })
}

// ---------------------------------------------------------------------------
// TYPE11
// ---------------------------------------------------------------------------

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

fn read_type11(cards: &mut Cards) -> DeckResult<Type11> {
    let c1 = cards.next("the card with line_IDs, line_IDm, Istf, Ithe, Igap, Irem_gap, Idel")?;
    let line_ids = c1.id(1, "line_IDs")?;
    let line_idm = c1.id_opt(11, "line_IDm")?;
    let mut istf = flag(&c1, 21, "Istf", &[0, 1, 2, 3, 4, 5], 5)?;
    let ithe = flag(&c1, 31, "Ithe", &[0, 1, 2], 0)?;
    let igap = c1.int(41, "Igap", 0)?;
    if igap == 2 {
        return Err(c1.err(
            "Igap",
            "2 in columns 41-50: Igap = 2 is not available for TYPE11; expected 0, 1, 3 or 1000",
        ));
    }
    let igap = flag(&c1, 41, "Igap", &[0, 1, 3, 1000], 1000)?;
    let mut irem_gap = flag(&c1, 61, "Irem_gap", &[0, 1, 2], 1)?;
    if igap == 3 {
        irem_gap = 1;
    }
    let idel = flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?;

    let c2 = cards.next("the card with Stmin, Stmax, %mesh_size, dtmin, Iform, sens_ID")?;
    let stmin = real_ge0(&c2, 1, "Stmin", 0.0, "the minimum stiffness")?;
    let stmax = real_ge0(&c2, 21, "Stmax", EP30, "the maximum stiffness")?;
    if stmax < stmin {
        return Err(c2.err(
            "Stmax",
            format!("{stmax} in columns 21-40 is below Stmin = {stmin}: expected Stmax >= Stmin"),
        ));
    }
    let mesh_size_pct = real_ge0(&c2, 41, "%mesh_size", 0.4, "the mesh size fraction")?;
    let dtmin = real_ge0(&c2, 61, "dtmin", 0.0, "the minimum time step")?;
    let iform = flag(&c2, 81, "Iform", &[0, 1, 2], 1)?;
    let sens_id = c2.id_opt(91, "sens_ID")?;

    let c3 = cards.next("the card with Stfac, Fric, Gapmin, Tstart, Tstop")?;
    // A negative Stfac is the old way of giving the stiffness itself (Istf = 1).
    let mut stfac = c3.real(1, "Stfac", 0.0)?;
    if stfac < 0.0 {
        istf = 1;
        stfac = -stfac;
    } else if stfac == 0.0 {
        stfac = 1.0;
    }
    let fric = real_ge0(&c3, 21, "Fric", 0.0, "the friction coefficient")?;
    let gapmin = real_ge0(&c3, 41, "Gapmin", 0.0, "the minimum gap")?;
    let (tstart, tstop) = times(&c3)?;

    let c4 = cards.next("the card with IBC, Inacti, VISs, VISF, Bumult")?;
    let ibc = read_ibc(&c4)?;
    let inacti = flag(&c4, 31, "Inacti", &[0, 1, 2, 3, 5, 6, 1000], 1000)?;
    let viss = real_ge0(&c4, 41, "VISs", 0.05, "the critical damping")?;
    let visf = real_ge0(&c4, 61, "VISF", 1.0, "the friction critical damping")?;
    let bumult = real_ge0(&c4, 81, "Bumult", 0.2, "the sorting factor")?;

    // Card 5 (fric_ID) exists from format 2018; older decks end after card 4,
    // which is harmless unless the thermal cards must follow it.
    let c5 = if ithe > 0 {
        Some(cards.next("the card with fric_ID (columns 91-100)")?)
    } else {
        cards.next_opt()
    };
    let fric_id = match &c5 {
        Some(c) => c.id_opt(91, "fric_ID")?,
        None => 0,
    };

    let thermal = if ithe > 0 {
        let t1 = cards
            .next("the thermal card with Kthe, fct_IDK, AscaleK, Tint, Ithe_form (Ithe > 0)")?;
        let t2 = cards.next("the thermal card with Frad, Drad (Ithe > 0)")?;
        let fct_idk = t1.id_opt(21, "fct_IDK")?;
        let kthe = real_ge0(&t1, 1, "Kthe", 0.0, "the heat exchange coefficient")?;
        Some(Type11Thermal {
            kthe: if kthe == 0.0 && fct_idk != 0 {
                1.0
            } else {
                kthe
            },
            fct_idk,
            ascalek: real_ge0(&t1, 31, "AscaleK", 1.0, "the abscissa scale factor")?,
            tint: t1.real(51, "Tint", 0.0)?,
            ithe_form: flag(&t1, 71, "Ithe_form", &[0, 1], 0)?,
            frad: real_ge0(&t2, 1, "Frad", 0.0, "the radiation factor")?,
            drad: real_ge0(&t2, 21, "Drad", 0.0, "the radiation distance")?,
        })
    } else {
        None
    };

    Ok(Type11 {
        line_ids,
        line_idm,
        istf,
        ithe,
        igap,
        irem_gap,
        idel,
        stmin,
        stmax,
        mesh_size_pct,
        dtmin,
        iform,
        sens_id,
        stfac,
        fric,
        gapmin,
        tstart,
        tstop,
        ibc,
        inacti,
        viss,
        visf,
        bumult,
        fric_id,
        thermal,
    })
}

// ---------------------------------------------------------------------------
// Dispatch and shared field readers
// ---------------------------------------------------------------------------

/// Reads one /INTER block. Returns false for an interface type this reader
/// does not support (the caller warns, or fails with --strict).
pub(super) fn parse_interface(block: &Block, deck: &mut Deck) -> DeckResult<bool> {
    let ty = block.parts.get(1).map(String::as_str).unwrap_or("");
    let which = match ty {
        "TYPE2" => 2,
        "TYPE3" => 3,
        "TYPE5" => 5,
        "TYPE7" => 7,
        "TYPE11" => 11,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "inter_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let kind = match which {
        2 => InterfaceKind::Type2(read_type2(&mut cards)?),
        3 => InterfaceKind::Type3(read_type3(&mut cards)?),
        5 => InterfaceKind::Type5(read_type5(&mut cards)?),
        7 => InterfaceKind::Type7(read_type7(&mut cards)?),
        _ => InterfaceKind::Type11(read_type11(&mut cards)?),
    };
    let extra: Vec<_> = cards
        .remaining()
        .iter()
        .filter(|l| !l.text.trim().is_empty())
        .collect();
    if let Some(first) = extra.first() {
        deck.warnings.push(Warning {
            loc: first.loc.clone(),
            keyword: block.header.clone(),
            message: format!(
                "{} line(s) after the last card this /INTER/{ty} expects are ignored \
                 (check the flags that announce optional cards, e.g. Ifric, Icurv, Iadm, Ithe)",
                extra.len()
            ),
        });
    }
    deck.interfaces.push(InterfaceCard {
        id,
        unit_id,
        title,
        kind,
        loc: block.loc.clone(),
        ids_loc: block
            .lines
            .get(1)
            .map_or_else(|| block.loc.clone(), |l| l.loc.clone()),
    });
    Ok(true)
}

/// A 10-column integer flag at `col` that must be one of `allowed`; 0 (or
/// blank) becomes `zero`.
fn flag(c: &Card, col: usize, name: &str, allowed: &[i64], zero: i64) -> DeckResult<i64> {
    let width = 10;
    let v = c.int_opt(col, width, name)?.unwrap_or(0);
    if !allowed.contains(&v) {
        return Err(c.err(
            name,
            format!(
                "{v} in columns {col}-{}: expected one of {allowed:?} (0 = default {zero})",
                col + width - 1
            ),
        ));
    }
    Ok(if v == 0 { zero } else { v })
}

/// A 20-column real at `col` that must be >= 0; 0 (or blank) becomes `zero`.
fn real_ge0(c: &Card, col: usize, name: &str, zero: f64, what: &str) -> DeckResult<f64> {
    let width = 20;
    let v = c.real_opt(col, width, name)?.unwrap_or(0.0);
    if v < 0.0 {
        return Err(c.err(
            name,
            format!(
                "{v} in columns {col}-{}: {what} must be >= 0 (0 = default {zero})",
                col + width - 1
            ),
        ));
    }
    Ok(if v == 0.0 { zero } else { v })
}

/// Tstart (61-80, default 0) and Tstop (81-100, 0 → 1e30) of a card.
fn times(c: &Card) -> DeckResult<(f64, f64)> {
    let tstart = real_ge0(c, 61, "Tstart", 0.0, "the start time")?;
    let tstop = real_ge0(c, 81, "Tstop", EP30, "the stop time")?;
    if tstop < tstart {
        return Err(c.err(
            "Tstop",
            format!("{tstop} in columns 81-100 is before Tstart = {tstart}: expected Tstop >= Tstart (0 = never stop)"),
        ));
    }
    Ok((tstart, tstop))
}

/// IBC: three one-column 0/1 flags IBCX, IBCY, IBCZ in columns 8, 9, 10
/// (written e.g. `       000`); columns 1-7 are blank.
fn read_ibc(c: &Card) -> DeckResult<[bool; 3]> {
    let lead = c.text(1, 7);
    if !lead.is_empty() {
        return Err(c.err(
            "IBC",
            format!("'{lead}' in columns 1-7: expected blanks; IBC is three one-column 0/1 flags IBCX IBCY IBCZ in columns 8, 9, 10 (e.g. '       001')"),
        ));
    }
    let mut out = [false; 3];
    for (i, name) in ["IBCX", "IBCY", "IBCZ"].iter().enumerate() {
        let col = 8 + i;
        match c.text(col, 1) {
            "" | "0" => {}
            "1" => out[i] = true,
            t => return Err(c.err(name, format!("'{t}' in column {col}: expected 0 or 1"))),
        }
    }
    Ok(out)
}

/// Ifiltr (11-20) and Xfreq (21-40) of a friction card, with the Starter's
/// rules: Ifiltr is forced to 0 when Xfreq = 0; with Ifiltr = 1, Xfreq is the
/// filter coefficient α in (0, 1]; with Ifiltr = 2 it is the number of steps
/// per period (α = 2π/Xfreq must be <= 1).
fn filter(c: &Card) -> DeckResult<(i64, f64)> {
    let ifiltr = flag(c, 11, "Ifiltr", &[0, 1, 2, 3], 0)?;
    let xfreq = real_ge0(c, 21, "Xfreq", 0.0, "the filtering coefficient")?;
    if xfreq == 0.0 {
        return Ok((0, 0.0));
    }
    match ifiltr {
        1 if xfreq > 1.0 => Err(c.err(
            "Xfreq",
            format!("{xfreq} in columns 21-40: with Ifiltr = 1 the filter coefficient must be in (0, 1]"),
        )),
        2 if xfreq < 2.0 * std::f64::consts::PI => Err(c.err(
            "Xfreq",
            format!("{xfreq} in columns 21-40: with Ifiltr = 2 Xfreq is the number of steps per filtering period and must be >= 2π (6.2832)"),
        )),
        _ => Ok((ifiltr, xfreq)),
    }
}

/// C1..C5 (when Ifric > 0) and C6 (when Ifric > 1), 20 columns each.
fn friction_coefs(cards: &mut Cards, ifric: i64) -> DeckResult<Option<[f64; 6]>> {
    if ifric <= 0 {
        return Ok(None);
    }
    let mut cs = [0.0; 6];
    let c = cards.next("the card with friction coefficients C1, C2, C3, C4, C5 (Ifric > 0)")?;
    for (i, name) in ["C1", "C2", "C3", "C4", "C5"].iter().enumerate() {
        cs[i] = c.real(1 + 20 * i, name, 0.0)?;
    }
    if ifric > 1 {
        let c = cards.next("the card with friction coefficient C6 (Ifric > 1)")?;
        cs[5] = c.real(1, "C6", 0.0)?;
    }
    Ok(Some(cs))
}

#[cfg(test)]
mod tests {
    use super::super::source::Line;
    use super::*;

    /// A block as the source reader makes it (comment lines already removed).
    fn block(header: &str, lines: &[&str]) -> Block {
        let parts = header[1..]
            .split('/')
            .map(|p| p.trim().to_ascii_uppercase())
            .collect();
        Block {
            header: header.to_string(),
            parts,
            loc: Loc {
                file: "t.rad".into(),
                line: 1,
            },
            lines: lines
                .iter()
                .enumerate()
                .map(|(i, t)| Line {
                    text: t.to_string(),
                    loc: Loc {
                        file: "t.rad".into(),
                        line: i + 2,
                    },
                })
                .collect(),
        }
    }

    fn parse(header: &str, lines: &[&str]) -> DeckResult<(InterfaceCard, Deck)> {
        let mut deck = Deck::default();
        let ok = parse_interface(&block(header, lines), &mut deck)?;
        assert!(ok, "{header} should be supported");
        Ok((deck.interfaces[0].clone(), deck))
    }

    // INT357 (OpenRadioss QA), with the listing's values in the assertions.
    const INT357_TYPE3: &[&str] = &[
        "interface_3",
        "         9        10                                                           0",
        "                   0                  .2                   0                   0                   0",
        "       000         0         0",
    ];
    const INT357_TYPE5: &[&str] = &[
        "interface_5",
        "        11        12                                                 0         0",
        "                   0                  .2                   0                   0                   0",
        "       000                   0         0",
        "         0         0                   0                   0                   0",
    ];
    const INT357_TYPE7: &[&str] = &[
        "interface_7",
        "        13        14         0         0         0                   0         0         0         0",
        "                   0                   0                   0",
        "                   0                   0                   0                   0         0         0",
        "                   0                  .2                   0                   0                   0",
        "       000                             0                   0                   0                   0",
        "         0         0                   0         0         0         0                   0         0",
    ];

    #[test]
    fn int357_type3() {
        let (card, _) = parse("/INTER/TYPE3/3", INT357_TYPE3).unwrap();
        assert_eq!(card.id, 3);
        assert_eq!(card.title, "interface_3");
        assert_eq!(card.type_number(), 3);
        assert_eq!(card.secondary_side(), Side::Surface(9));
        assert_eq!(card.main_side(), Side::Surface(10));
        let InterfaceKind::Type3(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 0.2);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.gap, 0.0);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.ptlim, 1e30, "card 4 absent → 1e30");
        assert_eq!(t.ibc, [false; 3]);
        assert_eq!((t.irs, t.irm, t.idel), (0, 0, 0));
    }

    #[test]
    fn int357_type5() {
        let (card, deck) = parse("/INTER/TYPE5/6", INT357_TYPE5).unwrap();
        assert!(deck.warnings.is_empty());
        assert_eq!(card.secondary_side(), Side::NodeGroup(11));
        assert_eq!(card.main_side(), Side::Surface(12));
        let InterfaceKind::Type5(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 0.2);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.ptlim, 1e30);
        assert_eq!((t.inacti, t.ifric, t.ifiltr, t.xfreq), (0, 0, 0, 0.0));
        assert_eq!(t.fric_coefs, None);
    }

    #[test]
    fn int357_type7_defaults() {
        let (card, deck) = parse("/INTER/TYPE7/10", INT357_TYPE7).unwrap();
        assert!(deck.warnings.is_empty());
        assert_eq!(card.type_number(), 7);
        assert_eq!(card.secondary_side(), Side::NodeGroup(13));
        assert_eq!(card.main_side(), Side::Surface(14));
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 1.0);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.istf, 1000);
        assert_eq!(t.igap, 1000);
        assert_eq!(t.inacti, 1000);
        assert_eq!(t.idel, 1000);
        assert_eq!(t.ibag, 1000);
        assert_eq!(t.irem_gap, 1);
        assert_eq!(t.irem_i2, 3);
        assert_eq!(t.iform, 1);
        assert_eq!(t.viss, 0.05);
        assert_eq!(t.visf, 1.0);
        assert_eq!(t.bumult, 0.2);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.stmax, 1e30);
        assert_eq!(t.gapmax, 1e30);
        assert_eq!(t.fscalegap, 1.0);
        assert_eq!(t.ascalef, 1.0);
        assert_eq!(t.gapmin, 0.0);
        assert_eq!(t.ibc, [false; 3]);
        assert_eq!((t.ifric, t.ifiltr, t.fric_id, t.sens_id), (0, 0, 0, 0));
        assert!(t.fric_coefs.is_none() && t.adm.is_none() && t.thermal.is_none());
        assert!(t.curv_nodes.is_none());
    }

    #[test]
    fn type7_self_contact_and_ibc() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "         0        14";
        lines[5] = "       101";
        let (card, _) = parse("/INTER/TYPE7/10/2", &lines).unwrap();
        assert_eq!(card.unit_id, 2);
        assert_eq!(card.secondary_side(), Side::SameAsOther);
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ibc, [true, false, true]);
    }

    /// Right-aligned fixed-width fields: `(width, text)`.
    fn row(fields: &[(usize, &str)]) -> String {
        fields
            .iter()
            .map(|(w, t)| format!("{t:>w$}", w = *w))
            .collect()
    }

    #[test]
    fn type7_friction_law_cards() {
        let c15 = row(&[(20, ".1"), (20, ".2"), (20, ".3"), (20, ".4"), (20, ".5")]);
        let mut lines = INT357_TYPE7.to_vec();
        lines[6] = "         1";
        lines.push(&c15);
        let (card, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert!(deck.warnings.is_empty());
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ifric, 1);
        assert_eq!(t.fric_coefs, Some([0.1, 0.2, 0.3, 0.4, 0.5, 0.0]));

        // Ifric = 3 (Renard) also reads C6; then the Iadm and thermal cards follow.
        let c1 = row(&[
            (10, "13"),
            (10, "14"),
            (10, "0"),
            (10, "1"),
            (10, "0"),
            (10, ""),
            (10, "0"),
            (10, "0"),
            (10, "0"),
            (10, "2"),
        ]);
        let c6 = row(&[(20, ".6")]);
        let adm = row(&[(10, "0"), (20, "0"), (20, "30")]);
        let th1 = row(&[(20, "10"), (10, "7"), (10, ""), (20, "293"), (10, "1")]);
        let th2 = row(&[(20, "0"), (20, "0"), (20, ".5"), (20, ".5")]);
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = &c1;
        lines[6] = "         3";
        lines.extend([c15.as_str(), &c6, &adm, &th1, &th2]);
        let (card, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert!(deck.warnings.is_empty());
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!((t.ithe, t.iadm), (1, 2));
        assert_eq!(t.fric_coefs, Some([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]));
        assert_eq!(
            t.adm,
            Some(Type7Adm {
                nradm: 3,
                padm: 1.0,
                angladm: 30.0
            })
        );
        let th = t.thermal.as_ref().unwrap();
        assert_eq!(
            (th.kthe, th.fct_idk, th.tint, th.ithe_form),
            (10.0, 7, 293.0, 1)
        );
        assert_eq!(th.ascalek, 1.0);
        assert_eq!((th.fheats, th.fheatm), (0.5, 0.5));
    }

    #[test]
    fn type7_curvature_nodes() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "        13        14         0         0         0                   0         0         2";
        lines.insert(4, "       101       102");
        let (card, _) = parse("/INTER/TYPE7/10", &lines).unwrap();
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.curv_nodes, Some([101, 102]));

        lines[4] = "       101";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "node_ID2");
    }

    #[test]
    fn type7_bad_flag_names_the_field() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "        13        14         7";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "Istf");
        assert!(e.message.contains("columns 21-30"), "{}", e.message);
        assert_eq!(e.loc.line, 3);

        let mut lines = INT357_TYPE7.to_vec();
        lines[4] = "                -1.0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "Stfac");
        assert!(e.message.contains(">= 0"), "{}", e.message);

        let mut lines = INT357_TYPE7.to_vec();
        lines[5] = "       0x0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "IBCY");

        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "         0         0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "surf_IDm");
    }

    #[test]
    fn type7_truncated_card() {
        let lines = &INT357_TYPE7[..6];
        let e = parse("/INTER/TYPE7/10", lines).unwrap_err();
        assert!(e.message.contains("card missing"), "{}", e.message);
        assert!(e.message.contains("Ifric"), "{}", e.message);

        // Ifric = 2 announces C1..C5 and C6: a missing C6 card is an error too.
        let mut lines = INT357_TYPE7.to_vec();
        lines[6] = "         2";
        lines.push("                  .1");
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert!(
            e.message.contains("card missing") && e.message.contains("C6"),
            "{}",
            e.message
        );
    }

    #[test]
    fn extra_lines_warn() {
        let mut lines = INT357_TYPE7.to_vec();
        lines.push("                  .1                  .2");
        let (_, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert_eq!(deck.warnings.len(), 1);
        assert_eq!(deck.warnings[0].loc.line, 9);
    }

    #[test]
    fn type3_with_ptlim() {
        let mut lines = INT357_TYPE3.to_vec();
        lines.push("                                                                       5000.");
        let (card, _) = parse("/INTER/TYPE3/3", &lines).unwrap();
        let InterfaceKind::Type3(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ptlim, 5000.0);
    }

    #[test]
    fn type2_kinematic_and_penalty() {
        let (card, _) = parse("/INTER/TYPE2/4", &["tied", "         3         4"]).unwrap();
        assert_eq!(card.secondary_side(), Side::NodeGroup(3));
        assert_eq!(card.main_side(), Side::Surface(4));
        let InterfaceKind::Type2(t) = &card.kind else {
            panic!()
        };
        assert_eq!(
            (t.ignore, t.spotflag, t.isearch, t.idel2),
            (1000, 5, 2, 1000)
        );
        assert!(t.penalty.is_none() && t.rupture.is_none() && t.thermal.is_none());

        let (card, _) = parse(
            "/INTER/TYPE2/4",
            &[
                "tied",
                "         3         4                  25         2",
                "",
                "         1                   3",
            ],
        )
        .unwrap();
        let InterfaceKind::Type2(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.level, 0, "forced to 0 for Spotflag 25");
        assert_eq!(
            t.penalty,
            Some(Type2Penalty {
                stfac: 1.0,
                visc: 0.05,
                istf: 2
            })
        );
        let th = t.thermal.as_ref().unwrap();
        assert_eq!((th.ithe, th.kthe, th.iproj), (1, 3.0, 1));

        let e = parse(
            "/INTER/TYPE2/4",
            &["tied", "         3         4                   6"],
        )
        .unwrap_err();
        assert_eq!(e.field, "Spotflag");
    }

    #[test]
    fn type11_self_contact_and_negative_stfac() {
        let (card, _) = parse(
            "/INTER/TYPE11/8",
            &["edges", "         5", "", "              -1000.", ""],
        )
        .unwrap();
        assert_eq!(card.secondary_side(), Side::Line(5));
        assert_eq!(card.main_side(), Side::SameAsOther);
        let InterfaceKind::Type11(t) = &card.kind else {
            panic!()
        };
        assert_eq!((t.istf, t.stfac), (1, 1000.0));
        assert_eq!(
            (t.igap, t.idel, t.inacti, t.iform, t.irem_gap),
            (1000, 1000, 1000, 1, 1)
        );
        assert_eq!(
            (t.viss, t.bumult, t.tstop, t.stmax),
            (0.05, 0.2, 1e30, 1e30)
        );
        assert_eq!(t.fric_id, 0);

        let e = parse(
            "/INTER/TYPE11/8",
            &[
                "edges",
                "         5         6         0         0         2",
            ],
        )
        .unwrap_err();
        assert_eq!(e.field, "Igap");
    }

    #[test]
    fn unsupported_type() {
        let mut deck = Deck::default();
        let b = block("/INTER/TYPE24/1", &["t", "1 2"]);
        assert!(!parse_interface(&b, &mut deck).unwrap());
        assert!(deck.interfaces.is_empty());
    }
}
